//! Fitting Gaussians to posed images: the 3DGS optimisation loop on the GPU engine (forward,
//! host loss, backward, fused Adam) with densification and pruning on the host between steps.
//! The generator's reconstructive stage and `dreamscene fit` both run it.
use super::adam::{Adam, AdamState, LearningRates, Moments};
use super::backward::{Backward, GpuGrads};
use super::cloud::{sh_coeffs, Gaussians, SH_C0};
use super::loss;
use super::raster::{Frame, GpuGaussians, Rasterizer};
use crate::camera::Camera;
use crate::gpu::{Buffer, BufferUsage, Context, GpuError, Result, Stream};
use glam::{DMat3, DVec3};
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};

/// Optimisation settings. Defaults are those of 3DGS, with the densification schedule expressed
/// as fractions of the run so that short runs keep its shape (30,000 iterations: densify every
/// 100 from 500 to 15,000, opacity reset every 3,000).
#[derive(Debug, Clone)]
pub struct FitConfig {
    pub iterations: u32,
    /// Weight of D-SSIM in the loss.
    pub lambda_dssim: f64,
    pub background: [f32; 3],
    /// Initial and final learning rate of the means, times the scene extent.
    pub lr_means: (f32, f32),
    pub lr_scales: f32,
    pub lr_rotations: f32,
    pub lr_opacities: f32,
    pub lr_sh: f32,
    /// Densify and prune at all.
    pub densify: bool,
    /// Fraction of the run after which densification starts.
    pub densify_from: f64,
    /// Fraction of the run after which it stops.
    pub densify_until: f64,
    pub densify_every: u32,
    /// Opacity reset period, as a fraction of the run (0 disables).
    pub opacity_reset: f64,
    /// Final learning rates of SH, log-scales and rotations (log-linear decay from the initial
    /// ones, as the generators' configs schedule them); `None` keeps a rate constant.
    pub lr_sh_final: Option<f32>,
    pub lr_scales_final: Option<f32>,
    pub lr_rotations_final: Option<f32>,
    /// Mean NDC centre-gradient norm above which a Gaussian is cloned or split.
    pub grad_threshold: f32,
    /// Gaussians larger than this fraction of the extent are split, smaller ones cloned.
    pub percent_dense: f32,
    pub min_opacity: f32,
    /// Densification stops adding Gaussians beyond this count.
    pub max_gaussians: usize,
    pub seed: u64,
}

impl Default for FitConfig {
    fn default() -> Self {
        FitConfig {
            iterations: 7000,
            lambda_dssim: 0.2,
            background: [0.0; 3],
            lr_means: (0.000_16, 0.000_001_6),
            lr_scales: 0.005,
            lr_rotations: 0.001,
            lr_opacities: 0.05,
            lr_sh: 0.0025,
            densify: true,
            densify_from: 500.0 / 30_000.0,
            densify_until: 0.5,
            densify_every: 100,
            opacity_reset: 0.1,
            lr_sh_final: None,
            lr_scales_final: None,
            lr_rotations_final: None,
            grad_threshold: 0.0002,
            percent_dense: 0.01,
            min_opacity: 0.005,
            max_gaussians: 3_000_000,
            seed: 0,
        }
    }
}

#[derive(Debug, Clone)]
/// A posed training image.
pub struct View {
    pub camera: Camera,
    /// Row-major RGB in [0, 1], `camera.width x camera.height` pixels.
    pub pixels: Vec<[f32; 3]>,
}

/// What one step did.
#[derive(Debug, Clone, Copy)]
pub struct StepReport {
    pub iteration: u32,
    pub loss: f64,
    pub psnr: f64,
    pub gaussians: usize,
}

/// Centre and radius of the camera positions (3DGS's "cameras extent": 1.1 x the largest
/// distance from their mean, at least a small positive value).
pub fn camera_extent(cams: &[Camera]) -> (DVec3, f64) {
    let n = cams.len().max(1) as f64;
    let c = cams
        .iter()
        .fold(DVec3::ZERO, |a, cam| a + DVec3::from(cam.position))
        / n;
    let r = cams
        .iter()
        .map(|cam| (DVec3::from(cam.position) - c).length())
        .fold(0.0, f64::max);
    (c, (1.1 * r).max(1e-3))
}

