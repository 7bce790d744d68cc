//! Kernel throughput measurements shared by `dreamscene bench` and `benches/kernels.rs`.
//! Buffers are allocated outside the timed region where the API allows; the device is waited on
//! inside it. Each figure is the median of `runs` runs after two warm-ups.
use crate::camera::Camera;
use crate::gpu::{Buffer, Context, Result, Stream};
use crate::splat::backward::{Backward, GpuGrads};
use crate::splat::raster::{GpuGaussians, Rasterizer};
use crate::splat::sort::{RadixSort, SortScratch};
use crate::splat::{reference, Gaussians};
use rand::{Rng, SeedableRng};
use serde::Serialize;
use std::time::Instant;

#[derive(Debug, Serialize)]
pub struct SortFigures {
    pub pairs: u32,
    pub ms: f64,
    pub pairs_per_s: f64,
}

#[derive(Debug, Serialize)]
pub struct RasterFigures {
    pub gaussians: u32,
    pub width: u32,
    pub height: u32,
    /// (tile, Gaussian) intersections; each is evaluated at the tile's 256 pixels at most.
    pub intersections: u32,
    pub ms: f64,
    /// intersections x 256 / wall time of the whole pass (projection, sorts, blend, readbacks).
    pub gaussian_pixels_per_s: f64,
}

#[derive(Debug, Serialize)]
pub struct BenchReport {
    pub device: String,
    pub sort: SortFigures,
    pub forward: RasterFigures,
    /// Blend and projection backward for a random colour gradient (the forward is not timed).
    pub backward: RasterFigures,
    /// The same forward pass by the multithreaded CPU reference (rayon, f64).
    pub cpu_forward: RasterFigures,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn time<F: FnMut() -> Result<()>>(runs: usize, mut f: F) -> Result<f64> {
    for _ in 0..2 {
        f()?;
    }
    let mut t = Vec::new();
    for _ in 0..runs.max(1) {
        let s = Instant::now();
        f()?;
        t.push(s.elapsed().as_secs_f64() * 1e3);
    }
    Ok(median(t))
}

/// The benchmark scene (as in the platform notes): means uniform in x, y in [-1, 1], z in [2, 4],
/// camera at the origin looking down +z, 60 degree field of view, seed 42.
pub fn bench_scene(n: usize, width: u32, height: u32) -> (Gaussians, Camera) {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(42);
    // Scale shrinks with density so that coverage stays comparable across sizes.
    let scale = 0.02 * (10_000.0 / n.max(1) as f32).sqrt().clamp(0.1, 3.0);
    let g = Gaussians::random(&mut rng, n, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], scale, 0);
    let cam = Camera::look_at(
        [0.0; 3],
        [0.0, 0.0, 1.0],
        [0.0, -1.0, 0.0],
        width,
        height,
        60f64.to_radians(),
    );
    (g, cam)
}

/// Sorts `pairs` random 32-bit key/value pairs.
pub fn bench_sort(ctx: &Context, pairs: u32, runs: usize) -> Result<SortFigures> {
    let sort = RadixSort::new(ctx)?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let keys: Vec<u32> = (0..pairs).map(|_| rng.gen()).collect();
    let vals: Vec<u32> = (0..pairs).collect();
    let src_k = Buffer::from_slice(ctx, "bench keys (source)", &keys)?;
    let src_v = Buffer::from_slice(ctx, "bench values (source)", &vals)?;
    let k = Buffer::zeroed::<u32>(ctx, "bench keys", pairs as usize)?;
    let v = Buffer::zeroed::<u32>(ctx, "bench values", pairs as usize)?;
    let scratch = SortScratch::new(ctx, pairs)?;
    // The copy that restores unsorted input is timed separately and subtracted.
    let copy_ms = time(runs, || {
        let mut s = Stream::new(ctx)?;
        s.copy(&src_k, &k, pairs as u64 * 4);
        s.copy(&src_v, &v, pairs as u64 * 4);
        s.submit().map(|_| ())
    })?;
    let ms = time(runs, || {
        let mut s = Stream::new(ctx)?;
        s.copy(&src_k, &k, pairs as u64 * 4);
        s.copy(&src_v, &v, pairs as u64 * 4);
        sort.record(&mut s, &k, &v, pairs, 32, &scratch)?;
        s.submit().map(|_| ())
    })? - copy_ms;
    Ok(SortFigures {
        pairs,
        ms,
        pairs_per_s: pairs as f64 / (ms * 1e-3),
    })
}

/// Full GPU forward pass on the bench scene.
pub fn bench_forward(
    ctx: &Context,
    n: usize,
    width: u32,
    height: u32,
    runs: usize,
) -> Result<RasterFigures> {
    let (g, cam) = bench_scene(n, width, height);
    let r = Rasterizer::new(ctx)?;
    let gg = GpuGaussians::upload(ctx, &g)?;
    let mut m = 0;
    let ms = time(runs, || {
        let f = r.forward(ctx, &gg, &cam, [0.0; 3])?;
        m = f.intersections;
        Ok(())
    })?;
    Ok(RasterFigures {
        gaussians: n as u32,
        width,
        height,
        intersections: m,
        ms,
        gaussian_pixels_per_s: m as f64 * 256.0 / (ms * 1e-3),
    })
}

/// GPU backward pass (blend backward and projection backward) on the bench scene, for a random
/// per-pixel colour gradient; the forward it differentiates runs once, outside the timing.
pub fn bench_backward(
    ctx: &Context,
    n: usize,
    width: u32,
    height: u32,
    runs: usize,
) -> Result<RasterFigures> {
    let (g, cam) = bench_scene(n, width, height);
    let r = Rasterizer::new(ctx)?;
    let bwd = Backward::new(ctx, false)?;
    let gg = GpuGaussians::upload(ctx, &g)?;
    let frame = r.forward(ctx, &gg, &cam, [0.0; 3])?;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
    let dl: Vec<[f32; 4]> = (0..width as usize * height as usize)
        .map(|_| {
            [
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                0.0,
            ]
        })
        .collect();
    let dlb = Buffer::from_slice(ctx, "bench colour gradient", &dl)?;
    let grads = GpuGrads::new(ctx, n as u32, g.sh_degree)?;
    let ms = time(runs, || {
        bwd.run(ctx, &frame, &gg, &cam, &dlb, &grads).map(|_| ())
    })?;
    Ok(RasterFigures {
        gaussians: n as u32,
        width,
        height,
        intersections: frame.intersections,
        ms,
        gaussian_pixels_per_s: frame.intersections as f64 * 256.0 / (ms * 1e-3),
    })
}

/// The multithreaded CPU reference on the same scene, with the GPU's intersection count.
pub fn bench_cpu_forward(
    n: usize,
    width: u32,
    height: u32,
    intersections: u32,
    runs: usize,
) -> RasterFigures {
    let (g, cam) = bench_scene(n, width, height);
    let ms = time(runs, || {
        std::hint::black_box(reference::render(&g, &cam, [0.0; 3]));
        Ok(())
    })
    .expect("CPU timing cannot fail");
    RasterFigures {
        gaussians: n as u32,
        width,
        height,
        intersections,
        ms,
        gaussian_pixels_per_s: intersections as f64 * 256.0 / (ms * 1e-3),
    }
}
