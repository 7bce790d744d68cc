//! Scene generation with the oracle prior: a reference scene directory (two objects, a
//! checkered room) is regenerated from its own layout through the object pipeline and the three
//! environment stages, starting from draft colours; views from inside the room that training
//! never used must reach 22 dB. Killed mid-stage, `--resume` finishes the run.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::scene::{explore_path, SceneBox};
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{Layout, SceneSpec};
use dreamscene::scene::dir::{compose_scene, read_scene};
use dreamscene::splat::loss::psnr;
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};
use std::process::Command;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-scene-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

const PROMPT: &str = "a tiny bedroom with a bed and a nightstand";

/// A 3 x 3 x 2.4 m room with a bed and a nightstand.
fn spec() -> SceneSpec {
    serde_json::from_str(
        r#"{"scene_type": "indoor", "scene_text": "a tiny bedroom",
            "room": {"size": [3.0, 3.0, 2.4]},
            "objects": {
              "bed": {"number": 1, "size": [1.4, 1.9, 0.9], "description": "A DSLR photo of a wooden bed"},
              "nightstand": {"number": 1, "size": [0.45, 0.4, 0.55], "description": "A DSLR photo of a white nightstand"}},
            "anchors": {"bed1": "SIDE"},
            "relations": [{"subject": "nightstand1", "relation": "NEXT", "object": "bed1"}]}"#,
    )
    .unwrap()
}

/// The reference: the draft of `spec()`, its room recoloured as a two-colour checkerboard and
/// its objects with their colour channels rotated, so a run from the draft must learn both.
fn reference(dir: &Path) -> Layout {
    let spec = spec();
    let l = layout(&spec, LayoutOptions::seeded(3)).unwrap();
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(dir.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&dir.join("layout.json")).unwrap();
    write_draft_scene(dir, PROMPT, 0, &spec, &l, false, &mut |_| {}).unwrap();
    let env = dir.join("environment.ply");
    let mut g = read_ply(&env).unwrap();
    common::recolour(&mut g, |p, _| {
        let cell = (p[0] / 0.6).floor() + (p[1] / 0.6).floor() + (p[2] / 0.6).floor();
        if cell.rem_euclid(2.0) < 1.0 {
            [0.8, 0.25, 0.1]
        } else {
            [0.15, 0.35, 0.85]
        }
    });
    write_ply(&env, &g).unwrap();
    for cat in ["bed", "nightstand"] {
        let p = dir.join(format!("objects/{cat}.ply"));
        let mut g = read_ply(&p).unwrap();
        common::recolour(&mut g, |_, c| [c[2], c[0], c[1]]);
        write_ply(&p, &g).unwrap();
    }
    l
}

/// The reference directory, made once and shared (read-only) by every test of this file.
fn shared_reference() -> &'static (PathBuf, Layout) {
    static REF: std::sync::OnceLock<(PathBuf, Layout)> = std::sync::OnceLock::new();
    REF.get_or_init(|| {
        let dir = tmp("ref");
        let l = reference(&dir);
        (dir, l)
    })
}

/// The reference with every eighth Gaussian of each cloud, for the mechanics-only runs (resume,
/// shards): the oracle renders its reference for every view of every step, which costs more
/// than the small runs themselves.
fn sparse_reference() -> &'static Path {
    static REF: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    REF.get_or_init(|| {
        let (full, _) = shared_reference();
        let dir = tmp("sparse");
        std::fs::create_dir_all(dir.join("objects")).unwrap();
        for f in ["spec.json", "layout.json", "scene.json"] {
            std::fs::copy(full.join(f), dir.join(f)).unwrap();
        }
        for f in [
            "environment.ply",
            "objects/bed.ply",
            "objects/nightstand.ply",
        ] {
            let g = read_ply(&full.join(f)).unwrap();
            let keep: Vec<bool> = (0..g.len()).map(|i| i % 8 == 0).collect();
            write_ply(
                &dir.join(f),
                &dreamscene::generate::object::subset(&g, &keep),
            )
            .unwrap();
        }
        dir
    })
}