/// The region the cameras look at: the point nearest to all optical axes (least squares), and
/// the half-size of the median view at that point's distance.
pub fn look_region(cams: &[Camera]) -> (DVec3, f64) {
    let mut a = DMat3::ZERO;
    let mut b = DVec3::ZERO;
    for cam in cams {
        let r = cam.rotation;
        let d = DVec3::new(r[0][2], r[1][2], r[2][2]).normalize();
        let p = DMat3::IDENTITY - DMat3::from_cols(d * d.x, d * d.y, d * d.z);
        a += p;
        b += p * DVec3::from(cam.position);
    }
    let centre = if a.determinant().abs() > 1e-9 {
        a.inverse() * b
    } else {
        // Parallel axes: a point in front of the mean camera.
        let (c, ext) = camera_extent(cams);
        let r = cams[0].rotation;
        c + DVec3::new(r[0][2], r[1][2], r[2][2]) * ext
    };
    let mut half: Vec<f64> = cams
        .iter()
        .map(|cam| {
            let dist = (DVec3::from(cam.position) - centre).length();
            let tan_x = 0.5 * cam.width as f64 / cam.fx;
            let tan_y = 0.5 * cam.height as f64 / cam.fy;
            dist * tan_x.min(tan_y)
        })
        .collect();
    half.sort_by(f64::total_cmp);
    (centre, half[half.len() / 2].max(1e-3))
}

/// `n` random Gaussians filling the ball the cameras look at: random colours, opacity 0.1,
/// isotropic scales about the mean spacing, identity rotations.
pub fn random_init(cams: &[Camera], n: usize, sh_degree: u32, seed: u64) -> Gaussians {
    let (centre, radius) = look_region(cams);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let k = sh_coeffs(sh_degree);
    let spacing = radius * (4.0 / 3.0 * std::f64::consts::PI / n.max(1) as f64).cbrt();
    let mut g = Gaussians {
        sh_degree,
        ..Default::default()
    };
    while g.len() < n {
        let p = DVec3::new(
            rng.gen_range(-1.0..1.0),
            rng.gen_range(-1.0..1.0),
            rng.gen_range(-1.0..1.0),
        );
        if p.length_squared() > 1.0 {
            continue;
        }
        let m = centre + p * radius;
        g.means.push([m.x as f32, m.y as f32, m.z as f32]);
        g.scales.push([(0.5 * spacing).ln() as f32; 3]);
        g.rotations.push([1.0, 0.0, 0.0, 0.0]);
        g.opacities.push((0.1f32 / 0.9).ln());
        for c in 0..k {
            for _ in 0..3 {
                let v: f64 = rng.gen_range(0.0..1.0);
                g.sh.push(if c == 0 {
                    ((v - 0.5) / SH_C0) as f32
                } else {
                    0.0
                });
            }
        }
    }
    g
}

/// Per-Gaussian rows of a flat array with `stride` values each, gathered by `src` (None: zeros).
fn gather(v: &[f32], stride: usize, src: &[Option<usize>]) -> Vec<f32> {
    let mut out = Vec::with_capacity(src.len() * stride);
    for s in src {
        match s {
            Some(i) => out.extend_from_slice(&v[i * stride..(i + 1) * stride]),
            None => out.extend(std::iter::repeat_n(0.0, stride)),
        }
    }
    out
}

fn sigmoid(x: f32) -> f32 {
    1.0 / (1.0 + (-x).exp())
}

/// The optimisation state of one fit.
pub struct Trainer {
    pub(super) ctx: Context,
    pub(super) raster: Rasterizer,
    pub(super) backward: Backward,
    pub(super) adam: Adam,
    pub config: FitConfig,
    pub(super) views: Vec<View>,
    pub(super) gaussians: GpuGaussians,
    pub(super) grads: GpuGrads,
    pub(super) state: AdamState,
    pub(super) extent: f64,
    pub(super) iteration: u32,
    pub(super) order: Vec<usize>,
    pub(super) rng: rand_chacha::ChaCha8Rng,
    /// Per-view scratch reused between steps: (pixels, colour gradient, backward state).
    pub(super) scratch: Option<(u64, Buffer, Buffer)>,
    /// Per-view scratch of guided batches (colour gradient, backward state), `batch_pixels` each.
    pub(super) batch_scratch: Vec<(Buffer, Buffer)>,
    pub(super) batch_pixels: u64,
    /// Only Gaussians in this index range are optimised (the rest keep their parameters).
    pub trainable: Option<std::ops::Range<u32>>,
    /// Frames of earlier guided batches, rendered into again by [`Trainer::render_view`].
    pub(super) frames: Vec<Frame>,
    /// A guided view's colour gradient padded to the backward's `vec4` per pixel.
    pub(super) padded: Vec<[f32; 4]>,
    /// Whether guided steps record per-dispatch GPU times.
    pub(super) timed: bool,
}

