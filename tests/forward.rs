//! GPU forward pass against the f64 CPU reference on random scenes and edge cases.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::Camera;
use dreamscene::splat::raster::{BlendWidth, Rasterizer, RenderOutput};
use dreamscene::splat::reference::{self, RefImage};
use dreamscene::splat::reference_grad;
use dreamscene::splat::Gaussians;

fn front_camera(w: u32, h: u32) -> Camera {
    Camera::look_at(
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, -1.0, 0.0],
        w,
        h,
        60f64.to_radians(),
    )
}

/// Largest absolute differences (colour, transmittance, depth / max depth) between GPU and CPU,
/// leaving out the pixels where a splat sits within 1e-5 of a blending cutoff (there f32 and f64
/// may round to opposite sides: seen on an NVIDIA driver, whose `exp` differs from lavapipe's).
/// Such pixels must be rare: at most one in 200.
fn compare(gpu: &RenderOutput, cpu: &RefImage, g: &Gaussians, cam: &Camera) -> (f64, f64, f64) {
    let skip = reference_grad::near_cutoff_pixels(g, cam, 1e-5);
    let skipped = skip.iter().filter(|s| **s).count();
    assert!(
        skipped * 200 <= skip.len(),
        "{skipped} of {} pixels near a cutoff",
        skip.len()
    );
    assert_eq!(
        gpu.color.len(),
        cpu.color.len(),
        "the GPU and CPU images differ in size"
    );
    // A NaN difference (e.g. an output the kernel never wrote) counts as infinitely wrong;
    // f64::max alone would skip it.
    let worst = |m: f64, d: f64| if d.is_nan() { f64::INFINITY } else { m.max(d) };
    let mut dc: f64 = 0.0;
    let mut dt: f64 = 0.0;
    let mut dd: f64 = 0.0;
    for (i, &skip_pixel) in skip.iter().enumerate() {
        assert!(
            gpu.color[i].iter().all(|v| v.is_finite()),
            "non-finite pixel {i}"
        );
        if skip_pixel {
            continue;
        }
        for c in 0..3 {
            dc = worst(dc, (gpu.color[i][c] as f64 - cpu.color[i][c]).abs());
        }
        dt = worst(
            dt,
            (gpu.transmittance[i] as f64 - cpu.transmittance[i]).abs(),
        );
        dd = worst(dd, (gpu.depth[i] as f64 - cpu.depth[i]).abs() / 4.0);
    }
    (dc, dt, dd)
}

fn check_scene(
    r: &Rasterizer,
    ctx: &dreamscene::gpu::Context,
    g: &Gaussians,
    cam: &Camera,
    bg: [f32; 3],
    what: &str,
) -> RenderOutput {
    let gpu = r.render(ctx, g, cam, bg).unwrap();
    let cpu = reference::render(g, cam, bg.map(f64::from));
    let (dc, dt, dd) = compare(&gpu, &cpu, g, cam);
    // f32 against f64: measured ~5e-7 on lavapipe; 2e-5 leaves room for other drivers.
    eprintln!("{what}: max diff colour {dc:e}, T {dt:e}, depth {dd:e}");
    assert!(
        dc < 2e-5 && dt < 2e-5 && dd < 2e-5,
        "{what}: max |diff| colour {dc:e}, T {dt:e}, depth {dd:e}"
    );
    gpu
}

#[test]
fn forward_matches_reference_on_random_scenes_all_sh_degrees() {
    let ctx = common::gpu();
    for width in [BlendWidth::One, BlendWidth::Wide] {
        forward_matches_reference_with(&ctx, width);
    }
    ctx.check_validation().unwrap();
}

/// One pixel per invocation (GPUs) and several (the `_wide` kernels CPU devices use).
fn forward_matches_reference_with(ctx: &dreamscene::gpu::Context, width: BlendWidth) {
    let r = Rasterizer::with_width(ctx, width).unwrap();
    let mut rng = common::rng(10);
    for (deg, (w, h), n) in [
        (0u32, (64u32, 48u32), 300usize),
        (1, (77, 50), 500),
        (2, (128, 96), 800),
        (3, (100, 131), 500),
    ] {
        let g = Gaussians::random(&mut rng, n, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.1, deg);
        let out = check_scene(
            &r,
            ctx,
            &g,
            &front_camera(w, h),
            [0.2, 0.5, 0.9],
            &format!("{width:?}: degree {deg}, {w}x{h}"),
        );
        // The scene is not trivially empty: most pixels are covered.
        let covered = out.transmittance.iter().filter(|&&t| t < 0.5).count();
        assert!(
            covered > out.transmittance.len() / 4,
            "degree {deg}: only {covered} covered pixels"
        );
    }
}

