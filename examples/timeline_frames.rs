//! Renders a scene directory's timeline into PNG frames with `compose_at`, from every camera of
//! a cameras.json (default: the scene's renders/cameras.json):
//! `cargo run --release --example timeline_frames -- DIR OUT [CAMERAS.json]`
//! writes `OUT/<camera>_<frame>.png` at the timeline's fps (one frame for a static scene).
use anyhow::{Context as _, Result};
use dreamscene::camera::read_cameras;
use dreamscene::edit::commit::save_png;
use dreamscene::scene::dir::read_scene;
use dreamscene::scene::timeline::{compose_at, frame_times};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use std::path::PathBuf;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [dir, out, rest @ ..] = args.as_slice() else {
        anyhow::bail!("usage: timeline_frames DIR OUT [CAMERAS.json]");
    };
    let dir = PathBuf::from(dir);
    let out = PathBuf::from(out);
    let cams_path = rest
        .first()
        .map(PathBuf::from)
        .unwrap_or_else(|| dir.join("renders/cameras.json"));
    let cams = read_cameras(&cams_path).with_context(|| cams_path.display().to_string())?;
    let scene = read_scene(&dir)?;
    let times = scene.timeline.as_ref().map_or(vec![0.0], frame_times);
    std::fs::create_dir_all(&out)?;
    let ctx = dreamscene::gpu::Context::new()?;
    let r = Rasterizer::new(&ctx)?;
    for (k, t) in times.iter().enumerate() {
        let g = GpuGaussians::upload(&ctx, &compose_at(&dir, *t)?)?;
        for cam in &cams {
            let img = r.forward(&ctx, &g, cam, [0.0; 3])?.read()?;
            let p = out.join(format!("{}_{k:04}.png", cam.img_name));
            save_png(&p, img.width, img.height, &img.color)?;
        }
        eprintln!("frame {}/{} (t = {t:.2} s)", k + 1, times.len());
    }
    Ok(())
}
