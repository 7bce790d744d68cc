//! `dreamscene video`: a scene directory or splat PLY rendered along a camera path into an
//! H.264 MP4 or an animated GIF (and a depth video beside it with `--depth`).
use super::open_device;
use anyhow::{bail, Context as _, Result};
use dreamscene::export::trajectory::{cameras, open_input, Size, Trajectory};
use dreamscene::export::video::{
    depth_far, render_video, FrameSource, StaticCloud, TimelineSource, VideoOptions,
};
use dreamscene::generate::progress::Progress;
use dreamscene::scene::timeline::Animated;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// A scene directory (what `generate` writes) or a splat PLY.
    pub input: PathBuf,
    /// Output video: .mp4 (H.264) or .gif.
    #[arg(long)]
    pub out: PathBuf,
    /// Camera path: `orbit` (around a splat file, or inside the room around its centre),
    /// `explore` (a loop at eye height through the room, outside every object; circles
    /// outdoors) or a cameras.json (one frame per camera).
    #[arg(long, default_value = "orbit")]
    pub trajectory: Trajectory,
    /// Length in seconds (orbit and explore): 4, or the scene's timeline when it has one.
    #[arg(long)]
    pub seconds: Option<f64>,
    /// Frames per second.
    #[arg(long, default_value_t = 30.0)]
    pub fps: f64,
    /// Frame size WIDTHxHEIGHT (default 640x480; a cameras.json keeps its own unless given).
    #[arg(long)]
    pub size: Option<Size>,
    /// Also write a depth video beside the colour one (<out>.depth.mp4 / .gif; near is bright).
    #[arg(long)]
    pub depth: bool,
    /// Background colour as R,G,B in [0, 1].
    #[arg(long, default_value = "0,0,0", value_parser = super::parse_rgb)]
    pub background: [f32; 3],
}

/// `<stem>.depth.<ext>` beside `out`.
pub fn depth_path(out: &Path) -> PathBuf {
    let stem = out.file_stem().unwrap_or_default().to_string_lossy();
    let ext = out.extension().unwrap_or_default().to_string_lossy();
    out.with_file_name(format!("{stem}.depth.{ext}"))
}

/// How many frames `seconds` at `fps` make (at least one).
pub fn frame_count(seconds: f64, fps: f64) -> Result<usize> {
    if !(fps.is_finite() && fps > 0.0 && fps <= 240.0) {
        bail!("--fps {fps}: give a number in (0, 240]");
    }
    if !(seconds.is_finite() && seconds > 0.0 && seconds * fps <= 100_000.0) {
        bail!("--seconds {seconds}: give a positive length of at most 100000 frames");
    }
    Ok(((seconds * fps).round() as usize).max(1))
}

pub fn run(a: Args) -> Result<()> {
    let out = a.out.clone();
    super::saying_if_replaced(&out, || write(a))
}

fn write(a: Args) -> Result<()> {
    dreamscene::export::encode::Container::of(&a.out)?;
    super::check_writable(&a.out)?;
    // A scene with a timeline plays it: the motion and the camera path together.
    let (input, animated) = super::read_input(&a.input, || {
        let input = open_input(&a.input)?;
        let animated = match &input.scene {
            Some((dir, _)) => Some(Animated::open(dir)?).filter(|s| s.is_animated()),
            None => None,
        };
        Ok((input, animated))
    })?;
    let timeline_seconds = animated
        .as_ref()
        .and_then(|s| s.scene.timeline.as_ref())
        .map(|t| t.duration);
    let seconds = a
        .seconds
        .or(timeline_seconds.filter(|d| *d > 0.0))
        .unwrap_or(4.0);
    let frames = frame_count(seconds, a.fps)?;
    let cams = cameras(&a.trajectory, &input.subject, frames, a.size)?;
    super::create_parent(&a.out)?;
    let (min, max) = input.subject.bounds();
    let opts = VideoOptions {
        fps: a.fps,
        background: a.background,
        depth_far: depth_far(&cams, min, max),
    };
    let depth = a.depth.then(|| depth_path(&a.out));
    let ctx = open_device()?;
    let mut progress = Progress::new(cams.len() as u64, false);
    let mut source: Box<dyn FrameSource> = match animated {
        Some(scene) => {
            eprintln!(
                "playing the scene's timeline ({:.1} s) along the camera path",
                timeline_seconds.unwrap_or(0.0)
            );
            Box::new(TimelineSource::new(scene))
        }
        None => Box::new(StaticCloud::new(input.cloud)),
    };
    let report = render_video(
        &ctx,
        source.as_mut(),
        &cams,
        &opts,
        &a.out,
        depth.as_deref(),
        &mut |done, _| progress.update(done as u64, "frames"),
    )
    .with_context(|| format!("writing {}", a.out.display()))?;
    progress.finish();
    println!(
        "wrote {} ({} frames, {}x{}, {:.2} s at {} fps){}",
        a.out.display(),
        report.frames,
        report.width,
        report.height,
        report.seconds,
        a.fps,
        depth
            .map(|d| format!(" and {}", d.display()))
            .unwrap_or_default()
    );
    Ok(())
}
