//! Kernel throughput: radix sort, the full forward pass and the backward pass at 10k, 100k and 1M Gaussians
//! (512x512), beside the multithreaded CPU reference. `cargo bench --bench kernels`.
//!
//! Sizes: 10k is a single object early in optimisation, 100k a finished object, 1M a whole scene.
//! Under `cargo test` (no `--bench` argument) it runs one tiny size as a smoke test.
use dreamscene::bench::{bench_backward, bench_cpu_forward, bench_forward, bench_sort};
use dreamscene::gpu::Context;

fn main() -> anyhow::Result<()> {
    let full = std::env::args().any(|a| a == "--bench");
    let ctx = Context::new()?;
    println!("device: {}", ctx.info().name);
    let (pairs, sizes, runs): (Vec<u32>, Vec<usize>, usize) = if full {
        (
            vec![1 << 16, 1 << 20, 1 << 22],
            vec![10_000, 100_000, 1_000_000],
            5,
        )
    } else {
        (vec![4096], vec![1000], 1)
    };
    for p in pairs {
        let s = bench_sort(&ctx, p, runs)?;
        println!(
            "sort {:>8} pairs: {:>8.2} ms, {:>7.2} M pairs/s",
            s.pairs,
            s.ms,
            s.pairs_per_s / 1e6
        );
    }
    for n in sizes {
        let f = bench_forward(&ctx, n, 512, 512, runs)?;
        let c = bench_cpu_forward(n, 512, 512, f.intersections, runs.min(3));
        println!(
            "forward {:>8} gaussians 512x512 ({} intersections): GPU {:>8.2} ms {:>7.2} M gaussian-pixels/s | CPU reference {:>8.2} ms {:>7.2} M/s",
            n,
            f.intersections,
            f.ms,
            f.gaussian_pixels_per_s / 1e6,
            c.ms,
            c.gaussian_pixels_per_s / 1e6
        );
        let b = bench_backward(&ctx, n, 512, 512, runs)?;
        println!(
            "backward {:>7} gaussians 512x512 ({} intersections): GPU {:>8.2} ms {:>7.2} M gaussian-pixels/s",
            n,
            b.intersections,
            b.ms,
            b.gaussian_pixels_per_s / 1e6
        );
    }
    Ok(())
}
