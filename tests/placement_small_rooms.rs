//! Placement in small rooms and of a kitchen's middle: a named table in a kitchen stands in the
//! middle instead of the default island and its bar stools; a room the text calls tiny keeps
//! only the defaults its walls take beside the rest (no piece placed by fallback, the chair at
//! its desk); a layout of a few pieces that still relaxes one tries more doors and windows (a
//! small TV room's loveseat faces its TV on every seed).
use dreamscene::plan::check::{facing_error, validity_problems, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedBy, SceneSpec};

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

fn fallbacks(l: &Layout) -> Vec<&str> {
    l.objects
        .iter()
        .filter(|o| o.placed_by == PlacedBy::Fallback)
        .map(|o| o.id.as_str())
        .collect()
}

#[test]
fn a_named_table_in_a_kitchen_stands_instead_of_the_default_island() {
    for (prompt, table) in [
        (
            "a kitchen with a round table in the middle and three stools around it",
            "round table",
        ),
        ("a kitchen with a table and chairs", "dining table"),
        ("a kitchen with a dining table for four", "dining table"),
    ] {
        let spec = plan_prompt(prompt).expect("planned").spec;
        assert!(
            spec.objects.contains_key(table),
            "{prompt}: {:?}",
            spec.objects.keys()
        );
        for gone in ["kitchen island", "bar stool"] {
            assert!(
                !spec.objects.contains_key(gone),
                "{prompt}: a default {gone} beside the named {table}"
            );
        }
        // what the place cannot do without stays
        for kept in ["refrigerator", "stove", "kitchen sink"] {
            assert!(spec.objects.contains_key(kept), "{prompt}: no {kept}");
        }
    }
    // a named island is kept beside a named table, its stools with it
    let spec = plan_prompt("a kitchen with an island, two bar stools and a dining table")
        .expect("planned")
        .spec;
    for kept in ["kitchen island", "bar stool", "dining table"] {
        assert!(spec.objects.contains_key(kept), "no {kept}");
    }
}

#[test]
fn a_tiny_room_keeps_only_the_defaults_its_walls_take() {
    for prompt in [
        "a tiny home office",
        "a tiny study",
        "a cramped home office",
    ] {
        let plan = plan_prompt(prompt).expect("planned");
        for kept in ["desk", "office chair"] {
            assert!(plan.spec.objects.contains_key(kept), "{prompt}: no {kept}");
        }
        assert!(
            plan.notes.iter().any(|n| n.contains("has no place for it")),
            "{prompt}: nothing trimmed for want of a wall: {:?}",
            plan.notes
        );
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            assert!(
                fallbacks(&l).is_empty(),
                "{prompt} seed {seed}: {:?}",
                fallbacks(&l)
            );
            assert!(
                l.unsatisfied.is_empty(),
                "{prompt} seed {seed}: {:?}",
                l.unsatisfied
            );
        }
    }
    // a room called only small keeps its defaults to the floor share
    let plan = plan_prompt("a small home office").expect("planned");
    assert!(!plan.notes.iter().any(|n| n.contains("has no place for it")));
}

#[test]
fn a_small_tv_rooms_loveseat_faces_its_tv_on_every_seed() {
    for prompt in [
        "a small tv room with a loveseat and a television on the wall",
        "a small snug with a loveseat and a tv on the wall",
        "a tiny tv room with a loveseat, a television on the wall and a bookshelf",
    ] {
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            let get = |c: &str| {
                l.objects
                    .iter()
                    .find(|o| o.category == c)
                    .unwrap_or_else(|| panic!("{prompt}: no {c}"))
            };
            let (seat, tv) = (get("loveseat"), get("tv"));
            let err = facing_error(&Box2::of(seat), &Box2::of(tv));
            assert!(
                err <= 30.0,
                "{prompt} seed {seed}: loveseat off the TV by {err:.0}°"
            );
            for o in [seat, tv] {
                assert_ne!(
                    o.placed_by,
                    PlacedBy::Fallback,
                    "{prompt} seed {seed}: {}",
                    o.id
                );
            }
        }
    }
}
