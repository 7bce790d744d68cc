//! What a person means by words about a room's surroundings and its seats: a landscape said
//! as where an indoor room is ("by the sea", "overlooking the lake", "a sea view") is outside,
//! never a sea inside a room grown to hold it; a bare plural of a small thing ("candles") is
//! more than one; a recliner named in a living room is its armchair (no default armchairs
//! besides) and in a home cinema its seats; a room called small or tiny keeps a share of an
//! office's workstations, not all of them.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;

fn spec(prompt: &str) -> SceneSpec {
    plan_prompt(prompt)
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
        .spec
}

fn number(s: &SceneSpec, c: &str) -> u32 {
    s.objects.get(c).map_or(0, |o| o.number)
}

#[test]
fn a_landscape_a_room_looks_out_on_is_not_in_it() {
    for (prompt, away, keeps) in [
        (
            "a small bedroom by the ocean with a double bed",
            "sea",
            "bed",
        ),
        ("a cosy study overlooking the river", "river", "desk"),
        (
            "a kitchen with a view of the lake and a big fridge",
            "lake",
            "refrigerator",
        ),
        ("a hotel bathroom with sea views", "sea", "toilet"),
        (
            "a lounge near the sea with a grand piano",
            "sea",
            "grand piano",
        ),
    ] {
        let s = spec(prompt);
        let keys: Vec<&String> = s.objects.keys().collect();
        let said = dreamscene::plan::kb::KnowledgeBase::builtin()
            .object(away)
            .map(|o| o.category.clone())
            .unwrap_or(away.to_string());
        assert_eq!(number(&s, &said), 0, "{prompt}: {keys:?}");
        assert!(number(&s, keys_of(&s, keeps)) > 0, "{prompt}: {keys:?}");
        let room = s.room.expect("an indoor room").size;
        assert!(
            room[0] * room[1] < 60.0,
            "{prompt}: a room grown to hold a landscape: {room:?}"
        );
    }
    // outdoors the same words name the landscape itself
    for (prompt, c) in [
        ("a beach by the ocean", "sea"),
        ("a campsite by a lake", "lake"),
    ] {
        let s = spec(prompt);
        assert!(number(&s, c) > 0, "{prompt}: {:?}", s.objects.keys());
    }
}

/// The planned category whose name ends with `word` (a double bed for "bed").
fn keys_of<'a>(s: &'a SceneSpec, word: &'a str) -> &'a str {
    s.objects
        .keys()
        .find(|c| *c == word || c.ends_with(&format!(" {word}")))
        .map_or(word, |c| c.as_str())
}

#[test]
fn a_bare_plural_of_candles_is_several() {
    for prompt in [
        "a bathroom with candles around the bath",
        "a dining room with candles on the table",
        "a cosy living room lit by candles",
    ] {
        let s = spec(prompt);
        assert!(number(&s, "candle") >= 2, "{prompt}: {:?}", s.objects);
    }
    assert_eq!(
        number(&spec("a bedroom with a candle on the nightstand"), "candle"),
        1
    );
}

#[test]
fn recliners_are_the_armchairs_of_a_living_room_and_the_seats_of_a_cinema() {
    for prompt in [
        "a den with two recliners and a big tv",
        "a living room with a leather recliner by the window",
        "a cosy lounge with a pair of recliners",
    ] {
        let s = spec(prompt);
        assert!(
            number(&s, "recliner") >= 1,
            "{prompt}: {:?}",
            s.objects.keys()
        );
        assert_eq!(
            number(&s, "armchair"),
            0,
            "{prompt}: {:?}",
            s.objects.keys()
        );
    }
    let s = spec("a home theatre with eight recliners");
    assert_eq!(number(&s, "recliner"), 8);
    assert_eq!(number(&s, "theater seat"), 0);
    let faced = s
        .relations
        .iter()
        .filter(|r| r.subject.starts_with("recliner"))
        .filter(|r| r.object.starts_with("projector screen"))
        .count();
    assert_eq!(
        faced, 8,
        "the cinema's recliners face its screen: {:?}",
        s.relations
    );
}

#[test]
fn a_small_office_keeps_a_share_of_its_workstations() {
    let full = number(&spec("an office"), "desk");
    for prompt in [
        "a small office",
        "a tiny office with a window",
        "a little open-plan office",
    ] {
        let s = spec(prompt);
        let desks = number(&s, "desk");
        assert!(
            desks >= 1 && desks < full,
            "{prompt}: {desks} of {full} desks"
        );
        assert_eq!(
            number(&s, "office chair"),
            desks,
            "{prompt}: a chair at each desk"
        );
    }
}
