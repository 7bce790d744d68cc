//! Restyling a part of the scene (paper §III-E, its equation MTS_Editing): an instance, the
//! environment or the floor takes a new description. With the sd or oracle prior the editing
//! rule ε(y_edit) − ε(y) drives that part's Gaussians alone, from orbit views in the object's
//! frame; the rest of the scene is not touched. With a draft's shape prior the part is
//! recoloured from the description's colour and material words, geometry kept, and it says so.
use super::commit::Edit;
use super::reopt::{need, open_sd, scene_prior, ReoptConfig, ScenePrior, BATCH, FLOOR_Z};
use super::state::SceneState;
use super::{EditError, Result};
use crate::camera::object::{random_views, ObjectFrame, OrbitRanges};
use crate::diffusion::guidance::{MtsRange, MtsSettings};
use crate::diffusion::model::Codec;
use crate::diffusion::target::{Guide, Rule};
use crate::generate::object::GenError;
use crate::generate::prior::{oracle_targets, to_latent, OraclePrior, Prior, PriorView};
use crate::generate::progress::Progress;
use crate::generate::stage::{run_guided, GuidedStage, GuidedView};
use crate::gpu::Context;
use crate::scene::dir::SceneObject;
use crate::shape::{self, ShapeOptions};
use crate::splat::train::{FitConfig, Trainer};
use crate::splat::Gaussians;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// Appearance editing: colours fast, geometry refined slowly, no densification (the part keeps
/// its Gaussians one for one).
fn restyle_fit(iterations: u32, seed: u64) -> FitConfig {
    FitConfig {
        iterations,
        lr_means: (8e-4 / 3.5, 1.6e-5 / 3.5),
        lr_sh: 0.05,
        lr_sh_final: Some(0.01),
        lr_scales: 0.002,
        lr_rotations: 0.001,
        lr_opacities: 0.02,
        densify: false,
        opacity_reset: 0.0,
        seed,
        ..FitConfig::default()
    }
}

/// Which part a restyle names.
enum Part {
    Instance(SceneObject),
    Environment,
    Floor,
}

/// The editing prior of the oracle: ε(y) is the exact noise toward the current render (y
/// describes what the part looks like now), ε(y_edit) the noise toward the render of the second
/// reference; so ε(y_edit) − ε(y) pulls the part from what it is to the second reference and
/// vanishes there.
struct EditOracle {
    inner: OraclePrior,
    sched: crate::diffusion::schedule::Schedule,
}

impl Prior for EditOracle {
    fn kind(&self) -> &'static str {
        "oracle"
    }
    fn targets(
        &mut self,
        guide: &mut Guide,
        views: &[PriorView],
        step: u32,
    ) -> std::result::Result<Vec<Vec<[f32; 3]>>, GenError> {
        // The oracle's editing rule: ε(y) points at the current render and ε(y_edit) at the
        // second reference, so the edit stops exactly there.
        let mut targets = Vec::with_capacity(views.len());
        for v in views {
            targets.push(to_latent(
                &self.inner.reference_view(v.camera, v.background)?,
            ));
        }
        let current: Vec<Vec<f32>> = views.iter().map(|v| to_latent(v.render)).collect();
        oracle_targets(guide, &self.sched, views, &current, &targets, step)
    }
}

