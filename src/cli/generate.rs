//! `dreamscene generate`: a scene directory from a sentence. This build makes the draft (shape
//! priors, initial environment, composition, renders chosen by what they show); the optimising
//! scene stages are refused with a one-line reason.
use super::object::{models_dir, PriorChoice, NO_MODELS};
use anyhow::{bail, Context as _, Result};
use dreamscene::camera::scene::{render_views, SceneBox};
use dreamscene::camera::write_cameras;
use dreamscene::generate::scene::{check_resume, write_draft_scene};
use dreamscene::plan::llm::LlmConfig;
use dreamscene::plan::spec::{Layout, SceneSpec};
use dreamscene::scene::dir::read_scene;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What `generate` was asked.
pub struct GenerateArgs {
    pub prompt: Option<String>,
    pub out: PathBuf,
    pub dialogue: Option<PathBuf>,
    pub llm: Option<LlmConfig>,
    pub models: Option<PathBuf>,
    pub prior: PriorChoice,
    pub draft: bool,
    pub iterations: u32,
    pub object_iterations: u32,
    pub resolution: u32,
    pub renders: usize,
    /// Passes of the scene's and the objects' reconstruction fits.
    pub recon_passes: u32,
    pub object_recon_passes: u32,
    pub object_gaussians: Option<usize>,
    pub env_density: f64,
    pub seed: u64,
    pub resume: bool,
}

/// `--prior` for a scene: auto, sd, shape or oracle:DIR (a reference scene directory).
pub fn parse_scene_prior(s: &str) -> Result<PriorChoice, String> {
    super::object::parse_prior(s)
        .map_err(|_| format!("'{s}': expected auto, sd, shape or oracle:DIR (a scene directory)"))
}

/// The background of the renders: the environment encloses the views, so it barely shows.
const BACKGROUND: [f32; 3] = [0.0; 3];

pub fn run_with(a: GenerateArgs) -> Result<()> {
    let start = Instant::now();
    let models = models_dir(a.models.as_deref());
    let draft = match (&a.prior, a.draft) {
        (_, true) | (PriorChoice::Shape, _) => true,
        (PriorChoice::Auto, _) => models.is_none(),
        (PriorChoice::Sd, _) if models.is_none() => bail!(
            "--prior sd needs a model directory (--models DIR or DREAMSCENE_MODELS); --draft \
             makes a draft scene without one"
        ),
        (PriorChoice::Sd | PriorChoice::Oracle(_), _) => false,
    };
    let text = super::plan::plan_text(a.prompt.clone(), a.dialogue.clone(), false)?;
    let out = &a.out;
    let existing = out.join("scene.json");
    let mut keep = false;
    if a.resume && existing.is_file() {
        let scene = read_scene(out).context("--resume")?;
        if check_resume(&scene, &text, a.seed)? {
            println!(
                "{} is complete ({} objects); nothing to do",
                out.display(),
                scene.objects.len()
            );
            return Ok(());
        }
        keep = true;
    }
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    if !draft {
        return full(&a, &text, models.as_deref(), start);
    }
    if models.is_none() {
        eprintln!("{NO_MODELS}");
    } else {
        eprintln!("--draft: a draft scene from the shape priors, without the diffusion models");
    }
    let (spec, layout) = plan_or_reuse(&text, &a, keep)?;
    eprintln!(
        "plan: {} objects in {:.1} x {:.1} x {:.1} m ({} relations unsatisfied)",
        layout.objects.len(),
        layout.room.size[0],
        layout.room.size[1],
        layout.room.size[2],
        layout.unsatisfied.len()
    );
    let report = write_draft_scene(out, &text, a.seed, &spec, &layout, keep, &mut |l| {
        eprintln!("{l}")
    })?;
    let renders = out.join("renders");
    if a.renders > 0 {
        let g = dreamscene::splat::ply::read_ply(&out.join("scene.ply"))?;
        render_chosen(&g, &layout, a.renders, a.resolution, &renders)?;
        eprintln!(
            "renders: {} views chosen by what they show; contact sheet {}/overview.png",
            a.renders,
            renders.display()
        );
    }
    println!(
        "draft scene: {} objects ({} categories), {} Gaussians ({} environment) in {:.1} s; \
         wrote {d}/scene.json, {d}/scene.ply, {d}/objects/, {d}/environment.ply and {}",
        report.scene.objects.len(),
        report.object_gaussians.len(),
        report.scene_gaussians,
        report.environment_gaussians,
        start.elapsed().as_secs_f64(),
        if a.renders > 0 {
            format!("{} views in {}", a.renders, renders.display())
        } else {
            "no renders".to_string()
        },
        d = out.display(),
    );
    Ok(())
}

