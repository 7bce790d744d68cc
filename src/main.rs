//! The `dreamscene` command line: a thin layer over the library.
use anyhow::{anyhow, bail, Context as _, Result};
use clap::{Parser, Subcommand};
use dreamscene::camera::{read_cameras, write_cameras, Camera};
use dreamscene::diffusion::runtime::Provider;
use dreamscene::gpu::Context;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{PlacedBy, SceneSpec};
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer, RenderOutput};
use dreamscene::splat::train::{load_views, random_init, FitConfig, Trainer, View};
use dreamscene::splat::Gaussians;
use indicatif::{ProgressBar, ProgressStyle};
use rand::SeedableRng;
use std::path::{Path, PathBuf};

mod cli;

/// Text to editable 3D Gaussian-splat scenes on any Vulkan GPU (DreamScene method).
///
/// The Vulkan device is chosen automatically (discrete GPU, then integrated, then a CPU device
/// such as Mesa lavapipe); set DREAMSCENE_DEVICE to a name fragment or index to choose.
#[derive(Parser)]
#[command(name = "dreamscene", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a splat PLY from every camera of an INRIA cameras.json into <out>/<img_name>.png.
    Render {
        /// Splat PLY (INRIA 3DGS layout, SH degree 0 to 3).
        #[arg(long)]
        ply: PathBuf,
        /// INRIA cameras.json.
        #[arg(long)]
        cameras: PathBuf,
        /// Output directory (created if missing).
        #[arg(long)]
        out: PathBuf,
        /// Background colour as R,G,B in [0, 1].
        #[arg(long, default_value = "0,0,0", value_parser = parse_rgb)]
        background: [f32; 3],
    },
    /// Write a random demo scene (scene.ply, cameras.json on an orbit) and render it.
    Demo {
        /// Output directory.
        #[arg(long, default_value = "out/demo")]
        out: PathBuf,
        /// Number of Gaussians.
        #[arg(long, default_value_t = 20_000)]
        gaussians: usize,
        /// Seed of the random scene.
        #[arg(long, default_value_t = 7)]
        seed: u64,
    },
    /// Fit Gaussians to posed images (3DGS optimisation: Adam, densify and prune) and write a PLY.
    ///
    /// Images are found as <images>/<img_name>[.png|.jpg|.jpeg] for each camera. The model is
    /// checkpointed to --out every --checkpoint-every iterations, with the optimiser state
    /// (iteration, Adam moments) in <out>.state, so an interrupted fit continues with --resume.
    Fit {
        /// Directory of training images.
        #[arg(long)]
        images: PathBuf,
        /// INRIA cameras.json with one camera per image.
        #[arg(long)]
        cameras: PathBuf,
        /// Output PLY.
        #[arg(long)]
        out: PathBuf,
        /// Optimisation steps (one view each).
        #[arg(long, default_value_t = 7000)]
        iterations: u32,
        /// Start from this PLY instead of random Gaussians.
        #[arg(long)]
        init: Option<PathBuf>,
        /// Random Gaussians to start from (without --init), placed in the region the cameras see.
        #[arg(long, default_value_t = 10_000)]
        init_gaussians: usize,
        /// SH degree of a random start (0 to 3).
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(0..=3))]
        sh_degree: u32,
        /// Background colour as R,G,B in [0, 1] (transparent image pixels are composited over it).
        #[arg(long, default_value = "0,0,0", value_parser = parse_rgb)]
        background: [f32; 3],
        /// Turn off densification and pruning.
        #[arg(long)]
        no_densify: bool,
        /// Write the model every N iterations (0: only at the end).
        #[arg(long, default_value_t = 1000)]
        checkpoint_every: u32,
        /// Seed of the random start and the view order.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Continue an interrupted fit from --out and <out>.state (same --iterations).
        #[arg(long, conflicts_with = "init")]
        resume: bool,
    },
    /// Generate one object from a prompt: writes <out>/object.ply (object frame: bottom-face
    /// centre at the origin, front +y, z up), object.json, renders/ (a turntable) and
    /// checkpoints/.
    ///
    /// With Stable Diffusion (--models DIR or DREAMSCENE_MODELS) it runs Formation Pattern
    /// Sampling: MTS from the shape prior, 3D Gaussian filtering, reconstructive generation.
    /// Without models the object is its procedural shape prior (a draft in seconds).
    /// --prior oracle:REF.ply verifies the generator against a known answer.
    Object {
        /// What to make, e.g. "a red velvet armchair".
        prompt: String,
        /// Output directory.
        #[arg(long)]
        out: PathBuf,
        /// Size W,D,H in metres (default: the category's typical size).
        #[arg(long, value_parser = cli::object::parse_size)]
        size: Option<[f64; 3]>,
        /// Stable Diffusion ONNX export (Optimum layout); default $DREAMSCENE_MODELS.
        #[arg(long)]
        models: Option<PathBuf>,
        /// ONNX Runtime provider for the models.
        #[arg(long, value_enum, default_value = "cpu")]
        provider: Provider,
        /// auto (sd when models are found, else shape), sd, shape, or oracle:REF.ply.
        #[arg(long, default_value = "auto", value_parser = cli::object::parse_prior)]
        prior: cli::object::PriorChoice,
        /// Start from this PLY instead of the shape prior.
        #[arg(long)]
        init: Option<PathBuf>,
        /// Formation (MTS) iterations.
        #[arg(long, default_value_t = 1500, value_parser = clap::value_parser!(u32).range(1..))]
        iterations: u32,
        /// Render size in pixels (square).
        #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
        resolution: u32,
        /// Views per iteration.
        #[arg(long, default_value_t = 4, value_parser = clap::value_parser!(u64).range(1..=16))]
        batch: u64,
        /// Guidance rule of the formation stage: mts, sds, ism, dreamtime.
        #[arg(long, default_value = "mts", value_parser = cli::object::parse_rule)]
        rule: dreamscene::diffusion::target::Rule,
        /// Use the authors' code form of MTS (random jumps, CFG 7.5, averaged) instead of the
        /// paper's (m intervals).
        #[arg(long)]
        mts_code_form: bool,
        /// Final SH degree (raised one degree every 500 iterations).
        #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(0..=3))]
        sh_degree: u32,
        /// Turn off 3D Gaussian filtering.
        #[arg(long)]
        no_filter: bool,
        /// Fraction of the Gaussians filtering removes.
        #[arg(long, default_value_t = 0.6)]
        filter_fraction: f64,
        /// Filtering score: paper or code.
        #[arg(long, default_value = "paper")]
        filter_rule: String,
        /// Reconstruction views (0 turns reconstructive generation off).
        #[arg(long, default_value_t = 20)]
        recon_views: usize,
        /// Passes of the reconstruction fit over its views.
        #[arg(long, default_value_t = 40)]
        recon_passes: u32,
        /// Checkpoint every N iterations (0: only between stages).
        #[arg(long, default_value_t = 100)]
        checkpoint_every: u32,
        /// Turntable views written to renders/.
        #[arg(long, default_value_t = 8)]
        turntable: usize,
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Continue an interrupted run from <out>/checkpoints (same prompt, prior and settings).
        #[arg(long)]
        resume: bool,
    },
    /// Plan a scene from a sentence (or a dialogue) and lay it out: writes <out>/spec.json,
    /// <out>/layout.json and a top-down picture <out>/layout.png.
    ///
    /// Planning is offline, from the built-in knowledge base: the scene type, the objects the
    /// prompt names with their counts and adjectives, room size ("4m x 5m", "20 square meters"),
    /// placement phrases ("in the corner", "next to the sofa") and style words.
    Plan {
        /// What to build, e.g. "a cozy living room".
        prompt: Option<String>,
        /// A dialogue instead: a JSON list of {"role", "content"}; the user turns are planned.
        #[arg(long)]
        dialogue: Option<PathBuf>,
        #[command(flatten)]
        llm: LlmArgs,
        /// Ask about style and constraints before planning.
        #[arg(long)]
        interactive: bool,
        /// Seed of the layout.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Output directory.
        #[arg(long)]
        out: PathBuf,
    },
    /// Generate a scene from a sentence (or a dialogue): plan, lay out, make the objects and the
    /// environment, compose them. Writes the scene directory: scene.json, spec.json,
    /// layout.json, layout.png, objects/<category>.ply, environment.ply, scene.ply, renders/
    /// (views along an exploring path, with cameras.json) and checkpoints/.
    ///
    /// Without diffusion models (or with --draft or --prior shape) the scene is a draft in
    /// seconds: each object is its procedural shape prior and the environment its initial
    /// surfaces, with no optimisation.
    Generate {
        /// What to build, e.g. "a cozy living room".
        prompt: Option<String>,
        /// Output scene directory (created if missing).
        #[arg(long)]
        out: PathBuf,
        /// A dialogue instead: a JSON list of {"role", "content"}; the user turns are planned.
        #[arg(long)]
        dialogue: Option<PathBuf>,
        #[command(flatten)]
        llm: LlmArgs,
        /// Stable Diffusion ONNX export (Optimum layout); default $DREAMSCENE_MODELS.
        #[arg(long)]
        models: Option<PathBuf>,
        /// auto (sd when models are found, else shape), sd, shape, or oracle:DIR (a reference
        /// scene directory).
        #[arg(long, default_value = "auto", value_parser = cli::generate::parse_scene_prior)]
        prior: cli::object::PriorChoice,
        /// Make the draft (shape priors and the initial environment, no optimisation) even when
        /// models are found.
        #[arg(long)]
        draft: bool,
        /// Environment optimisation iterations.
        #[arg(long, default_value_t = 2000, value_parser = clap::value_parser!(u32).range(1..))]
        iterations: u32,
        /// Formation (MTS) iterations per object.
        #[arg(long, default_value_t = 1500, value_parser = clap::value_parser!(u32).range(1..))]
        object_iterations: u32,
        /// Render size in pixels (square).
        #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
        resolution: u32,
        /// Views along the exploring path written to renders/ (0: none).
        #[arg(long, default_value_t = 8)]
        renders: usize,
        /// Passes of the scene's reconstructive stage over its 80 views.
        #[arg(long, default_value_t = 25)]
        recon_passes: u32,
        /// Passes of each object's reconstruction fit over its 20 views.
        #[arg(long, default_value_t = 40)]
        object_recon_passes: u32,
        /// Gaussians of each object's shape prior (default: from its surface area, 30k-60k).
        #[arg(long)]
        object_gaussians: Option<usize>,
        /// Environment Gaussians per square metre of wall, ceiling and floor (capped at 300k).
        #[arg(long, default_value_t = 1500.0)]
        env_density: f64,
        /// Seed of the layout and the generation.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Continue an interrupted run in --out (same prompt and seed).
        #[arg(long)]
        resume: bool,
    },
    /// Place the objects of a scene spec (spec.json) with graph-based constraint placement.
    ///
    /// Writes layout.json: every instance placed exactly once, collision-free, with the relations
    /// it could not satisfy listed under `unsatisfied` and relaxed placements marked `fallback`.
    Layout {
        /// SceneSpec (spec.json, as `plan` writes it).
        #[arg(long)]
        spec: PathBuf,
        /// Seed: different seeds give different valid layouts.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Output layout.json.
        #[arg(long)]
        out: PathBuf,
    },
    /// Check the Vulkan device, ONNX Runtime, and (with --models) a diffusion model directory.
    Doctor {
        /// A Stable Diffusion ONNX model directory to check.
        #[arg(long, env = "DREAMSCENE_MODELS")]
        models: Option<PathBuf>,
        /// ONNX Runtime execution provider.
        #[arg(long, value_enum, default_value_t = Provider::Cpu)]
        provider: Provider,
    },
    /// Measure kernel throughput at fixed sizes on the selected device; with --unet, the latency
    /// of the diffusion models instead.
    Bench {
        /// Print one JSON object instead of a table.
        #[arg(long)]
        json: bool,
        /// Time the UNet (batches 1–3), text encoder and VAE of --models instead of the kernels.
        #[arg(long)]
        unet: bool,
        /// Time one formation iteration of object generation (oracle prior, 4 views) at 256²
        /// and 512² with 20k and 100k Gaussians, split into kernel, prior and host time.
        #[arg(long, conflicts_with = "unet")]
        generate: bool,
        /// Stable Diffusion ONNX model directory (Optimum's layout) for --unet.
        #[arg(long, env = "DREAMSCENE_MODELS")]
        models: Option<PathBuf>,
        /// ONNX Runtime execution provider for --unet.
        #[arg(long, value_enum, default_value_t = Provider::Cpu)]
        provider: Provider,
        /// Latent size for --unet, as HxW (default: what the model declares, else 64x64).
        #[arg(long, value_parser = parse_hw)]
        latent: Option<(usize, usize)>,
        /// Gaussians in the forward benchmark.
        #[arg(long, default_value_t = 100_000)]
        gaussians: usize,
        /// Image size of the forward benchmark.
        #[arg(long, default_value_t = 512)]
        size: u32,
        /// Key/value pairs in the sort benchmark.
        #[arg(long, default_value_t = 1 << 20)]
        pairs: u32,
        /// Timed runs per figure (median reported).
        #[arg(long, default_value_t = 5)]
        runs: usize,
    },
}

