//! What a placement phrase refers to when it names no object: a pronoun ("above it": the thing
//! named before its subject and what is said with it) or a part of an object ("facing the fire":
//! the fireplace), and seats said of each side of a table. None of these prompts is in a corpus.
mod reading;
use dreamscene::plan::spec::{RelationKind, SceneSpec};
use reading::plan;

/// The relation kinds `spec` has between an instance of `subject` and one of `object`
/// (categories).
fn between(spec: &SceneSpec, subject: &str, object: &str) -> Vec<RelationKind> {
    let of = |id: &str, c: &str| id.trim_end_matches(|ch: char| ch.is_ascii_digit()) == c;
    spec.relations
        .iter()
        .filter(|r| of(&r.subject, subject) && of(&r.object, object))
        .map(|r| r.relation)
        .collect()
}

fn number(spec: &SceneSpec, c: &str) -> u32 {
    spec.objects.get(c).map_or(0, |o| o.number)
}

#[test]
fn a_pronoun_names_the_thing_before_its_subject() {
    let s = plan("a den with a piano against the wall and a mirror hanging above it");
    let mirror = s
        .objects
        .keys()
        .find(|c| c.contains("mirror"))
        .cloned()
        .unwrap_or_default();
    assert_eq!(
        between(&s, &mirror, "piano"),
        vec![RelationKind::Over],
        "{:?}",
        s.relations
    );
    // "a laptop and a lamp on it": the lamp is said with the laptop; "it" is the desk
    let s = plan("a study with a writing desk, a laptop and a table lamp on it");
    assert_eq!(
        between(&s, "table lamp", "desk"),
        vec![RelationKind::Over],
        "{:?}",
        s.relations
    );
    assert!(
        between(&s, "table lamp", "laptop").is_empty(),
        "{:?}",
        s.relations
    );
}

#[test]
fn a_part_word_names_the_object_it_belongs_to() {
    let s = plan("a parlour with a fireplace and a rocking chair facing the fire");
    assert_eq!(
        between(&s, "rocking chair", "fireplace"),
        vec![RelationKind::Opposite],
        "{:?}",
        s.relations
    );
    // no fire is named: the part word makes no object
    assert!(
        s.objects
            .keys()
            .all(|c| !c.contains("fire") || c == "fireplace"),
        "{:?}",
        s.objects
    );
}

#[test]
fn either_side_of_one_thing_is_two() {
    let s = plan("a hall with a fireplace and a bench either side of it");
    let benches: u32 = s
        .objects
        .iter()
        .filter(|(c, _)| c.contains("bench"))
        .map(|(_, o)| o.number)
        .sum();
    assert_eq!(benches, 2, "{:?}", s.objects);
}

#[test]
fn seats_on_each_side_of_a_table_are_that_tables_seats() {
    let s = plan("a beer hall with three long tables and a bench on each side of every table");
    let seat = s
        .objects
        .keys()
        .find(|c| c.contains("bench"))
        .cloned()
        .unwrap_or_default();
    assert_eq!(number(&s, &seat), 6, "{:?}", s.objects);
    let table = s
        .objects
        .keys()
        .find(|c| c.ends_with("table"))
        .cloned()
        .unwrap_or_default();
    // every table has two of them, each tied to one table
    for k in 1..=3 {
        let at = s
            .relations
            .iter()
            .filter(|r| r.object == format!("{table}{k}") && r.subject.starts_with(&seat))
            .count();
        assert_eq!(at, 2, "{table}{k}: {:?}", s.relations);
    }
}

#[test]
fn a_bare_seat_noun_is_the_scenes_seat_of_that_kind() {
    // a living room's chairs are its armchairs, not dining chairs beside them
    let s = plan("a snug lounge with a sofa and a chair next to the bookcase");
    assert_eq!(number(&s, "armchair"), 1, "{:?}", s.objects);
    assert_eq!(number(&s, "dining chair"), 0, "{:?}", s.objects);
    // chairs said with a table to sit at stay the table's chairs
    let s = plan("a family room with a dining table and six chairs");
    assert_eq!(number(&s, "dining chair"), 6, "{:?}", s.objects);
}

