//! `dreamscene batch MANIFEST --out DIR`: many scenes, one worker per call; Slurm, Kubernetes or a
//! shell loop starts as many as it likes. `dreamscene batch --status DIR` counts them.
use super::generate::{parse_scene_prior, run_timed, GenerateArgs};
use super::object::PriorChoice;
use anyhow::{bail, Context as _, Result};
use dreamscene::batch::index::{self, Counts, SceneRecord, StageTime, Status};
use dreamscene::batch::manifest::{self, Entry};
use dreamscene::batch::shard::{self, Shard};
use dreamscene::batch::worker::{self, Outcome, WorkerOptions};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

#[derive(clap::Args)]
pub struct Args {
    /// One prompt a line, or JSONL of {"id", "prompt", "seed", ...generate flags}.
    #[arg(required_unless_present = "status")]
    pub manifest: Option<PathBuf>,
    /// Batch directory: DIR/<id>/ per scene, DIR/index.json, DIR/index.html.
    #[arg(long, required_unless_present = "status")]
    pub out: Option<PathBuf>,
    /// Print done/running/failed/left of a batch directory and exit.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["manifest", "out"])]
    pub status: Option<PathBuf>,
    /// This worker's shard I/N (default: SLURM_ARRAY_TASK_ID/COUNT, else JOB_COMPLETION_INDEX
    /// with --shards or DREAMSCENE_SHARDS, else every scene it can claim).
    #[arg(long, value_parser = Shard::parse)]
    pub shard: Option<Shard>,
    /// Shard count for a Kubernetes Indexed Job (its completions).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..))]
    pub shards: Option<u32>,
    /// The generate flags every scene gets unless its manifest line sets them.
    #[arg(long)]
    pub draft: bool,
    #[arg(long, default_value = "auto", value_parser = parse_scene_prior)]
    pub prior: PriorChoice,
    #[arg(long)]
    pub models: Option<PathBuf>,
    /// ONNX Runtime provider of the sd prior's models (auto: a GPU provider on a real GPU, else
    /// the CPU).
    #[arg(long, value_enum, default_value_t = dreamscene::diffusion::runtime::Provider::Auto)]
    pub provider: dreamscene::diffusion::runtime::Provider,
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
    pub resolution: u32,
    #[arg(long, default_value_t = 8)]
    pub renders: usize,
    #[arg(long, default_value_t = 2000, value_parser = clap::value_parser!(u32).range(1..))]
    pub iterations: u32,
    #[arg(long, default_value_t = 1500, value_parser = clap::value_parser!(u32).range(1..))]
    pub object_iterations: u32,
    #[arg(long, default_value_t = 25)]
    pub recon_passes: u32,
    #[arg(long, default_value_t = 40)]
    pub object_recon_passes: u32,
    #[arg(long)]
    pub object_gaussians: Option<usize>,
    #[arg(long, default_value_t = 1500.0)]
    pub env_density: f64,
    /// Seed of scenes whose line sets none.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
}

pub fn run(a: Args) -> Result<()> {
    if let Some(dir) = &a.status {
        return status(dir);
    }
    let (Some(manifest_path), Some(out)) = (a.manifest.clone(), a.out.clone()) else {
        bail!("batch needs MANIFEST and --out DIR (or --status DIR)");
    };
    let entries = manifest::read(&manifest_path)?;
    // Every line's flags are checked before any scene starts.
    for e in &entries {
        scene_args(&a, e, &out.join(&e.id))?;
    }
    let env = |k: &str| std::env::var(k).ok();
    let shard = shard::resolve(a.shard, a.shards, &env).map_err(anyhow::Error::msg)?;
    let stop = Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    ctrlc::set_handler(move || flag.store(true, Ordering::SeqCst))
        .context("installing the SIGTERM/SIGINT handler")?;
    let opts = WorkerOptions {
        out: out.clone(),
        shard,
        name: format!("{} pid {}", hostname(), std::process::id()),
    };
    let t = Instant::now();
    let sum = worker::run(
        &opts,
        &entries,
        &stop,
        &mut |e, dir| {
            scene_args(&a, e, dir).and_then(run_scene).map_err(|err| {
                let chain: Vec<String> = err.chain().map(|c| c.to_string()).collect();
                chain.join(": ")
            })
        },
        &mut |l| eprintln!("{l}"),
    )?;
    println!(
        "batch{}: {} scenes: {} done now, {} failed, {} done before, {} held by another worker in \
         {:.1} s; {}",
        shard.map_or(String::new(), |s| format!(" shard {s}")),
        sum.mine,
        sum.done,
        sum.failed,
        sum.skipped,
        sum.busy,
        t.elapsed().as_secs_f64(),
        out.join(index::INDEX).display()
    );
    if sum.stopped {
        bail!(
            "stopped by a signal with {} scenes left; run the same command again to resume them",
            sum.left
        );
    }
    if sum.failed > 0 {
        bail!(
            "{} scenes failed (their errors are in {})",
            sum.failed,
            out.join(index::INDEX).display()
        );
    }
    Ok(())
}

