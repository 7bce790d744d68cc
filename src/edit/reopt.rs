//! The edits that need the scene's prior: the local re-optimisation of the environment around
//! changed footprints, adding an object (generated with the object pipeline), and restyling a
//! part (the paper's MTS editing rule, ε(y_edit) − ε(y), on that part's Gaussians alone).
//!
//! Priors by the scene's `prior.kind`: `shape` (a draft: no optimisation; objects are built and
//! recoloured from colour and material words), `sd` (Stable Diffusion from `prior.models` or
//! `DREAMSCENE_MODELS`), `oracle` (the reference scene directory in `prior.models`: its objects
//! placed where the edited scene has them, and its environment, are what the views should show;
//! for restyling, a second reference is the target).
use super::commit::Edit;
use super::ops::place_new;
use super::state::SceneState;
use super::wanted::plan_object;
use super::{EditError, Result};
use crate::camera::object::ObjectFrame;
use crate::camera::scene::{valid_viewpoint, SceneBox};
use crate::camera::Camera;
use crate::diffusion::guidance::{MtsRange, MtsSettings, SCENE_FLOOR, SCENE_RECON};
use crate::diffusion::model::Codec;
use crate::diffusion::runtime::Provider;
use crate::diffusion::target::{Guide, Rule};
use crate::generate::object::{generate_object, subset, GenError, ObjectConfig};
use crate::generate::prior::{OraclePrior, Prior, SdPrior};
use crate::generate::prior_spec::PriorSpec;
use crate::generate::progress::Progress;
use crate::generate::scene::object_ply;
use crate::generate::scene_stages::stage_fit;
use crate::generate::stage::{pseudo_ground_truth, run_fit, run_guided, GuidedStage, GuidedView};
use crate::gpu::Context;
use crate::plan::check::Box2;
use crate::plan::spec::Anchor;
use crate::scene::compose::{merge, pad_sh, place};
use crate::scene::dir::SceneObject;
use crate::shape::{self, ShapeOptions};
use crate::splat::train::{FitConfig, Trainer};
use crate::splat::Gaussians;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde_json::json;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Settings of the prior-driven edits.
#[derive(Debug, Clone, Copy)]
pub struct ReoptConfig {
    /// Guided iterations (local environment, restyle).
    pub iterations: u32,
    /// Square render size of their views (a multiple of 8).
    pub resolution: u32,
    pub seed: u64,
    /// ONNX Runtime provider of an sd prior's models (`--provider`).
    pub provider: Provider,
}

impl Default for ReoptConfig {
    fn default() -> Self {
        ReoptConfig {
            iterations: 150,
            resolution: 128,
            seed: 0,
            provider: Provider::Auto,
        }
    }
}

/// Footprints are grown by this much to find the environment they hid (metres).
pub const MARGIN: f64 = 0.3;
/// Environment Gaussians below this height are the floor (or ground).
pub const FLOOR_Z: f32 = 0.05;
/// Views of the local re-optimisation per footprint, and views per iteration.
const VIEWS_PER_FOOTPRINT: usize = 12;
pub(super) const BATCH: usize = 4;
/// Passes of the reconstructive fit that follows the guided iterations.
const RECON_PASSES: u32 = 6;

/// The scene's prior, as the edits use it.
pub(super) enum ScenePrior {
    Shape,
    Sd(PathBuf),
    Oracle(PathBuf),
}

/// The scene's prior as scene.json records it ([`PriorSpec::from_record`]).
pub(super) fn scene_prior(state: &SceneState) -> Result<ScenePrior> {
    let env = crate::util::env_var("DREAMSCENE_MODELS").map(PathBuf::from);
    match PriorSpec::from_record(&state.scene.prior, env) {
        Ok((PriorSpec::Sd, Some(m))) => Ok(ScenePrior::Sd(m)),
        Ok((PriorSpec::Oracle(r), _)) => Ok(ScenePrior::Oracle(r)),
        Ok(_) => Ok(ScenePrior::Shape),
        Err(GenError::Prior(e)) => Err(EditError::Bad(e.to_string())),
        Err(e) => Err(e.into()),
    }
}

