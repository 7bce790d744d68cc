//! The diffusion side through ONNX Runtime, with the tiny model directories the repo generates
//! (scripts/dev/make_tiny_sd.py): goldens computed by numpy, broken directories, the whole
//! tokenise → text encoder → UNet with CFG → MTS → decoded target chain, and the analytic prior,
//! whose exact noise prediction lets the guidance be checked to converge to a known target.
//! These tests need the ONNX Runtime library (scripts/setup.sh installs it); without it they fail.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::diffusion::guidance::{
    code_schedule, ism_gradient, mts_gradient, paper_schedule, pseudo_gt, sds_gradient, Cond,
    MtsRule, MtsSettings, NoisePredictor, OBJECT_MTS,
};
use dreamscene::diffusion::model::{
    Codec, Conditioning, Embedding, ModelOptions, StableDiffusion, UnetPredictor,
};
use dreamscene::diffusion::runtime;
use dreamscene::diffusion::target::{target_loss, Guide, Rule, ISM_DEFAULT};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn data(p: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(p)
}

fn open(dir: &str) -> StableDiffusion {
    StableDiffusion::open(
        &data(dir),
        &ModelOptions {
            threads: Some(1),
            ..Default::default()
        },
    )
    .unwrap_or_else(|e| panic!("{e}"))
}

fn golden(dir: &str) -> Value {
    serde_json::from_str(&std::fs::read_to_string(data(dir).join("golden.json")).unwrap()).unwrap()
}

fn floats(v: &Value) -> Vec<f64> {
    fn walk(v: &Value, out: &mut Vec<f64>) {
        match v {
            Value::Array(a) => a.iter().for_each(|x| walk(x, out)),
            Value::Number(n) => out.push(n.as_f64().unwrap()),
            _ => panic!("not a number: {v}"),
        }
    }
    let mut out = vec![];
    walk(v, &mut out);
    out
}

fn assert_close(got: &[f32], want: &[f64], tol: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    let worst = got
        .iter()
        .zip(want)
        .map(|(g, w)| (*g as f64 - w).abs() / (1.0 + w.abs()))
        .fold(0.0, f64::max);
    assert!(worst < tol, "{what}: worst error {worst:e} ≥ {tol:e}");
}

/// The UNet on the golden batch: sin(0.37 i) latents at t = 500 under the first two prompts.
fn check_unet_golden(sd: &mut StableDiffusion, a: &Embedding, b: &Embedding, tol: f64) {
    let lat: Vec<f32> = (0..2 * 256).map(|i| (i as f32 * 0.37).sin()).collect();
    let u = sd
        .unet_batch(&[&lat[..256], &lat[256..]], (8, 8), 500, &[a, b])
        .unwrap();
    let want = floats(&golden("tiny-sd")["unet"]["out_sample"]);
    assert_close(&u.concat(), &want, tol, "out_sample");
}

#[test]
fn runtime_reports_library_version_and_cpu_provider() {
    let info = runtime::info().unwrap_or_else(|e| panic!("{e}"));
    assert!(info.library.is_file());
    assert!(
        info.version.starts_with(runtime::EXPECTED_VERSION),
        "{info:?}"
    );
    assert!(
        info.providers.iter().any(|p| p == "CPUExecutionProvider"),
        "{:?}",
        info.providers
    );
}