fn parse_hw(s: &str) -> Result<(usize, usize), String> {
    let (h, w) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("{s:?}: expected HxW, e.g. 64x64"))?;
    let p = |v: &str| {
        v.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=1024).contains(n))
            .ok_or_else(|| format!("{s:?}: sizes must be whole numbers from 1 to 1024"))
    };
    Ok((p(h)?, p(w)?))
}

fn parse_rgb(s: &str) -> Result<[f32; 3], String> {
    let v: Vec<f32> = s
        .split(',')
        .map(|x| x.trim().parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("`{s}`: {e}"))?;
    match v.as_slice() {
        [r, g, b] if v.iter().all(|c| (0.0..=1.0).contains(c)) => Ok([*r, *g, *b]),
        _ => Err(format!(
            "`{s}`: expected three numbers in [0, 1] such as 1,1,1"
        )),
    }
}

fn main() {
    // Output piped into `head` and the like ends quietly, as for other command-line tools,
    // instead of panicking on a closed stdout.
    // SAFETY: restoring the default disposition of SIGPIPE before any thread starts.
    #[cfg(unix)]
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let cli = Cli::parse();
    if let Err(e) = run(cli) {
        let chain: Vec<String> = e
            .chain()
            .map(|c| c.to_string().replace('\n', " "))
            .collect();
        eprintln!("error: {}", chain.join(": "));
        std::process::exit(1);
    }
}

fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Render {
            ply,
            cameras,
            out,
            background,
        } => {
            let g = read_ply(&ply)?;
            let cams = read_cameras(&cameras)?;
            render_all(&g, &cams, &out, background)
        }
        Command::Demo {
            out,
            gaussians,
            seed,
        } => demo(&out, gaussians, seed),
        Command::Fit {
            images,
            cameras,
            out,
            iterations,
            init,
            init_gaussians,
            sh_degree,
            background,
            no_densify,
            checkpoint_every,
            seed,
            resume,
        } => {
            let cams = read_cameras(&cameras)?;
            let views = load_views(&images, &cams, background).map_err(anyhow::Error::msg)?;
            let state = resume.then(|| state_path(&out));
            if let Some(st) = &state {
                if !out.is_file() || !st.is_file() {
                    bail!(
                        "--resume needs {} and {} from an earlier fit",
                        out.display(),
                        st.display()
                    );
                }
            }
            let start = match init.or(resume.then(|| out.clone())) {
                Some(p) => read_ply(&p)?,
                None => {
                    if init_gaussians == 0 {
                        bail!("--init-gaussians must be at least 1");
                    }
                    random_init(&cams, init_gaussians, sh_degree, seed)
                }
            };
            let config = FitConfig {
                iterations,
                background,
                densify: !no_densify,
                seed,
                ..Default::default()
            };
            fit(
                &start,
                views,
                config,
                &out,
                checkpoint_every,
                state.as_deref(),
            )
        }
        Command::Plan {
            prompt,
            dialogue,
            llm,
            interactive,
            seed,
            out,
        } => {
            let llm = llm.config();
            plan(prompt, dialogue, llm, interactive, seed, &out)
        }
        Command::Generate {
            prompt,
            out,
            dialogue,
            llm,
            models,
            prior,
            draft,
            iterations,
            object_iterations,
            resolution,
            renders,
            recon_passes,
            object_recon_passes,
            object_gaussians,
            env_density,
            seed,
            resume,
        } => cli::generate::run(cli::generate::GenerateArgs {
            prompt,
            out,
            dialogue,
            llm: llm.config(),
            models,
            prior,
            draft,
            iterations,
            object_iterations,
            resolution,
            renders,
            recon_passes,
            object_recon_passes,
            object_gaussians,
            env_density,
            seed,
            resume,
        }),
        Command::Object {
            prompt,
            out,
            size,
            models,
            provider,
            prior,
            init,
            iterations,
            resolution,
            batch,
            rule,
            mts_code_form,
            sh_degree,
            no_filter,
            filter_fraction,
            filter_rule,
            recon_views,
            recon_passes,
            checkpoint_every,
            turntable,
            seed,
            resume,
        } => {
            let filter = cli::object::filter_config(no_filter, filter_fraction, &filter_rule)?;
            let form = if mts_code_form {
                dreamscene::diffusion::guidance::MtsRule::Code
            } else {
                dreamscene::diffusion::guidance::MtsRule::Paper
            };
            let config = cli::object::config(
                iterations,
                resolution,
                seed,
                rule,
                form,
                batch as usize,
                sh_degree,
                filter,
                recon_views,
                recon_passes,
                checkpoint_every,
            );
            cli::object::run(cli::object::ObjectArgs {
                prompt,
                out,
                size,
                models,
                provider,
                prior,
                init,
                config,
                resume,
                turntable,
            })
        }
        Command::Layout { spec, seed, out } => {
            let spec = SceneSpec::read(&spec)?;
            let l = layout(&spec, LayoutOptions::seeded(seed))?;
            create_parent(&out)?;
            l.write(&out)
                .with_context(|| format!("writing {}", out.display()))?;
            let fallback = l
                .objects
                .iter()
                .filter(|o| o.placed_by == PlacedBy::Fallback)
                .count();
            println!(
                "wrote {}: {} objects in a {:.1} x {:.1} x {:.1} m room, {} of {} relations satisfied, {} fallback placements",
                out.display(),
                l.objects.len(),
                l.room.size[0],
                l.room.size[1],
                l.room.size[2],
                spec.relations.len() - l.unsatisfied.len(),
                spec.relations.len(),
                fallback
            );
            for r in &l.unsatisfied {
                println!("  unsatisfied: {} {:?} {}", r.subject, r.relation, r.object);
            }
            Ok(())
        }
        Command::Doctor { models, provider } => doctor(models.as_deref(), provider),
        Command::Bench {
            json,
            unet: true,
            models,
            provider,
            latent,
            runs,
            ..
        } => bench_unet(json, models, provider, latent, runs),
        Command::Bench {
            json,
            generate: true,
            runs,
            ..
        } => bench_generate(json, runs),
        Command::Bench {
            json,
            gaussians,
            size,
            pairs,
            runs,
            ..
        } => bench(json, gaussians, size, pairs, runs),
    }
}

