//! The priors the generators ask for image targets, behind one interface: rendered views (with
//! their cameras, backgrounds and prompt angles) in, an image target per view out, under a
//! [`Guide`] that holds the rule (MTS, pseudo-GT, SDS, ISM, editing), its timestep ranges and
//! its noise.
//!
//! - [`SdPrior`]: Stable Diffusion in ONNX Runtime; view-dependent prompts as the authors' code.
//! - [`OraclePrior`]: a prior that knows the answer. Its latents are the images themselves
//!   (identity codec, `z = 2x − 1`), and its noise prediction for the prompt (and the negative
//!   prompt) is the exact noise toward the render of a reference cloud from the same camera and
//!   background, `ε = (x_t − √ᾱ_t z*) / √(1 − ᾱ_t)`; for the empty prompt it predicts ε = 0 (an
//!   uninformed denoiser that keeps what it sees, as the analytic test model does); for the edit
//!   prompt, the noise toward a second reference. The guidance maths (DDIM inversion chain, the
//!   MTS sum, CFG, pseudo-GT) run unchanged on top, so the whole generator can be checked with a
//!   number: its fixed point is the reference.
//!
//! The `shape` prior has no targets (the object is its shape prior), so it is not a [`Prior`].
use super::object::GenError;
use crate::camera::Camera;
use crate::diffusion::convert::worth_parallel;
use crate::diffusion::guidance::{view_prompts, Cond, NoisePredictor, PerView};
use crate::diffusion::model::{Conditioning, StableDiffusion};
use crate::diffusion::schedule::{Schedule, SchedulerConfig};
use crate::diffusion::target::{Guide, ImageTarget};
use crate::diffusion::Error;
use crate::gpu::Context;
use crate::splat::raster::{Frame, GpuGaussians, Rasterizer};
use crate::splat::Gaussians;
use rayon::prelude::*;
use std::collections::HashMap;
use std::mem::ManuallyDrop;
use std::sync::Mutex;

/// The authors' negative prompt for objects.
pub const NEGATIVE: &str = "oversaturated color, ugly, tiling, low quality, noisy, blurry, out of \
                            focus, low contrast, dull, low-resolution, oversaturation.";

/// One rendered view a prior is asked about.
pub struct PriorView<'a> {
    pub camera: &'a Camera,
    /// The render, row-major, colour over `background`.
    pub render: &'a [[f32; 3]],
    pub background: [f32; 3],
    /// Azimuth (degrees, 0 in front) and elevation (polar − 90°) for view-dependent prompts.
    pub azimuth: f64,
    pub elevation: f64,
}

/// A source of per-view image targets.
pub trait Prior {
    /// What the prior is, for logs and `object.json` (`sd`, `oracle`).
    fn kind(&self) -> &'static str;
    /// The targets of all views of an iteration at training step `step` under `guide`, in
    /// order, each row-major like its render (pseudo-ground truth clamped to [0, 1]). The views
    /// share the iteration's timesteps ([`Guide::latent_targets`]), so a prior runs its model
    /// once per guidance step for all of them.
    fn targets(
        &mut self,
        guide: &mut Guide,
        views: &[PriorView],
        step: u32,
    ) -> Result<Vec<Vec<[f32; 3]>>, GenError>;
    /// The target of one view ([`Prior::targets`] of one).
    fn target(
        &mut self,
        guide: &mut Guide,
        view: &PriorView,
        step: u32,
    ) -> Result<Vec<[f32; 3]>, GenError> {
        self.targets(guide, std::slice::from_ref(view), step)?
            .pop()
            .ok_or_else(|| Error::Run("the prior returned no target".into()).into())
    }
}

fn unflat(v: &[f32]) -> Vec<[f32; 3]> {
    v.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
}

/// Noise predictions of the oracle for one view: the exact noise toward `reference` for the
/// positive and negative prompts, toward `edit` for the edit prompt, zero for the null prompt.
pub(crate) struct OraclePredictor<'a> {
    pub(crate) sched: &'a Schedule,
    pub(crate) reference: &'a [f32],
    pub(crate) edit: Option<&'a [f32]>,
}

impl NoisePredictor for OraclePredictor<'_> {
    fn predict(&mut self, x: &[f32], t: u32, conds: &[Cond]) -> Result<Vec<Vec<f32>>, String> {
        let ab = self.sched.alpha_bar(t as i64);
        let (sa, sn) = (ab.sqrt(), (1.0 - ab).max(1e-12).sqrt());
        let toward = |z: &[f32]| -> Vec<f32> {
            x.iter()
                .zip(z)
                .map(|(xt, zs)| ((*xt as f64 - sa * *zs as f64) / sn) as f32)
                .collect()
        };
        conds
            .iter()
            .map(|c| match c {
                Cond::Positive | Cond::Negative => Ok(toward(self.reference)),
                Cond::Null => Ok(vec![0.0; x.len()]),
                Cond::Edit => self
                    .edit
                    .map(toward)
                    .ok_or_else(|| "the oracle has no edit reference".to_string()),
            })
            .collect()
    }
}