#[test]
fn goldens_match_text_encoder_unet_and_vae() {
    let mut sd = open("tiny-sd");
    let g = golden("tiny-sd");
    assert_eq!(sd.latent_channels, 4);
    assert_eq!(sd.precision(), "fp32");
    let prompts: Vec<&str> = g["prompts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap())
        .collect();
    // Tokeniser: SD 2.1's padding ("!" = 0) from the directory's special-token files.
    let ids: Vec<Vec<i64>> = prompts
        .iter()
        .map(|p| sd.tokenizer.encode_padded(p))
        .collect();
    let want_ids: Vec<Vec<i64>> = g["input_ids"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| floats(r).into_iter().map(|v| v as i64).collect())
        .collect();
    assert_eq!(ids, want_ids);

    let out = sd.run_text_encoder(&ids).unwrap();
    assert_eq!(out.len(), 2, "last_hidden_state and pooler_output");
    assert_eq!(out[0].0, vec![3, 77, 32]);
    assert_close(
        &out[1].1,
        &floats(&g["pooler_output"]),
        1e-5,
        "pooler_output",
    );
    let last = &out[0].1;
    let sums: Vec<f32> = last.chunks(77 * 32).map(|c| c.iter().sum()).collect();
    assert_close(
        &sums,
        &floats(&g["last_hidden_state_sum"]),
        1e-4,
        "hidden sums",
    );
    let row1: Vec<f32> = last
        .chunks(77 * 32)
        .flat_map(|c| c[32..64].to_vec())
        .collect();
    assert_close(
        &row1,
        &floats(&g["last_hidden_state_row1"]),
        1e-5,
        "hidden row 1",
    );

    let emb = sd.encode_text(&prompts).unwrap();
    assert_eq!(emb[0].data, last[..77 * 32]);

    check_unet_golden(&mut sd, &emb[0], &emb[1], 5e-5);
    let lat: Vec<f32> = (0..2 * 256).map(|i| (i as f32 * 0.37).sin()).collect();

    let (img, hw) = sd.decode(&lat[..256], 1, (8, 8), Codec::Vae).unwrap();
    assert_eq!(hw, (64, 64));
    let sum: f64 = img.iter().map(|v| *v as f64).sum();
    let want_sum = g["vae_decoder"]["sample_sum"].as_f64().unwrap();
    assert!(
        (sum - want_sum).abs() < 1e-3 * (1.0 + want_sum.abs()),
        "{sum} vs {want_sum}"
    );
    assert_close(
        &img[..16],
        &floats(&g["vae_decoder"]["sample_first"]),
        1e-5,
        "decoded",
    );

    let image: Vec<f32> = (0..3 * 64 * 64)
        .map(|i| 0.8 * (i as f32 * 0.011).cos())
        .collect();
    let (z, zhw) = sd.encode(&image, 1, (64, 64), Codec::Vae).unwrap();
    assert_eq!(zhw, (8, 8));
    let want: Vec<f64> = floats(&g["vae_encoder"]["latent_unscaled_mean"])
        .iter()
        .map(|v| v * 0.18215)
        .collect();
    assert_close(
        &z,
        &want,
        1e-5,
        "encoded (mean of latent_parameters, scaled)",
    );

    // The tiny autoencoder shares the latent space: same results through Codec::Fast.
    assert!(sd.has_fast_codec());
    let (img2, _) = sd.decode(&lat[..256], 1, (8, 8), Codec::Fast).unwrap();
    assert_close(
        &img2,
        &img.iter().map(|v| *v as f64).collect::<Vec<_>>(),
        1e-4,
        "taesd decode",
    );
    let (z2, _) = sd.encode(&image, 1, (64, 64), Codec::Fast).unwrap();
    assert_close(&z2, &want, 1e-4, "taesd encode");
}

#[test]
fn whole_chain_runs_with_batched_unet_calls() {
    let mut sd = open("tiny-sd");
    let cond = Conditioning::new(
        &mut sd,
        "A DSLR photo of a wooden chair, front view",
        "unrealistic, blurry",
        Some("A DSLR photo of a red chair"),
    )
    .unwrap();
    assert_ne!(cond.positive, cond.null);
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let z: Vec<f32> = (0..256).map(|_| rng.gen_range(-1.0..1.0)).collect();
    let eps: Vec<f32> = (0..256).map(|_| rng.gen_range(-1.0..1.0)).collect();
    let ts = code_schedule(&OBJECT_MTS, 0, &mut rng);
    assert!(!ts.is_empty());
    let sched = sd.schedule.clone();
    let mut p = UnetPredictor {
        sd: &mut sd,
        cond: &cond,
        hw: (8, 8),
        runs: 0,
    };
    let g = mts_gradient(&mut p, &sched, &z, &eps, &ts, &MtsSettings::default()).unwrap();
    // One UNet run per point of the chain (t_start and each sampled t), conditions batched.
    assert_eq!(p.runs, ts.len() + 1);
    assert!(g.iter().all(|v| v.is_finite()) && g.iter().any(|v| *v != 0.0));
    // The same gradient from per-condition calls: batching changes nothing.
    struct OneByOne<'a, 'b>(&'a mut UnetPredictor<'b>);
    impl NoisePredictor for OneByOne<'_, '_> {
        fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
            conds
                .iter()
                .map(|c| self.0.predict(x, t, &[*c]).map(|mut v| v.remove(0)))
                .collect()
        }
    }
    let g1 = mts_gradient(
        &mut OneByOne(&mut p),
        &sched,
        &z,
        &eps,
        &ts,
        &MtsSettings::default(),
    )
    .unwrap();
    let worst = g
        .iter()
        .zip(&g1)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert!(worst < 1e-5, "batched vs single: {worst}");

    // Through the image-space target, for every rule.
    let render: Vec<f32> = (0..64 * 64 * 3).map(|i| ((i % 97) as f32) / 96.0).collect();
    for rule in [
        Rule::Mts { m: 4 },
        Rule::PseudoGt,
        Rule::Edit,
        Rule::Sds {
            t_min: 20,
            t_max: 980,
        },
        Rule::DreamTime {
            t_min: 20,
            t_max: 980,
            steps: 1000,
        },
        ISM_DEFAULT,
    ] {
        let mut guide = Guide::new(rule, OBJECT_MTS, MtsSettings::default(), Codec::Vae, 7);
        let t = guide
            .image_target(&mut sd, &cond, &render, 64, 64, 100)
            .unwrap_or_else(|e| panic!("{rule:?}: {e}"));
        assert_eq!((t.width, t.height, t.image.len()), (64, 64, 64 * 64 * 3));
        assert!(t.image.iter().all(|v| (0.0..=1.0).contains(v)), "{rule:?}");
        assert!(!t.timesteps.is_empty());
        // Deterministic for a seed.
        let mut again = Guide::new(rule, OBJECT_MTS, MtsSettings::default(), Codec::Vae, 7);
        let t2 = again
            .image_target(&mut sd, &cond, &render, 64, 64, 100)
            .unwrap();
        assert_eq!(t.image, t2.image, "{rule:?}");
    }
    // A wrong-sized render is refused.
    let mut guide = Guide::new(
        Rule::PseudoGt,
        OBJECT_MTS,
        MtsSettings::default(),
        Codec::Vae,
        7,
    );
    assert!(guide
        .image_target(&mut sd, &cond, &render[..10], 64, 64, 0)
        .is_err());
}

