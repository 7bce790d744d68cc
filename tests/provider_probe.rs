//! The provider probe (src/diffusion/probe.rs) through ONNX Runtime: the CPU provider probed
//! against itself agrees, and a wrong result planted through the test hook is caught — split the
//! batch when only large batches are wrong, fall back when every size is. Then the split through
//! the tiny exported pipeline: a UNet batch run in halves equals the batch run at once.
//! Needs the ONNX Runtime library (scripts/setup.sh installs it).
use dreamscene::diffusion::model::{ModelOptions, StableDiffusion};
use dreamscene::diffusion::probe::{probe, Op, ProbeSizes, Verdict};
use dreamscene::diffusion::runtime::Provider;
use std::path::Path;

fn sizes(half: bool) -> ProbeSizes {
    ProbeSizes {
        batch: 4,
        heads: 2,
        hw: (6, 5),
        channels: 8,
        half,
    }
}

#[test]
fn planted_wrong_results_are_caught() {
    for half in [false, true] {
        let honest = probe(Provider::Cpu, &sizes(half), None).unwrap();
        assert_eq!(honest.verdict, Verdict::Trust, "half {half}");
        assert!(honest.checks.iter().all(|c| c.error == 0.0));

        // A Softmax wrong above one item, as a storage binding overflows: split to one item.
        let big_batches_wrong = |op: Op, b: usize, y: &mut [f32]| {
            if op == Op::Softmax && b > 1 {
                y[y.len() - 1] += 0.45;
            }
        };
        let r = probe(Provider::Cpu, &sizes(half), Some(&big_batches_wrong)).unwrap();
        assert_eq!(r.verdict, Verdict::Split { max_batch: 1 }, "half {half}");

        // A Conv off by a few percent of its range: the CPU instead.
        let conv_wrong = |op: Op, _b: usize, y: &mut [f32]| {
            if op == Op::Conv {
                let m = y.iter().fold(0.0f32, |m, v| m.max(v.abs()));
                y[0] += 0.1 * m.max(1.0);
            }
        };
        let r = probe(Provider::Cpu, &sizes(half), Some(&conv_wrong)).unwrap();
        assert!(
            matches!(r.verdict, Verdict::Fallback { ref reason } if reason.contains("Conv")),
            "{r:?}"
        );

        // A NaN anywhere is never trusted.
        let nan = |op: Op, _b: usize, y: &mut [f32]| {
            if op == Op::Softmax {
                y[0] = f32::NAN;
            }
        };
        let r = probe(Provider::Cpu, &sizes(half), Some(&nan)).unwrap();
        assert!(matches!(r.verdict, Verdict::Fallback { .. }), "{r:?}");
    }
}

#[test]
fn a_split_unet_batch_equals_the_whole_batch() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/exported-sd/fp32");
    let opts = ModelOptions {
        threads: Some(1),
        ..Default::default()
    };
    let mut whole = StableDiffusion::open(&dir, &opts).unwrap();
    let cond = whole.encode_text(&["a red chair", ""]).unwrap();
    let n = whole.latent_channels * 8 * 8;
    let x: Vec<f32> = (0..n)
        .map(|i| ((i * 37 % 101) as f32 / 50.0) - 1.0)
        .collect();
    let y: Vec<f32> = x.iter().map(|v| -0.5 * v).collect();
    let samples = [x.as_slice(), y.as_slice(), x.as_slice()];
    let conds = [&cond[0], &cond[1], &cond[1]];
    let want = whole.unet_batch(&samples, (8, 8), 500, &conds).unwrap();

    let mut split = StableDiffusion::open(&dir, &opts).unwrap();
    let wrong_above_two = |op: Op, b: usize, y: &mut [f32]| {
        if op == Op::Softmax && b > 2 {
            y[0] += 0.45;
        }
    };
    split
        .probe_provider_with((8, 8), 3, Some(&wrong_above_two))
        .unwrap();
    let got = split.unet_batch(&samples, (8, 8), 500, &conds).unwrap();
    assert_eq!(got.len(), 3);
    for (g, w) in got.iter().zip(&want) {
        let d = g
            .iter()
            .zip(w)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f32::max);
        assert!(d < 1e-5, "split run differs by {d}");
    }
    // The split happened: the probe saw the batch of 3 wrong and 2 right.
    assert_eq!(split.unet_max_batch(), Some(2));
    assert_eq!(whole.unet_max_batch(), None);
}

/// The probe runs once per latent size and growing batch: a provider right at a batch is right at
/// every smaller batch of that size, so the runs of a whole object (the null prompt's, the chain
/// points', the pseudo-ground truth's) and of later objects share it; a larger batch or another
/// latent size is probed again, and a split batch keeps its cap.
#[test]
fn a_probed_batch_covers_the_smaller_ones() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tiny-sd");
    let opts = ModelOptions {
        threads: Some(1),
        ..Default::default()
    };
    let mut sd = StableDiffusion::open(&dir, &opts).unwrap();
    let honest = |_: Op, _: usize, _: &mut [f32]| {};
    let probe_at = |sd: &mut StableDiffusion, hw, b| {
        sd.probe_provider_with(hw, b, Some(&honest)).unwrap();
        sd.probes_run()
    };
    assert_eq!(probe_at(&mut sd, (8, 8), 6), 1);
    for b in [1, 3, 6] {
        assert_eq!(probe_at(&mut sd, (8, 8), b), 1, "batch {b}");
    }
    assert_eq!(probe_at(&mut sd, (8, 8), 12), 2);
    assert_eq!(probe_at(&mut sd, (8, 8), 8), 2);
    assert_eq!(probe_at(&mut sd, (4, 4), 2), 3);
    assert_eq!(sd.unet_max_batch(), None);

    // Wrong above two items at six: split to two, and a later batch of four keeps the cap.
    let mut split = StableDiffusion::open(&dir, &opts).unwrap();
    let wrong_above_two = |op: Op, b: usize, y: &mut [f32]| {
        if op == Op::Softmax && b > 2 {
            y[0] += 0.45;
        }
    };
    split
        .probe_provider_with((8, 8), 6, Some(&wrong_above_two))
        .unwrap();
    split
        .probe_provider_with((8, 8), 4, Some(&wrong_above_two))
        .unwrap();
    assert_eq!(split.probes_run(), 1);
    assert_eq!(split.unet_max_batch(), Some(2));
}
