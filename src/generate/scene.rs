//! The draft scene: a planned layout turned into a scene directory without optimisation. One
//! object PLY per category from its shape prior at the category's planned size, the initial
//! environment (cuboid indoors, hemisphere outdoors, env and floor merged, world frame), the
//! composed `scene.ply` and `scene.json` (ARCHITECTURE.md's scene directory). Host-only; the
//! caller renders.
use crate::plan::spec::{Layout, SceneSpec, SceneType};
use crate::scene::compose::merge;
use crate::scene::dir::{self, SceneFile, SceneObject, Stage};
use crate::scene::env::{init_environment, scene_colours, EnvKind, EnvOptions};
use crate::shape::{self, ShapeOptions};
use crate::splat::ply::{read_ply, write_ply};
use crate::splat::Gaussians;
use anyhow::{bail, Context as _, Result};
use std::collections::BTreeMap;
use std::path::Path;

/// The stages a finished scene lists, in order.
pub const STAGES: [&str; 2] = ["objects", "environment"];

/// What a draft scene was made of.
#[derive(Debug, Clone)]
pub struct DraftReport {
    pub scene: SceneFile,
    /// Categories whose PLY was built (not kept from an earlier run).
    pub built: Vec<String>,
    /// Gaussians per category PLY.
    pub object_gaussians: BTreeMap<String, usize>,
    pub environment_gaussians: usize,
    /// Gaussians of `scene.ply`.
    pub scene_gaussians: usize,
}

/// The relative PLY path of a category's object.
pub fn object_ply(category: &str) -> String {
    let safe: String = category
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("objects/{safe}.ply")
}

/// Each category's size: the spec's, else the first instance's in the layout.
pub fn category_sizes(spec: &SceneSpec, layout: &Layout) -> BTreeMap<String, [f64; 3]> {
    let mut out = BTreeMap::new();
    for o in &layout.objects {
        let size = spec
            .objects
            .get(&o.category)
            .map(|s| s.size)
            .unwrap_or(o.size);
        out.entry(o.category.clone()).or_insert(size);
    }
    out
}

/// The `scene.json` of a layout: instances with their category PLY, position, yaw and the scale
/// of their size against the category's; both stages done.
pub fn scene_file(
    prompt: &str,
    seed: u64,
    spec: &SceneSpec,
    layout: &Layout,
    prior: dir::Prior,
) -> SceneFile {
    let sizes = category_sizes(spec, layout);
    let objects = layout
        .objects
        .iter()
        .map(|o| {
            let c = sizes[&o.category];
            SceneObject {
                id: o.id.clone(),
                category: o.category.clone(),
                ply: object_ply(&o.category),
                position: o.position,
                yaw: o.yaw,
                scale: [0, 1, 2].map(|a| {
                    let s = o.size[a] / c[a];
                    if (s - 1.0).abs() < 1e-9 {
                        1.0
                    } else {
                        s
                    }
                }),
            }
        })
        .collect();
    let kind = env_kind(layout.scene_type);
    SceneFile {
        version: dir::VERSION,
        prompt: prompt.to_string(),
        seed,
        scene_type: layout.scene_type,
        room: dir::Room {
            size: layout.room.size,
        },
        prior,
        objects,
        environment: Some(dir::Environment {
            kind: match kind {
                EnvKind::Cuboid => "cuboid",
                EnvKind::Hemisphere => "hemisphere",
            }
            .to_string(),
            ply: "environment.ply".to_string(),
        }),
        stages: STAGES
            .iter()
            .map(|n| Stage {
                name: n.to_string(),
                done: true,
            })
            .collect(),
        timeline: None,
        history: vec![],
        extra: openings_key(layout),
    }
}

/// The layout's doors and windows as scene.json's `openings` key (indoor rooms).
fn openings_key(layout: &Layout) -> serde_json::Map<String, serde_json::Value> {
    let mut m = serde_json::Map::new();
    if !layout.openings.is_empty() {
        if let Ok(v) = serde_json::to_value(&layout.openings) {
            m.insert("openings".to_string(), v);
        }
    }
    m
}

