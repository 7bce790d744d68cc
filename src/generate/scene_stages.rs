//! Scene generation with a prior (paper §IV-C, Algorithm 2): every unique object by Formation
//! Pattern Sampling, composed into the layout; the environment initialised and optimised in three
//! stages over one cloud `[objects | environment | floor]`:
//! 1. the environment (walls and ceiling, or sky) alone, objects and floor frozen, MTS with the
//!    environment's ranges, cameras of stage 1;
//! 2. the floor (ground) alone, MTS with the floor's ranges, cameras of stage 2;
//! 3. reconstructive: stage-3 views rendered once into pseudo-ground truth and fitted, everything
//!    trainable indoors, the ground alone outdoors.
//!
//! Densification stays off in the scene stages so the frozen ranges keep their indices (the
//! initial environment is already dense). Each object, each stage and every
//! `checkpoint_every` iterations is checkpointed in `checkpoints/`, and `resume` continues.
use super::checkpoint::{remove_old, restore_trainer, write_trainer};
use super::object::{GenError, ObjectConfig};
use super::prior::{OraclePrior, Prior, SdPrior};
use super::progress::Progress;
use super::scene::{category_sizes, object_ply};
use super::stage::{pseudo_ground_truth, run_fit, run_guided, GuidedStage, GuidedView};
use crate::camera::scene::{stage_cameras, SceneBox, Stage};
use crate::camera::Camera;
use crate::diffusion::guidance::{
    MtsRange, MtsRule, MtsSettings, SCENE_ENVIRONMENT, SCENE_FLOOR, SCENE_RECON,
};
use crate::diffusion::model::Codec;
use crate::diffusion::target::{Guide, Rule};
use crate::diffusion::Error;
use crate::gpu::Context;
use crate::plan::spec::{Layout, SceneSpec, SceneType};
use crate::scene::compose::{merge, pad_sh, place, Placement};
use crate::scene::env::{init_environment, scene_colours, EnvOptions};
use crate::splat::ply::{read_ply, write_ply};
use crate::splat::train::{FitConfig, Trainer};
use crate::splat::Gaussians;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One scene run's inputs, shared by its steps (all objects and the environment, or one shard's
/// objects): the device, the scene directory (holding spec.json and layout.json), the prompt,
/// the plan, the settings, and whether to continue from `checkpoints/`.
#[derive(Clone, Copy)]
pub struct SceneJob<'a> {
    pub ctx: &'a Context,
    pub out: &'a Path,
    pub prompt: &'a str,
    pub spec: &'a SceneSpec,
    pub layout: &'a Layout,
    pub cfg: &'a SceneConfig,
    pub resume: bool,
}

/// Settings of a scene generation. Defaults are the paper's and the authors' code's.
#[derive(Debug, Clone)]
pub struct SceneConfig {
    /// Environment iterations of stages 1 and 2 together, split 1000 : 700 as the authors.
    pub iterations: u32,
    /// Settings of every object's generation.
    pub object: ObjectConfig,
    pub resolution: u32,
    pub batch: usize,
    /// Stage-3 views and passes over them.
    pub recon_views: usize,
    pub recon_passes: u32,
    pub checkpoint_every: u32,
    pub seed: u64,
    pub env: EnvOptions,
    /// Gaussians of each object's shape prior (`None`: from its area).
    pub object_gaussians: Option<usize>,
}

impl Default for SceneConfig {
    fn default() -> Self {
        SceneConfig {
            iterations: 2000,
            object: ObjectConfig {
                sh_degree: 1,
                ..ObjectConfig::default()
            },
            resolution: 512,
            batch: 4,
            recon_views: 80,
            recon_passes: 25,
            checkpoint_every: 100,
            seed: 0,
            env: EnvOptions::default(),
            object_gaussians: None,
        }
    }
}

impl SceneConfig {
    fn stage_iterations(&self) -> [u32; 2] {
        let one = (self.iterations as u64 * 1000 / 1700) as u32;
        [one, self.iterations - one]
    }

    /// Everything a checkpoint must agree on.
    pub fn fingerprint(&self, prompt: &str, prior: &str) -> String {
        format!(
            "{}|{}|{}|{}|{}|{}|{}|{:?}",
            self.object.fingerprint(prompt, prior),
            self.iterations,
            self.resolution,
            self.batch,
            self.recon_views,
            self.recon_passes,
            self.env.density,
            self.object_gaussians
        )
    }
}

