//! `dreamscene bench`: kernel, generation and diffusion-model timings.
use super::open_device;
use anyhow::{anyhow, bail, Result};
use dreamscene::diffusion::runtime::Provider;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Print one JSON object instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Time the UNet (batches 1–3), text encoder and VAE of --models instead of the kernels.
    #[arg(long)]
    pub unet: bool,
    /// Time one formation iteration of object generation (oracle prior, 4 views) at 256²
    /// and 512² with 20k and 100k Gaussians, split into kernel, prior and host time.
    #[arg(long, conflicts_with = "unet")]
    pub generate: bool,
    /// The prior of --generate: oracle (a random reference cloud), or sd (the models of
    /// --models: the iteration split into text encoder, UNet and autoencoder (ONNX Runtime's
    /// runs alone), conversions of their inputs and outputs, guidance maths, kernels and host,
    /// batched and per view).
    #[arg(long, default_value = "oracle", value_parser = ["oracle", "sd"], requires = "generate")]
    pub prior: String,
    /// Which sd iterations --generate --prior sd times: both (batched and per view), batched
    /// or per-view.
    #[arg(long, default_value = "both", value_parser = ["both", "batched", "per-view"])]
    pub modes: String,
    /// Stable Diffusion ONNX model directory (Optimum's layout) for --unet and --generate --prior
    /// sd.
    #[arg(long, env = "DREAMSCENE_MODELS")]
    pub models: Option<PathBuf>,
    /// ONNX Runtime execution provider for --unet and --generate --prior sd (auto: a GPU
    /// provider on a real GPU, else the CPU).
    #[arg(long, value_enum, default_value_t = Provider::Auto)]
    pub provider: Provider,
    /// Latent size for --unet, as HxW (default: what the model declares, else 64x64).
    #[arg(long, value_parser = super::parse_hw)]
    pub latent: Option<(usize, usize)>,
    /// Gaussians in the forward benchmark.
    #[arg(long, default_value_t = 100_000)]
    pub gaussians: usize,
    /// Image size of the forward benchmark.
    #[arg(long, default_value_t = 512)]
    pub size: u32,
    /// Key/value pairs in the sort benchmark.
    #[arg(long, default_value_t = 1 << 20)]
    pub pairs: u32,
    /// Timed runs per figure (median reported).
    #[arg(long, default_value_t = 5)]
    pub runs: usize,
    /// Untimed iterations before the timed ones of --generate --prior sd (a GPU provider may
    /// tune its kernels to each new shape in the first runs).
    #[arg(long, default_value_t = 2)]
    pub warmups: usize,
}

pub fn run(a: Args) -> Result<()> {
    if a.unet {
        bench_unet(a.json, a.models, a.provider, a.latent, a.runs)
    } else if a.generate && a.prior == "sd" {
        bench_generate_sd(a.json, a.models, a.provider, a.runs, a.warmups, &a.modes)
    } else if a.generate {
        bench_generate(a.json, a.runs)
    } else {
        bench(a.json, a.gaussians, a.size, a.pairs, a.runs)
    }
}

fn bench_unet(
    json: bool,
    models: Option<PathBuf>,
    provider: Provider,
    latent: Option<(usize, usize)>,
    runs: usize,
) -> Result<()> {
    let Some(dir) = models else {
        bail!(
            "bench --unet needs --models DIR (or DREAMSCENE_MODELS): a Stable Diffusion ONNX export, \
             e.g. from `optimum-cli export onnx --model stabilityai/stable-diffusion-2-1-base DIR`"
        );
    };
    let opts = dreamscene::diffusion::model::ModelOptions {
        provider,
        threads: None,
    };
    let f =
        dreamscene::bench::bench_diffusion(&dir, &opts, latent, runs).map_err(|e| anyhow!(e))?;
    if json {
        println!("{}", serde_json::json!({ "unet": f }));
    } else {
        println!(
            "models: {} ({}, {}), latents {}x{}",
            f.models, f.precision, f.provider, f.latent[0], f.latent[1]
        );
        for (b, ms) in &f.unet_ms {
            println!("unet batch {b}:        {ms:>9.2} ms");
        }
        println!("text encoder (3):    {:>9.2} ms", f.text_encoder_ms);
        let show = |o: Option<f64>| o.map_or("-".to_string(), |v| format!("{v:.2} ms"));
        println!("vae encode:          {:>12}", show(f.vae_encode_ms));
        println!("vae decode:          {:>12}", show(Some(f.vae_decode_ms)));
        println!("tiny ae encode:      {:>12}", show(f.taesd_encode_ms));
        println!("tiny ae decode:      {:>12}", show(f.taesd_decode_ms));
    }
    Ok(())
}

/// Render sizes of the sd iteration split: 256² (latents 32², the tiny exports' size) and 512²
/// (the paper's object resolution, latents 64²); 4 views, 20k Gaussians.
const SD_SIZES: [u32; 2] = [256, 512];