#[test]
fn a_named_lamp_replaces_the_default_lamp_of_its_kind() {
    let s = plan("a lounge with a sofa and a tripod lamp in the corner");
    assert_eq!(number(&s, "tripod lamp"), 1, "{:?}", s.objects);
    assert_eq!(number(&s, "floor lamp"), 0, "{:?}", s.objects);
}

#[test]
fn a_thing_beneath_each_window_stands_at_a_window() {
    use dreamscene::plan::spec::Anchor;
    let s = plan("a study with two tall windows and a bookcase below each one");
    let cases: Vec<_> = s
        .anchors
        .iter()
        .filter(|(id, _)| id.starts_with("bookshelf"))
        .collect();
    assert_eq!(cases.len(), 2, "{:?}", s.anchors);
    assert!(
        cases.iter().all(|(_, a)| **a == Anchor::Window),
        "{:?}",
        s.anchors
    );
}

#[test]
fn a_thing_on_the_wall_is_the_kind_of_it_that_hangs_there() {
    let s = plan("a garage with a workbench and some shelves on the wall");
    assert!(number(&s, "wall shelf") >= 1, "{:?}", s.objects);
    let s = plan("a great hall with a long table and three tapestries hung on the walls");
    assert_eq!(number(&s, "tapestry"), 3, "{:?}", s.objects);
    assert_eq!(number(&s, "tapestry stand"), 0, "{:?}", s.objects);
}

#[test]
fn a_relation_after_a_support_phrase_belongs_to_the_thing_placed() {
    // a neighbour that stands on surfaces is the placed thing's neighbour
    let s = plan("a den with a radio on the sideboard beside the vase");
    assert!(
        between(&s, "sideboard", "vase").is_empty(),
        "{:?}",
        s.relations
    );
    assert!(
        !between(&s, "radio", "vase").is_empty(),
        "{:?}",
        s.relations
    );
    // a neighbour on the floor is the support's ("a lamp on the side table next to the sofa")
    let s = plan("a lounge with a vase on the side table next to the recliner");
    assert_eq!(
        between(&s, "side table", "recliner"),
        vec![RelationKind::Next],
        "{:?}",
        s.relations
    );
    assert_eq!(between(&s, "vase", "side table"), vec![RelationKind::Over]);
}

#[test]
fn it_is_one_thing_and_them_every_thing_said_together() {
    // "it" is never the plural before it
    let s = plan("a bar with four stools, a counter and a till on it");
    assert_eq!(
        between(&s, "cash register", "bar counter"),
        vec![RelationKind::Over],
        "{:?}",
        s.relations
    );
    assert!(
        s.relations
            .iter()
            .all(|r| !r.subject.starts_with("cash register") || !r.object.contains("stool")),
        "{:?}",
        s.relations
    );
    // "them": both things said together, not the last one
    let s = plan(
        "a utility room with a freezer and a washing machine and a shelf on the wall above them",
    );
    let shelf = s
        .objects
        .keys()
        .find(|c| c.contains("shelf"))
        .cloned()
        .unwrap_or_default();
    assert!(
        !between(&s, &shelf, "refrigerator").is_empty(),
        "{:?}",
        s.relations
    );
    assert!(
        !between(&s, &shelf, "washing machine").is_empty(),
        "{:?}",
        s.relations
    );
}

#[test]
fn things_on_a_counted_support_and_on_a_named_one_stay() {
    // "on four benches": the number is the support's
    let s = plan("a workshop with six lamps on three workbenches");
    assert!(
        !between(&s, "table lamp", "workbench").is_empty(),
        "{:?}",
        s.relations
    );
    // "the laptop" beside a lamp on "the desk" is planned
    let s = plan("a den with a lamp on the desk beside the laptop");
    assert_eq!(number(&s, "laptop"), 1, "{:?}", s.objects.keys());
    // what stands on a desk takes no seat's place at it
    let s = plan("a study with a desk and a laptop");
    assert_eq!(number(&s, "office chair"), 1, "{:?}", s.objects.keys());
}

