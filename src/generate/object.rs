//! Formation Pattern Sampling for one object (paper §IV-B, Algorithm 2): from an initial cloud,
//! B random views per iteration get image targets from the prior under MTS (the decreasing
//! timestep window), the renders are pulled toward them (image-space loss, backward, Adam,
//! densification, SH degree raised every 500 steps); then 3D Gaussian filtering drops the
//! Gaussians that contribute least; then reconstructive generation renders K views once, turns
//! them into pseudo-ground truth at small t, and fits the cloud to them with the 3DGS trainer.
//! Checkpoints hold everything needed to continue exactly (see [`super::checkpoint`]).
use super::checkpoint::{RunState, Stage};
use super::filter::{self, FilterConfig};
use super::prior::Prior;
use super::progress::Progress;
pub use super::stage::{guided_iteration, image_loss, GuidedView, IterationReport};
use super::stage::{
    pseudo_ground_truth, run_fit, run_guided, stage_iteration, GuidedStage, ShSchedule, ViewSource,
};
use crate::camera::object::{random_views, ring_views, sphere_views, ObjectFrame, OrbitRanges};
use crate::diffusion::guidance::{MtsRange, MtsRule, MtsSettings, OBJECT_MTS, OBJECT_RECON};
use crate::diffusion::model::Codec;
use crate::diffusion::target::{Guide, Rule};
use crate::gpu::Context;
use crate::splat::score::ScoreRule;
use crate::splat::train::{FitConfig, Trainer};
use crate::splat::Gaussians;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::{Path, PathBuf};

use std::time::Instant;

/// Settings of one object generation. Defaults are the paper's and the authors' code's.
#[derive(Debug, Clone)]
pub struct ObjectConfig {
    /// Formation (MTS) iterations.
    pub iterations: u32,
    /// Views per iteration (the authors' `C_batch_size`).
    pub batch: usize,
    /// Render size (square).
    pub resolution: u32,
    /// The guidance rule of the formation stage.
    pub rule: Rule,
    /// Paper or code form of MTS.
    pub mts_form: MtsRule,
    /// Final SH degree, reached one degree every `sh_every` iterations.
    pub sh_degree: u32,
    pub sh_every: u32,
    /// Probability that a training view gets a random (50%) or black (50%) background instead
    /// of white.
    pub background_aug: f64,
    /// Filtering after the formation stage (`None`: off).
    pub filter: Option<FilterConfig>,
    /// Reconstructive generation: views rendered once into pseudo-ground truth (0: off) and
    /// passes of the fit over them.
    pub recon_views: usize,
    pub recon_passes: u32,
    pub max_gaussians: usize,
    /// Checkpoint every this many iterations (0: only between stages).
    pub checkpoint_every: u32,
    pub seed: u64,
}

impl Default for ObjectConfig {
    fn default() -> Self {
        ObjectConfig {
            iterations: 1500,
            batch: 4,
            resolution: 512,
            rule: Rule::Mts { m: 4 },
            mts_form: MtsRule::Paper,
            sh_degree: 3,
            sh_every: 500,
            background_aug: 0.66,
            filter: Some(FilterConfig::default()),
            recon_views: 20,
            recon_passes: 40,
            max_gaussians: 1_200_000,
            checkpoint_every: 100,
            seed: 0,
        }
    }
}

impl ObjectConfig {
    /// Everything a checkpoint must agree on to be resumed.
    pub fn fingerprint(&self, prompt: &str, prior: &str) -> String {
        format!(
            "{prompt}|{prior}|{}|{}|{}|{:?}|{:?}|{}|{}|{:?}|{}|{}|{}",
            self.iterations,
            self.batch,
            self.resolution,
            self.rule,
            self.mts_form,
            self.sh_degree,
            self.background_aug,
            self.filter,
            self.recon_views,
            self.recon_passes,
            self.seed
        )
    }

    fn recon_steps(&self) -> u32 {
        if self.recon_views == 0 {
            0
        } else {
            self.recon_passes * self.recon_views as u32
        }
    }
}

/// Gaussian counts through the run (`object.json`).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Counts {
    pub initial: usize,
    pub before_filter: usize,
    pub after_filter: usize,
    #[serde(rename = "final")]
    pub final_: usize,
}

/// What a run produced besides the cloud.
#[derive(Debug, Clone)]
pub struct ObjectReport {
    pub counts: Counts,
    pub seconds: f64,
    /// Seconds spent in each stage: formation, filtering, reconstruction.
    pub stage_seconds: [f64; 3],
    /// Split of a formation iteration: GPU work, prior and host (seconds in total).
    pub formation_split: [f64; 3],
}