impl Trainer {
    /// Starts a fit of `init` to `views`.
    pub fn new(
        ctx: &Context,
        init: &Gaussians,
        views: Vec<View>,
        config: FitConfig,
    ) -> Result<Trainer> {
        if views.is_empty() {
            return Err(GpuError::Kernel {
                kernel: "fit".into(),
                msg: "no training views".into(),
            });
        }
        for v in &views {
            if v.pixels.len() != (v.camera.width * v.camera.height) as usize {
                return Err(GpuError::Kernel {
                    kernel: "fit".into(),
                    msg: format!(
                        "view {}: {} pixels for a {}x{} camera",
                        v.camera.img_name,
                        v.pixels.len(),
                        v.camera.width,
                        v.camera.height
                    ),
                });
            }
        }
        let cams: Vec<Camera> = views.iter().map(|v| v.camera.clone()).collect();
        let (_, extent) = camera_extent(&cams);
        let mut t = Trainer::guided(ctx, init, config, extent)?;
        t.views = views;
        Ok(t)
    }

    /// Iterations done so far.
    pub fn iteration(&self) -> u32 {
        self.iteration
    }

    /// The scene extent used for learning rates and densification.
    pub fn extent(&self) -> f64 {
        self.extent
    }

    /// Number of Gaussians now.
    pub fn len(&self) -> usize {
        self.gaussians.n as usize
    }

    /// True when there are no Gaussians.
    pub fn is_empty(&self) -> bool {
        self.gaussians.n == 0
    }

    /// The current Gaussians.
    pub fn gaussians(&self) -> Result<Gaussians> {
        self.gaussians.download()
    }

    /// The learning rates at the current iteration (means decay log-linearly).
    pub fn learning_rates(&self) -> LearningRates {
        let c = &self.config;
        let t = (self.iteration as f64 / c.iterations.max(1) as f64).clamp(0.0, 1.0);
        let decay = |a: f32, b: Option<f32>| -> f32 {
            let b = b.unwrap_or(a) as f64;
            ((a as f64).ln() * (1.0 - t) + b.ln() * t).exp() as f32
        };
        let means = decay(c.lr_means.0, Some(c.lr_means.1)) as f64 * self.extent;
        let sh = decay(c.lr_sh, c.lr_sh_final);
        LearningRates {
            means: means as f32,
            scales: decay(c.lr_scales, c.lr_scales_final),
            rotations: decay(c.lr_rotations, c.lr_rotations_final),
            opacities: c.lr_opacities,
            sh_dc: sh,
            sh_rest: c.lr_sh / 20.0,
        }
    }

    /// Renders the current Gaussians from `cam` (colour over the configured background).
    pub fn render(&self, cam: &Camera) -> Result<Vec<[f32; 3]>> {
        Ok(self
            .raster
            .forward(&self.ctx, &self.gaussians, cam, self.config.background)?
            .read()?
            .color)
    }

    fn next_view(&mut self) -> usize {
        if self.order.is_empty() {
            self.order = (0..self.views.len()).collect();
            self.order.shuffle(&mut self.rng);
        }
        self.order.pop().expect("refilled")
    }

