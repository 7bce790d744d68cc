//! Object generation against the oracle prior: a random multi-coloured reference object is
//! recovered from a ball, checked on views never used in training; filtering's share and cost;
//! the other guidance rules through the same loop.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::object::{orbit_camera, ObjectFrame};
use dreamscene::camera::Camera;
use dreamscene::diffusion::target::{Rule, ISM_DEFAULT};
use dreamscene::generate::object::{generate_object, ObjectConfig};
use dreamscene::generate::prior::OraclePrior;
use dreamscene::generate::progress::Progress;
use dreamscene::gpu::Context;
use dreamscene::splat::cloud::SH_C0;
use dreamscene::splat::loss::psnr;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use rand::Rng;

const FRAME: ObjectFrame = ObjectFrame {
    size: [1.0, 0.8, 0.9],
};

/// Three overlapping ellipsoids of distinct random colours (with a stripe pattern on one),
/// sampled as small opaque Gaussians on their surfaces, inside `FRAME`.
fn reference(seed: u64) -> Gaussians {
    let mut rng = common::rng(seed);
    let mut g = Gaussians::default();
    let blobs = [
        ([0.0, 0.0, 0.3], [0.45, 0.35, 0.28]),
        ([0.18, 0.05, 0.62], [0.25, 0.25, 0.25]),
        ([-0.22, -0.1, 0.55], [0.2, 0.22, 0.3]),
    ];
    for (b, (c, r)) in blobs.iter().enumerate() {
        let base: [f64; 3] = [rng.gen(), rng.gen(), rng.gen()];
        let n = 3000;
        for _ in 0..n {
            let d: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-1.0..1.0));
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if !(0.1..=1.0).contains(&l) {
                continue;
            }
            let p: [f64; 3] = std::array::from_fn(|a| c[a] + r[a] * d[a] / l);
            g.means.push(p.map(|v| v as f32));
            g.scales.push([(0.03f32).ln(); 3]);
            g.rotations.push([1.0, 0.0, 0.0, 0.0]);
            g.opacities.push(3.0);
            let stripe = if b == 0 && (p[2] * 12.0).floor() as i64 % 2 == 0 {
                0.5
            } else {
                1.0
            };
            g.sh.extend(base.map(|b| ((b * stripe - 0.5) / SH_C0) as f32));
        }
    }
    g
}

/// A ball of grey Gaussians around the object's centre (the authors' "random ball" init).
fn ball(n: usize, seed: u64) -> Gaussians {
    let mut rng = common::rng(seed);
    let mut g = Gaussians::default();
    let c = FRAME.centre();
    while g.len() < n {
        let d: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-1.0..1.0));
        if d.iter().map(|v| v * v).sum::<f64>() > 1.0 {
            continue;
        }
        g.means
            .push(std::array::from_fn(|a| (c[a] + 0.4 * d[a]) as f32));
        g.scales.push([(0.02f32).ln(); 3]);
        g.rotations.push([1.0, 0.0, 0.0, 0.0]);
        g.opacities.push((0.1f32 / 0.9).ln());
        g.sh.extend([0.0; 3]);
    }
    g
}

/// Views never used in training: random directions at other radii and angles.
fn held_out(res: u32) -> Vec<Camera> {
    let mut rng = common::rng(999);
    (0..8)
        .map(|_| {
            orbit_camera(
                &FRAME,
                rng.gen_range(4.0..5.0),
                rng.gen_range(50.0..100.0),
                rng.gen_range(-180.0..180.0),
                0.5,
                res,
                None,
            )
        })
        .collect()
}

fn held_out_psnr(ctx: &Context, g: &Gaussians, oracle: &OraclePrior, res: u32) -> f64 {
    let r = Rasterizer::new(ctx).unwrap();
    let gg = GpuGaussians::upload(ctx, g).unwrap();
    let cams = held_out(res);
    let mut total = 0.0;
    for c in &cams {
        let img = r
            .forward(ctx, &gg, c, [1.0; 3])
            .unwrap()
            .read()
            .unwrap()
            .color;
        let want = oracle.reference_view(c, [1.0; 3]).unwrap();
        total += psnr(&img, &want);
    }
    total / cams.len() as f64
}

