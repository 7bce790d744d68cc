//! `dreamscene batch` by hand: two workers on one manifest finish it once; SIGTERM stops a
//! worker after its current scene and a rerun does only what is left; `batch --status`; a bad
//! manifest line refused in one line; `generate --stage scene` names missing objects; the
//! Kubernetes job file validates against the Kubernetes schemas offline.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::batch::index::{self, Status};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_dreamscene");
const FLAGS: [&str; 5] = ["--draft", "--resolution", "32", "--renders", "1"];

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-batch-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn cmd() -> Command {
    let mut c = Command::new(BIN);
    c.env_remove("DREAMSCENE_MODELS")
        .env_remove("DREAMSCENE_LLM_URL")
        .env_remove("SLURM_ARRAY_TASK_ID")
        .env_remove("JOB_COMPLETION_INDEX");
    c
}

fn batch(manifest: &Path, out: &Path) -> Command {
    let mut c = cmd();
    c.arg("batch")
        .arg(manifest)
        .arg("--out")
        .arg(out)
        .args(FLAGS);
    c
}

/// A one-line manifest of `prompt` in a fresh directory: (directory, out), and
/// `batch MANIFEST --out OUT` without the draft flags.
fn one_scene(name: &str, prompt: &str) -> (PathBuf, PathBuf, Command) {
    let d = tmp(name);
    let m = d.join("m.txt");
    std::fs::write(&m, format!("{prompt}\n")).unwrap();
    let out = d.join("out");
    let mut c = cmd();
    c.arg("batch").arg(&m).arg("--out").arg(&out);
    (d, out, c)
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

#[test]
fn two_workers_on_one_manifest_do_each_scene_once() {
    let d = tmp("two");
    let m = d.join("m.jsonl");
    std::fs::write(
        &m,
        r#"{"id": "bedroom", "prompt": "a bedroom with a desk", "seed": 3}
{"id": "kitchen", "prompt": "a kitchen with a fridge"}
{"id": "patio", "prompt": "a patio with two chairs", "seed": 1}
{"id": "den", "prompt": "a den with a sofa", "renders": 2}
"#,
    )
    .unwrap();
    let out = d.join("out");
    let spawn = || {
        batch(&m, &out)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap()
    };
    let (a, b) = (spawn(), spawn());
    let (a, b) = (a.wait_with_output().unwrap(), b.wait_with_output().unwrap());
    assert!(
        a.status.success() && b.status.success(),
        "{}\n{}",
        text(&a),
        text(&b)
    );
    let ix = index::read(&out).unwrap();
    assert_eq!(ix.scenes.len(), 4);
    for r in &ix.scenes {
        assert_eq!((r.status, r.attempts), (Status::Done, 1), "{r:?}");
        assert!(r.gaussians.unwrap() > 0 && r.stages.len() == 3, "{r:?}");
        assert!(out.join(&r.id).join("scene.json").is_file());
    }
    let seed = |id: &str| {
        let s: serde_json::Value =
            serde_json::from_slice(&std::fs::read(out.join(id).join("scene.json")).unwrap())
                .unwrap();
        s["seed"].as_u64().unwrap()
    };
    assert_eq!((seed("bedroom"), seed("kitchen")), (3, 0));
    let renders = std::fs::read_dir(out.join("den/renders")).unwrap().count();
    assert_eq!(renders, 4, "two views, cameras.json and overview.png");
    // Each worker says how many it did; together exactly the manifest.
    let done_now = |o: &Output| -> usize {
        let s = String::from_utf8_lossy(&o.stdout);
        let l = s.lines().find(|l| l.starts_with("batch")).unwrap();
        let before = l.split(" done now").next().unwrap();
        before.rsplit(' ').next().unwrap().parse().unwrap()
    };
    assert_eq!(done_now(&a) + done_now(&b), 4, "{}\n{}", text(&a), text(&b));
    let st = cmd()
        .args(["batch", "--status"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        text(&st).contains("4 scenes: 4 done, 0 running, 0 failed, 0 left"),
        "{}",
        text(&st)
    );
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert_eq!(html.matches("<figure>").count(), 4);
    assert!(html.contains("den/renders/") && html.contains("a patio with two chairs"));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn sigterm_stops_after_the_current_scene_and_a_rerun_does_the_rest() {
    let d = tmp("term");
    let m = d.join("m.txt");
    std::fs::write(&m, "a bedroom\na kitchen\na study\na garden\na bathroom\n").unwrap();
    let out = d.join("out");
    let child = batch(&m, &out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let t = Instant::now();
    while index::read(&out).map_or(true, |ix| ix.status("0001") != Status::Done) {
        assert!(
            t.elapsed() < Duration::from_secs(60),
            "first scene never finished"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    let pid = child.id().to_string();
    assert!(Command::new("kill")
        .args(["-TERM", &pid])
        .status()
        .unwrap()
        .success());
    let o = child.wait_with_output().unwrap();
    assert!(!o.status.success(), "a stopped worker reports it");
    assert!(text(&o).contains("stopped by a signal"), "{}", text(&o));
    let ix = index::read(&out).unwrap();
    assert!(
        ix.scenes.iter().all(|r| r.status != Status::Running),
        "{ix:?}"
    );
    let before: Vec<_> = ix
        .scenes
        .iter()
        .filter(|r| r.status == Status::Done)
        .cloned()
        .collect();
    assert!(!before.is_empty() && before.len() < 5, "{ix:?}");
    let again = batch(&m, &out).output().unwrap();
    assert!(again.status.success(), "{}", text(&again));
    let ix = index::read(&out).unwrap();
    assert!(ix
        .scenes
        .iter()
        .all(|r| r.status == Status::Done && r.attempts == 1));
    for r in &before {
        let now = ix.scenes.iter().find(|x| x.id == r.id).unwrap();
        assert_eq!(now.finished, r.finished, "{} redone", r.id);
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn bad_manifests_and_missing_objects_are_one_line() {
    let d = tmp("bad");
    let m = d.join("m.jsonl");
    std::fs::write(
        &m,
        "{\"prompt\": \"a bedroom\"}\n{\"prompt\": \"a den\", \"sed\": 2}\n",
    )
    .unwrap();
    let o = batch(&m, &d.join("out")).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.trim().lines().count() == 1,
        "{err}"
    );
    assert!(err.contains("line 2") && err.contains("sed"), "{err}");
    assert!(
        !d.join("out").exists(),
        "nothing written for a bad manifest"
    );

    // Object shard 0 of 3 alone: the scene step names what is missing, then succeeds.
    let scene = d.join("scene");
    let stage = |extra: &[&str]| {
        cmd()
            .args([
                "generate",
                "a living room with a sofa, a tv and a lamp",
                "--out",
            ])
            .arg(&scene)
            .args(FLAGS)
            .args(extra)
            .output()
            .unwrap()
    };
    let o = stage(&["--stage", "objects", "--shard", "0/3"]);
    assert!(o.status.success(), "{}", text(&o));
    let o = stage(&["--stage", "scene"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.contains("missing objects: "),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    for s in ["1/3", "2/3"] {
        assert!(stage(&["--stage", "objects", "--shard", s])
            .status
            .success());
    }
    let o = stage(&["--stage", "scene"]);
    assert!(o.status.success(), "{}", text(&o));
    assert!(scene.join("scene.ply").is_file() && scene.join("renders").is_dir());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_kubernetes_job_validates_against_the_schemas() {
    let have = Command::new("kubernetes-validate")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    let problem = (!have).then(|| {
        "kubernetes-validate is missing: python3 -m pip install kubernetes-validate".to_string()
    });
    if !common::external_tool("kubernetes-validate", problem) {
        return;
    }
    let job = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/k8s/batch-job.yaml");
    let check = |p: &Path| {
        Command::new("kubernetes-validate")
            .arg("--strict")
            .arg(p)
            .output()
            .unwrap()
    };
    let o = check(&job);
    assert!(o.status.success(), "{}", text(&o));
    // The check can fail: the same Job with a misspelt field is refused.
    let d = tmp("k8s");
    let bad = d.join("bad.yaml");
    let y = std::fs::read_to_string(&job).unwrap();
    assert!(y.contains("completionMode: Indexed") && y.contains("DREAMSCENE_SHARDS"));
    std::fs::write(&bad, y.replace("completionMode:", "completionMod:")).unwrap();
    assert!(!check(&bad).status.success());
    let _ = std::fs::remove_dir_all(&d);
}

/// `batch --provider` reaches every scene's sd prior: CUDA asked of a library without it fails
/// the scene with the provider's own message in index.json (skipped where CUDA exists).
#[test]
fn the_provider_reaches_every_scene() {
    let has_cuda = dreamscene::diffusion::runtime::available_providers()
        .unwrap()
        .iter()
        .any(|p| p == "CUDAExecutionProvider");
    if has_cuda {
        return;
    }
    let (d, out, mut c) = one_scene("provider", "a tiny bedroom with a bed");
    let o = c
        .args(["--prior", "sd", "--models", "tests/data/tiny-sd"])
        .args(["--provider", "cuda", "--renders", "0", "--resolution", "64"])
        .output()
        .unwrap();
    assert!(!o.status.success(), "{}", text(&o));
    let idx = std::fs::read_to_string(out.join("index.json")).unwrap();
    assert!(
        idx.contains("\"failed\"") && idx.contains("no CUDA provider"),
        "{idx}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// A full (sd prior) scene's record in index.json holds the time of each stage the generation
/// ran, not one figure for the whole scene.
#[test]
fn a_full_scene_records_each_stage() {
    let (d, out, mut c) = one_scene("stages", "an empty room with one chair");
    let o = c
        .args([
            "--prior",
            "sd",
            "--models",
            "tests/data/tiny-sd",
            "--provider",
            "cpu",
        ])
        .args([
            "--renders",
            "0",
            "--resolution",
            "16",
            "--object-gaussians",
            "300",
        ])
        .args(["--object-iterations", "1", "--iterations", "1"])
        .args([
            "--recon-passes",
            "1",
            "--object-recon-passes",
            "1",
            "--env-density",
            "10",
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o));
    let idx: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("index.json")).unwrap()).unwrap();
    let stages = &idx["scenes"][0]["stages"];
    let names: Vec<&str> = stages
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        ["plan and priors", "objects", "environment", "outputs"],
        "{idx}"
    );
    assert!(
        stages
            .as_array()
            .unwrap()
            .iter()
            .all(|s| s["seconds"].as_f64().unwrap() >= 0.0),
        "{idx}"
    );
    let _ = std::fs::remove_dir_all(&d);
}
