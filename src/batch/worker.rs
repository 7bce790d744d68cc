//! One batch worker: walks its shard of the manifest, claims each scene by its scene lock
//! (`DIR/<id>/.lock`, the lock every scene writer takes), skips what is done or held by another
//! worker, runs the scene, and records it in `DIR/index.json`. A stop request (SIGTERM from
//! Slurm, Kubernetes or `kill`) is honoured at the next safe point: between scenes.
use super::index::{self, StageTime, Status};
use super::manifest::Entry;
use super::shard::Shard;
use super::BatchError;
use crate::scene::lock::{LockError, SceneLock, Wait};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Instant, SystemTime, UNIX_EPOCH};

/// What a worker does.
#[derive(Debug, Clone)]
pub struct WorkerOptions {
    /// The batch directory (`DIR/<id>/` per scene, `DIR/index.json`).
    pub out: PathBuf,
    pub shard: Option<Shard>,
    /// Who this is, for the index and the lock (e.g. `host pid 12`).
    pub name: String,
}

/// What running one scene produced.
#[derive(Debug, Clone, Default)]
pub struct Outcome {
    pub stages: Vec<StageTime>,
    pub gaussians: Option<usize>,
}

/// What a worker did.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Summary {
    /// Scenes of its shard.
    pub mine: usize,
    /// Finished by this worker now.
    pub done: usize,
    /// Failed now (recorded with their error).
    pub failed: usize,
    /// Found finished already.
    pub skipped: usize,
    /// Held by another writer, or failed under another worker since this one began (left for
    /// the next run, so a scene that fails is not tried again by every worker of the run).
    pub busy: usize,
    /// Left because a stop was requested.
    pub left: usize,
    pub stopped: bool,
}

fn now() -> f64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0.0, |d| d.as_secs_f64())
}

/// Whether scene `id` failed at or after `began` (under a worker running beside this one).
fn failed_since(ix: &index::Index, id: &str, began: f64) -> bool {
    ix.scenes
        .iter()
        .any(|r| r.id == id && r.status == Status::Failed && r.finished.is_some_and(|f| f >= began))
}

