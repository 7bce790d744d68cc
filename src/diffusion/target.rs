//! From a latent-space guidance gradient to an image the renderer can fit.
//!
//! The authors' PyTorch code back-propagates the latent gradient g through the VAE encoder:
//! ∂L/∂x = J_E(x)ᵀ g, then through the rasteriser. ONNX Runtime has no autograd, so we use the
//! image-space form instead: with z = E(x), decode the guided latent to a target
//! x̃ = D(z − g) (or x̃ = D(x̂₀) for the pseudo-ground truth of reconstructive generation) and let
//! the renderer minimise ½ w ‖x − x̃‖². Its gradient is w (x − D(z − g)). Where the autoencoder
//! reproduces the render (x ≈ D(E(x))), this is w (D(z) − D(z − g)) ≈ w J_D g: the latent
//! gradient pushed through the decoder's Jacobian rather than the encoder's transpose. The two
//! agree up to a positive-definite metric when D is a left inverse of E (J_E J_D = I), and both
//! vanish exactly where g does, so the fixed points of the guidance are kept. The target is
//! recomputed every iteration, as the authors' pseudo-ground-truth views are; a small autoencoder
//! (TAESD, `Codec::Fast`) keeps the per-iteration encode/decode cheap.
use super::convert::{hwc01_to_chw11_into, worth_parallel};
use super::guidance::{
    code_schedule, dreamtime_t, edit_gradients, ism_gradients, mts_gradients, paper_schedule,
    pseudo_gts, sds_gradients, EachView, MtsRange, MtsRule, MtsSettings, NoisePredictor,
    ViewsPredictor,
};
use super::model::{chw11_to_hwc01, Codec, Conditioning, StableDiffusion, UnetViews};
use super::schedule::Schedule;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;
use rayon::prelude::*;

/// LucidDreamer's ISM settings (t in [20, 500), t − s = 80, x_s by 5 inversion steps of 200).
pub const ISM_DEFAULT: Rule = Rule::Ism {
    t_min: 20,
    t_max: 500,
    delta: 80,
    xs_delta: 200,
    xs_steps: 5,
};

/// Which guidance rule a [`Guide`] applies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// MTS (paper or code form per `MtsSettings::rule`; the paper form uses `m` intervals).
    Mts { m: u32 },
    /// Reconstructive generation: the target is D(x̂₀).
    PseudoGt,
    /// Appearance editing: ε(y_edit) − ε(y).
    Edit,
    /// Score distillation at a uniform t in `[t_min, t_max)`.
    Sds { t_min: u32, t_max: u32 },
    /// Score distillation with DreamTime's t, decreasing from `t_max` to `t_min` over `steps`.
    DreamTime { t_min: u32, t_max: u32, steps: u32 },
    /// Interval score matching (LucidDreamer): t uniform in `[t_min, t_max)`, s = t − `delta`,
    /// x_s reached by DDIM inversion in steps of `xs_delta`, at most `xs_steps` of them.
    Ism {
        t_min: u32,
        t_max: u32,
        delta: u32,
        xs_delta: u32,
        xs_steps: u32,
    },
}

/// One view's latent target: the guided latent, the timesteps sampled and the RMS of the
/// latent gradient (0 for pseudo-ground truth).
pub type LatentTarget = (Vec<f32>, Vec<u32>, f64);

/// One iteration's image target.
#[derive(Debug, Clone)]
pub struct ImageTarget {
    /// `h × w × 3` in [0, 1], the renderer's layout.
    pub image: Vec<f32>,
    pub width: usize,
    pub height: usize,
    /// The timesteps sampled.
    pub timesteps: Vec<u32>,
    /// RMS of the latent gradient (0 for pseudo-GT).
    pub latent_rms: f64,
}

/// The per-iteration guidance the object and scene generators call.
pub struct Guide {
    pub rule: Rule,
    pub range: MtsRange,
    pub settings: MtsSettings,
    pub codec: Codec,
    rng: ChaCha8Rng,
}

impl Guide {
    pub fn new(
        rule: Rule,
        range: MtsRange,
        settings: MtsSettings,
        codec: Codec,
        seed: u64,
    ) -> Guide {
        Guide {
            rule,
            range,
            settings,
            codec,
            rng: ChaCha8Rng::seed_from_u64(seed),
        }
    }

    /// Position of the noise generator (for checkpoints).
    pub fn rng_position(&self) -> u128 {
        self.rng.get_word_pos()
    }

    /// Continues the noise generator from a position [`Guide::rng_position`] returned.
    pub fn set_rng_position(&mut self, pos: u128) {
        self.rng.set_word_pos(pos);
    }

    /// The latent target for latent `z` at training step `step` under any noise predictor, with
    /// the timesteps sampled and the gradient's RMS ([`Guide::latent_targets`] of one view).
    pub fn latent_target(
        &mut self,
        p: &mut dyn NoisePredictor,
        sched: &Schedule,
        z: &[f32],
        step: u32,
    ) -> Result<LatentTarget, String> {
        self.latent_targets(&mut EachView(p), sched, &[z], step)?
            .pop()
            .ok_or_else(|| "no view".to_string())
    }

