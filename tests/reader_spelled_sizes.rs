//! Sizes said in words: "five metres by four", "twelve feet by ten", "four by three meters",
//! "about ten square metres" are the room's size, never things called "meter" or "foot"; a
//! length said of a distance ("one metre from the wall") places nothing; a number beside "by"
//! that is no size ("a table for six by the window") still counts; a whole number with its unit
//! before a noun ("a 55 inch telly", "a 2 metre bench") is the thing's size, not its count.
//! Prompts of no corpus.
mod reading;
use dreamscene::plan::offline::plan_prompt;
use reading::{keys, number};

fn room_of(prompt: &str) -> ([f64; 2], Vec<String>, Vec<String>) {
    let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
    let size = p.spec.room.as_ref().expect("a room").size;
    (
        [size[0], size[1]],
        keys(&p.spec),
        p.understood.unused.clone(),
    )
}

#[test]
fn a_room_size_in_words_is_the_room_and_no_object() {
    for (prompt, w, d) in [
        (
            "a studio apartment five metres by four with a double bed",
            5.0,
            4.0,
        ),
        ("a bedroom twelve feet by ten with a bed", 3.66, 3.05),
        ("an office four by three meters with a desk", 4.0, 3.0),
        (
            "a hall twenty-four metres by eighteen with a stage",
            24.0,
            18.0,
        ),
        ("a kitchen six by five metres with an island", 6.0, 5.0),
    ] {
        let (room, keys, unused) = room_of(prompt);
        assert!(
            (room[0] - w).abs() < 0.05 && (room[1] - d).abs() < 0.05,
            "{prompt}: {room:?}"
        );
        assert!(
            !keys
                .iter()
                .any(|k| k.contains("meter") || k.contains("metre") || k.contains("foot")),
            "{prompt}: {keys:?}"
        );
        assert!(unused.is_empty(), "{prompt}: {unused:?}");
    }
}

#[test]
fn an_area_in_words_sizes_the_floor() {
    for (prompt, area) in [
        ("a bathroom of about ten square metres with a bathtub", 10.0),
        ("a bedroom of roughly twelve square meters with a bed", 12.0),
        (
            "an office of approximately twenty square metres with two desks",
            20.0,
        ),
    ] {
        let (room, keys, unused) = room_of(prompt);
        assert!((room[0] * room[1] - area).abs() < 0.6, "{prompt}: {room:?}");
        assert!(
            !keys.iter().any(|k| k.contains("meter")),
            "{prompt}: {keys:?}"
        );
        assert!(unused.is_empty(), "{prompt}: {unused:?}");
    }
}

#[test]
fn a_distance_places_nothing_and_a_count_beside_by_still_counts() {
    for prompt in [
        "two chairs one metre from the wall",
        "two chairs 1 metre from the wall",
        "a rug half a metre from the bed",
    ] {
        let (_, keys, _) = room_of(prompt);
        assert!(
            !keys
                .iter()
                .any(|k| k.contains("metre") || k.contains("meter")),
            "{prompt}: {keys:?}"
        );
    }
    let s = reading::plan("a dining room with a table for six by the window");
    assert_eq!(number(&s, "dining chair"), 6, "{:?}", keys(&s));
}

#[test]
fn a_size_said_before_punctuation_is_the_rooms_not_the_next_things() {
    // The size ends a clause; the thing after the colon or full stop is not that size.
    for (prompt, w, d, thing) in [
        (
            "little sound booth roughly 2m x 2.5m: a microphone on a stand and a stool",
            2.0,
            2.5,
            "microphone",
        ),
        (
            "cloakroom, very small, maybe 1.4 x 1.8m. a toilet and a corner basin",
            1.4,
            1.8,
            "toilet",
        ),
        (
            "a box room of 2.2 x 2.6 m; single bed under the window",
            2.2,
            2.6,
            "bed",
        ),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let size = p.spec.room.as_ref().expect("a room").size;
        assert!(
            (size[0] - w).abs() < 0.05 && (size[1] - d).abs() < 0.05,
            "{prompt}: room {size:?}"
        );
        let o = p
            .spec
            .objects
            .iter()
            .find(|o| o.0.contains(thing))
            .map(|o| o.1)
            .unwrap_or_else(|| panic!("{prompt}: no {thing}"));
        assert!(
            !((o.size[0] - w).abs() < 0.05 && (o.size[1] - d).abs() < 0.05),
            "{prompt}: {thing} took the room's size {:?}",
            o.size
        );
    }
    // A size right before its noun is still that thing's.
    let p = plan_prompt("a living room with a 3 x 2 m rug and a sofa").expect("plans");
    let rug = p
        .spec
        .objects
        .iter()
        .find(|o| o.0 == "rug")
        .map(|o| o.1)
        .expect("a rug");
    assert!(
        (rug.size[0] - 3.0).abs() < 0.05 && (rug.size[1] - 2.0).abs() < 0.05,
        "{:?}",
        rug.size
    );
}

#[test]
fn a_whole_number_with_its_unit_before_a_noun_is_its_size_not_its_count() {
    for (prompt, cat, n) in [
        ("a den with a 55 inch telly on the wall and a sofa", "tv", 1),
        ("a hall with a 2 metre bench and a coat rack", "bench", 1),
        (
            "a workshop with three 2 m workbenches and stools",
            "workbench",
            3,
        ),
        ("a games room with a 7 ft pool table", "pool table", 1),
    ] {
        let s = plan_prompt(prompt)
            .unwrap_or_else(|e| panic!("{prompt}: {e}"))
            .spec;
        let got = s.objects.get(cat).map_or(0, |o| o.number);
        assert_eq!(got, n, "{prompt}: {:?}", keys(&s));
    }
}