/// Where a fit writing `out` keeps its optimiser state.
fn state_path(out: &Path) -> PathBuf {
    let mut s = out.as_os_str().to_owned();
    s.push(".state");
    PathBuf::from(s)
}

fn fit(
    start: &Gaussians,
    views: Vec<View>,
    config: FitConfig,
    out: &Path,
    checkpoint_every: u32,
    resume_from: Option<&Path>,
) -> Result<()> {
    create_parent(out)?;
    let ctx = open_device()?;
    let n_views = views.len();
    let iterations = config.iterations;
    let mut t = Trainer::new(&ctx, start, views, config)?;
    if let Some(st) = resume_from {
        t.restore(st).map_err(anyhow::Error::msg)?;
        if t.iteration() >= iterations {
            println!(
                "{} is already at iteration {} of {iterations}",
                out.display(),
                t.iteration()
            );
            return Ok(());
        }
        eprintln!("resuming at iteration {}", t.iteration());
    }
    let bar = ProgressBar::new(iterations as u64).with_style(
        ProgressStyle::with_template(
            "{bar:40} {pos}/{len} [{elapsed_precise}<{eta_precise}] {msg}",
        )
        .expect("valid template"),
    );
    bar.set_position(t.iteration() as u64);
    let state = state_path(out);
    let save = |t: &Trainer| -> Result<()> {
        let g = t.gaussians()?;
        write_ply(out, &g).with_context(|| format!("writing {}", out.display()))?;
        t.save_state(&state)
            .with_context(|| format!("writing {}", state.display()))
    };
    // Loss and PSNR averaged over the last epoch-sized window, for a steadier readout.
    let mut window: std::collections::VecDeque<(f64, f64)> = Default::default();
    while t.iteration() < iterations {
        let r = t.step()?;
        window.push_back((r.loss, r.psnr));
        if window.len() > n_views {
            window.pop_front();
        }
        if r.iteration % 10 == 0 || r.iteration == iterations {
            let k = window.len() as f64;
            let (l, p) = window
                .iter()
                .fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
            bar.set_message(format!(
                "loss {:.4}  PSNR {:.2} dB  {} Gaussians",
                l / k,
                p / k,
                r.gaussians
            ));
        }
        bar.inc(1);
        if checkpoint_every > 0 && r.iteration % checkpoint_every == 0 && r.iteration < iterations {
            save(&t)?;
        }
    }
    save(&t)?;
    bar.finish();
    println!("wrote {} ({} Gaussians)", out.display(), t.len());
    Ok(())
}

