//! The 3D Gaussian filtering score of the DreamScene method, accumulated on the GPU per view.
use super::raster::{Frame, GpuGaussians};
use crate::gpu::push_matches;
use crate::gpu::{
    groups_for, kernels, Buffer, BufferUsage, Context, GpuError, Kernel, Result, Stream,
};
use bytemuck::{Pod, Zeroable};

/// Which score to accumulate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScoreRule {
    /// The paper: sum over contributing rays of V(i) / (D(r, i)^2 * maxV(r)).
    Paper,
    /// The authors' code: sum over contributing pixels of 1 / z^2; the volume factor
    /// (V / V_ref)^0.1 is applied afterwards by [`code_volume_weighting`].
    Code,
}

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct ScorePush {
    width: u32,
    height: u32,
    tiles_x: u32,
    seg_begin: u32,
    first: u32,
    mode: u32,
}
push_matches!(ScorePush, SCORE);

/// The score kernel (native float atomics, or the compare-and-swap variant).
pub struct Scorer {
    kernel: Kernel,
}

impl Scorer {
    /// Uses native float atomics when the device has them, unless `force_cas`.
    pub fn new(ctx: &Context, force_cas: bool) -> Result<Scorer> {
        let src = if ctx.info().float_atomics && !force_cas {
            kernels::SCORE
        } else {
            kernels::SCORE_CAS
        };
        Ok(Scorer {
            kernel: Kernel::new(ctx, src, kernels::TILE * kernels::TILE)?,
        })
    }

    /// Adds this view's score of every Gaussian to `scores` (`g.n` floats).
    pub fn accumulate(
        &self,
        ctx: &Context,
        frame: &Frame,
        g: &GpuGaussians,
        rule: ScoreRule,
        scores: &Buffer,
    ) -> Result<()> {
        if scores.size() < g.n as u64 * 4 || frame.n != g.n {
            return Err(GpuError::Kernel {
                kernel: "score".into(),
                msg: format!(
                    "scores buffer of {} bytes for {} Gaussians (frame of {})",
                    scores.size(),
                    g.n,
                    frame.n
                ),
            });
        }
        let np = frame.width as u64 * frame.height as u64;
        let pstate = Buffer::new(ctx, "score pixel state", np * 16, BufferUsage::Device)?;
        let segments = frame.max_tile_len.div_ceil(kernels::SEGMENT).max(1);
        let modes: &[u32] = match rule {
            ScoreRule::Code => &[0],
            ScoreRule::Paper => &[1, 2],
        };
        let mut s = Stream::new(ctx)?;
        s.fill(&pstate, 0);
        for &mode in modes {
            for seg in 0..segments {
                let push = ScorePush {
                    width: frame.width,
                    height: frame.height,
                    tiles_x: frame.tiles_x,
                    seg_begin: seg * kernels::SEGMENT,
                    first: (seg == 0) as u32,
                    mode,
                };
                s.dispatch(
                    &self.kernel,
                    &[
                        ("proj", &frame.proj),
                        ("isect_ids", &frame.isect_ids),
                        ("ranges", &frame.ranges),
                        ("scales", &g.scales),
                        ("pstate", &pstate),
                        ("score", scores),
                    ],
                    bytemuck::bytes_of(&push),
                    groups_for(frame.tiles_x * frame.tiles_y),
                )?;
            }
        }
        s.submit()?;
        Ok(())
    }
}

/// The authors' LightGaussian-style weighting: `score = (V / V_ref)^v_pow * importance`, with
/// V_ref the volume that 90% of the Gaussians exceed (their code uses `v_pow` = 0.1).
pub fn code_volume_weighting(importance: &[f32], log_scales: &[[f32; 3]], v_pow: f32) -> Vec<f32> {
    let vol: Vec<f32> = log_scales
        .iter()
        .map(|s| (s[0] + s[1] + s[2]).exp())
        .collect();
    if vol.is_empty() {
        return vec![];
    }
    let mut sorted = vol.clone();
    sorted.sort_by(|a, b| b.total_cmp(a));
    let v_ref =
        sorted[((0.9 * vol.len() as f64) as usize).min(vol.len() - 1)].max(f32::MIN_POSITIVE);
    vol.iter()
        .zip(importance)
        .map(|(v, i)| (v / v_ref).powf(v_pow) * i)
        .collect()
}
