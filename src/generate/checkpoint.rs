//! Checkpoints of an object run, in `<out>/checkpoints/`: the cloud as a PLY and the optimiser
//! state beside it (iteration, Adam moments, the trainer's generator), and `run.json` with the
//! stage, the positions of the run's random generators and the Gaussian counts. Each checkpoint
//! writes new numbered files first and `run.json` last (atomically), then removes the old files,
//! so a kill at any moment leaves a complete checkpoint: the last one `run.json` names. The scene
//! stages write the same files ([`write_trainer`]) under their own cursor, `scene_run.json`.
use super::object::{Checkpoints, Counts, GenError};
use crate::splat::ply::{read_ply, write_ply};
use crate::splat::train::Trainer;
use crate::splat::Gaussians;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Which stage a run is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    Formation,
    Reconstruction,
    Done,
}

impl Stage {
    pub fn name(self) -> &'static str {
        match self {
            Stage::Formation => "formation",
            Stage::Reconstruction => "reconstruction",
            Stage::Done => "done",
        }
    }
}

/// `run.json`.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct RunState {
    pub fingerprint: String,
    pub stage: Stage,
    /// Iterations done in the stage.
    pub iteration: u32,
    /// The stage's cloud and optimiser state (relative to the checkpoint directory).
    pub ply: Option<String>,
    /// The filtered cloud reconstruction starts from.
    pub filtered_ply: Option<String>,
    /// Word positions of the run's generators (cameras and backgrounds; the two guides' noise).
    pub rng: u128,
    pub guide: u128,
    pub recon_guide: u128,
    pub counts: Counts,
    pub stage_seconds: [f64; 3],
    pub previous_seconds: f64,
    #[serde(skip)]
    pub filtered: Option<Gaussians>,
}

const RUN: &str = "run.json";

/// Writes a stage checkpoint of `t` into `dir`: the cloud as `<stage>_<iteration>.ply` and the
/// optimiser state (iteration, Adam moments, the trainer's generator) beside it as `.state`.
/// Returns the PLY's name, which the caller's cursor records once both files are written.
pub fn write_trainer(dir: &Path, stage: &str, t: &Trainer) -> Result<String, GenError> {
    std::fs::create_dir_all(dir).map_err(|err| GenError::Io {
        path: dir.to_path_buf(),
        err,
    })?;
    let name = format!("{stage}_{:06}.ply", t.iteration());
    let path = dir.join(&name);
    let g = t.gaussians()?;
    write_ply(&path, &g).map_err(|err| GenError::Io {
        path: path.clone(),
        err,
    })?;
    let state = dir.join(format!("{name}.state"));
    t.save_state(&state)
        .map_err(|err| GenError::Io { path: state, err })?;
    Ok(name)
}

/// Restores into `t` the optimiser state a [`write_trainer`] checkpoint named `name` holds.
pub fn restore_trainer(dir: &Path, name: &str, t: &mut Trainer) -> Result<(), GenError> {
    t.restore(&dir.join(format!("{name}.state"))).map_err(ck)
}

/// Removes the checkpoint files of `old` once the cursor names `keep` instead.
pub fn remove_old(dir: &Path, old: Option<String>, keep: Option<&str>) {
    if let Some(o) = old {
        if Some(o.as_str()) != keep {
            let _ = std::fs::remove_file(dir.join(&o));
            let _ = std::fs::remove_file(dir.join(format!("{o}.state")));
        }
    }
}

fn ck(msg: String) -> GenError {
    GenError::Checkpoint(msg)
}

impl RunState {
    pub fn new(initial: usize) -> RunState {
        RunState {
            fingerprint: String::new(),
            stage: Stage::Formation,
            iteration: 0,
            ply: None,
            filtered_ply: None,
            rng: 0,
            guide: 0,
            recon_guide: 0,
            counts: Counts {
                initial,
                ..Counts::default()
            },
            stage_seconds: [0.0; 3],
            previous_seconds: 0.0,
            filtered: None,
        }
    }

