//! Everyday prompts of places and phrasings no corpus has: plural names of several words, a
//! table that holds computers, a ship's bridge, "pairs of", what is said per instance of a
//! support whose count the reader works out, and places the knowledge base now knows (a post
//! office, a call centre, boarding kennels, a generic shop, a print shop, a dental surgery, a
//! wheelhouse); counted chairs, two-word numbers, misspelt nouns and ceiling lights over tables.
//! Prompts of no corpus.
#![allow(clippy::unwrap_used, reason = "tests")]
mod reading;
use dreamscene::plan::spec::{RelationKind, SceneSpec};
use reading::plan;

/// Instances of the categories whose name has `word` as a whole word.
fn number(spec: &SceneSpec, word: &str) -> u32 {
    spec.objects
        .iter()
        .filter(|(c, _)| c.split(' ').any(|w| w == word) || c.as_str() == word)
        .map(|(_, o)| o.number)
        .sum()
}

fn count(spec: &SceneSpec, category: &str) -> u32 {
    spec.objects.get(category).map_or(0, |o| o.number)
}

#[test]
fn a_plural_name_of_several_words_is_its_category() {
    let s = plan("a tailor's shop with four sewing machines on a long bench");
    assert_eq!(count(&s, "sewing machine"), 4, "{:?}", s.objects.keys());
    assert_eq!(count(&s, "machine"), 0, "{:?}", s.objects.keys());
    let on_bench = s
        .relations
        .iter()
        .filter(|r| r.subject.starts_with("sewing machine") && r.relation == RelationKind::Over)
        .count();
    assert_eq!(on_bench, 4, "{:?}", s.relations);
    let s = plan("a garage with two lawn mowers and a bike");
    assert_eq!(count(&s, "lawn mower"), 2, "{:?}", s.objects.keys());
}

#[test]
fn a_table_that_holds_computers_is_a_desk() {
    let s = plan("an IT support office with ten computers on tables");
    assert_eq!(count(&s, "dining table"), 0, "{:?}", s.objects.keys());
    assert!(count(&s, "desk") >= 5, "{:?}", s.objects.keys());
    assert_eq!(count(&s, "computer"), 10, "{:?}", s.objects.keys());
    // a table that holds what is not worked at stays a table
    for p in [
        "a dining room with a laptop on the table",
        "a kitchen with a laptop on the table",
    ] {
        let s = plan(p);
        assert_eq!(count(&s, "desk"), 0, "{p}: {:?}", s.objects.keys());
    }
    let s = plan("a dining room with a vase of tulips on the table");
    assert_eq!(count(&s, "desk"), 0, "{:?}", s.objects.keys());
    assert!(number(&s, "table") >= 1, "{:?}", s.objects.keys());
}

#[test]
fn what_is_said_per_support_follows_the_supports_count() {
    let s = plan("a call center with thirty laptops on tables and a chair at each one");
    let desks = count(&s, "desk");
    assert!(desks >= 15, "{:?}", s.objects);
    assert_eq!(count(&s, "laptop"), 30, "{:?}", s.objects);
    // a chair at each of them (the room may have its own chair besides, a teacher's)
    assert!(number(&s, "chair") >= desks, "{:?}", s.objects);
}

#[test]
fn a_ships_bridge_is_the_bridge_scene() {
    for p in [
        "the bridge of the ship, with a captain's chair and two consoles",
        "a ship's bridge with two consoles and a captain's chair",
    ] {
        let s = plan(p);
        assert_eq!(number(&s, "bridge"), 0, "{p}: {:?}", s.objects.keys());
        assert_eq!(number(&s, "console"), 2, "{p}: {:?}", s.objects.keys());
        assert_eq!(number(&s, "captain"), 1, "{p}: {:?}", s.objects.keys());
    }
}

#[test]
fn pairs_of_things_are_two_each() {
    let s = plan("a home gym with two pairs of treadmills and a bench");
    assert_eq!(count(&s, "treadmill"), 4, "{:?}", s.objects);
    assert_eq!(number(&s, "pair"), 0, "{:?}", s.objects.keys());
}

#[test]
fn new_places_are_their_own_scenes() {
    let s = plan("a post office with three counters");
    assert_eq!(count(&s, "counter"), 3, "{:?}", s.objects);
    assert_eq!(
        number(&s, "whiteboard") + number(&s, "desk"),
        0,
        "{:?}",
        s.objects
    );
    let s = plan("a contact center for customer support");
    assert!(
        count(&s, "computer") >= 1 && count(&s, "desk") >= 1,
        "{:?}",
        s.objects
    );
    // the crates of kennels are its dog crates
    let s = plan("dog kennels with eight crates");
    assert_eq!(count(&s, "dog crate"), 8, "{:?}", s.objects);
    assert_eq!(number(&s, "crate"), 8, "{:?}", s.objects);
}

