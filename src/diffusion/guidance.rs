//! Guidance rules: functions from noise predictions to a latent-space gradient (or target),
//! written against [`NoisePredictor`], which runs the positive, negative and null prompts (and the
//! edit prompt) as one batch per timestep.
//!
//! - MTS as the paper states it: T_end decreasing linearly over the run, [1, T_end] cut into m
//!   intervals with one random t in each, DDIM inversion with the null prompt between them, and
//!   Σ w(tᵢ)(ε(y) − ε(∅)).
//! - MTS as the authors' code runs it: random jumps from t = 1 while below T_end (at most 4),
//!   CFG 7.5 with the view-dependent negative prompt as "unconditional", λ = 0.1, averaged.
//! - Pseudo-ground truth of reconstructive generation: x̂₀ at the first sampled t with the CFG ε.
//! - Editing: ε(y_edit) − ε(y) along the same inversion chain.
//! - Ablations: SDS, DreamTime's decreasing t, LucidDreamer's ISM.
use super::schedule::{add_noise, cfg, ddim_step, predict_x0, weight, Schedule};
use rand::Rng;
use rayon::prelude::*;

/// Which prompt embedding a prediction uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cond {
    /// The (view-dependent) prompt y.
    Positive,
    /// The (view-dependent) negative prompt.
    Negative,
    /// The empty prompt ∅.
    Null,
    /// The edit prompt y_edit.
    Edit,
}

/// Predicts ε for latent `x` at DDPM timestep `t` under each condition, in one batched run.
pub trait NoisePredictor {
    fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String>;
}

/// Predicts ε for all views of an iteration at one DDPM timestep, in one batched run: view
/// `v`'s latent `xs[v]` under each of `conds` (with view `v`'s own prompts). Returns
/// `[view][cond]`. The views of an iteration share their timesteps (as the authors' code
/// does), so every point of the guidance chain is one run over views × conditions.
pub trait ViewsPredictor {
    fn predict_views(
        &mut self,
        xs: &[&[f32]],
        t: u32,
        conds: &[Cond],
    ) -> Result<Vec<Vec<Vec<f32>>>, String>;
}

/// A [`NoisePredictor`] asked view by view (for predictors whose answer depends on the latent
/// alone, and for one view).
pub struct EachView<'a>(pub &'a mut dyn NoisePredictor);

impl ViewsPredictor for EachView<'_> {
    fn predict_views(
        &mut self,
        xs: &[&[f32]],
        t: u32,
        conds: &[Cond],
    ) -> Result<Vec<Vec<Vec<f32>>>, String> {
        xs.iter().map(|x| self.0.predict(x, t, conds)).collect()
    }
}

/// One [`NoisePredictor`] per view, each asked about its own view (the oracle's references
/// differ from view to view).
pub struct PerView<P>(pub Vec<P>);

/// The views are independent, so they are asked in parallel (the oracle's host maths at image
/// size is most of its iteration on a GPU).
impl<P: NoisePredictor + Send> ViewsPredictor for PerView<P> {
    fn predict_views(
        &mut self,
        xs: &[&[f32]],
        t: u32,
        conds: &[Cond],
    ) -> Result<Vec<Vec<Vec<f32>>>, String> {
        if xs.len() != self.0.len() {
            return Err(format!("{} latents for {} views", xs.len(), self.0.len()));
        }
        xs.par_iter()
            .zip(self.0.par_iter_mut())
            .map(|(x, p)| p.predict(x, t, conds))
            .collect()
    }
}

/// Timestep ranges of one phase (the authors' configs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MtsRange {
    /// T_end goes from `stage.1` down to `stage.0` over `period` steps.
    pub stage: (u32, u32),
    /// Random jump length range, high exclusive.
    pub jump: (u32, u32),
    pub period: u32,
}

pub const OBJECT_MTS: MtsRange = MtsRange {
    stage: (400, 850),
    jump: (175, 225),
    period: 1500,
};
pub const OBJECT_RECON: MtsRange = MtsRange {
    stage: (140, 200),
    jump: (75, 150),
    period: 1,
};
pub const SCENE_ENVIRONMENT: MtsRange = MtsRange {
    stage: (400, 850),
    jump: (175, 225),
    period: 1000,
};
pub const SCENE_FLOOR: MtsRange = MtsRange {
    stage: (350, 750),
    jump: (150, 200),
    period: 700,
};
/// The scene's reconstructive phase uses the object's ranges.
pub const SCENE_RECON: MtsRange = OBJECT_RECON;