#[test]
fn empty_offscreen_and_behind_scenes_render_background() {
    let ctx = common::gpu();
    let r = Rasterizer::new(&ctx).unwrap();
    let mut rng = common::rng(11);
    let cam = front_camera(40, 33);
    let bg = [0.25f32, 0.5, 0.75];
    let empty = Gaussians {
        sh_degree: 0,
        ..Default::default()
    };
    let behind = Gaussians::random(&mut rng, 200, [-1.0, -1.0, -4.0], [1.0, 1.0, 0.1], 0.1, 1);
    let offscreen = Gaussians::random(&mut rng, 200, [30.0, 30.0, 2.0], [40.0, 40.0, 3.0], 0.1, 0);
    for (g, what) in [
        (empty, "empty"),
        (behind, "behind the near plane"),
        (offscreen, "off-screen"),
    ] {
        let out = r.render(&ctx, &g, &cam, bg).unwrap();
        for (i, c) in out.color.iter().enumerate() {
            assert_eq!(*c, bg, "{what}: pixel {i}");
            assert_eq!(out.transmittance[i], 1.0, "{what}: pixel {i}");
        }
    }
    ctx.check_validation().unwrap();
}

#[test]
fn huge_splats_and_mixed_sizes_match_reference() {
    let ctx = common::gpu();
    let r = Rasterizer::new(&ctx).unwrap();
    let mut rng = common::rng(12);
    let mut g = Gaussians::random(&mut rng, 50, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.02, 2);
    let big = Gaussians::random(&mut rng, 6, [-0.5, -0.5, 1.0], [0.5, 0.5, 5.0], 3.0, 2);
    g.means.extend(big.means);
    g.scales.extend(big.scales);
    g.rotations.extend(big.rotations);
    g.opacities.extend(big.opacities);
    g.sh.extend(big.sh);
    check_scene(
        &r,
        &ctx,
        &g,
        &front_camera(90, 70),
        [0.0, 0.0, 0.0],
        "huge splats",
    );
    ctx.check_validation().unwrap();
}

#[test]
fn nan_and_inf_inputs_are_culled_without_poisoning_others() {
    let ctx = common::gpu();
    let r = Rasterizer::new(&ctx).unwrap();
    let mut rng = common::rng(13);
    let g = Gaussians::random(&mut rng, 300, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.06, 1);
    let mut bad = g.clone();
    let nan = f32::NAN;
    bad.means[3][0] = nan;
    bad.scales[7][1] = f32::INFINITY;
    bad.rotations[11] = [0.0; 4];
    bad.opacities[13] = nan;
    bad.sh[17 * 12] = f32::NEG_INFINITY;
    bad.rotations[19][2] = nan;
    let cam = front_camera(64, 64);
    let out = r.render(&ctx, &bad, &cam, [1.0, 1.0, 1.0]).unwrap();
    // The same as the scene without the broken Gaussians.
    let mut clean = g.clone();
    for i in [19usize, 17, 13, 11, 7, 3] {
        clean.means.remove(i);
        clean.scales.remove(i);
        clean.rotations.remove(i);
        clean.opacities.remove(i);
        clean.sh.drain(i * 12..(i + 1) * 12);
    }
    let cpu = reference::render(&clean, &cam, [1.0; 3]);
    let (dc, dt, _) = compare(&out, &cpu, &clean, &cam);
    assert!(dc < 2e-5 && dt < 2e-5, "colour {dc:e}, T {dt:e}");
    ctx.check_validation().unwrap();
}