pub(super) fn need(ctx: Option<&Context>) -> Result<&Context> {
    ctx.ok_or_else(|| EditError::Gpu("this edit needs a Vulkan device".into()))
}

pub(super) fn open_sd(
    models: &std::path::Path,
    prompt: &str,
    edit: Option<&str>,
    cfg: &ReoptConfig,
) -> Result<SdPrior> {
    Ok(crate::generate::prior_spec::open_sd(
        models,
        cfg.provider,
        prompt,
        edit,
    )?)
}

/// The oracle's world for the edited scene: the reference's object PLYs (by category; the
/// scene's own where the reference has none) placed as `scene` places its instances, and the
/// reference's environment.
fn oracle_world(state: &SceneState, refdir: &std::path::Path, edit: &Edit) -> Result<Gaussians> {
    let mut parts = vec![];
    for o in &edit.scene.objects {
        let r = refdir.join(object_ply(&o.category));
        let g = if r.is_file() {
            crate::splat::ply::read_ply(&r)?
        } else {
            state.load(&o.ply, &edit.files)?
        };
        parts.push(place(&g, &o.placement()));
    }
    let env = crate::scene::dir::read_scene(refdir)?
        .environment
        .map(|e| e.ply)
        .unwrap_or_else(|| "environment.ply".into());
    parts.push(crate::splat::ply::read_ply(&refdir.join(env))?);
    Ok(merge(&parts))
}

/// Cameras around footprint `b`: a ring at 1.3 to 1.6 m height, looking at the footprint's
/// centre on the floor, kept inside the room and out of the objects.
pub fn footprint_cameras(scene: &SceneBox, b: &Box2, count: usize, res: u32) -> Vec<Camera> {
    let reach = b.half[0].hypot(b.half[1]);
    let mut out = vec![];
    let mut k = 0;
    while out.len() < count && k < count * 8 {
        let a = k as f64 * 2.399_963; // golden angle: spread over the ring
        let r = (reach + 1.0) * (1.0 + 0.25 * ((k % 3) as f64));
        let h = 1.3 + 0.15 * ((k % 3) as f64);
        let eye = [b.c[0] + r * a.cos(), b.c[1] + r * a.sin(), h];
        k += 1;
        if !valid_viewpoint(scene, eye) {
            continue;
        }
        let target = [b.c[0], b.c[1], 0.15];
        let mut cam = Camera::look_at(eye, target, [0.0, 0.0, 1.0], res, res, 1.0);
        cam.id = out.len() as u32;
        cam.img_name = format!("local_{}", out.len());
        out.push(cam);
    }
    out
}

