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
    #[arg(long, value_enum, default_value_t = Provider::Cpu)]
    pub provider: Provider,
}

pub fn run(a: Args) -> Result<()> {
    doctor(a.models.as_deref(), a.provider)
}

fn doctor(models: Option<&Path>, provider: Provider) -> Result<()> {
    let mut ok = true;
    match dreamscene::diffusion::runtime::info() {
        Ok(i) => {
            println!(
                "onnx runtime: {} (version {})",
                i.library.display(),
                i.version
            );
            println!("  providers: {}", i.providers.join(", "));
        }
        Err(e) => {
            println!("onnx runtime: {e}");
            ok = false;
        }
    }
    match models {
        None => println!(
            "models: none given (--models DIR or DREAMSCENE_MODELS); generation needs a Stable \
             Diffusion ONNX export, e.g. `optimum-cli export onnx --model \
             stabilityai/stable-diffusion-2-1-base DIR`"
        ),
        Some(dir) => {
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
                    ok = false;
                }
            }
        }
    }
    match Context::list_devices() {
        Ok(devs) if !devs.is_empty() => {
            for (i, (name, ty)) in devs.iter().enumerate() {
                println!("vulkan device {i}: {name} ({ty})");
            }
        }
        Ok(_) => {
            println!("vulkan: no device (install mesa-vulkan-drivers for the lavapipe CPU device)");
            ok = false;
        }
        Err(e) => {
            println!("vulkan: {e}");
            ok = false;
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
                    ok = false;
                }
            }
        }
        Err(e) => {
            println!("selected: none: {e}");
            ok = false;
        }
    }
    if !ok {
        bail!("the engine cannot run here (see above)");
    }
    Ok(())
}