/// z*(prompt) as the script computed it with numpy.
fn zstar(i: usize) -> Vec<f32> {
    floats(&golden("analytic-sd")["zstar"][i])
        .into_iter()
        .map(|v| v as f32)
        .collect()
}

fn rms_dist(a: &[f32], b: &[f32]) -> f64 {
    (a.iter()
        .zip(b)
        .map(|(x, y)| ((x - y) as f64).powi(2))
        .sum::<f64>()
        / a.len() as f64)
        .sqrt()
}

#[test]
fn analytic_prior_is_exact() {
    let mut sd = open("analytic-sd");
    let g = golden("analytic-sd");
    assert_eq!(floats(&g["gate"]), vec![1.0, 1.0, 0.0]);
    let emb = sd.encode_text(&["a photo of a cat", ""]).unwrap();
    let z = zstar(0);
    let x: Vec<f32> = (0..256).map(|i| (i as f32 * 0.3).cos()).collect();
    for t in [5u32, 400, 950] {
        let ab = sd.schedule.alpha_bar(t as i64);
        let out = sd
            .unet_batch(&[&x, &x], (8, 8), t, &[&emb[0], &emb[1]])
            .unwrap();
        let want: Vec<f64> = x
            .iter()
            .zip(&z)
            .map(|(x, z)| (*x as f64 - ab.sqrt() * *z as f64) / (1.0 - ab).sqrt())
            .collect();
        assert_close(&out[0], &want, 1e-4, "ε for the cat prompt");
        assert!(
            out[1].iter().all(|v| *v == 0.0),
            "the empty prompt is uninformative"
        );
    }
}

