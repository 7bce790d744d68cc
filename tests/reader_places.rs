//! Places and kinds the reader infers: a fantastical version of a place keeps what its kind owns
//! and sheds the modern place's things, a place inside a template's outdoor place is indoors, a
//! potted tree is a potted plant, a named role at a table is no more of the same tables, and a
//! tiny room holds things at floor level without room to walk round them; heaps, participles,
//! area words, removal verbs and the seats a table already has are read the way people mean them.
//! Prompts of no corpus.
mod reading;
use dreamscene::plan::spec::{Anchor, RelationKind, SceneType};
use reading::{number, plan};

#[test]
fn a_fantastical_place_keeps_what_its_kind_owns() {
    let s = plan("an enchanted ballroom with a harp and a golden clock");
    assert!(number(&s, "dance floor") == 1, "{:?}", s.objects.keys());
    assert!(number(&s, "table") >= 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "dj"), 0, "{:?}", s.objects.keys());
    let room = s.room.map_or(0.0, |r| r.size[0] * r.size[1]);
    assert!(room > 40.0, "a ballroom is large: {room} m²");
}

#[test]
fn a_place_inside_an_outdoor_template_is_indoors() {
    let s = plan("a pirate ship's hold with sacks of grain and a lantern");
    assert_eq!(s.scene_type, SceneType::Indoor);
    assert_eq!(
        number(&s, "cannon") + number(&s, "wheel"),
        0,
        "{:?}",
        s.objects.keys()
    );
    let s = plan("a pirate ship deck with a mast");
    assert_eq!(s.scene_type, SceneType::Outdoor);
}

#[test]
fn a_potted_tree_is_a_potted_plant() {
    let s = plan("an office with a desk and a potted palm in the corner");
    let (c, o) = s
        .objects
        .iter()
        .find(|(c, _)| c.contains("plant") || c.contains("palm"))
        .unwrap_or_else(|| panic!("{:?}", s.objects.keys()));
    assert!(o.size[2] < 2.0, "{c}: {:?}", o.size);
}

#[test]
fn a_named_role_at_a_table_is_no_more_of_the_same_tables() {
    let s = plan("a banquet with six round tables and a head table for the couple");
    let round: u32 = s
        .objects
        .iter()
        .filter(|(c, _)| c.contains("round"))
        .map(|(_, o)| o.number)
        .sum();
    assert_eq!(round, 6, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "top table"), 1, "{:?}", s.objects.keys());
}

#[test]
fn a_tiny_room_fits_floor_level_things_without_room_round_them() {
    let s = plan("a tiny loft room with a floor mattress, two floor cushions and a clothes rail");
    let area = s.room.map_or(f64::MAX, |r| r.size[0] * r.size[1]);
    assert!(area <= 10.0, "{area} m²");
}

#[test]
fn a_heap_of_something_is_one_object_of_it() {
    let s = plan("a smugglers' cave with a pile of silver, a lantern and two barrels");
    assert_eq!(number(&s, "silver"), 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "pile"), 0, "{:?}", s.objects.keys());
    let s = plan("a tea house with a low table and a hanging scroll on the wall");
    assert_eq!(number(&s, "scroll"), 1, "{:?}", s.objects.keys());
    let s = plan("a cave with a snoring troll and a campfire");
    assert_eq!(number(&s, "troll"), 1, "{:?}", s.objects.keys());
}

#[test]
fn words_before_an_area_word_describe_the_area() {
    let s = plan("a living room with a music corner with a piano and a stool");
    assert_eq!(number(&s, "music"), 0, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "piano"), 1, "{:?}", s.objects.keys());
}

#[test]
fn removal_verbs_and_neither_nor_negate() {
    let s = plan("A bedroom with a double bed. Then get rid of the dresser and drop the rug.");
    assert_eq!(
        number(&s, "dresser") + number(&s, "rug"),
        0,
        "{:?}",
        s.objects.keys()
    );
    let s = plan("a den with a sofa and neither a tv nor a bookshelf");
    assert_eq!(
        number(&s, "tv") + number(&s, "bookshelf"),
        0,
        "{:?}",
        s.objects.keys()
    );
    let s = plan("a pilates studio with ten mats and not a single mirror");
    assert_eq!(number(&s, "mirror"), 0, "{:?}", s.objects.keys());
}

#[test]
fn counts_said_the_long_way() {
    let s = plan("a tea room with half a dozen tables and three chairs at each table");
    let tables: u32 = s
        .objects
        .iter()
        .filter(|(c, _)| c.ends_with("table") && !c.contains("side"))
        .map(|(_, o)| o.number)
        .sum();
    assert_eq!(tables, 6, "{:?}", s.objects);
    let s = plan("a hostel dorm with bunk beds");
    assert_eq!(number(&s, "bunk bed"), 1, "{:?}", s.objects.keys());
    let s = plan("a cabin with bunk beds for six campers");
    assert_eq!(number(&s, "bunk bed"), 3, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "camper"), 0, "{:?}", s.objects.keys());
}

