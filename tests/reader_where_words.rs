//! Where words put things and what place words make of the room: "the two X" said again is
//! no new pair, outdoor place nouns and "in a garden" put a
//! place out of doors (a view of one does not), a bare "seats" is the place's own seat, and
//! "long", "narrow", "huge" shape and scale the room. Prompts of no corpus.
mod reading;
use dreamscene::plan::spec::SceneType;
use reading::{keys, number, plan};

#[test]
fn the_two_things_named_again_are_no_new_pair() {
    for (prompt, many) in [
        (
            "a den with two recliners and a side table between the two recliners",
            "recliner",
        ),
        (
            "a lounge with two sofas and a floor lamp between both sofas",
            "sofa",
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, many), 2, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn outdoor_place_nouns_put_the_place_out_of_doors() {
    for prompt in [
        "a mountain lake with two canoes",
        "a river with a rowing boat and a kayak",
        "a wedding ceremony on a lawn",
        "a wedding ceremony in a rose garden with a string quartet",
    ] {
        assert_eq!(plan(prompt).scene_type, SceneType::Outdoor, "{prompt}");
    }
    // a view of one, a picture of one, a heap: still a room
    for prompt in [
        "a bedroom in the mountains",
        "a living room with a painting of a river",
        "a kitchen in a garden shed",
        "a sofa with a mountain of cushions",
    ] {
        assert_eq!(plan(prompt).scene_type, SceneType::Indoor, "{prompt}");
    }
}

#[test]
fn a_bare_seat_is_the_places_own_seat() {
    for (prompt, seat, n) in [
        ("a waiting room with twelve seats", "chair", 12),
        ("a kitchen with three seats at the island", "stool", 3),
        ("a cinema with twenty seats", "theater seat", 20),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, seat), n, "{prompt}: {:?}", keys(&s));
        if seat != "theater seat" {
            assert_eq!(number(&s, "theater"), 0, "{prompt}: {:?}", keys(&s));
        }
    }
    let s = plan("a den with a tray table and a sofa");
    assert_eq!(number(&s, "dining"), 0, "{:?}", keys(&s));
}

#[test]
fn long_narrow_and_huge_shape_the_room() {
    let side = |p: &str| {
        let s = plan(p);
        let r = s.room.unwrap_or_else(|| panic!("{p}: no room"));
        (r.size[0].max(r.size[1]), r.size[0].min(r.size[1]))
    };
    for p in [
        "a long narrow gallery",
        "a long hallway",
        "a narrow kitchen",
    ] {
        let (l, w) = side(p);
        assert!(l / w >= 2.0, "{p}: {l} x {w}");
    }
    let (l, w) = side("a huge bedroom");
    let (l0, w0) = side("a bedroom");
    assert!(l * w >= 1.8 * l0 * w0, "huge {l} x {w}, plain {l0} x {w0}");
}
