//! `dreamscene generate`: a scene directory from a sentence. Here: the arguments, the scene lock
//! and what `--resume` and `--force` find in `--out`, and the draft (shape priors, initial
//! environment, composition); full generation with the sd or oracle prior is in
//! [`super::generate_full`], the renders in [`super::scene_renders`].
use super::generate_full::{full, full_setup};
use super::object::{models_dir, PriorChoice, NO_MODELS};
use super::scene_renders::{complete_renders, render_chosen};
use anyhow::{bail, Context as _, Result};
use dreamscene::batch::index::StageTime;
use dreamscene::diffusion::runtime::Provider;
use dreamscene::generate::scene::{check_resume, write_draft_scene};
use dreamscene::plan::llm::LlmConfig;
use dreamscene::plan::spec::{Layout, SceneSpec};
use dreamscene::scene::dir::read_scene;
use dreamscene::scene::lock::{CommitGuard, SceneLock, Wait};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What `generate` was asked.
pub struct GenerateArgs {
    pub prompt: Option<String>,
    pub out: PathBuf,
    pub dialogue: Option<PathBuf>,
    pub llm: Option<LlmConfig>,
    pub models: Option<PathBuf>,
    /// ONNX Runtime provider of the sd prior's models.
    pub provider: Provider,
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
    /// Replace a scene already in `out`, whole.
    pub force: bool,
    /// Exit at once when another command writes `out`.
    pub no_wait: bool,
    /// The caller already holds `out`'s scene lock (`batch` claims a scene by locking it).
    pub lock_held: bool,
}

/// `--prior` for a scene: auto, sd, shape or oracle:DIR (a reference scene directory).
pub fn parse_scene_prior(s: &str) -> Result<PriorChoice, String> {
    super::object::parse_prior(s)
        .map_err(|_| format!("'{s}': expected auto, sd, shape or oracle:DIR (a scene directory)"))
}

pub fn run_with(a: GenerateArgs) -> Result<()> {
    run_timed(a).map(|_| ())
}

/// [`run_with`], returning the time of each stage a full generation ran (plan and priors,
/// objects, environment, outputs; none for a draft or a scene already complete): what `batch`
/// records in its index.
pub fn run_timed(a: GenerateArgs) -> Result<Vec<StageTime>> {
    let start = Instant::now();
    let models = models_dir(a.models.as_deref());
    let draft = draft_mode(&a, models.as_deref())?;
    if !draft {
        check_full(&a, models.as_deref())?;
    }
    let text = super::plan::plan_text(a.prompt.clone(), a.dialogue.clone(), false)?;
    let out = &a.out;
    let created = !out.exists();
    super::create_dir(out)?;
    let result = locked(&a, &text, draft, models.as_deref(), start);
    if result.is_err() && created {
        // A run that failed before writing anything leaves no empty directory behind.
        remove_if_empty(out);
    }
    result
}

/// Files of a scene directory that are not the scene: the locks.
const LOCK_FILES: [&str; 2] = [
    dreamscene::scene::lock::LOCK_FILE,
    dreamscene::scene::lock::COMMIT_LOCK_FILE,
];

/// The entries of `dir` other than its lock files.
pub(super) fn contents(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = vec![];
    for e in std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))? {
        let e = e.with_context(|| format!("reading {}", dir.display()))?;
        if !LOCK_FILES.iter().any(|l| e.file_name() == *l) {
            out.push(e.path());
        }
    }
    out.sort();
    Ok(out)
}

/// Empties `out` of `found` (its entries) for `--force`: the old scene is replaced whole, so
/// nothing of it stays beside the new one. Holds the commit lock so no reader sees it half gone.
pub(super) fn empty_out(out: &Path, found: &[PathBuf]) -> Result<()> {
    let _readers_out = CommitGuard::acquire(out)?;
    for p in found {
        let removed = if p.is_dir() && !p.is_symlink() {
            std::fs::remove_dir_all(p)
        } else {
            std::fs::remove_file(p)
        };
        removed.with_context(|| format!("--force: removing {}", p.display()))?;
    }
    Ok(())
}

