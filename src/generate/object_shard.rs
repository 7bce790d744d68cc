//! One scene over several workers: the objects of a planned scene split into shards (`generate
//! --stage objects --shard I/N`), and the check the scene stage makes before composing (every
//! category's PLY present). A category's shard is its rank among the scene's sorted categories
//! modulo N, a pure function of the plan, so every worker that plans the same prompt and seed
//! agrees on it and N workers get within one object of each other. Host-only.
use super::scene::{category_sizes, draft_object, object_ply};
use crate::batch::shard::Shard;
use crate::plan::spec::{Layout, SceneSpec};
use crate::splat::ply::read_ply;
use anyhow::Result;
use std::path::Path;

/// The categories (with their sizes) of `shard`, or all of them when `None`.
pub fn shard_categories(
    spec: &SceneSpec,
    layout: &Layout,
    shard: Option<Shard>,
) -> Vec<(String, [f64; 3])> {
    category_sizes(spec, layout)
        .into_iter()
        .enumerate()
        .filter(|(k, _)| shard.is_none_or(|s| *k as u32 % s.count == s.index))
        .map(|(_, c)| c)
        .collect()
}

/// Builds the draft PLYs of `shard`'s categories into `out/objects/` (a valid PLY already there
/// is kept); returns each category's Gaussians and whether it was built now.
pub fn build_draft_objects(
    out: &Path,
    spec: &SceneSpec,
    layout: &Layout,
    seed: u64,
    shard: Option<Shard>,
) -> Result<Vec<(String, usize, bool)>> {
    let dir = out.join("objects");
    std::fs::create_dir_all(&dir)
        .map_err(|e| anyhow::anyhow!("creating {}: {e}", dir.display()))?;
    shard_categories(spec, layout, shard)
        .into_iter()
        .map(|(cat, size)| {
            let (g, built) = draft_object(out, spec, &cat, size, seed, true)?;
            Ok((cat, g.len(), built))
        })
        .collect()
}

/// The categories whose `objects/<category>.ply` is missing or unreadable.
pub fn missing_objects(out: &Path, spec: &SceneSpec, layout: &Layout) -> Vec<String> {
    category_sizes(spec, layout)
        .into_keys()
        .filter(|cat| {
            read_ply(&out.join(object_ply(cat)))
                .ok()
                .is_none_or(|g| g.check().is_err() || g.is_empty())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::gcp::{layout, LayoutOptions};
    use crate::plan::offline::plan_offline;

    #[test]
    fn shards_cover_every_category_once_and_evenly() {
        let spec = plan_offline("a living room with a sofa, a tv, a rug, a lamp and a bookshelf");
        let l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
        let all: Vec<String> = shard_categories(&spec, &l, None)
            .into_iter()
            .map(|c| c.0)
            .collect();
        assert!(all.len() >= 4, "{all:?}");
        for n in 1..=4u32 {
            let mut got: Vec<String> = vec![];
            let mut sizes = vec![];
            for i in 0..n {
                let part = shard_categories(&spec, &l, Some(Shard { index: i, count: n }));
                sizes.push(part.len());
                got.extend(part.into_iter().map(|c| c.0));
            }
            got.sort();
            assert_eq!(got, all, "{n} shards cover each category once");
            let (lo, hi) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
            assert!(hi - lo <= 1, "{n} shards: {sizes:?}");
        }
    }
}
