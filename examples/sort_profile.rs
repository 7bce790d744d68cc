//! Per-kernel GPU times of one radix sort (timestamp queries): `cargo run --release --example sort_profile`.
use dreamscene::gpu::{Buffer, Context, Stream};
use dreamscene::splat::sort::{RadixSort, SortScratch};
use rand::{Rng, SeedableRng};

fn main() -> anyhow::Result<()> {
    let n: u32 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1 << 20);
    let ctx = Context::new()?;
    let sort = RadixSort::new(&ctx)?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let keys: Vec<u32> = (0..n).map(|_| rng.gen()).collect();
    let k = Buffer::from_slice(&ctx, "k", &keys)?;
    let v = Buffer::from_slice(&ctx, "v", &keys)?;
    let scratch = SortScratch::new(&ctx, n)?;
    for _ in 0..3 {
        let mut s = Stream::timed(&ctx, 128)?;
        sort.record(&mut s, &k, &v, n, 32, &scratch)?;
        println!("{}", s.submit()?.summary());
    }
    Ok(())
}
