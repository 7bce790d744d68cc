//! GPU scan and radix sort against CPU references, on random inputs and edge sizes.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::gpu::{Buffer, Stream};
use dreamscene::splat::scan::{Scan, ScanScratch};
use dreamscene::splat::sort::{RadixSort, SortVariant};
use rand::Rng;

fn cpu_exclusive_scan(v: &[u32]) -> Vec<u32> {
    let mut run = 0u32;
    v.iter()
        .map(|&x| {
            let r = run;
            run = run.wrapping_add(x);
            r
        })
        .collect()
}

#[test]
fn exclusive_scan_matches_cpu_at_block_edges() {
    let ctx = common::gpu();
    let scan = Scan::new(&ctx).unwrap();
    let mut rng = common::rng(1);
    for n in [0usize, 1, 7, 1023, 1024, 1025, 4096 * 256 + 17, 1 << 21] {
        let data: Vec<u32> = (0..n).map(|_| rng.gen_range(0..1000)).collect();
        // The buffer is longer than n and its tail is garbage that must stay untouched.
        let mut padded = data.clone();
        padded.extend([0xDEAD_BEEFu32; 5]);
        let buf = Buffer::from_slice(&ctx, "scan data", &padded).unwrap();
        let scratch = ScanScratch::new(&ctx, n as u32).unwrap();
        let mut s = Stream::new(&ctx).unwrap();
        scan.record(&mut s, &buf, n as u32, &scratch).unwrap();
        s.submit().unwrap();
        let got: Vec<u32> = buf.read(n + 5).unwrap();
        assert_eq!(&got[..n], &cpu_exclusive_scan(&data)[..], "scan of {n}");
        assert_eq!(
            &got[n..],
            &[0xDEAD_BEEFu32; 5],
            "scan of {n} wrote past its end"
        );
    }
    ctx.check_validation().unwrap();
}

fn cpu_sort(keys: &[u32], vals: &[u32], bits: u32) -> (Vec<u32>, Vec<u32>) {
    let mask = if bits >= 32 {
        u32::MAX
    } else {
        (1u32 << bits) - 1
    };
    let mut idx: Vec<usize> = (0..keys.len()).collect();
    idx.sort_by_key(|&i| keys[i] & mask); // stable
    (
        idx.iter().map(|&i| keys[i]).collect(),
        idx.iter().map(|&i| vals[i]).collect(),
    )
}

/// Both variants: the subgroup-ballot one (GPUs) and the lane-serial one (CPU devices).
const VARIANTS: [SortVariant; 2] = [SortVariant::Subgroup, SortVariant::Serial];

#[test]
fn sorted_pairs_match_cpu_stable_sort() {
    for v in VARIANTS {
        sorted_pairs_match_cpu_stable_sort_with(v);
    }
}

fn sorted_pairs_match_cpu_stable_sort_with(variant: SortVariant) {
    let ctx = common::gpu();
    let sort = RadixSort::with_variant(&ctx, variant).unwrap();
    let mut rng = common::rng(2);
    for n in [0usize, 1, 7, 2047, 2048, 2049, (1 << 20) + 3] {
        let keys: Vec<u32> = (0..n).map(|_| rng.gen()).collect();
        let vals: Vec<u32> = (0..n as u32).collect();
        let (gk, gv) = sort.sort_pairs(&ctx, &keys, &vals, 32).unwrap();
        let (ck, cv) = cpu_sort(&keys, &vals, 32);
        assert_eq!(gk, ck, "{variant:?}: keys, n = {n}");
        assert_eq!(gv, cv, "{variant:?}: values, n = {n}");
    }
    ctx.check_validation().unwrap();
}

#[test]
fn sort_is_stable_with_many_equal_keys_and_partial_bits() {
    for v in VARIANTS {
        sort_is_stable_with(v);
    }
}

fn sort_is_stable_with(variant: SortVariant) {
    let ctx = common::gpu();
    let sort = RadixSort::with_variant(&ctx, variant).unwrap();
    let mut rng = common::rng(3);
    // Few distinct keys: most pairs tie, so any instability reorders values.
    for (n, bits, range) in [
        (100_003usize, 32u32, 16u32),
        (50_000, 12, 4096),
        (70_001, 20, 1 << 20),
        (9_999, 8, 3),
    ] {
        let keys: Vec<u32> = (0..n).map(|_| rng.gen_range(0..range)).collect();
        let vals: Vec<u32> = (0..n as u32)
            .map(|i| i.wrapping_mul(2_654_435_761))
            .collect();
        let (gk, gv) = sort.sort_pairs(&ctx, &keys, &vals, bits).unwrap();
        let (ck, cv) = cpu_sort(&keys, &vals, bits);
        assert_eq!(gk, ck, "{variant:?}: keys, n = {n}, bits = {bits}");
        assert_eq!(gv, cv, "{variant:?}: values, n = {n}, bits = {bits}");
    }
    ctx.check_validation().unwrap();
}

#[test]
fn device_reports_its_facts() {
    let ctx = common::gpu();
    let i = ctx.info();
    eprintln!("{i:#?}");
    assert!(i.subgroup_size >= 8);
    assert!(i.max_storage_buffer_range > 0);
}
