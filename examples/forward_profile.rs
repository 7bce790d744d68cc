//! Per-kernel GPU time of one forward pass on the bench scene:
//! `cargo run --release --example forward_profile [gaussians] [size]`.
use dreamscene::bench::RasterBench;
use dreamscene::gpu::Context;

fn main() -> anyhow::Result<()> {
    let (n, size) = dreamscene::bench::profile_args(100_000, 512);
    let ctx = Context::new()?;
    let mut bench = RasterBench::new(&ctx, n, size, size)?;
    bench.rasterizer.set_timed(true);
    for _ in 0..3 {
        let t0 = std::time::Instant::now();
        let f = bench.forward(&ctx)?;
        let wall = t0.elapsed().as_secs_f64() * 1e3;
        println!(
            "{}, wall {wall:.1} ms, {} intersections",
            f.timings.summary(),
            f.intersections
        );
    }
    Ok(())
}