/// Errors of the generators.
#[derive(Debug, thiserror::Error)]
pub enum GenError {
    #[error(transparent)]
    Gpu(#[from] crate::gpu::GpuError),
    #[error("prior: {0}")]
    Prior(#[from] crate::diffusion::Error),
    #[error("{0}")]
    Checkpoint(String),
    #[error("{path}: {err}")]
    Io { path: PathBuf, err: std::io::Error },
}

/// The authors' object learning rates (formation stage), relative to the extent of 3.5.
fn formation_fit(cfg: &ObjectConfig) -> FitConfig {
    let it = cfg.iterations.max(1) as f64;
    FitConfig {
        iterations: cfg.iterations,
        lr_means: (8e-4 / 3.5, 1.6e-5 / 3.5),
        lr_sh: 0.02,
        lr_sh_final: Some(0.003),
        lr_scales: 0.005,
        lr_scales_final: Some(0.001),
        lr_rotations: 0.001,
        lr_rotations_final: Some(2e-4),
        lr_opacities: 0.05,
        densify: true,
        densify_from: 100.0 / 1500.0,
        densify_until: (1400.0 / 1500.0f64).min((it - 1.0) / it),
        densify_every: (cfg.iterations / 15).clamp(5, 100),
        // The authors reset opacities at step 600 of 1500; a short run (tests, quick checks)
        // cannot grow them back, so it keeps them.
        opacity_reset: if cfg.iterations >= 1000 { 0.4 } else { 0.0 },
        grad_threshold: 1e-4,
        percent_dense: 0.003,
        max_gaussians: cfg.max_gaussians,
        seed: cfg.seed ^ 0x5eed,
        ..FitConfig::default()
    }
}

/// The authors' reconstructive-stage learning rates and schedule.
fn recon_fit(cfg: &ObjectConfig) -> FitConfig {
    FitConfig {
        iterations: cfg.recon_steps(),
        lambda_dssim: 0.2,
        background: [1.0; 3],
        lr_means: (8e-4 / 3.5, 8e-6 / 3.5),
        lr_sh: 0.005,
        lr_sh_final: Some(0.004),
        lr_scales: 0.005,
        lr_scales_final: Some(0.002),
        lr_rotations: 0.001,
        lr_rotations_final: Some(2e-4),
        lr_opacities: 0.05,
        densify: true,
        densify_from: 0.0,
        densify_until: 0.8,
        densify_every: 100,
        opacity_reset: 0.0,
        percent_dense: 0.01,
        max_gaussians: cfg.max_gaussians,
        seed: cfg.seed ^ 0x7ec0,
        ..FitConfig::default()
    }
}

fn guide(cfg: &ObjectConfig, rule: Rule, range: MtsRange, salt: u64) -> Guide {
    let settings = MtsSettings {
        rule: cfg.mts_form,
        ..MtsSettings::default()
    };
    Guide::new(rule, range, settings, Codec::Fast, cfg.seed ^ salt)
}

/// A view's background: white, or with probability `aug` a random colour or black (half each).
fn background(rng: &mut ChaCha8Rng, aug: f64) -> [f32; 3] {
    if rng.gen_bool(aug.clamp(0.0, 1.0)) {
        if rng.gen_bool(0.5) {
            [rng.gen(), rng.gen(), rng.gen()]
        } else {
            [0.0; 3]
        }
    } else {
        [1.0; 3]
    }
}

/// Where a run keeps its checkpoints, and whether to continue from them.
pub struct Checkpoints<'a> {
    pub dir: &'a Path,
    pub resume: bool,
    /// Must match the checkpoint's for it to be resumed (prompt, prior, settings).
    pub fingerprint: String,
}

/// Generates one object: formation from `init`, filtering, reconstruction. `frame` gives its
/// size (cameras scale with it). Returns the final cloud (object frame) and the report.
pub fn generate_object(
    ctx: &Context,
    init: &Gaussians,
    frame: &ObjectFrame,
    prior: &mut dyn Prior,
    cfg: &ObjectConfig,
    ckpt: Option<&Checkpoints>,
    progress: &mut Progress,
) -> Result<(Gaussians, ObjectReport), GenError> {
    let start = Instant::now();
    let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed);
    let mut form_guide = formation_guide(cfg);
    let mut recon_guide = guide(cfg, Rule::PseudoGt, OBJECT_RECON, 0x7265);
    let mut run = RunState::new(init.len());
    let mut trainer;
    if let Some(state) = ckpt
        .and_then(|c| c.resume.then_some(c))
        .map(RunState::load)
        .transpose()?
    {
        let c = ckpt.expect("resuming needs checkpoints");
        if state.fingerprint != c.fingerprint {
            return Err(GenError::Checkpoint(format!(
                "{}: the checkpoint is of another run (prompt, prior, seed or settings differ); \
                 remove it or drop --resume",
                c.dir.display()
            )));
        }
        run = state;
        rng.set_word_pos(run.rng);
        form_guide.set_rng_position(run.guide);
        recon_guide.set_rng_position(run.recon_guide);
        progress.println(&format!(
            "resuming at {} iteration {}",
            run.stage.name(),
            run.iteration
        ));
        trainer = None;
    } else {
        trainer = Some(Trainer::guided(
            ctx,
            init,
            formation_fit(cfg),
            frame.extent(),
        )?);
    }
    let total = cfg.iterations as u64 + cfg.recon_steps() as u64 + 1;
    let mut stage_seconds = run.stage_seconds;
    let mut split = [0.0f64; 3];

