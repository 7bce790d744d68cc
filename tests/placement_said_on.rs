//! Where the text puts a thing, the layout puts it: what is said "on top" of a support or
//! together "on it" stands on that support (a sofa and a standard lamp on a stage, a bowl on a
//! sideboard), a small thing the knowledge base does not know fits the top it is put on (a cup
//! of tea on a little side table, the birthday cake on the table though never named before),
//! a default thing gives way on a small top to a named one, and
//! what the text hangs on a wall that its kind stands on the floor, or that the knowledge base
//! does not know, hangs there (guitars, a framed print, a neon sign) while furniture "on the
//! back wall" stands against it. Plan and layout only; prompts of no corpus.
mod common;
use common::placed::stands_on;
use dreamscene::plan::check::{wall_distances, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject};

fn laid_out(prompt: &str, seed: u64) -> Layout {
    let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
    layout(&p.spec, LayoutOptions::seeded(seed)).unwrap_or_else(|e| panic!("{prompt}: {e}"))
}

fn of<'a>(l: &'a Layout, cat: &str) -> Vec<&'a PlacedObject> {
    l.objects.iter().filter(|o| o.category == cat).collect()
}

#[test]
fn things_said_on_a_support_stand_on_it() {
    for (prompt, thing, support) in [
        (
            "a dining room with a sideboard with a fruit bowl on top and a large painting on the wall",
            "fruit bowl",
            "sideboard",
        ),
        (
            "a village hall with a stage at one end with a sofa and a standard lamp on it",
            "sofa",
            "stage",
        ),
        (
            "a village hall with a stage at one end with a sofa and a standard lamp on it",
            "floor lamp",
            "stage",
        ),
        (
            "a reading room with an armchair and a little side table with a mug of cocoa on it",
            "mug",
            "side table",
        ),
        (
            "a study with bookcases, a small side table with a vase on it and a leather armchair",
            "vase",
            "side table",
        ),
        (
            "a party room with one long table with eight chairs around it and the birthday cake on the table",
            "birthday cake",
            "dining table",
        ),
        (
            "a workshop with a workbench and the old typewriter on the workbench",
            "typewriter",
            "workbench",
        ),
        (
            "a library with a leather armchair, a little side table with a vase on it",
            "vase",
            "side table",
        ),
    ] {
        for seed in [0, 3] {
            let l = laid_out(prompt, seed);
            let sup = of(&l, support);
            let things = of(&l, thing);
            assert!(!things.is_empty(), "{prompt}: no {thing}");
            for t in things {
                assert!(
                    sup.iter().any(|s| stands_on(t, s)),
                    "{prompt} (seed {seed}): {} at {:?} is on no {support}",
                    t.id,
                    t.position
                );
            }
        }
    }
}

#[test]
fn things_said_to_hang_on_a_wall_hang_there() {
    for (prompt, thing) in [
        (
            "a music room with a piano, a drum kit and three guitars hanging on the wall",
            "guitar",
        ),
        (
            "a tiny toilet with a basin and a small framed print on the wall",
            "picture",
        ),
        (
            "a cocktail bar with a long counter, stools and a neon sign on the wall",
            "sign",
        ),
    ] {
        let l = laid_out(prompt, 0);
        let things = of(&l, thing);
        assert!(!things.is_empty(), "{prompt}: no {thing}");
        for t in things {
            let near = wall_distances(&Box2::of(t), l.room.size)
                .into_iter()
                .fold(f64::MAX, f64::min);
            assert!(
                t.position[2] > 0.5 && near < 0.05 && t.size[1] <= 0.3,
                "{prompt}: {} at {:?} ({:?}) does not hang on a wall ({near:.2} m off)",
                t.id,
                t.position,
                t.size
            );
        }
    }
    // furniture "on the back wall" stands against it, on the floor
    let l = laid_out(
        "a bakery with bread shelves on the back wall and a counter",
        0,
    );
    for t in of(&l, "bakery shelf") {
        assert_eq!(t.position[2], 0.0, "{}: {:?}", t.id, t.position);
    }
}