#[test]
fn a_table_keeps_the_seats_the_text_gives_it() {
    // a named gaming chair is the desk's seat; one bar counter however many stools go along it
    let s = plan("a study with a writing desk and a gaming chair");
    assert_eq!(number(&s, "chair"), 1, "{:?}", s.objects.keys());
    let s = plan("a sake bar with ten stools along the counter");
    assert_eq!(number(&s, "counter"), 1, "{:?}", s.objects.keys());
    let s = plan("a porch with a small table and chairs");
    assert_eq!(number(&s, "chair"), 2, "{:?}", s.objects.keys());
}

#[test]
fn a_thing_of_its_own_for_each_spreads_over_them() {
    let s = plan("a beer garden with four tables, each under an umbrella");
    let under: std::collections::BTreeSet<&str> = s
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Under && r.subject.contains("table"))
        .map(|r| r.object.as_str())
        .collect();
    assert_eq!(under.len(), 4, "{:?}", s.relations);
    let s = plan("a village hall with benches against the far wall and a piano");
    let benches: Vec<_> = s
        .anchors
        .iter()
        .filter(|(i, _)| i.starts_with("bench"))
        .collect();
    assert!(
        !benches.is_empty() && benches.iter().all(|(_, a)| **a == Anchor::Side),
        "{benches:?}"
    );
}

#[test]
fn a_table_for_two_is_small_and_seats_add_up_over_mentions() {
    let s = plan("a breakfast room with a table for two");
    let t = &s.objects["dining table"];
    assert!(t.size[0] < 1.0 && t.size[1] < 1.0, "{:?}", t.size);
    let s = plan("a diner with four tables for two and a table for eight");
    assert_eq!(number(&s, "dining chair"), 16, "{:?}", s.objects.keys());
}

#[test]
fn benches_that_hold_things_are_work_benches() {
    let s = plan("an office with four computers on two benches");
    // a bench kind that holds things (a lab bench or a work bench)
    assert_eq!(
        number(&s, " bench") + number(&s, "workbench"),
        2,
        "{:?}",
        s.objects.keys()
    );
    assert!(!s.objects.contains_key("bench"), "{:?}", s.objects.keys());
    // a bench with nothing on it stays a seat
    let s = plan("a hallway with a bench and a coat rack");
    assert!(s.objects.contains_key("bench"), "{:?}", s.objects.keys());
}

#[test]
fn a_floor_lamp_kind_put_on_a_table_is_the_lamp_that_stands_on_tables() {
    let s = plan("a reading room with two long tables and a reading lamp on each table");
    assert_eq!(number(&s, "reading lamp"), 0, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "table lamp"), 2, "{:?}", s.objects.keys());
    // on something no one stands a lamp on, it stays what it was named
    let s = plan("a living room with a sofa and a floor lamp on the rug");
    assert_eq!(number(&s, "floor lamp"), 1, "{:?}", s.objects.keys());
}

#[test]
fn a_place_for_whom_another_scene_names_is_that_scene() {
    let s = plan("a classroom for toddlers and their teachers");
    assert_eq!(number(&s, "school desk") + number(&s, "blackboard"), 0);
    assert!(number(&s, "kids chair") >= 1, "{:?}", s.objects.keys());
    // no scene is named "kid kitchen": a kitchen for kids is a kitchen
    let s = plan("a kitchen for kids");
    assert!(number(&s, "stove") == 1, "{:?}", s.objects.keys());
    let s = plan("an ict suite with twelve computers");
    assert_eq!(number(&s, "fume hood") + number(&s, "microscope"), 0);
    assert_eq!(number(&s, "computer"), 12, "{:?}", s.objects);
}

#[test]
fn a_generic_name_is_the_default_of_its_role_and_a_named_kind_replaces_it() {
    let s = plan("a supermarket with shelving units in four rows");
    assert_eq!(number(&s, "bookshelf"), 0, "{:?}", s.objects.keys());
    assert!(number(&s, "display shelf") >= 4, "{:?}", s.objects);
    let s = plan("a den with shelving units");
    assert!(number(&s, "bookshelf") >= 1, "{:?}", s.objects.keys());
    let s = plan("a corner store with two drinks fridges");
    assert_eq!(number(&s, "refrigerator"), 0, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "drinks fridge"), 2, "{:?}", s.objects);
}