/// Restyles an instance, the environment or the floor from a new description. With the sd or
/// oracle prior: MTS editing on that part's Gaussians only (an instance in its own frame from
/// orbit views; an instance sharing its PLY with others gets a PLY of its own). With the shape
/// prior: recoloured from the description's colour and material words.
pub fn restyle(
    ctx: Option<&Context>,
    state: &SceneState,
    part: &str,
    description: &str,
    edit_reference: Option<&std::path::Path>,
    cfg: &ReoptConfig,
) -> Result<Edit> {
    let which = match part {
        "environment" | "walls" | "sky" => Part::Environment,
        "floor" | "ground" => Part::Floor,
        id => Part::Instance(state.object(id)?.clone()),
    };
    let mut edit = Edit::new(
        state,
        "restyle",
        json!({"part": part, "description": description}),
    );
    let prior = scene_prior(state)?;
    match which {
        Part::Instance(o) => {
            let cloud = state.load(&o.ply, &edit.files)?;
            let size_scaled = state.sizes[&o.id];
            let size = [0, 1, 2].map(|a| size_scaled[a] / o.scale[a].abs());
            let new = match prior {
                ScenePrior::Shape => {
                    let mount = state.mount(&o.category);
                    let (g, note) = recolour_object(
                        &o.category,
                        size,
                        mount,
                        &cloud,
                        description,
                        state.scene.seed,
                    )?;
                    edit.notes.push(format!("{}: {note}", o.id));
                    g
                }
                other => {
                    let ctx = need(ctx)?;
                    let mut p: Box<dyn Prior> = match other {
                        ScenePrior::Oracle(_) => {
                            let r = edit_reference.ok_or_else(|| {
                                EditError::Bad(
                                    "restyle with the oracle prior needs --edit-reference FILE.ply (the second reference, object frame)".into(),
                                )
                            })?;
                            let g = crate::splat::ply::read_ply(r)?;
                            Box::new(EditOracle {
                                inner: OraclePrior::new(ctx, &g, None)?,
                                sched: crate::diffusion::schedule::Schedule::new(
                                    crate::diffusion::schedule::SchedulerConfig::sd21_base(),
                                )
                                .map_err(EditError::Bad)?,
                            })
                        }
                        ScenePrior::Sd(m) => {
                            let before = format!("A DSLR photo of a {}", o.category);
                            Box::new(open_sd(&m, &before, Some(description), cfg)?)
                        }
                        ScenePrior::Shape => unreachable!("matched above"),
                    };
                    let g = edit_object(ctx, &cloud, size, p.as_mut(), cfg)?;
                    edit.notes.push(format!(
                        "{}: MTS editing with the {} prior, {} iterations on its {} Gaussians; the rest of the scene unchanged",
                        o.id, state.scene.prior.kind, cfg.iterations, g.len()
                    ));
                    g
                }
            };
            let shared = state
                .scene
                .objects
                .iter()
                .any(|x| x.id != o.id && x.ply == o.ply);
            let rel = if shared {
                let r = format!(
                    "objects/{}.ply",
                    o.id.replace(|c: char| !c.is_alphanumeric(), "_")
                );
                for x in &mut edit.scene.objects {
                    if x.id == o.id {
                        x.ply = r.clone();
                    }
                }
                edit.notes.push(format!(
                    "{} now has its own PLY {r} (others keep {})",
                    o.id, o.ply
                ));
                r
            } else {
                o.ply.clone()
            };
            edit.files.insert(rel, new);
        }
        Part::Environment | Part::Floor => {
            let floor = matches!(which, Part::Floor);
            let env_ref = edit
                .scene
                .environment
                .clone()
                .ok_or_else(|| EditError::Bad("the scene has no environment".into()))?;
            let env = state.load(&env_ref.ply, &edit.files)?;
            let mask: Vec<bool> = env
                .means
                .iter()
                .map(|m| (m[2] < FLOOR_Z) == floor)
                .collect();
            let new = match prior {
                ScenePrior::Shape => {
                    let s = &edit.scene;
                    let (g, note) = match crate::scene::env::restyle_surface(
                        &env,
                        s.scene_type,
                        s.room.size,
                        floor,
                        description,
                        s.seed,
                    ) {
                        Some(r) => r,
                        None => recolour_masked(&env, &mask, description)?,
                    };
                    edit.notes.push(format!("{part}: {note}"));
                    g
                }
                _ => {
                    return Err(EditError::Bad(format!(
                        "restyling the {part} with the {} prior is not available in this build (objects are)",
                        state.scene.prior.kind
                    )))
                }
            };
            edit.files.insert(env_ref.ply.clone(), new);
        }
    }
    Ok(edit)
}

/// MTS editing of an object-frame cloud from orbit views: every Gaussian of the part trains.
fn edit_object(
    ctx: &Context,
    cloud: &Gaussians,
    size: [f64; 3],
    prior: &mut dyn Prior,
    cfg: &ReoptConfig,
) -> Result<Gaussians> {
    let frame = ObjectFrame { size };
    let mut t = Trainer::guided(
        ctx,
        cloud,
        restyle_fit(cfg.iterations, cfg.seed),
        frame.extent(),
    )?;
    let mut guide = Guide::new(
        Rule::Edit,
        MtsRange {
            period: cfg.iterations.max(1),
            ..crate::diffusion::guidance::OBJECT_MTS
        },
        MtsSettings::default(),
        Codec::Fast,
        cfg.seed ^ 0xed17,
    );
    let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed ^ 0x7e57);
    let ranges = OrbitRanges::default();
    let mut progress = Progress::new(cfg.iterations as u64, false);
    let mut views = |step: u32, rng: &mut ChaCha8Rng| {
        random_views(&frame, &ranges, step, BATCH, cfg.resolution, rng)
            .into_iter()
            .map(|v| GuidedView {
                camera: v.camera,
                background: [1.0; 3],
                azimuth: v.azimuth,
                elevation: v.elevation,
            })
            .collect()
    };
    let mut stage = GuidedStage {
        iterations: cfg.iterations,
        trainable: None,
        sh: None,
        checkpoint_every: 0,
        views: &mut views,
    };
    run_guided(
        &mut stage,
        &mut t,
        prior,
        &mut guide,
        &mut rng,
        &mut |t, r, _, _, _| {
            progress.update(t.iteration() as u64, &format!("restyle loss {:.5}", r.loss));
            Ok(())
        },
    )?;
    progress.finish();
    Ok(t.gaussians()?)
}