/// Where the priors of a scene come from: one per object, one for the environment stages.
pub trait ScenePriors {
    /// `sd` or `oracle:DIR`, for scene.json and logs.
    fn kind(&self) -> String;
    fn for_object(&mut self, category: &str, description: &str)
        -> Result<&mut dyn Prior, GenError>;
    fn for_scene(&mut self, text: &str) -> Result<&mut dyn Prior, GenError>;
}

/// Stable Diffusion for everything: the object's description, then the scene text.
pub struct SdScenePriors(pub SdPrior);

impl ScenePriors for SdScenePriors {
    fn kind(&self) -> String {
        "sd".into()
    }
    fn for_object(
        &mut self,
        _category: &str,
        description: &str,
    ) -> Result<&mut dyn Prior, GenError> {
        self.0.set_prompt(description);
        Ok(&mut self.0)
    }
    fn for_scene(&mut self, text: &str) -> Result<&mut dyn Prior, GenError> {
        self.0.set_prompt(text);
        Ok(&mut self.0)
    }
}

/// The oracle of a reference scene directory: its object PLYs for the objects, its composed
/// world cloud for the environment stages.
pub struct OracleScenePriors {
    pub ctx: Context,
    pub dir: PathBuf,
    current: Option<OraclePrior>,
}

impl OracleScenePriors {
    pub fn new(ctx: &Context, dir: &Path) -> OracleScenePriors {
        OracleScenePriors {
            ctx: ctx.clone(),
            dir: dir.to_path_buf(),
            current: None,
        }
    }
}

impl ScenePriors for OracleScenePriors {
    fn kind(&self) -> String {
        format!("oracle:{}", self.dir.display())
    }
    fn for_object(&mut self, category: &str, _d: &str) -> Result<&mut dyn Prior, GenError> {
        let path = self.dir.join(object_ply(category));
        let g = read_ply(&path)
            .map_err(|e| GenError::Prior(Error::Oracle(format!("the oracle's reference: {e}"))))?;
        self.current = Some(OraclePrior::new(&self.ctx, &g, None)?);
        Ok(self.current.as_mut().expect("just set"))
    }
    fn for_scene(&mut self, _text: &str) -> Result<&mut dyn Prior, GenError> {
        let oracle = |e: String| GenError::Prior(Error::Oracle(e));
        let scene = crate::scene::dir::read_scene(&self.dir).map_err(|e| oracle(e.to_string()))?;
        let g = crate::scene::dir::compose_scene(&self.dir, &scene)
            .map_err(|e| oracle(e.to_string()))?;
        self.current = Some(OraclePrior::new(&self.ctx, &g, None)?);
        Ok(self.current.as_mut().expect("just set"))
    }
}

/// `checkpoints/scene.json`: what is finished and where the running stage stands.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct SceneRun {
    pub fingerprint: String,
    /// Categories whose object is finished.
    pub objects_done: Vec<String>,
    /// Environment stages finished (0 to 3).
    pub stages_done: u32,
    /// Iterations done in the running stage, its cloud checkpoint, generator positions.
    pub iteration: u32,
    pub ply: Option<String>,
    pub rng: u128,
    pub guide: u128,
    /// Index ranges: objects end, environment end (the floor follows).
    pub split: [u32; 2],
}

const RUN: &str = "scene_run.json";

fn io(path: &Path) -> impl Fn(std::io::Error) -> GenError + '_ {
    move |err| GenError::Io {
        path: path.to_path_buf(),
        err,
    }
}

impl SceneRun {
    fn save(&mut self, dir: &Path, fingerprint: &str) -> Result<(), GenError> {
        self.fingerprint = fingerprint.to_string();
        let text = serde_json::to_string_pretty(self).expect("serialisable");
        let path = dir.join(RUN);
        crate::util::write_atomic(&path, text.as_bytes()).map_err(io(&path))
    }
}

/// What a scene run made.
#[derive(Debug, Clone)]
pub struct SceneReport {
    pub objects: BTreeMap<String, usize>,
    pub environment: usize,
    pub seconds: [f64; 3],
}

