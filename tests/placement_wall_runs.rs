//! Things asked along one wall ("six chairs along the wall", "lined up against the wall") stand
//! in one run along one wall, evenly spaced, facing the room (on two walls only when one is
//! too short); a water cooler stands against a wall.
use dreamscene::plan::check::{validity_problems, wall_distances, Box2, WALL_NORMALS};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject};

const SEEDS: std::ops::Range<u64> = 0..3;

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> Layout {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    l
}

fn all<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category)
        .collect()
}

/// The wall (in `wall_distances` order) `o` stands against with its back, facing the room.
fn wall_of(l: &Layout, o: &PlacedObject) -> Option<usize> {
    let b = Box2::of(o);
    let wd = wall_distances(&b, l.room.size);
    (0..4).find(|&k| {
        let n = WALL_NORMALS[k];
        wd[k] <= 0.3 && b.ey[0] * n[0] + b.ey[1] * n[1] > 0.95
    })
}

#[test]
fn things_asked_along_the_wall_stand_in_one_run_there() {
    for (prompt, cat, n) in [
        (
            "a doctor's waiting room with seven chairs along the wall and a front desk",
            "waiting chair",
            7,
        ),
        (
            "a home gym with three treadmills lined up against one wall",
            "treadmill",
            3,
        ),
        (
            "a vet's waiting room, five chairs against the wall, a water cooler and a plant",
            "waiting chair",
            5,
        ),
    ] {
        for seed in SEEDS {
            let l = lay(prompt, seed);
            let things = all(&l, cat);
            assert_eq!(things.len(), n, "{prompt}");
            let walls: Vec<Option<usize>> = things.iter().map(|o| wall_of(&l, o)).collect();
            assert!(
                walls.iter().all(Option::is_some),
                "{prompt} (seed {seed}): not all against a wall facing the room: {walls:?}"
            );
            let mut distinct: Vec<usize> = walls.iter().flatten().copied().collect();
            distinct.sort();
            distinct.dedup();
            // one wall, unless the longest wall is too short for the run
            let run: f64 = things.iter().map(|o| o.size[0] + 0.1).sum();
            let longest = l.room.size[0].max(l.room.size[1]);
            let most = if run <= longest - 0.7 { 1 } else { 2 };
            assert!(
                distinct.len() <= most,
                "{prompt} (seed {seed}): on walls {distinct:?} of a {:?} room",
                l.room.size
            );
            // evenly spaced: the gaps between neighbours on each wall are the same
            for &k in &distinct {
                let axis = if k < 2 { 1 } else { 0 };
                let mut on: Vec<&&PlacedObject> = things
                    .iter()
                    .zip(&walls)
                    .filter(|(_, w)| **w == Some(k))
                    .map(|(o, _)| o)
                    .collect();
                on.sort_by(|a, b| a.position[axis].total_cmp(&b.position[axis]));
                let gaps: Vec<f64> = on
                    .windows(2)
                    .map(|w| {
                        (w[1].position[axis] - w[0].position[axis])
                            - 0.5 * (w[0].size[0] + w[1].size[0])
                    })
                    .collect();
                let (lo, hi) = gaps
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &g| {
                        (a.min(g), b.max(g))
                    });
                assert!(
                    gaps.is_empty() || (hi - lo < 0.02 && lo >= 0.0 && hi <= 0.3),
                    "{prompt} (seed {seed}): gaps {gaps:?}"
                );
            }
        }
    }
}

#[test]
fn a_water_cooler_stands_against_a_wall() {
    for prompt in [
        "an office with four desks and a water cooler",
        "a vet's waiting room, five chairs against the wall, a water cooler and a plant",
    ] {
        for seed in SEEDS {
            let l = lay(prompt, seed);
            for o in all(&l, "water cooler") {
                assert!(
                    wall_of(&l, o).is_some(),
                    "{prompt} (seed {seed}): {} stands off the walls at {:?}",
                    o.id,
                    o.position
                );
            }
        }
    }
}