/// lavapipe silently ends every shader invocation's loops after 65,535 iterations: the tile of
/// `common::crowded_tile` would leave its far-corner pixels background if the blend ran past it.
#[test]
fn tile_with_100k_splats_renders_past_the_loop_limit() {
    let ctx = common::gpu();
    let (g, cam) = common::crowded_tile();
    let cpu = reference::render(&g, &cam, [0.0; 3]);
    let far = 15 * 16 + 15;
    assert!(
        cpu.transmittance[far] < 0.9,
        "the far pixel is covered in the reference: T {} {:?}",
        cpu.transmittance[far],
        &cpu.transmittance[..20]
    );
    for width in [BlendWidth::One, BlendWidth::Wide] {
        let r = Rasterizer::with_width(&ctx, width).unwrap();
        let gpu = r.render(&ctx, &g, &cam, [0.0, 0.0, 0.0]).unwrap();
        let gg = dreamscene::splat::raster::GpuGaussians::upload(&ctx, &g).unwrap();
        let frame = r.forward(&ctx, &gg, &cam, [0.0; 3]).unwrap();
        assert!(
            frame.max_tile_len > 100_000,
            "the tile holds {} splats",
            frame.max_tile_len
        );
        let (dc, dt, dd) = compare(&gpu, &cpu, &g, &cam);
        assert!(
            dc < 2e-5 && dt < 2e-5 && dd < 2e-5,
            "{width:?}: colour {dc:e}, T {dt:e}, depth {dd:e}"
        );
    }
    ctx.check_validation().unwrap();
}

/// A frame rendered into again (after a larger view of a larger cloud, so its buffers and the
/// rasterizer's scratch hold stale data past the new sizes) gives the same image, bit for bit,
/// as a fresh forward pass, and the same backward gradients (up to the float atomics' order).
#[test]
fn reused_frame_matches_a_fresh_forward() {
    use dreamscene::splat::backward::{Backward, GpuGrads};
    use dreamscene::splat::raster::{Frame, GpuGaussians};
    let ctx = common::gpu();
    let mut rng = common::rng(77);
    let big = Gaussians::random(&mut rng, 3000, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.05, 1);
    let small = Gaussians::random(&mut rng, 800, [-1.0, -1.0, 2.0], [1.0, 1.0, 4.0], 0.08, 1);
    let r = Rasterizer::new(&ctx).unwrap();
    let (gb, gs) = (
        GpuGaussians::upload(&ctx, &big).unwrap(),
        GpuGaussians::upload(&ctx, &small).unwrap(),
    );
    let cam = front_camera(72, 56);
    let bg = [0.2, 0.5, 0.9];
    let mut frame = Frame::new(&ctx).unwrap();
    r.forward_into(
        &ctx,
        &gb,
        &front_camera(160, 128),
        [0.3; 3],
        &mut frame,
        true,
    )
    .unwrap();
    r.forward_into(&ctx, &gs, &cam, bg, &mut frame, true)
        .unwrap();
    let fresh = Rasterizer::new(&ctx)
        .unwrap()
        .forward(&ctx, &gs, &cam, bg)
        .unwrap();
    let (a, b) = (frame.read().unwrap(), fresh.read().unwrap());
    assert_eq!(frame.intersections, fresh.intersections);
    assert_eq!(frame.max_tile_len, fresh.max_tile_len);
    assert!(a.color == b.color && a.depth == b.depth && a.transmittance == b.transmittance);
    assert_eq!(frame.colour().unwrap(), b.color);
    let np = (cam.width * cam.height) as usize;
    let dl: Vec<[f32; 4]> = (0..np)
        .map(|i| [((i % 7) as f32 - 3.0) * 0.1, 0.2, -0.1, 0.0])
        .collect();
    let dl = dreamscene::gpu::Buffer::from_slice(&ctx, "dl", &dl).unwrap();
    let bwd = Backward::new(&ctx, false).unwrap();
    let grads = |f: &Frame| {
        let g = GpuGrads::new(&ctx, gs.n, gs.sh_degree).unwrap();
        bwd.run(&ctx, f, &gs, &cam, &dl, &g).unwrap();
        let mut v: Vec<f32> = g.means.read(3 * gs.n as usize).unwrap();
        v.extend(g.opacities.read::<f32>(gs.n as usize).unwrap());
        v
    };
    let (ga, gf) = (grads(&frame), grads(&fresh));
    let worst = ga
        .iter()
        .zip(&gf)
        .map(|(p, q)| (p - q).abs() / (1.0 + q.abs()))
        .fold(0.0f32, f32::max);
    assert!(worst <= 1e-5, "gradients differ by {worst:e}");
}
