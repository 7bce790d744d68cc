//! Names everyday prompts use for known things, once read as an unknown box or as the wrong
//! thing: a hob is a cooktop (a kind of stove), a waiter station a service sideboard, a
//! pied-à-terre a small flat (the place, never a thing in it), a desk lamp a task lamp of its own
//! (not a bedside table lamp). And a thing set on a table stands on a table of the scene that
//! fills the role of its supports when none of them is there (a printer on a lab's science
//! benches, a globe on a librarian's desk), not on the floor. Plan and layout only, cheap in debug.
mod common;
mod reading;
use common::placed::{all, lay, SEEDS};
use reading::{keys, plan};

/// Every prompt's plan holds `want` and no category containing any of `not`.
fn reads(prompts: &[&str], want: &str, not: &[&str]) {
    for prompt in prompts {
        let spec = plan(prompt);
        assert!(
            spec.objects.contains_key(want),
            "{prompt}: no {want}: {:?}",
            keys(&spec)
        );
        for n in not {
            assert!(
                !spec.objects.keys().any(|c| c.contains(n)),
                "{prompt}: {n}: {:?}",
                keys(&spec)
            );
        }
    }
}

#[test]
fn a_hob_is_a_stove() {
    reads(
        &[
            "a galley kitchen with a gas hob, a sink and a tall fridge",
            "a narrow flat with an induction hob beside the kitchen counter",
        ],
        "stove",
        &["hob"],
    );
}

#[test]
fn a_waiter_station_is_a_sideboard() {
    reads(
        &[
            "a bistro with six small tables and a waiter's station near the bar",
            "a hotel breakfast room with a waiter station against the back wall",
        ],
        "sideboard",
        &["station"],
    );
}

#[test]
fn a_pied_a_terre_is_the_place_not_a_thing() {
    for prompt in [
        "a tiny pied-à-terre in Rome with a sofa and a writing desk",
        "a bright pied-a-terre with a double bed and an armchair",
    ] {
        let spec = plan(prompt);
        assert!(
            !spec
                .objects
                .keys()
                .any(|c| c.contains("pied") || c.contains("terre")),
            "{prompt}: {:?}",
            keys(&spec)
        );
    }
}

#[test]
fn a_desk_lamp_is_a_task_lamp_on_the_desk() {
    reads(
        &[
            "a home office with a desk and an anglepoise lamp on it",
            "a student room: a desk with a desk lamp and a laptop",
        ],
        "task lamp",
        &["table lamp"],
    );
}

#[test]
fn tabletop_things_stand_on_a_table_of_the_role_of_their_supports() {
    for (prompt, thing, under) in [
        (
            "a chemistry lab with three science benches and a printer",
            "printer",
            "science bench",
        ),
        (
            "a quiet archive room with a librarian's desk, a globe and two filing cabinets",
            "globe",
            "librarian desk",
        ),
    ] {
        for seed in SEEDS {
            let (l, _) = lay(prompt, seed);
            let things = all(&l, thing);
            assert!(!things.is_empty(), "{prompt}: no {thing}");
            for o in things {
                let on = all(&l, under).into_iter().any(|u| {
                    let (dx, dy) = (o.position[0] - u.position[0], o.position[1] - u.position[1]);
                    let reach = 0.5 * u.size[0].max(u.size[1]);
                    (o.position[2] - u.size[2]).abs() < 0.05 && dx.hypot(dy) < reach
                });
                assert!(on, "{prompt} seed {seed}: {thing} not on a {under}: {o:?}");
            }
        }
    }
}
