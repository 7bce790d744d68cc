//! The loader against what the real exporter writes: a tiny random-weight pipeline of Stable
//! Diffusion's block types exported by `optimum-cli export onnx --task text-to-image` in fp32 and
//! fp16 (scripts/dev/make_exported_fixture.sh, committed under tests/data/exported-sd), run
//! through `StableDiffusion` and compared with PyTorch's outputs for the same inputs.
//! Needs the ONNX Runtime library (scripts/setup.sh installs it); without it this fails.
use dreamscene::diffusion::model::{Codec, Embedding, ModelOptions, StableDiffusion};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/exported-sd")
}

fn floats(v: &Value) -> Vec<f32> {
    v.as_array()
        .expect("a list of numbers")
        .iter()
        .map(|x| x.as_f64().expect("a number") as f32)
        .collect()
}

/// Largest difference relative to the reference's largest magnitude (at least 1).
fn rel_err(got: &[f32], want: &[f32], what: &str) -> f64 {
    assert_eq!(got.len(), want.len(), "{what}: lengths differ");
    let scale = want.iter().fold(1.0f64, |m, v| m.max(v.abs() as f64));
    got.iter()
        .zip(want)
        .map(|(a, b)| (*a as f64 - *b as f64).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn exporter_output_loads_and_matches_pytorch_in_fp32_and_fp16() {
    let golden: Value =
        serde_json::from_str(&std::fs::read_to_string(dir().join("golden.json")).unwrap()).unwrap();
    let prompt = golden["prompt"].as_str().unwrap();
    // fp32 agrees with PyTorch to float rounding (measured: below 1e-6); fp16 stores weights and
    // activations with 11 significant bits, and errors of a few parts in a thousand build up
    // through the layers (measured: up to 1.7e-3).
    for (variant, precision, tol) in [("fp32", "fp32", 1e-5), ("fp16", "fp16", 1e-2)] {
        let opts = ModelOptions {
            threads: Some(1),
            ..Default::default()
        };
        let mut sd = StableDiffusion::open(&dir().join(variant), &opts)
            .unwrap_or_else(|e| panic!("{variant}: {e}"));
        assert_eq!(sd.precision(), precision);
        let mut errs = vec![];
        assert!(sd.has_vae_encoder());
        assert_eq!(sd.default_latent_size(), (8, 8));

        // Our tokenizer gives the ids transformers' CLIPTokenizer gave.
        let ids: Vec<i64> = golden["input_ids"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_i64().unwrap())
            .collect();
        assert_eq!(sd.tokenizer.encode_padded(prompt), ids, "{variant}");

        let emb = sd.encode_text(&[prompt]).unwrap().remove(0);
        let want = floats(&golden["last_hidden_state"]);
        let e = rel_err(&emb.data, &want, "text encoder");
        assert!(e < tol, "{variant} text encoder: {e}");
        errs.push(("text encoder", e));

        // The UNet on PyTorch's embedding, so its error is its own.
        let cond = Embedding {
            data: want,
            seq: 77,
            hidden: emb.hidden,
        };
        let x = floats(&golden["sample"]);
        let t = golden["timestep"].as_u64().unwrap() as u32;
        let out = sd.unet_batch(&[&x], (8, 8), t, &[&cond]).unwrap();
        let e = rel_err(&out[0], &floats(&golden["out_sample"]), "unet");
        assert!(e < tol, "{variant} unet: {e}");
        errs.push(("unet", e));

        let (img, hw) = sd
            .decode(&floats(&golden["latent"]), 1, (4, 4), Codec::Vae)
            .unwrap();
        assert_eq!(hw, (32, 32));
        let e = rel_err(&img, &floats(&golden["decoded"]), "vae decoder");
        assert!(e < tol, "{variant} vae decoder: {e}");
        errs.push(("vae decoder", e));

        let (z, hw) = sd
            .encode(&floats(&golden["image"]), 1, (32, 32), Codec::Vae)
            .unwrap();
        assert_eq!(hw, (4, 4));
        let e = rel_err(&z, &floats(&golden["latent_mean"]), "vae encoder");
        assert!(e < tol, "{variant} vae encoder: {e}");
        errs.push(("vae encoder", e));
        let shown: Vec<String> = errs.iter().map(|(k, e)| format!("{k} {e:.1e}")).collect();
        eprintln!(
            "{variant}: relative errors against PyTorch: {}",
            shown.join(", ")
        );
    }
}

/// The batched prior (one autoencoder encode and decode and one UNet run per guidance step for
/// all views of an iteration) gives each view the target that running the views one by one
/// gives it: same noise, same timesteps, the same image up to float rounding.
#[test]
fn batched_image_targets_equal_the_per_view_targets() {
    use dreamscene::diffusion::guidance::{MtsSettings, OBJECT_MTS};
    use dreamscene::diffusion::model::Conditioning;
    use dreamscene::diffusion::target::{Guide, Rule};
    use rand::{Rng, SeedableRng};
    let opts = ModelOptions {
        threads: Some(1),
        ..Default::default()
    };
    let mut sd = StableDiffusion::open(&dir().join("fp32"), &opts).unwrap();
    let front = Conditioning::new(&mut sd, "a red chair, front view", "blurry", None).unwrap();
    let back = Conditioning::new(&mut sd, "a red chair, back view", "blurry", None).unwrap();
    let conds = [&front, &back, &front];
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let renders: Vec<Vec<f32>> = (0..3)
        .map(|_| (0..32 * 32 * 3).map(|_| rng.gen::<f32>()).collect())
        .collect();
    let refs: Vec<&[f32]> = renders.iter().map(Vec::as_slice).collect();
    for rule in [Rule::Mts { m: 4 }, Rule::PseudoGt] {
        let guide = || Guide::new(rule, OBJECT_MTS, MtsSettings::default(), Codec::Vae, 7);
        // One view's prompts a run: the views one by one.
        sd.set_unet_max_batch(Some(3));
        sd.take_times();
        let mut one = guide();
        let per = one
            .image_targets(&mut sd, &conds, &refs, 32, 32, 10)
            .unwrap();
        let split = sd.take_times();
        sd.set_unet_max_batch(None);
        let mut all = guide();
        let batched = all
            .image_targets(&mut sd, &conds, &refs, 32, 32, 10)
            .unwrap();
        let joint = sd.take_times();
        assert_eq!(batched.len(), 3);
        assert_eq!(one.rng_position(), all.rng_position(), "{rule:?}");
        // One run per chain point (t_start and each sampled timestep) for all three views.
        let points = batched[0].timesteps.len() + 1;
        let points = if rule == Rule::PseudoGt { 2 } else { points };
        assert_eq!(joint.unet_runs, points, "{rule:?}");
        // The start point asks for the null prompt alone (3 items: one run of at most 3); each
        // sampled point for its rule's prompts (MTS: 3, the pseudo ground truth's last point: 2).
        let per_point = if rule == Rule::PseudoGt { 2 } else { 3 };
        assert_eq!(split.unet_runs, 1 + per_point * (points - 1), "{rule:?}");
        assert_eq!(
            joint.unet_items,
            3 * (1 + per_point * (points - 1)),
            "{rule:?}"
        );
        assert_eq!(joint.unet_items, split.unet_items, "{rule:?}");
        for (i, (a, b)) in per.iter().zip(&batched).enumerate() {
            assert_eq!(a.timesteps, b.timesteps, "{rule:?} view {i}");
            // The UNet over a batch of 9 against 3 batches of 3: float rounding only.
            let e = rel_err(&b.image, &a.image, "batched target");
            assert!(e < 1e-5, "{rule:?} view {i}: relative error {e}");
        }
        // The views differ, so a batch that mixed them up could not pass.
        assert!(rel_err(&per[0].image, &per[1].image, "views") > 1e-3);
    }
}