fn config(iterations: u32) -> ObjectConfig {
    ObjectConfig {
        iterations,
        resolution: 128,
        sh_degree: 0,
        recon_views: 12,
        recon_passes: 25,
        checkpoint_every: 0,
        ..ObjectConfig::default()
    }
}

#[test]
fn oracle_recovers_a_reference_object_on_held_out_views() {
    let ctx = common::gpu();
    let refg = reference(1);
    let mut oracle = OraclePrior::new(&ctx, &refg, None).unwrap();
    let init = ball(40_000, 2);
    let before = held_out_psnr(&ctx, &init, &oracle, 128);
    let run = |init: &Gaussians, cfg: &ObjectConfig, oracle: &mut OraclePrior| {
        generate_object(
            &ctx,
            init,
            &FRAME,
            oracle,
            cfg,
            None,
            &mut Progress::new(0, true),
        )
        .unwrap()
    };
    let cfg = config(100);
    // The formation stage, run once: the filtered and the unfiltered runs below both continue
    // from its cloud (a run's formation does not depend on the filter that follows it), each
    // through filtering (or none) and reconstruction with no formation step of its own.
    let formation = ObjectConfig {
        filter: None,
        recon_views: 0,
        ..cfg.clone()
    };
    let (formed, _) = run(&init, &formation, &mut oracle);
    let rest = ObjectConfig {
        iterations: 0,
        ..cfg
    };
    let (g, report) = run(&formed, &rest, &mut oracle);
    assert_eq!(
        report.counts.before_filter,
        formed.len(),
        "filtering starts from the formed cloud"
    );
    let after = held_out_psnr(&ctx, &g, &oracle, 128);
    let removed = 1.0 - report.counts.after_filter as f64 / report.counts.before_filter as f64;
    println!(
        "held-out PSNR {before:.2} -> {after:.2} dB; counts {:?}; filtered {:.1}%; {:.1} s",
        report.counts,
        100.0 * removed,
        report.seconds,
    );
    assert!(after >= 25.0, "held-out PSNR {after:.2} dB");
    assert!(removed >= 0.5, "filtering removed {:.1}%", 100.0 * removed);
    // The same run without filtering ends within 0.5 dB (measured: 33.74 dB unfiltered against
    // 34.49 dB filtered, from 46k Gaussians before filtering; from a 20k ball, which formation
    // barely grows in 100 iterations, the cloud is not redundant yet and 60% filtering costs
    // 1.5 dB).
    let unfiltered = ObjectConfig {
        filter: None,
        ..rest
    };
    let (g2, _) = run(&formed, &unfiltered, &mut oracle);
    let plain = held_out_psnr(&ctx, &g2, &oracle, 128);
    println!("without filtering: {plain:.2} dB ({} Gaussians)", g2.len());
    assert!(
        after >= plain - 0.5,
        "filtered {after:.2} dB, unfiltered {plain:.2} dB"
    );
}

#[test]
fn sds_and_ism_run_through_the_same_loop() {
    let ctx = common::gpu();
    let refg = reference(3);
    let mut oracle = OraclePrior::new(&ctx, &refg, None).unwrap();
    let init = ball(2000, 4);
    let before = held_out_psnr(&ctx, &init, &oracle, 64);
    for rule in [
        Rule::Sds {
            t_min: 20,
            t_max: 980,
        },
        ISM_DEFAULT,
    ] {
        let cfg = ObjectConfig {
            rule,
            resolution: 64,
            recon_views: 0,
            filter: None,
            ..config(60)
        };
        let (g, _) = generate_object(
            &ctx,
            &init,
            &FRAME,
            &mut oracle,
            &cfg,
            None,
            &mut Progress::new(0, true),
        )
        .unwrap();
        let after = held_out_psnr(&ctx, &g, &oracle, 64);
        println!("{rule:?}: {before:.2} -> {after:.2} dB");
        assert!(
            after > before + 3.0,
            "{rule:?}: {before:.2} -> {after:.2} dB"
        );
    }
}
