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

impl<P: NoisePredictor> ViewsPredictor for PerView<P> {
    fn predict_views(
        &mut self,
        xs: &[&[f32]],
        t: u32,
        conds: &[Cond],
    ) -> Result<Vec<Vec<Vec<f32>>>, String> {
        if xs.len() != self.0.len() {
            return Err(format!("{} latents for {} views", xs.len(), self.0.len()));
        }
        xs.iter()
            .zip(&mut self.0)
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
        .map(|(p, x)| p.into_iter().map(|e| sched.to_eps(&e, x, ab)).collect())
        .collect())
}

/// One point of the inversion chain: the timestep, every view's latent there, and their
/// predictions (`[view][cond]`).
struct ChainPoint {
    t: u32,
    x: Vec<Vec<f32>>,
    preds: Vec<Vec<Vec<f32>>>,
}

/// Noises every `z0s[v]` (with `eps[v]`) to `t_start`, then walks up through `ts` (ascending) by
/// DDIM inversion with the null prompt, predicting `conds` (which must include Null) for all
/// views at every point in one batch.
fn chain(
    pred: &mut dyn ViewsPredictor,
    sched: &Schedule,
    z0s: &[&[f32]],
    eps: &[&[f32]],
    t_start: u32,
    ts: &[u32],
    conds: &[Cond],
) -> Result<Vec<ChainPoint>, String> {
    let null = conds
        .iter()
        .position(|c| *c == Cond::Null)
        .ok_or("the inversion chain needs the null prompt")?;
    let times: Vec<u32> = std::iter::once(t_start).chain(ts.iter().copied()).collect();
    let ab0 = sched.alpha_bar(t_start as i64);
    let mut x: Vec<Vec<f32>> = z0s
        .iter()
        .zip(eps)
        .map(|(z, e)| add_noise(z, e, ab0))
        .collect();
    let mut out: Vec<ChainPoint> = vec![];
    for (k, &t) in times.iter().enumerate() {
        if let Some(prev) = k.checked_sub(1).map(|i| &out[i]) {
            let (from, to) = (sched.alpha_bar(prev.t as i64), sched.alpha_bar(t as i64));
            x = prev
                .x
                .iter()
                .zip(&prev.preds)
                .map(|(xv, pv)| ddim_step(xv, &pv[null], from, to))
                .collect();
        }
        let preds = predict_eps(pred, sched, &x, t, conds)?;
        out.push(ChainPoint {
            t,
            x: x.clone(),
            preds,
        });
    }
    Ok(out)
}

