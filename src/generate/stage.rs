//! The one stage loop of the generators and the edits. Object formation, the environment and
//! floor stages, local re-optimisation and restyling are [`GuidedStage`] descriptions (how many
//! iterations, which Gaussians train, how the SH degree rises, where each iteration's views come
//! from, the checkpoint cadence) run by [`run_guided`]; the reconstructive stages of objects,
//! scenes and local edits make their pseudo-ground truth with [`pseudo_ground_truth`] and fit it
//! with [`run_fit`]. A stage's caller keeps the trainer, the prior, the guide and the generator
//! of its views; the loop tells it after every iteration whether a checkpoint is due, and the
//! checkpoint itself is written in the one format of [`super::checkpoint`].
use super::object::GenError;
use super::prior::{Prior, PriorView};
use crate::camera::Camera;
use crate::diffusion::convert::worth_parallel;
use crate::diffusion::target::Guide;
use crate::diffusion::Error;
use crate::gpu::{Context, Timings};
use crate::splat::guided::BatchView;
use crate::splat::train::{FitConfig, StepReport, Trainer, View};
use crate::splat::Gaussians;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use std::ops::Range;
use std::time::Instant;

/// One view of a guided iteration: camera, background and the angles its prompt depends on.
#[derive(Debug, Clone)]
pub struct GuidedView {
    pub camera: Camera,
    pub background: [f32; 3],
    pub azimuth: f64,
    pub elevation: f64,
}

/// The SH degree rises by one every `every` iterations up to `degree`.
#[derive(Debug, Clone, Copy)]
pub struct ShSchedule {
    pub degree: u32,
    pub every: u32,
}

/// Where a stage's views come from: iteration `step`'s views, drawn with the stage's generator.
pub type ViewSource<'a> = dyn FnMut(u32, &mut ChaCha8Rng) -> Vec<GuidedView> + 'a;

/// A guided stage: everything that differs between formation, the environment stages, local
/// re-optimisation and restyling.
pub struct GuidedStage<'a> {
    /// Iterations the stage runs to (the trainer's iteration counter).
    pub iterations: u32,
    /// The Gaussians that train (`None`: all); the others keep their parameters bit for bit.
    pub trainable: Option<Range<u32>>,
    /// SH degree schedule (`None`: the degree stays).
    pub sh: Option<ShSchedule>,
    /// A checkpoint is due every this many iterations (0: never inside the stage).
    pub checkpoint_every: u32,
    pub views: &'a mut ViewSource<'a>,
}

/// What one guided iteration took.
#[derive(Debug, Clone, Default)]
pub struct IterationReport {
    /// The batch's mean loss.
    pub loss: f64,
    /// Wall time of the whole iteration.
    pub seconds: f64,
    /// Wall time of the prior's targets.
    pub prior_seconds: f64,
    /// Wall time of the backward passes and Adam ([`Trainer::apply`]).
    pub apply_seconds: f64,
    /// GPU times of the renders, backward passes and Adam (empty unless the trainer is timed,
    /// [`Trainer::set_timed`]).
    pub kernels: Timings,
}

/// Totals of a stage run: the last iteration's loss and the split of its wall time into GPU
/// work (backward and Adam), the prior and the rest (seconds).
#[derive(Debug, Clone, Copy, Default)]
pub struct StageTotals {
    pub loss: f64,
    pub seconds: f64,
    pub split: [f64; 3],
}

/// Called after every iteration with the trainer, the iteration's report, the guide and the
/// view generator (whose positions a checkpoint records) and whether a checkpoint is due.
pub type Observer<'a> =
    dyn FnMut(&Trainer, &IterationReport, &Guide, &ChaCha8Rng, bool) -> Result<(), GenError> + 'a;