/// Most timesteps the code's schedule samples.
pub const MAX_POINTS: usize = 4;

/// T_end at `step`: linear from stage.1 down to stage.0.
pub fn t_end(r: &MtsRange, step: u32) -> u32 {
    let f = (step as f64 / r.period.max(1) as f64).min(1.0);
    r.stage.1 - ((r.stage.1 - r.stage.0) as f64 * f) as u32
}

/// The code's schedule: cumulative random jumps while below T_end (the first always kept),
/// ascending timestep indices.
pub fn code_schedule(r: &MtsRange, step: u32, rng: &mut impl Rng) -> Vec<u32> {
    let end = t_end(r, step);
    let mut ts: Vec<u32> = vec![];
    for _ in 0..MAX_POINTS {
        let j = rng.gen_range(r.jump.0..r.jump.1);
        match ts.last() {
            None => ts.push(j),
            Some(&last) if last + j < end => ts.push(last + j),
            _ => break,
        }
    }
    ts
}

/// The paper's schedule: [1, T_end] cut into `m` equal intervals, one uniform t in each.
pub fn paper_schedule(r: &MtsRange, step: u32, m: u32, rng: &mut impl Rng) -> Vec<u32> {
    let end = t_end(r, step).max(m + 1);
    let m = m.max(1);
    (0..m)
        .map(|i| {
            let lo = 1 + (end - 1) * i / m;
            let hi = (1 + (end - 1) * (i + 1) / m).max(lo + 1);
            rng.gen_range(lo..hi)
        })
        .collect()
}

/// Which form of the MTS gradient.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MtsRule {
    /// Σ w(tᵢ)(ε(y) − ε(∅)), scaled by λ.
    Paper,
    /// (1/n) Σ λ w(tᵢ)(ε_cfg − ε(∅)) with ε_cfg = ε(neg) + s (ε(y) − ε(neg)).
    Code,
}

/// Settings of the MTS gradient.
#[derive(Debug, Clone, Copy)]
pub struct MtsSettings {
    pub rule: MtsRule,
    pub guidance_scale: f64,
    pub lambda: f64,
    /// The timestep the chain starts from (the code noises the latent to t = 1 first).
    pub t_start: u32,
}

impl Default for MtsSettings {
    fn default() -> Self {
        MtsSettings {
            rule: MtsRule::Code,
            guidance_scale: 7.5,
            lambda: 0.1,
            t_start: 1,
        }
    }
}

/// `scale (a − b)`, with non-finite results zeroed so one bad prediction cannot poison a latent.
fn scaled_diff(a: &[f32], b: &[f32], scale: f64) -> Vec<f32> {
    a.iter()
        .zip(b)
        .map(|(a, b)| {
            let v = (scale * (*a as f64 - *b as f64)) as f32;
            if v.is_finite() {
                v
            } else {
                0.0
            }
        })
        .collect()
}

fn add_into(g: &mut [f32], term: &[f32]) {
    for (gi, ti) in g.iter_mut().zip(term) {
        *gi += ti;
    }
}

/// ε predictions of every view for `conds` at (xs[v], t), converted from v-prediction where the
/// model uses it, and checked for count and size: `[view][cond]`.
fn predict_eps(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    xs: &[Vec<f32>],
    t: u32,
    conds: &[Cond],
) -> Result<Vec<Vec<Vec<f32>>>, String> {
    let ab = sched.alpha_bar(t as i64);
    let refs: Vec<&[f32]> = xs.iter().map(Vec::as_slice).collect();
    let out = pred.predict_views(&refs, t, conds)?;
    let bad = out.len() != xs.len()
        || out
            .iter()
            .zip(xs)
            .any(|(p, x)| p.len() != conds.len() || p.iter().any(|e| e.len() != x.len()));
    if bad {
        return Err(format!(
            "noise predictor returned {} views of outputs for {} views × {} conditions, or of the \
             wrong size",
            out.len(),
            xs.len(),
            conds.len()
        ));
    }
    Ok(out
        .into_iter()
        .zip(xs)
        .map(|(p, x)| p.into_iter().map(|e| sched.into_eps(e, x, ab)).collect())
        .collect())
}

