//! The fused Adam kernel against an f64 host reference over three steps, with per-group learning
//! rates (SH rest at its own rate), non-finite gradients ignored, and gradients cleared.
mod common;
use dreamscene::splat::adam::{adam_step_reference, Adam, AdamConfig, AdamState, LearningRates};
use dreamscene::splat::backward::GpuGrads;
use dreamscene::splat::raster::GpuGaussians;
use dreamscene::splat::Gaussians;
use rand::Rng;

#[test]
fn adam_matches_reference() {
    let ctx = common::gpu();
    let mut rng = common::rng(70);
    let g = Gaussians::random(&mut rng, 333, [-1.0; 3], [1.0; 3], 0.1, 2);
    let gg = GpuGaussians::upload(&ctx, &g).unwrap();
    let grads = GpuGrads::new(&ctx, g.len() as u32, 2).unwrap();
    let adam = Adam::new(&ctx, AdamConfig::default()).unwrap();
    let mut state = AdamState::new(&ctx, &gg).unwrap();
    let lr = LearningRates {
        means: 0.01,
        scales: 0.005,
        rotations: 0.001,
        opacities: 0.05,
        sh_dc: 0.0025,
        sh_rest: 0.000125,
    };
    let kc3 = 27;
    let mut sh: Vec<f64> = g.sh.iter().map(|&v| v as f64).collect();
    let mut means: Vec<f64> = g.means.iter().flatten().map(|&v| v as f64).collect();
    let (mut sm1, mut sm2) = (vec![0.0; sh.len()], vec![0.0; sh.len()]);
    let (mut mm1, mut mm2) = (vec![0.0; means.len()], vec![0.0; means.len()]);
    for step in 1..=3u32 {
        let mut gsh: Vec<f32> = (0..sh.len()).map(|_| rng.gen_range(-1.0..1.0)).collect();
        let gmeans: Vec<f32> = (0..means.len()).map(|_| rng.gen_range(-1.0..1.0)).collect();
        gsh[5] = f32::NAN;
        grads.sh.write(&gsh).unwrap();
        grads.means.write(&gmeans).unwrap();
        let mut s = dreamscene::gpu::Stream::new(&ctx).unwrap();
        adam.record(&mut s, &gg, &grads, &mut state, &lr).unwrap();
        s.submit().unwrap();
        let gsh64: Vec<f64> = gsh.iter().map(|&v| v as f64).collect();
        let gm64: Vec<f64> = gmeans.iter().map(|&v| v as f64).collect();
        let c = AdamConfig::default();
        adam_step_reference(
            &mut sh,
            &gsh64,
            &mut sm1,
            &mut sm2,
            step,
            |e| {
                if e % kc3 >= 3 {
                    0.000125
                } else {
                    0.0025
                }
            },
            c,
        );
        adam_step_reference(&mut means, &gm64, &mut mm1, &mut mm2, step, |_| 0.01, c);
        let cleared: Vec<f32> = grads.sh.read(sh.len()).unwrap();
        assert!(
            cleared.iter().all(|&v| v == 0.0),
            "step {step}: gradients not cleared"
        );
    }
    let back = gg.download().unwrap();
    let worst = |a: &[f32], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (*x as f64 - y).abs())
            .fold(0.0f64, f64::max)
    };
    let esh = worst(&back.sh, &sh);
    let em = worst(
        &back.means.iter().flatten().copied().collect::<Vec<_>>(),
        &means,
    );
    eprintln!("max |diff|: sh {esh:e}, means {em:e}");
    assert!(esh < 1e-6 && em < 1e-6, "sh {esh:e}, means {em:e}");
    // The element with a NaN gradient moved only by the earlier steps' momentum, and is finite.
    assert!(back.sh[5].is_finite());
    // Parameters with zero gradient did not move.
    assert_eq!(back.opacities, g.opacities);
    ctx.check_validation().unwrap();
}
