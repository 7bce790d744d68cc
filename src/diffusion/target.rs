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
use super::guidance::{
    code_schedule, dreamtime_t, edit_gradient, ism_gradient, mts_gradient, paper_schedule,
    pseudo_gt, sds_gradient, MtsRange, MtsRule, MtsSettings,
};
use super::model::{
    chw11_to_hwc01, hwc01_to_chw11, Codec, Conditioning, StableDiffusion, UnetPredictor,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

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
    /// Interval score matching, t uniform in `[t_min, t_max)`, s = t − `delta`.
    Ism { t_min: u32, t_max: u32, delta: u32 },
}

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

    fn noise(&mut self, n: usize) -> Vec<f32> {
        (0..n)
            .map(|_| {
                // Box–Muller from two uniforms.
                let u1: f64 = self.rng.gen_range(1e-12..1.0);
                let u2: f64 = self.rng.gen();
                ((-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()) as f32
            })
            .collect()
    }

    /// The latent target for latent `z` (size `c × hw`) at training step `step`, with the
    /// timesteps used and the gradient's RMS.
    pub fn latent_target(
        &mut self,
        sd: &mut StableDiffusion,
        cond: &Conditioning,
        z: &[f32],
        hw: (usize, usize),
        step: u32,
    ) -> Result<(Vec<f32>, Vec<u32>, f64), String> {
        let eps = self.noise(z.len());
        let sched = sd.schedule.clone();
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
        let mut p = UnetPredictor {
            sd,
            cond,
            hw,
            runs: 0,
        };
        let s = &self.settings;
        let g = match self.rule {
            Rule::PseudoGt => {
                let x0 = pseudo_gt(&mut p, &sched, z, &eps, &ts, s)?;
                return Ok((x0, ts, 0.0));
            }
            Rule::Mts { .. } => mts_gradient(&mut p, &sched, z, &eps, &ts, s)?,
            Rule::Edit => edit_gradient(&mut p, &sched, z, &eps, &ts, s)?,
            Rule::Sds { .. } | Rule::DreamTime { .. } => {
                sds_gradient(&mut p, &sched, z, &eps, ts[0], s)?
            }
            Rule::Ism { delta, .. } => {
                let t = ts[0];
                let s_t = t.saturating_sub(delta).max(s.t_start);
                ism_gradient(&mut p, &sched, z, &eps, s_t, t, delta.max(1), 8, s)?
            }
        };
        let rms =
            (g.iter().map(|v| (*v as f64).powi(2)).sum::<f64>() / g.len().max(1) as f64).sqrt();
        let target = z.iter().zip(&g).map(|(a, b)| a - b).collect();
        Ok((target, ts, rms))
    }

    /// The image target for a render (`h × w × 3`, [0, 1]): encode, guide, decode.
    pub fn image_target(
        &mut self,
        sd: &mut StableDiffusion,
        cond: &Conditioning,
        render: &[f32],
        width: usize,
        height: usize,
        step: u32,
    ) -> Result<ImageTarget, String> {
        if render.len() != width * height * 3 {
            return Err(format!(
                "render has {} values, expected {width}×{height}×3",
                render.len()
            ));
        }
        let x = hwc01_to_chw11(render, width, height);
        let (z, hw) = sd.encode(&x, 1, (height, width), self.codec)?;
        let (zt, timesteps, latent_rms) = self.latent_target(sd, cond, &z, hw, step)?;
        let (img, (h, w)) = sd.decode(&zt, 1, hw, self.codec)?;
        Ok(ImageTarget {
            image: chw11_to_hwc01(&img, w, h),
            width: w,
            height: h,
            timesteps,
            latent_rms,
        })
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
