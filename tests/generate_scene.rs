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
use dreamscene::splat::cloud::SH_C0;
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

/// Recolours a cloud: `f(position, colour) -> colour`.
fn recolour(g: &mut Gaussians, f: impl Fn([f32; 3], [f32; 3]) -> [f32; 3]) {
    let k3 = g.coeffs() * 3;
    for i in 0..g.len() {
        let c: [f32; 3] = std::array::from_fn(|ch| 0.5 + SH_C0 as f32 * g.sh[i * k3 + ch]);
        let n = f(g.means[i], c);
        for (ch, v) in n.iter().enumerate() {
            g.sh[i * k3 + ch] = (v - 0.5) / SH_C0 as f32;
        }
    }
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
    recolour(&mut g, |p, _| {
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
        recolour(&mut g, |_, c| [c[2], c[0], c[1]]);
        write_ply(&p, &g).unwrap();
    }
    l
}

/// The oracle run; `quick` is the mechanics-only size (64², a few iterations) of the resume test.
fn generate(refdir: &Path, out: &Path, quick: bool, extra: &[&str]) -> Command {
    let (iterations, passes, res) = if quick {
        ("40", "1", "64")
    } else {
        ("200", "8", "128")
    };
    let mut c = Command::new(env!("CARGO_BIN_EXE_dreamscene"));
    c.env_remove("DREAMSCENE_MODELS").args([
        "generate",
        PROMPT,
        "--out",
        out.to_str().unwrap(),
        "--prior",
        &format!("oracle:{}", refdir.display()),
        "--iterations",
        iterations,
        "--object-iterations",
        "20",
        "--object-recon-passes",
        "4",
        "--recon-passes",
        passes,
        "--resolution",
        res,
        "--renders",
        "0",
        "--object-gaussians",
        "4000",
        "--env-density",
        "400",
    ]);
    c.args(extra);
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
    let refdir = tmp("ref");
    let l = reference(&refdir);
    // The starting point: the draft of the same prompt (draft colours, channel order).
    let draft = tmp("draft");
    std::fs::create_dir_all(&draft).unwrap();
    write_draft_scene(&draft, PROMPT, 0, &spec(), &l, false, &mut |_| {}).unwrap();
    let before = held_out(&ctx, &draft, &refdir, &l);

    let out = tmp("regen");
    let o = generate(&refdir, &out, false, &[]).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let scene = read_scene(&out).unwrap();
    assert_eq!(scene.prior.kind, "oracle");
    assert!(scene.stages.iter().all(|s| s.done));
    let after = held_out(&ctx, &out, &refdir, &l);
    println!("oracle scene: held-out PSNR {before:.2} -> {after:.2} dB");
    assert!(after >= 22.0, "held-out {after:.2} dB (from {before:.2})");
}

#[test]
fn scene_generation_killed_mid_stage_resumes() {
    let refdir = tmp("ref2");
    reference(&refdir);
    let out = tmp("cut");
    let mut child = generate(&refdir, &out, true, &["--seed", "1"])
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let run_json = out.join("checkpoints/scene_run.json");
    let t0 = std::time::Instant::now();
    loop {
        if let Ok(text) = std::fs::read_to_string(&run_json) {
            let j: serde_json::Value = serde_json::from_str(&text).unwrap_or_default();
            if j["stages_done"].as_u64().unwrap_or(0) >= 1 {
                break;
            }
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "finished before the kill"
        );
        assert!(t0.elapsed().as_secs() < 900, "no stage finished");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    assert!(!out.join("scene.json").exists());
    let o = generate(&refdir, &out, true, &["--seed", "1", "--resume"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("done before, kept"), "{err}");
    assert!(!err.contains("stage 1 done"), "stage 1 ran again: {err}");
    assert!(read_scene(&out).unwrap().stages.iter().all(|s| s.done));
    // Another seed is refused with the reason.
    let o = generate(&refdir, &out, true, &["--seed", "2", "--resume"])
        .output()
        .unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("seed"));
}

/// The oracle run at the smallest size that still runs every stage (mechanics only).
fn tiny(refdir: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    let o = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .env_remove("DREAMSCENE_MODELS")
        .args(["generate", PROMPT, "--out"])
        .arg(out)
        .args(["--prior", &format!("oracle:{}", refdir.display())])
        .args(["--iterations", "12", "--object-iterations", "6"])
        .args(["--object-recon-passes", "1", "--recon-passes", "1"])
        .args([
            "--resolution",
            "64",
            "--renders",
            "0",
            "--object-gaussians",
            "1500",
        ])
        .args(["--env-density", "150"])
        .args(extra)
        .output()
        .unwrap();
    o
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

/// Slow (about 3 minutes on 2 cores: a whole oracle run and the same run split), so left out of
/// the default suite: `cargo test --release --test generate_scene -- --ignored`.
#[test]
#[ignore = "slow: a whole oracle run twice; run with --ignored"]
fn oracle_object_shards_then_the_scene_step_equal_one_run() {
    let refdir = tmp("ref3");
    reference(&refdir);
    let one = tmp("one");
    ok(&tiny(&refdir, &one, &[]));
    // Two object shards (each its own state file), the scene step in between refused while
    // shard 1 has not run, naming its object.
    let split = tmp("split");
    let s0 = ok(&tiny(
        &refdir,
        &split,
        &["--stage", "objects", "--shard", "0/2"],
    ));
    assert!(
        split.join("checkpoints/objects_run_0of2.json").is_file(),
        "{s0}"
    );
    let o = tiny(&refdir, &split, &["--stage", "scene"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    let last = err.trim().lines().last().unwrap_or("");
    assert!(
        last.starts_with("error: ") && last.contains("missing objects: nightstand"),
        "{err}"
    );
    assert_eq!(err.matches("error").count(), 1, "{err}");
    ok(&tiny(
        &refdir,
        &split,
        &["--stage", "objects", "--shard", "1/2"],
    ));
    assert!(split.join("checkpoints/objects_run_1of2.json").is_file());
    let s = ok(&tiny(&refdir, &split, &["--stage", "scene"]));
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
    for d in [refdir, one, split] {
        std::fs::remove_dir_all(d).ok();
    }
}
