//! `dreamscene doctor`: what this machine can run.
use anyhow::{bail, Result};
use dreamscene::diffusion::runtime::Provider;
use dreamscene::gpu::Context;
use dreamscene::splat::raster::Rasterizer;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// A Stable Diffusion ONNX model directory to check.
    #[arg(long, env = "DREAMSCENE_MODELS")]
    pub models: Option<PathBuf>,
    /// ONNX Runtime execution provider.
    #[arg(long, value_enum, default_value_t = Provider::Auto)]
    pub provider: Provider,
}

pub fn run(a: Args) -> Result<()> {
    doctor(a.models.as_deref(), a.provider)
}

/// One component's verdict: what it serves and why it cannot run, if so.
struct Verdict {
    what: &'static str,
    problem: Option<String>,
    /// Asked for on the command line (--models, --provider): a problem fails the command.
    asked: bool,
}

fn doctor(models: Option<&Path>, provider: Provider) -> Result<()> {
    let mut render_problem: Option<String> = None;
    let mut sd_problem: Option<String> = None;
    match dreamscene::diffusion::runtime::info() {
        Ok(i) => {
            println!(
                "onnx runtime: {} (version {})",
                i.library.display(),
                i.version
            );
            println!("  providers: {}", i.providers.join(", "));
            use dreamscene::diffusion::runtime::{check_provider, choose_auto, gpu_facts};
            let name = |p: Provider| format!("{p:?}").to_lowercase();
            // Which providers can run here, which one `auto` takes and why.
            let mut failed = vec![];
            for p in [Provider::Cpu, Provider::Cuda, Provider::Webgpu] {
                match check_provider(p) {
                    Ok(()) => println!("  provider {}: can run", name(p)),
                    Err(e) => {
                        println!("  provider {}: cannot run: {e}", name(p));
                        failed.push(p);
                    }
                }
            }
            let (auto, why) = choose_auto(gpu_facts());
            println!("  auto picks {}: {why}", name(auto));
            let asked = provider.resolved();
            if failed.contains(&asked) {
                sd_problem = Some(format!("provider {} unavailable", name(asked)));
            }
        }
        Err(e) => {
            println!("onnx runtime: {e}");
            sd_problem = Some("no ONNX Runtime library".into());
        }
    }
    match models {
        None => {
            println!(
                "models: none given (--models DIR or DREAMSCENE_MODELS); generation needs a \
                 Stable Diffusion ONNX export, e.g. `optimum-cli export onnx --model \
                 stabilityai/stable-diffusion-2-1-base --task text-to-image DIR` (the README \
                 has the recipe)"
            );
            sd_problem.get_or_insert("no model directory given".into());
        }
        Some(dir) if sd_problem.is_none() => {
            let opts = dreamscene::diffusion::model::ModelOptions {
                provider,
                threads: None,
            };
            match dreamscene::diffusion::model::StableDiffusion::open(dir, &opts) {
                Ok(sd) => {
                    let (h, w) = sd.default_latent_size();
                    println!(
                        "models: {} ({}, {} latent channels, {}x{} latents, tokenizer {} tokens)",
                        dir.display(),
                        sd.precision(),
                        sd.latent_channels,
                        h,
                        w,
                        sd.tokenizer.vocab_size(),
                    );
                    if !sd.has_vae_encoder() {
                        println!("  missing: vae_encoder/ (needed to guide renders)");
                    }
                    if !sd.has_fast_codec() {
                        println!(
                            "  optional: taesd_encoder/ + taesd_decoder/ (a tiny autoencoder) \
                             would make the per-iteration encode/decode cheaper"
                        );
                    }
                }
                Err(e) => {
                    println!("models: {e}");
                    sd_problem = Some(format!("the models in {} do not load", dir.display()));
                }
            }
        }
        Some(dir) => println!(
            "models: {} not checked (ONNX Runtime cannot run them here, see above)",
            dir.display()
        ),
    }
    match Context::list_devices() {
        Ok(devs) if !devs.is_empty() => {
            for (i, (name, ty)) in devs.iter().enumerate() {
                println!("vulkan device {i}: {name} ({ty})");
            }
        }
        Ok(_) => {
            println!("vulkan: no device (install mesa-vulkan-drivers for the lavapipe CPU device)");
            render_problem = Some("no Vulkan device".into());
        }
        Err(e) => {
            println!("vulkan: {e}");
            render_problem = Some("no Vulkan".into());
        }
    }
    match Context::new() {
        Ok(ctx) => {
            let i = ctx.info();
            println!(
                "selected: {} ({}), Vulkan {}, driver {}",
                i.name, i.device_type, i.api_version, i.driver
            );
            println!("  subgroup size {}, float atomics {}, storage buffer range {} MiB, shared memory {} KiB",
                i.subgroup_size, if i.float_atomics { "native" } else { "compare-and-swap fallback" },
                i.max_storage_buffer_range >> 20, i.max_shared_memory >> 10);
            println!(
                "  validation layer: {}",
                if i.validation { "on" } else { "off" }
            );
            match Rasterizer::new(&ctx) {
                Ok(_) => println!("  kernels: all pipelines built"),
                Err(e) => {
                    println!("  kernels: {e}");
                    render_problem.get_or_insert("the kernels do not build".into());
                }
            }
        }
        Err(e) => {
            println!("selected: none: {e}");
            render_problem.get_or_insert("no usable Vulkan device".into());
        }
    }
    let sd_asked = models.is_some() || !matches!(provider, Provider::Cpu | Provider::Auto);
    let verdicts = [
        Verdict {
            what: "rendering, fit, demo, draft generation (shape prior)",
            problem: render_problem.clone(),
            asked: true,
        },
        Verdict {
            what: "Stable Diffusion generation (--prior sd)",
            problem: match (&render_problem, sd_problem) {
                (_, Some(p)) => Some(p),
                (Some(_), None) => Some("needs Vulkan too".into()),
                (None, None) => None,
            },
            asked: sd_asked,
        },
    ];
    println!("verdict:");
    let mut failed = vec![];
    for v in &verdicts {
        match &v.problem {
            None => println!("  ready: {}", v.what),
            Some(p) => {
                println!("  not ready: {} ({p})", v.what);
                if v.asked {
                    failed.push(v.what);
                }
            }
        }
    }
    if !failed.is_empty() {
        bail!("not ready here: {}", failed.join("; "));
    }
    Ok(())
}
