//! The filtering score on the GPU (native and compare-and-swap atomics) against the CPU reference.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::Camera;
use dreamscene::gpu::Buffer;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::reference;
use dreamscene::splat::score::{code_volume_weighting, ScoreRule, Scorer};
use dreamscene::splat::Gaussians;

fn check(force_cas: bool) {
    let ctx = common::gpu();
    let r = Rasterizer::new(&ctx).unwrap();
    let scorer = Scorer::new(&ctx, force_cas).unwrap();
    let mut rng = common::rng(30);
    let g = Gaussians::random(&mut rng, 400, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.08, 1);
    let cams = [
        Camera::look_at([0.0; 3], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0], 70, 45, 1.0),
        Camera::look_at(
            [0.5, 0.2, -0.3],
            [0.0, 0.0, 3.0],
            [0.0, -1.0, 0.0],
            48,
            64,
            1.1,
        ),
    ];
    let gg = GpuGaussians::upload(&ctx, &g).unwrap();
    for (rule, paper) in [(ScoreRule::Code, false), (ScoreRule::Paper, true)] {
        // Garbage would show up in the sum: start from a known value and subtract it.
        let scores = Buffer::from_slice(&ctx, "scores", &vec![0.5f32; g.len()]).unwrap();
        let mut want = vec![0.0; g.len()];
        for cam in &cams {
            let frame = r.forward(&ctx, &gg, cam, [0.0; 3]).unwrap();
            scorer.accumulate(&ctx, &frame, &gg, rule, &scores).unwrap();
            for (w, s) in want.iter_mut().zip(reference::score(&g, cam, paper)) {
                *w += s;
            }
        }
        let got: Vec<f32> = scores.read(g.len()).unwrap();
        let mut nonzero = 0;
        for i in 0..g.len() {
            let gi = got[i] as f64 - 0.5;
            assert!(
                (gi - want[i]).abs() <= 1e-4 * want[i].abs().max(1.0),
                "{rule:?} cas={force_cas}: gaussian {i}: {gi} vs {}",
                want[i]
            );
            nonzero += (want[i] > 0.0) as usize;
        }
        assert!(
            nonzero > g.len() / 2,
            "{rule:?}: only {nonzero} Gaussians scored"
        );
    }
    ctx.check_validation().unwrap();
}

#[test]
fn filtering_score_matches_reference_with_native_atomics() {
    check(false);
}

#[test]
fn filtering_score_matches_reference_with_cas_atomics() {
    check(true);
}

#[test]
fn code_volume_weighting_uses_the_90th_percentile_volume() {
    // Ten Gaussians with volumes e^0 .. e^9; sorted descending, index 9 holds e^0 = V_ref.
    let scales: Vec<[f32; 3]> = (0..10).map(|i| [i as f32, 0.0, 0.0]).collect();
    let w = code_volume_weighting(&[2.0; 10], &scales, 0.1);
    for (i, v) in w.iter().enumerate() {
        let want = 2.0 * (i as f32).exp().powf(0.1);
        assert!((v - want).abs() < 1e-5 * want, "{i}: {v} vs {want}");
    }
}