#[derive(serde::Deserialize)]
struct Turn {
    role: String,
    content: String,
}

/// Asks about style and constraints on the terminal; the answers join the user constraint.
fn interview(text: &str) -> Result<String> {
    use std::io::{BufRead, Write};
    let mut out = text.to_string();
    let stdin = std::io::stdin();
    for q in [
        "What style should it have (e.g. minimalist, rustic, beach-inspired)? ",
        "Any constraints: room size, objects it must have, where things go? ",
    ] {
        eprint!("{q}");
        std::io::stderr().flush().ok();
        let mut line = String::new();
        stdin
            .lock()
            .read_line(&mut line)
            .context("reading the answer")?;
        let a = line.trim();
        if !a.is_empty() {
            out = if out.is_empty() {
                a.to_string()
            } else {
                format!("{out}. {a}")
            };
        }
    }
    Ok(out)
}

fn plan(
    prompt: Option<String>,
    dialogue: Option<PathBuf>,
    llm: Option<dreamscene::plan::llm::LlmConfig>,
    interactive: bool,
    seed: u64,
    out: &Path,
) -> Result<()> {
    let text = plan_text(prompt, dialogue, interactive)?;
    let (spec, l) = plan_to_dir(&text, llm.as_ref(), seed, out)?;
    let n_rel = spec.relations.len();
    println!(
        "{} scene, {:.1} x {:.1} m: {} objects, {} of {} relations satisfied",
        match spec.scene_type {
            dreamscene::plan::spec::SceneType::Indoor => "indoor",
            dreamscene::plan::spec::SceneType::Outdoor => "outdoor",
        },
        l.room.size[0],
        l.room.size[1],
        l.objects.len(),
        n_rel - l.unsatisfied.len(),
        n_rel
    );
    println!(
        "wrote {0}/spec.json, {0}/layout.json, {0}/layout.png",
        out.display()
    );
    Ok(())
}