fn bench_generate_sd(
    json: bool,
    models: Option<PathBuf>,
    provider: Provider,
    runs: usize,
    warmups: usize,
    modes: &str,
) -> Result<()> {
    let per_view_modes: &[bool] = match modes {
        "batched" => &[false],
        "per-view" => &[true],
        _ => &[false, true],
    };
    let Some(dir) = models else {
        bail!("bench --generate --prior sd needs --models DIR (or DREAMSCENE_MODELS)");
    };
    let ctx = open_device()?;
    let mut figures = vec![];
    for size in SD_SIZES {
        for &per_view in per_view_modes {
            let f = dreamscene::bench_sd::bench_generate_sd(
                &ctx, &dir, provider, 20_000, 4, size, runs, warmups, per_view,
            )?;
            if !json {
                println!(
                    "sd {} {}² {:<8} {:>8.1} ms/it: text {:>6.1}  unet {:>8.1} ({:.0} runs, {:.0} items)  vae {:>7.1}  kernels {:>6.1}  conversions {:>6.1}  guidance {:>6.1}  host {:>6.1} ms ({:.1}% host)",
                    f.precision, f.size, f.mode, f.wall_ms, f.text_encoder_ms, f.unet_ms,
                    f.unet_runs, f.unet_items, f.vae_ms, f.kernels_ms, f.conversions_ms,
                    f.prior_host_ms, f.host_ms, 100.0 * f.host_share
                );
            }
            figures.push(f);
        }
    }
    if json {
        println!(
            "{}",
            serde_json::json!({ "device": ctx.info().name, "models": dir, "sd_iteration": figures })
        );
    }
    Ok(())
}

fn bench_generate(json: bool, runs: usize) -> Result<()> {
    use dreamscene::bench::{bench_generate, bench_scene_stage, GENERATE_SIZES, SCENE_STAGE_SIZES};
    let ctx = open_device()?;
    let show = |what: &str, f: &dreamscene::bench::GenerateFigures| {
        if !json {
            println!(
                "{what} {:>7} gaussians {} x {}²  {:>9.1} ms/it  kernel {:>8.1} ms  prior {:>8.1} ms  host {:>8.1} ms ({:.0}% of kernel)",
                f.gaussians, f.views, f.size, f.wall_ms, f.kernel_ms, f.prior_ms, f.host_ms, 100.0 * f.host_share
            );
        }
    };
    let mut figures = vec![];
    for (n, size) in GENERATE_SIZES {
        let f = bench_generate(&ctx, n, 4, size, runs)?;
        show("object", &f);
        figures.push(f);
    }
    let mut scene = vec![];
    // The projected splats take 48 bytes each in one storage binding.
    let most = ctx.info().max_storage_buffer_range / 48;
    for (n, size) in SCENE_STAGE_SIZES {
        if n as u64 > most {
            eprintln!(
                "scene  {n:>7} gaussians: skipped, over this device's {} MiB storage-binding \
                 limit (48-byte projected splats: at most {most} Gaussians)",
                ctx.info().max_storage_buffer_range >> 20
            );
            continue;
        }
        let f = bench_scene_stage(&ctx, n, 4, size, runs.min(3))?;
        show("scene ", &f);
        scene.push(f);
    }
    if json {
        println!(
            "{}",
            serde_json::json!({ "device": ctx.info().name, "generate": figures, "scene_stage": scene })
        );
    }
    Ok(())
}

fn bench(json: bool, gaussians: usize, size: u32, pairs: u32, runs: usize) -> Result<()> {
    use dreamscene::bench::*;
    let ctx = open_device()?;
    let sort = bench_sort(&ctx, pairs, runs)?;
    let forward = bench_forward(&ctx, gaussians, size, size, runs)?;
    let backward = bench_backward(&ctx, gaussians, size, size, runs)?;
    let cpu_forward = bench_cpu_forward(gaussians, size, size, forward.intersections, runs.min(3));
    let report = BenchReport {
        device: ctx.info().name.clone(),
        sort,
        forward,
        backward,
        cpu_forward,
    };
    if json {
        println!("{}", serde_json::to_string(&report)?);
    } else {
        println!("device: {}", report.device);
        println!(
            "sort:        {:>9} pairs  {:>9.2} ms  {:>8.2} M pairs/s",
            report.sort.pairs,
            report.sort.ms,
            report.sort.pairs_per_s / 1e6
        );
        for (name, f) in [
            ("forward", &report.forward),
            ("backward", &report.backward),
            ("cpu forward", &report.cpu_forward),
        ] {
            println!(
                "{name:<12} {:>9} gaussians {}x{}  {} intersections  {:>9.2} ms  {:>8.2} M gaussian-pixels/s",
                f.gaussians, f.width, f.height, f.intersections, f.ms, f.gaussian_pixels_per_s / 1e6
            );
        }
    }
    Ok(())
}
