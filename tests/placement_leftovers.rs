//! Placement leftovers of the own placement set: a shoe cabinet is a closed cabinet against the
//! wall (not an open shoe rack); a monitor is a monitor on its desk (not a desktop computer), and
//! the monitors the text names are the desks' screens, none added beside them; a game table the
//! text names is the games room's game table, no other game table added around it.
use dreamscene::plan::check::{gap, validity_problems, wall_distances, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject, SceneSpec};

const SEEDS: [u64; 3] = [0, 1, 2];

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

fn all<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category)
        .collect()
}

fn count(s: &SceneSpec, category: &str) -> u32 {
    s.objects.get(category).map_or(0, |o| o.number)
}

/// `thing` rests on `support`'s top with its centre over `support`'s footprint.
fn on(thing: &PlacedObject, support: &PlacedObject) -> bool {
    let b = Box2::of(support);
    let (x, y) = (thing.position[0], thing.position[1]);
    let top = support.position[2] + support.size[2];
    (thing.position[2] - top).abs() < 0.05 && b.contains([x, y])
}

#[test]
fn a_shoe_cabinet_is_a_cabinet_against_the_wall() {
    for prompt in [
        "an entryway with a shoe cabinet by the door and a coat stand",
        "a mudroom with a tall shoe cupboard and a bench",
        "a small hall with a white shoe cabinet, a mirror and an umbrella stand",
    ] {
        for seed in SEEDS {
            let (l, s) = lay(prompt, seed);
            assert_eq!(
                count(&s, "shoe cabinet"),
                1,
                "{prompt}: {:?}",
                s.objects.keys()
            );
            assert_eq!(count(&s, "shoe rack"), 0, "{prompt}: a shoe rack beside it");
            for c in all(&l, "shoe cabinet") {
                let wd = wall_distances(&Box2::of(c), l.room.size);
                let near = wd.iter().cloned().fold(f64::INFINITY, f64::min);
                assert!(
                    near <= 0.3,
                    "{prompt} (seed {seed}): {} {near:.2} m off the wall",
                    c.id
                );
            }
        }
    }
}

#[test]
fn named_monitors_are_monitors_on_the_desks() {
    for (prompt, n, desk) in [
        (
            "a study with a standing desk and two monitors on it",
            2,
            "standing desk",
        ),
        ("an office with four desks, each with a monitor", 4, "desk"),
        (
            "a computer room with six lab desks in two rows and a monitor on every desk",
            6,
            "lab desk",
        ),
    ] {
        for seed in SEEDS {
            let (l, s) = lay(prompt, seed);
            assert_eq!(count(&s, "monitor"), n, "{prompt}: {:?}", s.objects.keys());
            assert_eq!(
                count(&s, "computer"),
                0,
                "{prompt}: computers beside the monitors"
            );
            let desks = all(&l, desk);
            for m in all(&l, "monitor") {
                assert!(
                    desks.iter().any(|d| on(m, d)),
                    "{prompt} (seed {seed}): {} at {:?} is on no {desk}",
                    m.id,
                    m.position
                );
            }
        }
    }
}

#[test]
fn a_named_game_table_is_the_game_rooms_table() {
    let game_tables = [
        "pool table",
        "ping pong table",
        "poker table",
        "foosball table",
        "air hockey table",
    ];
    for (prompt, named, seats) in [
        (
            "a rec room with a card table and six stools round it",
            "poker table",
            6,
        ),
        (
            "a games room with an air hockey table and a sofa",
            "air hockey table",
            0,
        ),
        (
            "a recreation room with a foosball table by the wall and a tv",
            "foosball table",
            0,
        ),
    ] {
        for seed in SEEDS {
            let (l, s) = lay(prompt, seed);
            for t in game_tables {
                let want = u32::from(t == named);
                assert_eq!(
                    count(&s, t),
                    want,
                    "{prompt}: {t} in {:?}",
                    s.objects.keys()
                );
            }
            if seats > 0 {
                let table = all(&l, named)[0];
                let b = Box2::of(table);
                let near = all(&l, "stool")
                    .into_iter()
                    .filter(|o| gap(&b, &Box2::of(o)) <= 0.5)
                    .count();
                assert_eq!(near, seats, "{prompt} (seed {seed}): stools at the {named}");
            }
        }
    }
}

#[test]
fn a_lab_of_benches_in_rows_is_laid_out_with_a_microscope_for_each_of_its_benches() {
    // the lab's microscopes spread over its benches, one each, rather than one on the first
    // and the rest left to find a bench among the rows (which refused the plan)
    for prompt in [
        "biology lab with 6 lab benches in 2 rows of 3 and a fume cupboard against the wall",
        "a school laboratory: eight lab benches in two rows of four, a whiteboard on the front wall",
    ] {
        let plan = dreamscene::plan::offline::plan_prompt(prompt)
            .unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let spec = &plan.spec;
        let n = spec.objects.get("microscope").map_or(0, |o| o.number);
        let on = spec
            .relations
            .iter()
            .filter(|r| r.subject.starts_with("microscope") && r.object.starts_with("science bench"))
            .count();
        assert_eq!(on as u32, n, "{prompt}: {:?}", spec.relations);
        let l = dreamscene::plan::gcp::layout(spec, dreamscene::plan::gcp::LayoutOptions::seeded(0))
            .unwrap_or_else(|e| panic!("{prompt}: {e}"));
        assert!(dreamscene::plan::check::validity_problems(&l, spec).is_empty(), "{prompt}");
    }
}