    /// The latent targets of all views of an iteration (latents `zs`) at training step `step`,
    /// each with the timesteps sampled and its gradient's RMS. Every view draws its own noise
    /// (in view order), then the views share one timestep schedule, as the authors' code does
    /// for its batch of views; so each point of the guidance chain is one prediction over all
    /// views. One view draws exactly what [`Guide::latent_target`] draws.
    pub fn latent_targets(
        &mut self,
        p: &mut dyn ViewsPredictor,
        sched: &Schedule,
        zs: &[&[f32]],
        step: u32,
    ) -> Result<Vec<LatentTarget>, String> {
        if zs.is_empty() {
            return Ok(vec![]);
        }
        let eps: Vec<Vec<f32>> = zs
            .iter()
            .map(|z| {
                (&mut self.rng)
                    .sample_iter(StandardNormal)
                    .take(z.len())
                    .collect()
            })
            .collect();
        let eps: Vec<&[f32]> = eps.iter().map(Vec::as_slice).collect();
        let ts: Vec<u32> = match self.rule {
            Rule::Mts { m } if self.settings.rule == MtsRule::Paper => {
                paper_schedule(&self.range, step, m, &mut self.rng)
            }
            Rule::Mts { .. } | Rule::PseudoGt | Rule::Edit => {
                code_schedule(&self.range, step, &mut self.rng)
            }
            Rule::Sds { t_min, t_max } | Rule::Ism { t_min, t_max, .. } => {
                vec![self.rng.gen_range(t_min..t_max.max(t_min + 1))]
            }
            Rule::DreamTime {
                t_min,
                t_max,
                steps,
            } => vec![dreamtime_t(step, steps, t_min, t_max)],
        };
        let s = &self.settings;
        let g = match self.rule {
            Rule::PseudoGt => {
                let x0 = pseudo_gts(p, sched, zs, &eps, &ts, s)?;
                return Ok(x0.into_iter().map(|x| (x, ts.clone(), 0.0)).collect());
            }
            Rule::Mts { .. } => mts_gradients(p, sched, zs, &eps, &ts, s)?,
            Rule::Edit => edit_gradients(p, sched, zs, &eps, &ts, s)?,
            Rule::Sds { .. } | Rule::DreamTime { .. } => {
                sds_gradients(p, sched, zs, &eps, ts[0], s)?
            }
            Rule::Ism {
                delta,
                xs_delta,
                xs_steps,
                ..
            } => {
                let t = ts[0];
                let s_t = t.saturating_sub(delta).max(s.t_start);
                ism_gradients(p, sched, zs, &eps, s_t, t, xs_delta.max(1), xs_steps, s)?
            }
        };
        Ok(zs
            .iter()
            .zip(g)
            .map(|(z, g)| {
                let rms = (g.iter().map(|v| (*v as f64).powi(2)).sum::<f64>()
                    / g.len().max(1) as f64)
                    .sqrt();
                let target = z.iter().zip(&g).map(|(a, b)| a - b).collect();
                (target, ts.clone(), rms)
            })
            .collect())
    }

    /// The image target for a render (`h × w × 3`, [0, 1]): encode, guide, decode
    /// ([`Guide::image_targets`] of one view).
    pub fn image_target(
        &mut self,
        sd: &mut StableDiffusion,
        cond: &Conditioning,
        render: &[f32],
        width: usize,
        height: usize,
        step: u32,
    ) -> Result<ImageTarget, String> {
        self.image_targets(sd, &[cond], &[render], width, height, step)?
            .pop()
            .ok_or_else(|| "no view".to_string())
    }
}