#[test]
fn the_bare_noun_of_a_kind_named_before_is_that_object() {
    let s = plan("a courtyard with a cafe table under a parasol and two chairs at the table");
    assert_eq!(number(&s, "cafe table"), 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "dining table"), 0, "{:?}", s.objects.keys());
    let s = plan("a kitchen with a farmhouse table and a bench beside the table");
    assert_eq!(number(&s, "dining table"), 0, "{:?}", s.objects.keys());
}

#[test]
fn a_count_either_side_is_the_pair_and_each_side_multiplies() {
    let benches = |s: &SceneSpec| -> u32 {
        s.objects
            .iter()
            .filter(|(c, _)| c.contains("bench"))
            .map(|(_, o)| o.number)
            .sum()
    };
    let s = plan("a hall with a fireplace and two benches either side of it");
    assert_eq!(benches(&s), 2, "{:?}", s.objects);
    let s = plan("a ship's deck with two cannons on each side");
    assert_eq!(number(&s, "cannon"), 4, "{:?}", s.objects);
}

#[test]
fn a_verb_after_a_noun_is_no_object() {
    let s = plan("a pond garden where a wooden bridge crosses the stream");
    assert_eq!(number(&s, "wooden bridge"), 1, "{:?}", s.objects.keys());
    assert!(
        !s.objects.keys().any(|c| c.contains("cross")),
        "{:?}",
        s.objects.keys()
    );
    let s = plan("a loft with a cat sleeping on the rug");
    assert_eq!(number(&s, "cat"), 1, "{:?}", s.objects.keys());
    assert!(
        !s.objects.keys().any(|c| c.contains("sleeping")),
        "{:?}",
        s.objects.keys()
    );
}

#[test]
fn it_after_a_relation_is_that_relations_object() {
    let s = plan("a terrace with a table by the fountain and planters around it");
    assert_eq!(
        between(&s, "planter", "fountain"),
        vec![RelationKind::Around; 3],
        "{:?}",
        s.relations
    );
    assert!(
        between(&s, "planter", "patio table").is_empty(),
        "{:?}",
        s.relations
    );
}

#[test]
fn a_bare_noun_is_the_scenes_single_default_of_it() {
    // the study's floor lamp is the lamp the text puts on the desk
    let s = plan("a study with a lamp on the desk beside the printer");
    assert_eq!(number(&s, "table lamp"), 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "floor lamp"), 0, "{:?}", s.objects.keys());
}

#[test]
fn seats_around_a_table_named_before_are_that_tables_seats() {
    let s = plan("a kids playroom with a small table and four little chairs around it");
    // the small table is the playroom's kids table, the little chairs its seats: no desks or
    // office chairs come for them
    assert_eq!(number(&s, "kids table"), 1, "{:?}", s.objects);
    assert_eq!(number(&s, "desk"), 0, "{:?}", s.objects);
    assert_eq!(number(&s, "office chair"), 0, "{:?}", s.objects);
    let around: usize = s
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Around && r.subject.contains("chair"))
        .count();
    assert_eq!(around, 4, "{:?}", s.relations);
}

#[test]
fn a_thing_of_a_companions_slot_takes_its_place() {
    // a laptop on the desk is its computer; the chair at it stays
    let s = plan("a study with a writing desk by the window and a laptop on it");
    assert_eq!(number(&s, "laptop"), 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "computer"), 0, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "office chair"), 1, "{:?}", s.objects.keys());
    // "the laptop" names it as well
    let s = plan("a study with a printer on the desk beside the laptop");
    assert_eq!(number(&s, "computer"), 0, "{:?}", s.objects.keys());
}