fn remove_if_empty(dir: &Path) {
    if contents(dir).is_ok_and(|c| c.is_empty()) {
        let _ = std::fs::remove_dir_all(dir);
    }
}

/// The run, once `out` is locked and checked: a non-empty `out` that is not this run's own
/// unfinished scene is refused (naming --resume and --force); --force empties it first.
fn locked(
    a: &GenerateArgs,
    text: &str,
    draft: bool,
    models: Option<&Path>,
    start: Instant,
) -> Result<Vec<StageTime>> {
    let out = &a.out;
    let wait = if a.no_wait { Wait::NoWait } else { Wait::Block };
    let command = std::env::args().collect::<Vec<_>>().join(" ");
    let _lock = if a.lock_held {
        None
    } else {
        Some(SceneLock::acquire(out, wait, &command)?)
    };
    let existing = out.join("scene.json");
    let found = contents(out)?;
    if a.force {
        empty_out(out, &found)?;
    } else if !found.is_empty() {
        let own_run = out.join("spec.json").is_file() || existing.is_file();
        if !(a.resume && own_run) {
            let what = match read_scene(out) {
                Ok(s)
                    if !dreamscene::scene::dir::missing_files(out, &s).is_empty()
                        || super::scene_renders::renders_missing(out) =>
                {
                    "an unfinished scene: files or views are missing".to_string()
                }
                Ok(s) if !s.history.is_empty() => {
                    let n = s.history.len();
                    format!("a scene with {n} edit{}", if n == 1 { "" } else { "s" })
                }
                Ok(_) => "a scene".to_string(),
                Err(_) if own_run => "an unfinished run: a plan, no scene yet".to_string(),
                Err(_) => format!("{} entries", found.len()),
            };
            bail!(
                "{} is not empty (it holds {what}); --resume continues an unfinished run of the \
                 same prompt, --force replaces it, or give another --out",
                out.display()
            );
        }
    }
    let mut keep = false;
    if a.resume && existing.is_file() {
        let scene = read_scene(out).context("--resume")?;
        if check_resume(&scene, text, a.seed)? {
            let missing = dreamscene::scene::dir::missing_files(out, &scene);
            if missing.is_empty() {
                match complete_renders(out, a)? {
                    None => println!(
                        "{} is complete ({} objects); nothing to do",
                        out.display(),
                        scene.objects.len()
                    ),
                    Some(redone) => println!(
                        "{}: rendered {redone}; the scene is complete",
                        out.display()
                    ),
                }
                return Ok(vec![]);
            }
            if !scene.history.is_empty() {
                bail!(
                    "{}: {} missing, and the scene has {} edits that redoing it would lose; \
                     `dreamscene edit {} undo` back to an intact state, or --force to start again",
                    out.display(),
                    missing.join(", "),
                    scene.history.len(),
                    out.display()
                );
            }
            eprintln!("--resume: {} missing; redoing them", missing.join(", "));
        }
        keep = true;
    }
    if !draft {
        let setup = full_setup(a, text, models, a.resume)?;
        return full(a, text, models, start, a.resume, setup);
    }
    let (spec, layout) = plan_or_reuse(text, a, keep)?;
    eprintln!(
        "{}{}",
        plan_line(&layout),
        super::plan::unsatisfied_note(&layout)
    );
    let report = write_draft_scene(out, text, a.seed, &spec, &layout, keep, &mut |l| {
        eprintln!("{l}")
    })?;
    // Said once a draft is written, not before an error.
    if models.is_none() {
        eprintln!("{NO_MODELS}");
    } else {
        eprintln!("--draft: a draft scene from the shape priors, without the diffusion models");
    }
    let renders = out.join("renders");
    let mut rendered = 0;
    if a.renders > 0 {
        let g = dreamscene::splat::ply::read_ply(&out.join("scene.ply"))?;
        rendered = render_chosen(&g, &layout, a.renders, a.resolution, &renders)?;
        eprintln!(
            "renders: {rendered} views chosen by what they show{}; contact sheet {}/overview.png",
            if rendered < a.renders {
                format!(
                    " (of {} asked: the room gives no more distinct good ones)",
                    a.renders
                )
            } else {
                String::new()
            },
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
            format!("{rendered} views in {}", renders.display())
        } else {
            "no renders".to_string()
        },
        d = out.display(),
    );
    Ok(vec![])
}

