//! Instances of one category that a draft draws differently: the n-th poster, painting or
//! statue of a scene (in layout order) is its archetype's variant n mod the variant count
//! (`shape/kb/variants.txt`), so a row of posters shows different prints. Variant 0 is the
//! category's own PLY (`objects/<category>.ply`); each other variant in use is built once, into
//! `objects/<category>--v<n>.ply`, and the instances drawn in it point there in `scene.json`.
//! Categories with one variant, and all heavy shapes, are built once per scene as before.
use super::scene::object_ply;
use crate::plan::spec::SceneSpec;
use crate::scene::dir::SceneFile;
use crate::shape::{self, ShapeOptions};
use crate::splat::ply::{read_ply, write_ply};
use anyhow::{Context, Result};
use std::collections::BTreeMap;
use std::path::Path;

/// The variant each instance of `scene` is drawn in, by index into `scene.objects`: the count of
/// earlier instances of its category, modulo its archetype's variant count.
pub fn instance_variants(scene: &SceneFile) -> Vec<u32> {
    let mut seen: BTreeMap<&str, u32> = BTreeMap::new();
    scene
        .objects
        .iter()
        .map(|o| {
            let n = seen.entry(o.category.as_str()).or_insert(0);
            let v = *n % shape::variants::count(shape::archetype_of(&o.category));
            *n += 1;
            v
        })
        .collect()
}

/// The relative PLY path of variant `variant` of a category (its own PLY for variant 0).
pub fn variant_ply(category: &str, variant: u32) -> String {
    let own = object_ply(category);
    if variant == 0 {
        own
    } else {
        format!("{}--v{variant}.ply", own.trim_end_matches(".ply"))
    }
}

/// Points every instance drawn in a variant other than 0 at that variant's PLY, building each
/// such PLY once (kept when `keep` and a readable one is there) at its category's size with the
/// category's description. Returns the variant PLYs built.
pub fn draft_variants(
    out: &Path,
    spec: &SceneSpec,
    scene: &mut SceneFile,
    sizes: &BTreeMap<String, [f64; 3]>,
    seed: u64,
    keep: bool,
) -> Result<Vec<String>> {
    let mut built = vec![];
    let variants = instance_variants(scene);
    for (o, v) in scene.objects.iter_mut().zip(variants) {
        if v == 0 {
            continue;
        }
        let rel = variant_ply(&o.category, v);
        let path = out.join(&rel);
        let usable = |p: &Path| read_ply(p).is_ok_and(|g| g.check().is_ok() && !g.is_empty());
        let kept = keep && path.is_file() && usable(&path);
        if !kept && !built.contains(&rel) {
            let size = sizes.get(&o.category).copied().unwrap_or([1.0, 1.0, 1.0]);
            let description = spec
                .objects
                .get(&o.category)
                .map(|s| s.description.clone())
                .unwrap_or_else(|| format!("a {}", o.category));
            let g = shape::build(
                &o.category,
                size,
                &description,
                &ShapeOptions {
                    gaussians: None,
                    seed,
                    variant: v,
                    mount: Some(shape::Mount::in_scene(spec, &o.category)),
                },
            )
            .with_context(|| format!("building variant {v} of `{}`", o.category))?;
            write_ply(&path, &g).with_context(|| format!("writing {}", path.display()))?;
            built.push(rel.clone());
        }
        o.ply = rel;
    }
    Ok(built)
}
