//! `dreamscene batch` and `generate --stage` on a real single-node Slurm started inside the test
//! (Debian's slurmctld, slurmd, slurm-client and munge; tests/slurm/slurm_up.sh), with the job
//! files users submit (scripts/slurm/*.sbatch): a 12-prompt manifest over a 4-task array gives
//! every scene byte for byte as a serial `generate`; a task cancelled mid-run and requeued
//! completes only its missing scenes; object shards plus the dependent scene step give the same
//! scene as one `generate`; with a prior (the oracle), object shards and the scene step give a
//! complete scene. Missing Slurm fails the test unless `DREAMSCENE_SKIP_EXTERNAL=slurm`.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::batch::index::{self, Status};
use dreamscene::batch::shard::shard_of;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_dreamscene");
const FLAGS: [&str; 5] = ["--draft", "--resolution", "32", "--renders", "1"];
const PROMPTS: [&str; 12] = [
    "a small bedroom",
    "a kitchen with two stools",
    "a garden with a bench",
    "an office with a desk and a lamp",
    "a living room with a sofa and a tv",
    "a dining room with a table and four chairs",
    "a bathroom",
    "a classroom",
    "a park with two trees",
    "a study with a bookshelf",
    "a cozy reading corner with an armchair",
    "a bedroom with a bed and a wardrobe",
];

struct Cluster {
    dir: PathBuf,
    conf: String,
    work: PathBuf,
}

