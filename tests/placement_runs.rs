//! Runs and trimming: a place's repeated machines stand in a run along its walls, each beside
//! the one before (a laundromat's washers, not one per wall); a studio's stove and fridge stand
//! beside its kitchen counter; a hotel lobby's armchairs at its coffee tables; a room the text
//! calls tiny loses a large optional piece (an office's conference table) before one of many
//! desks; a cramped kitchen whose things stand against its walls is sized for them in a run; a
//! dryer the text puts against the wall still stands beside the washer there.
use dreamscene::plan::check::{gap, validity_problems, wall_distances, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, RelationKind, SceneSpec};

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

fn boxed(l: &Layout, id: &str) -> Box2 {
    Box2::of(l.objects.iter().find(|o| o.id == id).expect("placed"))
}

/// The least gap from `id` to any instance of `category`.
fn gap_to(l: &Layout, id: &str, category: &str) -> f64 {
    let b = boxed(l, id);
    l.objects
        .iter()
        .filter(|o| o.category == category && o.id != id)
        .map(|o| gap(&b, &Box2::of(o)))
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn a_laundromats_machines_stand_in_runs_along_its_walls() {
    for prompt in [
        "a laundromat",
        "a launderette with eight washing machines",
        "a coin laundry with six washers and four dryers",
    ] {
        let spec = plan_prompt(prompt).expect("planned").spec;
        for cat in ["washing machine", "dryer"] {
            let n = spec.objects.get(cat).map_or(0, |o| o.number);
            assert!(n >= 2, "{prompt}: {n} {cat}");
            // each beside the one before, in the spec
            for k in 2..=n {
                assert!(
                    spec.relations
                        .iter()
                        .any(|r| r.relation == RelationKind::Next
                            && r.subject == format!("{cat}{k}")
                            && r.object == format!("{cat}{}", k - 1)),
                    "{prompt}: {cat}{k} not beside {cat}{}",
                    k - 1
                );
            }
        }
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            for o in l
                .objects
                .iter()
                .filter(|o| o.category == "washing machine" || o.category == "dryer")
            {
                let b = Box2::of(o);
                let wall = wall_distances(&b, l.room.size)
                    .into_iter()
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    wall <= 0.3,
                    "{prompt} seed {seed}: {} {wall:.2} m off the wall",
                    o.id
                );
                // beside another machine of the run
                let near = gap_to(&l, &o.id, "washing machine").min(gap_to(&l, &o.id, "dryer"));
                assert!(
                    near <= 0.5,
                    "{prompt} seed {seed}: {} alone ({near:.2} m)",
                    o.id
                );
            }
        }
    }
}

#[test]
fn a_studios_stove_and_fridge_stand_beside_its_counter() {
    for prompt in [
        "a studio flat",
        "a studio apartment",
        "a bedsit with a sofa bed",
    ] {
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            for id in ["stove1", "refrigerator1"] {
                let g = gap_to(&l, id, "kitchen counter");
                assert!(
                    g <= 0.5,
                    "{prompt} seed {seed}: {id} {g:.2} m from the counter"
                );
            }
        }
    }
}

#[test]
fn a_lobbys_armchairs_sit_at_its_coffee_tables() {
    for prompt in [
        "a hotel lobby",
        "a hotel reception area with a front desk",
        "a grand hotel lobby with a chandelier",
    ] {
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            let chairs: Vec<String> = l
                .objects
                .iter()
                .filter(|o| o.category == "armchair")
                .map(|o| o.id.clone())
                .collect();
            assert!(!chairs.is_empty(), "{prompt}: no armchair");
            for id in chairs {
                let g = gap_to(&l, &id, "coffee table");
                assert!(
                    g <= 0.5,
                    "{prompt} seed {seed}: {id} {g:.2} m from a coffee table"
                );
            }
        }
    }
}

#[test]
fn a_tiny_office_loses_its_conference_table_before_its_desks() {
    for prompt in ["a tiny office", "a cramped office", "a tiny startup office"] {
        let spec = plan_prompt(prompt).expect("planned").spec;
        assert!(
            !spec.objects.contains_key("conference table"),
            "{prompt}: {:?}",
            spec.objects.keys()
        );
        let desks = spec.objects.get("desk").map_or(0, |o| o.number);
        assert!(desks >= 2, "{prompt}: {desks} desks");
    }
    // an office of ordinary size keeps it
    let spec = plan_prompt("an office").expect("planned").spec;
    assert!(spec.objects.contains_key("conference table"));
}

#[test]
fn a_cramped_kitchen_is_sized_for_its_runs() {
    for (prompt, most) in [
        (
            "galley kitchen, quite cramped, counters down both sides, fridge at the far end and no dishwasher",
            12.0,
        ),
        ("a cramped kitchen with two counters and a fridge", 12.0),
        ("a tiny kitchen with a counter, a sink and a fridge", 10.0),
    ] {
        let (l, _) = lay(prompt, 0);
        let area = l.room.size[0] * l.room.size[1];
        assert!(area <= most, "{prompt}: {area:.2} m² > {most}");
        for o in l.objects.iter().filter(|o| o.category.contains("counter")) {
            let wall = wall_distances(&Box2::of(o), l.room.size)
                .into_iter()
                .fold(f64::INFINITY, f64::min);
            assert!(wall <= 0.3, "{prompt}: {} {wall:.2} m off the wall", o.id);
        }
    }
}

#[test]
fn a_dryer_said_against_the_wall_still_stands_beside_the_washer() {
    for prompt in [
        "a laundry room with a washing machine and a dryer side by side against the wall",
        "a utility room with a washer and a tumble dryer against the wall",
        "a laundry with a dryer and a washing machine along the wall and a laundry basket",
    ] {
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            let g = gap_to(&l, "dryer1", "washing machine");
            assert!(
                g <= 0.5,
                "{prompt} seed {seed}: dryer {g:.2} m from the washer"
            );
        }
    }
}
