//! `dreamscene demo`: a random scene, its orbit cameras and their renders.
use anyhow::{bail, Result};
use dreamscene::camera::{write_cameras, Camera};
use dreamscene::splat::ply::write_ply;
use dreamscene::splat::Gaussians;
use rand::SeedableRng;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Output directory.
    #[arg(long, default_value = "out/demo")]
    pub out: PathBuf,
    /// Number of Gaussians.
    #[arg(long, default_value_t = 20_000)]
    pub gaussians: usize,
    /// Seed of the random scene.
    #[arg(long, default_value_t = 7)]
    pub seed: u64,
}

pub fn run(a: Args) -> Result<()> {
    demo(&a.out, a.gaussians, a.seed)
}

fn demo(out: &Path, n: usize, seed: u64) -> Result<()> {
    if n == 0 {
        bail!("--gaussians must be at least 1");
    }
    super::create_dir(out)?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let g = Gaussians::random(&mut rng, n, [-1.0; 3], [1.0; 3], 0.03, 1);
    let cams: Vec<Camera> = (0..8)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 8.0;
            let mut c = Camera::look_at(
                [4.0 * a.cos(), 4.0 * a.sin(), 1.5],
                [0.0; 3],
                [0.0, 0.0, 1.0],
                256,
                256,
                0.8,
            );
            c.id = i;
            c.img_name = format!("view_{i:02}");
            c
        })
        .collect();
    write_ply(&out.join("scene.ply"), &g)?;
    write_cameras(&out.join("cameras.json"), &cams)?;
    super::render::render_all(&g, &cams, &out.join("renders"), [1.0, 1.0, 1.0])?;
    println!(
        "wrote {}/scene.ply, cameras.json and renders/*.png",
        out.display()
    );
    Ok(())
}
