//! Kernel throughput measurements shared by `dreamscene bench` and `benches/kernels.rs`.
//! Buffers are allocated outside the timed region where the API allows; the device is waited on
//! inside it. Each figure is the median of `runs` runs after two warm-ups.
use crate::camera::Camera;
use crate::gpu::{Buffer, Context, Result, Stream, Timings};
use crate::splat::backward::{Backward, GpuGrads};
use crate::splat::raster::{Frame, GpuGaussians, Rasterizer};
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

impl RasterFigures {
    fn measured(n: usize, width: u32, height: u32, intersections: u32, ms: f64) -> RasterFigures {
        RasterFigures {
            gaussians: n as u32,
            width,
            height,
            intersections,
            ms,
            gaussian_pixels_per_s: intersections as f64 * 256.0 / (ms * 1e-3),
        }
    }
}

/// A per-pixel colour gradient (RGB uniform in [−1, 1], alpha slot 0) for `pixels` pixels:
/// what the backward benchmark and tests feed the blend backward.
pub fn random_colour_gradient(rng: &mut impl Rng, pixels: usize) -> Vec<[f32; 4]> {
    (0..pixels)
        .map(|_| {
            [
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                0.0,
            ]
        })
        .collect()
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

/// The bench scene uploaded to the device with a rasterizer for it.
pub struct RasterBench {
    pub cam: Camera,
    pub rasterizer: Rasterizer,
    pub gaussians: GpuGaussians,
}

/// What a backward pass of the bench scene needs: the forward frame, a random per-pixel colour
/// gradient (seeded) and zeroed gradient buffers.
pub struct BackwardInputs {
    pub frame: Frame,
    pub colour_grad: Buffer,
    pub grads: GpuGrads,
}

impl RasterBench {
    pub fn new(ctx: &Context, n: usize, width: u32, height: u32) -> Result<RasterBench> {
        let (g, cam) = bench_scene(n, width, height);
        Ok(RasterBench {
            cam,
            rasterizer: Rasterizer::new(ctx)?,
            gaussians: GpuGaussians::upload(ctx, &g)?,
        })
    }

    /// One forward pass (black background).
    pub fn forward(&self, ctx: &Context) -> Result<Frame> {
        self.rasterizer
            .forward(ctx, &self.gaussians, &self.cam, [0.0; 3])
    }

    /// Runs the forward once and prepares the inputs of the backward.
    pub fn backward_inputs(&self, ctx: &Context) -> Result<BackwardInputs> {
        let frame = self.forward(ctx)?;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let dl = random_colour_gradient(&mut rng, (self.cam.width * self.cam.height) as usize);
        Ok(BackwardInputs {
            frame,
            colour_grad: Buffer::from_slice(ctx, "bench colour gradient", &dl)?,
            grads: GpuGrads::new(ctx, self.gaussians.n, self.gaussians.sh_degree)?,
        })
    }

    /// One backward pass with `bwd`; returns its GPU timings.
    pub fn backward(&self, ctx: &Context, bwd: &Backward, b: &BackwardInputs) -> Result<Timings> {
        bwd.run(
            ctx,
            &b.frame,
            &self.gaussians,
            &self.cam,
            &b.colour_grad,
            &b.grads,
        )
    }
}

/// Full GPU forward pass on the bench scene.
pub fn bench_forward(
    ctx: &Context,
    n: usize,
    width: u32,
    height: u32,
    runs: usize,
) -> Result<RasterFigures> {
    let b = RasterBench::new(ctx, n, width, height)?;
    let mut m = 0;
    let ms = time(runs, || {
        m = b.forward(ctx)?.intersections;
        Ok(())
    })?;
    Ok(RasterFigures::measured(n, width, height, m, ms))
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
    let b = RasterBench::new(ctx, n, width, height)?;
    let bwd = Backward::new(ctx, false)?;
    let inputs = b.backward_inputs(ctx)?;
    let ms = time(runs, || b.backward(ctx, &bwd, &inputs).map(|_| ()))?;
    Ok(RasterFigures::measured(
        n,
        width,
        height,
        inputs.frame.intersections,
        ms,
    ))
}

/// `[gaussians] [size]` from the command line of the profiling examples, with defaults.
pub fn profile_args(default_gaussians: usize, default_size: u32) -> (usize, u32) {
    let arg = |i: usize| std::env::args().nth(i);
    (
        arg(1)
            .and_then(|s| s.parse().ok())
            .unwrap_or(default_gaussians),
        arg(2).and_then(|s| s.parse().ok()).unwrap_or(default_size),
    )
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
    RasterFigures::measured(n, width, height, intersections, ms)
}

/// Latency of the diffusion models at the batch sizes the guidance rules use.
#[derive(Debug, Clone, Serialize)]
pub struct DiffusionFigures {
    pub models: String,
    pub provider: String,
    pub precision: String,
    /// Latent height and width.
    pub latent: [usize; 2],
    /// Median UNet latency per batch size ("1": ISM's null-prompt steps, "2": SDS's positive and
    /// negative, "3": one MTS / pseudo-GT / editing point).
    pub unet_ms: std::collections::BTreeMap<String, f64>,
    /// The text encoder on the three prompts of one conditioning.
    pub text_encoder_ms: f64,
    pub vae_encode_ms: Option<f64>,
    pub vae_decode_ms: f64,
    pub taesd_encode_ms: Option<f64>,
    pub taesd_decode_ms: Option<f64>,
}

/// Times the pipeline in `dir` (median of `runs` after one warm-up run each).
pub fn bench_diffusion(
    dir: &std::path::Path,
    opts: &crate::diffusion::model::ModelOptions,
    latent: Option<(usize, usize)>,
    runs: usize,
) -> std::result::Result<DiffusionFigures, String> {
    use crate::diffusion::model::{Codec, StableDiffusion};
    let mut sd = StableDiffusion::open(dir, opts)?;
    let hw = match latent {
        Some(hw) => hw,
        None => sd.default_latent_size(),
    };
    let runs = runs.max(1);
    let time_ms = |f: &mut dyn FnMut() -> std::result::Result<(), String>| {
        f()?;
        let mut v = vec![];
        for _ in 0..runs {
            let t = Instant::now();
            f()?;
            v.push(t.elapsed().as_secs_f64() * 1e3);
        }
        Ok::<f64, String>(median(v))
    };
    let prompts = [
        "A DSLR photo of a wooden chair, front view",
        "unrealistic, blurry",
        "",
    ];
    let text_encoder_ms = time_ms(&mut || sd.encode_text(&prompts).map(|_| ()))?;
    let emb = sd.encode_text(&prompts)?;
    let n = sd.latent_channels * hw.0 * hw.1;
    let x: Vec<f32> = (0..n).map(|i| ((i as f32) * 0.37).sin()).collect();
    let mut unet_ms = std::collections::BTreeMap::new();
    for b in 1..=3 {
        let samples: Vec<&[f32]> = vec![&x; b];
        let conds: Vec<_> = emb.iter().take(b).collect();
        let ms = time_ms(&mut || sd.unet_batch(&samples, hw, 500, &conds).map(|_| ()))?;
        unet_ms.insert(b.to_string(), ms);
    }
    let vae_decode_ms = time_ms(&mut || sd.decode(&x, 1, hw, Codec::Vae).map(|_| ()))?;
    let (img, ihw) = sd.decode(&x, 1, hw, Codec::Vae)?;
    let vae_encode_ms = time_ms(&mut || sd.encode(&img, 1, ihw, Codec::Vae).map(|_| ())).ok();
    let (taesd_encode_ms, taesd_decode_ms) = if sd.has_fast_codec() {
        (
            time_ms(&mut || sd.encode(&img, 1, ihw, Codec::Fast).map(|_| ())).ok(),
            Some(time_ms(&mut || {
                sd.decode(&x, 1, hw, Codec::Fast).map(|_| ())
            })?),
        )
    } else {
        (None, None)
    };
    Ok(DiffusionFigures {
        models: dir.display().to_string(),
        provider: format!("{:?}", opts.provider).to_lowercase(),
        precision: sd.precision().to_string(),
        latent: [hw.0, hw.1],
        unet_ms,
        text_encoder_ms,
        vae_encode_ms,
        vae_decode_ms,
        taesd_encode_ms,
        taesd_decode_ms,
    })
}

/// One formation iteration of object generation, split by where its time goes.
#[derive(Debug, Clone, Serialize)]
pub struct GenerateFigures {
    pub gaussians: u32,
    pub views: usize,
    pub size: u32,
    /// Median wall time of an iteration.
    pub wall_ms: f64,
    /// Median GPU time from timestamps: the views' forward passes, their backward passes and
    /// Adam (the oracle's reference renders count as prior time).
    pub kernel_ms: f64,
    /// Median time in the prior (the oracle: its reference render and the guidance maths).
    pub prior_ms: f64,
    /// Median of wall − kernel − prior: allocation, readbacks, submissions, the loss and
    /// bookkeeping on the host.
    pub host_ms: f64,
    /// host / kernel.
    pub host_share: f64,
    pub iterations_per_s: f64,
    /// Whether the device writes timestamps (without them kernel time reads 0).
    pub timestamps: bool,
}

impl GenerateFigures {
    /// The medians of the iterations' wall, kernel, prior and host times (ms) of `n` Gaussians,
    /// `views` views of `size`².
    fn from_runs(
        ctx: &Context,
        (n, views, size): (usize, usize, u32),
        runs: &[crate::generate::object::IterationReport],
    ) -> Self {
        let of = |f: &dyn Fn(&crate::generate::object::IterationReport) -> f64| {
            median(runs.iter().map(f).collect())
        };
        let wall = of(&|r| r.seconds * 1e3);
        let kernel = of(&|r| r.kernels.total_ms());
        let prior = of(&|r| r.prior_seconds * 1e3);
        let host = of(&|r| (r.seconds - r.prior_seconds) * 1e3 - r.kernels.total_ms());
        GenerateFigures {
            gaussians: n as u32,
            views,
            size,
            wall_ms: wall,
            kernel_ms: kernel,
            prior_ms: prior,
            host_ms: host,
            host_share: host / kernel.max(1e-9),
            iterations_per_s: 1e3 / wall,
            timestamps: ctx.info().timestamp_period_ns > 0.0,
        }
    }
}

/// The sizes `dreamscene bench --generate` measures: the 4 views at 256² (the
/// oracle-recovery runs) and 512² (the paper's object resolution), with 20k Gaussians (an object
/// early in formation) and 100k (a densified one).
pub const GENERATE_SIZES: [(usize, u32); 4] =
    [(20_000, 256), (20_000, 512), (100_000, 256), (100_000, 512)];

/// A random cloud of `n` Gaussians filling the middle of `frame`, with scales shrinking as
/// the count grows (as [`bench_scene`]).
fn object_cloud(frame: &crate::camera::object::ObjectFrame, n: usize, seed: u64) -> Gaussians {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let c = frame.centre();
    let lo = std::array::from_fn(|a| (c[a] - 0.35 * frame.size[a]) as f32);
    let hi = std::array::from_fn(|a| (c[a] + 0.35 * frame.size[a]) as f32);
    let scale = 0.01 * (20_000.0 / n.max(1) as f32).cbrt();
    Gaussians::random(&mut rng, n, lo, hi, scale, 0)
}

/// Times formation iterations ([`crate::generate::object::formation_iteration`], the loop
/// body of object generation) with the oracle prior, whose reference is another random
/// cloud: `views` views of `size`² a step, `n` Gaussians, median of `runs` after two warm-ups.
/// The iterations stay before the first densification, so `n` holds throughout.
pub fn bench_generate(
    ctx: &Context,
    n: usize,
    views: usize,
    size: u32,
    runs: usize,
) -> std::result::Result<GenerateFigures, crate::generate::object::GenError> {
    use crate::camera::object::OrbitRanges;
    use crate::generate::object::{formation_guide, formation_iteration, formation_trainer};
    use crate::generate::prior::OraclePrior;
    let (frame, cfg) = bench_object(views, size);
    let reference = object_cloud(&frame, n, 11);
    let mut prior = OraclePrior::new(ctx, &reference, None)?;
    let mut t = formation_trainer(ctx, &object_cloud(&frame, n, 12), &frame, &cfg)?;
    t.set_timed(true);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(13);
    let mut guide = formation_guide(&cfg);
    let ranges = OrbitRanges::default();
    let mut reports = vec![];
    for i in 0..runs.max(1) + 2 {
        let r = formation_iteration(
            &mut t, &mut prior, &mut guide, &mut rng, &frame, &ranges, &cfg,
        )?;
        if i >= 2 {
            reports.push(r);
        }
    }
    Ok(GenerateFigures::from_runs(ctx, (n, views, size), &reports))
}

/// The sizes of the scene-stage measurement: a furnished room's cloud (1M), the most lavapipe's
/// 128 MiB storage bindings hold (2.5M; projected splats take 48 bytes each) and the authors'
/// environment cap (3M, on GPUs), 4 views at 512².
pub const SCENE_STAGE_SIZES: [(usize, u32); 3] =
    [(1_000_000, 512), (2_500_000, 512), (3_000_000, 512)];

/// Times environment-stage iterations ([`crate::generate::object::guided_iteration`] on the
/// stage-1 camera list, the scene stages' loop body) with the oracle prior: `n` random
/// Gaussians (SH degree 0) filling a 5 x 4 x 2.8 m room, the last two thirds trainable (the environment),
/// `views` views of `size`², median of `runs` after one warm-up.
pub fn bench_scene_stage(
    ctx: &Context,
    n: usize,
    views: usize,
    size: u32,
    runs: usize,
) -> std::result::Result<GenerateFigures, crate::generate::object::GenError> {
    use crate::camera::scene::{stage_cameras, SceneBox, Stage};
    use crate::diffusion::guidance::{MtsSettings, SCENE_ENVIRONMENT};
    use crate::diffusion::model::Codec;
    use crate::diffusion::target::{Guide, Rule};
    use crate::generate::object::guided_iteration;
    use crate::generate::prior::OraclePrior;
    use crate::generate::scene_stages::{stage_fit, stage_views};
    use crate::splat::train::Trainer;
    let room = [5.0, 4.0, 2.8];
    let cloud = |seed: u64| {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let lo = [-2.5f32, -2.0, 0.0];
        let hi = [2.5f32, 2.0, 2.8];
        let scale = 0.01 * (1_000_000.0 / n.max(1) as f32).cbrt();
        // SH degree 0: at degree 1 the SH of 3M Gaussians (144 MB) passes lavapipe's 128 MiB
        // storage-binding limit.
        Gaussians::random(&mut rng, n, lo, hi, scale, 0)
    };
    let mut prior = OraclePrior::new(ctx, &cloud(21), None)?;
    let mut t = Trainer::guided(ctx, &cloud(22), stage_fit(1000, 0), 1.0)?;
    t.set_timed(true);
    let scene = SceneBox {
        scene_type: crate::plan::spec::SceneType::Indoor,
        room,
        objects: vec![],
        openings: vec![],
    };
    let iters = runs.max(1) as u32 + 1;
    let cams = stage_cameras(Stage::One, &scene, iters as usize * views, size, size, 5);
    let mut guide = Guide::new(
        Rule::Mts { m: 4 },
        SCENE_ENVIRONMENT,
        MtsSettings::default(),
        Codec::Fast,
        6,
    );
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(23);
    let trainable = Some(n as u32 / 3..n as u32);
    let mut reports = vec![];
    for i in 0..iters {
        let v = stage_views(&cams, i, views, iters, &mut rng);
        let r = guided_iteration(&mut t, &mut prior, &mut guide, &v, trainable.clone())?;
        if i > 0 {
            reports.push(r);
        }
    }
    Ok(GenerateFigures::from_runs(ctx, (n, views, size), &reports))
}

/// The object the generation benches optimise: a chair-sized frame, `views` views a step at
/// `size`², SH degree 0, no checkpoints.
pub(crate) fn bench_object(
    views: usize,
    size: u32,
) -> (
    crate::camera::object::ObjectFrame,
    crate::generate::object::ObjectConfig,
) {
    let frame = crate::camera::object::ObjectFrame {
        size: [1.0, 0.8, 0.9],
    };
    let cfg = crate::generate::object::ObjectConfig {
        batch: views,
        resolution: size,
        sh_degree: 0,
        checkpoint_every: 0,
        ..Default::default()
    };
    (frame, cfg)
}
