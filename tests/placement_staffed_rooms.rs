//! The room the planner chooses for a counter staff stand behind takes their band too: the
//! counter stands with its back the staff's depth off a wall, facing the room, in a small
//! cafeteria as in a large hall (not put anywhere by the fallback, facing a wall).
mod common;
use common::placed::{lay, SEEDS};
use dreamscene::plan::check::{wall_distances, Box2, WALL_NORMALS};
use dreamscene::plan::spec::PlacedBy;

#[test]
fn a_staffed_counter_stands_before_its_staff_band() {
    for prompt in [
        "a cafeteria with a serving counter and tables",
        "a works canteen: a long counter, three dining tables",
    ] {
        for seed in SEEDS {
            let (l, _) = lay(prompt, seed);
            let counter = l
                .objects
                .iter()
                .find(|o| o.category == "counter")
                .expect("a counter");
            assert_eq!(
                counter.placed_by,
                PlacedBy::Constraint,
                "{prompt} seed {seed}"
            );
            let b = Box2::of(counter);
            // the wall behind it: the one whose inward normal it faces along
            let (k, _) = WALL_NORMALS
                .iter()
                .enumerate()
                .map(|(k, n)| (k, n[0] * b.ey[0] + n[1] * b.ey[1]))
                .fold((0, f64::MIN), |a, x| if x.1 > a.1 { x } else { a });
            let behind = wall_distances(&b, l.room.size)[k];
            assert!(
                (0.8..=1.3).contains(&behind),
                "{prompt} seed {seed}: its back {behind:.2} m off the wall behind it"
            );
        }
    }
}
