//! Guided optimisation: the trainer driven by targets that change every iteration (the
//! generators' image targets from a diffusion prior), a batch of views per Adam step, plus the
//! operations the generators add to the fit: raising the SH degree, pruning by a mask and
//! freezing part of the cloud.
use super::backward::GpuGrads;
use super::cloud::{sh_coeffs, Gaussians};
use super::raster::{Frame, GpuGaussians, Rasterizer};
use super::train::{FitConfig, Trainer};
use super::{adam::Adam, adam::AdamConfig, adam::AdamState, backward::Backward};
use crate::camera::Camera;
use crate::gpu::{kernels, Buffer, BufferUsage, Context, GpuError, Result, Stream, Timings};
use rand::SeedableRng;

/// One rendered view of a batch, kept on the device until its gradient is applied.
pub struct BatchView {
    pub camera: Camera,
    pub frame: Frame,
    /// The render read back (colour over the view's background), row-major.
    pub color: Vec<[f32; 3]>,
}

fn bad(msg: String) -> GpuError {
    GpuError::Kernel {
        kernel: "guided step".into(),
        msg,
    }
}

impl Trainer {
    /// A trainer with no fixed views: each step takes rendered views and their loss gradients
    /// ([`Trainer::render_view`], [`Trainer::apply`]). `extent` scales the means' learning rate
    /// and the densification thresholds, as the camera extent does in a fit.
    pub fn guided(
        ctx: &Context,
        init: &Gaussians,
        config: FitConfig,
        extent: f64,
    ) -> Result<Trainer> {
        let limit = ctx.info().max_storage_buffer_range;
        super::view::check_trainable(init.len(), init.sh_degree, limit)?;
        let gaussians = GpuGaussians::upload(ctx, init)?;
        let grads = GpuGrads::new(ctx, gaussians.n, gaussians.sh_degree)?;
        let state = AdamState::new(ctx, &gaussians)?;
        Ok(Trainer {
            ctx: ctx.clone(),
            raster: Rasterizer::new(ctx)?,
            backward: Backward::new(ctx, false)?,
            adam: Adam::new(ctx, AdamConfig::default())?,
            rng: rand_chacha::ChaCha8Rng::seed_from_u64(config.seed),
            config,
            views: vec![],
            gaussians,
            grads,
            state,
            extent: extent.max(1e-6),
            iteration: 0,
            order: vec![],
            scratch: None,
            batch_scratch: vec![],
            batch_pixels: 0,
            trainable: None,
            frames: vec![],
            padded: vec![],
            timed: false,
        })
    }

    /// The device context the trainer runs on.
    pub fn context(&self) -> &Context {
        &self.ctx
    }

    /// The Gaussians on the device (for scoring or rendering by other kernels).
    pub fn device_gaussians(&self) -> &GpuGaussians {
        &self.gaussians
    }

    /// Renders the current Gaussians from `camera` over `background` and keeps the frame for
    /// [`Trainer::apply`]. The frame comes from those handed back by [`Trainer::recycle`] when
    /// there is one (no allocation once the sizes settle); the colour comes back in the render's
    /// own submission.
    pub fn render_view(&mut self, camera: &Camera, background: [f32; 3]) -> Result<BatchView> {
        let mut frame = match self.frames.pop() {
            Some(f) => f,
            None => Frame::new(&self.ctx)?,
        };
        self.raster.forward_into(
            &self.ctx,
            &self.gaussians,
            camera,
            background,
            &mut frame,
            true,
        )?;
        let color = frame.colour()?;
        Ok(BatchView {
            camera: camera.clone(),
            frame,
            color,
        })
    }

    /// Takes back the frames of a batch that has been applied, for the next renders.
    pub fn recycle(&mut self, batch: Vec<BatchView>) {
        self.frames.extend(batch.into_iter().map(|v| v.frame));
    }

