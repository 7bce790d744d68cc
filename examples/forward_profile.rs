//! Per-kernel GPU time of one forward pass on the bench scene:
//! `cargo run --release --example forward_profile [gaussians] [size]`.
use dreamscene::bench::bench_scene;
use dreamscene::gpu::Context;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};

fn main() -> anyhow::Result<()> {
    let (n, size) = dreamscene::bench::profile_args(100_000, 512);
    let ctx = Context::new()?;
    let mut r = Rasterizer::new(&ctx)?;
    r.set_timed(true);
    let (g, cam) = bench_scene(n, size, size);
    let gg = GpuGaussians::upload(&ctx, &g)?;
    for _ in 0..3 {
        let t0 = std::time::Instant::now();
        let f = r.forward(&ctx, &gg, &cam, [0.0; 3])?;
        let wall = t0.elapsed().as_secs_f64() * 1e3;
        let mut names: Vec<&str> = f.timings.entries.iter().map(|e| e.0).collect();
        names.sort();
        names.dedup();
        for name in names {
            print!("{name} {:.1}  ", f.timings.ms(name));
        }
        println!(
            "| kernels {:.1} ms, wall {wall:.1} ms, {} intersections",
            f.timings.total_ms(),
            f.intersections
        );
    }
    Ok(())
}