/// How big an oracle run is.
#[derive(Clone, Copy)]
enum Size {
    /// What the held-out check needs.
    Full,
    /// Mechanics only (32², a few iterations, small clouds), with enough environment
    /// iterations that the run is still going when stage 1 ends (the resume test).
    Quick,
    /// The smallest run that still runs every stage (mechanics only).
    Tiny,
}

/// The oracle run of `PROMPT` against `refdir` into `out`.
fn generate(refdir: &Path, out: &Path, size: Size, extra: &[&str]) -> Command {
    // iterations, object iterations, object and scene reconstruction passes, resolution,
    // Gaussians of each object, environment density.
    let sizes: [&str; 7] = match size {
        Size::Full => ["200", "20", "4", "8", "128", "4000", "400"],
        Size::Quick => ["12", "4", "1", "1", "32", "400", "40"],
        Size::Tiny => ["4", "2", "1", "1", "32", "400", "40"],
    };
    let [iterations, object_iterations, object_passes, passes, res, gaussians, density] = sizes;
    let mut c = Command::new(env!("CARGO_BIN_EXE_dreamscene"));
    c.env_remove("DREAMSCENE_MODELS")
        .args(["generate", PROMPT, "--out"])
        .arg(out)
        .args(["--prior", &format!("oracle:{}", refdir.display())])
        .args(["--iterations", iterations])
        .args(["--object-iterations", object_iterations])
        .args(["--object-recon-passes", object_passes])
        .args(["--recon-passes", passes])
        .args(["--resolution", res, "--renders", "0"])
        .args(["--object-gaussians", gaussians, "--env-density", density])
        .args(extra);
    c
}

/// Mean PSNR of `dir`'s scene against the reference from views along the explore path (never
/// used in training), at 128².
fn held_out(ctx: &dreamscene::gpu::Context, dir: &Path, refdir: &Path, l: &Layout) -> f64 {
    let r = Rasterizer::new(ctx).unwrap();
    let load = |d: &Path| {
        let s = read_scene(d).unwrap();
        GpuGaussians::upload(ctx, &compose_scene(d, &s).unwrap()).unwrap()
    };
    let (a, b) = (load(dir), load(refdir));
    let cams = explore_path(&SceneBox::from_layout(l), 6, 128, 128);
    let mut total = 0.0;
    for c in &cams {
        let x = r
            .forward(ctx, &a, c, [0.0; 3])
            .unwrap()
            .read()
            .unwrap()
            .color;
        let y = r
            .forward(ctx, &b, c, [0.0; 3])
            .unwrap()
            .read()
            .unwrap()
            .color;
        total += psnr(&x, &y);
    }
    total / cams.len() as f64
}

