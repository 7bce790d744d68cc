//! Where things hung from the ceiling hang (issue 23's look, the placement of lights): one said
//! to hang over a thing hangs centred over it from the ceiling, several in an even row along
//! it; one said to hang nowhere hangs over the room's main piece or in the middle; several
//! spread evenly, clear of the walls. The prompts were written for these tests, not tuned on.
use dreamscene::plan::check::ceiling::{hangs_from_ceiling, hangs_over};
use dreamscene::plan::check::{validity_problems, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject, RelationKind};

const HUNG: [&str; 4] = [
    "chandelier",
    "pendant light",
    "ceiling light",
    "ceiling fan",
];

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> Layout {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    l
}

/// The things of `category` or a kind of it ("bed": a king size bed).
fn all<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category || o.category.ends_with(&format!(" {category}")))
        .collect()
}

fn hung(l: &Layout) -> Vec<&PlacedObject> {
    l.objects
        .iter()
        .filter(|o| HUNG.contains(&o.category.as_str()))
        .collect()
}

fn dist(a: &PlacedObject, b: &PlacedObject) -> f64 {
    (a.position[0] - b.position[0]).hypot(a.position[1] - b.position[1])
}

#[test]
fn a_ceiling_thing_said_to_hang_over_a_thing_hangs_centred_over_it() {
    for (prompt, thing, below) in [
        (
            "a games room with a pool table and a chandelier hanging over the pool table",
            "chandelier",
            "pool table",
        ),
        (
            "a farmhouse dining room with a dining table for eight and a pendant light above it",
            "pendant light",
            "dining table",
        ),
        // said the other way round: the table under the chandelier
        (
            "a games room with a chandelier and a pool table under it",
            "chandelier",
            "pool table",
        ),
        (
            "a loft kitchen with a kitchen island, bar stools and four pendant lights over the island",
            "pendant light",
            "kitchen island",
        ),
    ] {
        let l = lay(prompt, 1);
        let under = all(&l, below);
        let things = all(&l, thing);
        assert!(!things.is_empty() && !under.is_empty(), "{prompt}: {l:?}");
        for t in &things {
            assert!(
                under
                    .iter()
                    .any(|u| hangs_over(&Box2::of(t), &Box2::of(u), l.room.size)),
                "{prompt}: {} at {:?} does not hang over a {below}",
                t.id,
                t.position
            );
        }
        // several: an even row along it
        if things.len() > 2 {
            let mut c: Vec<[f64; 2]> = things
                .iter()
                .map(|t| [t.position[0], t.position[1]])
                .collect();
            c.sort_by(|a, b| (a[0] + a[1]).total_cmp(&(b[0] + b[1])));
            let steps: Vec<f64> = c
                .windows(2)
                .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
                .collect();
            let (lo, hi) = steps
                .iter()
                .fold((f64::INFINITY, 0.0_f64), |a, &s| (a.0.min(s), a.1.max(s)));
            assert!(
                hi - lo <= 0.05 && lo >= 0.3,
                "{prompt}: uneven row, steps {steps:?}"
            );
        }
    }
}

#[test]
fn a_lone_ceiling_thing_hangs_over_the_main_piece_or_the_middle() {
    for (prompt, main) in [
        (
            "a master bedroom with a king size bed, a dresser and a ceiling fan",
            Some("bed"),
        ),
        (
            "a dining room with a table for six and a crystal chandelier",
            Some("dining table"),
        ),
        (
            "a home office with a desk, a bookcase and a ceiling light",
            None,
        ),
    ] {
        let l = lay(prompt, 2);
        let h = hung(&l);
        assert_eq!(h.len(), 1, "{prompt}: {h:?}");
        let t = h[0];
        assert!(
            hangs_from_ceiling(&Box2::of(t), l.room.size),
            "{prompt}: {} at {:?} does not hang clear of the walls",
            t.id,
            t.position
        );
        match main {
            Some(m) => assert!(
                all(&l, m)
                    .iter()
                    .any(|u| hangs_over(&Box2::of(t), &Box2::of(u), l.room.size)),
                "{prompt}: {} at {:?} is not over the {m}",
                t.id,
                t.position
            ),
            None => {
                // nothing is gathered at a desk by a wall: the middle of the room
                let off = t.position[0].hypot(t.position[1]);
                assert!(
                    off <= 0.3,
                    "{prompt}: {} is {off:.2} m off the middle",
                    t.id
                );
            }
        }
    }
}

#[test]
fn several_ceiling_things_spread_evenly_clear_of_the_walls() {
    for prompt in [
        "a gym with six treadmills, a weight bench and six ceiling lights",
        "a classroom with a teacher desk, sixteen school desks and four ceiling fans",
        "a bistro with eight small tables, chairs and five pendant lights",
    ] {
        let l = lay(prompt, 0);
        let h = hung(&l);
        assert!(h.len() >= 4, "{prompt}: {h:?}");
        for t in &h {
            assert!(
                hangs_from_ceiling(&Box2::of(t), l.room.size),
                "{prompt}: {} at {:?} does not hang clear of the walls",
                t.id,
                t.position
            );
        }
        // evenly: each one's nearest neighbour about as far as any other's
        let nearest: Vec<f64> = h
            .iter()
            .map(|a| {
                h.iter()
                    .filter(|b| b.id != a.id)
                    .map(|b| dist(a, b))
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        let (lo, hi) = nearest
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |a, &s| (a.0.min(s), a.1.max(s)));
        assert!(
            lo >= 0.6 && hi <= 1.6 * lo,
            "{prompt}: not spread evenly, nearest neighbours {nearest:?}"
        );
    }
}

#[test]
fn over_before_a_count_is_more_than_not_above() {
    for (prompt, counted) in [
        ("a conference hall with a stage and over 40 chairs", "chair"),
        (
            "a cafe with a counter and over a dozen small tables",
            "table",
        ),
    ] {
        let plan = plan_prompt(prompt).expect("planned");
        let on: Vec<_> = plan
            .spec
            .relations
            .iter()
            .filter(|r| r.relation == RelationKind::Over && r.object.contains(counted))
            .collect();
        assert!(on.is_empty(), "{prompt}: {on:?}");
    }
}

#[test]
fn a_light_hung_over_no_named_piece_leaves_head_room_below_it() {
    // people walk under it: its bottom at 2 m or higher, still touching the ceiling
    for prompt in [
        "a bedroom with a pendant light",
        "a hallway with two hanging lamps",
        "a study with a desk and a pendant lamp",
    ] {
        for seed in 0..2 {
            let l = lay(prompt, seed);
            let lights = hung(&l);
            assert!(!lights.is_empty(), "{prompt}: no hung light");
            for o in lights {
                let b = Box2::of(o);
                assert!(
                    b.z0 >= 2.0 - 1e-6,
                    "{prompt}: {} hangs down to {:.2} m",
                    o.id,
                    b.z0
                );
                assert!(
                    hangs_from_ceiling(&b, l.room.size),
                    "{prompt}: {} off the ceiling",
                    o.id
                );
            }
        }
    }
}