/// The environment kind of a scene type.
pub fn env_kind(t: SceneType) -> EnvKind {
    match t {
        SceneType::Indoor => EnvKind::Cuboid,
        SceneType::Outdoor => EnvKind::Hemisphere,
    }
}

/// Whether an existing scene may be resumed by a run with `prompt` and `seed`: `Ok(true)` when it
/// is finished, `Ok(false)` when it may be continued, an error saying why not otherwise.
pub fn check_resume(existing: &SceneFile, prompt: &str, seed: u64) -> Result<bool> {
    if existing.prompt != prompt {
        bail!(
            "--resume: the scene was made from \"{}\", not \"{prompt}\" (use another --out or drop \
             --resume to start again)",
            existing.prompt
        );
    }
    if existing.seed != seed {
        bail!(
            "--resume: the scene was made with --seed {}, not {seed} (use another --out or drop \
             --resume to start again)",
            existing.seed
        );
    }
    Ok(STAGES
        .iter()
        .all(|n| existing.stages.iter().any(|s| s.name == *n && s.done)))
}

/// The draft PLY of one category, `objects/<category>.ply`: kept when `keep` and a valid one is
/// there, else built from its shape prior and written. Returns it and whether it was built.
pub fn draft_object(
    out: &Path,
    spec: &SceneSpec,
    cat: &str,
    size: [f64; 3],
    seed: u64,
    keep: bool,
) -> Result<(Gaussians, bool)> {
    let path = out.join(object_ply(cat));
    if keep && path.is_file() {
        if let Some(g) = read_ply(&path)
            .ok()
            .filter(|g| g.check().is_ok() && !g.is_empty())
        {
            return Ok((g, false));
        }
    }
    let description = spec
        .objects
        .get(cat)
        .map(|o| o.description.clone())
        .unwrap_or_else(|| format!("a {cat}"));
    let g = shape::build(
        cat,
        size,
        &description,
        &ShapeOptions {
            gaussians: None,
            seed,
            variant: 0,
            mount: Some(shape::Mount::in_scene(spec, cat)),
        },
    )
    .with_context(|| format!("building the shape prior of `{cat}`"))?;
    write_ply(&path, &g).with_context(|| format!("writing {}", path.display()))?;
    Ok((g, true))
}

