//! Requests heard from people who did not tune the reader: a gym's wall bars are climbing bars,
//! not a bar counter; "a bench seat" is a bench; a pair of headphones is one thing; "rows of
//! chairs" without a number are the place's own seats, or a block of them, set out in rows; a
//! pub's named stools want a longer bar, not a second one, and named booths take the place of
//! its default tables and chairs; a tiny room keeps floor free by leaving out what the place can
//! do without, never what it cannot. Prompts of no corpus.
mod reading;
use dreamscene::plan::capacity::{floor_area, FREE_FLOOR};
use dreamscene::plan::spec::RelationKind;
use reading::{keys, number, plan};

#[test]
fn wall_bars_are_climbing_bars_not_a_bar_counter() {
    for (prompt, n) in [
        ("a home gym with wall bars and a bench", 1),
        ("a sports hall with wall bars along one wall", 1),
        (
            "a school gym with two sets of wall bars and a pile of mats",
            2,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "wall bars"), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "bar counter"), 0, "{prompt}: {:?}", keys(&s));
    }
    // a bar is still a bar
    let s = plan("a pub with a long bar and four stools");
    assert_eq!(number(&s, "bar counter"), 1, "{:?}", keys(&s));
}

#[test]
fn a_seat_named_after_a_seat_is_that_seat() {
    for prompt in [
        "a hallway with a bench seat and a coat rack",
        "a kitchen with a bench seat under the window",
        "a bedroom with a double bed and a padded bench seat at its foot",
    ] {
        let s = plan(prompt);
        assert!(number(&s, "bench") >= 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "theater seat"), 0, "{prompt}: {:?}", keys(&s));
    }
    // seats alone are an audience's, and a car seat is no bench
    let s = plan("a cinema with forty seats");
    assert_eq!(number(&s, "theater seat"), 40, "{:?}", keys(&s));
}

#[test]
fn a_pair_of_headphones_is_one_thing_on_what_it_is_said_to_be_on() {
    for (prompt, n, support) in [
        ("a DJ booth with headphones", 1, "dj booth"),
        (
            "a recording studio with two pairs of headphones on the desk",
            2,
            "mixing desk",
        ),
        (
            "a bedroom with a pair of headphones on the nightstand",
            1,
            "nightstand",
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "headphones"), n, "{prompt}: {:?}", keys(&s));
        let on: Vec<&str> = s
            .relations
            .iter()
            .filter(|r| r.subject.starts_with("headphones") && r.relation == RelationKind::Over)
            .map(|r| r.object.as_str())
            .collect();
        if prompt.contains(" on ") {
            assert_eq!(on.len(), n as usize, "{prompt}: {:?}", s.relations);
        }
        assert!(
            on.iter().all(|o| o.starts_with(support)),
            "{prompt}: {on:?}"
        );
    }
    // a pair of what is not one thing is still two
    let s = plan("a living room with a pair of armchairs");
    assert_eq!(number(&s, "armchair"), 2, "{:?}", keys(&s));
}

#[test]
fn rows_of_chairs_without_a_number_are_the_places_seats_in_rows() {
    // the place's own seats when it has them, a block of three rows of four when not
    for (prompt, seat, n) in [
        ("a waiting room with rows of chairs", "waiting chair", 8),
        (
            "a classroom with rows of chairs facing the whiteboard",
            "dining chair",
            8,
        ),
        ("a garden with rows of chairs facing a pergola", "chair", 12),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, seat), n, "{prompt}: {:?}", keys(&s));
        let rows = s
            .objects
            .iter()
            .filter(|(c, _)| c.contains(seat))
            .map(|(_, o)| o.rows)
            .max()
            .unwrap_or(0);
        assert!(rows >= 2, "{prompt}: {rows} rows");
    }
    // a counted row keeps its count
    let s = plan("a waiting room with two rows of five chairs");
    assert_eq!(number(&s, "chair"), 10, "{:?}", keys(&s));
}

#[test]
fn a_pubs_named_seating_takes_the_place_of_its_default_seating() {
    for (prompt, stools, booths) in [
        ("a pub with six bar stools and two booths", 6, 2),
        ("an irish pub with three booths and a dartboard", 5, 3),
        (
            "an american diner with six booths and a long counter with eight stools",
            8,
            6,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "stool"), stools, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "booth"), booths, "{prompt}: {:?}", keys(&s));
        // one bar however many stools it seats, and no chairs without their tables
        assert_eq!(number(&s, "bar counter"), 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "chair"), 0, "{prompt}: {:?}", keys(&s));
    }
    // stools alone leave the pub its tables and chairs
    let s = plan("a pub with eight bar stools");
    assert_eq!(number(&s, "bar counter"), 1, "{:?}", keys(&s));
    assert!(number(&s, "cafe chair") > 0, "{:?}", keys(&s));
}

#[test]
fn a_tiny_room_keeps_floor_free_and_what_the_place_cannot_do_without() {
    for (prompt, kept) in [
        ("a tiny home office", &["desk", "office chair"][..]),
        ("a tiny box room with a desk", &["desk"]),
        ("a cramped study with a desk", &["desk"]),
    ] {
        let s = plan(prompt);
        for k in kept {
            assert!(number(&s, k) >= 1, "{prompt}: no {k} in {:?}", keys(&s));
        }
        let room = s.room.expect("a planned room").size;
        let floor = room[0] * room[1];
        let defaults_only = !prompt.contains("with");
        if defaults_only {
            assert!(
                floor_area(&s) <= floor - FREE_FLOOR + 1e-9,
                "{prompt}: {:.2} m² of {floor:.2} m² covered: {:?}",
                floor_area(&s),
                keys(&s)
            );
        }
    }
}

#[test]
fn a_shop_named_by_its_owner_is_that_shop_with_its_own_furniture() {
    for (prompt, own, n) in [
        ("a barber's with two barber chairs", "barber chair", 2),
        (
            "we need a barber's with four chairs facing mirrors and a coat stand by the door",
            "salon station",
            3,
        ),
        ("a florist's with a counter", "flower", 1),
    ] {
        let s = plan(prompt);
        assert!(number(&s, own) >= n, "{prompt}: {:?}", keys(&s));
    }
    // an owner's name before another noun still qualifies it: a pirate ship's hold is indoors
    let s = plan("a pirate ship's hold with barrels");
    assert_eq!(
        s.scene_type,
        dreamscene::plan::spec::SceneType::Indoor,
        "{:?}",
        keys(&s)
    );
}
