//! `dreamscene generate` through the binary: the draft scene directory indoors and outdoors
//! (objects inside their layout boxes, the environment around the room, scene.ply the sum of
//! its parts, scene.json by the contract, renders that show something), the optimising prior
//! refused without models, and --resume.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::plan::spec::{Layout, SceneType};
use dreamscene::scene::compose::transform;
use dreamscene::scene::dir::read_scene;
use dreamscene::scene::env::hemisphere_radius;
use dreamscene::splat::ply::read_ply;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .env_remove("DREAMSCENE_MODELS")
        .env_remove("DREAMSCENE_LLM_URL")
        .args(args)
        .output()
        .expect("runs")
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-generate-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn generate(prompt: &str, out: &Path, extra: &[&str]) -> Output {
    let o = out.to_str().unwrap();
    let mut args = vec![
        "generate",
        prompt,
        "--out",
        o,
        "--resolution",
        "64",
        "--renders",
        "2",
    ];
    args.extend_from_slice(extra);
    run(&args)
}

/// Everything a draft scene directory must satisfy.
fn check_draft(out: &Path, prompt: &str) {
    // scene.json: typed, and the contract's keys.
    let scene = read_scene(out).expect("scene.json reads");
    assert_eq!(scene.prompt, prompt, "scene.json keeps the prompt");
    assert_eq!(scene.prior.kind, "shape", "the scene names the shape prior");
    let j = json(&out.join("scene.json"));
    for k in [
        "version",
        "prompt",
        "seed",
        "scene_type",
        "room",
        "prior",
        "objects",
        "environment",
        "stages",
        "timeline",
    ] {
        assert!(j.get(k).is_some(), "scene.json lacks {k}: {j}");
    }
    assert_eq!(j["version"], 1, "scene.json version");
    assert!(j["timeline"].is_null(), "a still scene has no timeline");
    assert!(
        j["prior"]["models"].is_null(),
        "the shape prior names no models"
    );
    for o in j["objects"].as_array().unwrap() {
        for k in ["id", "category", "ply", "position", "yaw", "scale"] {
            assert!(o.get(k).is_some(), "object lacks {k}: {o}");
        }
    }
    let stages: Vec<(String, bool)> = scene
        .stages
        .iter()
        .map(|s| (s.name.clone(), s.done))
        .collect();
    assert_eq!(
        stages,
        vec![
            ("objects".to_string(), true),
            ("environment".to_string(), true)
        ],
        "both stages are done"
    );
    for f in [
        "spec.json",
        "layout.json",
        "layout.png",
        "renders/cameras.json",
    ] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    assert!(out.join("checkpoints").is_dir(), "checkpoints/ is kept");

    // Every instance's Gaussians inside its layout box (shape prior centres within 1 cm).
    let layout: Layout =
        serde_json::from_str(&std::fs::read_to_string(out.join("layout.json")).unwrap()).unwrap();
    assert_eq!(
        layout.objects.len(),
        scene.objects.len(),
        "every scene object has a layout box"
    );
    let boxes: HashMap<&str, _> = layout.objects.iter().map(|o| (o.id.as_str(), o)).collect();
    let mut total = 0usize;
    let mut plys = HashMap::new();
    for o in &scene.objects {
        let g = plys
            .entry(o.ply.clone())
            .or_insert_with(|| read_ply(&out.join(&o.ply)).expect("object ply"));
        assert!(!g.is_empty(), "{} is empty", o.ply);
        total += g.len();
        let b = boxes[o.id.as_str()];
        assert_eq!(o.position, b.position, "{}", o.id);
        assert_eq!(o.yaw, b.yaw, "{}", o.id);
        let w = transform(g, o.yaw, o.scale, o.position);
        let (s, c) = (-b.yaw).to_radians().sin_cos();
        let tol = 0.015;
        for m in &w.means {
            let d = [0, 1, 2].map(|a| m[a] as f64 - b.position[a]);
            let local = [c * d[0] - s * d[1], s * d[0] + c * d[1], d[2]];
            assert!(
                local[0].abs() <= 0.5 * b.size[0] + tol
                    && local[1].abs() <= 0.5 * b.size[1] + tol
                    && local[2] >= -tol
                    && local[2] <= b.size[2] + tol,
                "{}: Gaussian at {m:?} (local {local:?}) outside its {:?} box",
                o.id,
                b.size
            );
        }
    }

    // The environment encloses the room: nothing strictly inside the room box but the floor.
    let env = read_ply(&out.join("environment.ply")).expect("environment.ply");
    let [w, d, h] = scene.room.size;
    let mut floor = 0;
    for m in &env.means {
        let [x, y, z] = m.map(f64::from);
        assert!(z >= -0.03, "environment below the floor at {m:?}");
        if z.abs() < 0.03 {
            floor += 1;
            continue;
        }
        if scene.scene_type == SceneType::Indoor {
            let inside =
                x.abs() < 0.5 * w - 0.01 && y.abs() < 0.5 * d - 0.01 && z < h - 0.01 && z > 0.03;
            assert!(!inside, "environment Gaussian inside the room at {m:?}");
        } else {
            // The sky: radius R jittered by cbrt(U(0.95, 1.05)), R the room box's corner.
            let r = hemisphere_radius(scene.room.size);
            let rad = (x * x + y * y + z * z).sqrt();
            assert!(rad >= 0.98 * r, "sky Gaussian at {m:?} inside radius {r}");
        }
    }
    assert!(floor > 1000, "only {floor} floor Gaussians");
    assert!(env.len() > floor + 1000, "no walls / sky");
    // Every object stands inside the room or ground area, under its ceiling or sky.
    for o in &layout.objects {
        let reach = 0.5 * (o.size[0].hypot(o.size[1]));
        assert!(
            o.position[0].abs() <= 0.5 * w + reach && o.position[1].abs() <= 0.5 * d + reach,
            "{} outside the room",
            o.id
        );
        assert!(
            o.position[2] + o.size[2] <= h + 0.01,
            "{} above the room",
            o.id
        );
    }

    // scene.ply: every instance plus the environment, lit as a draft (the doors' and windows'
    // own surfels appended to environment.ply's).
    let all = read_ply(&out.join("scene.ply")).expect("scene.ply");
    let mut lit = env.clone();
    let openings = dreamscene::scene::env::openings_of(scene.extra.get("openings"));
    dreamscene::scene::env::bake_light(&mut lit, scene.scene_type, scene.room.size, &[], &openings);
    assert!(
        scene.scene_type != SceneType::Indoor || lit.len() > env.len(),
        "an indoor draft's doors and windows are drawn by surfels of their own"
    );
    assert_eq!(
        all.len(),
        total + lit.len(),
        "scene.ply holds every instance and the lit environment"
    );

    // Renders show something; overview.png is their contact sheet.
    assert!(out.join("renders/overview.png").is_file(), "overview.png");
    let mut n = 0;
    for e in std::fs::read_dir(out.join("renders")).unwrap() {
        let p = e.unwrap().path();
        // Every view (the contact sheet is wider).
        if p.extension().is_some_and(|x| x == "png") && !p.ends_with("overview.png") {
            let img = image::open(&p).unwrap().to_rgb8();
            assert_eq!(img.width(), 64, "renders are 64 px wide");
            let first = img.get_pixel(0, 0);
            assert!(
                img.pixels().any(|q| q != first),
                "{} is one colour",
                p.display()
            );
            let dark = img.pixels().filter(|q| q.0.iter().all(|&v| v < 8)).count();
            assert!(
                dark * 4 < (img.width() * img.height()) as usize,
                "{} mostly black",
                p.display()
            );
            n += 1;
        }
    }
    assert_eq!(n, 2, "two views");
}