    // ---- formation (MTS) ----
    if run.stage == Stage::Formation {
        let mut t = match trainer.take() {
            Some(t) => t,
            None => {
                let c = ckpt.expect("resume has checkpoints");
                let g = run.load_ply(c.dir)?;
                let mut t = Trainer::guided(ctx, &g, formation_fit(cfg), frame.extent())?;
                run.restore_trainer(c.dir, &mut t)?;
                t
            }
        };
        let ranges = OrbitRanges::default();
        let mut views = formation_views(frame, &ranges, cfg);
        let mut stage = formation_stage(cfg, &mut views);
        let totals = run_guided(
            &mut stage,
            &mut t,
            prior,
            &mut form_guide,
            &mut rng,
            &mut |t, r, guide, rng, due| {
                stage_seconds[0] += r.seconds;
                progress.update(
                    t.iteration() as u64,
                    &format!("formation loss {:.5} gaussians {}", r.loss, t.len()),
                );
                if let (Some(c), true) = (ckpt, due) {
                    run.rng = rng.get_word_pos();
                    run.guide = guide.rng_position();
                    run.recon_guide = recon_guide.rng_position();
                    run.stage_seconds = stage_seconds;
                    run.save_formation(c, t)?;
                }
                Ok(())
            },
        )?;
        split = totals.split;
        // ---- filtering ----
        let tf = Instant::now();
        run.counts.before_filter = t.len();
        let mut g = t.gaussians()?;
        if let Some(f) = &cfg.filter {
            let cams = sphere_views(frame, f.views, cfg.resolution, &mut rng);
            let scores = filter::scores(
                ctx,
                &crate::splat::raster::Rasterizer::new(ctx)?,
                t.device_gaussians(),
                &cams,
                f.rule,
            )?;
            let keep = filter::keep_mask(&scores, f.fraction);
            g = subset(&g, &keep);
            progress.println(&format!(
                "filtering removed {} of {} Gaussians ({:.1}%)",
                run.counts.before_filter - g.len(),
                run.counts.before_filter,
                100.0 * (run.counts.before_filter - g.len()) as f64
                    / run.counts.before_filter.max(1) as f64
            ));
        }
        run.counts.after_filter = g.len();
        stage_seconds[1] += tf.elapsed().as_secs_f64();
        run.stage = Stage::Reconstruction;
        run.iteration = 0;
        run.rng = rng.get_word_pos();
        run.guide = form_guide.rng_position();
        run.recon_guide = recon_guide.rng_position();
        run.stage_seconds = stage_seconds;
        if let Some(c) = ckpt {
            run.save_filtered(c, &g)?;
        }
        run.filtered = Some(g);
    }

    // ---- reconstructive generation ----
    let filtered = match run.filtered.take() {
        Some(g) => g,
        None => run.load_filtered(ckpt.expect("resume has checkpoints").dir)?,
    };
    let mut result = filtered.clone();
    if run.stage == Stage::Reconstruction && cfg.recon_steps() > 0 {
        let tr = Instant::now();
        // Pseudo-ground truth, made once from the filtered cloud (deterministic given the
        // guide's position, so a resumed run makes the same targets).
        recon_guide.set_rng_position(run.recon_guide);
        let views: Vec<GuidedView> = ring_views(frame, cfg.recon_views, cfg.resolution)
            .into_iter()
            .map(|v| GuidedView {
                camera: v.camera,
                background: [1.0; 3],
                azimuth: v.azimuth,
                elevation: v.elevation,
            })
            .collect();
        let views =
            pseudo_ground_truth(ctx, &filtered, prior, &mut recon_guide, &views, cfg.batch)?;
        let mut t = if run.iteration > 0 {
            let c = ckpt.expect("resume has checkpoints");
            let g = run.load_ply(c.dir)?;
            let mut t = Trainer::new(ctx, &g, views, recon_fit(cfg))?;
            run.restore_trainer(c.dir, &mut t)?;
            t
        } else {
            Trainer::new(ctx, &filtered, views, recon_fit(cfg))?
        };
        let every = if ckpt.is_some() {
            cfg.checkpoint_every
        } else {
            0
        };
        run_fit(&mut t, cfg.recon_steps(), every, &mut |t, r, due| {
            progress.update(
                cfg.iterations as u64 + r.iteration as u64,
                &format!(
                    "reconstruction loss {:.4} psnr {:.1} gaussians {}",
                    r.loss, r.psnr, r.gaussians
                ),
            );
            if let (Some(c), true) = (ckpt, due) {
                run.stage_seconds = stage_seconds;
                run.save_recon(c, t)?;
            }
            Ok(())
        })?;
        stage_seconds[2] += tr.elapsed().as_secs_f64();
        result = t.gaussians()?;
    }
    run.counts.final_ = result.len();
    run.stage = Stage::Done;
    run.stage_seconds = stage_seconds;
    if let Some(c) = ckpt {
        run.save_done(c)?;
    }
    progress.update(total, &format!("done, {} gaussians", result.len()));
    Ok((
        result,
        ObjectReport {
            counts: run.counts,
            seconds: run.previous_seconds + start.elapsed().as_secs_f64(),
            stage_seconds,
            formation_split: split,
        },
    ))
}

