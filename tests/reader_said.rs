//! What a sentence says beside its objects, on requests nobody tuned on: an answer to "where
//! do I put the piano?" places the piano; the place a scene is in ("in a park") is no object;
//! weather, mood and the words naming a place's finish ("a dentist waiting room") are read,
//! never left unused; "buckets of flowers" are several buckets; a long mirror is a full-length
//! one; a tv room, a hotel room and a balcony are places of their own (a balcony a narrow strip);
//! naming a laundromat's washers leaves its dryers unless the text takes them away.
mod reading;
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Anchor, RelationKind};
use reading::{keys, number, plan};

fn unused(prompt: &str) -> Vec<String> {
    plan_prompt(prompt)
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
        .understood
        .unused
}

#[test]
fn an_answer_to_where_a_thing_goes_places_that_thing() {
    for (prompt, thing, next_to, anchor) in [
        (
            r#""Where do I put the piano?" "By the window, next to the bookshelf.""#,
            "piano1",
            Some("bookshelf1"),
            Some(Anchor::Window),
        ),
        (
            "Where should the armchair go? Next to the fireplace.",
            "armchair1",
            Some("fireplace1"),
            None,
        ),
        (
            "User: a study. Assistant: where do you want the desk? User: under the window",
            "desk1",
            None,
            Some(Anchor::Window),
        ),
    ] {
        let s = plan(prompt);
        if let Some(o) = next_to {
            assert!(
                s.relations.iter().any(|r| r.subject == thing
                    && r.relation == RelationKind::Next
                    && r.object == o),
                "{prompt}: {:?}",
                s.relations
            );
        }
        if let Some(a) = anchor {
            assert_eq!(s.anchors.get(thing), Some(&a), "{prompt}: {:?}", s.anchors);
        }
    }
    // a statement before the phrase keeps its own subject
    let s = plan("A study with a desk. A lamp next to the bookshelf.");
    assert!(
        s.relations
            .iter()
            .all(|r| !(r.subject.starts_with("desk") && r.object.starts_with("bookshelf"))),
        "{:?}",
        s.relations
    );
}

#[test]
fn the_place_a_scene_is_in_is_no_object() {
    for (prompt, place) in [
        ("a picnic spot in a park", "park"),
        ("a picnic blanket in a meadow", "meadow"),
        ("a picnic spot in a quiet city park", "park"),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, place), 0, "{prompt}: {:?}", keys(&s));
        assert!(unused(prompt).is_empty(), "{prompt}: {:?}", unused(prompt));
    }
    // a thing of that name stays the thing
    let s = plan("a campsite with a lantern in a tent");
    assert!(number(&s, "tent") >= 1, "{:?}", keys(&s));
}

#[test]
fn weather_mood_and_time_of_day_are_read_not_placed() {
    for prompt in [
        "a cozy reading nook on a rainy day",
        "a snowy backyard with a snowman",
        "a quiet library on a stormy afternoon with three study carrels",
        r#""I want a cozy living room." "With a fireplace?" "Yes, and two armchairs.""#,
    ] {
        assert!(unused(prompt).is_empty(), "{prompt}: {:?}", unused(prompt));
        let s = plan(prompt);
        for w in ["afternoon", "day", "rainy", "stormy"] {
            assert_eq!(number(&s, w), 0, "{prompt}: {:?}", keys(&s));
        }
    }
}

#[test]
fn the_words_naming_a_places_finish_are_used() {
    for prompt in [
        "a dentist waiting room",
        "a vet's waiting room with a fish tank",
        "a doctor's waiting room with ten chairs",
    ] {
        assert!(unused(prompt).is_empty(), "{prompt}: {:?}", unused(prompt));
    }
}

#[test]
fn containers_said_in_the_plural_of_their_goods_are_several() {
    for prompt in [
        "a flower stall with buckets of flowers",
        "a florist with buckets of roses by the door",
    ] {
        let s = plan(prompt);
        assert!(number(&s, "flower bucket") >= 2, "{prompt}: {:?}", keys(&s));
    }
    let s = plan("a market stall with a bucket of flowers");
    assert_eq!(number(&s, "flower bucket"), 1, "{:?}", keys(&s));
}