/// The shape prior's restyle of an object: its shape prior rebuilt from the new description
/// (same category, size, mount and seed). When the rebuilt geometry is the object's own (a draft), only
/// the colours are taken; otherwise the object is tinted toward the description's colour.
fn recolour_object(
    category: &str,
    size: [f64; 3],
    mount: shape::Mount,
    cloud: &Gaussians,
    description: &str,
    seed: u64,
) -> Result<(Gaussians, String)> {
    let words: Vec<String> = crate::shape::materials::colour_words(description)
        .into_iter()
        .map(|w| w.phrase)
        .collect();
    if words.is_empty() {
        return Err(EditError::Bad(format!(
            "\"{description}\": no colour or material word; the shape prior can only recolour (a scene generated with --prior sd restyles freely)"
        )));
    }
    let rebuilt = shape::build(
        category,
        size,
        description,
        &ShapeOptions {
            gaussians: None,
            seed,
            variant: 0,
            mount: Some(mount),
        },
    )
    .map_err(|e| EditError::Bad(e.to_string()))?;
    if rebuilt.len() == cloud.len() && rebuilt.means == cloud.means && cloud.sh_degree == 0 {
        let mut out = cloud.clone();
        out.sh = rebuilt.sh;
        return Ok((
            out,
            format!(
                "shape prior: recoloured from the words {} (geometry kept bit for bit)",
                words.join(", ")
            ),
        ));
    }
    let mask = vec![true; cloud.len()];
    let (g, _) = recolour_masked(cloud, &mask, description)?;
    Ok((
        g,
        format!(
            "shape prior: tinted toward the words {} (geometry kept bit for bit)",
            words.join(", ")
        ),
    ))
}

/// Tints the Gaussians of `mask` toward the first colour word of `description`, keeping each
/// one's brightness relative to the masked mean (the pattern stays, its colour changes).
fn recolour_masked(g: &Gaussians, mask: &[bool], description: &str) -> Result<(Gaussians, String)> {
    use crate::splat::cloud::SH_C0;
    let words = crate::shape::materials::colour_words(description);
    let Some(w) = words.first() else {
        return Err(EditError::Bad(format!(
            "\"{description}\": no colour or material word; the shape prior can only recolour (a scene generated with --prior sd restyles freely)"
        )));
    };
    let target = w.rgb;
    let k3 = g.coeffs() * 3;
    let colour =
        |i: usize| -> [f64; 3] { std::array::from_fn(|c| 0.5 + SH_C0 * g.sh[i * k3 + c] as f64) };
    let (mut sum, mut n) = (0.0, 0usize);
    for i in (0..g.len()).filter(|&i| mask[i]) {
        let c = colour(i);
        sum += (c[0] + c[1] + c[2]) / 3.0;
        n += 1;
    }
    let mean = if n > 0 {
        (sum / n as f64).max(1e-3)
    } else {
        1.0
    };
    let mut out = g.clone();
    for i in (0..g.len()).filter(|&i| mask[i]) {
        let c = colour(i);
        let rel = (c[0] + c[1] + c[2]) / 3.0 / mean;
        for (ch, t) in target.iter().enumerate() {
            let v = (*t as f64 * rel).clamp(0.0, 1.0);
            out.sh[i * k3 + ch] = ((v - 0.5) / SH_C0) as f32;
        }
    }
    Ok((
        out,
        format!(
            "shape prior: {n} Gaussians recoloured to \"{}\" ({:.2}, {:.2}, {:.2}), pattern kept",
            w.phrase, target[0], target[1], target[2]
        ),
    ))
}
