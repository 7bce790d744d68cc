//! Nothing lost when many processes race on one scene: rounds of concurrent `edit move`s, a
//! `generate --resume` and readers (`export`, `edit history`), some killed (SIGKILL) at random
//! moments. After every round the history is consistent (one record per entry, no edit twice,
//! scene.ply the composition of scene.json), every edit that said "done" is in it, every reader
//! wrote a state that was committed (never a mix; a history read is the start of the history
//! after the round), and at the end undo walks back to the original scene byte for byte. Tiny draft scene (shape prior), no rendering: a few seconds on 2 cores.
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::SceneSpec;
use dreamscene::scene::dir::{compose_scene, read_scene};
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::Gaussians;
use rand::{Rng, SeedableRng};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

const ROUNDS: usize = 10;
const EDITS: usize = 4;
const READERS: usize = 2;
const PROMPT: &str = "a small bedroom";

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-race-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// A draft bedroom (3.6 x 3 m, three objects) thinned to a few thousand Gaussians.
fn scene(dir: &Path) {
    let spec: SceneSpec = serde_json::from_str(
        r#"{"scene_type": "indoor", "scene_text": "a small bedroom",
            "room": {"size": [3.6, 3.0, 2.4]},
            "objects": {
              "bed": {"number": 1, "size": [1.4, 1.9, 0.6], "description": "a bed"},
              "nightstand": {"number": 1, "size": [0.45, 0.4, 0.55], "description": "a nightstand"},
              "chair": {"number": 1, "size": [0.45, 0.45, 0.85], "description": "a chair"}},
            "anchors": {}, "relations": []}"#,
    )
    .expect("spec");
    let l = layout(&spec, LayoutOptions::seeded(2)).expect("layout");
    std::fs::write(
        dir.join("spec.json"),
        serde_json::to_string(&spec).expect("spec json"),
    )
    .expect("spec.json");
    l.write(&dir.join("layout.json")).expect("layout.json");
    write_draft_scene(dir, PROMPT, 0, &spec, &l, false, &mut |_| {}).expect("draft");
    let mut plys = vec![dir.join("environment.ply")];
    for e in std::fs::read_dir(dir.join("objects")).expect("objects") {
        plys.push(e.expect("entry").path());
    }
    for p in plys {
        let g = read_ply(&p).expect("ply");
        let keep: Vec<bool> = (0..g.len()).map(|i| i % 40 == 0).collect();
        write_ply(&p, &dreamscene::generate::object::subset(&g, &keep)).expect("thin");
    }
    let s = read_scene(dir).expect("scene");
    write_ply(
        &dir.join("scene.ply"),
        &compose_scene(dir, &s).expect("compose"),
    )
    .expect("ply");
}

/// Every file outside history/ and the dot-files, with its bytes.
fn snapshot(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).expect("read dir") {
            let p = e.expect("entry").path();
            let rel = p
                .strip_prefix(dir)
                .expect("inside")
                .to_string_lossy()
                .to_string();
            if rel.starts_with("history") || rel.starts_with('.') {
                continue;
            }
            if p.is_dir() {
                stack.push(p);
            } else {
                out.insert(rel, std::fs::read(&p).expect("read"));
            }
        }
    }
    out
}

fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .env_remove("DREAMSCENE_MODELS")
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn dreamscene")
}

/// Same positions and colours (a reader that mixed two states has one's and the other's).
fn same_state(a: &Gaussians, b: &Gaussians) -> bool {
    a.len() == b.len()
        && a.means
            .iter()
            .zip(&b.means)
            .all(|(p, q)| (0..3).all(|k| (p[k] - q[k]).abs() < 1e-5))
        && a.sh.len() == b.sh.len()
        && a.sh.iter().zip(&b.sh).all(|(p, q)| (p - q).abs() < 1e-5)
}

/// The history's consistency: entry k has its record history/000k, no edit twice, scene.ply is
/// the composition of scene.json, no transaction left behind. Returns what each entry asked.
fn check_history(dir: &Path) -> (Vec<String>, String) {
    // A reader finishes a transaction a kill left half applied (one killed before its commit
    // point leaves only a stage, discarded by the next writer).
    let o = spawn(&["edit", &dir.to_string_lossy(), "history"])
        .wait_with_output()
        .expect("history");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let listed = String::from_utf8_lossy(&o.stdout).to_string();
    assert!(
        !dir.join(".edit/journal.json").exists(),
        "no committed transaction left half applied"
    );
    let s = read_scene(dir).expect("scene.json readable after the race");
    let mut seen = BTreeSet::new();
    let mut bys = vec![];
    for (i, e) in s.history.iter().enumerate() {
        let record = format!("history/{:04}", i + 1);
        assert_eq!(
            e["undo"]["dir"].as_str(),
            Some(record.as_str()),
            "entry {i}"
        );
        assert!(dir.join(&record).join("scene.json").is_file(), "{record}");
        let asked = match (e["flags"].as_str(), e["description"].as_str()) {
            (Some(f), _) => f.to_string(),
            (None, Some(d)) => d.to_string(),
            _ => panic!("entry {i} is neither a move nor a restyle: {e}"),
        };
        assert!(
            seen.insert(asked.clone()),
            "{asked} recorded twice: {:#?}",
            s.history
        );
        bys.push(asked);
    }
    let extra = dir.join(format!("history/{:04}", s.history.len() + 1));
    assert!(!extra.exists(), "no record without an entry");
    let composed = compose_scene(dir, &s).expect("compose");
    let ply = read_ply(&dir.join("scene.ply")).expect("scene.ply");
    assert!(same_state(&composed, &ply), "scene.ply matches scene.json");
    (bys, listed)
}