/// Gradient descent on a latent with a guidance rule; returns the RMS distance to the target
/// before and after.
fn descend(
    sd: &mut StableDiffusion,
    cond: &Conditioning,
    s: &MtsSettings,
    which: &str,
    target: &[f32],
    steps: u32,
    lr: f32,
) -> (f64, f64, Vec<f32>) {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut z: Vec<f32> = (0..256).map(|_| rng.gen_range(-1.5..1.5)).collect();
    let start = rms_dist(&z, target);
    let sched = sd.schedule.clone();
    for step in 0..steps {
        let eps: Vec<f32> = (0..256).map(|_| rng.gen_range(-1.7..1.7)).collect();
        let mut p = UnetPredictor {
            sd,
            cond,
            hw: (8, 8),
            runs: 0,
        };
        let g = match which {
            "sds" => {
                let t = rng.gen_range(20..980);
                sds_gradient(&mut p, &sched, &z, &eps, t, s).unwrap()
            }
            "mts-code" => {
                let ts = code_schedule(&OBJECT_MTS, step * 10, &mut rng);
                mts_gradient(&mut p, &sched, &z, &eps, &ts, s).unwrap()
            }
            "ism" => {
                let t = rng.gen_range(100..500);
                ism_gradient(&mut p, &sched, &z, &eps, t - 80, t, 200, 5, s).unwrap()
            }
            "mts-paper" => {
                let ts = paper_schedule(&OBJECT_MTS, step * 10, 4, &mut rng);
                mts_gradient(&mut p, &sched, &z, &eps, &ts, s).unwrap()
            }
            "pseudo-gt" => {
                let ts = code_schedule(&OBJECT_MTS, step * 10, &mut rng);
                let x0 = pseudo_gt(&mut p, &sched, &z, &eps, &ts, s).unwrap();
                z.iter().zip(&x0).map(|(a, b)| a - b).collect()
            }
            _ => unreachable!(),
        };
        // A decaying step (a/(k0 + k)) averages out the noise that SDS with CFG carries.
        let k0 = steps as f32 / 10.0;
        let lr_k = lr * k0 / (k0 + step as f32);
        for (zi, gi) in z.iter_mut().zip(&g) {
            *zi -= lr_k * gi;
        }
    }
    (start, rms_dist(&z, target), z)
}

#[test]
fn guidance_drives_latent_and_image_to_the_analytic_target() {
    let mut sd = open("analytic-sd");
    let target = zstar(0);
    // Empty negative prompt: uninformative, so CFG keeps the target at z*(y).
    let cond = Conditioning::new(&mut sd, "a photo of a cat", "", None).unwrap();
    // SDS without CFG (scale 1); MTS in both forms and the pseudo-GT with the code's CFG 7.5.
    let mut report = vec![];
    let mut ok = true;
    for (rule, form, scale, lr, steps) in [
        ("sds", MtsRule::Code, 1.0, 2.0, 200),
        ("mts-code", MtsRule::Code, 7.5, 2.0, 200),
        ("mts-paper", MtsRule::Paper, 7.5, 2.0, 200),
        ("ism", MtsRule::Code, 7.5, 2.0, 200),
        ("pseudo-gt", MtsRule::Code, 7.5, 0.2, 100),
    ] {
        let s = MtsSettings {
            rule: form,
            guidance_scale: scale,
            ..Default::default()
        };
        let (start, end, _) = descend(&mut sd, &cond, &s, rule, &target, steps, lr);
        report.push(format!("{rule}: {start:.3} → {end:.4}"));
        eprintln!("{}", report.last().unwrap());
        ok &= end < 0.05 * start && end < 0.05;
    }
    assert!(ok, "RMS distance to z*: {report:?}");

    // With a content negative prompt, CFG moves the fixed point to z_neg + s (z_pos − z_neg).
    let cond = Conditioning::new(
        &mut sd,
        "a photo of a cat",
        "A DSLR photo of a cozy living room",
        None,
    )
    .unwrap();
    let (zp, zn) = (zstar(0), zstar(1));
    let s = MtsSettings::default();
    let cfg_target: Vec<f32> = zp
        .iter()
        .zip(&zn)
        .map(|(p, n)| n + s.guidance_scale as f32 * (p - n))
        .collect();
    let (start, end, _) = descend(&mut sd, &cond, &s, "sds", &cfg_target, 400, 4.0);
    eprintln!("sds, CFG 7.5 with a content negative: {start:.3} → {end:.4}");
    assert!(end < 0.05 * start, "SDS with CFG: {start:.3} → {end:.4}");

    // Image space: a free image (standing in for the renderer) fitted to the per-iteration target
    // D(z − g) reaches the decoded target D(z*).
    let cond = Conditioning::new(&mut sd, "a photo of a cat", "", None).unwrap();
    let (want_img, _) = sd.decode(&target, 1, (8, 8), Codec::Vae).unwrap();
    let want_img = dreamscene::diffusion::model::chw11_to_hwc01(&want_img, 64, 64);
    let mut img = vec![0.5f32; 64 * 64 * 3];
    let start = rms_dist(&img, &want_img);
    let mut guide = Guide::new(
        Rule::Mts { m: 4 },
        OBJECT_MTS,
        MtsSettings::default(),
        Codec::Fast,
        5,
    );
    let mut last_loss = f64::INFINITY;
    for step in 0..200 {
        let t = guide
            .image_target(&mut sd, &cond, &img, 64, 64, step)
            .unwrap();
        let (loss, grad) = target_loss(&img, &t.image, 1.0);
        last_loss = loss;
        let lr = 40.0 / (40.0 + step as f32);
        for (x, g) in img.iter_mut().zip(&grad) {
            *x = (*x - lr * g).clamp(0.0, 1.0);
        }
    }
    let end = rms_dist(&img, &want_img);
    eprintln!("image-space MTS: RMS to D(z*) {start:.3} → {end:.4}");
    assert!(
        end < 0.1 * start,
        "image RMS to D(z*): {start:.3} → {end:.4} (loss {last_loss:.2e})"
    );
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            copy_dir(&p, &to.join(e.file_name()));
        } else {
            std::fs::copy(&p, to.join(e.file_name())).unwrap();
        }
    }
}

