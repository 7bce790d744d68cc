//! The fused Adam optimiser over a cloud's parameter buffers (one dispatch per array).
use super::backward::GpuGrads;
use super::raster::GpuGaussians;
use crate::gpu::push_matches;
use crate::gpu::{groups_for, kernels, Buffer, Context, Kernel, Result, Stream};
use bytemuck::{Pod, Zeroable};

const WG: u32 = 256;

#[repr(C)]
#[derive(Debug, Clone, Copy, Pod, Zeroable)]
struct AdamPush {
    n: u32,
    stride: u32,
    rest_from: u32,
    lr: f32,
    lr_rest: f32,
    beta1: f32,
    beta2: f32,
    eps: f32,
    bc1: f32,
    bc2: f32,
}
push_matches!(AdamPush, ADAM);

/// Adam hyper-parameters shared by all arrays (3DGS uses these).
#[derive(Debug, Clone, Copy)]
pub struct AdamConfig {
    pub beta1: f32,
    pub beta2: f32,
    pub eps: f32,
}

impl Default for AdamConfig {
    fn default() -> Self {
        AdamConfig {
            beta1: 0.9,
            beta2: 0.999,
            eps: 1e-15,
        }
    }
}

/// Learning rates of one step, per parameter group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LearningRates {
    pub means: f32,
    pub scales: f32,
    pub rotations: f32,
    pub opacities: f32,
    /// SH degree 0 (the base colour).
    pub sh_dc: f32,
    /// SH above degree 0.
    pub sh_rest: f32,
}

/// First and second moments of one parameter array.
pub struct Moments {
    pub m1: Buffer,
    pub m2: Buffer,
}

impl Moments {
    pub fn zeroed(ctx: &Context, name: &str, len: usize) -> Result<Moments> {
        Ok(Moments {
            m1: Buffer::zeroed::<f32>(ctx, &format!("{name} adam m1"), len)?,
            m2: Buffer::zeroed::<f32>(ctx, &format!("{name} adam m2"), len)?,
        })
    }
}

/// Adam state of a cloud: moments per array, and the step count.
pub struct AdamState {
    pub means: Moments,
    pub scales: Moments,
    pub rotations: Moments,
    pub opacities: Moments,
    pub sh: Moments,
    pub step: u32,
}

impl AdamState {
    /// Zero moments for `g`.
    pub fn new(ctx: &Context, g: &GpuGaussians) -> Result<AdamState> {
        let n = g.n as usize;
        let k = super::cloud::sh_coeffs(g.sh_degree);
        Ok(AdamState {
            means: Moments::zeroed(ctx, "means", n * 3)?,
            scales: Moments::zeroed(ctx, "scales", n * 3)?,
            rotations: Moments::zeroed(ctx, "rotations", n * 4)?,
            opacities: Moments::zeroed(ctx, "opacities", n)?,
            sh: Moments::zeroed(ctx, "sh", n * k * 3)?,
            step: 0,
        })
    }
}

/// The Adam kernel.
pub struct Adam {
    kernel: Kernel,
    pub config: AdamConfig,
}

impl Adam {
    pub fn new(ctx: &Context, config: AdamConfig) -> Result<Adam> {
        Ok(Adam {
            kernel: Kernel::new(ctx, kernels::ADAM, WG)?,
            config,
        })
    }

    /// Records one step over every array of `g`, clearing `grads`' parameter gradients.
    pub fn record(
        &self,
        s: &mut Stream,
        g: &GpuGaussians,
        grads: &GpuGrads,
        state: &mut AdamState,
        lr: &LearningRates,
    ) -> Result<()> {
        state.step += 1;
        let t = state.step as i32;
        let c = self.config;
        let bc1 = 1.0 - c.beta1.powi(t);
        let bc2 = 1.0 - c.beta2.powi(t);
        let n = g.n;
        let kc3 = super::cloud::sh_coeffs(g.sh_degree) as u32 * 3;
        let arrays: [(&Buffer, &Buffer, &Moments, u32, f32, u32, f32); 5] = [
            (
                &g.means,
                &grads.means,
                &state.means,
                n * 3,
                lr.means,
                0,
                0.0,
            ),
            (
                &g.scales,
                &grads.scales,
                &state.scales,
                n * 3,
                lr.scales,
                0,
                0.0,
            ),
            (
                &g.rotations,
                &grads.rotations,
                &state.rotations,
                n * 4,
                lr.rotations,
                0,
                0.0,
            ),
            (
                &g.opacities,
                &grads.opacities,
                &state.opacities,
                n,
                lr.opacities,
                0,
                0.0,
            ),
            (
                &g.sh,
                &grads.sh,
                &state.sh,
                n * kc3,
                lr.sh_dc,
                kc3,
                lr.sh_rest,
            ),
        ];
        for (param, grad, mo, len, lr0, stride, lr_rest) in arrays {
            if len == 0 {
                continue;
            }
            let push = AdamPush {
                n: len,
                stride,
                rest_from: 3,
                lr: lr0,
                lr_rest,
                beta1: c.beta1,
                beta2: c.beta2,
                eps: c.eps,
                bc1,
                bc2,
            };
            s.dispatch(
                &self.kernel,
                &[
                    ("param", param),
                    ("grad", grad),
                    ("moment1", &mo.m1),
                    ("moment2", &mo.m2),
                ],
                bytemuck::bytes_of(&push),
                groups_for(len.div_ceil(WG)),
            )?;
        }
        Ok(())
    }
}

/// One Adam step in f64 on the host: the reference the kernel is tested against.
#[allow(
    clippy::too_many_arguments,
    reason = "the kernel's push constants, one argument each, as in the kernel"
)]
pub fn adam_step_reference(
    param: &mut [f64],
    grad: &[f64],
    m1: &mut [f64],
    m2: &mut [f64],
    step: u32,
    lr: impl Fn(usize) -> f64,
    c: AdamConfig,
) {
    let (b1, b2) = (c.beta1 as f64, c.beta2 as f64);
    let bc1 = 1.0 - b1.powi(step as i32);
    let bc2 = 1.0 - b2.powi(step as i32);
    for e in 0..param.len() {
        let g = if grad[e].is_finite() { grad[e] } else { 0.0 };
        m1[e] = b1 * m1[e] + (1.0 - b1) * g;
        m2[e] = b2 * m2[e] + (1.0 - b2) * g * g;
        param[e] -= lr(e) * (m1[e] / bc1) / ((m2[e] / bc2).sqrt() + c.eps as f64);
    }
}