/// The text to plan: the prompt, or the user turns of a dialogue file joined, after the
/// interview when `interactive`. Never empty.
pub(crate) fn plan_text(
    prompt: Option<String>,
    dialogue: Option<PathBuf>,
    interactive: bool,
) -> Result<String> {
    let text = match (prompt, dialogue) {
        (Some(p), None) => p,
        (None, Some(f)) => {
            let raw =
                std::fs::read_to_string(&f).with_context(|| format!("reading {}", f.display()))?;
            let turns: Vec<Turn> = serde_json::from_str(&raw).with_context(|| {
                format!("{}: expected a JSON list of {{role, content}}", f.display())
            })?;
            let user: Vec<String> = turns
                .into_iter()
                .filter(|t| t.role == "user")
                .map(|t| t.content)
                .collect();
            if user.is_empty() {
                bail!("{}: the dialogue has no user turns", f.display());
            }
            user.join(". ")
        }
        (Some(_), Some(_)) => bail!("give a prompt or --dialogue, not both"),
        (None, None) if interactive => String::new(),
        (None, None) => {
            bail!("give a prompt (or --dialogue FILE), e.g. \"a cozy living room\"")
        }
    };
    let text = if interactive {
        if text.is_empty() {
            eprint!("What scene would you like? ");
            let mut line = String::new();
            std::io::stdin()
                .read_line(&mut line)
                .context("reading the answer")?;
            interview(line.trim())?
        } else {
            interview(&text)?
        }
    } else {
        text
    };
    if text.trim().is_empty() {
        bail!("the prompt is empty");
    }
    Ok(text)
}