#[test]
fn broken_model_directories_give_clear_errors() {
    let root = std::env::temp_dir().join(format!("ds-broken-{}", std::process::id()));
    let opts = ModelOptions::default();
    let fresh = |name: &str| {
        let d = root.join(name);
        let _ = std::fs::remove_dir_all(&d);
        copy_dir(&data("tiny-sd"), &d);
        d
    };
    let err = |d: &Path| StableDiffusion::open(d, &opts).err().expect("must fail");

    let e = err(&root.join("nowhere"));
    assert!(e.contains("not found"), "{e}");

    let d = fresh("no-index");
    std::fs::remove_file(d.join("model_index.json")).unwrap();
    let e = err(&d);
    assert!(
        e.contains("model_index.json") && e.contains("optimum-cli"),
        "{e}"
    );

    let d = fresh("no-unet");
    std::fs::remove_file(d.join("unet/model.onnx")).unwrap();
    let e = err(&d);
    assert!(
        e.contains("unet/model.onnx") && e.contains("missing"),
        "{e}"
    );

    let d = fresh("no-external-data");
    std::fs::remove_file(d.join("unet/model.onnx_data")).unwrap();
    let e = err(&d);
    assert!(e.contains("unet/model.onnx"), "{e}");

    let d = fresh("garbage");
    std::fs::write(d.join("vae_decoder/model.onnx"), b"not a protobuf at all").unwrap();
    let e = err(&d);
    assert!(
        e.contains("vae_decoder/model.onnx") && e.contains("cannot load"),
        "{e}"
    );

    // A model with the wrong interface: the text encoder where the UNet should be.
    let d = fresh("swapped");
    std::fs::copy(d.join("text_encoder/model.onnx"), d.join("unet/model.onnx")).unwrap();
    let e = err(&d);
    assert!(e.contains("unet/model.onnx") && e.contains("input"), "{e}");

    // The UNet of the analytic prior declares a float timestep and a fixed 8×8 latent: it loads,
    // and a 16×16 latent is refused with the declared shape named.
    let d = fresh("wrong-size");
    std::fs::copy(
        data("analytic-sd/unet/model.onnx"),
        d.join("unet/model.onnx"),
    )
    .unwrap();
    std::fs::copy(
        data("analytic-sd/unet/model.onnx_data"),
        d.join("unet/model.onnx_data"),
    )
    .unwrap();
    let mut sd = StableDiffusion::open(&d, &opts).unwrap();
    let emb = sd.encode_text(&["a cat"]).unwrap();
    let big = vec![0.0f32; 4 * 16 * 16];
    let e = sd
        .unet_batch(&[&big], (16, 16), 10, &[&emb[0]])
        .err()
        .unwrap();
    assert!(e.contains("sample") && e.contains("16"), "{e}");

    // A decoder whose static latent channels differ from the UNet's.
    let d = fresh("channels");
    std::fs::copy(
        data("broken/vae_decoder_8ch/model.onnx"),
        d.join("vae_decoder/model.onnx"),
    )
    .unwrap();
    let e = err(&d);
    assert!(
        e.contains("vae_decoder/model.onnx") && e.contains("has 8 at axis 1"),
        "{e}"
    );

    let d = fresh("bad-scheduler");
    std::fs::write(
        d.join("scheduler/scheduler_config.json"),
        "{\"beta_schedule\": 3",
    )
    .unwrap();
    let e = err(&d);
    assert!(e.contains("scheduler_config.json"), "{e}");

    let d = fresh("bad-vocab");
    std::fs::write(d.join("tokenizer/merges.txt"), "#version: 0.2\na\n").unwrap();
    let e = err(&d);
    assert!(e.contains("merges.txt"), "{e}");

    std::fs::remove_dir_all(&root).ok();
}

