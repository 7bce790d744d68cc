//! Nothing lost, through the command line: `generate --out` onto a scene refuses (naming
//! --resume and --force), --force replaces it whole, and so does `plan --out` (naming --force), a failed run leaves no directory, --resume
//! renders the views cameras.json lists that are missing, a second writer with --no-wait names
//! the holder, empty environment variables mean unset, values out of bounds in scene.json are
//! refused in one line naming the instance, messages say each path once, and each edit
//! operation's help shows only the flags that apply to it, every argument described.
use dreamscene::scene::dir::read_scene;
use dreamscene::scene::lock::{SceneLock, Wait};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-lost-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn run(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_dreamscene"));
    c.env_remove("DREAMSCENE_MODELS").args(args);
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("run dreamscene")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

const PROMPT: &str = "a small bedroom with a bed and a desk";

/// A draft at the smallest sizes, with `renders` views of 16 pixels.
fn draft(out: &Path, renders: &str, extra: &[&str]) -> Output {
    let o = out.to_string_lossy().to_string();
    let mut args = vec![
        "generate",
        PROMPT,
        "--out",
        &o,
        "--renders",
        renders,
        "--resolution",
        "16",
    ];
    args.extend_from_slice(extra);
    run(&args, &[])
}

/// A fresh temporary directory `name` with a draft scene (no renders) in `scene/`: the directory,
/// the scene's path, and that path as an argument.
fn drafted(name: &str) -> (PathBuf, PathBuf, String) {
    let root = tmp(name);
    let out = root.join("scene");
    let o = draft(&out, "0", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let d = out.to_string_lossy().to_string();
    (root, out, d)
}

#[test]
fn generate_refuses_an_existing_scene_force_replaces_it_whole_and_failures_leave_nothing() {
    let (root, out, _) = drafted("overwrite");
    let before = std::fs::read(out.join("scene.json")).expect("scene.json");
    std::fs::write(out.join("notes.txt"), "mine").expect("a stray file");
    let o = draft(&out, "0", &[]);
    let err = stderr(&o);
    assert!(!o.status.success(), "refused");
    assert!(
        err.contains("--resume") && err.contains("--force") && err.lines().count() == 1,
        "one line naming --resume and --force: {err}"
    );
    assert_eq!(
        std::fs::read(out.join("scene.json")).expect("scene.json"),
        before,
        "nothing changed"
    );
    let o = draft(&out, "0", &["--force"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !out.join("notes.txt").exists(),
        "--force leaves no stale file"
    );
    assert!(out.join("scene.json").is_file(), "the new scene");
    // A prompt that cannot be planned leaves no directory behind.
    let bad = root.join("bad");
    let b = bad.to_string_lossy().to_string();
    let o = run(&["generate", "asdf qwerty zxcv", "--out", &b], &[]);
    assert!(!o.status.success(), "refused");
    assert!(!bad.exists(), "no empty output directory: {}", stderr(&o));
    let _ = std::fs::remove_dir_all(&root);
}

/// Every file under `dir` with its bytes, sorted by path.
fn files_of(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = vec![];
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).expect("read dir") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let bytes = std::fs::read(&p).expect("read file");
                out.push((p, bytes));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn plan_refuses_a_scene_in_its_out_and_force_replaces_it() {
    let (root, out, d) = drafted("plan-onto");
    let before = files_of(&out);
    let o = run(&["plan", "a studio flat with a futon", "--out", &d], &[]);
    let err = stderr(&o);
    assert!(!o.status.success(), "refused");
    assert!(
        err.contains("--force") && err.lines().filter(|l| l.starts_with("error")).count() == 1,
        "one line naming --force: {err}"
    );
    assert!(files_of(&out) == before, "nothing of the scene changed");
    let o = run(
        &["plan", "a studio flat with a futon", "--out", &d, "--force"],
        &[],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !out.join("scene.json").exists() && !out.join("objects").exists(),
        "--force replaces the scene whole"
    );
    let spec = std::fs::read_to_string(out.join("spec.json")).expect("spec.json");
    assert!(spec.contains("futon"), "the new plan");
    // a plan's own directory is planned again without asking
    let o = run(
        &["plan", "a sunroom with two wicker chairs", "--out", &d],
        &[],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn resume_renders_the_views_cameras_json_lists_that_are_missing() {
    let root = tmp("resume");
    let out = root.join("scene");
    let o = draft(&out, "3", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let cams = dreamscene::camera::read_cameras(&out.join("renders/cameras.json")).expect("cams");
    assert_eq!(cams.len(), 3, "three views listed");
    let png = |i: usize| out.join(format!("renders/{}.png", cams[i].img_name));
    let kept = std::fs::read(png(0)).expect("first view");
    // As if killed during the render stage: two of the three views are missing.
    std::fs::remove_file(png(1)).expect("remove");
    std::fs::remove_file(png(2)).expect("remove");
    // run again without --resume: refused, saying the scene is unfinished
    let o = draft(&out, "3", &[]);
    assert!(!o.status.success(), "refused");
    assert!(
        stderr(&o).contains("unfinished scene") && stderr(&o).contains("--resume"),
        "{}",
        stderr(&o)
    );
    let o = draft(&out, "3", &["--resume"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.contains('2'), "says it rendered 2: {said}");
    for i in 0..3 {
        assert!(png(i).is_file(), "view {i} there after --resume");
    }
    assert_eq!(
        std::fs::read(png(0)).expect("first"),
        kept,
        "present views kept"
    );
    // A missing object PLY of an unedited scene is made again.
    let ply = out.join(&read_scene(&out).expect("scene").objects[0].ply);
    std::fs::remove_file(&ply).expect("remove");
    let o = draft(&out, "3", &["--resume"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(ply.is_file(), "{} made again", ply.display());
    let o = draft(&out, "3", &["--resume"]);
    assert!(
        String::from_utf8_lossy(&o.stdout).contains("nothing to do"),
        "complete now"
    );
    // complete: a rerun's refusal no longer calls it unfinished
    let o = draft(&out, "3", &[]);
    assert!(
        !o.status.success() && !stderr(&o).contains("unfinished scene"),
        "{}",
        stderr(&o)
    );
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn a_second_writer_waits_or_with_no_wait_names_the_holder() {
    let (root, out, d) = drafted("busy");
    let held = SceneLock::acquire(&out, Wait::NoWait, "a test holding the scene").expect("lock");
    let o = run(
        &["edit", &d, "move", "bed1", "--by", "0.1,0", "--no-wait"],
        &[],
    );
    let err = stderr(&o);
    assert!(!o.status.success(), "refused while held");
    assert!(
        err.contains("a test holding the scene") && err.contains(&std::process::id().to_string()),
        "names the holder's pid and command: {err}"
    );
    let o = draft(&out, "0", &["--resume", "--no-wait"]);
    assert!(!o.status.success(), "generate --resume refused too");
    assert!(
        stderr(&o).contains("a test holding the scene"),
        "{}",
        stderr(&o)
    );
    drop(held);
    let o = run(
        &[
            "edit",
            &d,
            "move",
            "bed1",
            "--by",
            "0.1,0",
            "--force",
            "--no-render",
            "--no-wait",
        ],
        &[],
    );
    assert!(o.status.success(), "admitted once released: {}", stderr(&o));
    let h = run(&["edit", &d, "history"], &[]);
    let text = String::from_utf8_lossy(&h.stdout).to_string();
    assert_eq!(
        text.trim(),
        "1 move bed1 --by 0.1,0",
        "one short line an edit"
    );
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn empty_environment_variables_mean_unset() {
    let root = tmp("env");
    let out = root.join("scene");
    let o = out.to_string_lossy().to_string();
    let empty = [
        ("DREAMSCENE_MODELS", ""),
        ("DREAMSCENE_LLM_URL", ""),
        ("DREAMSCENE_LLM_MODEL", ""),
        ("DREAMSCENE_DEVICE", ""),
        ("OPENAI_API_KEY", ""),
    ];
    // With DREAMSCENE_LLM_URL empty the planner stays offline (no request anywhere) and with
    // DREAMSCENE_MODELS empty the scene is a draft.
    let g = run(&["generate", PROMPT, "--out", &o, "--renders", "0"], &empty);
    assert!(g.status.success(), "{}", stderr(&g));
    assert_eq!(read_scene(&out).expect("scene").prior.kind, "shape");
    let d = run(&["doctor"], &empty);
    assert!(
        !stderr(&d).contains("a value is required"),
        "{}",
        stderr(&d)
    );
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn out_of_bounds_values_are_refused_in_one_line_and_messages_say_each_path_once() {
    let (root, out, d) = drafted("bounds");
    // A move that would put the bed 150 m outside the room is refused even with --force.
    let o = run(
        &[
            "edit",
            &d,
            "move",
            "bed1",
            "--by",
            "150,0",
            "--force",
            "--no-render",
        ],
        &[],
    );
    assert!(!o.status.success(), "refused");
    assert!(stderr(&o).contains("outside the"), "{}", stderr(&o));
    // The same position written by hand is named before any work, in one line.
    let path = out.join("scene.json");
    let mut v: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&path).expect("read")).expect("json");
    let objects = v["objects"].as_array_mut().expect("objects");
    let i = objects
        .iter()
        .position(|o| o["id"] == "bed1")
        .expect("bed1");
    objects[i]["position"][0] = serde_json::json!(1e8);
    std::fs::write(&path, serde_json::to_vec(&v).expect("json")).expect("write");
    let start = std::time::Instant::now();
    let o = run(
        &["edit", &d, "move", "bed1", "--by", "0.1,0", "--no-render"],
        &[],
    );
    let err = stderr(&o);
    assert!(!o.status.success(), "refused");
    assert!(
        err.contains("bed1") && err.contains("outside") && err.lines().count() == 1,
        "{err}"
    );
    assert!(start.elapsed().as_secs() < 5, "at once");
    // export names the intact scene.ply beside a scene.json it cannot use.
    let x = root.join("x.spz").to_string_lossy().to_string();
    let o = run(&["export", &d, "--out", &x], &[]);
    assert!(
        stderr(&o).contains("scene.ply") && stderr(&o).contains("dreamscene export"),
        "{}",
        stderr(&o)
    );
    // --format from the extension, and a write error naming its path once.
    let ply = out.join("scene.ply").to_string_lossy().to_string();
    let o = run(&["export", &ply, "--out", &x], &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let blocked = root.join("file");
    std::fs::write(&blocked, "not a directory").expect("write");
    let y = blocked.join("y.spz").to_string_lossy().to_string();
    let o = run(&["export", &ply, "--out", &y], &[]);
    let err = stderr(&o);
    assert!(!o.status.success(), "refused");
    let name = blocked.to_string_lossy().to_string();
    assert!(
        err.matches(name.as_str()).count() == 1,
        "the path once: {err}"
    );
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn video_and_render_check_their_output_before_rendering() {
    let (root, _, d) = drafted("early");
    // A regular file where the output's directory should be: nothing can be written under it
    // (even as root, unlike a read-only mode bit).
    let blocker = root.join("blocker");
    std::fs::write(&blocker, b"x").expect("write blocker");
    let gif = blocker.join("x.gif").to_string_lossy().to_string();
    // Enough frames that rendering them all would take far longer than the check.
    let o = run(
        &["video", &d, "--out", &gif, "--seconds", "60", "--fps", "30"],
        &[],
    );
    let err = stderr(&o);
    assert!(!o.status.success(), "video refused");
    assert!(err.contains("blocker"), "names the path: {err}");
    assert!(!err.contains("frame"), "no frame rendered first: {err}");
    let dir = blocker.join("views").to_string_lossy().to_string();
    let o = run(&["render", &d, "--trajectory", "orbit", "--out", &dir], &[]);
    assert!(!o.status.success(), "render refused");
    assert!(stderr(&o).contains("blocker"), "{}", stderr(&o));
    assert!(
        std::fs::read(&blocker).expect("blocker kept") == b"x",
        "nothing overwritten"
    );
    let _ = std::fs::remove_dir_all(&root);
}

/// The arguments and options `help` lists, each with its description (empty when it has none).
fn help_entries(help: &str) -> Vec<(String, String)> {
    let lines: Vec<&str> = help.lines().collect();
    let is_entry = |l: &str| {
        let t = l.trim_start();
        // `--flag`, `-h, --help` or `<ARG>`; not a value list's `- cpu:`.
        let flag =
            t.starts_with('-') && t[1..].starts_with(|c: char| c == '-' || c.is_alphanumeric());
        l.starts_with("  ") && (flag || t.starts_with('<'))
    };
    let mut out = vec![];
    let mut in_list = false;
    for (i, l) in lines.iter().enumerate() {
        if l.trim().is_empty() {
            continue;
        }
        if !l.starts_with(' ') {
            in_list = l.starts_with("Arguments:") || l.starts_with("Options:");
            continue;
        }
        if !in_list || !is_entry(l) {
            continue;
        }
        let t = l.trim_start();
        let (name, desc) = t.split_once("  ").unwrap_or((t, ""));
        let desc = match desc.trim() {
            "" => lines
                .get(i + 1)
                .filter(|n| !is_entry(n))
                .map_or("", |n| n.trim()),
            d => d,
        };
        out.push((name.trim().to_string(), desc.to_string()));
    }
    out
}

#[test]
fn each_edit_operation_lists_only_its_flags_each_described() {
    let help = |op: &str| {
        let o = run(&["edit", "DIR", op, "--help"], &[]);
        assert!(o.status.success(), "edit {op} --help: {}", stderr(&o));
        String::from_utf8_lossy(&o.stdout).to_string()
    };
    let flags = |op: &str| -> Vec<String> {
        help_entries(&help(op))
            .into_iter()
            .map(|(n, _)| n)
            .filter(|n| n.starts_with("--") && n != "--help")
            .map(|n| n.split(' ').next().unwrap_or("").to_string())
            .collect()
    };
    // Reading the history takes no lock and writes nothing; undo restores renders as they were.
    assert_eq!(
        flags("history"),
        Vec::<String>::new(),
        "history has no flags"
    );
    assert_eq!(flags("undo"), vec!["--no-wait"], "undo only waits or not");
    assert!(
        !flags("animate").contains(&"--iterations".to_string()),
        "animate re-optimises nothing"
    );
    for op in ["move", "add", "remove", "restyle", "animate"] {
        let text = help(op);
        let entries = help_entries(&text);
        assert!(
            entries.iter().any(|(n, _)| n.starts_with('<')),
            "edit {op} takes an argument: {text}"
        );
        for (name, desc) in &entries {
            assert!(!desc.is_empty(), "edit {op}: {name} has no description");
        }
        for f in ["--no-render", "--no-wait"] {
            assert!(flags(op).iter().any(|x| x == f), "edit {op} has {f}");
        }
    }
}

/// An `--out` that names a file is refused in one line that says it is a file, and the file is
/// left as it was.
#[test]
fn an_out_that_is_a_file_is_refused_in_one_line_and_kept() {
    let root = tmp("outfile");
    let f = root.join("afile");
    std::fs::write(&f, "mine").expect("a file");
    let fs = f.to_string_lossy().to_string();
    for args in [
        vec!["generate", PROMPT, "--out", &fs, "--renders", "0"],
        vec!["plan", PROMPT, "--out", &fs],
        vec!["object", "a chair", "--out", &fs],
    ] {
        let o = run(&args, &[]);
        let err = stderr(&o);
        assert!(!o.status.success(), "{args:?}: refused");
        assert!(
            err.contains("is a file, not a folder")
                && err.lines().filter(|l| l.starts_with("error")).count() == 1,
            "{args:?}: one line saying it is a file: {err}"
        );
        assert_eq!(
            std::fs::read_to_string(&f).expect("kept"),
            "mine",
            "{args:?}"
        );
    }
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn an_export_whose_extension_and_format_disagree_is_refused_and_a_replaced_file_is_named() {
    let (root, out, _) = drafted("ext");
    let ply = out.join("scene.ply").to_string_lossy().to_string();
    let x = root.join("x.spz");
    let xs = x.to_string_lossy().to_string();
    let o = run(&["export", &ply, "--format", "ply", "--out", &xs], &[]);
    let err = stderr(&o);
    assert!(!o.status.success(), "refused: {err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("spz") && err.contains("ply"), "{err}");
    assert!(!x.exists(), "nothing written");
    // the first export says nothing of replacing; the second names the file it replaces
    let o = run(&["export", &ply, "--out", &xs], &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("replaced"), "{}", stderr(&o));
    let o = run(&["export", &ply, "--format", "spz", "--out", &xs], &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&xs) && stderr(&o).contains("replaced"),
        "{}",
        stderr(&o)
    );
    let _ = std::fs::remove_dir_all(&root);
}
