//! `dreamscene fit`: 3DGS optimisation of Gaussians to posed images.
use super::{create_parent, open_device};
use anyhow::{bail, Context as _, Result};
use dreamscene::camera::read_cameras;
use dreamscene::generate::progress::Progress;
use dreamscene::splat::ply::write_ply;
use dreamscene::splat::train::{load_views, random_init, FitConfig, Trainer, View};
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Directory of training images.
    #[arg(long)]
    pub images: PathBuf,
    /// INRIA cameras.json with one camera per image.
    #[arg(long)]
    pub cameras: PathBuf,
    /// Output PLY.
    #[arg(long)]
    pub out: PathBuf,
    /// Optimisation steps (one view each).
    #[arg(long, default_value_t = 7000)]
    pub iterations: u32,
    /// Start from this PLY instead of random Gaussians.
    #[arg(long)]
    pub init: Option<PathBuf>,
    /// Random Gaussians to start from (without --init), placed in the region the cameras see.
    #[arg(long, default_value_t = 10_000)]
    pub init_gaussians: usize,
    /// SH degree of a random start (0 to 3).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(0..=3))]
    pub sh_degree: u32,
    /// Background colour as R,G,B in [0, 1] (transparent image pixels are composited over it).
    #[arg(long, default_value = "0,0,0", value_parser = super::parse_rgb)]
    pub background: [f32; 3],
    /// Turn off densification and pruning.
    #[arg(long)]
    pub no_densify: bool,
    /// Write the model every N iterations (0: only at the end).
    #[arg(long, default_value_t = 1000)]
    pub checkpoint_every: u32,
    /// Seed of the random start and the view order.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Continue an interrupted fit from --out and <out>.state. It must ask for the same
    /// --iterations as the interrupted fit (its schedules are fractions of the run); to train
    /// further, start a new fit with --init <out>.
    #[arg(long, conflicts_with = "init")]
    pub resume: bool,
    /// Leave out Gaussians of --init with non-finite values (NaN, Inf) or a zero rotation,
    /// saying how many, instead of refusing the PLY.
    #[arg(long)]
    pub drop_invalid: bool,
}

pub fn run(a: Args) -> Result<()> {
    let cams = read_cameras(&a.cameras)?;
    let views = load_views(&a.images, &cams, a.background).map_err(anyhow::Error::msg)?;
    let state = a.resume.then(|| state_path(&a.out));
    if let Some(st) = &state {
        if !a.out.is_file() || !st.is_file() {
            bail!(
                "--resume needs {} and {} from an earlier fit",
                a.out.display(),
                st.display()
            );
        }
    }
    // Find out now, not after the last iteration, that the results cannot be written.
    create_parent(&a.out)?;
    check_writable(&a.out)?;
    check_writable(&state_path(&a.out))?;
    let start = match a.init.or(a.resume.then(|| a.out.clone())) {
        Some(p) => super::render::read_splats(&p, a.drop_invalid)?,
        None => {
            if a.init_gaussians == 0 {
                bail!("--init-gaussians must be at least 1");
            }
            random_init(&cams, a.init_gaussians, a.sh_degree, a.seed)
        }
    };
    let config = FitConfig {
        iterations: a.iterations,
        background: a.background,
        densify: !a.no_densify,
        seed: a.seed,
        ..Default::default()
    };
    fit(
        &start,
        views,
        config,
        &a.out,
        a.checkpoint_every,
        state.as_deref(),
    )
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
    let mut progress = Progress::new(iterations as u64, false);
    let started = std::time::Instant::now();
    let first = t.iteration();
    let state = state_path(out);
    let save = |t: &Trainer| -> Result<()> {
        let g = t.gaussians()?;
        write_ply(out, &g).with_context(|| format!("writing {}", out.display()))?;
        t.save_state(&state)
            .with_context(|| format!("writing {}", state.display()))
    };
    // Loss and PSNR averaged over the last epoch-sized window, for a steadier readout.
    let mut window: std::collections::VecDeque<(f64, f64)> = Default::default();
    let mean = |w: &std::collections::VecDeque<(f64, f64)>| {
        let k = w.len().max(1) as f64;
        let (l, p) = w.iter().fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
        (l / k, p / k)
    };
    while t.iteration() < iterations {
        let r = t.step()?;
        window.push_back((r.loss, r.psnr));
        if window.len() > n_views {
            window.pop_front();
        }
        let (l, p) = mean(&window);
        progress.update(
            r.iteration as u64,
            &format!(
                "fit iteration {}: loss {l:.4}, PSNR {p:.2} dB, {} Gaussians",
                r.iteration, r.gaussians
            ),
        );
        if checkpoint_every > 0 && r.iteration % checkpoint_every == 0 && r.iteration < iterations {
            save(&t)?;
        }
    }
    save(&t)?;
    progress.finish();
    let (l, p) = mean(&window);
    println!(
        "wrote {} ({} Gaussians): iterations {first} to {iterations} in {:.1} s, PSNR {p:.2} dB \
         and loss {l:.4} over the last {} views",
        out.display(),
        t.len(),
        started.elapsed().as_secs_f64(),
        window.len()
    );
    Ok(())
}

/// Refuses a path that [`dreamscene::util::write_atomic`] could not write.
fn check_writable(path: &Path) -> Result<()> {
    dreamscene::util::check_writable(path).map_err(|e| anyhow::anyhow!("cannot write: {e}"))
}