    /// Reads `run.json` of `c`; a missing one is an error that says so.
    pub fn load(c: &Checkpoints) -> Result<RunState, GenError> {
        let path = c.dir.join(RUN);
        let text = std::fs::read_to_string(&path).map_err(|e| {
            ck(format!(
                "{}: nothing to resume ({e}); run without --resume",
                path.display()
            ))
        })?;
        let mut s: RunState = serde_json::from_str(&text).map_err(|e| {
            ck(format!(
                "{}: not a dreamscene checkpoint ({e})",
                path.display()
            ))
        })?;
        // Time already spent, so the report covers the whole run.
        s.previous_seconds = s.stage_seconds.iter().sum();
        Ok(s)
    }

    /// The stage's checkpointed cloud.
    pub fn load_ply(&self, dir: &Path) -> Result<Gaussians, GenError> {
        let name = self
            .ply
            .as_ref()
            .ok_or_else(|| ck(format!("{}: the checkpoint names no cloud", dir.display())))?;
        read_ply(&dir.join(name)).map_err(|e| ck(e.to_string()))
    }

    /// The filtered cloud reconstruction starts from.
    pub fn load_filtered(&self, dir: &Path) -> Result<Gaussians, GenError> {
        let name = self.filtered_ply.as_ref().ok_or_else(|| {
            ck(format!(
                "{}: the checkpoint has no filtered cloud",
                dir.display()
            ))
        })?;
        read_ply(&dir.join(name)).map_err(|e| ck(e.to_string()))
    }

    /// Restores the optimiser state written beside the stage's cloud.
    pub fn restore_trainer(&self, dir: &Path, t: &mut Trainer) -> Result<(), GenError> {
        let name = self
            .ply
            .as_ref()
            .ok_or_else(|| ck(format!("{}: the checkpoint names no cloud", dir.display())))?;
        restore_trainer(dir, name, t)
    }

    fn commit(&mut self, c: &Checkpoints, new_ply: Option<String>) -> Result<(), GenError> {
        self.fingerprint = c.fingerprint.clone();
        let old = std::mem::replace(&mut self.ply, new_ply);
        let text = serde_json::to_string_pretty(self).expect("serialisable");
        let path = c.dir.join(RUN);
        crate::util::write_atomic(&path, text.as_bytes()).map_err(|err| GenError::Io {
            path: path.clone(),
            err,
        })?;
        remove_old(c.dir, old, self.ply.as_deref());
        Ok(())
    }

    fn write_stage(&mut self, c: &Checkpoints, t: &Trainer, prefix: &str) -> Result<(), GenError> {
        let name = write_trainer(c.dir, prefix, t)?;
        self.iteration = t.iteration();
        self.commit(c, Some(name))
    }

    /// A formation checkpoint.
    pub fn save_formation(&mut self, c: &Checkpoints, t: &Trainer) -> Result<(), GenError> {
        self.write_stage(c, t, "formation")
    }

    /// A reconstruction checkpoint.
    pub fn save_recon(&mut self, c: &Checkpoints, t: &Trainer) -> Result<(), GenError> {
        self.write_stage(c, t, "reconstruction")
    }

    /// The filtered cloud, at the start of reconstruction.
    pub fn save_filtered(&mut self, c: &Checkpoints, g: &Gaussians) -> Result<(), GenError> {
        std::fs::create_dir_all(c.dir).map_err(|err| GenError::Io {
            path: c.dir.to_path_buf(),
            err,
        })?;
        let name = "filtered.ply".to_string();
        let path = c.dir.join(&name);
        write_ply(&path, g).map_err(|err| GenError::Io { path, err })?;
        self.filtered_ply = Some(name);
        self.commit(c, None)
    }

    /// The run finished.
    pub fn save_done(&mut self, c: &Checkpoints) -> Result<(), GenError> {
        std::fs::create_dir_all(c.dir).map_err(|err| GenError::Io {
            path: c.dir.to_path_buf(),
            err,
        })?;
        self.commit(c, None)
    }
}
