//! The objects of a scene generated with a prior (sd or oracle), all of them or one shard's
//! (`generate --stage objects --shard I/N`), each checkpointed in `checkpoints/objects/<cat>/`.
//! A shard records what it finished in its own state file, `checkpoints/objects_run_<I>of<N>.json`
//! (so shards running at once never write the same file); the scene step merges every state
//! file of the same run (same fingerprint) with its own `scene_run.json`, and refuses, naming
//! them, while an object is missing. Which shard makes a category is
//! [`super::object_shard::shard_categories`]'s pure function of the plan.
use super::object::{generate_object, Checkpoints, GenError};
use super::object_shard::shard_categories;
use super::progress::Progress;
use super::scene::object_ply;
use super::scene_stages::{SceneJob, ScenePriors};
use crate::batch::shard::Shard;
use crate::camera::object::ObjectFrame;
use crate::diffusion::Error;
use crate::shape::{self, ShapeOptions};
use crate::splat::ply::{read_ply, write_ply};
use crate::splat::Gaussians;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A shard's state file: the run it belongs to and the categories it finished.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct ObjectsRun {
    pub fingerprint: String,
    pub objects_done: Vec<String>,
}

/// The state file of `shard` in the checkpoint directory `ck`.
pub fn shard_state(ck: &Path, shard: Shard) -> PathBuf {
    ck.join(format!("objects_run_{}of{}.json", shard.index, shard.count))
}

/// The categories that any shard of the run `fingerprint` finished (state files of other runs
/// are ignored), sorted and each once.
pub fn done_by_shards(ck: &Path, fingerprint: &str) -> Vec<String> {
    let mut done: Vec<String> = std::fs::read_dir(ck)
        .into_iter()
        .flatten()
        .flatten()
        .filter(|e| {
            let name = e.file_name().to_string_lossy().to_string();
            name.starts_with("objects_run_") && name.ends_with(".json")
        })
        .filter_map(|e| std::fs::read_to_string(e.path()).ok())
        .filter_map(|t| serde_json::from_str::<ObjectsRun>(&t).ok())
        .filter(|r| r.fingerprint == fingerprint)
        .flat_map(|r| r.objects_done)
        .collect();
    done.sort();
    done.dedup();
    done
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> GenError + '_ {
    move |err| GenError::Io {
        path: path.to_path_buf(),
        err,
    }
}

/// Generates the objects of `shard` (all when `None`) into the job's `out/objects/`.
/// Categories in `done` are read back instead; each one finished is added to `done` and
/// `save(done)` is called (the caller's state file). Returns every category's cloud handled here.
pub fn generate_objects(
    job: &SceneJob,
    priors: &mut dyn ScenePriors,
    shard: Option<Shard>,
    done: &mut Vec<String>,
    save: &mut dyn FnMut(&[String]) -> Result<(), GenError>,
    log: &mut dyn FnMut(&str),
) -> Result<BTreeMap<String, Gaussians>, GenError> {
    let SceneJob {
        ctx,
        out,
        spec,
        layout,
        cfg,
        resume,
        ..
    } = *job;
    let ck = out.join("checkpoints");
    std::fs::create_dir_all(out.join("objects")).map_err(io(out))?;
    let mut objects = BTreeMap::new();
    for (cat, size) in shard_categories(spec, layout, shard) {
        let path = out.join(object_ply(&cat));
        if done.contains(&cat) {
            let g = read_ply(&path).map_err(|e| GenError::Checkpoint(e.to_string()))?;
            objects.insert(cat.clone(), g);
            log(&format!("object {cat}: done before, kept"));
            continue;
        }
        let description = spec.objects.get(&cat).map_or_else(
            || format!("A DSLR photo of a {cat}"),
            |o| o.description.clone(),
        );
        let init = shape::build(
            &cat,
            size,
            &description,
            &ShapeOptions {
                gaussians: cfg.object_gaussians,
                seed: cfg.seed,
                variant: 0,
                mount: Some(shape::Mount::in_scene(spec, &cat)),
            },
        )
        .map_err(|e| GenError::Prior(Error::Input(e.to_string())))?;
        let prior = priors.for_object(&cat, &description)?;
        let odir = ck.join("objects").join(cat.replace(' ', "_"));
        let c = Checkpoints {
            dir: &odir,
            resume: resume && odir.join("run.json").is_file(),
            fingerprint: cfg.object.fingerprint(&description, prior.kind()),
        };
        log(&format!(
            "object {cat}: generating ({} iterations)",
            cfg.object.iterations
        ));
        let mut progress = Progress::new(0, true);
        let (g, rep) = generate_object(
            ctx,
            &init,
            &ObjectFrame { size },
            prior,
            &cfg.object,
            Some(&c),
            &mut progress,
        )?;
        write_ply(&path, &g).map_err(io(&path))?;
        log(&format!(
            "object {cat}: {} Gaussians ({} before filtering, {} after), {:.1} s",
            g.len(),
            rep.counts.before_filter,
            rep.counts.after_filter,
            rep.seconds
        ));
        objects.insert(cat.clone(), g);
        done.push(cat);
        save(done)?;
    }
    Ok(objects)
}

