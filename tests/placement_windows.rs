//! A thing asked under or by the window stands at a window: before its span, near its wall (a
//! window is made in the wall it stands at when the room has none free there); along the wall
//! past the window is not at it; and when the anchor cannot be met (a windowless room) the
//! layout lists it in `unsatisfied_anchors`.
use dreamscene::plan::check::{anchor_holds_in, at_window, validity_problems, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Anchor, Layout, Opening, OpeningKind, SceneType, Wall};

const SEEDS: std::ops::Range<u64> = 0..3;

fn lay(prompt: &str, seed: u64) -> Layout {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    l
}

#[test]
fn beside_the_window_along_its_wall_is_not_at_it() {
    // a 0.96 m window in the middle of the north wall of a 3.2 x 2.6 m room
    let w = Opening {
        kind: OpeningKind::Window,
        wall: Wall::North,
        position: [0.0, 1.3, 0.9],
        width: 0.96,
        height: 1.3,
    };
    // a desk against the north wall just past the window's end, turned along the east wall
    let beside = Box2::new([0.96, 0.58], -90.0, [1.4, 0.7], 0.0, 0.75);
    assert!(!at_window(&beside, &w));
    // the same desk under the window, its back to it
    let under = Box2::new([0.0, 0.93], 180.0, [1.4, 0.7], 0.0, 0.75);
    assert!(at_window(&under, &w));
    // a plant just beside the window's frame is by it; one in the middle of the room is not
    let by = Box2::new([0.7, 1.0], 0.0, [0.4, 0.4], 0.0, 1.0);
    assert!(at_window(&by, &w));
    let mid = Box2::new([0.0, -0.2], 0.0, [0.4, 0.4], 0.0, 1.0);
    assert!(!at_window(&mid, &w));
    let room = [3.2, 2.6, 2.8];
    assert!(!anchor_holds_in(
        &beside,
        Anchor::Window,
        SceneType::Indoor,
        room,
        &[w]
    ));
}

#[test]
fn a_thing_asked_under_the_window_stands_at_one() {
    for (prompt, id) in [
        (
            "a little bedroom with a single bed, a writing desk beneath the window and a red lamp",
            "desk1",
        ),
        (
            "a box room with a narrow bed, a desk under the window and a chair",
            "desk1",
        ),
        (
            "a guest room with a double bed, a wardrobe and an armchair by the window",
            "armchair1",
        ),
    ] {
        for seed in SEEDS {
            let l = lay(prompt, seed);
            let o = l
                .objects
                .iter()
                .find(|o| o.id == id)
                .unwrap_or_else(|| panic!("{prompt}: no {id}"));
            assert_eq!(o.anchor, Anchor::Window, "{prompt}");
            let b = Box2::of(o);
            let at = l
                .openings
                .iter()
                .any(|w| w.kind == OpeningKind::Window && at_window(&b, w));
            assert!(
                at,
                "{prompt} (seed {seed}): {id} at {:?} is at no window of {:?}",
                o.position, l.openings
            );
            assert!(
                !l.unsatisfied_anchors.iter().any(|a| a.id == id),
                "{prompt} (seed {seed}): {id} listed unmet"
            );
        }
    }
}

#[test]
fn a_window_anchor_that_cannot_be_met_is_listed() {
    for prompt in [
        "a windowless storage room with a desk under the window and two shelves",
        "a windowless cellar with an armchair by the window",
    ] {
        for seed in SEEDS {
            let l = lay(prompt, seed);
            assert!(
                !l.openings.iter().any(|o| o.kind == OpeningKind::Window),
                "{prompt}: windows made in a windowless room"
            );
            let asked: Vec<&str> = l
                .objects
                .iter()
                .filter(|o| o.anchor == Anchor::Window)
                .map(|o| o.id.as_str())
                .collect();
            assert!(!asked.is_empty(), "{prompt}: nothing asked at a window");
            for id in asked {
                assert!(
                    l.unsatisfied_anchors
                        .iter()
                        .any(|a| a.id == id && a.anchor == Anchor::Window),
                    "{prompt} (seed {seed}): {id} not listed in {:?}",
                    l.unsatisfied_anchors
                );
            }
        }
    }
}