/// The view angles of a scene camera for view-dependent prompts: azimuth of its forward axis
/// about +z from +y (degrees), elevation as polar − 90° (negative when looking down).
fn angles(cam: &Camera) -> (f64, f64) {
    let r = cam.rotation;
    let f = [r[0][2], r[1][2], r[2][2]];
    // The camera looks along f; the view is "from" −f.
    let az = (-f[0]).atan2(-f[1]).to_degrees();
    let el = (f[2].clamp(-1.0, 1.0)).asin().to_degrees();
    (az, el)
}

/// The views of a stage's iteration `step`: the next `batch` cameras of the stage's list, with
/// random backgrounds less and less often (half the views at the start, none at the end).
pub fn stage_views(
    cams: &[Camera],
    step: u32,
    batch: usize,
    iters: u32,
    rng: &mut ChaCha8Rng,
) -> Vec<GuidedView> {
    (0..batch)
        .map(|b| {
            let camera = cams[(step as usize * batch + b) % cams.len()].clone();
            let (azimuth, elevation) = angles(&camera);
            GuidedView {
                background: background(rng, 0.5 * (1.0 - step as f64 / iters.max(1) as f64)),
                camera,
                azimuth,
                elevation,
            }
        })
        .collect()
}

fn background(rng: &mut ChaCha8Rng, aug: f64) -> [f32; 3] {
    if rng.gen_bool(aug.clamp(0.0, 1.0)) {
        [rng.gen(), rng.gen(), rng.gen()]
    } else {
        [1.0; 3]
    }
}

/// The authors' scene-stage learning rates (extent 1: the scene is in metres).
pub fn stage_fit(iterations: u32, seed: u64) -> FitConfig {
    FitConfig {
        iterations,
        lr_means: (8e-4, 2.5e-5),
        lr_sh: 0.02,
        lr_sh_final: Some(0.005),
        lr_scales: 0.005,
        lr_rotations: 0.001,
        lr_rotations_final: Some(4e-4),
        lr_opacities: 0.05,
        densify: false,
        opacity_reset: 0.0,
        seed,
        ..FitConfig::default()
    }
}

