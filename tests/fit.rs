//! End-to-end proof that forward, backward and the optimiser agree: fitting 24 posed 128x96
//! images of a random 500-Gaussian scene (rendered by the f64 CPU reference) from random
//! Gaussians reaches at least 25 dB PSNR on 8 held-out views.
mod common;
use dreamscene::camera::Camera;
use dreamscene::splat::loss::psnr;
use dreamscene::splat::reference;
use dreamscene::splat::train::{random_init, FitConfig, Trainer, View};
use dreamscene::splat::Gaussians;
use rand::Rng;

fn orbit(n: usize, seed: u64) -> Vec<Camera> {
    let mut rng = common::rng(seed);
    (0..n)
        .map(|i| {
            let az = (i as f64 / n as f64) * std::f64::consts::TAU + rng.gen_range(-0.1..0.1);
            let el: f64 = rng.gen_range(-0.5..1.0);
            let r = 4.0;
            let eye = [
                r * el.cos() * az.cos(),
                -r * el.sin(),
                r * el.cos() * az.sin(),
            ];
            let mut c =
                Camera::look_at(eye, [0.0; 3], [0.0, -1.0, 0.0], 128, 96, 50f64.to_radians());
            c.id = i as u32;
            c.img_name = format!("view{i:02}");
            c
        })
        .collect()
}

fn to_f32(img: &reference::RefImage) -> Vec<[f32; 3]> {
    img.color.iter().map(|c| c.map(|v| v as f32)).collect()
}

/// Each camera's view of `scene`, rendered by the f64 reference on black.
fn views_of(scene: &Gaussians, cams: &[Camera]) -> Vec<View> {
    cams.iter()
        .map(|c| View {
            camera: c.clone(),
            pixels: to_f32(&reference::render(scene, c, [0.0; 3])),
        })
        .collect()
}