/// Plans `text` (offline, or with the LLM endpoint) and lays it out: writes spec.json,
/// layout.json and layout.png into `out` (created); returns the spec and the layout.
pub(crate) fn plan_to_dir(
    text: &str,
    llm: Option<&dreamscene::plan::llm::LlmConfig>,
    seed: u64,
    out: &Path,
) -> Result<(SceneSpec, dreamscene::plan::spec::Layout)> {
    let spec = match llm {
        None => dreamscene::plan::offline::plan_offline(text),
        Some(cfg) => {
            eprintln!("asking {} ({})", cfg.url, cfg.model);
            let (spec, report) = dreamscene::plan::llm::plan_llm(cfg, text);
            for w in &report.warnings {
                eprintln!("warning: {w}");
            }
            spec
        }
    };
    let l = layout(&spec, LayoutOptions::seeded(seed))?;
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let spec_json = serde_json::to_string_pretty(&spec)?;
    dreamscene::util::write_atomic(&out.join("spec.json"), spec_json.as_bytes())
        .with_context(|| format!("writing {}/spec.json", out.display()))?;
    l.write(&out.join("layout.json"))
        .with_context(|| format!("writing {}/layout.json", out.display()))?;
    write_png(
        &dreamscene::plan::draw::draw_layout(&l),
        &out.join("layout.png"),
    )?;
    Ok((spec, l))
}

