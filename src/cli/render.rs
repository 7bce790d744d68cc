//! `dreamscene render`: a splat PLY seen from every camera of a cameras.json.
use super::{open_device, save_png};
use anyhow::{Context as _, Result};
use dreamscene::camera::{read_cameras, Camera};
use dreamscene::splat::ply::read_ply;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Splat PLY (INRIA 3DGS layout, SH degree 0 to 3).
    #[arg(long)]
    pub ply: PathBuf,
    /// INRIA cameras.json.
    #[arg(long)]
    pub cameras: PathBuf,
    /// Output directory (created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// Background colour as R,G,B in [0, 1].
    #[arg(long, default_value = "0,0,0", value_parser = super::parse_rgb)]
    pub background: [f32; 3],
}

pub fn run(a: Args) -> Result<()> {
    let g = read_ply(&a.ply)?;
    let cams = read_cameras(&a.cameras)?;
    render_all(&g, &cams, &a.out, a.background)
}

pub fn render_all(g: &Gaussians, cams: &[Camera], out: &Path, background: [f32; 3]) -> Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let ctx = open_device()?;
    let r = Rasterizer::new(&ctx)?;
    let gg = GpuGaussians::upload(&ctx, g)?;
    let bar = ProgressBar::new(cams.len() as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} views {msg}").expect("valid template"),
    );
    for c in cams {
        let img = r.forward(&ctx, &gg, c, background)?.read()?;
        let name = if c.img_name.is_empty() {
            format!("{:05}", c.id)
        } else {
            c.img_name.clone()
        };
        let path = out.join(format!("{name}.png"));
        save_png(&img, &path)?;
        bar.set_message(name);
        bar.inc(1);
    }
    bar.finish();
    Ok(())
}
