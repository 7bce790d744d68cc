//! Helpers shared by the tests (GPU devices and fixtures, placed objects for layout checks).
#![allow(dead_code, reason = "each test crate uses some of the shared helpers")]
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
pub mod placed;
pub mod samples;

use dreamscene::gpu::Context;
use rand::{Rng, SeedableRng};

/// Opens the Vulkan device. A GPU test never passes without one: no device is a failure, with
/// the reason (install mesa-vulkan-drivers for lavapipe).
pub fn gpu() -> Context {
    checked(Context::new())
}

/// As [`gpu`], with kernels built for subgroups as small as `n` (the general paths).
pub fn gpu_with_min_subgroup(n: u32) -> Context {
    checked(Context::with_min_subgroup_size(n))
}

fn checked(ctx: dreamscene::gpu::Result<Context>) -> Context {
    let ctx = ctx.unwrap_or_else(|e| panic!("GPU test needs a Vulkan device and found none: {e}"));
    if std::env::var("DREAMSCENE_REQUIRE_VALIDATION").is_ok_and(|v| v == "1") {
        assert!(
            ctx.info().validation,
            "validation layer required but not active"
        );
    }
    ctx
}

/// Deterministic RNG for a test.
pub fn rng(seed: u64) -> rand_chacha::ChaCha8Rng {
    rand_chacha::ChaCha8Rng::seed_from_u64(seed)
}

/// One 16x16 tile holding 100,000 tiny splats in its top-left corner, in front of four large
/// anisotropic ones: pixels in the far corner only get colour from the large splats, which come
/// after index 100,000 in the tile's list, so any blend (or blend backward) loop that runs past
/// lavapipe's 65,535-iteration limit in one invocation leaves them wrong.
pub fn crowded_tile() -> (dreamscene::splat::Gaussians, dreamscene::camera::Camera) {
    let mut rng = rng(14);
    let cam = dreamscene::camera::Camera::look_at(
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, -1.0, 0.0],
        16,
        16,
        60f64.to_radians(),
    );
    let f = cam.fx as f32;
    let mut g = dreamscene::splat::Gaussians {
        sh_degree: 0,
        ..Default::default()
    };
    for _ in 0..100_000 {
        let z = rng.gen_range(2.0f32..2.5);
        let (u, v) = (rng.gen_range(1.0f32..3.0), rng.gen_range(1.0f32..3.0));
        g.means.push([(u - 8.0) * z / f, (v - 8.0) * z / f, z]);
        g.scales.push([(0.002f32).ln(); 3]);
        g.rotations.push([1.0, 0.0, 0.0, 0.0]);
        g.opacities.push(0.0);
        g.sh.extend([rng.gen_range(-1.0f32..1.0), 0.5, -0.5]);
    }
    for k in 0..4 {
        g.means
            .push([0.05 * k as f32, -0.05 * k as f32, 3.5 + 0.1 * k as f32]);
        g.scales.push([(3.0f32).ln(), (2.0f32).ln(), (1.5f32).ln()]);
        g.rotations.push([1.0, 0.1 * k as f32, 0.2, 0.0]);
        g.opacities.push(-1.0);
        g.sh.extend([1.2, -1.0, 0.3 * k as f32]);
    }
    (g, cam)
}

/// Two clusters of `n` small opaque Gaussians each (normal spread `sigma`), red around
/// x = +0.5 and blue around x = −0.5, 0.5 m above the floor, written to `path` as a splat PLY.
pub fn two_clusters(path: &std::path::Path, n: usize, sigma: f32, seed: u64) {
    use rand_distr::{Distribution, Normal};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let normal = Normal::new(0.0f32, sigma).unwrap();
    let mut g = dreamscene::splat::Gaussians::default();
    for (cx, col) in [(0.5f32, [1.0f32, 0.0, 0.0]), (-0.5, [0.0, 0.0, 1.0])] {
        for _ in 0..n {
            g.means.push([
                cx + normal.sample(&mut rng),
                normal.sample(&mut rng),
                0.5 + normal.sample(&mut rng),
            ]);
            g.scales.push([-3.5; 3]);
            g.rotations.push([1.0, 0.0, 0.0, 0.0]);
            g.opacities.push(4.0);
            g.sh.extend(col.map(|c| ((c as f64 - 0.5) / dreamscene::splat::cloud::SH_C0) as f32));
        }
    }
    dreamscene::splat::ply::write_ply(path, &g).unwrap();
}