impl Guide {
    /// The image targets of all views of an iteration (each `h × w × 3` in [0, 1], view `i`
    /// under `conds[i]`): one autoencoder encode of the whole batch, the guidance of all views
    /// together ([`Guide::latent_targets`]: one UNet run over views × prompts per chain point),
    /// one decode of the whole batch.
    pub fn image_targets(
        &mut self,
        sd: &mut StableDiffusion,
        conds: &[&Conditioning],
        renders: &[&[f32]],
        width: usize,
        height: usize,
        step: u32,
    ) -> Result<Vec<ImageTarget>, String> {
        let n = renders.len();
        if n == 0 {
            return Ok(vec![]);
        }
        if conds.len() != n {
            return Err(format!("{n} renders and {} conditionings", conds.len()));
        }
        let per = width * height * 3;
        if let Some(r) = renders.iter().find(|r| r.len() != per) {
            return Err(format!(
                "render has {} values, expected {width}×{height}×3",
                r.len()
            ));
        }
        // One batch buffer written in place, the views in parallel.
        let t0 = std::time::Instant::now();
        let mut x = vec![0.0f32; n * per];
        let to_model = |(out, r): (&mut [f32], &&[f32])| hwc01_to_chw11_into(r, width, height, out);
        if worth_parallel(n * per) {
            x.par_chunks_mut(per.max(1))
                .zip(renders.par_iter())
                .for_each(to_model);
        } else {
            x.chunks_mut(per.max(1)).zip(renders).for_each(to_model);
        }
        sd.add_conversion_seconds(t0.elapsed().as_secs_f64());
        let (z, hw) = sd.encode(&x, n, (height, width), self.codec)?;
        let per = z.len() / n;
        let sched = sd.schedule.clone();
        let zs: Vec<&[f32]> = z.chunks_exact(per).collect();
        let mut p = UnetViews {
            sd,
            conds,
            hw,
            runs: 0,
        };
        let mut guided = Vec::with_capacity(z.len());
        let mut meta = Vec::with_capacity(n);
        for (zt, timesteps, latent_rms) in self.latent_targets(&mut p, &sched, &zs, step)? {
            guided.extend(zt);
            meta.push((timesteps, latent_rms));
        }
        let (img, (h, w)) = sd.decode(&guided, n, hw, self.codec)?;
        let t0 = std::time::Instant::now();
        let per = img.len() / n;
        let to_target = |(im, (timesteps, latent_rms)): (&[f32], (Vec<u32>, f64))| ImageTarget {
            image: chw11_to_hwc01(im, w, h),
            width: w,
            height: h,
            timesteps,
            latent_rms,
        };
        let targets = if worth_parallel(img.len()) {
            img.par_chunks_exact(per.max(1))
                .zip(meta)
                .map(to_target)
                .collect()
        } else {
            img.chunks_exact(per.max(1))
                .zip(meta)
                .map(to_target)
                .collect()
        };
        sd.add_conversion_seconds(t0.elapsed().as_secs_f64());
        Ok(targets)
    }
}

/// ½ w Σ (x − x̃)² and its gradient w (x − x̃) with respect to the render.
pub fn target_loss(render: &[f32], target: &[f32], weight: f32) -> (f64, Vec<f32>) {
    let mut loss = 0.0f64;
    let grad = render
        .iter()
        .zip(target)
        .map(|(x, t)| {
            let d = x - t;
            loss += 0.5 * weight as f64 * (d as f64).powi(2);
            weight * d
        })
        .collect();
    (loss, grad)
}

#[cfg(test)]
mod tests {
    use super::super::guidance::{Cond, OBJECT_MTS};
    use super::super::schedule::SchedulerConfig;
    use super::*;

    /// Records (t, conditions) of every call; predicts ε = 0.1 x.
    struct Recorder(Vec<(u32, Vec<Cond>)>);
    impl NoisePredictor for Recorder {
        fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
            self.0.push((t, conds.to_vec()));
            Ok(conds
                .iter()
                .map(|_| x.iter().map(|v| 0.1 * v).collect())
                .collect())
        }
    }

    /// Each rule calls the predictor at the timesteps and with the prompts it should.
    #[test]
    fn rules_call_the_predictor_as_specified() {
        let sched = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        let z = vec![0.3f32; 16];
        let s = MtsSettings::default();
        let run = |rule: Rule, step: u32| {
            let mut g = Guide::new(rule, OBJECT_MTS, s, Codec::Vae, 4);
            let mut r = Recorder(vec![]);
            let (target, ts, _) = g.latent_target(&mut r, &sched, &z, step).unwrap();
            assert_eq!(target.len(), z.len());
            (r.0, ts)
        };
        use Cond::*;
        // ISM: inversion from t_start in steps of 200 (null prompt) up to s = t − 80, one null
        // prediction at s, then the guided pair at t.
        let (calls, ts) = run(ISM_DEFAULT, 0);
        let t = ts[0];
        assert!((20..500).contains(&t));
        let s_t = t.saturating_sub(80).max(1);
        let mut want: Vec<u32> = vec![];
        let mut cur = 1;
        while cur < s_t && want.len() < 5 {
            want.push(cur);
            cur = (cur + 200).min(s_t);
        }
        want.push(cur);
        want.push(t);
        assert_eq!(
            calls.iter().map(|c| c.0).collect::<Vec<_>>(),
            want,
            "t = {t}"
        );
        assert!(calls[..calls.len() - 1].iter().all(|c| c.1 == vec![Null]));
        assert_eq!(calls.last().unwrap().1, vec![Positive, Negative]);
        // MTS: one batched call per chain point (t_start, then each sampled t).
        let (calls, ts) = run(Rule::Mts { m: 4 }, 0);
        let mut want = vec![1];
        want.extend(&ts);
        assert_eq!(calls.iter().map(|c| c.0).collect::<Vec<_>>(), want);
        // The start point only drives the first inversion step: the null prompt alone.
        assert_eq!(calls[0].1, vec![Null]);
        assert!(calls[1..]
            .iter()
            .all(|c| c.1 == vec![Positive, Negative, Null]));
        // DreamTime: t falls from t_max to t_min over the run.
        let dt = Rule::DreamTime {
            t_min: 20,
            t_max: 980,
            steps: 100,
        };
        assert_eq!(run(dt, 0).1, vec![980]);
        assert_eq!(run(dt, 100).1, vec![20]);
        assert_eq!(run(dt, 50).1, vec![500]);
    }
}
