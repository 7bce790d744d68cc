//! `dreamscene render`: a splat PLY (or a scene directory) seen from every camera of a
//! cameras.json, or along a camera path as `video` draws it.
use super::{open_device, save_png};
use anyhow::{bail, Context as _, Result};
use dreamscene::camera::Camera;
use dreamscene::export::trajectory::{cameras, open_input, Size, Trajectory};
use dreamscene::generate::progress::Progress;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
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
    let input = open_input(input)?;
    let cams = cameras(&trajectory, &input.subject, a.frames, a.size)?;
    render_all(&input.cloud, &cams, &a.out, a.background)
}

pub fn render_all(g: &Gaussians, cams: &[Camera], out: &Path, background: [f32; 3]) -> Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let ctx = open_device()?;
    let r = Rasterizer::new(&ctx)?;
    let gg = GpuGaussians::upload(&ctx, g)?;
    let mut bar = Progress::new(cams.len() as u64, false);
    for (i, c) in cams.iter().enumerate() {
        let img = r.forward(&ctx, &gg, c, background)?.read()?;
        let name = if c.img_name.is_empty() {
            format!("{:05}", c.id)
        } else {
            c.img_name.clone()
        };
        let path = out.join(format!("{name}.png"));
        save_png(&img, &path)?;
        bar.update(i as u64 + 1, &name);
    }
    bar.finish();
    Ok(())
}