#[test]
fn generate_indoor_draft_scene_directory() {
    let out = tmp("indoor");
    let prompt = "a cozy living room";
    let o = generate(prompt, &out, &[]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("draft") && err.contains("DREAMSCENE_MODELS"),
        "{err}"
    );
    assert_eq!(
        read_scene(&out).unwrap().environment.unwrap().kind,
        "cuboid"
    );
    check_draft(&out, prompt);

    // --resume with the same prompt and seed: complete, nothing done.
    let o = generate(prompt, &out, &["--resume"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("complete"));
    // --resume with another seed: refused with the reason.
    let o = generate(prompt, &out, &["--resume", "--seed", "3"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        err.contains("--seed 0") && err.lines().count() <= 2,
        "{err}"
    );
    // Another prompt: refused too.
    let o = generate("a kitchen", &out, &["--resume"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("a cozy living room"));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn generate_outdoor_draft_scene_directory() {
    let out = tmp("outdoor");
    let prompt = "a garden with a bench and two trees";
    let o = generate(prompt, &out, &["--prior", "shape", "--seed", "2"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let scene = read_scene(&out).unwrap();
    assert_eq!(scene.seed, 2);
    assert_eq!(scene.environment.as_ref().unwrap().kind, "hemisphere");
    assert_eq!(
        scene
            .objects
            .iter()
            .filter(|o| o.category == "tree")
            .count(),
        2
    );
    check_draft(&out, prompt);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn generate_refuses_a_missing_model_directory_clearly() {
    let out = tmp("sd");
    // No models: --prior sd cannot run.
    let o = generate("a cozy living room", &out, &["--prior", "sd"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        err.contains("--prior sd") && err.contains("--draft"),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    // A model directory that is not there is named, in one line, and nothing is written.
    let o = generate(
        "a cozy living room",
        &out,
        &["--prior", "sd", "--models", "/nonexistent/models"],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(err.contains("/nonexistent/models"), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        !out.exists(),
        "refused before planning: nothing written, not even the directory"
    );
    // ...while --draft makes the draft anyway.
    let o = generate(
        "a cozy living room",
        &out,
        &[
            "--prior",
            "sd",
            "--models",
            "/nonexistent/models",
            "--draft",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.join("scene.json").is_file());
    let _ = std::fs::remove_dir_all(&out);
}

/// The tiny Stable Diffusion model drives every stage end to end: objects by Formation Pattern
/// Sampling, the three environment stages, and a complete scene directory.
#[test]
fn generate_with_the_tiny_sd_model_runs_every_stage() {
    let out = tmp("sdrun");
    let o = run(&[
        "generate",
        "a tiny bedroom with a bed",
        "--models",
        "tests/data/tiny-sd",
        "--out",
        out.to_str().unwrap(),
        "--iterations",
        "4",
        "--object-iterations",
        "2",
        "--object-recon-passes",
        "1",
        "--recon-passes",
        "1",
        "--resolution",
        "64",
        "--renders",
        "1",
        "--object-gaussians",
        "1000",
        "--env-density",
        "60",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    for s in ["stage 1 done", "stage 2 done", "stage 3 done"] {
        assert!(err.contains(s), "{s}: {err}");
    }
    let scene = read_scene(&out).unwrap();
    assert_eq!(scene.prior.kind, "sd");
    assert!(scene.stages.iter().all(|s| s.done));
    let g = read_ply(&out.join("scene.ply")).unwrap();
    assert!(g.len() > 1000 && g.means.iter().flatten().all(|v| v.is_finite()));
    assert!(out.join("renders/view_0000.png").is_file());
    // --provider reaches the model sessions of generate and edit: CUDA asked of a library
    // without it is refused in one line naming why (where the library has CUDA, it would run).
    let has_cuda = dreamscene::diffusion::runtime::available_providers()
        .unwrap()
        .iter()
        .any(|p| p == "CUDAExecutionProvider");
    if !has_cuda {
        let before = std::fs::read(out.join("scene.json")).unwrap();
        let o = run(&[
            "edit",
            out.to_str().unwrap(),
            "move",
            "bed1",
            "--by",
            "0.2,0",
            "--iterations",
            "1",
            "--resolution",
            "64",
            "--provider",
            "cuda",
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success() && err.contains("no CUDA provider"),
            "{err}"
        );
        assert_eq!(std::fs::read(out.join("scene.json")).unwrap(), before);
        let other = tmp("sdcuda");
        let o = run(&[
            "generate",
            "a tiny bedroom with a bed",
            "--models",
            "tests/data/tiny-sd",
            "--out",
            other.to_str().unwrap(),
            "--provider",
            "cuda",
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success() && err.contains("no CUDA provider"),
            "{err}"
        );
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        let _ = std::fs::remove_dir_all(&other);
    }
    let _ = std::fs::remove_dir_all(&out);
}