    /// One optimisation step on the next view (views are visited in a random order per epoch),
    /// then densification, pruning and opacity reset when the schedule says.
    pub fn step(&mut self) -> Result<StepReport> {
        if self.views.is_empty() {
            return Err(GpuError::Kernel {
                kernel: "fit".into(),
                msg: "no training views (a guided trainer takes its targets per batch)".into(),
            });
        }
        let vi = self.next_view();
        let cam = self.views[vi].camera.clone();
        let np = cam.width as u64 * cam.height as u64;
        let frame =
            self.raster
                .forward(&self.ctx, &self.gaussians, &cam, self.config.background)?;
        let out = frame.read()?;
        let target = &self.views[vi].pixels;
        let (w, h) = (cam.width as usize, cam.height as usize);
        let (loss, dl) = loss::l1_dssim(&out.color, target, w, h, self.config.lambda_dssim);
        let psnr = loss::psnr(&out.color, target);
        if self.scratch.as_ref().is_none_or(|s| s.0 < np) {
            self.scratch = Some((
                np,
                Buffer::new(&self.ctx, "colour gradient", np * 16, BufferUsage::Upload)?,
                Buffer::new(
                    &self.ctx,
                    "backward pixel state",
                    np * 16,
                    BufferUsage::Device,
                )?,
            ));
        }
        let (_, dlb, state) = self.scratch.as_ref().expect("allocated");
        dlb.write(&dl)?;
        let lr = self.learning_rates();
        let mut s = Stream::new(&self.ctx)?;
        self.backward.record(
            &mut s,
            &frame,
            &self.gaussians,
            &cam,
            dlb,
            &self.grads,
            state,
        )?;
        if let Some(r) = self.trainable.clone() {
            self.zero_outside(&mut s, r);
        }
        self.adam
            .record(&mut s, &self.gaussians, &self.grads, &mut self.state, &lr)?;
        s.submit()?;
        drop(frame);
        self.iteration += 1;
        self.after_step()?;
        Ok(StepReport {
            iteration: self.iteration,
            loss,
            psnr,
            gaussians: self.len(),
        })
    }

    /// Densification, pruning and opacity reset when the schedule says, after a step.
    pub(super) fn after_step(&mut self) -> Result<()> {
        let c = &self.config;
        let it = self.iteration;
        let total = c.iterations as f64;
        let from = (c.densify_from * total) as u32;
        let until = (c.densify_until * total) as u32;
        let reset_every = (c.opacity_reset * total) as u32;
        if c.densify && it < until {
            if it > from && it.is_multiple_of(c.densify_every.max(1)) {
                let prune_big = reset_every > 0 && it > reset_every;
                self.densify_and_prune(prune_big)?;
            }
            if reset_every > 0 && it.is_multiple_of(reset_every) {
                self.reset_opacity()?;
            }
        }
        Ok(())
    }