#[test]
fn a_long_or_tall_mirror_is_a_full_length_mirror() {
    for prompt in [
        "a bedroom with a long mirror",
        "a hallway with a tall mirror and a coat rack",
        "a dressing room with a full-length mirror",
    ] {
        let s = plan(prompt);
        let m = s
            .objects
            .get("full length mirror")
            .unwrap_or_else(|| panic!("{prompt}: {:?}", keys(&s)));
        assert!(m.size[2] >= 1.5, "{prompt}: {:?}", m.size);
    }
}

#[test]
fn a_tv_room_even_a_tiny_one_has_a_seat_before_its_tv() {
    for prompt in [
        "a tiny tv room",
        "a tv room with a big sofa",
        "a cosy television room",
    ] {
        let s = plan(prompt);
        assert!(number(&s, "tv") >= 1, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "sofa") >= 1, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_hotel_room_is_a_bedroom_for_guests() {
    for prompt in [
        "a hotel room with two queen beds and a desk",
        "a hotel room",
        "a motel room with a king bed",
    ] {
        let s = plan(prompt);
        assert!(number(&s, "bed") >= 1, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "nightstand") >= 1, "{prompt}: {:?}", keys(&s));
        assert!(unused(prompt).is_empty(), "{prompt}: {:?}", unused(prompt));
    }
    assert_eq!(
        number(&plan("a hotel room with two queen beds and a desk"), "bed"),
        2
    );
}

#[test]
fn a_balcony_is_a_narrow_strip_whatever_its_size_word() {
    let area = |p: &str| {
        let s = plan(p);
        let r = s.room.unwrap_or_else(|| panic!("{p}: no room"));
        r.size[0] * r.size[1]
    };
    for prompt in [
        "a small balcony",
        "a balcony with two chairs and a little table",
        "an apartment balcony with plants",
    ] {
        let a = area(prompt);
        assert!(a <= 10.0, "{prompt}: {a:.1} m²");
        assert!(number(&plan(prompt), "chair") >= 1, "{prompt}");
    }
    assert!(area("a large balcony") <= 15.0);
    // a patio is no balcony
    assert!(area("a patio") > 20.0);
}

#[test]
fn naming_a_laundromats_washers_leaves_its_dryers_unless_taken_away() {
    // the text counts the washers; the dryers are the place's own and stay
    let s = plan("a laundromat with four washing machines");
    assert_eq!(number(&s, "washing machine"), 4, "{:?}", keys(&s));
    assert!(number(&s, "dryer") >= 1, "{:?}", keys(&s));
    let s = plan("a laundromat with four washing machines and no dryers");
    assert_eq!(number(&s, "dryer"), 0, "{:?}", keys(&s));
    let s = plan("a laundromat with 8 washers and 2 dryers");
    assert_eq!(
        (number(&s, "washing machine"), number(&s, "dryer")),
        (8, 2),
        "{:?}",
        keys(&s)
    );
}

#[test]
fn long_and_tall_scale_an_objects_length_and_height() {
    let size = |p: &str, c: &str| {
        let s = plan(p);
        s.objects
            .get(c)
            .unwrap_or_else(|| panic!("{p}: {:?}", keys(&s)))
            .size
    };
    let plain = size("a dining room with a table", "dining table");
    let long = size("a dining room with a long table", "dining table");
    assert!(
        long[0].max(long[1]) > 1.3 * plain[0].max(plain[1]),
        "{long:?}"
    );
    assert_eq!(long[2], plain[2]);
    let bench = size("a hallway with a bench", "bench");
    let long_bench = size("a hallway with a long bench", "bench");
    assert!(long_bench[0] > bench[0], "{long_bench:?}");
    let plant = size("an office with a potted plant", "potted plant");
    let tall = size("an office with a tall potted plant", "potted plant");
    assert!(tall[2] > plant[2] && tall[0] == plant[0], "{tall:?}");
    // the seats a table is laid for set its length
    assert_eq!(
        size("a diner with a long table for eight", "dining table"),
        size("a diner with a table for eight", "dining table")
    );
}