/// Writes the draft scene into `dir` (which holds spec.json and layout.json already): object
/// PLYs (kept when `keep_objects` and present), `environment.ply`, `scene.ply`, `scene.json` and
/// an empty `checkpoints/`. Every file is written atomically; `progress` gets one line a stage.
pub fn write_draft_scene(
    out: &Path,
    prompt: &str,
    seed: u64,
    spec: &SceneSpec,
    layout: &Layout,
    keep_objects: bool,
    progress: &mut dyn FnMut(&str),
) -> Result<DraftReport> {
    let objects_dir = out.join("objects");
    std::fs::create_dir_all(&objects_dir)
        .with_context(|| format!("creating {}", objects_dir.display()))?;
    let checkpoints = out.join("checkpoints");
    std::fs::create_dir_all(&checkpoints)
        .with_context(|| format!("creating {}", checkpoints.display()))?;
    let mut scene = scene_file(
        prompt,
        seed,
        spec,
        layout,
        dir::Prior {
            kind: "shape".into(),
            models: None,
        },
    );
    let mut built = vec![];
    let mut object_gaussians = BTreeMap::new();
    for (cat, size) in category_sizes(spec, layout) {
        let (g, was_built) = draft_object(out, spec, &cat, size, seed, keep_objects)?;
        if was_built {
            built.push(cat.clone());
        }
        progress(&format!(
            "object {cat}: {} Gaussians ({:.2} x {:.2} x {:.2} m){}",
            g.len(),
            size[0],
            size[1],
            size[2],
            if built.last() == Some(&cat) {
                ""
            } else {
                ", kept"
            }
        ));
        object_gaussians.insert(cat, g.len());
    }
    let variants = super::variants::draft_variants(
        out,
        spec,
        &mut scene,
        &category_sizes(spec, layout),
        seed,
        keep_objects,
    )?;
    if !variants.is_empty() {
        progress(&format!("variants: {}", variants.join(", ")));
    }
    let colours = scene_colours(layout, prompt);
    let env = init_environment(
        layout.scene_type,
        layout.room.size,
        &colours,
        &EnvOptions {
            seed,
            ..EnvOptions::default()
        },
    );
    let env_g: Gaussians = merge(&[env.env, env.floor]);
    let env_path = out.join("environment.ply");
    write_ply(&env_path, &env_g).with_context(|| format!("writing {}", env_path.display()))?;
    progress(&format!(
        "environment ({}): {} Gaussians",
        scene.environment.as_ref().map_or("", |e| e.kind.as_str()),
        env_g.len()
    ));
    // scene.ply carries instance_id and semantic_id; labels.json names them.
    let composed = crate::export::labels::write_labelled_scene(out, &scene)?;
    dir::write_scene(out, &scene)?;
    progress(&format!(
        "scene: {} Gaussians, scene.json written",
        composed.len()
    ));
    Ok(DraftReport {
        scene,
        built,
        object_gaussians,
        environment_gaussians: env_g.len(),
        scene_gaussians: composed.len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::gcp::{layout, LayoutOptions};
    use crate::plan::offline::plan_offline;

    #[test]
    fn instances_of_another_size_scale_the_category_ply() {
        let spec = plan_offline("a living room with two armchairs");
        let mut l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
        let chairs: Vec<usize> = (0..l.objects.len())
            .filter(|&i| l.objects[i].category == "armchair")
            .collect();
        assert_eq!(chairs.len(), 2);
        let base = spec.objects["armchair"].size;
        l.objects[chairs[1]].size = [base[0] * 1.5, base[1], base[2] * 0.5];
        let s = scene_file(
            "p",
            0,
            &spec,
            &l,
            dir::Prior {
                kind: "shape".into(),
                models: None,
            },
        );
        let by_id = |id: &str| s.objects.iter().find(|o| o.id == id).unwrap();
        assert_eq!(by_id(&l.objects[chairs[0]].id).scale, [1.0; 3]);
        let sc = by_id(&l.objects[chairs[1]].id).scale;
        assert!((sc[0] - 1.5).abs() < 1e-12 && sc[1] == 1.0 && (sc[2] - 0.5).abs() < 1e-12);
        assert!(s.objects.iter().all(|o| o.ply == object_ply(&o.category)));
        assert_eq!(object_ply("coffee table"), "objects/coffee_table.ply");
        assert!(s.validate().is_ok());
    }

    #[test]
    fn scene_json_carries_the_layouts_openings() {
        let spec = plan_offline("a bedroom");
        let l = layout(&spec, LayoutOptions::seeded(2)).unwrap();
        assert!(!l.openings.is_empty());
        let prior = dir::Prior {
            kind: "shape".into(),
            models: None,
        };
        let s = scene_file("a bedroom", 2, &spec, &l, prior);
        let back: Vec<crate::plan::spec::Opening> =
            serde_json::from_value(s.extra["openings"].clone()).unwrap();
        assert_eq!(back, l.openings);
    }

    #[test]
    fn resume_accepts_only_the_same_prompt_and_seed() {
        let spec = plan_offline("a bedroom");
        let l = layout(&spec, LayoutOptions::seeded(1)).unwrap();
        let mut s = scene_file(
            "a bedroom",
            1,
            &spec,
            &l,
            dir::Prior {
                kind: "shape".into(),
                models: None,
            },
        );
        assert!(check_resume(&s, "a bedroom", 1).unwrap());
        assert!(check_resume(&s, "a bedroom", 2)
            .unwrap_err()
            .to_string()
            .contains("--seed 1"));
        assert!(check_resume(&s, "a kitchen", 1)
            .unwrap_err()
            .to_string()
            .contains("a bedroom"));
        s.stages[1].done = false;
        assert!(!check_resume(&s, "a bedroom", 1).unwrap());
    }
}
