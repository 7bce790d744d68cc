//! Noise-schedule maths of the Stable Diffusion pipeline as pure functions: betas and ᾱ from
//! `scheduler/scheduler_config.json`, timestep spacing with offset, noising, x̂₀ prediction, the
//! deterministic DDIM step (η = 0) that also runs the inversion, classifier-free guidance, and the
//! weight w(ᾱ) = sqrt((1 − ᾱ)/ᾱ). Coefficients are f64; latents are f32 slices.
use serde::Deserialize;
use std::path::Path;

/// The fields of a diffusers `scheduler_config.json` that matter here (diffusers' defaults).
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct SchedulerConfig {
    #[serde(default = "d_train")]
    pub num_train_timesteps: u32,
    #[serde(default = "d_beta_start")]
    pub beta_start: f64,
    #[serde(default = "d_beta_end")]
    pub beta_end: f64,
    #[serde(default = "d_schedule")]
    pub beta_schedule: String,
    #[serde(default)]
    pub steps_offset: u32,
    #[serde(default = "d_spacing")]
    pub timestep_spacing: String,
    #[serde(default = "d_prediction")]
    pub prediction_type: String,
    #[serde(default = "d_true")]
    pub set_alpha_to_one: bool,
}

fn d_train() -> u32 {
    1000
}
fn d_beta_start() -> f64 {
    0.0001
}
fn d_beta_end() -> f64 {
    0.02
}
fn d_schedule() -> String {
    "linear".into()
}
fn d_spacing() -> String {
    "leading".into()
}
fn d_prediction() -> String {
    "epsilon".into()
}
fn d_true() -> bool {
    true
}

impl SchedulerConfig {
    /// Stable Diffusion 2.1 base's scheduler (DDIM, scaled-linear 0.00085 to 0.012, leading
    /// spacing with offset 1, epsilon prediction).
    pub fn sd21_base() -> SchedulerConfig {
        SchedulerConfig {
            num_train_timesteps: 1000,
            beta_start: 0.00085,
            beta_end: 0.012,
            beta_schedule: "scaled_linear".into(),
            steps_offset: 1,
            timestep_spacing: "leading".into(),
            prediction_type: "epsilon".into(),
            set_alpha_to_one: false,
        }
    }

    /// Reads `scheduler_config.json`; errors name the file.
    pub fn read(path: &Path) -> Result<SchedulerConfig, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
    }
}

/// What the UNet predicts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Prediction {
    Epsilon,
    /// v = sqrt(ᾱ) ε − sqrt(1 − ᾱ) x₀ (SD 2.x at 768 px).
    V,
}

/// A noise schedule.
#[derive(Debug, Clone)]
pub struct Schedule {
    pub config: SchedulerConfig,
    /// ᾱ_t for t = 0 .. num_train_timesteps − 1.
    pub alphas_cumprod: Vec<f64>,
    /// ᾱ "before" t = 0, used when a DDIM step lands below 0.
    pub final_alpha_cumprod: f64,
    pub prediction: Prediction,
}

impl Schedule {
    pub fn new(config: SchedulerConfig) -> Result<Schedule, String> {
        let n = config.num_train_timesteps as usize;
        if !(2..=100_000).contains(&n) {
            return Err(format!("num_train_timesteps {n}"));
        }
        let (a, b) = (config.beta_start, config.beta_end);
        if !(a > 0.0 && b < 1.0 && a <= b) {
            return Err(format!("betas {a} to {b}"));
        }
        let lin = |lo: f64, hi: f64, i: usize| lo + (hi - lo) * i as f64 / (n - 1) as f64;
        let betas: Vec<f64> = match config.beta_schedule.as_str() {
            "linear" => (0..n).map(|i| lin(a, b, i)).collect(),
            "scaled_linear" => (0..n).map(|i| lin(a.sqrt(), b.sqrt(), i).powi(2)).collect(),
            "squaredcos_cap_v2" => {
                let f = |t: f64| {
                    ((t + 0.008) / 1.008 * std::f64::consts::FRAC_PI_2)
                        .cos()
                        .powi(2)
                };
                (0..n)
                    .map(|i| {
                        let (t1, t2) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
                        (1.0 - f(t2) / f(t1)).min(0.999)
                    })
                    .collect()
            }
            s => {
                return Err(format!(
                    "beta_schedule `{s}` (linear, scaled_linear, squaredcos_cap_v2)"
                ))
            }
        };
        let mut acc = 1.0;
        let alphas_cumprod: Vec<f64> = betas
            .iter()
            .map(|b| {
                acc *= 1.0 - b;
                acc
            })
            .collect();
        let prediction = match config.prediction_type.as_str() {
            "epsilon" => Prediction::Epsilon,
            "v_prediction" => Prediction::V,
            s => return Err(format!("prediction_type `{s}` (epsilon or v_prediction)")),
        };
        let final_alpha_cumprod = if config.set_alpha_to_one {
            1.0
        } else {
            alphas_cumprod[0]
        };
        Ok(Schedule {
            config,
            alphas_cumprod,
            final_alpha_cumprod,
            prediction,
        })
    }

