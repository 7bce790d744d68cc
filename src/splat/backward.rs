//! The GPU backward pass: blend backward (screen-space gradients, subgroup-reduced float atomics)
//! then projection backward (raw parameter gradients and densification statistics).
use super::raster::{BlendWidth, CameraData, Frame, GpuGaussians};
use crate::camera::Camera;
use crate::gpu::push_matches;
use crate::gpu::{
    groups_for, kernels, Buffer, BufferUsage, Context, GpuError, Kernel, Result, Stream, Timings,
};
use bytemuck::{Pod, Zeroable};

const WG: u32 = 128;
/// Floats per Gaussian in the screen-space gradient buffer.
pub const GRAD2D_STRIDE: usize = 9;

#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct BlendBackwardPush {
    width: u32,
    height: u32,
    tiles_x: u32,
    seg_begin: u32,
    seg_len: u32,
    first: u32,
    bg: [f32; 3],
}
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct ProjectBackwardPush {
    cam: CameraData,
    n: u32,
    sh_degree: u32,
    pad: [u32; 2],
}
push_matches!(BlendBackwardPush, BLEND_BACKWARD);
push_matches!(ProjectBackwardPush, PROJECT_BACKWARD);

/// Gradient buffers for a cloud, laid out as [`GpuGaussians`], plus the screen-space gradients
/// and the densification statistics. Gradients accumulate over backward calls until cleared
/// (the Adam step clears them).
pub struct GpuGrads {
    pub means: Buffer,
    pub scales: Buffer,
    pub rotations: Buffer,
    pub opacities: Buffer,
    pub sh: Buffer,
    /// Per Gaussian: d xy, d conic (3), d opacity, d rgb; cleared by each projection backward.
    pub grad2d: Buffer,
    /// Per Gaussian: (sum of NDC centre-gradient norms, views visible, max radius in pixels, 0).
    pub stats: Buffer,
    pub n: u32,
    pub sh_degree: u32,
}

/// Gradients read back to the host.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct HostGrads {
    pub means: Vec<[f32; 3]>,
    pub scales: Vec<[f32; 3]>,
    pub rotations: Vec<[f32; 4]>,
    pub opacities: Vec<f32>,
    pub sh: Vec<f32>,
    /// Densification statistics (see [`GpuGrads::stats`]).
    pub stats: Vec<[f32; 4]>,
}

impl GpuGrads {
    /// Zeroed gradients for `n` Gaussians of SH degree `sh_degree`.
    pub fn new(ctx: &Context, n: u32, sh_degree: u32) -> Result<GpuGrads> {
        let n_ = n as usize;
        let k = super::cloud::sh_coeffs(sh_degree);
        Ok(GpuGrads {
            means: Buffer::zeroed::<f32>(ctx, "grad means", n_ * 3)?,
            scales: Buffer::zeroed::<f32>(ctx, "grad log scales", n_ * 3)?,
            rotations: Buffer::zeroed::<f32>(ctx, "grad rotations", n_ * 4)?,
            opacities: Buffer::zeroed::<f32>(ctx, "grad opacity logits", n_)?,
            sh: Buffer::zeroed::<f32>(ctx, "grad sh", n_ * k * 3)?,
            grad2d: Buffer::zeroed::<f32>(ctx, "grad screen space", n_ * GRAD2D_STRIDE)?,
            stats: Buffer::zeroed::<f32>(ctx, "densify stats", n_ * 4)?,
            n,
            sh_degree,
        })
    }

    /// Reads everything back.
    pub fn download(&self) -> Result<HostGrads> {
        let n = self.n as usize;
        let k = super::cloud::sh_coeffs(self.sh_degree);
        Ok(HostGrads {
            means: self.means.read(n)?,
            scales: self.scales.read(n)?,
            rotations: self.rotations.read(n)?,
            opacities: self.opacities.read(n)?,
            sh: self.sh.read(n * k * 3)?,
            stats: self.stats.read(n)?,
        })
    }

    /// Zeroes the parameter gradients (not the statistics).
    pub fn clear(&self, s: &mut Stream) {
        for b in [
            &self.means,
            &self.scales,
            &self.rotations,
            &self.opacities,
            &self.sh,
        ] {
            s.fill(b, 0);
        }
    }
}

/// The backward kernels.
pub struct Backward {
    blend: Kernel,
    project: Kernel,
    seg_len: u32,
    timed: bool,
}

impl Backward {
    /// Uses native float atomics when the device has them, unless `force_cas`, and the blend
    /// width suited to the device ([`BlendWidth::for_device`]).
    pub fn new(ctx: &Context, force_cas: bool) -> Result<Backward> {
        Self::with_width(ctx, force_cas, BlendWidth::for_device(ctx))
    }