/// Re-optimises the environment around `footprints` (old and new places of moved, added or
/// removed objects) with the scene's prior: the environment Gaussians inside the footprints
/// grown by `MARGIN` are trained, with MTS from cameras around them and then a reconstructive
/// fit, everything else frozen and written back bit for bit. Puts the new `environment.ply`
/// into `edit` and says what was done.
pub fn local_environment(
    ctx: Option<&Context>,
    state: &SceneState,
    edit: &mut Edit,
    footprints: &[Box2],
    cfg: &ReoptConfig,
) -> Result<String> {
    let prior = scene_prior(state)?;
    if let ScenePrior::Shape = prior {
        return Ok(
            "environment: draft (shape prior) — its initial cloud already covers the floor \
                   and walls under every footprint; nothing to re-optimise (scenes generated with \
                   the sd or oracle prior are re-optimised locally)"
                .into(),
        );
    }
    let Some(env_ref) = edit.scene.environment.clone() else {
        return Ok("environment: none in this scene; nothing to re-optimise".into());
    };
    let ctx = need(ctx)?;
    let env = state.load(&env_ref.ply, &edit.files)?;
    let grown: Vec<Box2> = footprints
        .iter()
        .map(|b| Box2 {
            half: [b.half[0] + MARGIN, b.half[1] + MARGIN],
            ..*b
        })
        .collect();
    let region: Vec<bool> = env
        .means
        .iter()
        .map(|m| grown.iter().any(|b| b.contains([m[0] as f64, m[1] as f64])))
        .collect();
    let n_region = region.iter().filter(|r| **r).count();
    if n_region == 0 {
        return Ok("environment: no Gaussians under the footprints; nothing to re-optimise".into());
    }
    // [objects | environment outside | environment inside], only the last part trained.
    let mut next = state.clone();
    next.scene = edit.scene.clone();
    if let Some(l) = &edit.layout {
        for o in &l.objects {
            next.sizes.insert(o.id.clone(), o.size);
            next.anchors.insert(o.id.clone(), o.anchor);
        }
    }
    let objects: Vec<Gaussians> = {
        let mut loaded: BTreeMap<String, Gaussians> = BTreeMap::new();
        let mut out = vec![];
        for o in &next.scene.objects {
            if !loaded.contains_key(&o.ply) {
                loaded.insert(o.ply.clone(), next.load(&o.ply, &edit.files)?);
            }
            out.push(place(&loaded[&o.ply], &o.placement()));
        }
        out
    };
    let outside = subset(&env, &region.iter().map(|r| !r).collect::<Vec<_>>());
    let inside = subset(&env, &region);
    let mut parts = objects;
    parts.push(outside);
    parts.push(inside);
    let cloud = merge(&parts);
    let n = cloud.len() as u32;
    let first = n - n_region as u32;
    let layout = next.current_layout();
    let sb = SceneBox::from_layout(&layout);
    let mut cams = vec![];
    for b in footprints {
        cams.extend(footprint_cameras(
            &sb,
            b,
            VIEWS_PER_FOOTPRINT,
            cfg.resolution,
        ));
    }
    if cams.is_empty() {
        return Ok("environment: no camera fits around the footprints; left as it was".into());
    }
    let text = format!(
        "{}, 4k, 8k, best quality, ultra-detailed, highres",
        state.scene.prompt
    );
    let mut prior: Box<dyn Prior> = match &prior {
        ScenePrior::Oracle(dir) => {
            let world = oracle_world(state, dir, edit)?;
            Box::new(OraclePrior::new(ctx, &world, None)?)
        }
        ScenePrior::Sd(m) => Box::new(open_sd(m, &text, None, cfg)?),
        ScenePrior::Shape => unreachable!("returned above"),
    };
    let iters = cfg.iterations;
    let mut guide = Guide::new(
        Rule::Mts { m: 4 },
        MtsRange {
            period: iters.max(1),
            ..SCENE_FLOOR
        },
        MtsSettings::default(),
        Codec::Fast,
        cfg.seed ^ 0x10ca1,
    );
    let mut t = Trainer::guided(ctx, &cloud, local_fit(iters.max(1), cfg.seed), 1.0)?;
    let mut progress = Progress::new(iters as u64, false);
    let local_view = |camera: &Camera| GuidedView {
        camera: camera.clone(),
        background: [1.0; 3],
        azimuth: 0.0,
        elevation: -30.0,
    };
    let mut views = |step: u32, _: &mut ChaCha8Rng| {
        (0..BATCH)
            .map(|b| local_view(&cams[(step as usize * BATCH + b) % cams.len()]))
            .collect()
    };
    let mut stage = GuidedStage {
        iterations: iters,
        trainable: Some(first..n),
        sh: None,
        checkpoint_every: 0,
        views: &mut views,
    };
    // The views are fixed: the stage's generator is never drawn from.
    let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed);
    let loss = run_guided(
        &mut stage,
        &mut t,
        prior.as_mut(),
        &mut guide,
        &mut rng,
        &mut |t, r, _, _, _| {
            progress.update(
                t.iteration() as u64,
                &format!("local environment loss {:.5}", r.loss),
            );
            Ok(())
        },
    )?
    .loss;
    progress.finish();
    let mut cloud = t.gaussians()?;
    drop(t);
    // Reconstructive: the views once into pseudo-ground truth, then fitted.
    let mut pg = Guide::new(
        Rule::PseudoGt,
        SCENE_RECON,
        MtsSettings::default(),
        Codec::Fast,
        cfg.seed ^ 0x3ec0,
    );
    let views: Vec<GuidedView> = cams.iter().map(local_view).collect();
    let views = pseudo_ground_truth(ctx, &cloud, prior.as_mut(), &mut pg, &views, BATCH)?;
    let steps = RECON_PASSES * views.len() as u32;
    let fit = FitConfig {
        background: [1.0; 3],
        ..local_fit(steps, cfg.seed ^ 3)
    };
    let mut t = Trainer::new(ctx, &cloud, views, fit)?;
    t.trainable = Some(first..n);
    let psnr = run_fit(&mut t, steps, 0, &mut |_, _, _| Ok(()))?.map_or(0.0, |r| r.psnr);
    cloud = t.gaussians()?;
    // Write the trained part back into the environment, in its order; the rest as it was.
    let trained = subset(&cloud, &(0..n).map(|i| i >= first).collect::<Vec<_>>());
    let trained = pad_sh(&trained, env.sh_degree);
    let mut out = env.clone();
    let k3 = out.coeffs() * 3;
    let mut j = 0;
    for (i, inside) in region.iter().enumerate() {
        if *inside {
            out.means[i] = trained.means[j];
            out.scales[i] = trained.scales[j];
            out.rotations[i] = trained.rotations[j];
            out.opacities[i] = trained.opacities[j];
            out.sh[i * k3..(i + 1) * k3].copy_from_slice(&trained.sh[j * k3..(j + 1) * k3]);
            j += 1;
        }
    }
    edit.files.insert(env_ref.ply.clone(), out);
    Ok(format!(
        "environment: {n_region} Gaussians around {} footprint(s) re-optimised with the {} prior \
         ({iters} MTS iterations from {} views, last loss {loss:.4}; reconstructive fit PSNR \
         {psnr:.1} dB); the rest unchanged",
        footprints.len(),
        state.scene.prior.kind,
        cams.len()
    ))
}