/// Runs `stage` from the trainer's current iteration to its end.
pub fn run_guided(
    stage: &mut GuidedStage,
    t: &mut Trainer,
    prior: &mut dyn Prior,
    guide: &mut Guide,
    rng: &mut ChaCha8Rng,
    observe: &mut Observer,
) -> Result<StageTotals, GenError> {
    let mut totals = StageTotals::default();
    while t.iteration() < stage.iterations {
        let r = stage_iteration(stage, t, prior, guide, rng)?;
        totals.loss = r.loss;
        totals.seconds += r.seconds;
        totals.split[0] += r.apply_seconds;
        totals.split[1] += r.prior_seconds;
        totals.split[2] += r.seconds - r.apply_seconds - r.prior_seconds;
        let it = t.iteration();
        let due = stage.checkpoint_every > 0
            && it.is_multiple_of(stage.checkpoint_every)
            && it < stage.iterations;
        observe(t, &r, guide, rng, due)?;
    }
    Ok(totals)
}

/// One iteration of `stage` (the body of Algorithm 2's loop): raise the SH degree on schedule,
/// draw the views, render them, ask the prior for their targets, and apply the image loss's
/// gradient in one Adam step.
pub fn stage_iteration(
    stage: &mut GuidedStage,
    t: &mut Trainer,
    prior: &mut dyn Prior,
    guide: &mut Guide,
    rng: &mut ChaCha8Rng,
) -> Result<IterationReport, GenError> {
    let t0 = Instant::now();
    let step = t.iteration();
    if let Some(sh) = stage.sh {
        let want = (step / sh.every.max(1)).min(sh.degree);
        if t.device_gaussians().sh_degree < want {
            t.set_sh_degree(want)?;
        }
    }
    let views = (stage.views)(step, rng);
    let mut report = guided_iteration(t, prior, guide, &views, stage.trainable.clone())?;
    report.seconds = t0.elapsed().as_secs_f64();
    Ok(report)
}

/// Renders `views`, asks the prior for all their targets at once, and applies the image loss's
/// gradient in one Adam step (only `trainable` Gaussians move when it is set).
pub fn guided_iteration(
    t: &mut Trainer,
    prior: &mut dyn Prior,
    guide: &mut Guide,
    views: &[GuidedView],
    trainable: Option<Range<u32>>,
) -> Result<IterationReport, GenError> {
    let t0 = Instant::now();
    let step = t.iteration();
    let mut report = IterationReport::default();
    let (batch, targets) = render_and_ask(
        t,
        prior,
        guide,
        views,
        step,
        &mut report.kernels,
        &mut report.prior_seconds,
    )?;
    // The views' losses in parallel, summed in view order.
    let lambda = guide.settings.lambda;
    let renders: Vec<&[[f32; 3]]> = batch.iter().map(|bv| bv.color.as_slice()).collect();
    let loss = |(render, target): (&&[[f32; 3]], &Target)| image_loss(render, target, lambda);
    let pixels: usize = renders.iter().map(|r| 3 * r.len()).sum();
    let losses: Vec<(f64, Vec<[f32; 3]>)> = if worth_parallel(pixels) {
        renders
            .par_iter()
            .zip(targets.par_iter())
            .map(loss)
            .collect()
    } else {
        renders.iter().zip(&targets).map(loss).collect()
    };
    let mut grads = Vec::with_capacity(views.len());
    for (l, g) in losses {
        report.loss += l / views.len() as f64;
        grads.push(g);
    }
    let ta = Instant::now();
    let timings = t.apply(&batch, &grads, trainable)?;
    report.apply_seconds = ta.elapsed().as_secs_f64();
    report.kernels.entries.extend(timings.entries);
    t.recycle(batch);
    report.seconds = t0.elapsed().as_secs_f64();
    Ok(report)
}

/// An image target, row-major like its render.
type Target = Vec<[f32; 3]>;