/// The LLM endpoint settings, when a URL is given (the key comes from OPENAI_API_KEY).
/// The planner's LLM endpoint, shared by `plan` and `generate`.
#[derive(clap::Args)]
struct LlmArgs {
    /// Plan with an OpenAI-compatible chat endpoint instead (OpenAI, Ollama, llama.cpp, vLLM),
    /// e.g. https://api.openai.com/v1 or http://localhost:11434/v1. The key comes from
    /// OPENAI_API_KEY. Unusable answers are retried, then the offline planner takes over.
    #[arg(long, env = "DREAMSCENE_LLM_URL")]
    llm_url: Option<String>,
    /// Model name for the endpoint.
    #[arg(long, env = "DREAMSCENE_LLM_MODEL", default_value = "gpt-4o")]
    llm_model: String,
    /// Seconds to wait for each LLM answer.
    #[arg(long, default_value_t = 120)]
    llm_timeout: u64,
}

impl LlmArgs {
    /// The endpoint's settings when `--llm-url` is given (key from OPENAI_API_KEY).
    fn config(self) -> Option<dreamscene::plan::llm::LlmConfig> {
        let (model, timeout) = (self.llm_model, self.llm_timeout);
        self.llm_url.map(|url| dreamscene::plan::llm::LlmConfig {
            url,
            model,
            api_key: std::env::var("OPENAI_API_KEY")
                .ok()
                .filter(|k| !k.is_empty()),
            timeout: std::time::Duration::from_secs(timeout.max(1)),
            retries: 2,
        })
    }
}

pub(crate) fn open_device() -> Result<Context> {
    Context::new().context("opening the Vulkan device (run `dreamscene doctor`)")
}

fn render_all(g: &Gaussians, cams: &[Camera], out: &Path, background: [f32; 3]) -> Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let ctx = open_device()?;
    let r = Rasterizer::new(&ctx)?;
    let gg = GpuGaussians::upload(&ctx, g)?;
    let bar = ProgressBar::new(cams.len() as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} views {msg}").expect("valid template"),
    );
    for c in cams {
        let img = r.forward(&ctx, &gg, c, background)?.read()?;
        let name = if c.img_name.is_empty() {
            format!("{:05}", c.id)
        } else {
            c.img_name.clone()
        };
        let path = out.join(format!("{name}.png"));
        save_png(&img, &path)?;
        bar.set_message(name);
        bar.inc(1);
    }
    bar.finish();
    Ok(())
}

pub(crate) fn save_png(img: &RenderOutput, path: &Path) -> Result<()> {
    let mut buf = image::RgbImage::new(img.width, img.height);
    for (i, p) in buf.pixels_mut().enumerate() {
        let c = img.color[i];
        *p = image::Rgb(c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8));
    }
    write_png(&buf, path)
}

/// Writes a PNG atomically (temporary file, then rename).
pub(crate) fn write_png(img: &image::RgbImage, path: &Path) -> Result<()> {
    let tmp = path.with_extension("png.tmp");
    img.save_with_format(&tmp, image::ImageFormat::Png)
        .with_context(|| format!("writing {}", path.display()))?;
    std::fs::rename(&tmp, path).with_context(|| format!("writing {}", path.display()))
}

/// Creates the directory that will hold `file`.
fn create_parent(file: &Path) -> Result<()> {
    match file.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(dir) => {
            std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))
        }
        None => Ok(()),
    }
}

fn demo(out: &Path, n: usize, seed: u64) -> Result<()> {
    if n == 0 {
        bail!("--gaussians must be at least 1");
    }
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let g = Gaussians::random(&mut rng, n, [-1.0; 3], [1.0; 3], 0.03, 1);
    let cams: Vec<Camera> = (0..8)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 8.0;
            let mut c = Camera::look_at(
                [4.0 * a.cos(), 4.0 * a.sin(), 1.5],
                [0.0; 3],
                [0.0, 0.0, 1.0],
                256,
                256,
                0.8,
            );
            c.id = i;
            c.img_name = format!("view_{i:02}");
            c
        })
        .collect();
    write_ply(&out.join("scene.ply"), &g)?;
    write_cameras(&out.join("cameras.json"), &cams)?;
    render_all(&g, &cams, &out.join("renders"), [1.0, 1.0, 1.0])?;
    println!(
        "wrote {}/scene.ply, cameras.json and renders/*.png",
        out.display()
    );
    Ok(())
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
