//! `dreamscene bench --generate --prior sd`: one formation iteration of object generation with
//! the Stable Diffusion prior, split into the text encoder, the UNet and the autoencoder (each
//! ONNX Runtime's `session.run` alone), the conversions of the models' inputs and outputs, the
//! guidance maths on the host, the kernels and the rest, with the views of an iteration in one
//! UNet run per guidance step (batched) and one view at a time (per view), measured in one run.
use crate::camera::object::OrbitRanges;
use crate::diffusion::runtime::Provider;
use crate::generate::object::{formation_guide, formation_iteration, formation_trainer, GenError};
use crate::generate::prior_spec::open_sd;
use crate::gpu::Context;
use crate::splat::Gaussians;
use rand::SeedableRng;
use serde::Serialize;
use std::path::Path;

/// Where one sd iteration's time goes (means over the timed iterations, ms).
#[derive(Debug, Clone, Serialize)]
pub struct SdIterationFigures {
    /// `batched` (one UNet run over views × prompts per guidance step) or `per view`.
    pub mode: String,
    pub provider: String,
    pub precision: String,
    pub views: usize,
    pub size: u32,
    pub gaussians: u32,
    pub wall_ms: f64,
    /// ONNX Runtime's `session.run` of the text encoder.
    pub text_encoder_ms: f64,
    /// ONNX Runtime's `session.run` of the UNet.
    pub unet_ms: f64,
    /// ONNX Runtime's `session.run` of the autoencoder's encode and decode.
    pub vae_ms: f64,
    /// The host's preparation of the models' inputs and outputs: f32 ↔ f16, batching, latent
    /// scaling, image layout changes, the finiteness check.
    pub conversions_ms: f64,
    /// GPU time from timestamps: renders, backward passes and Adam.
    pub kernels_ms: f64,
    /// The rest of the prior's host work: guidance maths, noise, the schedule.
    pub prior_host_ms: f64,
    /// wall − prior − kernels: readbacks, submissions, the loss, bookkeeping.
    pub host_ms: f64,
    /// (conversions + prior host + host) / wall: the share outside ONNX Runtime and the kernels.
    pub host_share: f64,
    pub unet_runs: f64,
    pub unet_items: f64,
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// Times `runs` formation iterations (after `warmups` untimed ones) with the sd prior of `models` on
/// `provider`: `views` views of `size`² a step, a random cloud of `n` Gaussians. With
/// `per_view`, every UNet run holds one view's prompts (the iteration before batching).
#[allow(clippy::too_many_arguments, reason = "what one measurement varies")]
pub fn bench_generate_sd(
    ctx: &Context,
    models: &Path,
    provider: Provider,
    n: usize,
    views: usize,
    size: u32,
    runs: usize,
    warmups: usize,
    per_view: bool,
) -> Result<SdIterationFigures, GenError> {
    let (frame, cfg) = crate::bench::bench_object(views, size);
    let mut prior = open_sd(models, provider, "A DSLR photo of a wooden chair", None)?;
    // MTS asks three prompts at every guidance step: one view's worth a run.
    prior.sd.set_unet_max_batch(per_view.then_some(3));
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(12);
    let c = frame.centre();
    let lo = std::array::from_fn(|a| (c[a] - 0.35 * frame.size[a]) as f32);
    let hi = std::array::from_fn(|a| (c[a] + 0.35 * frame.size[a]) as f32);
    let cloud = Gaussians::random(&mut rng, n, lo, hi, 0.01, 0);
    let mut t = formation_trainer(ctx, &cloud, &frame, &cfg)?;
    t.set_timed(true);
    let mut guide = formation_guide(&cfg);
    let ranges = OrbitRanges::default();
    let mut rows: Vec<[f64; 10]> = vec![];
    for i in 0..runs.max(1) + warmups {
        let r = formation_iteration(
            &mut t, &mut prior, &mut guide, &mut rng, &frame, &ranges, &cfg,
        )?;
        let m = prior.sd.take_times();
        if i < warmups {
            continue;
        }
        let models_ms = (m.text_encoder + m.unet + m.autoencoder + m.conversions) * 1e3;
        let prior_ms = r.prior_seconds * 1e3;
        let kernels = r.kernels.total_ms();
        let wall = r.seconds * 1e3;
        rows.push([
            wall,
            m.text_encoder * 1e3,
            m.unet * 1e3,
            m.autoencoder * 1e3,
            kernels,
            prior_ms - models_ms,
            wall - prior_ms - kernels,
            m.unet_runs as f64,
            m.unet_items as f64,
            m.conversions * 1e3,
        ]);
    }
    let col = |k: usize| mean(&rows.iter().map(|r| r[k]).collect::<Vec<_>>());
    Ok(SdIterationFigures {
        mode: if per_view { "per view" } else { "batched" }.into(),
        provider: format!("{:?}", prior.sd.provider()).to_lowercase(),
        precision: prior.sd.precision().into(),
        views,
        size,
        gaussians: n as u32,
        wall_ms: col(0),
        text_encoder_ms: col(1),
        unet_ms: col(2),
        vae_ms: col(3),
        conversions_ms: col(9),
        kernels_ms: col(4),
        prior_host_ms: col(5),
        host_ms: col(6),
        host_share: (col(9) + col(5) + col(6)) / col(0).max(1e-9),
        unet_runs: col(7),
        unet_items: col(8),
    })
}