#[test]
fn oracle_scene_is_regenerated_from_its_own_layout() {
    let ctx = common::gpu();
    let (refdir, l) = shared_reference();
    let refdir = refdir.as_path();
    // The starting point: the draft of the same prompt (draft colours, channel order).
    let draft = tmp("draft");
    std::fs::create_dir_all(&draft).unwrap();
    write_draft_scene(&draft, PROMPT, 0, &spec(), l, false, &mut |_| {}).unwrap();
    let before = held_out(&ctx, &draft, refdir, l);

    let out = tmp("regen");
    let o = generate(refdir, &out, Size::Full, &[]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let scene = read_scene(&out).unwrap();
    assert_eq!(scene.prior.kind, "oracle");
    assert!(scene.stages.iter().all(|s| s.done));
    let after = held_out(&ctx, &out, refdir, l);
    println!("oracle scene: held-out PSNR {before:.2} -> {after:.2} dB");
    assert!(after >= 22.0, "held-out {after:.2} dB (from {before:.2})");
}

#[test]
fn scene_generation_killed_mid_stage_resumes() {
    let refdir = sparse_reference();
    let out = tmp("cut");
    common::kill_when(
        &mut generate(refdir, &out, Size::Quick, &["--seed", "1"]),
        &out.join("checkpoints/scene_run.json"),
        |j| j["stages_done"].as_u64().unwrap_or(0) >= 1,
        900,
    );
    assert!(!out.join("scene.json").exists());
    let o = generate(refdir, &out, Size::Quick, &["--seed", "1", "--resume"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("done before, kept"), "{err}");
    assert!(!err.contains("stage 1 done"), "stage 1 ran again: {err}");
    assert!(read_scene(&out).unwrap().stages.iter().all(|s| s.done));
    // Another seed is refused with the reason.
    let o = generate(refdir, &out, Size::Quick, &["--seed", "2", "--resume"])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("seed"));
}

fn tiny(refdir: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    generate(refdir, out, Size::Tiny, extra).output().unwrap()
}

fn ok(o: &std::process::Output) -> String {
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    String::from_utf8_lossy(&o.stdout).to_string() + &err
}

/// Largest absolute difference of any parameter of two clouds of the same size.
fn max_diff(a: &Gaussians, b: &Gaussians) -> f32 {
    assert_eq!(a.len(), b.len(), "the clouds compared differ in size");
    let flat = |g: &Gaussians| -> Vec<f32> {
        let mut v: Vec<f32> = g.means.iter().flatten().copied().collect();
        v.extend(g.scales.iter().flatten());
        v.extend(g.rotations.iter().flatten());
        v.extend(&g.opacities);
        v.extend(&g.sh);
        v
    };
    flat(a)
        .iter()
        .zip(flat(b))
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}

#[test]
fn oracle_object_shards_then_the_scene_step_equal_one_run() {
    let refdir = sparse_reference();
    let one = tmp("one");
    ok(&tiny(refdir, &one, &[]));
    // Two object shards (each its own state file), the scene step in between refused while
    // shard 1 has not run, naming its object.
    let split = tmp("split");
    let s0 = ok(&tiny(
        refdir,
        &split,
        &["--stage", "objects", "--shard", "0/2"],
    ));
    assert!(
        split.join("checkpoints/objects_run_0of2.json").is_file(),
        "{s0}"
    );
    let o = tiny(refdir, &split, &["--stage", "scene"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    let last = err.trim().lines().last().unwrap_or("");
    assert!(
        last.starts_with("error: ") && last.contains("missing objects: nightstand"),
        "{err}"
    );
    assert_eq!(err.matches("error").count(), 1, "{err}");
    ok(&tiny(
        refdir,
        &split,
        &["--stage", "objects", "--shard", "1/2"],
    ));
    assert!(split.join("checkpoints/objects_run_1of2.json").is_file());
    let s = ok(&tiny(refdir, &split, &["--stage", "scene"]));
    assert!(s.contains("done before, kept"), "{s}");
    assert!(
        !s.contains("generating"),
        "the scene step generated an object again: {s}"
    );
    // The plan and labels are the same bytes; the clouds the same up to the GPU's float noise
    // (summation order of the backward pass): two single runs of the same command differ by up
    // to 0.01-0.025 in a log-scale or opacity logit and 5e-5 m in a position, measured here.
    for f in ["scene.json", "labels.json", "layout.json", "spec.json"] {
        let (a, b) = (
            std::fs::read(one.join(f)).unwrap(),
            std::fs::read(split.join(f)).unwrap(),
        );
        assert!(a == b, "{f} differs from the single run's");
    }
    for (f, tol) in [
        ("objects/bed.ply", 0.05),
        ("objects/nightstand.ply", 0.05),
        ("environment.ply", 0.1),
        ("scene.ply", 0.1),
    ] {
        let (a, b) = (
            read_ply(&one.join(f)).unwrap(),
            read_ply(&split.join(f)).unwrap(),
        );
        let d = max_diff(&a, &b);
        println!("{f}: {} Gaussians, largest difference {d:.2e}", a.len());
        assert!(d <= tol, "{f}: differs by {d} from the single run's");
        let m = a
            .means
            .iter()
            .flatten()
            .zip(b.means.iter().flatten())
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f32::max);
        assert!(m <= 1e-3, "{f}: a centre moved {m} m");
    }
    for d in [one, split] {
        std::fs::remove_dir_all(d).ok();
    }
}
