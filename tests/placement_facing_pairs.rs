//! Two things asked to face each other (OPPOSITE) keep their sightline clear of what belongs to
//! neither; the seats pulled up to either end belong to it (two desks facing each other across
//! the room, each with its chair before it), so the pair holds.
mod common;
use common::placed::{lay, SEEDS};
use dreamscene::plan::spec::RelationKind;

#[test]
fn desks_facing_each_other_with_their_chairs_hold() {
    for prompt in [
        "an office with two desks facing each other",
        "a shared study: two writing desks face each other, each with its own chair",
        "a home office for a couple where two desks facing each other stand by the window",
    ] {
        for seed in SEEDS {
            let (l, spec) = lay(prompt, seed);
            assert!(
                spec.relations
                    .iter()
                    .any(|r| r.relation == RelationKind::Opposite),
                "{prompt}: no OPPOSITE read"
            );
            let missed: Vec<_> = l
                .unsatisfied
                .iter()
                .filter(|r| r.relation == RelationKind::Opposite)
                .collect();
            assert!(missed.is_empty(), "{prompt} seed {seed}: {missed:?}");
        }
    }
}
