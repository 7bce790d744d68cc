//! A table laid for more than its long sides seat has seats at its ends too: the room the
//! planner chooses takes its length and a chair at each end, so neither end stands against a
//! wall (a long table for ten shoved to one wall, its end chairs crowded at the other).
mod common;
use common::placed::{lay, SEEDS};
use dreamscene::plan::check::{wall_distances, Box2};

/// Room (m) each end of the table keeps to the wall: a chair's depth and room to sit down.
const END_ROOM: f64 = 0.75;

#[test]
fn a_table_for_many_keeps_room_for_a_chair_at_each_end() {
    for prompt in [
        "a table for twelve",
        "a long dining table for ten people",
        "one long wooden table for ten with chairs",
    ] {
        for seed in SEEDS {
            let (l, _) = lay(prompt, seed);
            let table = l
                .objects
                .iter()
                .find(|o| o.category == "dining table")
                .expect("a dining table");
            let b = Box2::of(table);
            let [x0, x1, y0, y1] = wall_distances(&b, l.room.size);
            // the walls at its ends: along its length (its local x)
            let ends = if b.ex[0].abs() > b.ex[1].abs() {
                [x0, x1]
            } else {
                [y0, y1]
            };
            assert!(
                ends.iter().all(|&e| e >= END_ROOM),
                "{prompt} seed {seed}: ends {ends:.2?} from the walls in {:?}",
                l.room.size
            );
        }
    }
}
