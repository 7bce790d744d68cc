//! A room the text calls tiny is trimmed to its floor share first (`capacity::fit`); what is
//! left can still be more than its walls take: a tiny home office's bookshelf and filing cabinet
//! beside the desk, where the layout then relaxes the desk and its chair to fit them. Here the
//! defaults the place can do without go, one at a time in `capacity`'s order, while each removal
//! leaves fewer pieces placed by fallback over a few seeds. Named objects and what the place
//! cannot do without never go.
use crate::plan::capacity::{next_to_trim, trim_one};
use crate::plan::gcp::classes::{effective_class, Class};
use crate::plan::gcp::{layout, LayoutOptions};
use crate::plan::spec::{PlacedBy, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};

/// Seeds the layouts are tried on (the figures read seeds 0 to 2).
const SEEDS: [u64; 3] = [0, 1, 2];

/// Pieces placed by fallback over [`SEEDS`]; a spec the layout refuses counts as worst.
fn fallbacks(spec: &SceneSpec) -> usize {
    SEEDS
        .iter()
        .map(|&seed| match layout(spec, LayoutOptions::seeded(seed)) {
            Ok(l) => l
                .objects
                .iter()
                .filter(|o| o.placed_by == PlacedBy::Fallback)
                .count(),
            Err(_) => usize::MAX / SEEDS.len(),
        })
        .sum()
}

/// Trims from `spec` (laid out in a tiny room) the defaults, not `essential`, whose going
/// lets the rest lay out with fewer fallbacks; one note per category trimmed.
pub(super) fn trim_unplaceable(
    spec: &mut SceneSpec,
    named: &BTreeSet<String>,
    essential: &BTreeSet<String>,
) -> Vec<String> {
    let mut worst = fallbacks(spec);
    let mut dropped = BTreeMap::new();
    // only what the place can do without and what stands on the floor is a candidate: an
    // essential default, a computer on the desk or a clock on the wall is never picked
    let on_floor = |c: &str| matches!(effective_class(spec, c), Class::Floor | Class::AgainstWall);
    let keep: BTreeSet<String> = spec
        .objects
        .keys()
        .filter(|c| named.contains(*c) || essential.contains(*c) || !on_floor(c))
        .cloned()
        .collect();
    while worst > 0 {
        let Some(c) = next_to_trim(spec, &keep, essential, true) else {
            break;
        };
        let mut fewer = spec.clone();
        let mut gone = BTreeMap::new();
        trim_one(&mut fewer, &c, named, essential, &mut gone);
        if fewer.objects.is_empty() {
            break;
        }
        let n = fallbacks(&fewer);
        if n >= worst {
            break;
        }
        (*spec, worst) = (fewer, n);
        for (c, k) in gone {
            *dropped.entry(c).or_insert(0) += k;
        }
    }
    let Some(room) = spec.room else {
        return vec![];
    };
    dropped
        .into_iter()
        .map(|(c, n)| {
            format!(
                "{n} default {c} left out: the {} x {} m room has no place for it beside the rest",
                room.size[0], room.size[1]
            )
        })
        .collect()
}
