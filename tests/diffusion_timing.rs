//! How the sd pipeline's timings split a call ([`ModelTimes`], which `bench --generate --prior sd`
//! reports): each model's time is ONNX Runtime's `session.run` alone, and the host's preparation
//! of inputs and outputs around it is counted once, as conversions. A planted slow conversion
//! must land in the conversions and nowhere else.
//! These tests need the ONNX Runtime library (scripts/setup.sh installs it); without it they fail.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::diffusion::guidance::{MtsSettings, OBJECT_MTS};
use dreamscene::diffusion::model::{
    Codec, Conditioning, ModelOptions, ModelTimes, StableDiffusion,
};
use dreamscene::diffusion::target::{Guide, Rule};
use std::path::Path;
use std::time::{Duration, Instant};

fn open(dir: &str) -> StableDiffusion {
    let d = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(dir);
    StableDiffusion::open(
        &d,
        &ModelOptions {
            threads: Some(1),
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

/// Encodes the prompts, then the image targets of two 64² views (one encode, the UNet runs of
/// the guidance, one decode): the times booked, the model runs made and the wall time of it all.
fn one_iteration(sd: &mut StableDiffusion) -> (ModelTimes, usize, f64) {
    sd.take_times();
    let t0 = Instant::now();
    let cond = Conditioning::new(sd, "a photo of a cat", "blurry", None).unwrap();
    let render: Vec<f32> = (0..64 * 64 * 3).map(|i| ((i % 97) as f32) / 96.0).collect();
    let mut guide = Guide::new(
        Rule::Mts { m: 4 },
        OBJECT_MTS,
        MtsSettings::default(),
        Codec::Vae,
        7,
    );
    let targets = guide
        .image_targets(sd, &[&cond, &cond], &[&render, &render], 64, 64, 100)
        .unwrap();
    let wall = t0.elapsed().as_secs_f64();
    assert_eq!(targets.len(), 2, "one target a view");
    let m = sd.take_times();
    // Text encoder, VAE encode and decode, and the UNet's runs.
    (m, 3 + m.unet_runs, wall)
}

fn models(m: &ModelTimes) -> f64 {
    m.text_encoder + m.unet + m.autoencoder
}

/// The parts never add up to more than the call (nothing counted twice), and a conversion made
/// slower by a planted delay shows in the conversions, at least the delay once per model run,
/// while the models' own time stays below what the call had left for them.
#[test]
fn conversions_are_booked_outside_the_models_time() {
    let mut sd = open("tiny-sd");
    one_iteration(&mut sd); // warm-up: first runs allocate
    let (plain, runs, wall) = one_iteration(&mut sd);
    assert!(runs >= 4 && plain.unet_runs >= 1, "{plain:?}");
    assert!(
        plain.unet > 0.0 && plain.autoencoder > 0.0 && plain.text_encoder > 0.0,
        "every model timed: {plain:?}"
    );
    assert!(plain.conversions > 0.0, "{plain:?}");
    assert!(
        models(&plain) + plain.conversions <= wall * 1.001 + 1e-4,
        "{plain:?} in {wall} s"
    );

    let delay = Duration::from_millis(40);
    sd.plant_slow_conversion(delay);
    let (slow, slow_runs, slow_wall) = one_iteration(&mut sd);
    assert_eq!(slow_runs, runs, "the same runs");
    let planted = slow_runs as f64 * delay.as_secs_f64();
    assert!(
        slow.conversions >= planted,
        "the planted {planted} s must be in the conversions: {slow:?}"
    );
    assert!(
        models(&slow) + slow.conversions <= slow_wall * 1.001 + 1e-4,
        "counted twice: {slow:?} in {slow_wall} s"
    );
    assert!(
        slow.unet <= slow_wall - planted,
        "the UNet's time holds conversions: {slow:?}"
    );
}

/// An fp16 export converts its inputs to f16 and its outputs back: that work is booked as
/// conversions too, and the image target is the same with and without the planted delay.
#[test]
fn fp16_conversions_are_booked_and_results_unchanged() {
    let mut sd = open("exported-sd/fp16");
    assert_eq!(sd.precision(), "fp16");
    let cond = Conditioning::new(&mut sd, "a chair", "", None).unwrap();
    let render: Vec<f32> = (0..64 * 64 * 3).map(|i| ((i % 89) as f32) / 88.0).collect();
    let run = |sd: &mut StableDiffusion| {
        let mut guide = Guide::new(
            Rule::PseudoGt,
            OBJECT_MTS,
            MtsSettings::default(),
            Codec::Vae,
            3,
        );
        guide
            .image_target(sd, &cond, &render, 64, 64, 10)
            .unwrap()
            .image
    };
    sd.take_times();
    let plain = run(&mut sd);
    let m = sd.take_times();
    assert!(m.conversions > 0.0 && m.unet > 0.0, "{m:?}");
    sd.plant_slow_conversion(Duration::from_millis(5));
    assert_eq!(run(&mut sd), plain, "a slower conversion changes nothing");
    let slow = sd.take_times();
    assert!(
        slow.conversions >= 0.005 * (2 + slow.unet_runs) as f64,
        "{slow:?}"
    );
}