/// Renders `views` with `t` (their GPU times added to `kernels`) and asks `prior` for all their
/// targets at `step` in one call (its wall time added to `prior_seconds`): the setup that the
/// guided iteration and the pseudo-ground-truth pass share.
fn render_and_ask(
    t: &mut Trainer,
    prior: &mut dyn Prior,
    guide: &mut Guide,
    views: &[GuidedView],
    step: u32,
    kernels: &mut Timings,
    prior_seconds: &mut f64,
) -> Result<(Vec<BatchView>, Vec<Target>), GenError> {
    let mut batch = Vec::with_capacity(views.len());
    for v in views {
        let bv = t.render_view(&v.camera, v.background)?;
        kernels.entries.extend_from_slice(&bv.frame.timings.entries);
        batch.push(bv);
    }
    let asked: Vec<PriorView> = views
        .iter()
        .zip(&batch)
        .map(|(v, bv)| PriorView {
            camera: &v.camera,
            render: &bv.color,
            background: v.background,
            azimuth: v.azimuth,
            elevation: v.elevation,
        })
        .collect();
    let tp = Instant::now();
    let targets = prior.targets(guide, &asked, step)?;
    *prior_seconds += tp.elapsed().as_secs_f64();
    drop(asked);
    if targets.len() != views.len() {
        return Err(GenError::Prior(Error::Run(format!(
            "the prior returned {} targets for {} views",
            targets.len(),
            views.len()
        ))));
    }
    Ok((batch, targets))
}

/// The loss `mean ½ (x − x̃)² / λ` over pixels and channels and its gradient: the guidance's
/// λ-scaled step toward the target, normalised back so that the loss reads like a mean squared
/// error against what the prior believes the view shows.
pub fn image_loss(render: &[[f32; 3]], target: &[[f32; 3]], lambda: f64) -> (f64, Vec<[f32; 3]>) {
    let n = (render.len() * 3).max(1) as f64;
    let k = (1.0 / lambda.max(1e-6)) / n;
    let mut loss = 0.0;
    let g = render
        .iter()
        .zip(target)
        .map(|(x, t)| {
            std::array::from_fn(|c| {
                let d = (x[c] - t[c]) as f64;
                loss += 0.5 * d * d * k;
                (d * k) as f32
            })
        })
        .collect();
    (loss, g)
}

/// The pseudo-ground-truth pass of every reconstructive stage: `cloud` rendered once from each
/// view (over its background) and turned into the prior's target at step 0 under `guide`
/// (the pseudo-GT rule), `batch` views per prior call.
pub fn pseudo_ground_truth(
    ctx: &Context,
    cloud: &Gaussians,
    prior: &mut dyn Prior,
    guide: &mut Guide,
    views: &[GuidedView],
    batch: usize,
) -> Result<Vec<View>, GenError> {
    // A trainer only to render with (its learning rates are never used).
    let mut maker = Trainer::guided(ctx, cloud, FitConfig::default(), 1.0)?;
    let mut out = Vec::with_capacity(views.len());
    let (mut kernels, mut seconds) = (Timings::default(), 0.0);
    for chunk in views.chunks(batch.max(1)) {
        let (rendered, targets) = render_and_ask(
            &mut maker,
            prior,
            guide,
            chunk,
            0,
            &mut kernels,
            &mut seconds,
        )?;
        for (v, pixels) in chunk.iter().zip(targets) {
            out.push(View {
                camera: v.camera.clone(),
                pixels,
            });
        }
        maker.recycle(rendered);
    }
    Ok(out)
}

/// Runs a reconstructive fit (a trainer made with fixed views) to `steps`, calling `observe`
/// after every step with whether a checkpoint is due (every `checkpoint_every` steps, 0: never).
pub fn run_fit(
    t: &mut Trainer,
    steps: u32,
    checkpoint_every: u32,
    observe: &mut dyn FnMut(&Trainer, &StepReport, bool) -> Result<(), GenError>,
) -> Result<Option<StepReport>, GenError> {
    let mut last = None;
    while t.iteration() < steps {
        let r = t.step()?;
        let it = t.iteration();
        let due = checkpoint_every > 0 && it.is_multiple_of(checkpoint_every) && it < steps;
        observe(t, &r, due)?;
        last = Some(r);
    }
    Ok(last)
}
