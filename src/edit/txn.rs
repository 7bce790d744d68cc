//! The edit transaction: an atomic in-place update of a scene directory.
//!
//! New files are written into `.edit/stage/` first. The files they replace or delete are
//! hard-linked (copied where links are refused) into `history/NNNN/`, the undo record. Then the
//! journal `.edit/journal.json` is written atomically: that rename is the commit point. Applying
//! it renames every staged file over its target (`scene.json` last) and deletes what the edit
//! drops; then the journal goes. [`recover`] (run before every edit) finishes a journal left by
//! a crash, or throws away a stage that never reached its journal, so a crash leaves the old scene
//! or the new one, never a mix. Replaced files are never written in place, so the hard links in
//! `history/` keep the old bytes exactly. Host-only.
use super::EditError;
use crate::scene::lock::{CommitGuard, LockError, ReadGuard, SceneLock, Wait};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

const WORK: &str = ".edit";
const STAGE: &str = ".edit/stage";
const JOURNAL: &str = ".edit/journal.json";
/// Where undo records live, one numbered directory per edit.
pub const HISTORY: &str = "history";

fn io(path: &Path) -> impl Fn(std::io::Error) -> EditError + '_ {
    move |e| EditError::Io(format!("{}: {e}", path.display()))
}

/// What a committed transaction does, replayable after a crash.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
struct Journal {
    /// (staged path, target path), relative to the scene directory, applied in order.
    renames: Vec<(String, String)>,
    deletes: Vec<String>,
    /// Directories removed once everything is in place (an undone edit's record).
    cleanup: Vec<String>,
}

/// An edit being prepared: staged files and deletions.
pub struct Txn {
    dir: PathBuf,
    writes: Vec<String>,
    deletes: Vec<String>,
    cleanup: Vec<String>,
}

/// What the files of a transaction were before it: the undo record's contents.
#[derive(Debug, Clone, Default, Serialize, Deserialize, PartialEq)]
pub struct Backup {
    /// The record's directory, relative to the scene directory.
    pub dir: String,
    /// Files that existed and are kept in the record.
    pub saved: Vec<String>,
    /// Files the edit created (undo deletes them).
    pub created: Vec<String>,
}

impl Txn {
    /// Starts a transaction on `dir`, first finishing or discarding an interrupted one.
    pub fn begin(dir: &Path) -> Result<Txn, EditError> {
        recover(dir)?;
        let stage = dir.join(STAGE);
        std::fs::create_dir_all(&stage).map_err(io(&stage))?;
        Ok(Txn {
            dir: dir.to_path_buf(),
            writes: vec![],
            deletes: vec![],
            cleanup: vec![],
        })
    }

    /// The scene directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Where the new version of `rel` is staged (its parent created); the caller writes it there
    /// and it replaces `rel` at commit.
    pub fn stage_path(&mut self, rel: &str) -> Result<PathBuf, EditError> {
        check_rel(rel)?;
        let p = self.dir.join(STAGE).join(rel);
        if let Some(parent) = p.parent() {
            std::fs::create_dir_all(parent).map_err(io(parent))?;
        }
        if !self.writes.iter().any(|w| w == rel) {
            self.writes.push(rel.to_string());
        }
        Ok(p)
    }

    /// Stages `bytes` as the new content of `rel`.
    pub fn write(&mut self, rel: &str, bytes: &[u8]) -> Result<(), EditError> {
        let p = self.stage_path(rel)?;
        std::fs::write(&p, bytes).map_err(io(&p))
    }

    /// Stages the removal of `rel` (nothing when it does not exist at commit).
    pub fn delete(&mut self, rel: &str) -> Result<(), EditError> {
        check_rel(rel)?;
        self.writes.retain(|w| w != rel);
        if !self.deletes.iter().any(|d| d == rel) {
            self.deletes.push(rel.to_string());
        }
        Ok(())
    }

    /// Removes directory `rel` once the transaction is applied.
    pub fn cleanup_dir(&mut self, rel: &str) -> Result<(), EditError> {
        check_rel(rel)?;
        self.cleanup.push(rel.to_string());
        Ok(())
    }

    /// Whether `rel` is staged for writing.
    pub fn is_written(&self, rel: &str) -> bool {
        self.writes.iter().any(|w| w == rel)
    }