    /// Clones small Gaussians and splits large ones whose mean NDC centre gradient exceeds the
    /// threshold; prunes transparent ones (and, after the first opacity reset, those too large
    /// on screen or in the world). Adam moments follow their Gaussians; new ones start at zero.
    #[allow(
        clippy::needless_range_loop,
        reason = "one index walks several parallel arrays"
    )]
    pub fn densify_and_prune(&mut self, prune_big: bool) -> Result<()> {
        let c = self.config.clone();
        let g = self.gaussians.download()?;
        let n = g.len();
        let stats: Vec<[f32; 4]> = self.grads.stats.read(n)?;
        let ext = self.extent as f32;
        let k3 = g.coeffs() * 3;
        let mut out = Gaussians {
            sh_degree: g.sh_degree,
            ..Default::default()
        };
        let mut src: Vec<Option<usize>> = vec![];
        let mut room = c.max_gaussians.saturating_sub(n);
        let normal = |rng: &mut rand_chacha::ChaCha8Rng| -> f64 {
            // Box-Muller
            let u1: f64 = rng.gen_range(f64::EPSILON..1.0);
            let u2: f64 = rng.gen_range(0.0..1.0);
            (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
        };
        let push = |out: &mut Gaussians,
                    src: &mut Vec<Option<usize>>,
                    i: usize,
                    m: [f32; 3],
                    s: [f32; 3],
                    from: Option<usize>| {
            out.means.push(m);
            out.scales.push(s);
            out.rotations.push(g.rotations[i]);
            out.opacities.push(g.opacities[i]);
            out.sh.extend_from_slice(&g.sh[i * k3..(i + 1) * k3]);
            src.push(from);
        };
        for i in 0..n {
            let st = stats[i];
            let grad = if st[1] > 0.0 { st[0] / st[1] } else { 0.0 };
            let smax = g.scales[i].iter().fold(f32::MIN, |a, &b| a.max(b)).exp();
            let transparent = sigmoid(g.opacities[i]) < c.min_opacity;
            let big_world = prune_big && smax > 0.1 * ext;
            let big_screen = prune_big && st[2] > 20.0;
            let dense = grad >= c.grad_threshold && !transparent && room > 0;
            if dense && smax > c.percent_dense * ext {
                // split into two samples of the Gaussian, 1.6 times smaller
                let q = g.rotations[i].map(f64::from);
                let rot = super::reference::quat_to_mat(q);
                let s = g.scales[i].map(|v| (v as f64).exp());
                let new_scale = g.scales[i].map(|v| v - (1.6f32).ln());
                for _ in 0..2 {
                    let z = [0, 1, 2].map(|a| normal(&mut self.rng) * s[a]);
                    let off = match rot {
                        Some(r) => {
                            [0, 1, 2].map(|a| r[a][0] * z[0] + r[a][1] * z[1] + r[a][2] * z[2])
                        }
                        None => z,
                    };
                    let m = [0, 1, 2].map(|a| g.means[i][a] + off[a] as f32);
                    push(&mut out, &mut src, i, m, new_scale, None);
                }
                room = room.saturating_sub(1);
                continue;
            }
            if transparent || big_world || big_screen {
                continue;
            }
            push(&mut out, &mut src, i, g.means[i], g.scales[i], Some(i));
            if dense {
                push(&mut out, &mut src, i, g.means[i], g.scales[i], None);
                room -= 1;
            }
        }
        self.rebuild(&out, &src)
    }

    /// Replaces the cloud by `g`, whose Gaussian j continues old Gaussian `src[j]` (its Adam
    /// moments are kept) or is new (zero moments). Densification statistics restart.
    pub(super) fn rebuild(&mut self, g: &Gaussians, src: &[Option<usize>]) -> Result<()> {
        let n_old = self.gaussians.n as usize;
        let k3 = sh_coeffs(g.sh_degree) * 3;
        let ctx = &self.ctx;
        let moved = |m: &Moments, stride: usize, name: &str| -> Result<Moments> {
            let m1: Vec<f32> = m.m1.read(n_old * stride)?;
            let m2: Vec<f32> = m.m2.read(n_old * stride)?;
            let (a, b) = (gather(&m1, stride, src), gather(&m2, stride, src));
            Ok(Moments {
                m1: Buffer::from_slice(ctx, &format!("{name} adam m1"), &a)?,
                m2: Buffer::from_slice(ctx, &format!("{name} adam m2"), &b)?,
            })
        };
        let state = AdamState {
            means: moved(&self.state.means, 3, "means")?,
            scales: moved(&self.state.scales, 3, "scales")?,
            rotations: moved(&self.state.rotations, 4, "rotations")?,
            opacities: moved(&self.state.opacities, 1, "opacities")?,
            sh: moved(&self.state.sh, k3, "sh")?,
            step: self.state.step,
        };
        self.gaussians = GpuGaussians::upload(ctx, g)?;
        self.grads = GpuGrads::new(ctx, g.len() as u32, g.sh_degree)?;
        self.state = state;
        Ok(())
    }

    /// Clamps every opacity to at most 0.01 and clears the opacity moments (3DGS's reset).
    pub fn reset_opacity(&mut self) -> Result<()> {
        let n = self.gaussians.n as usize;
        let mut o: Vec<f32> = self.gaussians.opacities.read(n)?;
        let cap = (0.01f32 / 0.99).ln();
        for v in &mut o {
            *v = v.min(cap);
        }
        self.gaussians.opacities.write(&o)?;
        let mut s = Stream::new(&self.ctx)?;
        s.fill(&self.state.opacities.m1, 0);
        s.fill(&self.state.opacities.m2, 0);
        s.submit()?;
        Ok(())
    }
}

/// Loads the training image of every camera from `dir`: `<img_name>`, or `<img_name>` with a
/// `.png`, `.jpg` or `.jpeg` extension. Transparent pixels are composited over `background`.
/// Errors name the file and what is wrong (missing, unreadable, size differs from the camera's).
pub fn load_views(
    dir: &std::path::Path,
    cams: &[Camera],
    background: [f32; 3],
) -> std::result::Result<Vec<View>, String> {
    let mut views = Vec::with_capacity(cams.len());
    for cam in cams {
        let path = find_image(dir, &cam.img_name).ok_or_else(|| {
            format!(
                "{}: no image for camera {} (looked for {}, .png, .jpg, .jpeg in any case)",
                dir.display(),
                cam.id,
                cam.img_name
            )
        })?;
        let path = &path;
        let img = image::open(path)
            .map_err(|e| format!("{}: {e}", path.display()))?
            .to_rgba32f();
        if img.width() != cam.width || img.height() != cam.height {
            return Err(format!(
                "{}: image is {}x{} but camera {} is {}x{}",
                path.display(),
                img.width(),
                img.height(),
                cam.id,
                cam.width,
                cam.height
            ));
        }
        let pixels = img
            .pixels()
            .map(|p| {
                let a = p[3];
                [0, 1, 2].map(|c| p[c] * a + background[c] * (1.0 - a))
            })
            .collect();
        views.push(View {
            camera: cam.clone(),
            pixels,
        });
    }
    Ok(views)
}