/// The formation trainer for `init` (the authors' formation learning rates and schedule).
pub fn formation_trainer(
    ctx: &Context,
    init: &Gaussians,
    frame: &ObjectFrame,
    cfg: &ObjectConfig,
) -> Result<Trainer, GenError> {
    Ok(Trainer::guided(
        ctx,
        init,
        formation_fit(cfg),
        frame.extent(),
    )?)
}

/// The formation stage's guide (MTS over the run's length).
pub fn formation_guide(cfg: &ObjectConfig) -> Guide {
    guide(cfg, cfg.rule, OBJECT_MTS_FOR(cfg), 0x6d7473)
}

/// The formation stage's views: `cfg.batch` random orbit views, each with its background
/// (white, or with probability `cfg.background_aug` random or black).
pub fn formation_views<'a>(
    frame: &'a ObjectFrame,
    ranges: &'a OrbitRanges,
    cfg: &'a ObjectConfig,
) -> impl FnMut(u32, &mut ChaCha8Rng) -> Vec<GuidedView> + 'a {
    move |step, rng| {
        random_views(frame, ranges, step, cfg.batch, cfg.resolution, rng)
            .into_iter()
            .map(|v| GuidedView {
                background: background(rng, cfg.background_aug),
                camera: v.camera,
                azimuth: v.azimuth,
                elevation: v.elevation,
            })
            .collect()
    }
}

/// The formation stage (Algorithm 2's loop): every Gaussian trains, the SH degree rises on
/// schedule, checkpoints every `cfg.checkpoint_every` iterations.
pub fn formation_stage<'a>(cfg: &ObjectConfig, views: &'a mut ViewSource<'a>) -> GuidedStage<'a> {
    GuidedStage {
        iterations: cfg.iterations,
        trainable: None,
        sh: Some(ShSchedule {
            degree: cfg.sh_degree,
            every: cfg.sh_every,
        }),
        checkpoint_every: cfg.checkpoint_every,
        views,
    }
}

/// One formation iteration (the body of Algorithm 2's loop), for measurements: the formation
/// stage's [`stage_iteration`].
pub fn formation_iteration(
    t: &mut Trainer,
    prior: &mut dyn Prior,
    guide: &mut Guide,
    rng: &mut ChaCha8Rng,
    frame: &ObjectFrame,
    ranges: &OrbitRanges,
    cfg: &ObjectConfig,
) -> Result<IterationReport, GenError> {
    let mut views = formation_views(frame, ranges, cfg);
    let mut stage = formation_stage(cfg, &mut views);
    stage_iteration(&mut stage, t, prior, guide, rng)
}

/// The formation range with the run's length as its period (T_end reaches its floor at the end).
#[allow(
    non_snake_case,
    reason = "named like the authors' OBJECT_MTS constant it replaces"
)]
fn OBJECT_MTS_FOR(cfg: &ObjectConfig) -> MtsRange {
    MtsRange {
        period: cfg.iterations.max(1),
        ..OBJECT_MTS
    }
}

/// The Gaussians where `keep` is true.
pub fn subset(g: &Gaussians, keep: &[bool]) -> Gaussians {
    let k3 = g.coeffs() * 3;
    let mut out = Gaussians {
        sh_degree: g.sh_degree,
        ..Default::default()
    };
    for i in (0..g.len()).filter(|&i| keep[i]) {
        out.means.push(g.means[i]);
        out.scales.push(g.scales[i]);
        out.rotations.push(g.rotations[i]);
        out.opacities.push(g.opacities[i]);
        out.sh.extend_from_slice(&g.sh[i * k3..(i + 1) * k3]);
    }
    out
}

/// A filtering rule by name (`paper` or `code`).
pub fn parse_score_rule(s: &str) -> Option<ScoreRule> {
    match s {
        "paper" => Some(ScoreRule::Paper),
        "code" => Some(ScoreRule::Code),
        _ => None,
    }
}
