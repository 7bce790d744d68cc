//! Blocks of default furniture scaled with a room the text calls small or tiny: the rows of
//! seats or desks and the floor of tables that a place adds on its own (a media room's eight
//! theatre seats, a classroom's desks, a cafe's tables) keep the share of their instances that
//! the room keeps of its floor, so the room is sized for a small place's crowd rather than grown
//! back to the full place's. What the text names, and what the place cannot do without, keeps
//! its count.
use super::trim_one;
use crate::plan::spec::{RelationKind, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};

/// Fewest instances a scaled block keeps (two seats still face the screen together).
const FEWEST: u32 = 2;

/// Whether category `c` of `spec` stands in a block: rows asked, in ROW before a front, tables
/// with seats AROUND them, or desks and counters with a seat AT each (an office's workstations).
fn in_block(spec: &SceneSpec, c: &str) -> bool {
    let base = |id: &str| {
        id.trim_end_matches(|ch: char| ch.is_ascii_digit())
            .to_string()
    };
    spec.objects.get(c).is_some_and(|o| o.rows > 0)
        || spec.relations.iter().any(|r| {
            (r.relation == RelationKind::Row && base(&r.subject) == c)
                || (matches!(r.relation, RelationKind::Around | RelationKind::At)
                    && base(&r.object) == c)
        })
}

/// The count a default block of `n` keeps in a room whose floor is scaled by `scale` (< 1).
fn scaled(n: u32, scale: f64) -> u32 {
    ((n as f64 * scale).ceil() as u32).clamp(FEWEST.min(n), n)
}

/// Scales every default block of `spec` (not in `keep` nor `essential`) by `scale`, the floor
/// factor of the room's size word: its last instances go, each with the defaults that then
/// relate to nothing (a desk's chair, a table's seats). Returns one note per category cut.
pub(crate) fn scale_blocks(
    spec: &mut SceneSpec,
    keep: &BTreeSet<String>,
    essential: &BTreeSet<String>,
    scale: f64,
) -> Vec<String> {
    let mut dropped: BTreeMap<String, u32> = BTreeMap::new();
    let blocks: Vec<(String, u32)> = spec
        .objects
        .iter()
        .filter(|(c, _)| !keep.contains(*c) && !essential.contains(*c) && in_block(spec, c))
        .map(|(c, o)| (c.clone(), o.number))
        .collect();
    for (c, n) in blocks {
        for _ in scaled(n, scale)..n {
            trim_one(spec, &c, keep, essential, &mut dropped);
        }
    }
    dropped
        .into_iter()
        .map(|(c, n)| format!("{n} default {c} left out: a smaller place seats fewer"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_block_keeps_its_floors_share_and_never_fewer_than_two() {
        assert_eq!(scaled(8, 0.5), 4);
        assert_eq!(scaled(8, 0.35), 3);
        assert_eq!(scaled(3, 0.35), 2);
        assert_eq!(scaled(1, 0.35), 1);
        assert_eq!(scaled(4, 1.0), 4);
    }
}