fn cli(args: &[&str], env: &[(&str, &str)]) -> (bool, String) {
    let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_dreamscene"));
    c.args(args).env_remove("DREAMSCENE_MODELS");
    for (k, v) in env {
        c.env(k, v);
    }
    let o = c.output().unwrap();
    (
        o.status.success(),
        format!(
            "{}{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        ),
    )
}

#[test]
fn cli_doctor_and_unet_bench() {
    let tiny = data("tiny-sd");
    let tiny = tiny.to_str().unwrap();
    let (ok, out) = cli(&["doctor", "--models", tiny], &[]);
    assert!(ok, "{out}");
    assert!(
        out.contains("onnx runtime:") && out.contains("CPUExecutionProvider"),
        "{out}"
    );
    assert!(out.contains("fp32") && out.contains("8x8 latents"), "{out}");
    // Which providers can run, and which one auto picks on this machine and why.
    use dreamscene::diffusion::runtime::{choose_auto, gpu_facts};
    assert!(out.contains("provider cpu: can run"), "{out}");
    for p in ["cuda", "webgpu"] {
        assert!(out.contains(&format!("provider {p}: ")), "{out}");
    }
    // Each provider in one line a user can act on: a WebGPU provider whose Dawn accepts no
    // adapter (Debian 12's lavapipe) says so, without ONNX Runtime's and Dawn's source paths.
    assert!(
        !out.contains("onnxruntime_src") && !out.contains("dawn-src"),
        "{out}"
    );
    if out.contains("provider webgpu: cannot run") {
        assert!(
            !out.contains("XDG_RUNTIME_DIR") && !out.contains("ArrayDynamicIndexing"),
            "{out}"
        );
    }
    let (auto, why) = choose_auto(gpu_facts());
    let line = format!("auto picks {}: {why}", format!("{auto:?}").to_lowercase());
    assert!(out.contains(&line), "{line} not in {out}");
    assert!(
        !out.contains("missing:") && !out.contains("optional:"),
        "{out}"
    );
    // Without a model directory, doctor says what is missing and how to get it.
    let (_, out) = cli(&["doctor"], &[]);
    assert!(
        out.contains("models: none given") && out.contains("optimum-cli"),
        "{out}"
    );

    let (ok, out) = cli(
        &["bench", "--unet", "--models", tiny, "--json", "--runs", "2"],
        &[],
    );
    assert!(ok, "{out}");
    let v: Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
    let u = &v["unet"];
    for b in ["1", "2", "3"] {
        assert!(u["unet_ms"][b].as_f64().unwrap() > 0.0, "{out}");
    }
    for k in [
        "text_encoder_ms",
        "vae_encode_ms",
        "vae_decode_ms",
        "taesd_decode_ms",
    ] {
        assert!(u[k].as_f64().unwrap() > 0.0, "{k}: {out}");
    }
    assert_eq!(u["latent"], serde_json::json!([8, 8]));

    let (ok, out) = cli(&["bench", "--unet"], &[]);
    assert!(!ok && out.contains("--models"), "{out}");
    // The help of the sd path reads as text: no rustdoc links, the conversions named.
    for cmd in ["bench", "doctor"] {
        let (ok, out) = cli(&[cmd, "--help"], &[]);
        assert!(ok && out.contains("--provider"), "{out}");
        assert!(
            !out.contains("[`"),
            "a rustdoc link in `{cmd} --help`: {out}"
        );
    }
    let (_, out) = cli(&["bench", "--help"], &[]);
    assert!(
        out.contains("conversions") && out.contains("--generate --prior sd"),
        "{out}"
    );
    let (ok, out) = cli(&["doctor", "--models", "/nonexistent/models"], &[]);
    assert!(
        !ok && out.contains("/nonexistent/models: model directory not found"),
        "{out}"
    );
    // A missing library is named, with the way to install it.
    let (ok, out) = cli(
        &["bench", "--unet", "--models", tiny],
        &[("DREAMSCENE_ORT_LIB", "/no/such/libonnxruntime.so")],
    );
    assert!(
        !ok && out.contains("DREAMSCENE_ORT_LIB=/no/such/libonnxruntime.so: no such file"),
        "{out}"
    );
    // CUDA asked of a CPU-only library: a clear error, not a silent CPU fallback.
    let (ok, out) = cli(
        &["bench", "--unet", "--models", tiny, "--provider", "cuda"],
        &[],
    );
    let has_cuda = runtime::available_providers()
        .unwrap()
        .iter()
        .any(|p| p == "CUDAExecutionProvider");
    if has_cuda {
        assert!(
            ok,
            "a CUDA-enabled library must run the tiny models on CUDA: {out}"
        );
    } else {
        assert!(!ok && out.contains("no CUDA provider"), "{out}");
    }
}

#[test]
fn fp16_export_loads_and_matches_the_goldens() {
    let d = std::env::temp_dir().join(format!("ds-fp16-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    copy_dir(&data("tiny-sd"), &d);
    for f in ["model.onnx", "model.onnx_data"] {
        std::fs::copy(data("fp16-unet").join(f), d.join("unet").join(f)).unwrap();
    }
    let mut sd = StableDiffusion::open(&d, &ModelOptions::default()).unwrap();
    assert_eq!(sd.precision(), "fp16");
    let emb = sd
        .encode_text(&["a photo of a cat", "A DSLR photo of a cozy living room"])
        .unwrap();
    // Half precision: inputs and outputs round to 11 significant bits.
    check_unet_golden(&mut sd, &emb[0], &emb[1], 1e-2);
    std::fs::remove_dir_all(&d).ok();
}

/// `bench --generate --prior sd` splits an iteration of the tiny models at both sizes: 36 UNet
/// items in 5 runs (the null prompt's run, then 4 chain points of 4 views × 2 prompts), the
/// measured parts (models, conversions, kernels) never more than the whole, the host share the
/// conversions, guidance maths and the rest over the whole; `--warmups` and `--runs` are taken.
#[test]
fn cli_sd_iteration_split() {
    let tiny = data("tiny-sd");
    let (ok, out) = cli(
        &[
            "bench",
            "--generate",
            "--prior",
            "sd",
            "--models",
            tiny.to_str().unwrap(),
            "--provider",
            "cpu",
            "--modes",
            "batched",
            "--runs",
            "1",
            "--warmups",
            "1",
            "--json",
        ],
        &[],
    );
    assert!(ok, "{out}");
    let v: Value = serde_json::from_str(out.lines().last().unwrap()).unwrap();
    let figs = v["sd_iteration"].as_array().unwrap();
    let sizes: Vec<u64> = figs.iter().map(|f| f["size"].as_u64().unwrap()).collect();
    assert_eq!(sizes, vec![256, 512], "{out}");
    for f in figs {
        assert_eq!(f["mode"], "batched", "{out}");
        assert_eq!(f["provider"], "cpu", "{out}");
        assert_eq!(f["unet_items"].as_f64(), Some(36.0), "{out}");
        assert_eq!(f["unet_runs"].as_f64(), Some(5.0), "{out}");
        let ms = |k: &str| f[k].as_f64().unwrap();
        let measured = ms("text_encoder_ms")
            + ms("unet_ms")
            + ms("vae_ms")
            + ms("conversions_ms")
            + ms("kernels_ms");
        assert!(ms("unet_ms") > 0.0 && ms("conversions_ms") > 0.0, "{out}");
        // Each part measured once: together no more than the iteration, and the conversions
        // inside the prior's time (its remainder, the guidance maths, is not negative).
        assert!(measured <= ms("wall_ms") * 1.001, "{out}");
        assert!(ms("prior_host_ms") >= 0.0, "{out}");
        let host = ms("conversions_ms") + ms("prior_host_ms") + ms("host_ms");
        let share = ms("host_share");
        assert!(
            (share - host / ms("wall_ms")).abs() < 1e-9 && (0.0..1.0).contains(&share),
            "{out}"
        );
    }
    let (ok, out) = cli(
        &["bench", "--generate", "--prior", "sd", "--warmups", "x"],
        &[],
    );
    assert!(!ok && out.contains("--warmups"), "{out}");
}