/// A plural support with no count ("on benches", "on tables") is as many as the things placed on
/// it need: each holds what fits along its width, at least a person's working width per thing.
#[test]
fn a_plural_support_without_a_count_holds_all_that_is_put_on_it() {
    for (prompt, thing, support) in [
        ("an office with twelve monitors on desks", "monitor", "desk"),
        (
            "a repair shop with ten laptops on workbenches",
            "laptop",
            "workbench",
        ),
        (
            "a call centre with fourteen computers on tables",
            "computer",
            "desk",
        ),
    ] {
        let spec = plan(prompt);
        let things = number(&spec, thing);
        let (n, size) = spec
            .objects
            .iter()
            .filter(|(c, _)| c.contains(support))
            .map(|(_, o)| (o.number, o.size))
            .max_by_key(|(n, _)| *n)
            .unwrap_or_else(|| panic!("{prompt}: no {support} in {:?}", spec.objects.keys()));
        let each = spec
            .objects
            .iter()
            .find(|(c, _)| c.contains(thing))
            .map(|(_, o)| o.size[0].max(0.7))
            .unwrap_or(0.7);
        let per = (size[0] / each).floor().max(1.0) as u32;
        assert!(things >= 9, "{prompt}: {things} {thing}");
        assert!(
            n * per >= things,
            "{prompt}: {n} {support} of {:.2} m hold {} of {things} {thing}",
            size[0],
            n * per
        );
    }
}

/// People ("the staff", "a receptionist") are no objects, and the rooms named after what people
/// do there ("a break room", "a staff room") or the places of the dead ("a cemetery", "a
/// graveyard") are places with their own furniture, the latter outdoors.
#[test]
fn people_and_activity_places_are_no_objects() {
    for prompt in [
        "a break room for the staff",
        "a staff room with a kettle on the counter",
        "a hotel lobby with a reception desk and a receptionist",
    ] {
        let s = plan(prompt);
        for word in ["break", "staff", "receptionist"] {
            assert!(
                !s.objects.keys().any(|c| c.split(' ').any(|w| w == word)),
                "{prompt}: {:?}",
                s.objects.keys()
            );
        }
        assert!(!s.objects.is_empty(), "{prompt}");
    }
    for prompt in ["a cemetery", "an old graveyard with two benches"] {
        let s = plan(prompt);
        assert_eq!(s.scene_type, SceneType::Outdoor, "{prompt}");
        assert!(
            number(&s, "tombstone") > 0,
            "{prompt}: {:?}",
            s.objects.keys()
        );
        assert!(!s.objects.contains_key("flagpole"), "{prompt}");
    }
    for prompt in ["a dance studio", "a ballet studio with a piano"] {
        let s = plan(prompt);
        assert_eq!(number(&s, "easel"), 0, "{prompt}: {:?}", s.objects.keys());
        assert_eq!(
            number(&s, "mirror wall"),
            1,
            "{prompt}: {:?}",
            s.objects.keys()
        );
    }
}

#[test]
fn an_owners_place_before_a_room_every_place_has_is_that_room() {
    // "the dentist's" names the surgery, but "a dentist's waiting room" is a waiting room (of
    // the dentist's): no dentist chair, its chairs waiting chairs, not desks with office chairs.
    for prompt in [
        "a dentist's waiting room with eight chairs and a fish tank",
        "the dentist's waiting room",
        "a cobbler's waiting room with four chairs",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "dentist"), 0, "{prompt}: {:?}", s.objects.keys());
        assert_eq!(
            number(&s, "office chair"),
            0,
            "{prompt}: {:?}",
            s.objects.keys()
        );
        assert!(
            number(&s, "waiting chair") >= 4,
            "{prompt}: {:?}",
            s.objects.keys()
        );
    }
    // The owner's own place stays the owner's, and an owner's generic room is the owner's room.
    assert_eq!(number(&plan("a dentist's office"), "dentist chair"), 1);
    assert_eq!(number(&plan("the dentist's"), "dentist chair"), 1);
    assert!(number(&plan("a wizard's laboratory"), "cauldron") >= 1);
}

#[test]
fn a_side_table_stands_beside_a_seat() {
    // A side table serves a seat: with no sofa, it is set beside the armchair or the waiting
    // chairs, not left free in the middle of the room.
    for (prompt, seat) in [
        (
            "a reading corner with an armchair, a side table and a bookcase",
            "armchair",
        ),
        ("a waiting room with six chairs", "waiting chair"),
        (
            "a bedroom with a rocking chair and a side table",
            "rocking chair",
        ),
    ] {
        let s = plan(prompt);
        assert!(
            s.relations
                .iter()
                .any(|r| r.subject.starts_with("side table")
                    && r.relation == RelationKind::Next
                    && r.object.starts_with(seat)),
            "{prompt}: {:?}",
            s.relations
        );
    }
}