/// The verification prior: knows the reference cloud (and optionally an edit reference).
pub struct OraclePrior {
    ctx: Context,
    raster: Rasterizer,
    reference: GpuGaussians,
    edit: Option<GpuGaussians>,
    sched: Schedule,
    /// The frame the references are rendered into, reused from view to view.
    frame: Mutex<Option<Frame>>,
}

impl OraclePrior {
    pub fn new(
        ctx: &Context,
        reference: &Gaussians,
        edit: Option<&Gaussians>,
    ) -> Result<OraclePrior, GenError> {
        let up = |g: &Gaussians| GpuGaussians::upload(ctx, g);
        Ok(OraclePrior {
            ctx: ctx.clone(),
            raster: Rasterizer::new(ctx)?,
            reference: up(reference)?,
            edit: edit.map(up).transpose()?,
            sched: Schedule::new(SchedulerConfig::sd21_base()).map_err(Error::Run)?,
            frame: Mutex::new(None),
        })
    }

    /// The reference rendered from `cam` over `bg`: what the oracle believes the view shows.
    pub fn reference_view(&self, cam: &Camera, bg: [f32; 3]) -> Result<Vec<[f32; 3]>, GenError> {
        self.render(&self.reference, cam, bg)
    }

    fn render(
        &self,
        g: &GpuGaussians,
        cam: &Camera,
        bg: [f32; 3],
    ) -> Result<Vec<[f32; 3]>, GenError> {
        let mut slot = self.frame.lock().unwrap_or_else(|e| e.into_inner());
        let frame = match slot.as_mut() {
            Some(f) => f,
            None => slot.insert(Frame::new(&self.ctx)?),
        };
        self.raster
            .forward_into(&self.ctx, g, cam, bg, frame, true)?;
        Ok(frame.colour()?)
    }
}

/// `2x − 1`, the oracle's latent of an image.
pub(crate) fn to_latent(img: &[[f32; 3]]) -> Vec<f32> {
    bytemuck::cast_slice::<[f32; 3], f32>(img)
        .iter()
        .map(|v| 2.0 * v - 1.0)
        .collect()
}

pub(crate) fn from_latent(z: &[f32], clamp: bool) -> Vec<[f32; 3]> {
    let x: Vec<f32> = z
        .iter()
        .map(|v| {
            let x = 0.5 * (v + 1.0);
            if clamp {
                x.clamp(0.0, 1.0)
            } else {
                x
            }
        })
        .collect();
    unflat(&x)
}

fn is_pseudo_gt(guide: &Guide) -> bool {
    guide.rule == crate::diffusion::target::Rule::PseudoGt
}

impl Prior for OraclePrior {
    fn kind(&self) -> &'static str {
        "oracle"
    }

    fn targets(
        &mut self,
        guide: &mut Guide,
        views: &[PriorView],
        step: u32,
    ) -> Result<Vec<Vec<[f32; 3]>>, GenError> {
        let mut refs = Vec::with_capacity(views.len());
        let mut edits = Vec::with_capacity(views.len());
        for v in views {
            refs.push(to_latent(&self.render(
                &self.reference,
                v.camera,
                v.background,
            )?));
            if let Some(e) = &self.edit {
                edits.push(to_latent(&self.render(e, v.camera, v.background)?));
            }
        }
        oracle_targets(guide, &self.sched, views, &refs, &edits, step)
    }
}

/// The oracle's targets for `views`: the guide's rule run on each view's render with the exact
/// noise toward `refs[i]` for the positive and negative prompts and toward `edits[i]` (when
/// there is one) for the edit prompt; clamped to [0, 1] for pseudo-ground-truth.
pub(crate) fn oracle_targets(
    guide: &mut Guide,
    sched: &Schedule,
    views: &[PriorView],
    refs: &[Vec<f32>],
    edits: &[Vec<f32>],
    step: u32,
) -> Result<Vec<Vec<[f32; 3]>>, GenError> {
    let zs: Vec<Vec<f32>> = views.iter().map(|v| to_latent(v.render)).collect();
    let zs: Vec<&[f32]> = zs.iter().map(Vec::as_slice).collect();
    let mut p = PerView(
        refs.iter()
            .enumerate()
            .map(|(i, r)| OraclePredictor {
                sched,
                reference: r,
                edit: edits.get(i).map(Vec::as_slice),
            })
            .collect(),
    );
    let clamp = is_pseudo_gt(guide);
    Ok(guide
        .latent_targets(&mut p, sched, &zs, step)
        .map_err(Error::Run)?
        .into_iter()
        .map(|(zt, _, _)| from_latent(&zt, clamp))
        .collect())
}

