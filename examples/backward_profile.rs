//! Per-kernel GPU time of one backward pass on the bench scene:
//! `cargo run --release --example backward_profile [gaussians] [size]`.
use dreamscene::bench::RasterBench;
use dreamscene::gpu::Context;
use dreamscene::splat::backward::Backward;

fn main() -> anyhow::Result<()> {
    let (n, size) = dreamscene::bench::profile_args(100_000, 512);
    let ctx = Context::new()?;
    let bench = RasterBench::new(&ctx, n, size, size)?;
    let mut bwd = Backward::new(&ctx, false)?;
    bwd.set_timed(true);
    let inputs = bench.backward_inputs(&ctx)?;
    for _ in 0..3 {
        println!("{}", bench.backward(&ctx, &bwd, &inputs)?.summary());
    }
    Ok(())
}