/// Full generation with the `sd` or `oracle:DIR` prior: objects by Formation Pattern Sampling,
/// the three environment stages, then scene.json, scene.ply and the renders.
fn full(a: &GenerateArgs, text: &str, models: Option<&Path>, start: Instant) -> Result<()> {
    use dreamscene::generate::object::ObjectConfig;
    use dreamscene::generate::scene_stages::{
        generate_scene, OracleScenePriors, SceneConfig, ScenePriors, SdScenePriors,
    };
    let out = &a.out;
    let ctx = super::open_device()?;
    // The oracle regenerates its reference scene from the reference's own plan and layout.
    if let PriorChoice::Oracle(dir) = &a.prior {
        for f in ["spec.json", "layout.json"] {
            let (from, to) = (dir.join(f), out.join(f));
            if !(a.resume && to.is_file()) {
                std::fs::copy(&from, &to).with_context(|| {
                    format!("the oracle's reference scene: copying {}", from.display())
                })?;
            }
        }
    }
    let resume_plan = a.resume || matches!(a.prior, PriorChoice::Oracle(_));
    let (spec, layout) = plan_or_reuse(text, a, resume_plan)?;
    let mut priors: Box<dyn ScenePriors> = match &a.prior {
        PriorChoice::Oracle(dir) => Box::new(OracleScenePriors::new(&ctx, dir)),
        _ => {
            let dir = models.expect("checked by the caller");
            let sd = dreamscene::diffusion::model::StableDiffusion::open(dir, &Default::default())
                .map_err(anyhow::Error::msg)?;
            Box::new(SdScenePriors(dreamscene::generate::prior::SdPrior::new(
                sd, text, None,
            )))
        }
    };
    if !(a.env_density.is_finite() && a.env_density > 0.0) {
        bail!(
            "--env-density {}: expected a positive number of Gaussians per m²",
            a.env_density
        );
    }
    if a.resolution % 8 != 0 {
        bail!(
            "--resolution {}: the priors need a multiple of 8",
            a.resolution
        );
    }
    let cfg = SceneConfig {
        iterations: a.iterations,
        object: ObjectConfig {
            iterations: a.object_iterations,
            resolution: a.resolution,
            sh_degree: 1,
            seed: a.seed,
            recon_passes: a.object_recon_passes,
            ..ObjectConfig::default()
        },
        resolution: a.resolution,
        recon_passes: a.recon_passes,
        seed: a.seed,
        object_gaussians: a.object_gaussians,
        env: dreamscene::scene::env::EnvOptions {
            density: a.env_density,
            ..Default::default()
        },
        ..SceneConfig::default()
    };
    eprintln!(
        "plan: {} objects in {:.1} x {:.1} x {:.1} m; prior {}",
        layout.objects.len(),
        layout.room.size[0],
        layout.room.size[1],
        layout.room.size[2],
        priors.kind()
    );
    let report = generate_scene(
        &ctx,
        out,
        text,
        &spec,
        &layout,
        priors.as_mut(),
        &cfg,
        a.resume,
        &mut |l| eprintln!("{l}"),
    )?;
    let mut scene = dreamscene::generate::scene::scene_file(
        text,
        a.seed,
        &spec,
        &layout,
        dreamscene::scene::dir::Prior {
            kind: match &a.prior {
                PriorChoice::Oracle(_) => "oracle".into(),
                _ => "sd".into(),
            },
            models: match &a.prior {
                PriorChoice::Oracle(d) => Some(d.display().to_string()),
                _ => models.map(|m| m.display().to_string()),
            },
        },
    );
    for name in ["floor", "reconstruction"] {
        scene.stages.push(dreamscene::scene::dir::Stage {
            name: name.into(),
            done: true,
        });
    }
    let composed = dreamscene::scene::dir::compose_scene(out, &scene)?;
    let scene_path = out.join("scene.ply");
    dreamscene::splat::ply::write_ply(&scene_path, &composed)
        .with_context(|| format!("writing {}", scene_path.display()))?;
    dreamscene::scene::dir::write_scene(out, &scene)?;
    if a.renders > 0 {
        render_chosen(
            &composed,
            &layout,
            a.renders,
            a.resolution,
            &out.join("renders"),
        )?;
    }
    println!(
        "scene: {} objects ({} categories), {} Gaussians ({} environment); objects {:.0} s, environment stages {:.0} s, {:.0} s in all; wrote {}",
        layout.objects.len(),
        report.objects.len(),
        composed.len(),
        report.environment,
        report.seconds[0],
        report.seconds[1],
        start.elapsed().as_secs_f64(),
        out.join("scene.json").display()
    );
    Ok(())
}