/// Runs the worker over `entries`. `run_scene(entry, scene_dir)` makes one scene (it is called
/// with the scene's lock held); `log` gets one line per scene.
pub fn run(
    opts: &WorkerOptions,
    entries: &[Entry],
    stop: &AtomicBool,
    run_scene: &mut dyn FnMut(&Entry, &Path) -> Result<Outcome, String>,
    log: &mut dyn FnMut(&str),
) -> Result<Summary, BatchError> {
    std::fs::create_dir_all(&opts.out).map_err(|e| BatchError::Io {
        path: opts.out.display().to_string(),
        msg: e.to_string(),
    })?;
    index::update(&opts.out, |ix| {
        for e in entries {
            ix.record(&e.id, &e.prompt);
        }
    })?;
    let mine: Vec<&Entry> = entries
        .iter()
        .filter(|e| opts.shard.is_none_or(|s| s.owns(&e.id)))
        .collect();
    let mut sum = Summary {
        mine: mine.len(),
        ..Summary::default()
    };
    // A scene that failed after this moment was tried by a worker running beside this one.
    let began = now();
    let who = match opts.shard {
        Some(s) => format!("{}, shard {s}", opts.name),
        None => opts.name.clone(),
    };
    for (k, e) in mine.iter().enumerate() {
        if stop.load(Ordering::SeqCst) {
            sum.stopped = true;
            sum.left = mine.len() - k;
            log(&format!(
                "stop requested: {} scenes of this worker left for the next run",
                sum.left
            ));
            break;
        }
        if index::read(&opts.out)?.status(&e.id) == Status::Done {
            sum.skipped += 1;
            continue;
        }
        let dir = opts.out.join(&e.id);
        std::fs::create_dir_all(&dir).map_err(|err| BatchError::Io {
            path: dir.display().to_string(),
            msg: err.to_string(),
        })?;
        let lock =
            match SceneLock::acquire(&dir, Wait::NoWait, &format!("dreamscene batch ({who})")) {
                Ok(l) => l,
                Err(LockError::Busy { holder, .. }) => {
                    log(&format!("{}: held by {holder}; skipped", e.id));
                    sum.busy += 1;
                    continue;
                }
                Err(LockError::Io { path, msg }) => return Err(BatchError::Io { path, msg }),
            };
        // Another worker may have finished it, or tried it and failed, between the read above
        // and the claim.
        let ix = index::read(&opts.out)?;
        if ix.status(&e.id) == Status::Done {
            sum.skipped += 1;
            continue;
        }
        if failed_since(&ix, &e.id, began) {
            log(&format!(
                "{}: failed under another worker of this run; left for the next run",
                e.id
            ));
            sum.busy += 1;
            continue;
        }
        let started = now();
        index::update(&opts.out, |ix| {
            let r = ix.record(&e.id, &e.prompt);
            r.status = Status::Running;
            r.worker = Some(who.clone());
            r.attempts += 1;
            r.started = Some(started);
            r.finished = None;
            r.stages.clear();
            r.seconds = None;
            r.gaussians = None;
            r.error = None;
        })?;
        let t = Instant::now();
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run_scene(e, &dir)))
            .unwrap_or_else(|p| {
                let what = p
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_else(|| "unknown".into());
                Err(format!("panicked: {what}"))
            });
        let seconds = t.elapsed().as_secs_f64();
        index::update(&opts.out, |ix| {
            let r = ix.record(&e.id, &e.prompt);
            r.finished = Some(now());
            r.seconds = Some(seconds);
            match &result {
                Ok(o) => {
                    r.status = Status::Done;
                    r.stages = o.stages.clone();
                    r.gaussians = o.gaussians;
                }
                Err(msg) => {
                    r.status = Status::Failed;
                    r.error = Some(msg.clone());
                }
            }
        })?;
        drop(lock);
        match result {
            Ok(o) => {
                sum.done += 1;
                log(&format!(
                    "{}: done in {seconds:.1} s{}",
                    e.id,
                    o.gaussians
                        .map_or(String::new(), |g| format!(", {g} Gaussians"))
                ));
            }
            Err(msg) => {
                sum.failed += 1;
                log(&format!("{}: failed: {msg}", e.id));
            }
        }
    }
    Ok(sum)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::manifest;

    fn tmp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("ds-worker-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn threads_without_shards_do_each_scene_once_and_a_stop_leaves_the_rest() {
        let out = tmp("once");
        let text: String = (0..24).map(|i| format!("room {i}\n")).collect();
        let entries = manifest::parse(&text, false).unwrap();
        let calls = std::sync::Mutex::new(Vec::<String>::new());
        // Threads that have run a scene (so they began before the bad scene fails).
        let started = std::sync::Mutex::new(std::collections::HashSet::new());
        let never = AtomicBool::new(false);
        std::thread::scope(|s| {
            for w in 0..3 {
                let (out, entries, calls, never, started) =
                    (&out, &entries, &calls, &never, &started);
                s.spawn(move || {
                    let opts = WorkerOptions {
                        out: out.clone(),
                        shard: None,
                        name: format!("thread {w}"),
                    };
                    run(
                        &opts,
                        entries,
                        never,
                        &mut |e, dir| {
                            calls.lock().unwrap().push(e.id.clone());
                            // Thread 0's first scene is slow, so it is behind when the bad
                            // scene fails and reaches that scene afterwards.
                            let first = started.lock().unwrap().insert(w);
                            let ms = if w == 0 && first { 200 } else { 5 };
                            std::thread::sleep(std::time::Duration::from_millis(ms));
                            std::fs::write(dir.join("scene.txt"), &e.prompt).unwrap();
                            if e.id == "0007" {
                                // A thread that began after the failure would rightly retry
                                // it (a later run); wait (a while at most) until all began.
                                let t = std::time::Instant::now();
                                while started.lock().unwrap().len() < 3
                                    && t.elapsed().as_secs() < 10
                                {
                                    std::thread::sleep(std::time::Duration::from_millis(2));
                                }
                                return Err("bad prompt".into());
                            }
                            Ok(Outcome::default())
                        },
                        &mut |_| {},
                    )
                    .unwrap();
                });
            }
        });
        let mut calls = calls.into_inner().unwrap();
        calls.sort();
        let before = calls.len();
        calls.dedup();
        assert_eq!(before, calls.len(), "no scene run twice");
        let ix = index::read(&out).unwrap();
        assert_eq!(ix.scenes.len(), 24);
        assert_eq!(ix.status("0007"), Status::Failed);
        let failed = ix.scenes.iter().find(|r| r.id == "0007").unwrap();
        assert_eq!(failed.error.as_deref(), Some("bad prompt"));
        let c = index::Counts::of(&ix, &|_| false);
        // A scene skipped as busy by one thread was run by the thread that held it, and the
        // scene that failed was not tried again by the threads behind it, so every scene ran
        // exactly once.
        assert_eq!((c.done, c.failed, c.left, calls.len()), (23, 1, 0, 24));

        // A rerun does only the failed scene; a stop before it leaves it.
        let stop = AtomicBool::new(true);
        let opts = WorkerOptions {
            out: out.clone(),
            shard: None,
            name: "again".into(),
        };
        let sum = run(
            &opts,
            &entries,
            &stop,
            &mut |_, _| Ok(Outcome::default()),
            &mut |_| {},
        )
        .unwrap();
        assert!(sum.stopped && sum.left == 24 && sum.done == 0);
        let mut ran = vec![];
        let sum = run(
            &opts,
            &entries,
            &AtomicBool::new(false),
            &mut |e, _| {
                ran.push(e.id.clone());
                Ok(Outcome::default())
            },
            &mut |_| {},
        )
        .unwrap();
        assert_eq!(ran, ["0007"]);
        assert_eq!((sum.done, sum.skipped), (1, 23));
        let _ = std::fs::remove_dir_all(&out);
    }
}
