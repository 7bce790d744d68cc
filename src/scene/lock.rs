//! One writer per scene directory: an advisory lock on `DIR/.lock`, taken by every command that
//! writes a scene (`generate`, `edit`, `generate --resume`, `batch`).
//!
//! The lock is the operating system's advisory file lock (`flock` on Unix) through the standard
//! library's `File::lock`/`try_lock`, so it is released by the kernel when the holder exits or is
//! killed: a crash never leaves a stale lock. The lock file is never deleted (deleting it would let
//! two writers lock two different files); after locking, the holder writes its pid and command
//! line into it so a refused writer can name who holds the scene. Host-only.
use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// The lock file's name inside a scene directory.
pub const LOCK_FILE: &str = ".lock";

/// What a writer does when another one holds the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wait {
    /// Block until the holder finishes (after one line on stderr naming it).
    Block,
    /// Return [`LockError::Busy`] at once.
    NoWait,
}

/// Why a scene could not be locked.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    /// Another process holds the scene.
    #[error("{dir} is being written by {holder}; wait for it to finish or stop it")]
    Busy { dir: String, holder: String },
    /// The lock file could not be opened or locked.
    #[error("{path}: {msg}")]
    Io { path: String, msg: String },
}

/// A held scene lock; dropping it releases the scene.
#[derive(Debug)]
pub struct SceneLock {
    file: File,
    path: PathBuf,
}

impl SceneLock {
    /// Locks `dir` (which must exist) for writing. `command` is recorded for other writers.
    pub fn acquire(dir: &Path, wait: Wait, command: &str) -> Result<SceneLock, LockError> {
        let path = dir.join(LOCK_FILE);
        let io = |e: std::io::Error| LockError::Io {
            path: path.display().to_string(),
            msg: e.to_string(),
        };
        let mut file = OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&path)
            .map_err(io)?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                let holder = holder_of(&mut file);
                if wait == Wait::NoWait {
                    return Err(LockError::Busy {
                        dir: dir.display().to_string(),
                        holder,
                    });
                }
                eprintln!("waiting: {} is being written by {holder}", dir.display());
                file.lock().map_err(io)?;
            }
            Err(TryLockError::Error(e)) => return Err(io(e)),
        }
        let note = format!("pid {} ({})\n", std::process::id(), command);
        file.set_len(0).map_err(io)?;
        file.seek(SeekFrom::Start(0)).map_err(io)?;
        file.write_all(note.as_bytes()).map_err(io)?;
        file.flush().map_err(io)?;
        Ok(SceneLock { file, path })
    }

    /// The lock file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for SceneLock {
    fn drop(&mut self) {
        // The holder note is cleared so a later reader of the file does not name a finished
        // process; the kernel releases the lock itself when the file closes.
        let _ = self.file.set_len(0);
        let _ = self.file.unlock();
    }
}

/// The file that orders a scene's commits against its readers (`DIR/.commit.lock`).
///
/// A writer holds [`SceneLock`] for its whole run (minutes with the sd prior) but changes the
/// files the readers see only while it applies a committed journal (milliseconds): it holds
/// this file's lock exclusively then ([`CommitGuard`]), and `render`, `video`, `export` and
/// `view` hold it shared while they read the scene's files ([`ReadGuard`]), so a reader sees
/// the scene before an edit or after it, never a mix, and never waits for a whole edit.
pub const COMMIT_LOCK_FILE: &str = ".commit.lock";

/// Held exclusively while a writer puts a committed edit in place; dropping it lets readers in.
#[derive(Debug)]
pub struct CommitGuard {
    _file: File,
}

/// Held shared while a reader reads a scene's files; dropping it lets writers commit.
#[derive(Debug)]
pub struct ReadGuard {
    _file: Option<File>,
}

fn open_commit_lock(dir: &Path, create: bool) -> Result<File, LockError> {
    let path = dir.join(COMMIT_LOCK_FILE);
    OpenOptions::new()
        .read(true)
        .write(create)
        .create(create)
        .truncate(false)
        .open(&path)
        .map_err(|e| LockError::Io {
            path: path.display().to_string(),
            msg: e.to_string(),
        })
}

impl CommitGuard {
    /// Waits until no reader is reading `dir`, then keeps them out until dropped.
    pub fn acquire(dir: &Path) -> Result<CommitGuard, LockError> {
        let file = open_commit_lock(dir, true)?;
        file.lock().map_err(|e| LockError::Io {
            path: dir.join(COMMIT_LOCK_FILE).display().to_string(),
            msg: e.to_string(),
        })?;
        Ok(CommitGuard { _file: file })
    }
}

impl ReadGuard {
    /// Waits until no writer is putting an edit in place in `dir`, then keeps writers from
    /// doing so until dropped. A scene nobody may write (a read-only directory without the
    /// lock file) needs no guard: the guard is then empty.
    pub fn acquire(dir: &Path) -> Result<ReadGuard, LockError> {
        let file = match open_commit_lock(dir, true) {
            Ok(f) => f,
            Err(_) => match open_commit_lock(dir, false) {
                Ok(f) => f,
                Err(_) => return Ok(ReadGuard { _file: None }),
            },
        };
        file.lock_shared().map_err(|e| LockError::Io {
            path: dir.join(COMMIT_LOCK_FILE).display().to_string(),
            msg: e.to_string(),
        })?;
        Ok(ReadGuard { _file: Some(file) })
    }
}

/// Who holds the lock, as its note says ("pid N (command)"), or "another process".
fn holder_of(file: &mut File) -> String {
    let mut s = String::new();
    let _ = file.seek(SeekFrom::Start(0));
    let _ = file.read_to_string(&mut s);
    let s = s.trim();
    if s.is_empty() {
        "another process".to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn second_writer_is_refused_naming_the_holder_and_admitted_after_release() {
        let dir = std::env::temp_dir().join(format!("ds-lock-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let first = SceneLock::acquire(&dir, Wait::NoWait, "edit move").expect("first lock");
        // flock locks belong to the open file description, so a second open in the same process
        // conflicts exactly as another process would.
        let err = SceneLock::acquire(&dir, Wait::NoWait, "edit restyle").expect_err("busy");
        let msg = err.to_string();
        assert!(msg.contains("edit move"), "holder named: {msg}");
        assert!(
            msg.contains(&std::process::id().to_string()),
            "pid named: {msg}"
        );
        drop(first);
        let again = SceneLock::acquire(&dir, Wait::NoWait, "edit restyle");
        assert!(again.is_ok(), "released lock can be taken again");
        drop(again);
        // Readers share the commit lock; a committing writer excludes them.
        let r1 = ReadGuard::acquire(&dir).expect("first reader");
        let r2 = ReadGuard::acquire(&dir).expect("readers share");
        let f = open_commit_lock(&dir, true).expect("lock file");
        assert!(
            matches!(f.try_lock(), Err(TryLockError::WouldBlock)),
            "a commit waits for the readers"
        );
        drop((r1, r2));
        let c = CommitGuard::acquire(&dir).expect("commit after the readers");
        assert!(
            matches!(f.try_lock_shared(), Err(TryLockError::WouldBlock)),
            "a reader waits for the commit"
        );
        drop(c);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
