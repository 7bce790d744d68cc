//! The video frame loop: each frame asks a [`FrameSource`] for the Gaussians at its time,
//! renders them on the engine from its camera and hands the image to a [`VideoSink`](super::encode::VideoSink); with a
//! depth path, the expected depth goes to a second video beside the colour one.
//!
//! A static scene is one cloud, uploaded once; an animated one (a `scene.json` timeline) gives a
//! new cloud whenever its state changes, through the same [`FrameSource::gaussians_at`].
use super::encode::{self, EncodeError};
use crate::camera::Camera;
use crate::gpu::{Context, GpuError};
use crate::splat::raster::{Frame, GpuGaussians, Rasterizer, RenderOutput};
use crate::splat::{view, Gaussians};
use std::path::Path;

/// Why a video cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum VideoError {
    #[error(transparent)]
    Gpu(#[from] GpuError),
    #[error(transparent)]
    Encode(#[from] EncodeError),
    #[error("{0}")]
    Invalid(String),
}

pub type Result<T> = std::result::Result<T, VideoError>;

/// The scene as the frame loop sees it: the Gaussians at time `t` seconds.
pub trait FrameSource {
    /// `Some` with the cloud to draw from time `t` on, or `None` when it is the same as the
    /// last one given (the loop keeps the uploaded copy). The first call always gives a cloud.
    fn gaussians_at(&mut self, t: f64) -> Option<&Gaussians>;
}

/// A scene that does not move: its cloud is given once.
pub struct StaticCloud {
    cloud: Gaussians,
    given: bool,
}

impl StaticCloud {
    pub fn new(cloud: Gaussians) -> StaticCloud {
        StaticCloud {
            cloud,
            given: false,
        }
    }
}

impl FrameSource for StaticCloud {
    fn gaussians_at(&mut self, _t: f64) -> Option<&Gaussians> {
        if self.given {
            None
        } else {
            self.given = true;
            Some(&self.cloud)
        }
    }
}

/// A scene with a timeline: the cloud is composed anew at every frame's time.
pub struct TimelineSource {
    scene: crate::scene::timeline::Animated,
    current: Gaussians,
}

impl TimelineSource {
    pub fn new(scene: crate::scene::timeline::Animated) -> TimelineSource {
        TimelineSource {
            scene,
            current: Gaussians::default(),
        }
    }
}

impl FrameSource for TimelineSource {
    fn gaussians_at(&mut self, t: f64) -> Option<&Gaussians> {
        self.current = self.scene.at(t);
        Some(&self.current)
    }
}

/// How frames are drawn and timed.
#[derive(Debug, Clone)]
pub struct VideoOptions {
    /// Frames per second; frame i is drawn at t = i / fps.
    pub fps: f64,
    pub background: [f32; 3],
    /// Depth mapped to grey as `1 − d / far` (near is bright), clamped to [0, 1].
    pub depth_far: f64,
}

/// What a finished video holds.
#[derive(Debug, Clone, PartialEq)]
pub struct VideoReport {
    pub frames: usize,
    pub width: u32,
    pub height: u32,
    pub seconds: f64,
}

/// Renders one frame per camera (all of one size) and writes the colour video to `out` and,
/// when given, the depth video to `depth_out` (container from each file's extension).
/// `progress(done, total)` is called after every frame.
pub fn render_video(
    ctx: &Context,
    source: &mut dyn FrameSource,
    cams: &[Camera],
    opts: &VideoOptions,
    out: &Path,
    depth_out: Option<&Path>,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<VideoReport> {
    let first = cams
        .first()
        .ok_or_else(|| VideoError::Invalid("a video needs at least one camera".into()))?;
    let (w, h) = (first.width, first.height);
    if let Some(c) = cams.iter().find(|c| (c.width, c.height) != (w, h)) {
        return Err(VideoError::Invalid(format!(
            "camera {} is {}x{}, the first is {w}x{h}: a video has one size (give --size)",
            c.img_name, c.width, c.height
        )));
    }
    let mut colour = encode::open(out, w, h, opts.fps)?;
    let mut depth = match depth_out {
        Some(p) => Some(encode::open(p, w, h, opts.fps)?),
        None => None,
    };
    let raster = Rasterizer::new(ctx)?;
    let mut frame = Frame::new(ctx)?;
    let mut uploaded: Option<GpuGaussians> = None;
    // a cloud too large for one render is kept on the host and drawn per frame from the part
    // the frame's camera sees (`splat::view`)
    let mut large: Option<(Gaussians, usize)> = None;
    for (i, cam) in cams.iter().enumerate() {
        let t = i as f64 / opts.fps;
        if let Some(g) = source.gaussians_at(t) {
            uploaded = None;
            let max = view::max_gaussians(ctx, g);
            if g.len() > max {
                large = Some((g.clone(), max));
            } else {
                large = None;
                uploaded = Some(GpuGaussians::upload(ctx, g)?);
            }
        }
        if let Some((g, max)) = &large {
            // the last frame's part is freed before the next is made
            drop(uploaded.take());
            let part = view::select(g, &view::visible(g, cam, *max));
            uploaded = Some(GpuGaussians::upload(ctx, &part)?);
        }
        let g = uploaded.as_ref().ok_or_else(|| {
            VideoError::Invalid("the frame source gave no Gaussians for the first frame".into())
        })?;
        raster.forward_into(ctx, g, cam, opts.background, &mut frame, false)?;
        let img = frame.read()?;
        colour.push(&colour_bytes(&img))?;
        if let Some(d) = depth.as_mut() {
            d.push(&depth_bytes(&img, opts.depth_far))?;
        }
        progress(i + 1, cams.len());
    }
    colour.finish()?;
    if let Some(d) = depth {
        d.finish()?;
    }
    Ok(VideoReport {
        frames: cams.len(),
        width: w,
        height: h,
        seconds: cams.len() as f64 / opts.fps,
    })
}

/// The image as 8-bit RGB.
pub fn colour_bytes(img: &RenderOutput) -> Vec<u8> {
    img.color
        .iter()
        .flat_map(|c| c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8))
        .collect()
}

/// Expected depth (accumulated depth over accumulated opacity) as grey `1 − d / far`; pixels
/// less than half covered are black.
pub fn depth_bytes(img: &RenderOutput, far: f64) -> Vec<u8> {
    img.depth
        .iter()
        .zip(&img.transmittance)
        .flat_map(|(&d, &t)| {
            let alpha = 1.0 - t as f64;
            let v = if alpha < 0.5 || far <= 0.0 {
                0.0
            } else {
                (1.0 - d as f64 / alpha / far).clamp(0.0, 1.0)
            };
            let b = (v * 255.0 + 0.5) as u8;
            [b, b, b]
        })
        .collect()
}

/// A far plane for the depth video: the largest distance from any camera to a corner of the
/// box `[min, max]` (the scene's bounds), so the grey scale is the same in every frame.
pub fn depth_far(cams: &[Camera], min: [f64; 3], max: [f64; 3]) -> f64 {
    let mut far: f64 = 0.0;
    for c in cams {
        for k in 0..8 {
            let q = [
                if k & 1 == 0 { min[0] } else { max[0] },
                if k & 2 == 0 { min[1] } else { max[1] },
                if k & 4 == 0 { min[2] } else { max[2] },
            ];
            let d = (0..3).map(|j| (q[j] - c.position[j]).powi(2)).sum::<f64>();
            far = far.max(d.sqrt());
        }
    }
    far.max(1e-3)
}