/// The line that says what was planned: `plan: N objects in W x D x H m`.
pub(super) fn plan_line(layout: &Layout) -> String {
    let [w, d, h] = layout.room.size;
    format!(
        "plan: {} objects in {w:.1} x {d:.1} x {h:.1} m",
        layout.objects.len()
    )
}

/// Whether `a` makes a draft (shape priors, no optimisation), given the models found.
pub(super) fn draft_mode(a: &GenerateArgs, models: Option<&Path>) -> Result<bool> {
    Ok(match (&a.prior, a.draft) {
        (_, true) | (PriorChoice::Shape, _) => true,
        (PriorChoice::Auto, _) => models.is_none(),
        (PriorChoice::Sd, _) if models.is_none() => bail!(
            "--prior sd needs a model directory (--models DIR or DREAMSCENE_MODELS); --draft \
             makes a draft scene without one"
        ),
        (PriorChoice::Sd | PriorChoice::Oracle(_), _) => false,
    })
}

/// What full generation needs, checked before anything is planned or written: the model
/// directory (prior sd) and the numbers the priors take.
fn check_full(a: &GenerateArgs, models: Option<&Path>) -> Result<()> {
    if !matches!(a.prior, PriorChoice::Oracle(_)) {
        let dir = models
            .context("--prior sd needs a model directory (--models DIR or DREAMSCENE_MODELS)")?;
        dreamscene::diffusion::model::StableDiffusion::check_dir(dir)
            .map_err(anyhow::Error::msg)?;
        if a.provider != Provider::Auto {
            dreamscene::diffusion::runtime::check_provider(a.provider)
                .map_err(anyhow::Error::msg)?;
        }
    }
    if !(a.env_density.is_finite() && a.env_density > 0.0) {
        bail!(
            "--env-density {}: expected a positive number of Gaussians per m²",
            a.env_density
        );
    }
    if !a.resolution.is_multiple_of(8) {
        bail!(
            "--resolution {}: the priors need a multiple of 8",
            a.resolution
        );
    }
    Ok(())
}

/// The spec and layout: re-read from `out` when resuming and both are there (an LLM plan is
/// not asked again), else planned afresh.
pub(super) fn plan_or_reuse(
    text: &str,
    a: &GenerateArgs,
    resume: bool,
) -> Result<(SceneSpec, Layout)> {
    let (spec_path, layout_path) = (a.out.join("spec.json"), a.out.join("layout.json"));
    if resume && spec_path.is_file() && layout_path.is_file() {
        let spec = SceneSpec::read(&spec_path)?;
        let layout = Layout::read(&layout_path)?;
        return Ok((spec, layout));
    }
    super::plan::plan_to_dir(text, a.llm.as_ref(), a.seed, &a.out)
}

fn positive_density(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 && v <= 1e6 => Ok(v),
        _ => Err(format!(
            "'{s}': expected a positive number of Gaussians per m² (at most 1e6)"
        )),
    }
}

