//! Counters staff stand behind (a reception desk, a checkout counter) keep 0.8-1.2 m free
//! between their back and the wall behind them, facing the room, with nothing unrelated
//! standing in that band (a soft cost in the search: a shop crowded with rows of shelves may
//! still have one there, so the band is checked where the room has space); a counter the
//! text puts against the wall stands there.
use dreamscene::plan::check::{
    overlap_depth, validity_problems, wall_distances, Box2, WALL_NORMALS,
};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, SceneSpec};

const SEEDS: std::ops::Range<u64> = 0..3;

fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

#[test]
fn a_reception_desk_or_checkout_keeps_room_for_its_staff() {
    for (prompt, cat, band_free) in [
        (
            "a physio clinic waiting room with a reception desk and five chairs along the wall",
            "reception desk",
            true,
        ),
        (
            "a hotel lobby with a front desk, two sofas and a coffee table",
            "hotel reception desk",
            true,
        ),
        (
            "a small grocery shop with a checkout counter and four shelves",
            "checkout counter",
            false,
        ),
    ] {
        for seed in SEEDS {
            let (l, spec) = lay(prompt, seed);
            let o = l
                .objects
                .iter()
                .find(|o| o.category == cat)
                .unwrap_or_else(|| panic!("{prompt}: no {cat}"));
            let b = Box2::of(o);
            // the wall behind it: the one its back is turned to
            let wd = wall_distances(&b, l.room.size);
            let k = (0..4)
                .max_by(|&a, &c| {
                    let dot =
                        |w: usize| b.ey[0] * WALL_NORMALS[w][0] + b.ey[1] * WALL_NORMALS[w][1];
                    dot(a).total_cmp(&dot(c))
                })
                .expect("a wall");
            let facing = b.ey[0] * WALL_NORMALS[k][0] + b.ey[1] * WALL_NORMALS[k][1];
            assert!(
                facing > 0.95 && (0.8..=1.2).contains(&wd[k]),
                "{prompt} (seed {seed}): {} {:.2} m off the wall behind it (facing {facing:.2})",
                o.id,
                wd[k]
            );
            // nothing unrelated stands in the band behind it
            let depth = wd[k];
            let band = Box2::new(
                [
                    b.c[0] - b.ey[0] * (b.half[1] + 0.5 * depth),
                    b.c[1] - b.ey[1] * (b.half[1] + 0.5 * depth),
                ],
                o.yaw,
                [2.0 * b.half[0], depth],
                0.0,
                2.0,
            );
            for x in &l.objects {
                let related = spec.relations.iter().any(|r| {
                    (r.subject == x.id && r.object == o.id)
                        || (r.object == x.id && r.subject == o.id)
                });
                if !band_free || x.id == o.id || related || x.position[2] > 0.0 {
                    continue;
                }
                assert!(
                    overlap_depth(&Box2::of(x), &band) <= 0.05,
                    "{prompt} (seed {seed}): {} stands behind {}",
                    x.id,
                    o.id
                );
            }
        }
    }
}

#[test]
fn a_counter_asked_against_the_wall_stands_there() {
    let prompt = "a corner shop with a sales counter against the back wall and two display racks";
    for seed in SEEDS {
        let (l, _) = lay(prompt, seed);
        let o = l
            .objects
            .iter()
            .find(|o| o.category == "sales counter")
            .expect("a sales counter");
        let wd = wall_distances(&Box2::of(o), l.room.size);
        assert!(
            wd.iter().any(|&d| d <= 0.3),
            "{prompt} (seed {seed}): {} off the walls",
            o.id
        );
    }
}