impl Drop for Cluster {
    fn drop(&mut self) {
        let _ = Command::new("bash")
            .arg(root().join("tests/slurm/slurm_down.sh"))
            .arg(&self.dir)
            .status();
    }
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn have(cmd: &str) -> bool {
    Command::new("sh")
        .args([
            "-c",
            &format!("command -v {cmd} || test -x /usr/sbin/{cmd}"),
        ])
        .output()
        .is_ok_and(|o| o.status.success())
}

impl Cluster {
    /// A cluster in a fresh directory, or `None` where `DREAMSCENE_SKIP_EXTERNAL` names
    /// `slurm`. Missing Slurm (or not running as root, which its daemons need) fails the test.
    fn up(work: &Path) -> Option<Cluster> {
        let missing: Vec<&str> = [
            "slurmctld",
            "slurmd",
            "munged",
            "sbatch",
            "squeue",
            "unshare",
        ]
        .into_iter()
        .filter(|c| !have(c))
        .collect();
        let as_root = Command::new("id")
            .arg("-u")
            .output()
            .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
        let problem = if !missing.is_empty() {
            Some(format!(
                "the Slurm test needs {}: apt-get install slurmctld slurmd slurm-client munge",
                missing.join(", ")
            ))
        } else if !as_root {
            Some("the Slurm test starts its daemons as root: run it as root".to_string())
        } else {
            None
        };
        if !common::external_tool("slurm", problem) {
            return None;
        }
        let dir = work.join("slurm");
        let port = 20000 + (std::process::id() % 2000) * 2;
        let out = Command::new("bash")
            .arg(root().join("tests/slurm/slurm_up.sh"))
            .arg(&dir)
            .arg(port.to_string())
            .arg((port + 1).to_string())
            .output()
            .expect("slurm_up.sh runs");
        let cluster = Cluster {
            dir: dir.clone(),
            conf: dir.join("slurm.conf").display().to_string(),
            work: work.to_path_buf(),
        };
        assert!(
            out.status.success(),
            "slurm did not start: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        Some(cluster)
    }

    fn cmd(&self, prog: &str) -> Command {
        let mut c = Command::new(prog);
        c.env("SLURM_CONF", &self.conf)
            .env("DREAMSCENE", BIN)
            .env_remove("DREAMSCENE_MODELS")
            .env_remove("DREAMSCENE_LLM_URL")
            .current_dir(&self.work);
        c
    }

    fn ok(&self, prog: &str, args: &[&str], env: &[(&str, &str)]) -> String {
        let mut c = self.cmd(prog);
        c.args(args);
        for (k, v) in env {
            c.env(k, v);
        }
        let o = c.output().expect("slurm client runs");
        assert!(
            o.status.success(),
            "{prog} {args:?}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        String::from_utf8_lossy(&o.stdout).trim().to_string()
    }

    /// Submits a job file with the test's overrides (no GPUs here, 1 CPU a task).
    fn sbatch(&self, extra: &[&str], script: &str, args: &[&str], env: &[(&str, &str)]) -> String {
        let mut a = vec!["--parsable", "--gres=none", "--cpus-per-task=1"];
        a.extend_from_slice(extra);
        let script = root().join("scripts/slurm").join(script);
        let script = script.display().to_string();
        a.push(&script);
        a.extend_from_slice(args);
        self.ok("sbatch", &a, env)
    }

    /// `(task, state)` of every task of `job` (for MinJobAge after the end).
    fn states(&self, job: &str) -> Vec<(String, String)> {
        self.ok(
            "squeue",
            &["-t", "all", "-h", "-j", job, "-o", "%i %T"],
            &[],
        )
        .lines()
        .filter_map(|l| l.split_once(' '))
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect()
    }

    /// `scene.sbatch objects` as an array of `shards` tasks, then `scene.sbatch scene` after it
    /// (afterok), waited for up to `limit`: the two job ids and the states of all their tasks.
    fn scene_shards(
        &self,
        shards: usize,
        flags: &[&str],
        env: &[(&str, &str)],
        limit: Duration,
    ) -> (String, String, Vec<(String, String)>) {
        let array = format!("--array=0-{}", shards - 1);
        let objects = self.sbatch(
            &[&array],
            "scene.sbatch",
            &[&["objects"][..], flags].concat(),
            env,
        );
        let dep = format!("--dependency=afterok:{objects}");
        let step = self.sbatch(
            &[&dep],
            "scene.sbatch",
            &[&["scene"][..], flags].concat(),
            env,
        );
        self.wait(&step, limit);
        let all = [self.states(&objects), self.states(&step)].concat();
        (objects, step, all)
    }

    fn wait(&self, job: &str, limit: Duration) {
        let t = Instant::now();
        loop {
            let active = self.ok(
                "squeue",
                &["-h", "-j", job, "-t", "PD,R,CG,CF,S,RQ,RS,SE"],
                &[],
            );
            if active.is_empty() {
                return;
            }
            assert!(t.elapsed() < limit, "job {job} still active: {active}");
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

/// Every file under `a` equals the one under `b` byte for byte, and no file is missing, except
/// the scene lock.
fn same_tree(a: &Path, b: &Path) {
    fn files(d: &Path, base: &Path, out: &mut BTreeMap<PathBuf, Vec<u8>>) {
        for e in std::fs::read_dir(d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                files(&p, base, out);
            } else if ![".lock", ".commit.lock"]
                .contains(&p.file_name().unwrap().to_str().unwrap_or(""))
            {
                out.insert(
                    p.strip_prefix(base).unwrap().into(),
                    std::fs::read(&p).unwrap(),
                );
            }
        }
    }
    let (mut fa, mut fb) = (BTreeMap::new(), BTreeMap::new());
    files(a, a, &mut fa);
    files(b, b, &mut fb);
    let (na, nb): (Vec<_>, Vec<_>) = (fa.keys().collect(), fb.keys().collect());
    assert_eq!(
        na,
        nb,
        "{} and {} list the same files",
        a.display(),
        b.display()
    );
    for (k, v) in &fa {
        assert!(
            v == &fb[k],
            "{} differs from {}",
            a.join(k).display(),
            b.join(k).display()
        );
    }
}

fn id(k: usize) -> String {
    format!("{:04}", k + 1)
}

#[test]
fn slurm_arrays_requeue_and_object_shards_match_serial_generate() {
    let work = std::env::temp_dir().join(format!("ds-batch-slurm-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();
    let Some(cl) = Cluster::up(&work) else {
        return;
    };
    let t0 = Instant::now();
    let manifest = work.join("prompts.txt");
    std::fs::write(&manifest, PROMPTS.join("\n") + "\n").unwrap();
    let out = work.join("batch");
    let (m, o) = (manifest.display().to_string(), out.display().to_string());
    let job = cl.sbatch(
        &["--array=0-3"],
        "batch.sbatch",
        &FLAGS,
        &[("MANIFEST", &m), ("OUT", &o)],
    );
    // The serial reference, made while the array runs.
    let serial = work.join("serial");
    for (k, p) in PROMPTS.iter().enumerate() {
        let d = serial.join(id(k));
        let st = Command::new(BIN)
            .env_remove("DREAMSCENE_MODELS")
            .args(["generate", p, "--out", d.to_str().unwrap()])
            .args(FLAGS)
            .output()
            .unwrap();
        assert!(
            st.status.success(),
            "{}",
            String::from_utf8_lossy(&st.stderr)
        );
    }
    cl.wait(&job, Duration::from_secs(240));
    let states = cl.states(&job);
    assert_eq!(states.len(), 4, "{states:?}");
    assert!(states.iter().all(|(_, s)| s == "COMPLETED"), "{states:?}");
    let ix = index::read(&out).unwrap();
    assert_eq!(ix.scenes.len(), 12);
    for (k, r) in ix.scenes.iter().enumerate() {
        assert_eq!(
            (r.id.as_str(), r.status, r.attempts),
            (id(k).as_str(), Status::Done, 1)
        );
        let shard = format!("shard {}/4", shard_of(&r.id, 4));
        assert!(r.worker.as_deref().unwrap().ends_with(&shard), "{r:?}");
        same_tree(&out.join(&r.id), &serial.join(&r.id));
    }
    println!(
        "array of 4 over 12 scenes (and the serial reference): {:.1} s",
        t0.elapsed().as_secs_f64()
    );

    // ---- a task cancelled mid-run, then requeued ----
    let t1 = Instant::now();
    let six = work.join("six.txt");
    std::fs::write(&six, PROMPTS[..6].join("\n") + "\n").unwrap();
    let out2 = work.join("requeue");
    let (m2, o2) = (six.display().to_string(), out2.display().to_string());
    let target = (0..2u32)
        .max_by_key(|&s| (0..6).filter(|&k| shard_of(&id(k), 2) == s).count())
        .unwrap();
    let theirs: Vec<String> = (0..6)
        .map(id)
        .filter(|i| shard_of(i, 2) == target)
        .collect();
    assert!(theirs.len() >= 3);
    let job2 = cl.sbatch(
        &["--array=0-1"],
        "batch.sbatch",
        &FLAGS,
        &[("MANIFEST", &m2), ("OUT", &o2)],
    );
    let task = format!("{job2}_{target}");
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        let ix = index::read(&out2).unwrap_or_default();
        let done = theirs
            .iter()
            .filter(|i| ix.status(i) == Status::Done)
            .count();
        if done >= 1 {
            break;
        }
        assert!(
            Instant::now() < deadline,
            "no scene of task {task} finished"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
    cl.ok("scancel", &[&task], &[]);
    let deadline = Instant::now() + Duration::from_secs(60);
    while !cl.states(&task).iter().any(|(_, s)| s == "CANCELLED") {
        assert!(Instant::now() < deadline, "{task} not cancelled");
        std::thread::sleep(Duration::from_millis(100));
    }
    let before = index::read(&out2).unwrap();
    let finished: Vec<(String, Option<f64>)> = before
        .scenes
        .iter()
        .filter(|r| r.status == Status::Done && theirs.contains(&r.id))
        .map(|r| (r.id.clone(), r.finished))
        .collect();
    assert!(
        finished.len() < theirs.len(),
        "the cancel came after task {task} had finished its scenes"
    );
    cl.ok("scontrol", &["requeue", &task], &[]);
    cl.ok(
        "scontrol",
        &["update", &format!("JobId={task}"), "StartTime=now"],
        &[],
    );
    cl.wait(&job2, Duration::from_secs(180));
    let after = index::read(&out2).unwrap();
    for r in &after.scenes {
        assert_eq!(r.status, Status::Done, "{r:?}");
        if let Some((_, t)) = finished.iter().find(|(i, _)| *i == r.id) {
            assert_eq!((r.finished, r.attempts), (*t, 1), "{} was redone", r.id);
        }
        if !theirs.contains(&r.id) {
            assert_eq!(r.attempts, 1, "the other task's scene {} redone", r.id);
        }
        same_tree(&out2.join(&r.id), &serial.join(&r.id));
    }
    let redone = after.scenes.iter().filter(|r| r.attempts > 1).count();
    assert!(
        redone <= 1,
        "at most the interrupted scene was claimed twice"
    );
    println!(
        "cancel + requeue of 6 scenes: {:.1} s",
        t1.elapsed().as_secs_f64()
    );

    // ---- one scene over three object shards and the dependent scene step ----
    let t2 = Instant::now();
    let scene = work.join("sharded");
    let env = [("PROMPT", PROMPTS[4]), ("OUT", scene.to_str().unwrap())];
    let (objects, _step, all) = cl.scene_shards(3, &FLAGS, &env, Duration::from_secs(120));
    assert!(all.iter().all(|(_, s)| s == "COMPLETED"), "{all:?}");
    same_tree(&scene, &serial.join(id(4)));
    // Each category was built by exactly one shard.
    let mut built = vec![];
    for k in 0..3 {
        let log = std::fs::read_to_string(work.join(format!("dreamscene-scene-{objects}_{k}.log")))
            .unwrap();
        let line = log
            .lines()
            .find(|l| l.starts_with("objects shard"))
            .unwrap()
            .to_string();
        let list = line.split_once(": ").unwrap().1;
        built.extend(
            list.split(", ")
                .filter(|c| !c.contains("kept") && *c != "none in this shard")
                .map(|c| c.split(" (").next().unwrap().to_string()),
        );
    }
    let n = built.len();
    built.sort();
    built.dedup();
    assert_eq!(n, built.len(), "a category built twice: {built:?}");
    let objects_dir = std::fs::read_dir(scene.join("objects")).unwrap().count();
    assert_eq!(n, objects_dir, "every object built by one shard");
    println!(
        "3 object shards + scene step: {:.1} s",
        t2.elapsed().as_secs_f64()
    );
    prior_object_shards_then_the_scene_step(&cl, &work);
    drop(cl);
    let _ = std::fs::remove_dir_all(&work);
}

/// The smallest oracle-prior run that still runs every stage (mechanics only, no quality).
const ORACLE_FLAGS: [&str; 18] = [
    "--iterations",
    "3",
    "--object-iterations",
    "2",
    "--object-recon-passes",
    "1",
    "--recon-passes",
    "1",
    "--resolution",
    "32",
    "--renders",
    "0",
    "--object-gaussians",
    "500",
    "--env-density",
    "50",
    "--seed",
    "0",
];

/// One scene with a prior (the oracle: a draft of the same prompt as its reference) over two
/// object shards and the dependent scene step, as `scripts/slurm/scene.sbatch` runs it: every
/// object of the plan is built by one shard, the scene step composes them all, and scene.ply
/// holds every object and the environment as labels.json says.
fn prior_object_shards_then_the_scene_step(cl: &Cluster, work: &Path) {
    let t = Instant::now();
    let prompt = "a tiny bedroom with a bed and a nightstand";
    let refdir = work.join("oracle-ref");
    let st = Command::new(BIN)
        .env_remove("DREAMSCENE_MODELS")
        .args(["generate", prompt, "--draft", "--renders", "0", "--out"])
        .arg(&refdir)
        .output()
        .unwrap();
    assert!(
        st.status.success(),
        "{}",
        String::from_utf8_lossy(&st.stderr)
    );
    let scene = work.join("oracle-scene");
    let prior = format!("oracle:{}", refdir.display());
    let flags = [&["--prior", prior.as_str()][..], &ORACLE_FLAGS].concat();
    let env = [("PROMPT", prompt), ("OUT", scene.to_str().unwrap())];
    let (objects, step, all) = cl.scene_shards(2, &flags, &env, Duration::from_secs(240));
    let logs = || {
        std::fs::read_dir(work)
            .unwrap()
            .filter_map(|e| {
                let p = e.unwrap().path();
                let n = p.file_name()?.to_str()?.to_string();
                (n.starts_with(&format!("dreamscene-scene-{objects}"))
                    || n.starts_with(&format!("dreamscene-scene-{step}")))
                .then(|| std::fs::read_to_string(&p).unwrap_or_default())
            })
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert!(
        all.len() == 3 && all.iter().all(|(_, s)| s == "COMPLETED"),
        "{all:?}\n{}",
        logs()
    );
    // The plan is the reference's; each of its objects was generated once, by one shard.
    let s = dreamscene::scene::dir::read_scene(&scene).unwrap();
    let r = dreamscene::scene::dir::read_scene(&refdir).unwrap();
    assert_eq!(s.prior.kind, "oracle", "the scene records its prior");
    let ids = |f: &dreamscene::scene::dir::SceneFile| -> Vec<String> {
        f.objects.iter().map(|o| o.id.clone()).collect()
    };
    assert_eq!(ids(&s), ids(&r), "the scene has every object of the plan");
    let mut built = vec![];
    for k in 0..2 {
        let log = std::fs::read_to_string(work.join(format!("dreamscene-scene-{objects}_{k}.log")))
            .unwrap();
        built.extend(
            log.lines()
                .filter_map(|l| l.strip_prefix("object "))
                .filter(|l| l.contains("Gaussians ("))
                .filter_map(|l| l.split(':').next())
                .map(str::to_string),
        );
    }
    let mut cats: Vec<String> = s.objects.iter().map(|o| o.category.clone()).collect();
    cats.sort();
    cats.dedup();
    built.sort();
    assert_eq!(built, cats, "each category generated by exactly one shard");
    // scene.ply is complete: every object's block and the environment, in labels.json's order.
    let g = dreamscene::splat::ply::read_ply(&scene.join("scene.ply")).unwrap();
    let labels: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(scene.join("labels.json")).unwrap()).unwrap();
    let mut total = 0;
    for o in &s.objects {
        let own = dreamscene::splat::ply::read_ply(&scene.join(&o.ply)).unwrap();
        assert!(!own.is_empty(), "{} has Gaussians", o.id);
        let inst = labels["instances"]
            .as_array()
            .unwrap()
            .iter()
            .find(|i| i["id"] == o.id.as_str())
            .unwrap();
        assert_eq!(
            inst["gaussians"][1].as_u64(),
            Some(own.len() as u64),
            "{}",
            o.id
        );
        total += own.len();
    }
    let env = &labels["instances"][0];
    assert_eq!(env["id"], "environment", "instance 0 is the environment");
    assert!(env["gaussians"][1].as_u64().unwrap() > 0, "an environment");
    total += env["gaussians"][1].as_u64().unwrap() as usize;
    assert_eq!(
        g.len(),
        total,
        "scene.ply holds every object and the environment"
    );
    println!(
        "oracle prior, 2 object shards + scene step: {:.1} s",
        t.elapsed().as_secs_f64()
    );
}