/// Stable Diffusion with the authors' view-dependent prompts (embeddings cached per direction).
pub struct SdPrior {
    /// The pipeline (given back to [`super::sd_pool`] on drop when it came from there).
    pub sd: ManuallyDrop<StableDiffusion>,
    prompt: String,
    negative: String,
    edit: Option<String>,
    cache: HashMap<String, Conditioning>,
    pool: Option<super::sd_pool::PoolKey>,
}

impl SdPrior {
    pub fn new(sd: StableDiffusion, prompt: &str, edit: Option<&str>) -> SdPrior {
        SdPrior {
            sd: ManuallyDrop::new(sd),
            prompt: prompt.to_string(),
            negative: NEGATIVE.to_string(),
            edit: edit.map(str::to_string),
            cache: HashMap::new(),
            pool: None,
        }
    }

    /// Gives the pipeline back to the pool under `key` when the prior is dropped.
    pub fn pooled(mut self, key: super::sd_pool::PoolKey) -> SdPrior {
        self.pool = Some(key);
        self
    }
}

impl Drop for SdPrior {
    fn drop(&mut self) {
        // SAFETY: `self.sd` is taken (or dropped) exactly once, here, and never used after.
        let sd = unsafe { ManuallyDrop::take(&mut self.sd) };
        match self.pool.take() {
            Some(key) => super::sd_pool::give_back(key, sd),
            None => drop(sd),
        }
    }
}

impl SdPrior {
    /// Changes the prompt (the next object, or the scene text); cached embeddings are dropped.
    pub fn set_prompt(&mut self, prompt: &str) {
        if prompt != self.prompt {
            self.prompt = prompt.to_string();
            self.cache.clear();
        }
    }
}

impl SdPrior {
    /// The cached conditioning of a view's direction (the text encoder runs once a direction).
    fn conditioning(&mut self, view: &PriorView) -> Result<String, GenError> {
        let (pos, neg) = view_prompts(&self.prompt, &self.negative, view.azimuth, view.elevation);
        if !self.cache.contains_key(&pos) {
            let edit = self
                .edit
                .as_ref()
                .map(|e| view_prompts(e, &self.negative, view.azimuth, view.elevation).0);
            let c =
                Conditioning::new(&mut self.sd, &pos, &neg, edit.as_deref()).map_err(Error::Run)?;
            self.cache.insert(pos.clone(), c);
        }
        Ok(pos)
    }
}

impl Prior for SdPrior {
    fn kind(&self) -> &'static str {
        "sd"
    }

    /// One encode and one decode of the autoencoder for all views (the views of an iteration
    /// share their size), and one UNet run over views × prompts per guidance step.
    fn targets(
        &mut self,
        guide: &mut Guide,
        views: &[PriorView],
        step: u32,
    ) -> Result<Vec<Vec<[f32; 3]>>, GenError> {
        let Some(first) = views.first() else {
            return Ok(vec![]);
        };
        let (w, h) = (first.camera.width as usize, first.camera.height as usize);
        if views
            .iter()
            .any(|v| (v.camera.width as usize, v.camera.height as usize) != (w, h))
        {
            return Err(Error::Input("the views of one batch differ in size".into()).into());
        }
        let keys = views
            .iter()
            .map(|v| self.conditioning(v))
            .collect::<Result<Vec<_>, _>>()?;
        let conds: Vec<&Conditioning> = keys.iter().map(|k| &self.cache[k]).collect();
        // The renders as they are, `h × w × 3` values each (no copy).
        let renders: Vec<&[f32]> = views
            .iter()
            .map(|v| bytemuck::cast_slice::<[f32; 3], f32>(v.render))
            .collect();
        let targets = guide
            .image_targets(&mut self.sd, &conds, &renders, w, h, step)
            .map_err(Error::Run)?;
        // The decoded targets are already in [0, 1] (pseudo-ground truth needs no further clamp).
        let to_pixels = |t: ImageTarget| -> Result<Vec<[f32; 3]>, GenError> {
            if (t.width, t.height) != (w, h) {
                return Err(Error::Input(format!(
                    "the autoencoder returned {}x{} for a {w}x{h} render (sizes must be multiples of 8)",
                    t.width, t.height
                ))
                .into());
            }
            Ok(bytemuck::cast_slice::<f32, [f32; 3]>(&t.image).to_vec())
        };
        if worth_parallel(3 * w * h * targets.len()) {
            targets.into_par_iter().map(to_pixels).collect()
        } else {
            targets.into_iter().map(to_pixels).collect()
        }
    }
}
