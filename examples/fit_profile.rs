//! Where the time of one fitting step goes (forward, readback, host loss, backward + Adam).
//! `cargo run --release --example fit_profile [gaussians] [size]`
use dreamscene::bench::bench_scene;
use dreamscene::gpu::{Buffer, BufferUsage, Context, Stream};
use dreamscene::splat::adam::{Adam, AdamConfig, AdamState, LearningRates};
use dreamscene::splat::backward::{Backward, GpuGrads};
use dreamscene::splat::loss::l1_dssim;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use std::time::Instant;

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).map(|s| s.parse()).transpose()?.unwrap_or(5000);
    let size: u32 = args.get(2).map(|s| s.parse()).transpose()?.unwrap_or(256);
    let ctx = Context::new()?;
    let (g, cam) = bench_scene(n, size, size);
    let r = Rasterizer::new(&ctx)?;
    let b = Backward::new(&ctx, false)?;
    let adam = Adam::new(&ctx, AdamConfig::default())?;
    let gg = GpuGaussians::upload(&ctx, &g)?;
    let grads = GpuGrads::new(&ctx, gg.n, gg.sh_degree)?;
    let mut st = AdamState::new(&ctx, &gg)?;
    let np = (size * size) as u64;
    let dlb = Buffer::new(&ctx, "dl", np * 16, BufferUsage::Upload)?;
    let state = Buffer::new(&ctx, "state", np * 16, BufferUsage::Device)?;
    let target = vec![[0.5f32; 3]; np as usize];
    let lr = LearningRates {
        means: 1e-4,
        scales: 5e-3,
        rotations: 1e-3,
        opacities: 5e-2,
        sh_dc: 2.5e-3,
        sh_rest: 1e-4,
    };
    let mut acc = [0.0f64; 5];
    let runs = 20;
    for it in 0..runs + 2 {
        let t0 = Instant::now();
        let frame = r.forward(&ctx, &gg, &cam, [0.0; 3])?;
        let t1 = Instant::now();
        let out = frame.read()?;
        let t2 = Instant::now();
        let (_, dl) = l1_dssim(&out.color, &target, size as usize, size as usize, 0.2);
        let t3 = Instant::now();
        dlb.write(&dl)?;
        let mut s = Stream::new(&ctx)?;
        b.record(&mut s, &frame, &gg, &cam, &dlb, &grads, &state)?;
        adam.record(&mut s, &gg, &grads, &mut st, &lr)?;
        s.submit()?;
        let t4 = Instant::now();
        if it >= 2 {
            for (a, d) in acc
                .iter_mut()
                .zip([t1 - t0, t2 - t1, t3 - t2, t4 - t3, t4 - t0])
            {
                *a += d.as_secs_f64() * 1e3 / runs as f64;
            }
        }
    }
    println!(
        "{n} Gaussians {size}x{size}: forward {:.1} ms, readback {:.1} ms, loss {:.1} ms, backward+adam {:.1} ms, step {:.1} ms",
        acc[0], acc[1], acc[2], acc[3], acc[4]
    );
    Ok(())
}
