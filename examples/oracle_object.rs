//! Generates an object with the oracle prior from a ball and writes a contact sheet of
//! reference / result pairs from held-out views: `cargo run --release --example oracle_object --
//! [iterations] [resolution] [out.png]`.
use dreamscene::camera::object::{orbit_camera, ObjectFrame};
use dreamscene::generate::object::{generate_object, ObjectConfig};
use dreamscene::generate::prior::OraclePrior;
use dreamscene::generate::progress::Progress;
use dreamscene::splat::cloud::SH_C0;
use dreamscene::splat::loss::psnr;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use rand::{Rng, SeedableRng};

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let iterations: u32 = args.get(1).map_or(Ok(300), |s| s.parse())?;
    let res: u32 = args.get(2).map_or(Ok(128), |s| s.parse())?;
    let out = args.get(3).cloned().unwrap_or("oracle_object.png".into());
    let frame = ObjectFrame {
        size: [1.0, 0.8, 0.9],
    };
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let mut refg = Gaussians::default();
    for (c, r) in [
        ([0.0, 0.0, 0.3], [0.45, 0.35, 0.28]),
        ([0.18, 0.05, 0.62], [0.25, 0.25, 0.25]),
        ([-0.22, -0.1, 0.55], [0.2, 0.22, 0.3]),
    ] {
        let base: [f64; 3] = [rng.gen(), rng.gen(), rng.gen()];
        for _ in 0..3000 {
            let d: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-1.0..1.0));
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if !(0.1..=1.0).contains(&l) {
                continue;
            }
            let p: [f64; 3] = std::array::from_fn(|a| c[a] + r[a] * d[a] / l);
            refg.means.push(p.map(|v| v as f32));
            refg.scales.push([(0.03f32).ln(); 3]);
            refg.rotations.push([1.0, 0.0, 0.0, 0.0]);
            refg.opacities.push(3.0);
            refg.sh.extend(base.map(|b| ((b - 0.5) / SH_C0) as f32));
        }
    }
    let mut init = Gaussians::default();
    while init.len() < 4000 {
        let d: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-1.0..1.0));
        if d.iter().map(|v| v * v).sum::<f64>() > 1.0 {
            continue;
        }
        init.means.push([
            0.4 * d[0] as f32,
            0.4 * d[1] as f32,
            0.45 + 0.4 * d[2] as f32,
        ]);
        init.scales.push([(0.03f32).ln(); 3]);
        init.rotations.push([1.0, 0.0, 0.0, 0.0]);
        init.opacities.push((0.1f32 / 0.9).ln());
        init.sh.extend([0.0; 3]);
    }
    let ctx = dreamscene::gpu::Context::new()?;
    let mut oracle = OraclePrior::new(&ctx, &refg, None).map_err(anyhow::Error::msg)?;
    let cfg = ObjectConfig {
        iterations,
        resolution: res,
        sh_degree: 0,
        recon_views: 12,
        recon_passes: std::env::var("RP").map_or(Ok(8), |v| v.parse())?,
        checkpoint_every: 0,
        ..ObjectConfig::default()
    };
    let (g, report) = generate_object(
        &ctx,
        &init,
        &frame,
        &mut oracle,
        &cfg,
        None,
        &mut Progress::new(iterations as u64 + 97, false),
    )?;
    println!(
        "{:?} {:.1} s split {:?}",
        report.counts, report.seconds, report.formation_split
    );
    let r = Rasterizer::new(&ctx)?;
    let gg = GpuGaussians::upload(&ctx, &g)?;
    let n = 4u32;
    let mut sheet = image::RgbImage::new(res * n, res * 2);
    for i in 0..n {
        let cam = orbit_camera(&frame, 4.5, 70.0, -150.0 + 100.0 * i as f64, 0.5, res, None);
        let got = r.forward(&ctx, &gg, &cam, [1.0; 3])?.read()?.color;
        let want = oracle
            .reference_view(&cam, [1.0; 3])
            .map_err(anyhow::Error::msg)?;
        println!("view {i}: {:.2} dB", psnr(&got, &want));
        for (row, img) in [(0, &want), (1, &got)] {
            for (k, p) in img.iter().enumerate() {
                let (x, y) = (k as u32 % res, k as u32 / res);
                let px = image::Rgb(p.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8));
                sheet.put_pixel(i * res + x, row * res + y, px);
            }
        }
    }
    sheet.save(&out)?;
    Ok(())
}