/// The spec and layout: re-read from `out` when resuming and both are there (an LLM plan is
/// not asked again), else planned afresh.
fn plan_or_reuse(text: &str, a: &GenerateArgs, resume: bool) -> Result<(SceneSpec, Layout)> {
    let (spec_path, layout_path) = (a.out.join("spec.json"), a.out.join("layout.json"));
    if resume && spec_path.is_file() && layout_path.is_file() {
        let spec = SceneSpec::read(&spec_path)?;
        let layout = Layout::read(&layout_path)?;
        return Ok((spec, layout));
    }
    super::plan::plan_to_dir(text, a.llm.as_ref(), a.seed, &a.out)
}

/// Renders `count` views chosen by what they show (`camera::scene::render_views`) into `dir`,
/// with `dir/cameras.json` and the contact sheet `dir/overview.png`.
fn render_chosen(g: &Gaussians, layout: &Layout, count: usize, res: u32, dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let cams = render_views(&SceneBox::from_layout(layout), count, res, res);
    write_cameras(&dir.join("cameras.json"), &cams)
        .with_context(|| format!("writing {}/cameras.json", dir.display()))?;
    let ctx = super::open_device()?;
    let r = Rasterizer::new(&ctx)?;
    let gg = GpuGaussians::upload(&ctx, g)?;
    let mut shots = vec![];
    for cam in &cams {
        let img = r.forward(&ctx, &gg, cam, BACKGROUND)?.read()?;
        super::save_png(&img, &dir.join(format!("{}.png", cam.img_name)))?;
        shots.push(img);
    }
    let tiles: Vec<_> = shots
        .iter()
        .map(|i| (i.width, i.height, i.color.as_slice()))
        .collect();
    let sheet = dreamscene::util::contact_sheet(&tiles, 4, 256);
    super::write_png(&sheet, &dir.join("overview.png"))
}

#[derive(clap::Args)]
pub struct Args {
    /// What to build, e.g. "a cozy living room".
    pub prompt: Option<String>,
    /// Output scene directory (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// A dialogue instead: a JSON list of {"role", "content"}; the user turns are planned.
    #[arg(long)]
    pub dialogue: Option<PathBuf>,
    #[command(flatten)]
    pub llm: super::plan::LlmArgs,
    /// Stable Diffusion ONNX export (Optimum layout); default $DREAMSCENE_MODELS.
    #[arg(long)]
    pub models: Option<PathBuf>,
    /// auto (sd when models are found, else shape), sd, shape, or oracle:DIR (a reference
    /// scene directory).
    #[arg(long, default_value = "auto", value_parser = parse_scene_prior)]
    pub prior: super::object::PriorChoice,
    /// Make the draft (shape priors and the initial environment, no optimisation) even when
    /// models are found.
    #[arg(long)]
    pub draft: bool,
    /// Environment optimisation iterations.
    #[arg(long, default_value_t = 2000, value_parser = clap::value_parser!(u32).range(1..))]
    pub iterations: u32,
    /// Formation (MTS) iterations per object.
    #[arg(long, default_value_t = 1500, value_parser = clap::value_parser!(u32).range(1..))]
    pub object_iterations: u32,
    /// Render size in pixels (square).
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
    pub resolution: u32,
    /// Views chosen by what they show written to renders/, with overview.png (0: none).
    #[arg(long, default_value_t = 8)]
    pub renders: usize,
    /// Passes of the scene's reconstructive stage over its 80 views.
    #[arg(long, default_value_t = 25)]
    pub recon_passes: u32,
    /// Passes of each object's reconstruction fit over its 20 views.
    #[arg(long, default_value_t = 40)]
    pub object_recon_passes: u32,
    /// Gaussians of each object's shape prior (default: from its surface area, 30k-60k).
    #[arg(long)]
    pub object_gaussians: Option<usize>,
    /// Environment Gaussians per square metre of wall, ceiling and floor (capped at 300k).
    #[arg(long, default_value_t = 1500.0)]
    pub env_density: f64,
    /// Seed of the layout and the generation.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Continue an interrupted run in --out (same prompt and seed).
    #[arg(long)]
    pub resume: bool,
}

pub fn run(a: Args) -> Result<()> {
    run_with(GenerateArgs {
        prompt: a.prompt,
        out: a.out,
        dialogue: a.dialogue,
        llm: a.llm.config(),
        models: a.models,
        prior: a.prior,
        draft: a.draft,
        iterations: a.iterations,
        object_iterations: a.object_iterations,
        resolution: a.resolution,
        renders: a.renders,
        recon_passes: a.recon_passes,
        object_recon_passes: a.object_recon_passes,
        object_gaussians: a.object_gaussians,
        env_density: a.env_density,
        seed: a.seed,
        resume: a.resume,
    })
}