/// Σ term(view's predictions at a point, w(t)) over the sampled points of a chain (the t_start
/// point only drives the first inversion step), per view.
fn sum_over_chain(
    points: &[ChainPoint],
    sched: &Schedule,
    term: impl Fn(&[Vec<f32>], f64) -> Vec<f32>,
) -> Vec<Vec<f32>> {
    (0..points[0].x.len())
        .map(|v| {
            let mut g = vec![0.0f32; points[0].x[v].len()];
            for p in &points[1..] {
                add_into(&mut g, &term(&p.preds[v], weight(sched.alpha_bar(p.t as i64))));
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
    let conds = [Cond::Positive, Cond::Negative, Cond::Null];
    let points = chain(pred, sched, z0s, eps, s.t_start, ts, &conds)?;
    let n = ts.len().max(1) as f64;
    Ok(sum_over_chain(&points, sched, |p, w| {
        let (pos, neg, null) = (&p[0], &p[1], &p[2]);
        match s.rule {
            MtsRule::Paper => scaled_diff(pos, null, s.lambda * w),
            MtsRule::Code => scaled_diff(&cfg(neg, pos, s.guidance_scale), null, s.lambda * w / n),
        }
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
    one(mts_gradients(&mut EachView(pred), sched, &[z0], &[eps], ts, s))
}

fn one(r: Result<Vec<Vec<f32>>, String>) -> Result<Vec<f32>, String> {
    r?.pop().ok_or_else(|| "no view".to_string())
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
    let conds = [Cond::Positive, Cond::Negative, Cond::Null];
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
    one(pseudo_gts(&mut EachView(pred), sched, &[z0], &[eps], ts, s))
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
    one(edit_gradients(&mut EachView(pred), sched, &[z0], &[eps], ts, s))
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
    one(sds_gradients(&mut EachView(pred), sched, &[z0], &[eps], t, s))
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
#[allow(clippy::too_many_arguments)]
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
        .iter()
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
#[allow(clippy::too_many_arguments)]
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
    one(ism_gradients(
        &mut EachView(pred),
        sched,
        &[z0],
        &[eps],
        s_t,
        t,
        xs_delta,
        xs_steps,
        set,
    ))
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
mod tests {
    use super::super::schedule::{Schedule, SchedulerConfig};
    use super::*;
    use rand::SeedableRng;

    /// ε = k(cond) x + t / 1000: simple enough to compute the chain by hand. Counts calls.
    struct Fake {
        calls: Vec<(u32, usize)>,
    }
    fn k(c: Cond) -> f32 {
        match c {
            Cond::Positive => 0.5,
            Cond::Negative => 0.2,
            Cond::Null => 0.1,
            Cond::Edit => 0.9,
        }
    }
    impl NoisePredictor for Fake {
        fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
            self.calls.push((t, conds.len()));
            Ok(conds
                .iter()
                .map(|c| x.iter().map(|v| k(*c) * v + t as f32 / 1000.0).collect())
                .collect())
        }
    }

    #[test]
    fn schedules_follow_their_rules() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        assert_eq!(t_end(&OBJECT_MTS, 0), 850);
        assert_eq!(t_end(&OBJECT_MTS, 750), 625);
        assert_eq!(t_end(&OBJECT_MTS, 5000), 400);
        for step in [0u32, 300, 900, 1500] {
            for _ in 0..50 {
                let ts = code_schedule(&OBJECT_MTS, step, &mut rng);
                assert!(!ts.is_empty() && ts.len() <= MAX_POINTS);
                assert!((175..225).contains(&ts[0]));
                for w in ts.windows(2) {
                    assert!((175..225).contains(&(w[1] - w[0])));
                    assert!(w[1] < t_end(&OBJECT_MTS, step));
                }
                let p = paper_schedule(&OBJECT_MTS, step, 4, &mut rng);
                let end = t_end(&OBJECT_MTS, step);
                assert_eq!(p.len(), 4);
                for (i, t) in p.iter().enumerate() {
                    let lo = 1 + (end - 1) * i as u32 / 4;
                    let hi = 1 + (end - 1) * (i as u32 + 1) / 4;
                    assert!(*t >= lo && *t < hi.max(lo + 1), "{t} not in [{lo}, {hi})");
                }
            }
        }
        assert_eq!(dreamtime_t(0, 100, 20, 980), 980);
        assert_eq!(dreamtime_t(100, 100, 20, 980), 20);
    }

    #[test]
    fn mts_gradient_matches_the_chain_computed_by_hand() {
        let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        let z0: Vec<f32> = (0..16).map(|i| (i as f32 * 0.3).sin()).collect();
        let eps: Vec<f32> = (0..16).map(|i| (i as f32 * 0.7).cos()).collect();
        let ts = [200u32, 410, 600];
        let s = MtsSettings::default();
        let mut fake = Fake { calls: vec![] };
        let g = mts_gradient(&mut fake, &sched, &z0, &eps, &ts, &s).unwrap();
        // One batched call per chain point (t = 1 and the three sampled), three conditions each.
        assert_eq!(fake.calls, vec![(1, 3), (200, 3), (410, 3), (600, 3)]);
        // By hand, in f64.
        let ab = |t: u32| sched.alpha_bar(t as i64);
        let mut x: Vec<f64> = z0
            .iter()
            .zip(&eps)
            .map(|(a, b)| ab(1).sqrt() * *a as f64 + (1.0 - ab(1)).sqrt() * *b as f64)
            .collect();
        let mut want = vec![0.0f64; 16];
        let mut cur = 1u32;
        for &t in &ts {
            // invert with the null prediction
            for xi in x.iter_mut() {
                let e = 0.1 * *xi + cur as f64 / 1000.0;
                let x0 = (*xi - (1.0 - ab(cur)).sqrt() * e) / ab(cur).sqrt();
                *xi = ab(t).sqrt() * x0 + (1.0 - ab(t)).sqrt() * e;
            }
            cur = t;
            for (k, xi) in x.iter().enumerate() {
                let c = t as f64 / 1000.0;
                let (pos, neg, null) = (0.5 * xi + c, 0.2 * xi + c, 0.1 * xi + c);
                let e_cfg = neg + 7.5 * (pos - neg);
                want[k] += 0.1 * weight(ab(t)) * (e_cfg - null) / 3.0;
            }
        }
        for (a, b) in g.iter().zip(&want) {
            assert!(
                (*a as f64 - b).abs() < 1e-4 * b.abs().max(1.0),
                "{a} vs {b}"
            );
        }
        // The paper's rule differs: no CFG, no averaging.
        let sp = MtsSettings {
            rule: MtsRule::Paper,
            ..s
        };
        let gp = mts_gradient(&mut Fake { calls: vec![] }, &sched, &z0, &eps, &ts, &sp).unwrap();
        assert!(gp.iter().zip(&g).any(|(a, b)| (a - b).abs() > 1e-3));
    }

    /// Predicts the true noise for every condition: the inversion chain then stays on
    /// add_noise(z0, eps, t), x̂₀ is z0 exactly and every guidance difference vanishes.
    struct Oracle(Vec<f32>);
    impl NoisePredictor for Oracle {
        fn predict(&mut self, _: &[f32], _: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
            Ok(conds.iter().map(|_| self.0.clone()).collect())
        }
    }

    #[test]
    fn a_perfect_predictor_recovers_the_latent() {
        let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        let z0: Vec<f32> = (0..32).map(|i| (i as f32 * 0.21).sin()).collect();
        let eps: Vec<f32> = (0..32).map(|i| (i as f32 * 0.9).cos()).collect();
        let s = MtsSettings::default();
        let gt = pseudo_gt(&mut Oracle(eps.clone()), &sched, &z0, &eps, &[130, 300], &s).unwrap();
        for (a, b) in gt.iter().zip(&z0) {
            assert!((a - b).abs() < 1e-4, "{a} vs {b}");
        }
        let g = mts_gradient(&mut Oracle(eps.clone()), &sched, &z0, &eps, &[200, 400], &s).unwrap();
        assert!(g.iter().all(|v| v.abs() < 1e-6));
        let sds = sds_gradient(&mut Oracle(eps.clone()), &sched, &z0, &eps, 500, &s).unwrap();
        assert!(sds.iter().all(|v| v.abs() < 1e-5));
        // A predictor returning the wrong number of outputs is an error, not a panic.
        struct Short;
        impl NoisePredictor for Short {
            fn predict(&mut self, x: &[f32], _: u32, _: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
                Ok(vec![x.to_vec()])
            }
        }
        assert!(mts_gradient(&mut Short, &sched, &z0, &eps, &[200], &s).is_err());
    }

    #[test]
    fn pseudo_gt_edit_sds_and_ism_run_and_differ() {
        let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        let z0 = vec![0.3f32; 8];
        let eps = vec![-0.4f32; 8];
        let s = MtsSettings::default();
        let gt = pseudo_gt(
            &mut Fake { calls: vec![] },
            &sched,
            &z0,
            &eps,
            &[120, 260],
            &s,
        )
        .unwrap();
        assert!(gt.iter().all(|v| v.is_finite()));
        let e = edit_gradient(&mut Fake { calls: vec![] }, &sched, &z0, &eps, &[300], &s).unwrap();
        assert!(e.iter().all(|v| *v > 0.0), "edit prompt pulls away from y");
        let sds = sds_gradient(&mut Fake { calls: vec![] }, &sched, &z0, &eps, 500, &s).unwrap();
        let mut f = Fake { calls: vec![] };
        let ism = ism_gradient(&mut f, &sched, &z0, &eps, 400, 480, 200, 5, &s).unwrap();
        assert_eq!(
            f.calls.iter().map(|c| c.0).collect::<Vec<_>>(),
            vec![1, 201, 400, 480]
        );
        assert!(sds.iter().zip(&ism).any(|(a, b)| (a - b).abs() > 1e-4));
    }

    /// Counts the batched calls over views; predicts as [`Fake`] with a slope per view.
    struct Views(Vec<(u32, usize, usize)>);
    impl ViewsPredictor for Views {
        fn predict_views(
            &mut self,
            xs: &[&[f32]],
            t: u32,
            conds: &[Cond],
        ) -> Result<Vec<Vec<Vec<f32>>>, String> {
            self.0.push((t, xs.len(), conds.len()));
            Ok(xs
                .iter()
                .enumerate()
                .map(|(v, x)| PerViewFake(v).predict(x, t, conds).unwrap())
                .collect())
        }
    }
    struct PerViewFake(usize);
    impl NoisePredictor for PerViewFake {
        fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
            let s = 1.0 + 0.3 * self.0 as f32;
            Ok(conds
                .iter()
                .map(|c| x.iter().map(|v| s * k(*c) * v + t as f32 / 1000.0).collect())
                .collect())
        }
    }

    /// Every rule over a batch of views gives each view what it gives that view alone, with one
    /// predictor call per chain point for all the views.
    #[test]
    fn rules_over_views_equal_the_rules_view_by_view() {
        let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        let z: Vec<Vec<f32>> = (0..3)
            .map(|v| (0..16).map(|i| ((i + 5 * v) as f32 * 0.3).sin()).collect())
            .collect();
        let e: Vec<Vec<f32>> = (0..3)
            .map(|v| (0..16).map(|i| ((i * 3 + v) as f32 * 0.7).cos()).collect())
            .collect();
        let zs: Vec<&[f32]> = z.iter().map(Vec::as_slice).collect();
        let es: Vec<&[f32]> = e.iter().map(Vec::as_slice).collect();
        let s = MtsSettings::default();
        let ts = [190u32, 380, 600];
        type Many<'a> = Box<dyn Fn(&mut Views) -> Vec<Vec<f32>> + 'a>;
        type One<'a> = Box<dyn Fn(&mut PerViewFake, usize) -> Vec<f32> + 'a>;
        let cases: Vec<(&str, Many, One, usize)> = vec![
            (
                "mts",
                Box::new(|p| mts_gradients(p, &sched, &zs, &es, &ts, &s).unwrap()),
                Box::new(|p, v| mts_gradient(p, &sched, zs[v], es[v], &ts, &s).unwrap()),
                4,
            ),
            (
                "pseudo-gt",
                Box::new(|p| pseudo_gts(p, &sched, &zs, &es, &ts, &s).unwrap()),
                Box::new(|p, v| pseudo_gt(p, &sched, zs[v], es[v], &ts, &s).unwrap()),
                2,
            ),
            (
                "edit",
                Box::new(|p| edit_gradients(p, &sched, &zs, &es, &ts, &s).unwrap()),
                Box::new(|p, v| edit_gradient(p, &sched, zs[v], es[v], &ts, &s).unwrap()),
                4,
            ),
            (
                "sds",
                Box::new(|p| sds_gradients(p, &sched, &zs, &es, 500, &s).unwrap()),
                Box::new(|p, v| sds_gradient(p, &sched, zs[v], es[v], 500, &s).unwrap()),
                1,
            ),
            (
                "ism",
                Box::new(|p| ism_gradients(p, &sched, &zs, &es, 400, 480, 200, 5, &s).unwrap()),
                Box::new(|p, v| {
                    ism_gradient(p, &sched, zs[v], es[v], 400, 480, 200, 5, &s).unwrap()
                }),
                4,
            ),
        ];
        for (name, many, one, points) in cases {
            let mut rec = Views(vec![]);
            let all = many(&mut rec);
            assert_eq!(rec.0.len(), points, "{name}: one call per chain point");
            assert!(rec.0.iter().all(|c| c.1 == 3), "{name}: every view in each call");
            for v in 0..3 {
                let alone = one(&mut PerViewFake(v), v);
                assert_eq!(all[v], alone, "{name} view {v}");
            }
            assert_ne!(all[0], all[1], "{name}: the views differ");
        }
    }

    #[test]
    fn view_prompts_as_the_code_builds_them() {
        let (p, n) = view_prompts("a chair", "ugly", 10.0, 0.0);
        assert!(p.starts_with("a chair, front view, 4k"));
        assert_eq!(n, "ugly, side view, back view, overhead view");
        assert!(view_prompts("a chair", "ugly", 90.0, 0.0)
            .0
            .contains("side view"));
        assert!(view_prompts("a chair", "ugly", -170.0, 0.0)
            .0
            .contains("back view"));
        assert!(view_prompts("a chair", "ugly", 0.0, -70.0)
            .0
            .contains("overhead view"));
    }
}