/// A prompt whose first line starts with a hyphen (a pasted dialogue) is a prompt, not an option.
#[test]
fn a_prompt_may_start_with_a_hyphen() {
    let exe = env!("CARGO_BIN_EXE_dreamscene");
    let dir = std::env::temp_dir().join(format!("dreamscene-hyphen-{}", std::process::id()));
    let out = std::process::Command::new(exe)
        .args(["plan", "- a small kitchen\n- with a fridge", "--out"])
        .arg(&dir)
        .env_remove("DREAMSCENE_LLM_URL")
        .env_remove("OPENAI_API_KEY")
        .env_remove("DREAMSCENE_MODELS")
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let spec = SceneSpec::read(&dir.join("spec.json")).unwrap();
    assert_eq!(spec.objects.get("refrigerator").map(|o| o.number), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

/// "Desks for twelve people": things that seat one each, said with how many people and no count,
/// are one per person.
#[test]
fn things_for_one_said_for_people_are_one_each() {
    let s = plan("an open plan office with desks for twelve people");
    assert_eq!(count(&s, "desk"), 12, "{:?}", s.objects);
    assert!(count(&s, "office chair") <= 13, "{:?}", s.objects);
    // a table for several keeps seating them each
    let s = plan("a canteen with tables for four");
    assert!(
        number(&s, "chair") >= 4 * number(&s, "table").max(1),
        "{:?}",
        s.objects
    );
}

#[test]
fn a_shop_of_no_known_kind_sells_no_clothes() {
    for p in [
        "a shoe store with a bench and three shelves",
        "a music shop with four guitars and a counter",
        "a copy shop with two large printers and a counter",
    ] {
        let s = plan(p);
        assert_eq!(
            number(&s, "mannequin") + number(&s, "clothes"),
            0,
            "{p}: {:?}",
            s.objects.keys()
        );
        assert_eq!(number(&s, "counter"), 1, "{p}: {:?}", s.objects.keys());
    }
    let s = plan("a copy shop with two large printers and a counter");
    assert_eq!(count(&s, "large format printer"), 2, "{:?}", s.objects);
    let s = plan("a fashion shop with two mirrors");
    assert!(number(&s, "clothes") >= 1, "{:?}", s.objects.keys());
}

#[test]
fn counted_chairs_are_all_the_chairs() {
    let s = plan("a nail bar with four manicure tables and eight chairs");
    assert_eq!(number(&s, "chair"), 8, "{:?}", s.objects);
    // the teacher's chair serves the teacher's desk, not the pupils' desks
    let s = plan("a classroom with 20 desks and 20 chairs");
    assert_eq!(number(&s, "chair"), 21, "{:?}", s.objects);
    // a pub's pool table is no table its customers sit at
    let s = plan("a pub with four tables and sixteen chairs");
    assert_eq!(count(&s, "pool table"), 1, "{:?}", s.objects);
    assert_eq!(number(&s, "chair"), 16, "{:?}", s.objects);
}

#[test]
fn numbers_of_two_words_count() {
    let s = plan("a classroom with thirty two desks and a blackboard");
    assert_eq!(count(&s, "school desk"), 32, "{:?}", s.objects);
    let s = plan("a banquet hall with twenty-one round tables");
    assert_eq!(count(&s, "round banquet table"), 21, "{:?}", s.objects);
}

#[test]
fn a_misspelt_noun_is_the_thing_it_almost_names() {
    let s = plan("a living room with a sofa, a bookcsae and an armchiar");
    assert_eq!(count(&s, "bookshelf"), 1, "{:?}", s.objects.keys());
    assert_eq!(count(&s, "armchair"), 1, "{:?}", s.objects.keys());
    // short real words stay themselves: a broom is no brook, a shell no shelf
    let s = plan("a witch's hut with a broom, a shell and a cauldron");
    assert_eq!(
        number(&s, "stream") + number(&s, "shelf"),
        0,
        "{:?}",
        s.objects.keys()
    );
}

#[test]
fn a_light_hung_over_a_table_lights_the_table_alone() {
    let s = plan("a small dining table beneath a chandelier with four chairs around it");
    let under = |subject: &str| {
        s.relations
            .iter()
            .any(|r| r.subject.starts_with(subject) && r.relation == RelationKind::Under)
    };
    assert!(under("dining table"), "{:?}", s.relations);
    assert!(!under("dining chair"), "{:?}", s.relations);
    // the seats of a table under a parasol are under it too
    let s = plan("a patio table under a parasol with four chairs");
    let sheltered = s
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Under && r.subject.contains("chair"))
        .count();
    assert_eq!(sheltered, 4, "{:?}", s.relations);
}

#[test]
fn sinks_wheels_and_reception_desks_are_those_of_the_place() {
    let s = plan("a barber shop with two sinks");
    assert_eq!(count(&s, "salon sink"), 2, "{:?}", s.objects.keys());
    let s = plan("a dental clinic with two dental chairs and a sink");
    assert_eq!(number(&s, "kitchen"), 0, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "sink"), 1, "{:?}", s.objects.keys());
    let s = plan("the wheelhouse of a fishing boat with a wheel and a radar screen");
    assert_eq!(count(&s, "ship wheel"), 1, "{:?}", s.objects.keys());
    let s = plan("a clinic waiting room with a reception desk and eight chairs");
    assert_eq!(number(&s, "reception"), 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "counter"), 0, "{:?}", s.objects.keys());
    let s = plan("a lakeside with two canoes and a jetty");
    assert_eq!(count(&s, "canoe"), 2, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "boat"), 0, "{:?}", s.objects.keys());
}
