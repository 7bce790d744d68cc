//! Per-Gaussian labels of a composed scene (ARCHITECTURE.md, "Labels"). `scene.ply` holds the
//! instances of `scene.json` in order, one contiguous block each, then the environment, so the
//! labels follow from the block sizes: `instance_id` is the instance's 1-based position in
//! `scene.json` (0 = walls, floor, ground), `semantic_id` the 1-based position of its category
//! among the scene's categories in order of first appearance (0 = environment). `labels.json`
//! maps both back to ids, categories and a display colour.
//!
//! Selections (`export --only` / `--without`) name instances by id (spaces or `_`), categories,
//! or `walls` / `floor` / `environment` for instance 0.
use super::{ExportError, Result};
use crate::scene::dir::SceneFile;
use crate::splat::ply::Labels;
use serde_json::{json, Value};

/// One instance's labels and its block in the composed cloud.
#[derive(Debug, Clone, PartialEq)]
pub struct Instance {
    pub instance_id: u16,
    pub id: String,
    pub category: String,
    pub semantic_id: u8,
    /// First Gaussian and count in the composed cloud.
    pub start: usize,
    pub count: usize,
}

/// The labels of a composed scene.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneLabels {
    pub instances: Vec<Instance>,
    /// Categories by semantic id minus one.
    pub categories: Vec<String>,
    /// The environment's block (instance 0), `(start, count)`.
    pub environment: (usize, usize),
}

/// A node name for an instance id: glTF readers sanitise names (three.js turns spaces into `_`
/// and drops `[ ] . : /`), so ids are written the way they will read back.
pub fn node_name(id: &str) -> String {
    id.chars()
        .filter(|c| !matches!(c, '[' | ']' | '.' | ':' | '/'))
        .map(|c| if c.is_whitespace() { '_' } else { c })
        .collect()
}

/// A distinct display colour for a semantic id (0, the environment, is grey): hues a golden
/// angle apart.
pub fn colour(semantic_id: u8) -> [u8; 3] {
    if semantic_id == 0 {
        return [128, 128, 128];
    }
    let h = (f64::from(semantic_id) * 0.618_033_988_75).fract() * 6.0;
    let (s, v) = (0.65, 0.95);
    let f = h.fract();
    let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
    let rgb = match h as u32 {
        0 => [v, t, p],
        1 => [q, v, p],
        2 => [p, v, t],
        3 => [p, q, v],
        4 => [t, p, v],
        _ => [v, p, q],
    };
    rgb.map(|c| (c * 255.0).round() as u8)
}

impl SceneLabels {
    /// The labels of `scene` composed from blocks of `counts[i]` Gaussians per instance, then
    /// `environment` Gaussians.
    pub fn new(scene: &SceneFile, counts: &[usize], environment: usize) -> Result<SceneLabels> {
        if counts.len() != scene.objects.len() {
            return Err(ExportError::Unrepresentable(format!(
                "{} instances but {} object blocks",
                scene.objects.len(),
                counts.len()
            )));
        }
        if scene.objects.len() >= usize::from(u16::MAX) {
            return Err(ExportError::Unrepresentable(format!(
                "{} instances: instance_id is a ushort (at most 65534 instances)",
                scene.objects.len()
            )));
        }
        let mut categories: Vec<String> = vec![];
        let mut instances = vec![];
        let mut start = 0;
        for (i, (o, &count)) in scene.objects.iter().zip(counts).enumerate() {
            let sem = match categories.iter().position(|c| *c == o.category) {
                Some(k) => k + 1,
                None => {
                    categories.push(o.category.clone());
                    categories.len()
                }
            };
            let semantic_id = u8::try_from(sem).map_err(|_| {
                ExportError::Unrepresentable(
                    "more than 255 categories: semantic_id is a uchar".into(),
                )
            })?;
            instances.push(Instance {
                instance_id: (i + 1) as u16,
                id: o.id.clone(),
                category: o.category.clone(),
                semantic_id,
                start,
                count,
            });
            start += count;
        }
        Ok(SceneLabels {
            instances,
            categories,
            environment: (start, environment),
        })
    }

    /// The labels of the parts a composition merges: one placed cloud per instance of
    /// `scene.objects`, then the environment's parts (none while its stage is pending).
    pub fn of_parts(scene: &SceneFile, parts: &[crate::splat::Gaussians]) -> Result<SceneLabels> {
        let n = scene.objects.len().min(parts.len());
        let counts: Vec<usize> = parts[..n].iter().map(|g| g.len()).collect();
        let env = parts[n..].iter().map(|g| g.len()).sum();
        SceneLabels::new(scene, &counts, env)
    }