    /// ᾱ at DDPM timestep `t` (negative: the final value).
    pub fn alpha_bar(&self, t: i64) -> f64 {
        if t < 0 {
            self.final_alpha_cumprod
        } else {
            self.alphas_cumprod[(t as usize).min(self.alphas_cumprod.len() - 1)]
        }
    }

    /// Inference timesteps for `steps` steps, descending, with the configured spacing and offset
    /// (diffusers' `set_timesteps`).
    pub fn timesteps(&self, steps: u32) -> Result<Vec<u32>, String> {
        let t = self.config.num_train_timesteps;
        if steps == 0 || steps > t {
            return Err(format!("{steps} inference steps for {t} training steps"));
        }
        let mut v: Vec<u32> = match self.config.timestep_spacing.as_str() {
            "leading" => {
                let ratio = t / steps;
                (0..steps)
                    .map(|i| i * ratio + self.config.steps_offset)
                    .collect()
            }
            "trailing" => {
                let ratio = t as f64 / steps as f64;
                (0..steps)
                    .map(|i| ((t as f64 - i as f64 * ratio).round() as u32).saturating_sub(1))
                    .rev()
                    .collect()
            }
            "linspace" => (0..steps)
                .map(|i| {
                    if steps == 1 {
                        0
                    } else {
                        (i as f64 * (t - 1) as f64 / (steps - 1) as f64).round() as u32
                    }
                })
                .collect(),
            s => {
                return Err(format!(
                    "timestep_spacing `{s}` (leading, trailing, linspace)"
                ))
            }
        };
        for x in &mut v {
            *x = (*x).min(t - 1);
        }
        v.reverse();
        Ok(v)
    }

    /// The UNet's output as ε (converts v-prediction).
    pub fn to_eps(&self, out: &[f32], x_t: &[f32], ab: f64) -> Vec<f32> {
        self.into_eps(out.to_vec(), x_t, ab)
    }

    /// [`Schedule::to_eps`] in place: an ε prediction is returned as it is, a v prediction is
    /// converted in its own buffer.
    pub fn into_eps(&self, mut out: Vec<f32>, x_t: &[f32], ab: f64) -> Vec<f32> {
        if self.prediction == Prediction::V {
            let (sa, sb) = (ab.sqrt(), (1.0 - ab).sqrt());
            for (v, x) in out.iter_mut().zip(x_t) {
                *v = (sa * *v as f64 + sb * *x as f64) as f32;
            }
        }
        out
    }
}

/// x_t = sqrt(ᾱ) x₀ + sqrt(1 − ᾱ) ε.
pub fn add_noise(x0: &[f32], eps: &[f32], ab: f64) -> Vec<f32> {
    let (sa, sb) = (ab.sqrt(), (1.0 - ab).sqrt());
    x0.iter()
        .zip(eps)
        .map(|(x, e)| (sa * *x as f64 + sb * *e as f64) as f32)
        .collect()
}

/// The one-step x̂₀ = (x_t − sqrt(1 − ᾱ) ε) / sqrt(ᾱ): the pseudo-ground-truth of
/// reconstructive generation when ε is the guided prediction.
pub fn predict_x0(x_t: &[f32], eps: &[f32], ab: f64) -> Vec<f32> {
    let (sa, sb) = (ab.sqrt(), (1.0 - ab).sqrt());
    x_t.iter()
        .zip(eps)
        .map(|(x, e)| ((*x as f64 - sb * *e as f64) / sa) as f32)
        .collect()
}

/// Deterministic DDIM step (η = 0) from ᾱ_from to ᾱ_to with noise prediction ε: denoising when
/// ᾱ_to > ᾱ_from, DDIM inversion when ᾱ_to < ᾱ_from.
pub fn ddim_step(x: &[f32], eps: &[f32], ab_from: f64, ab_to: f64) -> Vec<f32> {
    let (sf, sfb) = (ab_from.sqrt(), (1.0 - ab_from).sqrt());
    let (st, stb) = (ab_to.sqrt(), (1.0 - ab_to).sqrt());
    x.iter()
        .zip(eps)
        .map(|(x, e)| {
            let (x, e) = (*x as f64, *e as f64);
            let x0 = (x - sfb * e) / sf;
            (st * x0 + stb * e) as f32
        })
        .collect()
}