    /// Records per-dispatch GPU times: the frames of [`Trainer::render_view`] carry their
    /// forward's and [`Trainer::apply`] returns the backward's and Adam's.
    pub fn set_timed(&mut self, timed: bool) {
        self.timed = timed;
        self.raster.set_timed(timed);
        self.backward.set_timed(timed);
    }

    /// One Adam step from a batch: the gradient of the loss with respect to each view's rendered
    /// colour (`grads[i]`, row-major like the render) is carried back through every view, the
    /// parameter gradients summed, Adam applied once; then the densification schedule runs.
    /// Gaussians outside `trainable` (when set) keep their parameters. Returns the GPU times of
    /// the backward passes and Adam (empty unless [`Trainer::set_timed`]).
    pub fn apply(
        &mut self,
        batch: &[BatchView],
        grads: &[Vec<[f32; 3]>],
        trainable: Option<std::ops::Range<u32>>,
    ) -> Result<Timings> {
        if batch.len() != grads.len() || batch.is_empty() {
            return Err(bad(format!(
                "{} views and {} gradients",
                batch.len(),
                grads.len()
            )));
        }
        let np = batch
            .iter()
            .map(|v| v.camera.width as u64 * v.camera.height as u64)
            .max()
            .unwrap_or(0);
        if np > self.batch_pixels || self.batch_scratch.len() < batch.len() {
            let pixels = np.max(self.batch_pixels);
            self.batch_scratch.clear();
            for _ in 0..batch.len() {
                self.batch_scratch.push((
                    Buffer::new(
                        &self.ctx,
                        "colour gradient",
                        pixels * 16,
                        BufferUsage::Upload,
                    )?,
                    Buffer::new(
                        &self.ctx,
                        "backward pixel state",
                        pixels * 16,
                        BufferUsage::Device,
                    )?,
                ));
            }
            self.batch_pixels = pixels;
        }
        for ((v, g), (dl, _)) in batch.iter().zip(grads).zip(&self.batch_scratch) {
            let want = (v.camera.width * v.camera.height) as usize;
            if g.len() != want || v.frame.n != self.gaussians.n {
                return Err(bad(format!(
                    "view {}: gradient of {} pixels for {want}, or rendered from another cloud",
                    v.camera.img_name,
                    g.len()
                )));
            }
            // The backward reads one `vec4` per pixel (rgb used), as the fit's loss writes it.
            self.padded.clear();
            self.padded
                .extend(g.iter().map(|c| [c[0], c[1], c[2], 0.0]));
            dl.write(&self.padded)?;
        }
        let lr = self.learning_rates();
        let mut s = if self.timed {
            // Room for every dispatch: each view's blend segments, its projection backward,
            // and Adam's arrays.
            let per_view: u32 = batch
                .iter()
                .map(|v| v.frame.max_tile_len.div_ceil(kernels::SEGMENT) + 8)
                .sum();
            Stream::timed(&self.ctx, per_view + 32)?
        } else {
            Stream::new(&self.ctx)?
        };
        for (v, (dl, state)) in batch.iter().zip(&self.batch_scratch) {
            self.backward.record(
                &mut s,
                &v.frame,
                &self.gaussians,
                &v.camera,
                dl,
                &self.grads,
                state,
            )?;
        }
        if let Some(r) = trainable.or_else(|| self.trainable.clone()) {
            self.zero_outside(&mut s, r);
        }
        self.adam
            .record(&mut s, &self.gaussians, &self.grads, &mut self.state, &lr)?;
        let timings = s.submit()?;
        self.iteration += 1;
        self.after_step()?;
        Ok(timings)
    }