    /// Saves the current version of every file this transaction touches into `record` (relative
    /// to the scene directory, e.g. `history/0003`) and says what was there. Call after staging
    /// everything except `scene.json` itself, which is always recorded.
    pub fn backup(&self, record: &str) -> Result<Backup, EditError> {
        check_rel(record)?;
        let root = self.dir.join(record);
        if root.exists() {
            // A record of an edit that never committed (or was undone): not referenced.
            std::fs::remove_dir_all(&root).map_err(io(&root))?;
        }
        let tmp = self.dir.join(format!("{record}.tmp"));
        if tmp.exists() {
            std::fs::remove_dir_all(&tmp).map_err(io(&tmp))?;
        }
        let mut b = Backup {
            dir: record.to_string(),
            ..Backup::default()
        };
        let mut touched: Vec<&String> = self.writes.iter().chain(&self.deletes).collect();
        let scene_json = "scene.json".to_string();
        if !touched.contains(&&scene_json) {
            touched.push(&scene_json);
        }
        for rel in touched {
            let src = self.dir.join(rel);
            if src.is_file() {
                let dst = tmp.join(rel);
                if let Some(parent) = dst.parent() {
                    std::fs::create_dir_all(parent).map_err(io(parent))?;
                }
                if std::fs::hard_link(&src, &dst).is_err() {
                    std::fs::copy(&src, &dst).map_err(io(&src))?;
                }
                b.saved.push(rel.clone());
            } else {
                b.created.push(rel.clone());
            }
        }
        std::fs::create_dir_all(&tmp).map_err(io(&tmp))?;
        std::fs::rename(&tmp, &root).map_err(io(&root))?;
        Ok(b)
    }

    /// Commits: writes the journal (the commit point) and applies it. `scene.json`, when staged,
    /// is put in place last.
    pub fn commit(self) -> Result<(), EditError> {
        let mut renames: Vec<(String, String)> = self
            .writes
            .iter()
            .filter(|w| *w != "scene.json")
            .map(|w| (format!("{STAGE}/{w}"), w.clone()))
            .collect();
        if self.writes.iter().any(|w| w == "scene.json") {
            renames.push((format!("{STAGE}/scene.json"), "scene.json".into()));
        }
        let j = Journal {
            renames,
            deletes: self.deletes,
            cleanup: self.cleanup,
        };
        let path = self.dir.join(JOURNAL);
        let text = serde_json::to_vec_pretty(&j).map_err(|e| EditError::Io(e.to_string()))?;
        // Readers are kept out from the commit point until every file is in place.
        let _readers_out = CommitGuard::acquire(&self.dir)?;
        crate::util::write_atomic(&path, &text).map_err(io(&path))?;
        sync_dir(&self.dir.join(WORK));
        apply(&self.dir, &j)
    }

    /// Drops the staged files; the scene is untouched.
    pub fn abort(self) {
        let _ = std::fs::remove_dir_all(self.dir.join(STAGE));
    }
}

fn check_rel(rel: &str) -> Result<(), EditError> {
    let p = Path::new(rel);
    if rel.is_empty()
        || p.is_absolute()
        || p.components()
            .any(|c| !matches!(c, std::path::Component::Normal(_)))
    {
        return Err(EditError::Io(format!(
            "`{rel}` is not a path inside the scene directory"
        )));
    }
    Ok(())
}

fn sync_dir(dir: &Path) {
    if let Ok(f) = std::fs::File::open(dir) {
        let _ = f.sync_all();
    }
}

fn apply(dir: &Path, j: &Journal) -> Result<(), EditError> {
    for (from, to) in &j.renames {
        let (from, to) = (dir.join(from), dir.join(to));
        if from.exists() {
            if let Some(parent) = to.parent() {
                std::fs::create_dir_all(parent).map_err(io(parent))?;
            }
            std::fs::rename(&from, &to).map_err(io(&to))?;
        }
    }
    for d in &j.deletes {
        let p = dir.join(d);
        match std::fs::remove_file(&p) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(io(&p)(e)),
        }
    }
    sync_dir(dir);
    let journal = dir.join(JOURNAL);
    std::fs::remove_file(&journal).map_err(io(&journal))?;
    for c in &j.cleanup {
        let _ = std::fs::remove_dir_all(dir.join(c));
    }
    let _ = std::fs::remove_dir_all(dir.join(WORK));
    Ok(())
}

/// Finishes an edit a crash interrupted after its commit point, or discards one interrupted
/// before it. Returns what was done, if anything.
pub fn recover(dir: &Path) -> Result<Option<&'static str>, EditError> {
    let journal = dir.join(JOURNAL);
    if journal.is_file() {
        let _readers_out = CommitGuard::acquire(dir)?;
        let text = std::fs::read(&journal).map_err(io(&journal))?;
        let j: Journal = serde_json::from_slice(&text)
            .map_err(|e| EditError::Io(format!("{}: {e}", journal.display())))?;
        apply(dir, &j)?;
        return Ok(Some("finished an interrupted edit"));
    }
    let work = dir.join(WORK);
    if work.exists() {
        std::fs::remove_dir_all(&work).map_err(io(&work))?;
        return Ok(Some(
            "discarded an edit interrupted before it was committed",
        ));
    }
    Ok(None)
}