    /// Gaussians in all.
    pub fn len(&self) -> usize {
        self.environment.0 + self.environment.1
    }

    /// Whether the scene has no Gaussians.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// One label pair per Gaussian of the composed cloud.
    pub fn per_gaussian(&self) -> Labels {
        let mut l = Labels {
            instance: Vec::with_capacity(self.len()),
            semantic: Vec::with_capacity(self.len()),
        };
        for i in &self.instances {
            l.instance
                .extend(std::iter::repeat_n(i.instance_id, i.count));
            l.semantic
                .extend(std::iter::repeat_n(i.semantic_id, i.count));
        }
        l.instance
            .extend(std::iter::repeat_n(0, self.environment.1));
        l.semantic
            .extend(std::iter::repeat_n(0, self.environment.1));
        l
    }

    /// `labels.json`: every instance (id, category, both ids, colour, its Gaussian block) and
    /// the semantic table.
    pub fn to_json(&self) -> Value {
        let instances: Vec<Value> = std::iter::once(json!({
            "instance_id": 0, "id": "environment", "category": "environment",
            "semantic_id": 0, "colour": colour(0),
            "gaussians": [self.environment.0, self.environment.1]
        }))
        .chain(self.instances.iter().map(|i| {
            json!({
                "instance_id": i.instance_id, "id": i.id, "category": i.category,
                "semantic_id": i.semantic_id, "colour": colour(i.semantic_id),
                "gaussians": [i.start, i.count]
            })
        }))
        .collect();
        let semantic: Vec<Value> = std::iter::once(json!({
            "semantic_id": 0, "category": "environment", "colour": colour(0)
        }))
        .chain(self.categories.iter().enumerate().map(|(k, c)| {
            let s = (k + 1) as u8;
            json!({"semantic_id": s, "category": c, "colour": colour(s)})
        }))
        .collect();
        json!({"version": 1, "instances": instances, "semantic": semantic})
    }

    /// The text of `labels.json` (what [`write_labelled_scene`] and every edit write).
    pub fn to_json_text(&self) -> Result<String> {
        serde_json::to_string_pretty(&self.to_json())
            .map_err(|e| ExportError::Unrepresentable(e.to_string()))
    }

    /// Which instance ids (0 = environment) a selection keeps: `only` (empty = all) minus
    /// `without`. A name matching nothing is an error naming what the scene has.
    pub fn select(&self, only: &[String], without: &[String]) -> Result<Vec<bool>> {
        let n = self.instances.len() + 1;
        let matches = |name: &str| -> Result<Vec<u16>> {
            let key = node_name(name.trim()).to_lowercase();
            if ["walls", "wall", "floor", "environment", "ground"].contains(&key.as_str()) {
                return Ok(vec![0]);
            }
            let hit: Vec<u16> = self
                .instances
                .iter()
                .filter(|i| {
                    node_name(&i.id).to_lowercase() == key
                        || node_name(&i.category).to_lowercase() == key
                })
                .map(|i| i.instance_id)
                .collect();
            if hit.is_empty() {
                let ids: Vec<String> = self.instances.iter().map(|i| node_name(&i.id)).collect();
                return Err(ExportError::Unrepresentable(format!(
                    "`{name}` names no instance or category of this scene; it has {} and walls",
                    ids.join(", ")
                )));
            }
            Ok(hit)
        };
        let mut keep = vec![only.is_empty(); n];
        for name in only {
            for k in matches(name)? {
                keep[usize::from(k)] = true;
            }
        }
        for name in without {
            for k in matches(name)? {
                keep[usize::from(k)] = false;
            }
        }
        Ok(keep)
    }
}

/// Composes the scene in `dir` and writes `scene.ply` with its labels and `labels.json` beside
/// it, both atomically; returns the composed cloud (what `generate` writes).
pub fn write_labelled_scene(
    dir: &std::path::Path,
    scene: &SceneFile,
) -> Result<crate::splat::Gaussians> {
    let parts = crate::scene::dir::compose_parts(dir, scene)
        .map_err(|e| ExportError::Unrepresentable(e.to_string()))?;
    let labels = SceneLabels::of_parts(scene, &parts)?;
    let cloud = crate::scene::compose::merge(&parts);
    let write_err = |path: std::path::PathBuf| {
        move |source| ExportError::Write {
            path: path.display().to_string(),
            source,
        }
    };
    let ply = dir.join("scene.ply");
    crate::splat::ply::write_ply_labelled(&ply, &cloud, Some(&labels.per_gaussian()))
        .map_err(write_err(ply))?;
    let json = dir.join("labels.json");
    let text = labels.to_json_text()?;
    crate::util::write_atomic(&json, text.as_bytes()).map_err(write_err(json))?;
    Ok(cloud)
}