/// One point of the inversion chain: the timestep, every view's latent there, and their
/// predictions (`[view][cond]`).
struct ChainPoint {
    t: u32,
    x: Vec<Vec<f32>>,
    preds: Vec<Vec<Vec<f32>>>,
    /// Where the null prediction is in each view's predictions (the next inversion step's).
    null: Option<usize>,
}

/// Noises every `z0s[v]` (with `eps[v]`) to `t_start`, then walks up through `ts` (ascending) by
/// DDIM inversion with the null prompt, predicting `conds` for all views at every sampled point
/// in one batch. The `t_start` point only drives the first inversion step, so it predicts the
/// null prompt alone; `conds` must include Null when a sampled point drives a further step.
fn chain(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    t_start: u32,
    ts: &[u32],
    conds: &[Cond],
) -> Result<Vec<ChainPoint>, String> {
    const START: [Cond; 1] = [Cond::Null];
    let times: Vec<u32> = std::iter::once(t_start).chain(ts.iter().copied()).collect();
    let ab0 = sched.alpha_bar(t_start as i64);
    let mut x: Vec<Vec<f32>> = z0s
        .par_iter()
        .zip(eps)
        .map(|(z, e)| add_noise(z, e, ab0))
        .collect();
    let mut out: Vec<ChainPoint> = vec![];
    for (k, &t) in times.iter().enumerate() {
        if let Some(prev) = k.checked_sub(1).map(|i| &out[i]) {
            let null = prev
                .null
                .ok_or("the inversion chain needs the null prompt")?;
            let (from, to) = (sched.alpha_bar(prev.t as i64), sched.alpha_bar(t as i64));
            x = prev
                .x
                .par_iter()
                .zip(&prev.preds)
                .map(|(xv, pv)| ddim_step(xv, &pv[null], from, to))
                .collect();
        }
        let here: &[Cond] = if k == 0 { &START } else { conds };
        let preds = predict_eps(pred, sched, &x, t, here)?;
        out.push(ChainPoint {
            t,
            x: x.clone(),
            preds,
            null: here.iter().position(|c| *c == Cond::Null),
        });
    }
    Ok(out)
}

/// Σ term(view's predictions at a point, w(t)) over the sampled points of a chain (the t_start
/// point only drives the first inversion step), per view.
fn sum_over_chain(
    points: &[ChainPoint],
    sched: &Schedule,
    term: impl Fn(&[Vec<f32>], f64) -> Vec<f32> + Sync,
) -> Vec<Vec<f32>> {
    (0..points[0].x.len())
        .into_par_iter()
        .map(|v| {
            let mut g = vec![0.0f32; points[0].x[v].len()];
            for p in &points[1..] {
                add_into(
                    &mut g,
                    &term(&p.preds[v], weight(sched.alpha_bar(p.t as i64))),
                );
            }
            g
        })
        .collect()
}

/// The MTS gradients on the latents `z0s` (noise `eps`, one per view) for the timesteps `ts`
/// (ascending) the views share: one batched prediction per chain point for all views.
pub fn mts_gradients(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    ts: &[u32],
    s: &MtsSettings,
) -> Result<Vec<Vec<f32>>, String> {
    // The paper's rule needs no negative prompt: a third fewer UNet items per point.
    let conds: &[Cond] = match s.rule {
        MtsRule::Paper => &[Cond::Positive, Cond::Null],
        MtsRule::Code => &[Cond::Positive, Cond::Negative, Cond::Null],
    };
    let points = chain(pred, sched, z0s, eps, s.t_start, ts, conds)?;
    let n = ts.len().max(1) as f64;
    Ok(sum_over_chain(&points, sched, |p, w| match s.rule {
        MtsRule::Paper => scaled_diff(&p[0], &p[1], s.lambda * w),
        MtsRule::Code => scaled_diff(
            &cfg(&p[1], &p[0], s.guidance_scale),
            &p[2],
            s.lambda * w / n,
        ),
    }))
}

/// The MTS gradient on one latent `z0` ([`mts_gradients`] of one view).
pub fn mts_gradient(
    pred: &mut dyn NoisePredictor,
    sched: &Schedule,
    z0: &[f32],
    eps: &[f32],
    ts: &[u32],
    s: &MtsSettings,
) -> Result<Vec<f32>, String> {
    one_view(pred, z0, eps, |p, z, e| {
        mts_gradients(p, sched, z, e, ts, s)
    })
}