/// Runs `read` (which reads the scene's files) while no edit is being put in place, so it sees
/// the scene before an edit or after it, never a mix. Readers never wait for a whole edit, only
/// for its last milliseconds. An edit whose writer died while putting it in place is finished
/// first (when no other writer holds the scene), as the next edit would.
pub fn read_consistent<T>(dir: &Path, read: impl FnOnce() -> T) -> Result<T, EditError> {
    loop {
        let guard = ReadGuard::acquire(dir)?;
        if !dir.join(JOURNAL).is_file() {
            let value = read();
            drop(guard);
            return Ok(value);
        }
        drop(guard);
        match SceneLock::acquire(dir, Wait::NoWait, "recover before reading") {
            Ok(lock) => {
                recover(dir)?;
                drop(lock);
            }
            Err(LockError::Busy { .. }) => {
                std::thread::sleep(std::time::Duration::from_millis(50));
            }
            Err(e) => return Err(e.into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tmp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("ds-txn-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn commit_replaces_and_backs_up() {
        let d = tmp("commit");
        std::fs::write(d.join("scene.json"), "old").unwrap();
        std::fs::write(d.join("a.ply"), "A").unwrap();
        let mut t = Txn::begin(&d).unwrap();
        t.write("a.ply", b"A2").unwrap();
        t.write("objects/new.ply", b"N").unwrap();
        t.write("scene.json", b"new").unwrap();
        let b = t.backup("history/0001").unwrap();
        t.commit().unwrap();
        assert_eq!(
            std::fs::read_to_string(d.join("scene.json")).unwrap(),
            "new"
        );
        assert_eq!(std::fs::read_to_string(d.join("a.ply")).unwrap(), "A2");
        assert_eq!(
            std::fs::read_to_string(d.join("history/0001/a.ply")).unwrap(),
            "A"
        );
        assert_eq!(
            std::fs::read_to_string(d.join("history/0001/scene.json")).unwrap(),
            "old"
        );
        assert_eq!(b.created, vec!["objects/new.ply".to_string()]);
        assert!(!d.join(WORK).exists());
    }

    #[test]
    fn a_crash_before_the_journal_leaves_the_old_scene_and_after_it_the_new() {
        let d = tmp("crash");
        std::fs::write(d.join("scene.json"), "old").unwrap();
        std::fs::write(d.join("x"), "x0").unwrap();
        // Before the commit point: staged files only.
        let mut t = Txn::begin(&d).unwrap();
        t.write("x", b"x1").unwrap();
        t.write("scene.json", b"new").unwrap();
        drop(t);
        assert_eq!(
            recover(&d).unwrap(),
            Some("discarded an edit interrupted before it was committed")
        );
        assert_eq!(std::fs::read_to_string(d.join("x")).unwrap(), "x0");
        assert_eq!(
            std::fs::read_to_string(d.join("scene.json")).unwrap(),
            "old"
        );
        // After it: the journal written and one rename done.
        let mut t = Txn::begin(&d).unwrap();
        t.write("x", b"x1").unwrap();
        t.write("scene.json", b"new").unwrap();
        t.delete("gone").unwrap();
        std::fs::write(d.join("gone"), "g").unwrap();
        let j = Journal {
            renames: vec![
                (format!("{STAGE}/x"), "x".into()),
                (format!("{STAGE}/scene.json"), "scene.json".into()),
            ],
            deletes: vec!["gone".into()],
            cleanup: vec![],
        };
        std::fs::write(d.join(JOURNAL), serde_json::to_vec(&j).unwrap()).unwrap();
        std::fs::rename(d.join(STAGE).join("x"), d.join("x")).unwrap();
        assert_eq!(recover(&d).unwrap(), Some("finished an interrupted edit"));
        assert_eq!(std::fs::read_to_string(d.join("x")).unwrap(), "x1");
        assert_eq!(
            std::fs::read_to_string(d.join("scene.json")).unwrap(),
            "new"
        );
        assert!(!d.join("gone").exists());
        assert_eq!(recover(&d).unwrap(), None);
    }

    #[test]
    fn a_reader_sees_every_file_of_one_commit_never_a_mix() {
        let d = tmp("readers");
        std::fs::write(d.join("scene.json"), "0").unwrap();
        std::fs::write(d.join("a.ply"), "0").unwrap();
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let reader = {
            let (d, stop) = (d.clone(), stop.clone());
            std::thread::spawn(move || {
                let mut reads = 0;
                while !stop.load(std::sync::atomic::Ordering::SeqCst) {
                    let (j, a) = read_consistent(&d, || {
                        let j = std::fs::read_to_string(d.join("scene.json")).unwrap();
                        std::thread::yield_now();
                        (j, std::fs::read_to_string(d.join("a.ply")).unwrap())
                    })
                    .unwrap();
                    assert_eq!(j, a, "scene.json and a.ply of one commit");
                    reads += 1;
                }
                reads
            })
        };
        for n in 1..100 {
            let mut t = Txn::begin(&d).unwrap();
            t.write("a.ply", n.to_string().as_bytes()).unwrap();
            t.write("scene.json", n.to_string().as_bytes()).unwrap();
            t.commit().unwrap();
        }
        stop.store(true, std::sync::atomic::Ordering::SeqCst);
        let reads = reader.join().expect("the reader saw no mix");
        assert!(reads > 0, "the reader read");
    }
}