/// Classifier-free guidance: uncond + scale (cond − uncond).
pub fn cfg(uncond: &[f32], cond: &[f32], scale: f64) -> Vec<f32> {
    uncond
        .iter()
        .zip(cond)
        .map(|(u, c)| (*u as f64 + scale * (*c as f64 - *u as f64)) as f32)
        .collect()
}

/// The MTS / ISM weight w(ᾱ) = sqrt((1 − ᾱ)/ᾱ).
pub fn weight(ab: f64) -> f64 {
    ((1.0 - ab) / ab).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sd21_schedule_matches_diffusers() {
        let s = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        // SD 2.1 base (scaled_linear 0.00085..0.012), computed independently in Python:
        // alphas_cumprod[0] = 1 - 0.00085, [499] = 0.27766965, [999] = 0.00466010 (the familiar
        // ~0.0047 of SD's last step).
        assert!((s.alpha_bar(0) - 0.99915).abs() < 1e-12);
        assert!(
            (s.alpha_bar(499) - 0.277_669_650_456).abs() < 1e-9,
            "{}",
            s.alpha_bar(499)
        );
        assert!(
            (s.alpha_bar(999) - 0.004_660_098_513).abs() < 1e-11,
            "{}",
            s.alpha_bar(999)
        );
        assert_eq!(s.alpha_bar(-1), s.alpha_bar(0), "set_alpha_to_one false");
        let ts = s.timesteps(50).unwrap();
        assert_eq!((ts[0], ts[1], ts[49]), (981, 961, 1));
        // The authors' code flips set_timesteps(1000): index i is timestep i + 1.
        let full = s.timesteps(1000).unwrap();
        assert_eq!((full[999], full[0]), (1, 999));
        let mut c = SchedulerConfig::sd21_base();
        c.timestep_spacing = "trailing".into();
        let t = Schedule::new(c).unwrap().timesteps(50).unwrap();
        assert_eq!((t[0], t[49]), (999, 19));
    }

    #[test]
    fn ddim_inversion_undoes_denoising_and_x0_is_consistent() {
        let x: Vec<f32> = (0..64).map(|i| ((i as f32) * 0.37).sin()).collect();
        let eps: Vec<f32> = (0..64).map(|i| ((i as f32) * 1.3).cos()).collect();
        let (a, b) = (0.3, 0.8);
        let down = ddim_step(&x, &eps, a, b);
        let back = ddim_step(&down, &eps, b, a);
        for (p, q) in x.iter().zip(&back) {
            assert!((p - q).abs() < 1e-5);
        }
        let x0: Vec<f32> = (0..64).map(|i| (i as f32) * 0.01).collect();
        let xt = add_noise(&x0, &eps, 0.42);
        for (p, q) in x0.iter().zip(predict_x0(&xt, &eps, 0.42)) {
            assert!((p - q).abs() < 1e-5);
        }
        // A DDIM step to ᾱ = 1 lands on x̂₀.
        for (p, q) in ddim_step(&xt, &eps, 0.42, 1.0).iter().zip(&x0) {
            assert!((p - q).abs() < 1e-5);
        }
        assert_eq!(cfg(&[1.0], &[2.0], 7.5), vec![8.5]);
        assert!((weight(0.5) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn v_prediction_converts_to_eps() {
        let mut c = SchedulerConfig::sd21_base();
        c.prediction_type = "v_prediction".into();
        let s = Schedule::new(c).unwrap();
        let (x0, eps, ab) = ([0.3f32, -0.5], [1.1f32, 0.2], 0.6f64);
        let xt = add_noise(&x0, &eps, ab);
        let v: Vec<f32> = (0..2)
            .map(|i| (ab.sqrt() * eps[i] as f64 - (1.0 - ab).sqrt() * x0[i] as f64) as f32)
            .collect();
        for (p, q) in s.to_eps(&v, &xt, ab).iter().zip(eps) {
            assert!((p - q).abs() < 1e-6);
        }
    }

    #[test]
    fn bad_configs_are_refused() {
        let mut c = SchedulerConfig::sd21_base();
        c.beta_schedule = "cubic".into();
        assert!(Schedule::new(c).unwrap_err().contains("cubic"));
        let s = Schedule::new(SchedulerConfig::sd21_base()).unwrap();
        assert!(s.timesteps(0).is_err() && s.timesteps(1001).is_err());
        let c: SchedulerConfig = serde_json::from_str(
            r#"{"_class_name": "DDIMScheduler", "beta_start": 0.00085, "beta_end": 0.012,
                "beta_schedule": "scaled_linear", "steps_offset": 1, "set_alpha_to_one": false}"#,
        )
        .unwrap();
        assert_eq!(c, SchedulerConfig::sd21_base());
    }
}
