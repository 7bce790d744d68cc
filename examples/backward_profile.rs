//! Per-kernel GPU time of one backward pass on the bench scene:
//! `cargo run --release --example backward_profile [gaussians] [size]`.
use dreamscene::bench::{bench_scene, random_colour_gradient};
use dreamscene::gpu::{Buffer, Context};
use dreamscene::splat::backward::{Backward, GpuGrads};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use rand::SeedableRng;

fn main() -> anyhow::Result<()> {
    let (n, size) = dreamscene::bench::profile_args(100_000, 512);
    let ctx = Context::new()?;
    let r = Rasterizer::new(&ctx)?;
    let mut bwd = Backward::new(&ctx, false)?;
    bwd.set_timed(true);
    let (g, cam) = bench_scene(n, size, size);
    let gg = GpuGaussians::upload(&ctx, &g)?;
    let frame = r.forward(&ctx, &gg, &cam, [0.0; 3])?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
    let dl = random_colour_gradient(&mut rng, size as usize * size as usize);
    let dlb = Buffer::from_slice(&ctx, "colour gradient", &dl)?;
    let grads = GpuGrads::new(&ctx, n as u32, g.sh_degree)?;
    for _ in 0..3 {
        let t = bwd.run(&ctx, &frame, &gg, &cam, &dlb, &grads)?;
        let mut names: Vec<&str> = t.entries.iter().map(|e| e.0).collect();
        names.sort();
        names.dedup();
        for name in names {
            print!("{name} {:.1}  ", t.ms(name));
        }
        println!("| kernels {:.1} ms", t.total_ms());
    }
    Ok(())
}