/// A batched rule run on one view: `rule` is given the predictor asked view by view, and the
/// latent and its noise as batches of one.
fn one_view(
    pred: &mut dyn NoisePredictor,
    z0: &[f32],
    eps: &[f32],
    rule: impl FnOnce(&mut dyn ViewsPredictor, &[&[f32]], &[&[f32]]) -> Result<Vec<Vec<f32>>, String>,
) -> Result<Vec<f32>, String> {
    rule(&mut EachView(pred), &[z0], &[eps])?
        .pop()
        .ok_or_else(|| "no view".to_string())
}

/// The pseudo-ground-truth latents of reconstructive generation: along the same chain, x̂₀ at
/// the first sampled timestep with the CFG noise, per view.
pub fn pseudo_gts(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    ts: &[u32],
    s: &MtsSettings,
) -> Result<Vec<Vec<f32>>, String> {
    let first = *ts.first().ok_or("no timestep sampled")?;
    // The one sampled point drives no further inversion step: no null prompt there.
    let conds = [Cond::Positive, Cond::Negative];
    let points = chain(pred, sched, z0s, eps, s.t_start, &[first], &conds)?;
    let p = &points[1];
    let ab = sched.alpha_bar(first as i64);
    Ok(p.x
        .iter()
        .zip(&p.preds)
        .map(|(x, pv)| predict_x0(x, &cfg(&pv[1], &pv[0], s.guidance_scale), ab))
        .collect())
}

/// The pseudo-ground-truth latent of one view ([`pseudo_gts`]).
pub fn pseudo_gt(
    pred: &mut dyn NoisePredictor,
    sched: &Schedule,
    z0: &[f32],
    eps: &[f32],
    ts: &[u32],
    s: &MtsSettings,
) -> Result<Vec<f32>, String> {
    one_view(pred, z0, eps, |p, z, e| pseudo_gts(p, sched, z, e, ts, s))
}

/// The appearance-editing gradients: Σ λ w(tᵢ)(ε(y_edit) − ε(y)) / n along the inversion
/// chain, per view.
pub fn edit_gradients(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    ts: &[u32],
    s: &MtsSettings,
) -> Result<Vec<Vec<f32>>, String> {
    let conds = [Cond::Edit, Cond::Positive, Cond::Null];
    let points = chain(pred, sched, z0s, eps, s.t_start, ts, &conds)?;
    let n = ts.len().max(1) as f64;
    Ok(sum_over_chain(&points, sched, |p, w| {
        scaled_diff(&p[0], &p[1], s.lambda * w / n)
    }))
}

/// The appearance-editing gradient of one view ([`edit_gradients`]).
pub fn edit_gradient(
    pred: &mut dyn NoisePredictor,
    sched: &Schedule,
    z0: &[f32],
    eps: &[f32],
    ts: &[u32],
    s: &MtsSettings,
) -> Result<Vec<f32>, String> {
    one_view(pred, z0, eps, |p, z, e| {
        edit_gradients(p, sched, z, e, ts, s)
    })
}

/// Score distillation sampling: λ w(t)(ε_cfg(x_t) − ε) with x_t = noised z0, per view.
pub fn sds_gradients(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    t: u32,
    s: &MtsSettings,
) -> Result<Vec<Vec<f32>>, String> {
    let ab = sched.alpha_bar(t as i64);
    let x: Vec<Vec<f32>> = z0s
        .iter()
        .zip(eps)
        .map(|(z, e)| add_noise(z, e, ab))
        .collect();
    let p = predict_eps(pred, sched, &x, t, &[Cond::Positive, Cond::Negative])?;
    Ok(p.iter()
        .zip(eps)
        .map(|(pv, e)| {
            scaled_diff(
                &cfg(&pv[1], &pv[0], s.guidance_scale),
                e,
                s.lambda * weight(ab),
            )
        })
        .collect())
}

/// Score distillation sampling on one view ([`sds_gradients`]).
pub fn sds_gradient(
    pred: &mut dyn NoisePredictor,
    sched: &Schedule,
    z0: &[f32],
    eps: &[f32],
    t: u32,
    s: &MtsSettings,
) -> Result<Vec<f32>, String> {
    one_view(pred, z0, eps, |p, z, e| sds_gradients(p, sched, z, e, t, s))
}