    /// As [`Backward::new`] with a given blend width (both give the same gradients).
    pub fn with_width(ctx: &Context, force_cas: bool, width: BlendWidth) -> Result<Backward> {
        let cas = force_cas || !ctx.info().float_atomics;
        let (src, seg_len) = match (cas, width) {
            (true, BlendWidth::One) => (kernels::BLEND_BACKWARD_CAS, kernels::SEGMENT_CAS),
            (true, BlendWidth::Wide) => (kernels::BLEND_BACKWARD_CAS_WIDE, kernels::SEGMENT_CAS),
            (false, BlendWidth::One) => (kernels::BLEND_BACKWARD, kernels::SEGMENT),
            (false, BlendWidth::Wide) => (kernels::BLEND_BACKWARD_WIDE, kernels::SEGMENT),
        };
        Ok(Backward {
            blend: Kernel::new(ctx, src, width.workgroup_size())?,
            project: Kernel::new(ctx, kernels::PROJECT_BACKWARD, WG)?,
            seg_len,
            timed: false,
        })
    }

    /// Records per-dispatch GPU times into the timings `run` returns.
    pub fn set_timed(&mut self, timed: bool) {
        self.timed = timed;
    }

    /// Records the backward of `frame` (rendered from `g` and `cam`) for the per-pixel colour
    /// gradient `dl_dcolor` (`[f32; 4]` per pixel, rgb used), adding to `grads`. `state` is
    /// per-pixel scratch (16 bytes a pixel).
    #[allow(
        clippy::too_many_arguments,
        reason = "the kernel's buffers and sizes, one argument each"
    )]
    pub fn record(
        &self,
        s: &mut Stream,
        frame: &Frame,
        g: &GpuGaussians,
        cam: &Camera,
        dl_dcolor: &Buffer,
        grads: &GpuGrads,
        state: &Buffer,
    ) -> Result<()> {
        let np = frame.width as u64 * frame.height as u64;
        if frame.n != g.n || grads.n != g.n || grads.sh_degree != g.sh_degree {
            return Err(GpuError::Kernel {
                kernel: "backward".into(),
                msg: format!(
                    "frame of {} Gaussians, cloud of {} (degree {}), gradients of {} (degree {})",
                    frame.n, g.n, g.sh_degree, grads.n, grads.sh_degree
                ),
            });
        }
        if dl_dcolor.size() < np * 16 || state.size() < np * 16 {
            return Err(GpuError::Kernel {
                kernel: "backward".into(),
                msg: format!(
                    "colour gradient of {} bytes and state of {} bytes for {np} pixels",
                    dl_dcolor.size(),
                    state.size()
                ),
            });
        }
        if cam.width != frame.width || cam.height != frame.height {
            return Err(GpuError::Kernel {
                kernel: "backward".into(),
                msg: "camera differs from the frame's".into(),
            });
        }
        let segments = frame.max_tile_len.div_ceil(self.seg_len).max(1);
        for seg in 0..segments {
            let push = BlendBackwardPush {
                width: frame.width,
                height: frame.height,
                tiles_x: frame.tiles_x,
                seg_begin: seg * self.seg_len,
                seg_len: self.seg_len,
                first: (seg == 0) as u32,
                bg: frame.background,
            };
            s.dispatch(
                &self.blend,
                &[
                    ("proj", &frame.proj),
                    ("isect_ids", &frame.isect_ids),
                    ("ranges", &frame.ranges),
                    ("color", &frame.color),
                    ("last", &frame.last),
                    ("grad_color", dl_dcolor),
                    ("state", state),
                    ("grad2d", &grads.grad2d),
                ],
                bytemuck::bytes_of(&push),
                groups_for(frame.tiles_x * frame.tiles_y),
            )?;
        }
        let push = ProjectBackwardPush {
            cam: CameraData::new(cam),
            n: g.n,
            sh_degree: g.sh_degree,
            pad: [0; 2],
        };
        s.dispatch(
            &self.project,
            &[
                ("means", &g.means),
                ("scales", &g.scales),
                ("rotations", &g.rotations),
                ("opacities", &g.opacities),
                ("sh", &g.sh),
                ("proj", &frame.proj),
                ("grad2d", &grads.grad2d),
                ("grad_means", &grads.means),
                ("grad_scales", &grads.scales),
                ("grad_rotations", &grads.rotations),
                ("grad_opacities", &grads.opacities),
                ("grad_sh", &grads.sh),
                ("stats", &grads.stats),
            ],
            bytemuck::bytes_of(&push),
            groups_for(g.n.div_ceil(WG)),
        )?;
        Ok(())
    }

    /// Runs the backward of `frame` for the colour gradient `dl_dcolor` (`[f32; 4]` per pixel),
    /// adding to `grads`; returns the GPU timings (empty unless [`Backward::set_timed`]).
    pub fn run(
        &self,
        ctx: &Context,
        frame: &Frame,
        g: &GpuGaussians,
        cam: &Camera,
        dl_dcolor: &Buffer,
        grads: &GpuGrads,
    ) -> Result<Timings> {
        let np = frame.width as u64 * frame.height as u64;
        let state = Buffer::new(ctx, "backward pixel state", np * 16, BufferUsage::Device)?;
        let mut s = if self.timed {
            Stream::timed(ctx, 64)?
        } else {
            Stream::new(ctx)?
        };
        self.record(&mut s, frame, g, cam, dl_dcolor, grads, &state)?;
        s.submit()
    }
}