/// The scene stages' learning rates with a faster colour rate: a local edit runs for a few
/// hundred steps, not thousands, and its Gaussians start far from their colour (hidden floor).
fn local_fit(iterations: u32, seed: u64) -> FitConfig {
    FitConfig {
        lr_sh: 0.05,
        lr_sh_final: Some(0.02),
        ..stage_fit(iterations, seed)
    }
}

/// Adds an object from a description: planned from the knowledge base, placed by GCP around
/// the present objects (`near`: NEXT to that instance), generated with the scene's prior (shape:
/// the shape prior; sd or oracle: Formation Pattern Sampling for `object_iterations`). Refused
/// when no pose is free of collisions.
pub fn add_object(
    ctx: Option<&Context>,
    state: &SceneState,
    text: &str,
    near: Option<(&str, Option<crate::plan::spec::RelationKind>)>,
    anchor: Option<Anchor>,
    object_iterations: u32,
    cfg: &ReoptConfig,
) -> Result<(Edit, Box2)> {
    let planned = plan_object(text)?;
    let said = near.and_then(|n| n.1);
    let near = near.map(|n| n.0);
    let (id, pose, all_ok) = place_new(state, &planned, near, said, anchor)?;
    // The new instance in a state of its own, for the collision check and the layout.
    let mut next = state.clone();
    let mut rel = object_ply(&planned.category);
    if state.dir.join(&rel).exists() || state.scene.objects.iter().any(|o| o.ply == rel) {
        rel = format!(
            "objects/{}.ply",
            id.replace(|c: char| !c.is_alphanumeric(), "_")
        );
    }
    next.scene.objects.push(SceneObject {
        id: id.clone(),
        category: planned.category.clone(),
        ply: rel.clone(),
        position: pose.position,
        yaw: pose.yaw,
        scale: pose.scale,
    });
    next.sizes.insert(id.clone(), planned.size);
    next.anchors
        .insert(id.clone(), anchor.unwrap_or(planned.anchor));
    if let Some(n) = near {
        next.relations.push(crate::plan::spec::Relation {
            subject: id.clone(),
            relation: said.unwrap_or(crate::plan::spec::RelationKind::Next),
            object: n.to_string(),
        });
    }
    let empty = {
        let mut s = next.clone();
        s.scene.objects.pop();
        s
    };
    let problems = next.collisions(&id, &empty);
    if !problems.is_empty() {
        return Err(EditError::NoRoom(format!(
            "no free place for {id}: {}",
            problems.join("; ")
        )));
    }
    let init = shape::build(
        &planned.category,
        planned.size,
        &planned.description,
        &ShapeOptions {
            gaussians: None,
            seed: state.scene.seed,
            variant: 0,
            mount: Some(super::ops::mount_in(&next, &planned.category)),
        },
    )
    .map_err(|e| EditError::Bad(e.to_string()))?;
    let frame = ObjectFrame { size: planned.size };
    let ocfg = ObjectConfig {
        iterations: object_iterations,
        resolution: cfg.resolution,
        sh_degree: 1,
        recon_views: 12,
        recon_passes: 8,
        checkpoint_every: 0,
        seed: cfg.seed,
        ..ObjectConfig::default()
    };
    let (g, how) = match scene_prior(state)? {
        ScenePrior::Shape => (init, "shape prior".to_string()),
        ScenePrior::Sd(m) => {
            let mut p = open_sd(&m, &planned.description, None, cfg)?;
            let mut pr = Progress::new(0, true);
            let (g, _) = generate_object(need(ctx)?, &init, &frame, &mut p, &ocfg, None, &mut pr)?;
            (g, format!("sd prior, {object_iterations} iterations"))
        }
        ScenePrior::Oracle(dir) => {
            let r = dir.join(object_ply(&planned.category));
            if !r.is_file() {
                return Err(EditError::Bad(format!(
                    "the oracle's reference scene has no {} to generate a {} from",
                    r.display(),
                    planned.category
                )));
            }
            let reference = crate::splat::ply::read_ply(&r)?;
            let ctx = need(ctx)?;
            let mut p = OraclePrior::new(ctx, &reference, None)?;
            let mut pr = Progress::new(0, true);
            let (g, _) = generate_object(ctx, &init, &frame, &mut p, &ocfg, None, &mut pr)?;
            (g, format!("oracle prior, {object_iterations} iterations"))
        }
    };
    let mut edit = Edit::new(
        state,
        "add",
        json!({"id": id, "description": text, "near": near, "anchor": anchor.map(|a| format!("{a:?}").to_uppercase())}),
    );
    edit.scene = next.scene.clone();
    edit.layout = state.layout.as_ref().map(|_| next.current_layout());
    edit.notes.push(format!(
        "{id} ({}, {:.2} x {:.2} x {:.2} m) added at ({:.2}, {:.2}), yaw {:.0}{}; {} Gaussians by the {how} in {rel}",
        planned.category,
        planned.size[0],
        planned.size[1],
        planned.size[2],
        pose.position[0],
        pose.position[1],
        // rounded, and never "-0"
        pose.yaw.round() + 0.0,
        if all_ok { "" } else { " (not every constraint could hold)" },
        g.len()
    ));
    edit.files.insert(rel, g);
    let b = next.box_of(next.object(&id)?);
    Ok((edit, b))
}
