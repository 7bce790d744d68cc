//! `dreamscene render`: a splat PLY (or a scene directory) seen from every camera of a
//! cameras.json, or along a camera path as `video` draws it.
use super::{open_device, save_png};
use anyhow::{bail, Result};
use dreamscene::camera::Camera;
use dreamscene::export::trajectory::{cameras, open_input_at, Input, Size, Subject, Trajectory};
use dreamscene::generate::progress::Progress;
use dreamscene::splat::ply::{read_ply_with, Invalid};
use dreamscene::splat::raster::Rasterizer;
use dreamscene::splat::view::ViewSource;
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// A scene directory (what `generate` writes) or a splat PLY, instead of --ply.
    #[arg(conflicts_with = "ply")]
    pub input: Option<PathBuf>,
    /// Splat PLY (INRIA 3DGS layout, SH degree 0 to 3).
    #[arg(long)]
    pub ply: Option<PathBuf>,
    /// INRIA cameras.json (the same as --trajectory FILE).
    #[arg(long, conflicts_with = "trajectory")]
    pub cameras: Option<PathBuf>,
    /// Camera path as `video` takes it: orbit, explore or a cameras.json.
    #[arg(long)]
    pub trajectory: Option<Trajectory>,
    /// Views on an orbit or explore path.
    #[arg(long, default_value_t = 120)]
    pub frames: usize,
    /// Image size WIDTHxHEIGHT (default 640x480 on a path; a cameras.json keeps its own
    /// unless given, with focal lengths scaled to it).
    #[arg(long)]
    pub size: Option<Size>,
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// Background colour as R,G,B in [0, 1].
    #[arg(long, default_value = "0,0,0", value_parser = super::parse_rgb)]
    pub background: [f32; 3],
    /// Leave out Gaussians with non-finite values (NaN, Inf) or a zero rotation, saying how many,
    /// instead of refusing the PLY.
    #[arg(long)]
    pub drop_invalid: bool,
    /// Play the scene's timeline (scene.json `timeline`, made by `edit animate`) to this time in
    /// seconds before rendering.
    #[arg(long)]
    pub time: Option<f64>,
}

pub fn run(a: Args) -> Result<()> {
    let Some(input) = a.input.as_ref().or(a.ply.as_ref()) else {
        bail!("give a scene directory or a splat PLY (--ply FILE)");
    };
    let trajectory = match (a.trajectory, a.cameras) {
        (Some(t), None) => t,
        (None, Some(c)) => Trajectory::Cameras(c),
        _ => bail!("give --cameras FILE or --trajectory orbit|explore|FILE"),
    };
    let is_ply = input.is_file()
        && !input
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let input = if a.drop_invalid && is_ply && a.time.is_none() {
        let cloud = read_splats(input, true)?;
        let subject = Subject::of_cloud(&cloud)?;
        Input {
            cloud,
            subject,
            scene: None,
        }
    } else {
        super::read_input(input, || Ok(open_input_at(input, a.time)?))?
    };
    let cams = cameras(&trajectory, &input.subject, a.frames, a.size)?;
    super::check_writable_dir(&a.out)?;
    render_all(&input.cloud, &cams, &a.out, a.background)
}

/// Reads a splat PLY; with `drop_invalid`, Gaussians with non-finite values or a zero rotation
/// are left out with a line saying how many, else the file is refused.
pub fn read_splats(path: &Path, drop_invalid: bool) -> Result<Gaussians> {
    let how = if drop_invalid {
        Invalid::Drop
    } else {
        Invalid::Refuse
    };
    let r = read_ply_with(path, how)?;
    if r.dropped > 0 {
        eprintln!(
            "{}: dropped {} Gaussians with non-finite values or a zero rotation, kept {}",
            path.display(),
            r.dropped,
            r.gaussians.len()
        );
    }
    if r.gaussians.is_empty() {
        bail!("{}: no Gaussians to use", path.display());
    }
    Ok(r.gaussians)
}

/// Renders every camera into `<out>/<img_name>.png` (sub-directories of `img_name` created) and
/// says what it wrote.
pub fn render_all(g: &Gaussians, cams: &[Camera], out: &Path, background: [f32; 3]) -> Result<()> {
    super::create_dir(out)?;
    let ctx = open_device()?;
    let r = Rasterizer::new(&ctx)?;
    let mut source = ViewSource::new(&ctx, g);
    let mut progress = Progress::new(cams.len() as u64, false);
    let mut written = Vec::with_capacity(cams.len());
    for (i, c) in cams.iter().enumerate() {
        let img = r
            .forward(&ctx, source.for_camera(&ctx, c)?, c, background)?
            .read()?;
        let name = format!("{}.png", c.output_name());
        let path = out.join(&name);
        super::create_parent(&path)?;
        save_png(&img, &path)?;
        progress.update(i as u64 + 1, &format!("render {name}"));
        written.push(name);
    }
    progress.finish();
    let shown = match written.as_slice() {
        [one] => one.clone(),
        [first, .., last] => format!("{first} ... {last}"),
        [] => String::new(),
    };
    println!(
        "wrote {} images to {} ({shown})",
        written.len(),
        out.display()
    );
    Ok(())
}