#[test]
fn racing_writers_readers_and_kills_lose_no_committed_edit_and_undo_walks_back() {
    let root = tmp("scene");
    let dir = root.join("scene");
    std::fs::create_dir_all(&dir).expect("scene dir");
    scene(&dir);
    let original = snapshot(&dir);
    let d = dir.to_string_lossy().to_string();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(24);
    let mut done: Vec<String> = vec![];
    let mut reads: Vec<PathBuf> = vec![];
    let (mut killed, mut waited, mut history_reads) = (0, 0, 0);
    for round in 0..ROUNDS {
        let mut kids: Vec<(String, Option<PathBuf>, Child)> = vec![];
        for e in 0..EDITS {
            // Unique, tiny shifts: each edit is recognisable in the history.
            if e == 1 {
                // A restyle rewrites the chair's PLY: a reader mixing states would show it.
                let colour = ["red", "blue", "green", "white", "black", "yellow"][round % 6];
                let words = format!("a {colour} chair number {round}");
                let args = ["edit", &d, "restyle", "chair1", &words, "--no-render"];
                kids.push((words.clone(), None, spawn(&args)));
                continue;
            }
            let by = format!("{},{}", (round + 1) as f64 / 1e3, (e + 1) as f64 / 1e4);
            let args = [
                "edit",
                &d,
                "move",
                "chair1",
                "--by",
                &by,
                "--force",
                "--no-follow",
                "--no-render",
            ];
            kids.push((format!("--by {by}"), None, spawn(&args)));
            if e == EDITS / 2 {
                let resume = [
                    "generate",
                    PROMPT,
                    "--out",
                    &d,
                    "--resume",
                    "--renders",
                    "0",
                ];
                kids.push(("resume".into(), None, spawn(&resume)));
            }
        }
        for r in 0..READERS {
            let out = root.join(format!("read-{round}-{r}.ply"));
            let o = out.to_string_lossy().to_string();
            let args = ["export", &d, "--scene-frame", "--out", &o];
            kids.push(("read".into(), Some(out), spawn(&args)));
        }
        // A history reader: what it lists must be a committed history, the start of the one
        // after the round (edits only append while nothing is undone).
        kids.push(("history".into(), None, spawn(&["edit", &d, "history"])));
        // Kill about a third of them, each at its own moment, wherever it is by then.
        for (_, _, c) in kids.iter_mut() {
            std::thread::sleep(Duration::from_millis(rng.gen_range(0..25)));
            if rng.gen_bool(0.33) && matches!(c.try_wait(), Ok(None)) && c.kill().is_ok() {
                killed += 1;
            }
        }
        let mut listings = vec![];
        for (what, out, c) in kids {
            let o = c.wait_with_output().expect("wait");
            waited += 1;
            let err = String::from_utf8_lossy(&o.stderr).to_string();
            if o.status.success() {
                match (what.as_str(), out) {
                    ("read", Some(p)) => reads.push(p),
                    ("history", _) => listings.push(String::from_utf8_lossy(&o.stdout).to_string()),
                    ("resume", _) => {}
                    (by, _) => done.push(by.to_string()),
                }
            } else {
                assert!(o.status.code().is_none(), "{what} failed unkilled: {err}");
            }
        }
        let (bys, listed) = check_history(&dir);
        for l in &listings {
            let l = l.trim_end();
            let is_start = l == "no edits" || listed.lines().take(l.lines().count()).eq(l.lines());
            assert!(
                is_start,
                "a history read during the round is no committed history:\n{l}\nafter:\n{listed}"
            );
            history_reads += 1;
        }
        for by in &done {
            assert!(
                bys.contains(by),
                "edit {by} said done but is not in the history"
            );
        }
    }
    let s = read_scene(&dir).expect("scene");
    let n = s.history.len();
    eprintln!(
        "race: {ROUNDS} rounds x {} processes, {waited} run, {killed} killed, {} edits said done, \
         {n} in the history, {} reads, {history_reads} history reads",
        EDITS + 1 + READERS + 1,
        done.len(),
        reads.len()
    );
    assert!(!done.is_empty(), "some edits finished");
    // Every state the history passed through, as the scene.ply of its record, and the last one.
    let mut states: Vec<Gaussians> = (1..=n)
        .map(|k| read_ply(&dir.join(format!("history/{k:04}/scene.ply"))).expect("record ply"))
        .collect();
    states.push(read_ply(&dir.join("scene.ply")).expect("scene.ply"));
    for p in &reads {
        let g = read_ply(p).expect("a finished reader's output");
        assert!(
            states.iter().any(|s| same_state(s, &g)),
            "{} is no committed state of the scene",
            p.display()
        );
    }
    assert!(history_reads > 0, "some history reads finished");
    for k in (0..n).rev() {
        let o = spawn(&["edit", &d, "undo"])
            .wait_with_output()
            .expect("undo");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert_eq!(
            read_scene(&dir).expect("scene").history.len(),
            k,
            "one undone"
        );
        check_history(&dir);
    }
    assert!(
        snapshot(&dir) == original,
        "undo walked back to the original scene byte for byte"
    );
    let _ = std::fs::remove_dir_all(&root);
}
