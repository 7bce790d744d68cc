//! Things hung on a wall asked "in a row" hang in a run along the walls at their height (each beside
//! the one before; a long run may turn a corner), never in
//! rows standing on the floor; things hung from the ceiling asked in a row hang from it. Prompts of
//! no corpus, over three seeds. A thing under one hung on a wall (a sink under a mirror) holds
//! that relation.
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject};

fn lay(prompt: &str, seed: u64) -> Layout {
    let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
    layout(&p.spec, LayoutOptions::seeded(seed)).unwrap_or_else(|e| panic!("{prompt}: {e}"))
}

fn of<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category)
        .collect()
}

#[test]
fn wall_things_in_a_row_hang_in_a_run_each_beside_the_one_before() {
    for (prompt, cat, n) in [
        (
            "a teenager's bedroom with four posters in a row on the wall",
            "poster",
            4,
        ),
        ("a dorm room with a row of five posters", "poster", 5),
        ("a hallway with three paintings in a row", "painting", 3),
    ] {
        for seed in 0..3 {
            let l = lay(prompt, seed);
            let hung = of(&l, cat);
            assert_eq!(hung.len(), n, "{prompt}");
            let at = |o: &PlacedObject| format!("{:?}", o.position);
            for o in &hung {
                assert!(
                    o.position[2] > 0.5,
                    "{prompt} seed {seed}: {} at {}",
                    o.id,
                    at(o)
                );
            }
            // a run: each beside the one before (a long run may turn a corner)
            let mut ids: Vec<&&PlacedObject> = hung.iter().collect();
            ids.sort_by_key(|o| o.id.trim_start_matches(cat).parse::<u32>().unwrap_or(0));
            for w in ids.windows(2) {
                let (a, b) = (w[0].position, w[1].position);
                let gap = (a[0] - b[0]).hypot(a[1] - b[1]);
                assert!(
                    gap <= w[0].size[0] + 0.6,
                    "{prompt} seed {seed}: {} {} {:.2} m apart",
                    w[0].id,
                    w[1].id,
                    gap
                );
            }
        }
    }
}

#[test]
fn ceiling_things_in_a_row_hang_from_the_ceiling() {
    for prompt in [
        "a bar with a row of four pendant lights",
        "a kitchen with three pendant lights in a row",
    ] {
        for seed in 0..3 {
            let l = lay(prompt, seed);
            let lights = of(&l, "pendant light");
            assert!(lights.len() >= 3, "{prompt}");
            for o in lights {
                assert!(
                    o.position[2] > 1.5,
                    "{prompt} seed {seed}: {} {:?}",
                    o.id,
                    o.position
                );
            }
        }
    }
}

#[test]
fn a_thing_under_one_hung_on_the_wall_holds_its_relation() {
    for prompt in [
        "a bathroom with a sink under a mirror, a toilet and a bathtub",
        "a bathroom with a mirror above the sink",
        "a hallway with a console table under a mirror",
    ] {
        for seed in 0..3 {
            let l = lay(prompt, seed);
            assert!(
                l.unsatisfied.is_empty(),
                "{prompt} seed {seed}: {:?}",
                l.unsatisfied
            );
            let mirror = of(&l, "mirror");
            assert_eq!(mirror.len(), 1, "{prompt}");
            assert!(
                mirror[0].placed_by == dreamscene::plan::spec::PlacedBy::Constraint,
                "{prompt} seed {seed}: the mirror by fallback"
            );
        }
    }
}