/// `generate --stage objects --shard I/N` with a prior: this shard's objects, its state file
/// kept after each one (and read back with `resume`, so a requeued shard redoes only what it
/// had not finished; a state file of another run is set aside with a line in the log).
/// Returns the categories this shard holds.
pub fn generate_shard(
    job: &SceneJob,
    priors: &mut dyn ScenePriors,
    shard: Shard,
    log: &mut dyn FnMut(&str),
) -> Result<Vec<String>, GenError> {
    let SceneJob {
        out,
        prompt,
        cfg,
        resume,
        ..
    } = *job;
    let ck = out.join("checkpoints");
    std::fs::create_dir_all(&ck).map_err(io(&ck))?;
    let fp = cfg.fingerprint(prompt, &priors.kind());
    let state = shard_state(&ck, shard);
    let before = std::fs::read_to_string(&state)
        .ok()
        .filter(|_| resume)
        .and_then(|t| serde_json::from_str::<ObjectsRun>(&t).ok());
    let mut done = match before {
        Some(r) if r.fingerprint == fp => r.objects_done,
        Some(_) => {
            log(&format!(
                "{}: the state of another run (prompt, prior, seed or settings differ); this \
                 shard starts afresh",
                state.display()
            ));
            vec![]
        }
        None => vec![],
    };
    let mut save = |d: &[String]| {
        let r = ObjectsRun {
            fingerprint: fp.clone(),
            objects_done: d.to_vec(),
        };
        let text = serde_json::to_string_pretty(&r).expect("serialisable");
        crate::util::write_atomic(&state, text.as_bytes()).map_err(io(&state))
    };
    save(&done)?;
    let made = generate_objects(job, priors, Some(shard), &mut done, &mut save, log)?;
    Ok(made.into_keys().collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shard_states_merge_only_within_one_run() {
        let d = std::env::temp_dir().join(format!("ds-objects-run-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        let write = |s: Shard, fp: &str, done: &[&str]| {
            let r = ObjectsRun {
                fingerprint: fp.into(),
                objects_done: done.iter().map(|c| c.to_string()).collect(),
            };
            std::fs::write(shard_state(&d, s), serde_json::to_string(&r).unwrap()).unwrap();
        };
        write(Shard { index: 0, count: 2 }, "a", &["desk", "bed"]);
        write(Shard { index: 1, count: 2 }, "a", &["chair", "bed"]);
        write(Shard { index: 0, count: 3 }, "b", &["lamp"]);
        std::fs::write(d.join("objects_run_9of9.json"), "not json").unwrap();
        assert_eq!(done_by_shards(&d, "a"), ["bed", "chair", "desk"]);
        assert_eq!(done_by_shards(&d, "b"), ["lamp"]);
        assert!(done_by_shards(&d, "c").is_empty());
        std::fs::remove_dir_all(&d).ok();
    }
}