    /// Clears the parameter gradients of Gaussians outside `keep` so that Adam leaves them
    /// (their moments stay zero as long as they are never trained).
    pub(super) fn zero_outside(&self, s: &mut Stream, keep: std::ops::Range<u32>) {
        let n = self.gaussians.n;
        let k3 = sh_coeffs(self.gaussians.sh_degree) as u64 * 3;
        let arrays: [(&Buffer, u64); 5] = [
            (&self.grads.means, 3),
            (&self.grads.scales, 3),
            (&self.grads.rotations, 4),
            (&self.grads.opacities, 1),
            (&self.grads.sh, k3),
        ];
        for (b, stride) in arrays {
            let w = stride * 4;
            if keep.start > 0 {
                s.fill_region(b, 0, keep.start as u64 * w, 0);
            }
            if keep.end < n {
                s.fill_region(b, keep.end as u64 * w, (n - keep.end) as u64 * w, 0);
            }
        }
    }

    /// Sets the current iteration (the generators drive their own schedules).
    pub fn set_iteration(&mut self, iteration: u32) {
        self.iteration = iteration;
    }

    /// Raises (or lowers) the SH degree: new coefficients start at zero with zero moments;
    /// lowering drops the higher bands.
    pub fn set_sh_degree(&mut self, degree: u32) -> Result<()> {
        let old = self.gaussians.sh_degree;
        if degree == old {
            return Ok(());
        }
        if degree > 3 {
            return Err(bad(format!("SH degree {degree} (0 to 3 supported)")));
        }
        let g = self.gaussians.download()?;
        let n = g.len();
        let (ko, kn) = (sh_coeffs(old) * 3, sh_coeffs(degree) * 3);
        let resize = |v: &[f32]| -> Vec<f32> {
            let mut out = vec![0.0f32; n * kn];
            for i in 0..n {
                let m = ko.min(kn);
                out[i * kn..i * kn + m].copy_from_slice(&v[i * ko..i * ko + m]);
            }
            out
        };
        let m1: Vec<f32> = self.state.sh.m1.read(n * ko)?;
        let m2: Vec<f32> = self.state.sh.m2.read(n * ko)?;
        let mut ng = g.clone();
        ng.sh = resize(&g.sh);
        ng.sh_degree = degree;
        self.gaussians = GpuGaussians::upload(&self.ctx, &ng)?;
        self.state.sh.m1 = Buffer::from_slice(&self.ctx, "sh adam m1", &resize(&m1))?;
        self.state.sh.m2 = Buffer::from_slice(&self.ctx, "sh adam m2", &resize(&m2))?;
        self.grads = GpuGrads::new(&self.ctx, n as u32, degree)?;
        Ok(())
    }

    /// Keeps only the Gaussians where `keep` is true, with their Adam moments.
    pub fn retain(&mut self, keep: &[bool]) -> Result<()> {
        let g = self.gaussians.download()?;
        if keep.len() != g.len() {
            return Err(bad(format!(
                "mask of {} for {} Gaussians",
                keep.len(),
                g.len()
            )));
        }
        let k3 = g.coeffs() * 3;
        let mut out = Gaussians {
            sh_degree: g.sh_degree,
            ..Default::default()
        };
        let mut src = vec![];
        for (i, _) in keep.iter().enumerate().filter(|(_, k)| **k) {
            out.means.push(g.means[i]);
            out.scales.push(g.scales[i]);
            out.rotations.push(g.rotations[i]);
            out.opacities.push(g.opacities[i]);
            out.sh.extend_from_slice(&g.sh[i * k3..(i + 1) * k3]);
            src.push(Some(i));
        }
        self.rebuild(&out, &src)
    }

    /// Replaces the parameters by `g` (same count and degree), keeping the optimiser state.
    pub fn set_gaussians(&mut self, g: &Gaussians) -> Result<()> {
        if g.len() != self.gaussians.n as usize || g.sh_degree != self.gaussians.sh_degree {
            return Err(bad(format!(
                "{} Gaussians of degree {} for a trainer of {} of degree {}",
                g.len(),
                g.sh_degree,
                self.gaussians.n,
                self.gaussians.sh_degree
            )));
        }
        self.gaussians = GpuGaussians::upload(&self.ctx, g)?;
        Ok(())
    }
}
