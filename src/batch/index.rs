//! `DIR/index.json`: one record per scene (status, worker, attempts, timings per stage,
//! Gaussians, error), shared by every worker. Each change is a read-modify-write under an
//! advisory lock on `DIR/.index.lock`, and the file is replaced atomically, so a reader never sees
//! half a file and no worker's record overwrites another's. `DIR/index.html`, a contact sheet of
//! the finished scenes, is rewritten with it.
use super::BatchError;
use serde::{Deserialize, Serialize};
use std::fs::{File, OpenOptions};
use std::path::Path;

/// Where a scene stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    #[default]
    Pending,
    Running,
    Done,
    Failed,
}

/// The time one stage of a scene took.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StageTime {
    pub name: String,
    pub seconds: f64,
}

/// One scene's record.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct SceneRecord {
    pub id: String,
    pub prompt: String,
    pub status: Status,
    /// The worker that last claimed it: `host pid N, shard I/N`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub worker: Option<String>,
    /// How many times it was claimed.
    #[serde(default)]
    pub attempts: u32,
    /// Unix times (seconds) of the last claim and of its end.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub started: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub finished: Option<f64>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<StageTime>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seconds: Option<f64>,
    /// Gaussians of the finished scene.ply.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gaussians: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The whole index.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Index {
    pub scenes: Vec<SceneRecord>,
}

impl Index {
    /// The record of `id`, created (pending) when missing.
    pub fn record(&mut self, id: &str, prompt: &str) -> &mut SceneRecord {
        let k = match self.scenes.iter().position(|s| s.id == id) {
            Some(k) => k,
            None => {
                self.scenes.push(SceneRecord {
                    id: id.to_string(),
                    prompt: prompt.to_string(),
                    ..SceneRecord::default()
                });
                self.scenes.len() - 1
            }
        };
        &mut self.scenes[k]
    }

    /// The status of `id`, pending when unknown.
    pub fn status(&self, id: &str) -> Status {
        self.scenes
            .iter()
            .find(|s| s.id == id)
            .map_or(Status::Pending, |s| s.status)
    }
}

pub const INDEX: &str = "index.json";
pub const HTML: &str = "index.html";
const LOCK: &str = ".index.lock";

fn io_err(path: &Path) -> impl Fn(std::io::Error) -> BatchError + '_ {
    move |e| BatchError::Io {
        path: path.display().to_string(),
        msg: e.to_string(),
    }
}

/// Reads `DIR/index.json` (an empty index when there is none).
pub fn read(dir: &Path) -> Result<Index, BatchError> {
    let path = dir.join(INDEX);
    match std::fs::read_to_string(&path) {
        Ok(t) => serde_json::from_str(&t).map_err(|e| BatchError::Index {
            path: path.display().to_string(),
            msg: e.to_string(),
        }),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Index::default()),
        Err(e) => Err(io_err(&path)(e)),
    }
}

/// Applies `change` to the index under the index lock and writes index.json and index.html
/// atomically; returns what `change` returned.
pub fn update<T>(dir: &Path, change: impl FnOnce(&mut Index) -> T) -> Result<T, BatchError> {
    let lock_path = dir.join(LOCK);
    let lock: File = OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(&lock_path)
        .map_err(io_err(&lock_path))?;
    lock.lock().map_err(io_err(&lock_path))?;
    let mut index = read(dir)?;
    let out = change(&mut index);
    write(dir, &index)?;
    let _ = lock.unlock();
    Ok(out)
}

/// Writes index.json and index.html atomically (the caller holds the index lock).
fn write(dir: &Path, index: &Index) -> Result<(), BatchError> {
    let path = dir.join(INDEX);
    let mut text = serde_json::to_string_pretty(index).map_err(|e| BatchError::Index {
        path: path.display().to_string(),
        msg: e.to_string(),
    })?;
    text.push('\n');
    crate::util::write_atomic(&path, text.as_bytes()).map_err(io_err(&path))?;
    let html_path = dir.join(HTML);
    crate::util::write_atomic(&html_path, contact_sheet(dir, index).as_bytes())
        .map_err(io_err(&html_path))
}

/// The first render of a finished scene (by name), relative to the batch directory.
fn overview(dir: &Path, id: &str) -> Option<String> {
    let mut pngs: Vec<String> = std::fs::read_dir(dir.join(id).join("renders"))
        .ok()?
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".png"))
        .collect();
    pngs.sort();
    pngs.into_iter().next().map(|n| format!("{id}/renders/{n}"))
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// `index.html`: every finished scene's overview render with its id and prompt, and the counts.
pub fn contact_sheet(dir: &Path, index: &Index) -> String {
    let c = Counts::of(index, &|_| false);
    let mut s = format!(
        "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>dreamscene batch</title>\n\
         <style>body{{font-family:sans-serif;background:#111;color:#ddd}}\
         figure{{display:inline-block;width:260px;margin:6px;vertical-align:top}}\
         img{{width:256px;height:256px;object-fit:cover;background:#222}}\
         figcaption{{font-size:12px}}</style></head><body>\n\
         <h1>{} done, {} running, {} failed, {} left</h1>\n",
        c.done, c.running, c.failed, c.left
    );
    for r in index.scenes.iter().filter(|r| r.status == Status::Done) {
        let img = overview(dir, &r.id).map_or(String::new(), |p| {
            format!("<img src=\"{}\" alt=\"{}\">", escape(&p), escape(&r.id))
        });
        s.push_str(&format!(
            "<figure><a href=\"{id}/\">{img}</a><figcaption><b>{id}</b> {}</figcaption></figure>\n",
            escape(&r.prompt),
            id = escape(&r.id),
        ));
    }
    s.push_str("</body></html>\n");
    s
}

/// Scenes by status; a running record whose worker is gone counts as left.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    pub done: usize,
    pub running: usize,
    pub failed: usize,
    pub left: usize,
}

impl Counts {
    /// Counts `index`; `gone(record)` says whether a running record's worker has died.
    pub fn of(index: &Index, gone: &dyn Fn(&SceneRecord) -> bool) -> Counts {
        let mut c = Counts::default();
        for r in &index.scenes {
            match r.status {
                Status::Done => c.done += 1,
                Status::Failed => c.failed += 1,
                Status::Running if !gone(r) => c.running += 1,
                Status::Running | Status::Pending => c.left += 1,
            }
        }
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn concurrent_updates_lose_nothing_and_the_sheet_escapes_prompts() {
        let dir = std::env::temp_dir().join(format!("ds-index-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::thread::scope(|s| {
            for t in 0..4 {
                let dir = &dir;
                s.spawn(move || {
                    for k in 0..10 {
                        update(dir, |ix| {
                            ix.record(&format!("{t}-{k}"), "a <b> & c").status = Status::Done
                        })
                        .unwrap();
                    }
                });
            }
        });
        let ix = read(&dir).unwrap();
        assert_eq!(ix.scenes.len(), 40, "every worker's records kept");
        let c = Counts::of(&ix, &|_| false);
        assert_eq!((c.done, c.left), (40, 0));
        let html = std::fs::read_to_string(dir.join(HTML)).unwrap();
        assert!(html.contains("a &lt;b&gt; &amp; c") && !html.contains("<b> &"));
        assert!(html.contains("40 done"));
        std::fs::write(dir.join(INDEX), "{not json").unwrap();
        let err = read(&dir).unwrap_err().to_string();
        assert!(err.contains("index.json"), "{err}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