/// One scene: a draft in timed stages, else a whole `generate --resume`.
fn run_scene(g: GenerateArgs) -> Result<Outcome> {
    if super::stage::is_draft(&g)? {
        let (stages, gaussians) = super::stage::draft_timed(&g)?;
        return Ok(Outcome {
            stages,
            gaussians: Some(gaussians),
        });
    }
    let t = Instant::now();
    let scene_ply = g.out.join("scene.ply");
    let mut stages = run_timed(g)?;
    if stages.is_empty() {
        stages.push(StageTime {
            name: "generate".into(),
            seconds: t.elapsed().as_secs_f64(),
        });
    }
    let gaussians = dreamscene::splat::ply::read_ply(&scene_ply)
        .ok()
        .map(|p| p.len());
    Ok(Outcome { stages, gaussians })
}

/// The generate arguments of one manifest line over the batch's own.
fn scene_args(a: &Args, e: &Entry, out: &Path) -> Result<GenerateArgs> {
    let prior = match &e.prior {
        Some(p) => parse_scene_prior(p)
            .map_err(|m| anyhow::anyhow!("manifest scene `{}`: --prior {m}", e.id))?,
        None => a.prior.clone(),
    };
    let resolution = e.resolution.unwrap_or(a.resolution);
    if !(16..=2048).contains(&resolution) {
        bail!(
            "manifest scene `{}`: resolution {resolution} is outside 16 to 2048",
            e.id
        );
    }
    Ok(GenerateArgs {
        prompt: Some(e.prompt.clone()),
        out: out.to_path_buf(),
        dialogue: None,
        llm: None,
        models: e.models.clone().or_else(|| a.models.clone()),
        provider: a.provider,
        prior,
        draft: e.draft.unwrap_or(a.draft),
        iterations: e.iterations.unwrap_or(a.iterations).max(1),
        object_iterations: e.object_iterations.unwrap_or(a.object_iterations).max(1),
        resolution,
        renders: e.renders.unwrap_or(a.renders),
        recon_passes: e.recon_passes.unwrap_or(a.recon_passes),
        object_recon_passes: e.object_recon_passes.unwrap_or(a.object_recon_passes),
        object_gaussians: e.object_gaussians.or(a.object_gaussians),
        env_density: e.env_density.unwrap_or(a.env_density),
        seed: e.seed.unwrap_or(a.seed),
        resume: true,
        force: false,
        no_wait: true,
        lock_held: true,
    })
}

fn hostname() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .map(|h| h.trim().to_string())
        .ok()
        .filter(|h| !h.is_empty())
        .or_else(|| std::env::var("HOSTNAME").ok())
        .unwrap_or_else(|| "localhost".into())
}

/// Whether a running record's worker is known to be gone: it ran on this host and its pid is
/// no longer alive. Workers on other hosts are taken at their word.
fn gone(r: &SceneRecord) -> bool {
    let Some(w) = &r.worker else { return true };
    let mut it = w.split(' ');
    let (Some(host), Some("pid"), Some(pid)) = (it.next(), it.next(), it.next()) else {
        return false;
    };
    let pid = pid.trim_end_matches(',');
    host == hostname() && !Path::new("/proc").join(pid).exists()
}

/// `batch --status DIR`.
fn status(dir: &Path) -> Result<()> {
    if !dir.join(index::INDEX).is_file() {
        bail!("{}: no index.json (not a batch directory)", dir.display());
    }
    let ix = index::read(dir)?;
    let c = Counts::of(&ix, &gone);
    println!(
        "{}: {} scenes: {} done, {} running, {} failed, {} left",
        dir.display(),
        ix.scenes.len(),
        c.done,
        c.running,
        c.failed,
        c.left
    );
    for r in &ix.scenes {
        match r.status {
            Status::Failed => println!(
                "  failed  {}: {}",
                r.id,
                r.error.as_deref().unwrap_or("no error recorded")
            ),
            Status::Running if gone(r) => println!(
                "  interrupted  {} ({}): resumes on the next run",
                r.id,
                r.worker.as_deref().unwrap_or("?")
            ),
            Status::Running => println!(
                "  running  {} ({})",
                r.id,
                r.worker.as_deref().unwrap_or("?")
            ),
            _ => {}
        }
    }
    Ok(())
}
