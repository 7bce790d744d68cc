//! What hangs on the wall above a thing (shelves over a washer, cabinets over a stove) is no
//! load on its top: the thing keeps its own width, while things that stand side by side on a
//! support (monitors on a bench) still widen it. "Wall shelves" in a place whose shelves are
//! storage shelving are the hanging kind the words name.
mod common;
use common::placed::{all, lay, SEEDS};
use dreamscene::plan::kb::KnowledgeBase;

#[test]
fn shelves_hung_above_machines_leave_them_their_own_width() {
    let kb = KnowledgeBase::builtin();
    for (prompt, below) in [
        (
            "a utility room with a washing machine and a tumble dryer, two wall shelves above them",
            &["washing machine", "dryer"][..],
        ),
        (
            "a small kitchen with a fridge and a stove, and two wall cabinets above the stove",
            &["stove"][..],
        ),
        (
            "a bathroom with a washing machine under three wall shelves",
            &["washing machine"][..],
        ),
    ] {
        for seed in SEEDS {
            let (l, spec) = lay(prompt, seed);
            for c in below {
                let own = kb.object(c).map(|o| o.size[0]).unwrap();
                let o = spec
                    .objects
                    .get(*c)
                    .unwrap_or_else(|| panic!("{prompt}: no {c}"));
                assert!(
                    o.size[0] <= own + 1e-6,
                    "{prompt}: {c} planned {:.2} m wide (its own {own:.2})",
                    o.size[0]
                );
                assert!(
                    !all(&l, c).is_empty(),
                    "{prompt} seed {seed}: {c} not placed"
                );
            }
        }
    }
}

#[test]
fn things_standing_side_by_side_still_widen_their_support() {
    let kb = KnowledgeBase::builtin();
    let prompt = "a workshop with four monitors on one workbench";
    let (_, spec) = lay(prompt, 0);
    let own = kb.object("workbench").map(|o| o.size[0]).unwrap();
    let w = spec.objects["workbench"].size[0];
    let monitors = spec.objects.get("monitor").map_or(0, |o| o.number);
    assert_eq!(monitors, 4, "{prompt}");
    let need = 4.0 * spec.objects["monitor"].size[0];
    assert!(
        w >= need.min(3.0 * own) - 1e-6,
        "{prompt}: workbench {w:.2} m for 4 monitors"
    );
}

#[test]
fn a_kind_named_by_its_own_word_is_not_the_places_bare_noun() {
    // A garage's and a laundry's shelves are their storage shelving, but "wall shelves" and
    // "floating shelves" name the hanging kind by a word of its own name.
    for (prompt, n) in [
        ("a garage with two wall shelves and a workbench", 2),
        ("a laundry room with three floating shelves", 3),
        (
            "a utility room with a washing machine and a tumble dryer, two wall shelves above them",
            2,
        ),
    ] {
        let (_, spec) = lay(prompt, 0);
        let got = spec.objects.get("wall shelf").map_or(0, |o| o.number);
        assert_eq!(
            got,
            n,
            "{prompt}: {:?}",
            spec.objects.keys().collect::<Vec<_>>()
        );
    }
    // the bare noun is still the place's own
    let (_, spec) = lay("a laundry room with two shelves", 0);
    assert!(
        !spec.objects.contains_key("wall shelf"),
        "bare shelves of a laundry"
    );
}