/// Recolours a cloud of degree-0 colour: `f(position, colour) -> colour`.
pub fn recolour(g: &mut dreamscene::splat::Gaussians, f: impl Fn([f32; 3], [f32; 3]) -> [f32; 3]) {
    use dreamscene::splat::cloud::SH_C0;
    let k3 = g.coeffs() * 3;
    for i in 0..g.len() {
        let c: [f32; 3] = std::array::from_fn(|ch| 0.5 + SH_C0 as f32 * g.sh[i * k3 + ch]);
        let n = f(g.means[i], c);
        for (ch, v) in n.iter().enumerate() {
            g.sh[i * k3 + ch] = (v - 0.5) / SH_C0 as f32;
        }
    }
}

/// Starts `cmd` (stderr dropped) and SIGKILLs it as soon as the JSON file `state` satisfies
/// `reached`; fails if the run ends first or nothing is reached within `limit_s` seconds.
pub fn kill_when(
    cmd: &mut std::process::Command,
    state: &std::path::Path,
    reached: impl Fn(&serde_json::Value) -> bool,
    limit_s: u64,
) {
    let mut child = cmd.stderr(std::process::Stdio::null()).spawn().unwrap();
    let t0 = std::time::Instant::now();
    loop {
        if let Ok(text) = std::fs::read_to_string(state) {
            let j: serde_json::Value = serde_json::from_str(&text).unwrap_or_default();
            if reached(&j) {
                break;
            }
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "finished before the kill"
        );
        assert!(
            t0.elapsed().as_secs() < limit_s,
            "{} reached nothing in {limit_s} s",
            state.display()
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
}

/// A placed object for hand-built layouts: its category is its id without the trailing number.
pub fn obj(
    id: &str,
    size: [f64; 3],
    pos: [f64; 3],
    yaw: f64,
) -> dreamscene::plan::spec::PlacedObject {
    use dreamscene::plan::spec::{Anchor, PlacedBy, PlacedObject};
    PlacedObject {
        id: id.into(),
        category: id.trim_end_matches(char::is_numeric).into(),
        size,
        position: pos,
        yaw,
        anchor: Anchor::Others,
        placed_by: PlacedBy::Constraint,
    }
}

/// Whether a test may use an outside tool that `scripts/setup.sh` installs (Blender, Slurm,
/// kubernetes-validate): `problem` is `None` when it can run, or one line saying what is missing
/// and how to install it. A missing tool fails the test with that line, since a check that
/// passes without running is a defect. `DREAMSCENE_SKIP_EXTERNAL` (comma-separated names, or
/// `all`) opts out explicitly; the test then prints that it skipped and returns false.
pub fn external_tool(name: &str, problem: Option<String>) -> bool {
    let opted_out = std::env::var("DREAMSCENE_SKIP_EXTERNAL").is_ok_and(|v| {
        v.split(',')
            .map(str::trim)
            .any(|n| n.eq_ignore_ascii_case(name) || n.eq_ignore_ascii_case("all"))
    });
    if opted_out {
        println!("SKIPPED the {name} check: DREAMSCENE_SKIP_EXTERNAL names {name}");
        return false;
    }
    if let Some(p) = problem {
        panic!("{p}; or set DREAMSCENE_SKIP_EXTERNAL={name} to skip this check");
    }
    true
}

/// Runs `dreamscene edit DIR ARGS…` without models (the scene's own prior), as a user would.
pub fn edit(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .env_remove("DREAMSCENE_MODELS")
        .arg("edit")
        .arg(dir)
        .args(args)
        .output()
        .unwrap()
}
