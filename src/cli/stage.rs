//! `generate --stage objects|scene`: one scene spread over several workers. Every objects
//! worker plans the same prompt and seed (or reuses the plan already in --out) and builds its
//! shard of the categories; the scene stage (an `afterok` dependency on all of them) checks that
//! every object is there, naming any that is missing, then writes the environment, scene.ply,
//! scene.json and the renders exactly as a single `generate` does. Drafts here; the sd and
//! oracle priors in [`super::stage_prior`]. Also the timed stages that `batch` runs for each
//! draft scene.
use super::generate::{draft_mode, plan_or_reuse, GenerateArgs};
use super::object::models_dir;
use super::scene_renders::render_chosen;
use anyhow::{bail, Result};
use dreamscene::batch::index::StageTime;
use dreamscene::batch::shard::{self, Shard};
use dreamscene::generate::object_shard::{build_draft_objects, missing_objects};
use dreamscene::generate::scene::{check_resume, write_draft_scene};
use dreamscene::plan::spec::{Layout, SceneSpec};
use dreamscene::scene::dir::read_scene;
use std::time::Instant;

/// A stage of `generate`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Stage {
    /// Plan (or reuse the plan in --out) and build this shard's objects.
    Objects,
    /// Environment, composition and renders, once every object is there.
    Scene,
}

/// `generate --stage`.
pub fn run(a: &GenerateArgs, stage: Stage, shard: Option<Shard>) -> Result<()> {
    let models = models_dir(a.models.as_deref());
    let text = super::plan::plan_text(a.prompt.clone(), a.dialogue.clone(), false)?;
    super::create_dir(&a.out)?;
    if !draft_mode(a, models.as_deref())? {
        return super::stage_prior::run(a, &text, models.as_deref(), stage, shard);
    }
    match stage {
        Stage::Objects => {
            let env = |k: &str| std::env::var(k).ok();
            let shard = shard::resolve(shard, None, &env).map_err(anyhow::Error::msg)?;
            let (spec, layout) = plan_or_reuse(&text, a, true)?;
            let built = build_draft_objects(&a.out, &spec, &layout, a.seed, shard)?;
            let names: Vec<String> = built
                .iter()
                .map(|(c, n, new)| format!("{c} ({n}{})", if *new { "" } else { ", kept" }))
                .collect();
            println!(
                "objects{}: {}",
                shard.map_or(String::new(), |s| format!(" shard {s}")),
                if names.is_empty() {
                    "none in this shard".to_string()
                } else {
                    names.join(", ")
                }
            );
        }
        Stage::Scene => {
            if shard.is_some() {
                bail!("--shard goes with --stage objects; the scene stage runs once");
            }
            let (spec, layout) = planned(a)?;
            let t = Instant::now();
            let g = scene_stage(a, &text, &spec, &layout)?;
            println!(
                "scene: {} Gaussians in {:.1} s; wrote {}",
                g,
                t.elapsed().as_secs_f64(),
                a.out.join("scene.json").display()
            );
        }
    }
    Ok(())
}

/// The plan an objects stage left in --out.
fn planned(a: &GenerateArgs) -> Result<(SceneSpec, Layout)> {
    let (s, l) = (a.out.join("spec.json"), a.out.join("layout.json"));
    if !(s.is_file() && l.is_file()) {
        bail!(
            "{}: no spec.json and layout.json; run `generate --stage objects` first",
            a.out.display()
        );
    }
    Ok((SceneSpec::read(&s)?, Layout::read(&l)?))
}

/// Environment, scene.ply, scene.json and renders from the objects in --out; the scene's
/// Gaussians.
fn scene_stage(a: &GenerateArgs, text: &str, spec: &SceneSpec, layout: &Layout) -> Result<usize> {
    let missing = missing_objects(&a.out, spec, layout);
    if !missing.is_empty() {
        bail!(
            "{}: missing objects: {} (their `generate --stage objects` shard has not finished)",
            a.out.display(),
            missing.join(", ")
        );
    }
    let report = write_draft_scene(&a.out, text, a.seed, spec, layout, true, &mut |_| {})?;
    if a.renders > 0 {
        let g = dreamscene::splat::ply::read_ply(&a.out.join("scene.ply"))?;
        render_chosen(&g, layout, a.renders, a.resolution, &a.out.join("renders"))?;
    }
    Ok(report.scene_gaussians)
}

/// A whole draft scene in timed stages (plan, objects, scene with renders), resuming whatever
/// an interrupted run left; the same files as `generate`. Returns the stage times and the
/// scene's Gaussians.
pub fn draft_timed(a: &GenerateArgs) -> Result<(Vec<StageTime>, usize)> {
    let text = super::plan::plan_text(a.prompt.clone(), a.dialogue.clone(), false)?;
    if a.out.join("scene.json").is_file() {
        // A scene of another prompt or seed is refused, never overwritten.
        check_resume(&read_scene(&a.out)?, &text, a.seed)?;
    }
    super::create_dir(&a.out)?;
    let mut times = vec![];
    let mut timed = |name: &str, t: Instant| {
        times.push(StageTime {
            name: name.to_string(),
            seconds: t.elapsed().as_secs_f64(),
        })
    };
    let t = Instant::now();
    let (spec, layout) = plan_or_reuse(&text, a, true)?;
    timed("plan", t);
    let t = Instant::now();
    build_draft_objects(&a.out, &spec, &layout, a.seed, None)?;
    timed("objects", t);
    let t = Instant::now();
    let g = scene_stage(a, &text, &spec, &layout)?;
    timed("scene", t);
    Ok((times, g))
}

/// Whether `a` makes a draft.
pub fn is_draft(a: &GenerateArgs) -> Result<bool> {
    draft_mode(a, models_dir(a.models.as_deref()).as_deref())
}