/// The image file of `img_name` in `dir`: the name itself, or the name with a `.png`, `.jpg` or
/// `.jpeg` extension in any letter case (`.PNG`, `.JPG` as cameras write them); the first in
/// name order when several match.
fn find_image(dir: &std::path::Path, img_name: &str) -> Option<std::path::PathBuf> {
    let exact = dir.join(img_name);
    if exact.is_file() {
        return Some(exact);
    }
    let parent = exact.parent()?;
    let stem = exact.file_name()?.to_str()?;
    let mut found: Vec<std::path::PathBuf> = std::fs::read_dir(parent)
        .ok()?
        .filter_map(|e| e.ok())
        .filter(|e| {
            let name = e.file_name();
            let Some(name) = name.to_str() else {
                return false;
            };
            name.rsplit_once('.').is_some_and(|(s, ext)| {
                s == stem && ["png", "jpg", "jpeg"].contains(&ext.to_ascii_lowercase().as_str())
            })
        })
        .map(|e| e.path())
        .filter(|p| p.is_file())
        .collect();
    found.sort();
    found.into_iter().next()
}

/// Magic and version of the optimiser-state file written beside a fit's PLY.
const STATE_MAGIC: &[u8; 8] = b"DSFIT\x00\x03\x00";

/// FNV-1a over the Gaussians' means and opacities: ties a state file to the PLY written with it.
fn fingerprint(g: &Gaussians) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let bytes = bytemuck::cast_slice::<[f32; 3], u8>(&g.means)
        .iter()
        .chain(bytemuck::cast_slice::<f32, u8>(&g.opacities));
    for b in bytes {
        h = (h ^ *b as u64).wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

impl Trainer {
    /// Writes the optimiser state (iteration, Adam step and both moments of every parameter
    /// group) to `path`, atomically (a temporary file renamed into place). With the PLY written
    /// at the same iteration it lets [`Trainer::restore`] continue the fit where it stopped.
    pub fn save_state(&self, path: &std::path::Path) -> std::io::Result<()> {
        let mut buf: Vec<u8> = STATE_MAGIC.to_vec();
        for v in [
            self.iteration,
            self.state.step,
            self.gaussians.n,
            self.gaussians.sh_degree,
        ] {
            buf.extend_from_slice(&v.to_le_bytes());
        }
        let io = |e: GpuError| std::io::Error::other(e.to_string());
        buf.extend_from_slice(&fingerprint(&self.gaussians().map_err(io)?).to_le_bytes());
        // The view order: the generator's position and the rest of this epoch.
        buf.extend_from_slice(&self.rng.get_word_pos().to_le_bytes());
        buf.extend_from_slice(&(self.order.len() as u32).to_le_bytes());
        for &v in &self.order {
            buf.extend_from_slice(&(v as u32).to_le_bytes());
        }
        for m in self.moments() {
            for b in [&m.m1, &m.m2] {
                let v: Vec<f32> = b.read_all().map_err(io)?;
                buf.extend_from_slice(&(v.len() as u64).to_le_bytes());
                buf.extend_from_slice(bytemuck::cast_slice(&v));
            }
        }
        // The run's length: its schedules are fractions of it, so a resume must keep it.
        buf.extend_from_slice(&self.config.iterations.to_le_bytes());
        crate::util::write_atomic(path, &buf)
    }

    fn moments(&self) -> [&Moments; 5] {
        [
            &self.state.means,
            &self.state.scales,
            &self.state.rotations,
            &self.state.opacities,
            &self.state.sh,
        ]
    }

    /// Restores a state written by [`Trainer::save_state`] for the Gaussians this trainer was
    /// started with (and the same seed and views): the iteration, Adam and the view order continue
    /// exactly; densification statistics restart.
    pub fn restore(&mut self, path: &std::path::Path) -> std::result::Result<(), String> {
        let shown = path.display();
        let data = std::fs::read(path).map_err(|e| format!("{shown}: {e}"))?;
        if data.len() < 32 || &data[..8] != STATE_MAGIC {
            let older = data.len() >= 8 && data[..5] == STATE_MAGIC[..5];
            return Err(format!(
                "{shown}: not a dreamscene fit state of this version ({})",
                if older {
                    "written by another version"
                } else {
                    "bad header"
                }
            ));
        }
        let word = |i: usize| {
            u32::from_le_bytes(
                data[8 + 4 * i..12 + 4 * i]
                    .try_into()
                    .expect("a 4-byte slice"),
            )
        };
        let (iteration, step, n, sh) = (word(0), word(1), word(2), word(3));
        if n != self.gaussians.n || sh != self.gaussians.sh_degree {
            return Err(format!(
                "{shown}: state is for {n} Gaussians at SH degree {sh}, the model has {} at degree \
                 {} (was the PLY written at another iteration?)",
                self.gaussians.n, self.gaussians.sh_degree
            ));
        }
        let stored = u64::from_le_bytes(data[24..32].try_into().expect("an 8-byte slice"));
        let g = self.gaussians().map_err(|e| format!("{shown}: {e}"))?;
        if stored != fingerprint(&g) {
            return Err(format!(
                "{shown}: the state was written with another model than the PLY being resumed \
                 (interrupted between the two writes?); restart, or continue with --init"
            ));
        }
        let mut at = 32usize;
        let mut take = |len: usize| -> std::result::Result<&[u8], String> {
            let b = data
                .get(at..at + len)
                .ok_or_else(|| format!("{shown}: truncated"))?;
            at += len;
            Ok(b)
        };
        let word_pos = u128::from_le_bytes(take(16)?.try_into().expect("take gives 16 bytes"));
        let n_order = u32::from_le_bytes(take(4)?.try_into().expect("take gives 4 bytes")) as usize;
        if n_order > self.views.len() {
            return Err(format!(
                "{shown}: {n_order} pending views, the fit has {}",
                self.views.len()
            ));
        }
        let order: Vec<usize> = bytemuck::pod_collect_to_vec::<u8, u32>(take(4 * n_order)?)
            .into_iter()
            .map(|v| v as usize)
            .collect();
        if order.iter().any(|v| *v >= self.views.len()) {
            return Err(format!("{shown}: a pending view is out of range"));
        }
        let mut arrays: Vec<Vec<f32>> = vec![];
        for _ in 0..10 {
            let len = u64::from_le_bytes(take(8)?.try_into().expect("take gives 8 bytes")) as usize;
            if len > (data.len() / 4) {
                return Err(format!("{shown}: truncated"));
            }
            arrays.push(bytemuck::pod_collect_to_vec(take(len * 4)?));
        }
        let total = u32::from_le_bytes(take(4)?.try_into().expect("take gives 4 bytes"));
        if total != self.config.iterations {
            return Err(format!(
                "{shown}: the interrupted fit was for {total} iterations, this one asks for {}; \
                 --resume continues with the same --iterations (the learning-rate and \
                 densification schedules are fractions of the run). To train further, start a \
                 new fit with --init and the PLY",
                self.config.iterations
            ));
        }
        if at != data.len() {
            return Err(format!(
                "{shown}: {} unexpected trailing bytes",
                data.len() - at
            ));
        }
        let mut it = arrays.into_iter();
        for m in self.moments() {
            for b in [&m.m1, &m.m2] {
                let v = it.next().expect("ten arrays");
                if v.len() * 4 != b.size() as usize {
                    return Err(format!(
                        "{shown}: a moment array has {} values, the model needs {}",
                        v.len(),
                        b.size() / 4
                    ));
                }
                b.write(&v).map_err(|e| format!("{shown}: {e}"))?;
            }
        }
        self.state.step = step;
        self.iteration = iteration;
        self.order = order;
        self.rng = rand_chacha::ChaCha8Rng::seed_from_u64(self.config.seed);
        self.rng.set_word_pos(word_pos);
        Ok(())
    }
}
