//! GPU backward pass (native and compare-and-swap atomics) against the f64 CPU reference
//! gradients on random scenes, and on a tile holding 100,000 splats.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::Camera;
use dreamscene::gpu::{Buffer, Context};
use dreamscene::splat::backward::{Backward, GpuGrads, HostGrads};
use dreamscene::splat::raster::{BlendWidth, GpuGaussians, Rasterizer};
use dreamscene::splat::reference::Cutoffs;
use dreamscene::splat::reference_grad::{self, Grad2d, Grads};
use dreamscene::splat::Gaussians;

fn camera(w: u32, h: u32) -> Camera {
    Camera::look_at(
        [0.2, -0.1, -0.3],
        [0.0, 0.0, 3.0],
        [0.0, -1.0, 0.0],
        w,
        h,
        60f64.to_radians(),
    )
}

/// Largest |gpu - reference| of one parameter array (`k` values per Gaussian), relative to the
/// array's largest reference magnitude, over the Gaussians not marked `skip`. NaN counts as
/// infinitely wrong.
fn rel_err(gpu: &[f32], cpu: &[f64], k: usize, skip: &[bool]) -> f64 {
    assert_eq!(
        gpu.len(),
        cpu.len(),
        "the GPU and CPU gradients differ in length"
    );
    let scale = cpu.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut worst = 0.0f64;
    for (j, (a, b)) in gpu.iter().zip(cpu).enumerate() {
        if skip[j / k] {
            continue;
        }
        let d = (*a as f64 - b).abs();
        worst = if d.is_nan() {
            f64::INFINITY
        } else {
            worst.max(d)
        };
    }
    worst / scale.max(1e-12)
}

fn flat<const K: usize>(v: &[[f32; K]]) -> Vec<f32> {
    v.iter().flatten().copied().collect()
}
fn flat64<const K: usize>(v: &[[f64; K]]) -> Vec<f64> {
    v.iter().flatten().copied().collect()
}

struct Run {
    gpu: HostGrads,
    cpu: Grads,
    cpu2d: Vec<Grad2d>,
    /// Gaussians within f32 rounding of a blending cutoff at some pixel (see `near_cutoffs`).
    skip: Vec<bool>,
}

fn run(ctx: &Context, bwd: &Backward, g: &Gaussians, cam: &Camera, bg: [f32; 3], seed: u64) -> Run {
    let r = Rasterizer::new(ctx).unwrap();
    let mut rng = common::rng(seed);
    let np = (cam.width * cam.height) as usize;
    let dl = dreamscene::bench::random_colour_gradient(&mut rng, np);
    let gg = GpuGaussians::upload(ctx, g).unwrap();
    let frame = r.forward(ctx, &gg, cam, bg).unwrap();
    let grads = GpuGrads::new(ctx, g.len() as u32, g.sh_degree).unwrap();
    let dlb = Buffer::from_slice(ctx, "dL/dcolour", &dl).unwrap();
    bwd.run(ctx, &frame, &gg, cam, &dlb, &grads).unwrap();
    let gpu = grads.download().unwrap();
    // The screen-space slots are cleared for the next view.
    let g2: Vec<f32> = grads.grad2d.read(g.len() * 9).unwrap();
    assert!(
        g2.iter().all(|&v| v == 0.0),
        "screen-space gradients not cleared"
    );
    let dl64: Vec<[f64; 3]> = dl.iter().map(|d| [0, 1, 2].map(|c| d[c] as f64)).collect();
    let (cpu2d, cpu) = reference_grad::backward(g, cam, bg.map(f64::from), &dl64, Cutoffs::Exact);
    let skip = reference_grad::near_cutoffs(g, cam, 1e-5);
    ctx.check_validation().unwrap();
    Run {
        gpu,
        cpu,
        cpu2d,
        skip,
    }
}

fn check(run: &Run, cam: &Camera, what: &str, tol: f64) {
    let skip = &run.skip;
    let n = skip.len();
    let skipped = skip.iter().filter(|&&s| s).count();
    // Rounding can only put a few Gaussians at a cutoff; many would hide a real difference.
    assert!(
        skipped * 50 <= n,
        "{what}: {skipped} of {n} Gaussians at a cutoff"
    );
    let kc = run.cpu.sh.len() / n.max(1);
    let errs = [
        (
            "means",
            rel_err(&flat(&run.gpu.means), &flat64(&run.cpu.means), 3, skip),
        ),
        (
            "scales",
            rel_err(&flat(&run.gpu.scales), &flat64(&run.cpu.scales), 3, skip),
        ),
        (
            "rotations",
            rel_err(
                &flat(&run.gpu.rotations),
                &flat64(&run.cpu.rotations),
                4,
                skip,
            ),
        ),
        (
            "opacities",
            rel_err(&run.gpu.opacities, &run.cpu.opacities, 1, skip),
        ),
        ("sh", rel_err(&run.gpu.sh, &run.cpu.sh, kc, skip)),
    ];
    eprintln!("{what}: {skipped} Gaussians at a cutoff skipped; relative errors {errs:?}");
    for (name, e) in errs {
        assert!(e < tol, "{what}: {name} gradients off by {e:e} (relative)");
    }
    // Densification statistics: NDC centre-gradient norm and visibility.
    let norms: Vec<f64> = run.cpu2d.iter().map(|g| g.ndc_norm(cam)).collect();
    let gpu_norms: Vec<f32> = run.gpu.stats.iter().map(|s| s[0]).collect();
    let e = rel_err(&gpu_norms, &norms, 1, skip);
    assert!(e < tol, "{what}: densify statistic off by {e:e}");
}

