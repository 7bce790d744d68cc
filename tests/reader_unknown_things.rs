//! Things the knowledge base does not know, said the way people say them: with no article
//! ("a changing table with wipes on it", "with jam and scones on it"), after a possessive
//! ("my sewing kit on the dresser", "his toolbox on the workbench"), or at the end of a clause
//! ("a side table with her crossword on"), become things when the text puts them on a thing it
//! names or hangs them on a wall; a noun before an unknown head names its kind with it ("a
//! label maker", "a tape gun"; a material only describes it). Whom or what a place is for
//! ("a bedroom for my three girls", "a hall for a charity auction") adds nothing. Plan and
//! layout only; prompts of no corpus.
mod common;
use common::placed::{lay, stands_on};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject};

/// `prompt` planned and laid out on seed 0, with no validity problem.
fn laid_out(prompt: &str) -> Layout {
    lay(prompt, 0).0
}

fn named<'a>(l: &'a Layout, word: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category.split(' ').any(|w| w == word))
        .collect()
}

#[test]
fn unknown_things_put_on_a_named_thing_stand_on_it() {
    for (prompt, thing, support) in [
        (
            "a nursery with a cot, a changing table with wipes on it and a rocking chair",
            "wipe",
            "changing table",
        ),
        (
            "a tea room with a counter with jam and scones on it and four little tables",
            "jam",
            "counter",
        ),
        (
            "a tea room with a counter with jam and scones on it and four little tables",
            "scone",
            "counter",
        ),
        (
            "a spare room with a dresser and my sewing kit on the dresser",
            "kit",
            "dresser",
        ),
        (
            "a garage with a workbench, his toolbox on the workbench and a bike",
            "toolbox",
            "workbench",
        ),
        (
            "a sitting room with an armchair by the fire and a side table with her crossword on, and a clock",
            "crossword",
            "side table",
        ),
    ] {
        let l = laid_out(prompt);
        let things = named(&l, thing);
        let sups = named(&l, support.rsplit(' ').next().unwrap());
        assert!(!things.is_empty(), "{prompt}: no {thing}: {:?}", l.objects.iter().map(|o| &o.id).collect::<Vec<_>>());
        for t in &things {
            assert!(
                sups.iter().any(|s| stands_on(t, s)),
                "{prompt}: {} is not on a {support}",
                t.id
            );
        }
    }
}

#[test]
fn unknown_things_hung_on_a_wall_hang() {
    for (prompt, thing) in [
        (
            "a museum gallery with display cases and information boards on the walls",
            "board",
        ),
        (
            "a gym with treadmills, a rowing machine and motivational posters on the wall",
            "poster",
        ),
        (
            "a shop with a counter and our shop logo on the back wall",
            "logo",
        ),
    ] {
        let l = laid_out(prompt);
        let things = named(&l, thing);
        assert!(!things.is_empty(), "{prompt}: no {thing}");
        for t in things {
            assert!(
                t.position[2] > 0.5,
                "{prompt}: {} stands at z={}",
                t.id,
                t.position[2]
            );
        }
    }
}

#[test]
fn a_noun_before_an_unknown_head_names_its_kind() {
    for (prompt, category) in [
        (
            "a post room with a sorting table and a label maker",
            "label maker",
        ),
        (
            "a packing station with a long bench and a tape gun on it",
            "tape gun",
        ),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert!(
            p.spec.objects.contains_key(category),
            "{prompt}: no {category} in {:?}",
            p.spec.objects.keys().collect::<Vec<_>>()
        );
    }
    // a material or colour describes the thing it is said of; it is no kind of it
    let p = plan_prompt("a garden with a bronze gong and a lawn").expect("gong");
    assert!(
        p.spec.objects.contains_key("gong"),
        "{:?}",
        p.spec.objects.keys().collect::<Vec<_>>()
    );
}

#[test]
fn whom_or_what_a_place_is_for_and_unplaced_bare_words_add_nothing() {
    for (prompt, word) in [
        (
            "a bedroom for my three girls with a bunk bed and a single bed",
            "girl",
        ),
        (
            "a village hall for a charity auction with rows of chairs and a lectern",
            "auction",
        ),
        (
            "a study with sunlight and bookshelves and a desk",
            "sunlight",
        ),
        ("a kitchen with storage and an island", "storage"),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert!(
            !p.spec
                .objects
                .keys()
                .any(|c| c.split(' ').any(|w| w.trim_end_matches('s') == word)),
            "{prompt}: {word} became a thing: {:?}",
            p.spec.objects.keys().collect::<Vec<_>>()
        );
    }
}
