//! `generate --stage objects|scene` with the sd or oracle prior: each objects worker generates
//! its shard's objects (`--shard I/N`, or from the Slurm or Kubernetes environment) and keeps
//! its own state file in `checkpoints/`; the scene stage merges every shard's state, names any
//! object still missing, and otherwise runs the environment stages, scene.ply, scene.json and
//! the renders as a single `generate` would, keeping the shards' objects.
use super::generate::GenerateArgs;
use super::generate_full::{full, full_setup};
use super::stage::Stage;
use anyhow::{bail, Result};
use dreamscene::batch::shard::{self, Shard};
use dreamscene::generate::object_shard::shard_categories;
use dreamscene::generate::scene::object_ply;
use dreamscene::generate::scene_objects::{done_by_shards, generate_shard};
use dreamscene::generate::scene_stages::{SceneJob, SceneRun};
use std::path::Path;
use std::time::Instant;

/// One stage with a prior.
pub fn run(
    a: &GenerateArgs,
    text: &str,
    models: Option<&Path>,
    stage: Stage,
    shard: Option<Shard>,
) -> Result<()> {
    let start = Instant::now();
    match stage {
        Stage::Objects => {
            let env = |k: &str| std::env::var(k).ok();
            let shard = shard::resolve(shard, None, &env)
                .map_err(anyhow::Error::msg)?
                .unwrap_or(Shard { index: 0, count: 1 });
            let mut f = full_setup(a, text, models, true)?;
            let job = SceneJob {
                ctx: &f.ctx,
                out: &a.out,
                prompt: text,
                spec: &f.spec,
                layout: &f.layout,
                cfg: &f.cfg,
                resume: true,
            };
            let made = generate_shard(&job, f.priors.as_mut(), shard, &mut |l| eprintln!("{l}"))?;
            println!(
                "objects shard {shard}: {} in {:.1} s",
                if made.is_empty() {
                    "none in this shard".to_string()
                } else {
                    made.join(", ")
                },
                start.elapsed().as_secs_f64()
            );
            Ok(())
        }
        Stage::Scene => {
            if shard.is_some() {
                bail!("--shard goes with --stage objects; the scene stage runs once");
            }
            if !(a.out.join("spec.json").is_file() && a.out.join("layout.json").is_file()) {
                bail!(
                    "{}: no spec.json and layout.json; run `generate --stage objects` first",
                    a.out.display()
                );
            }
            let f = full_setup(a, text, models, true)?;
            let missing = missing(&a.out, &f, text);
            if !missing.is_empty() {
                bail!(
                    "{}: missing objects: {} (their `generate --stage objects` shard has not \
                     finished)",
                    a.out.display(),
                    missing.join(", ")
                );
            }
            full(a, text, models, start, true, f).map(|_| ())
        }
    }
}

/// The categories no shard of this run (nor an earlier scene step) finished, or whose PLY is
/// gone.
fn missing(out: &Path, f: &super::generate_full::Full, text: &str) -> Vec<String> {
    let ck = out.join("checkpoints");
    let fp = f.cfg.fingerprint(text, &f.priors.kind());
    let mut done = done_by_shards(&ck, &fp);
    let run: Option<SceneRun> = std::fs::read_to_string(ck.join("scene_run.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok());
    if let Some(r) = run.filter(|r| r.fingerprint == fp) {
        done.extend(r.objects_done);
    }
    shard_categories(&f.spec, &f.layout, None)
        .into_iter()
        .map(|(c, _)| c)
        .filter(|c| !done.contains(c) || !out.join(object_ply(c)).is_file())
        .collect()
}