/// DreamTime's time-prioritised schedule: t decreases monotonically from `t_max` to `t_min`
/// over the run (uniform prior weights).
pub fn dreamtime_t(step: u32, steps: u32, t_min: u32, t_max: u32) -> u32 {
    let f = (step as f64 / steps.max(1) as f64).min(1.0);
    (t_max as f64 - (t_max - t_min) as f64 * f).round() as u32
}

/// LucidDreamer's interval score matching, per view: x_s by DDIM inversion (null prompt) from
/// t_start in steps of `xs_delta` (at most `xs_steps`), one inversion step s → t whose ε is the
/// target, and λ w(t)(ε_cfg(x_t) − ε_∅(x_s, s)).
#[allow(
    clippy::too_many_arguments,
    reason = "the rule's own parameters, as LucidDreamer names them"
)]
pub fn ism_gradients(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    s_t: u32,
    t: u32,
    xs_delta: u32,
    xs_steps: u32,
    set: &MtsSettings,
) -> Result<Vec<Vec<f32>>, String> {
    let mut cur = set.t_start;
    let ab0 = sched.alpha_bar(cur as i64);
    let mut x: Vec<Vec<f32>> = z0s
        .par_iter()
        .zip(eps)
        .map(|(z, e)| add_noise(z, e, ab0))
        .collect();
    for _ in 0..xs_steps {
        if cur >= s_t {
            break;
        }
        let nxt = (cur + xs_delta).min(s_t);
        let e = predict_eps(pred, sched, &x, cur, &[Cond::Null])?;
        let (from, to) = (sched.alpha_bar(cur as i64), sched.alpha_bar(nxt as i64));
        x = x
            .iter()
            .zip(&e)
            .map(|(xv, ev)| ddim_step(xv, &ev[0], from, to))
            .collect();
        cur = nxt;
    }
    let e_s = predict_eps(pred, sched, &x, cur, &[Cond::Null])?;
    let (from, to) = (sched.alpha_bar(cur as i64), sched.alpha_bar(t as i64));
    let x_t: Vec<Vec<f32>> = x
        .iter()
        .zip(&e_s)
        .map(|(xv, ev)| ddim_step(xv, &ev[0], from, to))
        .collect();
    let p = predict_eps(pred, sched, &x_t, t, &[Cond::Positive, Cond::Negative])?;
    let w = weight(sched.alpha_bar(t as i64));
    Ok(p.iter()
        .zip(&e_s)
        .map(|(pv, es)| {
            scaled_diff(
                &cfg(&pv[1], &pv[0], set.guidance_scale),
                &es[0],
                set.lambda * w,
            )
        })
        .collect())
}

/// Interval score matching on one view ([`ism_gradients`]).
#[allow(
    clippy::too_many_arguments,
    reason = "the rule's own parameters, as LucidDreamer names them"
)]
pub fn ism_gradient(
    pred: &mut dyn NoisePredictor,
    sched: &Schedule,
    z0: &[f32],
    eps: &[f32],
    s_t: u32,
    t: u32,
    xs_delta: u32,
    xs_steps: u32,
    set: &MtsSettings,
) -> Result<Vec<f32>, String> {
    one_view(pred, z0, eps, |p, z, e| {
        ism_gradients(p, sched, z, e, s_t, t, xs_delta, xs_steps, set)
    })
}

/// View-dependent prompts as the authors' object code builds them.
pub fn view_prompts(
    text: &str,
    negative: &str,
    azimuth_deg: f64,
    elevation_deg: f64,
) -> (String, String) {
    const STYLE: &str =
        "4k, 8k, best quality, ultra-detailed, finely detail, highres, high resolution";
    let a = azimuth_deg.abs();
    let (d, others) = if elevation_deg < -60.0 {
        ("overhead", "front view, back view, side view")
    } else if elevation_deg >= 60.0 {
        ("bottom", "front view, back view, side view, overhead view")
    } else if a < 37.5 {
        ("front", "side view, back view, overhead view")
    } else if a < 142.5 {
        ("side", "front view, back view, overhead view")
    } else {
        ("back", "front view, side view, overhead view")
    };
    (
        format!("{text}, {d} view, {STYLE}"),
        format!("{negative}, {others}"),
    )
}

#[cfg(test)]
#[path = "guidance_tests.rs"]
mod tests;