#[test]
fn fit_recovers_a_random_scene() {
    let ctx = common::gpu();
    let mut rng = common::rng(80);
    let scene = Gaussians::random(&mut rng, 500, [-1.0; 3], [1.0; 3], 0.12, 0);
    let cams = orbit(32, 81);
    let views = views_of(&scene, &cams);
    let (test, train): (Vec<View>, Vec<View>) =
        views.into_iter().partition(|v| v.camera.id % 4 == 3);
    assert_eq!((train.len(), test.len()), (24, 8));
    let train_cams: Vec<Camera> = train.iter().map(|v| v.camera.clone()).collect();
    let init = random_init(&train_cams, 1000, 0, 1);
    let iterations: u32 = std::env::var("FIT_ITERATIONS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(600);
    let config = FitConfig {
        iterations,
        ..Default::default()
    };
    let mut t = Trainer::new(&ctx, &init, train, config).unwrap();
    let start = std::time::Instant::now();
    let held_out = |t: &Trainer| -> f64 {
        test.iter()
            .map(|v| psnr(&t.render(&v.camera).unwrap(), &v.pixels))
            .sum::<f64>()
            / test.len() as f64
    };
    let before = held_out(&t);
    let mut last = None;
    for i in 0..iterations {
        let r = t.step().unwrap();
        if (i + 1) % 200 == 0 {
            eprintln!(
                "iteration {}: loss {:.4}, train PSNR {:.2}, {} Gaussians, held-out PSNR {:.2} dB, {:.1} s",
                r.iteration, r.loss, r.psnr, r.gaussians, held_out(&t), start.elapsed().as_secs_f64()
            );
        }
        last = Some(r);
    }
    let after = held_out(&t);
    eprintln!(
        "held-out PSNR {before:.2} dB -> {after:.2} dB in {iterations} iterations, {:.1} s, {} Gaussians",
        start.elapsed().as_secs_f64(),
        last.unwrap().gaussians
    );
    assert!(after >= 25.0, "held-out PSNR {after:.2} dB");
    ctx.check_validation().unwrap();
}

/// A fit interrupted after a checkpoint and restored from the PLY and the optimiser state ends
/// where an uninterrupted fit does; restarting Adam instead does not. A state written for another
/// model is refused.
#[test]
fn resumed_fit_matches_an_uninterrupted_one() {
    let ctx = common::gpu();
    let mut rng = common::rng(90);
    let scene = Gaussians::random(&mut rng, 200, [-1.0; 3], [1.0; 3], 0.15, 0);
    let cams = orbit(4, 91);
    let views = views_of(&scene, &cams);
    let init = random_init(&cams, 300, 0, 2);
    let config = FitConfig {
        iterations: 40,
        densify: false,
        ..Default::default()
    };
    let run = |t: &mut Trainer, steps: u32| {
        for _ in 0..steps {
            t.step().unwrap();
        }
    };
    let mut straight = Trainer::new(&ctx, &init, views.clone(), config.clone()).unwrap();
    run(&mut straight, 20);
    let want = straight.gaussians().unwrap();

    let dir = std::env::temp_dir().join(format!("dreamscene-resume-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let state = dir.join("model.ply.state");
    let mut first = Trainer::new(&ctx, &init, views.clone(), config.clone()).unwrap();
    run(&mut first, 10);
    first.save_state(&state).unwrap();
    let mid = first.gaussians().unwrap();
    drop(first);

    let mut resumed = Trainer::new(&ctx, &mid, views.clone(), config.clone()).unwrap();
    let up = resumed.gaussians().unwrap();
    assert_eq!(
        (
            up.means == mid.means,
            up.scales == mid.scales,
            up.rotations == mid.rotations,
            up.opacities == mid.opacities,
            up.sh == mid.sh
        ),
        (true, true, true, true, true)
    );
    resumed.restore(&state).unwrap();
    assert_eq!(resumed.iteration(), 10);
    run(&mut resumed, 10);
    let mut restarted = Trainer::new(&ctx, &mid, views.clone(), config.clone()).unwrap();
    run(&mut restarted, 10);

    let flat = |g: &Gaussians| -> Vec<f32> {
        let mut v: Vec<f32> = g.means.concat();
        v.extend(g.scales.concat());
        v.extend(g.rotations.concat());
        v.extend(&g.opacities);
        v.extend(&g.sh);
        v
    };
    let want = flat(&want);
    // Mean absolute difference: float atomics make two identical runs differ slightly (Adam
    // amplifies sign flips of near-zero gradients), so the bar is the run-to-run difference.
    let diff = |g: &Gaussians| -> f64 {
        flat(g)
            .iter()
            .zip(&want)
            .map(|(a, b)| (a - b).abs() as f64)
            .sum::<f64>()
            / want.len() as f64
    };
    // The run-to-run difference varies between runs (5e-5 to 3e-4 here, more under load), so it
    // is measured three times and the largest taken.
    let mut d_twice = 0.0f64;
    for _ in 0..3 {
        let mut again = Trainer::new(&ctx, &init, views.clone(), config.clone()).unwrap();
        run(&mut again, 20);
        d_twice = d_twice.max(diff(&again.gaussians().unwrap()));
    }
    let (d_resumed, d_restarted) = (
        diff(&resumed.gaussians().unwrap()),
        diff(&restarted.gaussians().unwrap()),
    );
    eprintln!(
        "mean parameter difference from the uninterrupted fit: resumed {d_resumed:e}, Adam \
         restarted {d_restarted:e}, the same fit run again {d_twice:e}"
    );
    // The floor: when lavapipe happens to run both fits bit-identically (seen: 1.3e-8), the
    // resumed fit still differs by ~2e-5 because a resume restarts the densification statistics
    // (see `Trainer::restore`); that is far below Adam restarted (~5e-3), which the test must tell.
    let noise = d_twice.max(1e-5);
    assert!(
        d_resumed < 6.0 * noise,
        "resumed fit drifted by {d_resumed:e}"
    );
    // Restarting Adam moves the result well outside that band, so the test can tell the two.
    assert!(
        d_restarted > 12.0 * noise,
        "the test cannot tell: {d_restarted:e}"
    );

    // Another model (the start, not the checkpoint) is refused, as is a damaged file.
    let mut other = Trainer::new(&ctx, &init, views.clone(), config.clone()).unwrap();
    let e = other.restore(&state).unwrap_err();
    assert!(e.contains("another model"), "{e}");
    let bytes = std::fs::read(&state).unwrap();
    std::fs::write(&state, &bytes[..bytes.len() - 5]).unwrap();
    let mut again = Trainer::new(&ctx, &mid, views, config).unwrap();
    let e = again.restore(&state).unwrap_err();
    assert!(e.contains("truncated"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}
