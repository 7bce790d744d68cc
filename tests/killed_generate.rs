//! A real `generate` (shape prior, three 16-pixel views) killed with SIGKILL at random moments,
//! then `--resume`d (itself killed at a random moment too), then resumed to its end: the scene
//! directory is then the one an uninterrupted run writes, file for file and byte for byte
//! (every object PLY, the environment, scene.json, scene.ply, each view cameras.json lists and
//! the contact sheet), with no stray file left by a killed run.
use rand::{Rng, SeedableRng};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// Trials: a run killed, its `--resume` killed, a `--resume` let finish.
const KILLS: usize = 2;
const PROMPT: &str = "a small bedroom with a bed and a desk";

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-killed-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn generate(out: &Path, resume: bool) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_dreamscene"));
    c.env_remove("DREAMSCENE_MODELS")
        .env_remove("DREAMSCENE_LLM_URL")
        .args(["generate", PROMPT, "--out"])
        .arg(out)
        .args(["--renders", "3", "--resolution", "16"])
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    if resume {
        c.arg("--resume");
    }
    c
}

/// Every file of `dir` but its lock files, with its bytes.
fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).expect("read dir") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            let rel = p.strip_prefix(dir).expect("inside").to_string_lossy();
            if !rel.ends_with(".lock") {
                out.insert(rel.to_string(), std::fs::read(&p).expect("read"));
            }
        }
    }
    out
}

#[test]
fn a_generate_killed_at_random_moments_resumes_to_the_uninterrupted_scene() {
    let root = tmp("scene");
    let reference = root.join("reference");
    let t0 = Instant::now();
    let o = generate(&reference, false).output().expect("run");
    let full = t0.elapsed();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let want = files(&reference);
    let cameras: serde_json::Value = serde_json::from_slice(
        want.get("renders/cameras.json")
            .expect("cameras.json written"),
    )
    .expect("cameras.json");
    assert_eq!(
        cameras.as_array().map(Vec::len),
        Some(3),
        "three views listed: {cameras}"
    );

    // Each trial kills a fresh run at a moment of its own share of the run's length (so the
    // kills cover it from start to end), then kills a `--resume` at a random moment, then lets
    // a `--resume` finish.
    // KILL_SEED=N draws other moments (a soak run); the suite uses one fixed draw.
    let seed = std::env::var("KILL_SEED").map_or(24, |v| v.parse().expect("KILL_SEED: a number"));
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut killed_at = vec![];
    for k in 0..KILLS {
        let out = root.join(format!("scene{k}"));
        for (run, resume) in [(0, false), (1, true)] {
            let share = if run == 0 {
                (k as f64 + rng.gen_range(0.0..1.0)) / KILLS as f64
            } else {
                rng.gen_range(0.0..1.0)
            };
            let mut child = generate(&out, resume).spawn().expect("spawn");
            std::thread::sleep(full.mul_f64(share));
            if matches!(child.try_wait(), Ok(None)) {
                child.kill().expect("SIGKILL");
                killed_at.push(format!("{:.0}%", 100.0 * share));
            }
            let o = child.wait_with_output().expect("wait");
            assert!(
                o.status.success() || o.status.code().is_none(),
                "trial {k} run {run} failed unkilled: {}",
                String::from_utf8_lossy(&o.stderr)
            );
        }
        let o = generate(&out, true).output().expect("resume");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "trial {k}, the last --resume: {err}");
        let got = files(&out);
        let names = |m: &BTreeMap<String, Vec<u8>>| m.keys().cloned().collect::<Vec<_>>();
        assert_eq!(names(&got), names(&want), "trial {k}: the same files");
        for (name, bytes) in &want {
            assert!(
                got[name] == *bytes,
                "trial {k}: {name} differs from the uninterrupted run"
            );
        }
    }
    eprintln!(
        "{KILLS} trials of 3 runs; killed at {} of an uninterrupted run ({:.1} s)",
        killed_at.join(", "),
        full.as_secs_f64()
    );
    let _ = std::fs::remove_dir_all(&root);
}