#[derive(clap::Args)]
pub struct Args {
    /// What to build, e.g. "a cozy living room".
    /// A prompt may start with a hyphen ("- a kitchen", a dialogue's first line).
    #[arg(allow_hyphen_values = true)]
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
    /// ONNX Runtime provider for the models (auto: a GPU provider on a real GPU, else the CPU).
    #[arg(long, value_enum, default_value = "auto")]
    pub provider: Provider,
    /// auto (sd when models are found, else shape), sd, shape, or oracle:DIR (a reference
    /// scene directory).
    #[arg(long, default_value = "auto", value_parser = parse_scene_prior)]
    pub prior: super::object::PriorChoice,
    /// Make the draft (shape priors and the initial environment, no optimisation) even when
    /// models are found.
    #[arg(long)]
    pub draft: bool,
    /// Environment optimisation iterations.
    #[arg(long, default_value_t = 2000, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub iterations: u32,
    /// Formation (MTS) iterations per object.
    #[arg(long, default_value_t = 1500, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub object_iterations: u32,
    /// Render size in pixels (square).
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
    pub resolution: u32,
    /// Views chosen by what they show written to renders/, with overview.png (0: none).
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u64).range(0..=1000))]
    pub renders: u64,
    /// Passes of the scene's reconstructive stage over its 80 views.
    #[arg(long, default_value_t = 25, value_parser = clap::value_parser!(u32).range(0..=10_000))]
    pub recon_passes: u32,
    /// Passes of each object's reconstruction fit over its 20 views.
    #[arg(long, default_value_t = 40, value_parser = clap::value_parser!(u32).range(0..=10_000))]
    pub object_recon_passes: u32,
    /// Gaussians of each object's shape prior (default: from its surface area, 30k-60k).
    #[arg(long, value_parser = clap::value_parser!(u64).range(100..=2_000_000))]
    pub object_gaussians: Option<u64>,
    /// Environment Gaussians per square metre of wall, ceiling and floor (capped at 300k).
    #[arg(long, default_value_t = 1500.0, value_parser = positive_density)]
    pub env_density: f64,
    /// Seed of the layout and the generation.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Continue an interrupted run in --out (same prompt and seed): every output a finished
    /// stage promises is checked and what is missing is redone.
    #[arg(long, conflicts_with = "force")]
    pub resume: bool,
    /// One stage of a scene spread over workers: `objects` (with --shard I/N: that shard's
    /// objects) or `scene` (environment, composition and renders once every object is there).
    #[arg(long, value_enum)]
    pub stage: Option<super::stage::Stage>,
    /// With --stage objects: the worker's shard I/N of the scene's objects (default: all; also
    /// from SLURM_ARRAY_TASK_ID/COUNT or JOB_COMPLETION_INDEX with DREAMSCENE_SHARDS).
    #[arg(long, value_parser = dreamscene::batch::shard::Shard::parse)]
    pub shard: Option<dreamscene::batch::shard::Shard>,
    /// Replace the scene already in --out, whole (its edits and renders included).
    #[arg(long)]
    pub force: bool,
    /// When another command is writing --out, exit at once naming it instead of waiting.
    #[arg(long)]
    pub no_wait: bool,
}

pub fn run(a: Args) -> Result<()> {
    let (stage, shard) = (a.stage, a.shard);
    let args = GenerateArgs {
        prompt: a.prompt,
        out: a.out,
        dialogue: a.dialogue,
        llm: a.llm.config(),
        models: a.models,
        provider: a.provider,
        prior: a.prior,
        draft: a.draft,
        iterations: a.iterations,
        object_iterations: a.object_iterations,
        resolution: a.resolution,
        renders: a.renders as usize,
        recon_passes: a.recon_passes,
        object_recon_passes: a.object_recon_passes,
        object_gaussians: a.object_gaussians.map(|n| n as usize),
        env_density: a.env_density,
        seed: a.seed,
        resume: a.resume,
        force: a.force,
        no_wait: a.no_wait,
        lock_held: false,
    };
    match stage {
        Some(st) => super::stage::run(&args, st, shard),
        None => run_with(args),
    }
}