/// Generates objects and environment into the job's `out` (which holds spec.json and
/// layout.json), writes `objects/*.ply`, `environment.ply`, `scene.ply` and returns the counts.
/// `scene.json` is the caller's (it knows the prompt's provenance).
pub fn generate_scene(
    job: &SceneJob,
    priors: &mut dyn ScenePriors,
    log: &mut dyn FnMut(&str),
) -> Result<SceneReport, GenError> {
    let SceneJob {
        ctx,
        out,
        prompt,
        spec,
        layout,
        cfg,
        resume,
    } = *job;
    let t0 = std::time::Instant::now();
    let ck = out.join("checkpoints");
    std::fs::create_dir_all(&ck).map_err(io(&ck))?;
    std::fs::create_dir_all(out.join("objects")).map_err(io(out))?;
    let fp = cfg.fingerprint(prompt, &priors.kind());
    let mut run = SceneRun::default();
    if resume {
        if let Ok(text) = std::fs::read_to_string(ck.join(RUN)) {
            run = serde_json::from_str(&text)
                .map_err(|e| GenError::Checkpoint(format!("{}: {e}", ck.join(RUN).display())))?;
            if run.fingerprint != fp {
                return Err(GenError::Checkpoint(format!(
                    "{}: the checkpoint is of another run (prompt, prior, seed or settings \
                     differ); remove it or drop --resume",
                    ck.display()
                )));
            }
        }
    }
    // ---- objects (with resume, those any shard of this run finished are kept) ----
    let sizes = category_sizes(spec, layout);
    if resume {
        for cat in super::scene_objects::done_by_shards(&ck, &fp) {
            if !run.objects_done.contains(&cat) {
                run.objects_done.push(cat);
            }
        }
    }
    let mut done = std::mem::take(&mut run.objects_done);
    let objects = super::scene_objects::generate_objects(
        job,
        priors,
        None,
        &mut done,
        &mut |d| {
            run.objects_done = d.to_vec();
            run.save(&ck, &fp)
        },
        log,
    )?;
    run.objects_done = done;
    let t_objects = t0.elapsed().as_secs_f64();
    // ---- the scene cloud: [objects | environment | floor] ----
    let sb = SceneBox::from_layout(layout);
    let cloud_path = |name: &str| ck.join(name);
    let (mut cloud, split) = match (&run.ply, run.stages_done) {
        (Some(name), _) => {
            let g = read_ply(&cloud_path(name)).map_err(|e| GenError::Checkpoint(e.to_string()))?;
            (g, run.split)
        }
        (None, _) => {
            let placed: Vec<Gaussians> = layout
                .objects
                .iter()
                .map(|o| {
                    let base = sizes[&o.category];
                    let p = Placement {
                        yaw: o.yaw,
                        scale: [0, 1, 2].map(|a| o.size[a] / base[a]),
                        position: o.position,
                    };
                    place(&objects[&o.category], &p)
                })
                .collect();
            let objs = merge(&placed);
            let env = init_environment(
                layout.scene_type,
                layout.room.size,
                &scene_colours(layout, prompt),
                &EnvOptions {
                    seed: cfg.seed,
                    ..cfg.env
                },
            );
            let n_obj = objs.len() as u32;
            let n_env = env.env.len() as u32;
            let g = pad_sh(&merge(&[objs, env.env, env.floor]), 1);
            (g, [n_obj, n_obj + n_env])
        }
    };
    run.split = split;
    let n = cloud.len() as u32;
    let outdoor = layout.scene_type == SceneType::Outdoor;
    let text = format!(
        "{}, {}",
        spec.scene_text, "4k, 8k, best quality, ultra-detailed, highres"
    );
    let [it1, it2] = cfg.stage_iterations();
    let t_env = std::time::Instant::now();
    // ---- stages 1 and 2 ----
    for (k, (stage, range, iters, trainable)) in [
        (Stage::One, SCENE_ENVIRONMENT, it1, split[0]..split[1]),
        (Stage::Two, SCENE_FLOOR, it2, split[1]..n),
    ]
    .into_iter()
    .enumerate()
    {
        if run.stages_done > k as u32 || iters == 0 {
            continue;
        }
        let prior = priors.for_scene(&text)?;
        let mut guide = Guide::new(
            Rule::Mts { m: 4 },
            MtsRange {
                period: iters,
                ..range
            },
            MtsSettings {
                rule: cfg.object.mts_form,
                ..MtsSettings::default()
            },
            Codec::Fast,
            cfg.seed ^ (0x57a6e + k as u64),
        );
        let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed ^ 0x5ce7e ^ k as u64);
        let mut t = Trainer::guided(ctx, &cloud, stage_fit(iters, cfg.seed ^ k as u64), 1.0)?;
        if let Some(ply) = run.ply.as_ref().filter(|_| run.iteration > 0) {
            restore_trainer(&ck, ply, &mut t)?;
            rng.set_word_pos(run.rng);
            guide.set_rng_position(run.guide);
            log(&format!(
                "stage {}: resuming at iteration {}",
                k + 1,
                run.iteration
            ));
        }
        let cams = stage_cameras(
            stage,
            &sb,
            iters as usize * cfg.batch,
            cfg.resolution,
            cfg.resolution,
            cfg.seed + k as u64,
        );
        let mut progress = Progress::new(iters as u64, false);
        let mut views =
            |step, rng: &mut ChaCha8Rng| stage_views(&cams, step, cfg.batch, iters, rng);
        let mut desc = GuidedStage {
            iterations: iters,
            trainable: Some(trainable.clone()),
            sh: None,
            checkpoint_every: cfg.checkpoint_every,
            views: &mut views,
        };
        run_guided(
            &mut desc,
            &mut t,
            prior,
            &mut guide,
            &mut rng,
            &mut |t, r, guide, rng, due| {
                progress.update(
                    t.iteration() as u64,
                    &format!("stage {} loss {:.5}", k + 1, r.loss),
                );
                if due {
                    let name = write_trainer(&ck, &format!("stage{}", k + 1), t)?;
                    let old = run.ply.replace(name);
                    run.iteration = t.iteration();
                    run.rng = rng.get_word_pos();
                    run.guide = guide.rng_position();
                    run.save(&ck, &fp)?;
                    remove_old(&ck, old, run.ply.as_deref());
                }
                Ok(())
            },
        )?;
        progress.finish();
        cloud = t.gaussians()?;
        let name = format!("stage{}_done.ply", k + 1);
        write_ply(&cloud_path(&name), &cloud).map_err(io(&ck))?;
        let old = run.ply.replace(name);
        run.stages_done = k as u32 + 1;
        run.iteration = 0;
        run.save(&ck, &fp)?;
        remove_old(&ck, old, run.ply.as_deref());
        log(&format!("stage {} done ({iters} iterations)", k + 1));
    }
    // ---- stage 3: reconstructive ----
    if run.stages_done < 3 && cfg.recon_views > 0 && cfg.recon_passes > 0 {
        let prior = priors.for_scene(&text)?;
        let mut guide = Guide::new(
            Rule::PseudoGt,
            SCENE_RECON,
            MtsSettings {
                rule: MtsRule::Code,
                ..MtsSettings::default()
            },
            Codec::Fast,
            cfg.seed ^ 0x3ec0,
        );
        let views: Vec<GuidedView> = stage_cameras(
            Stage::Three,
            &sb,
            cfg.recon_views,
            cfg.resolution,
            cfg.resolution,
            cfg.seed + 3,
        )
        .into_iter()
        .map(|camera| {
            let (azimuth, elevation) = angles(&camera);
            GuidedView {
                camera,
                background: [1.0; 3],
                azimuth,
                elevation,
            }
        })
        .collect();
        let views = pseudo_ground_truth(ctx, &cloud, prior, &mut guide, &views, cfg.batch)?;
        let steps = cfg.recon_passes * views.len() as u32;
        let fit = FitConfig {
            background: [1.0; 3],
            lr_means: (8e-4 / 3.5, 8e-6 / 3.5),
            lr_sh: 0.005,
            lr_sh_final: Some(0.004),
            lr_scales_final: Some(0.002),
            lr_rotations_final: Some(2e-4),
            ..stage_fit(steps, cfg.seed ^ 3)
        };
        let mut t = Trainer::new(ctx, &cloud, views, fit)?;
        t.trainable = Some(if outdoor { split[1]..n } else { 0..n });
        let mut progress = Progress::new(steps as u64, false);
        run_fit(&mut t, steps, 0, &mut |_, r, _| {
            progress.update(
                r.iteration as u64,
                &format!("stage 3 loss {:.4} psnr {:.1}", r.loss, r.psnr),
            );
            Ok(())
        })?;
        progress.finish();
        cloud = t.gaussians()?;
        let name = "stage3_done.ply".to_string();
        write_ply(&cloud_path(&name), &cloud).map_err(io(&ck))?;
        let old = run.ply.replace(name);
        run.stages_done = 3;
        run.save(&ck, &fp)?;
        remove_old(&ck, old, run.ply.as_deref());
        log(&format!("stage 3 done ({steps} view steps)"));
    }
    let t_stages = t_env.elapsed().as_secs_f64();
    // ---- write back: environment, objects in their own frame (first instance of each) ----
    let env = super::object::subset(&cloud, &(0..n).map(|i| i >= split[0]).collect::<Vec<_>>());
    let env_path = out.join("environment.ply");
    write_ply(&env_path, &env).map_err(io(&env_path))?;
    if !outdoor && run.stages_done >= 3 {
        let mut start = 0u32;
        let mut written = std::collections::BTreeSet::new();
        for o in &layout.objects {
            let len = objects[&o.category].len() as u32;
            if written.insert(o.category.clone()) {
                let keep: Vec<bool> = (0..n).map(|i| i >= start && i < start + len).collect();
                let world = super::object::subset(&cloud, &keep);
                let base = sizes[&o.category];
                let local = unplace(
                    &world,
                    o.yaw,
                    [0, 1, 2].map(|a| o.size[a] / base[a]),
                    o.position,
                );
                let path = out.join(object_ply(&o.category));
                write_ply(&path, &local).map_err(io(&path))?;
            }
            start += len;
        }
    }
    Ok(SceneReport {
        objects: objects.iter().map(|(k, v)| (k.clone(), v.len())).collect(),
        environment: env.len(),
        seconds: [t_objects, t_stages, t0.elapsed().as_secs_f64()],
    })
}

/// The inverse of an instance placement: world → object frame.
fn unplace(g: &Gaussians, yaw: f64, scale: [f64; 3], position: [f64; 3]) -> Gaussians {
    use crate::scene::compose::transform;
    let a = transform(g, 0.0, [1.0; 3], position.map(|v| -v));
    let b = transform(&a, -yaw, [1.0; 3], [0.0; 3]);
    transform(&b, 0.0, scale.map(|s| 1.0 / s), [0.0; 3])
}
