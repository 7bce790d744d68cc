//! The WebGPU execution provider against the CPU provider on every tiny export
//! (tests/data/exported-sd, fp32 and fp16: text encoder, UNet, VAE encoder and decoder), on
//! Mesa 25's lavapipe, which scripts/setup.sh installs privately (Dawn rejects Debian 12's
//! Mesa 22.3). The comparison runs in a child process that sees that driver (its env.sh sets the
//! Vulkan driver files and the library path, which the dynamic loader reads at start). Skipped,
//! with the reason, only when the private Mesa 25 is absent.
use dreamscene::diffusion::model::{Codec, Embedding, ModelOptions, StableDiffusion};
use dreamscene::diffusion::runtime::Provider;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn mesa_env() -> Option<PathBuf> {
    let base = std::env::var_os("XDG_DATA_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".local/share")))?;
    let env = base.join("dreamscene/mesa25/env.sh");
    env.is_file().then_some(env)
}

#[test]
fn webgpu_matches_cpu_on_every_tiny_export() {
    let Some(env) = mesa_env() else {
        eprintln!("skipped: Mesa 25 lavapipe is not installed (run `bash scripts/setup.sh`)");
        return;
    };
    let exe = std::env::current_exe().unwrap();
    let o = Command::new("bash")
        .arg("-c")
        .arg(format!(
            ". '{}' && exec '{}' --exact compare_providers --ignored --nocapture",
            env.display(),
            exe.display()
        ))
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    let err = String::from_utf8_lossy(&o.stderr);
    eprintln!("{err}");
    assert!(o.status.success(), "{out}\n{err}");
    assert!(
        out.contains("1 passed"),
        "the comparison did not run: {out}"
    );
}

fn max_rel(a: &[f32], b: &[f32]) -> f64 {
    assert_eq!(a.len(), b.len(), "the outputs differ in length");
    let scale = b.iter().fold(1e-6f64, |m, v| m.max(v.abs() as f64));
    a.iter()
        .zip(b)
        .map(|(x, y)| (*x as f64 - *y as f64).abs())
        .fold(0.0, f64::max)
        / scale
}

/// Run by the test above in a process that sees Mesa 25.
#[test]
#[ignore = "run by webgpu_matches_cpu_on_every_tiny_export with Mesa 25's environment"]
fn compare_providers() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/exported-sd");
    let golden: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("golden.json")).unwrap()).unwrap();
    let f = |k: &str| -> Vec<f32> {
        golden[k]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap() as f32)
            .collect()
    };
    // Measured on Mesa 25.0.7 lavapipe (shared/reference/webgpu-ep.md): fp32 within 1e-4 of the
    // CPU provider; fp16 within 2.8e-2 (its Conv accumulates in fp16). Every fp32 model runs;
    // of the fp16 export only the UNet, where half precision matters (its Conv accumulation and
    // attention; the other fp16 graphs use the same kernels), to keep the test short: each
    // WebGPU run on lavapipe compiles its shaders first.
    for (variant, tol, all) in [("fp32", 1e-3, true), ("fp16", 6e-2, false)] {
        let open = |provider| {
            StableDiffusion::open(
                &dir.join(variant),
                &ModelOptions {
                    provider,
                    threads: Some(1),
                },
            )
            .unwrap_or_else(|e| panic!("{variant} {provider:?}: {e}"))
        };
        let t = golden["timestep"].as_u64().unwrap() as u32;
        let data = f("last_hidden_state");
        let cond = Embedding {
            hidden: data.len() / 77,
            data,
            seq: 77,
        };
        let mut results = vec![];
        for provider in [Provider::Cpu, Provider::Webgpu] {
            let started = std::time::Instant::now();
            let mut sd = open(provider);
            let unet = sd
                .unet_batch(&[&f("sample")], (8, 8), t, &[&cond])
                .unwrap()
                .remove(0);
            let mut r = vec![unet];
            if all {
                let emb = sd
                    .encode_text(&[golden["prompt"].as_str().unwrap()])
                    .unwrap();
                r.push(emb[0].data.clone());
                r.push(sd.decode(&f("latent"), 1, (4, 4), Codec::Vae).unwrap().0);
                r.push(sd.encode(&f("image"), 1, (32, 32), Codec::Vae).unwrap().0);
            }
            eprintln!(
                "{variant} {provider:?}: {:.1} s",
                started.elapsed().as_secs_f64()
            );
            results.push(r);
        }
        let mut differs = false;
        for (k, name) in ["unet", "text encoder", "vae decoder", "vae encoder"]
            .iter()
            .enumerate()
            .take(results[0].len())
        {
            let e = max_rel(&results[1][k], &results[0][k]);
            eprintln!("{variant} {name}: webgpu vs cpu {e:.1e}");
            assert!(e < tol, "{variant} {name}: {e} (tolerance {tol})");
            differs |= e > 0.0;
        }
        // Bit-identical outputs everywhere would mean the sessions fell back to the CPU.
        assert!(
            differs,
            "{variant}: the WebGPU sessions ran on the CPU provider"
        );
    }
}
