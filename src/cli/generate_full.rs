//! Full generation with the `sd` or `oracle:DIR` prior (`generate` and `generate --stage`):
//! the device, plan, priors and settings, then the object and environment stages and the scene
//! files.
use super::generate::{plan_line, plan_or_reuse, GenerateArgs};
use super::object::PriorChoice;
use super::scene_renders::render_chosen;
use anyhow::{Context as _, Result};
use dreamscene::batch::index::StageTime;
use dreamscene::generate::scene_stages::{generate_scene, SceneJob};
use dreamscene::plan::spec::{Layout, SceneSpec};
use std::path::Path;
use std::time::Instant;

/// What a generation with the `sd` or `oracle:DIR` prior runs with.
pub(super) struct Full {
    pub ctx: dreamscene::gpu::Context,
    pub spec: SceneSpec,
    pub layout: Layout,
    pub priors: Box<dyn dreamscene::generate::scene_stages::ScenePriors>,
    pub cfg: dreamscene::generate::scene_stages::SceneConfig,
}

/// The device, plan (reused from --out with `resume`, and always for the oracle, whose plan is
/// its reference's), priors and settings of a generation with the `sd` or `oracle:DIR` prior.
pub(super) fn full_setup(
    a: &GenerateArgs,
    text: &str,
    models: Option<&Path>,
    resume: bool,
) -> Result<Full> {
    use dreamscene::generate::object::ObjectConfig;
    use dreamscene::generate::scene_stages::{
        OracleScenePriors, SceneConfig, ScenePriors, SdScenePriors,
    };
    let out = &a.out;
    let ctx = super::open_device()?;
    // The oracle regenerates its reference scene from the reference's own plan and layout.
    if let PriorChoice::Oracle(dir) = &a.prior {
        for f in ["spec.json", "layout.json"] {
            let (from, to) = (dir.join(f), out.join(f));
            if !(resume && to.is_file()) {
                // Read whole and written atomically: another shard may be reading `to`.
                let bytes = std::fs::read(&from).with_context(|| {
                    format!("the oracle's reference scene: reading {}", from.display())
                })?;
                dreamscene::util::write_atomic(&to, &bytes)
                    .with_context(|| format!("writing {}", to.display()))?;
            }
        }
    }
    let resume_plan = resume || matches!(a.prior, PriorChoice::Oracle(_));
    let (spec, layout) = plan_or_reuse(text, a, resume_plan)?;
    let priors: Box<dyn ScenePriors> = match &a.prior {
        PriorChoice::Oracle(dir) => Box::new(OracleScenePriors::new(&ctx, dir)),
        _ => {
            let dir = models.expect("checked by the caller");
            let sd = dreamscene::generate::prior_spec::open_sd(dir, a.provider, text, None)?;
            Box::new(SdScenePriors(sd))
        }
    };
    let cfg = SceneConfig {
        iterations: a.iterations,
        object: ObjectConfig {
            iterations: a.object_iterations,
            resolution: a.resolution,
            sh_degree: 1,
            seed: a.seed,
            recon_passes: a.object_recon_passes,
            ..ObjectConfig::default()
        },
        resolution: a.resolution,
        recon_passes: a.recon_passes,
        seed: a.seed,
        object_gaussians: a.object_gaussians,
        env: dreamscene::scene::env::EnvOptions {
            density: a.env_density,
            ..Default::default()
        },
        ..SceneConfig::default()
    };
    eprintln!("{}; prior {}", plan_line(&layout), priors.kind());
    Ok(Full {
        ctx,
        spec,
        layout,
        priors,
        cfg,
    })
}

/// Full generation with the `sd` or `oracle:DIR` prior: objects by Formation Pattern Sampling
/// (with `resume`, those already finished, by an earlier run or by `--stage objects` shards,
/// are kept), the three environment stages, then scene.json, scene.ply and the renders.
pub(super) fn full(
    a: &GenerateArgs,
    text: &str,
    models: Option<&Path>,
    start: Instant,
    resume: bool,
    setup: Full,
) -> Result<Vec<StageTime>> {
    let out = &a.out;
    let Full {
        ctx,
        spec,
        layout,
        mut priors,
        cfg,
    } = setup;
    let job = SceneJob {
        ctx: &ctx,
        out,
        prompt: text,
        spec: &spec,
        layout: &layout,
        cfg: &cfg,
        resume,
    };
    let set_up = start.elapsed().as_secs_f64();
    let report = generate_scene(&job, priors.as_mut(), &mut |l| eprintln!("{l}"))?;
    let outputs = Instant::now();
    let mut scene = dreamscene::generate::scene::scene_file(
        text,
        a.seed,
        &spec,
        &layout,
        match &a.prior {
            PriorChoice::Oracle(_) => a.prior.record(None),
            _ => PriorChoice::Sd.record(models),
        },
    );
    for name in ["floor", "reconstruction"] {
        scene.stages.push(dreamscene::scene::dir::Stage {
            name: name.into(),
            done: true,
        });
    }
    // scene.ply carries instance_id and semantic_id; labels.json names them.
    let composed = dreamscene::export::labels::write_labelled_scene(out, &scene)?;
    dreamscene::scene::dir::write_scene(out, &scene)?;
    if a.renders > 0 {
        render_chosen(
            &composed,
            &layout,
            a.renders,
            a.resolution,
            &out.join("renders"),
        )?;
    }
    println!(
        "scene: {} objects ({} categories), {} Gaussians ({} environment); objects {:.0} s, environment stages {:.0} s, {:.0} s in all; wrote {}",
        layout.objects.len(),
        report.objects.len(),
        composed.len(),
        report.environment,
        report.seconds[0],
        report.seconds[1],
        start.elapsed().as_secs_f64(),
        out.join("scene.json").display()
    );
    let stage = |name: &str, seconds: f64| StageTime {
        name: name.into(),
        seconds,
    };
    Ok(vec![
        stage("plan and priors", set_up),
        stage("objects", report.seconds[0]),
        stage("environment", report.seconds[1]),
        stage("outputs", outputs.elapsed().as_secs_f64()),
    ])
}