/// Most Gaussians of a random scene get a gradient: the comparison is not between zeros.
fn assert_mostly_nonzero(run: &Run, what: &str) {
    let nonzero = run.cpu.opacities.iter().filter(|v| v.abs() > 0.0).count();
    assert!(
        nonzero > run.cpu.opacities.len() / 3,
        "{what}: only {nonzero} Gaussians have gradients"
    );
}

#[test]
fn backward_matches_reference_on_random_scenes_all_sh_degrees() {
    let ctx = common::gpu();
    // One pixel per invocation (GPUs) and several (the `_wide` kernels CPU devices use).
    for width in WIDTHS {
        let bwd = Backward::with_width(&ctx, false, width).unwrap();
        let mut rng = common::rng(50);
        for (deg, (w, h), n) in [
            (0u32, (64u32, 48u32), 300usize),
            (1, (77, 50), 400),
            (2, (90, 70), 500),
            (3, (45, 61), 300),
        ] {
            let g = Gaussians::random(&mut rng, n, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.1, deg);
            let cam = camera(w, h);
            let r = run(&ctx, &bwd, &g, &cam, [0.2, 0.5, 0.9], 60 + deg as u64);
            let what = format!("{width:?}: degree {deg}, {w}x{h}");
            check(&r, &cam, &what, 1e-3);
            assert_mostly_nonzero(&r, &what);
        }
    }
}

const WIDTHS: [BlendWidth; 2] = [BlendWidth::One, BlendWidth::Wide];

/// Every (CAS atomics?, blend width) combination.
fn atomics_and_widths() -> impl Iterator<Item = (bool, BlendWidth)> {
    [false, true]
        .into_iter()
        .flat_map(|c| WIDTHS.map(|w| (c, w)))
}

fn atomics_name(cas: bool) -> &'static str {
    if cas {
        "CAS"
    } else {
        "native"
    }
}

#[test]
fn backward_with_cas_atomics_matches_reference() {
    let ctx = common::gpu();
    let mut rng = common::rng(51);
    let g = Gaussians::random(&mut rng, 400, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.1, 1);
    let cam = camera(70, 52);
    for width in WIDTHS {
        let bwd = Backward::with_width(&ctx, true, width).unwrap();
        let r = run(&ctx, &bwd, &g, &cam, [0.0, 0.0, 0.0], 61);
        let what = format!("{width:?}: CAS atomics");
        check(&r, &cam, &what, 1e-3);
        assert_mostly_nonzero(&r, &what);
    }
}

/// The 100,000-splat tile of `common::crowded_tile`: the large splats behind the crowd are
/// blended only in later segments, so their gradients are zero if any loop is cut short or the
/// running colour and T are not carried between segments.
#[test]
fn tile_with_100k_splats_differentiates_past_the_loop_limit() {
    let ctx = common::gpu();
    let (g, cam) = common::crowded_tile();
    for (cas, width) in atomics_and_widths() {
        let bwd = Backward::with_width(&ctx, cas, width).unwrap();
        let r = run(&ctx, &bwd, &g, &cam, [0.1, 0.2, 0.3], 62);
        let what = &format!("100k tile, {width:?}, {}", atomics_name(cas));
        check(&r, &cam, what, 1e-3);
        // The large splats have real gradients, and the GPU's agree with the reference's.
        for i in 100_000..100_004 {
            let c = r.cpu.opacities[i];
            assert!(c.abs() > 1e-3, "{what}: large splat {i} has gradient {c}");
            let d = (r.gpu.opacities[i] as f64 - c).abs();
            assert!(
                d < 1e-3 * c.abs(),
                "{what}: splat {i}: gpu {} cpu {c}",
                r.gpu.opacities[i]
            );
        }
    }
}

/// Devices whose subgroups can be smaller than 8 lanes add a splat's nine gradients from one
/// elected lane; lavapipe (8 lanes) normally spreads them over eight. Built for a minimum of 4,
/// the kernels take the elected-lane path, which must give the same gradients.
#[test]
fn backward_for_small_subgroups_matches_reference() {
    let ctx = common::gpu_with_min_subgroup(4);
    assert!(ctx.info().min_subgroup_size <= 4);
    let mut rng = common::rng(53);
    let g = Gaussians::random(&mut rng, 400, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.1, 2);
    let cam = camera(70, 52);
    for (cas, width) in atomics_and_widths() {
        let bwd = Backward::with_width(&ctx, cas, width).unwrap();
        let r = run(&ctx, &bwd, &g, &cam, [0.1, 0.0, 0.2], 63);
        let what = &format!("small subgroups, {width:?}, {}", atomics_name(cas));
        check(&r, &cam, what, 1e-3);
        assert_mostly_nonzero(&r, what);
    }
}
