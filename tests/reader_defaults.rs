//! What a place's defaults become when the text names, refuses or misspells things: a nursery's
//! one seat for the parent is its rocking chair or the nursing chair named instead, a sewing room's big table is a
//! cutting table, a rack there only for magazines goes with "no magazines", a pile of books is
//! one pile on a table, misspelt object words are mended as place names are (never one
//! letter changed for another), a bare plural in N rows fills every row, and things said to
//! hang on the wall (a map, a calendar) are things that hang; recliners named in a home theatre
//! are its seats, as chairs in rows in a church are its congregation's; "chairs" in a barber's are its
//! barber chairs; a reading lamp on a desk is the room's lamp; a tea shop is a cafe. Prompts of no corpus.
mod reading;
use reading::{keys, number, plan};

#[test]
fn a_nursery_seats_its_parent_in_one_chair() {
    for (prompt, seat, not) in [
        ("a nursery", "rocking chair", "nursing chair"),
        (
            "a nursery with a nursing chair",
            "nursing chair",
            "rocking chair",
        ),
        (
            "a baby room with a glider and a crib",
            "nursing chair",
            "rocking chair",
        ),
        (
            "a nursery with a cot and a nursing chair by the window",
            "nursing chair",
            "rocking chair",
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, seat), 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, not), 0, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn recliners_named_in_a_home_theatre_are_its_seats() {
    for (prompt, n) in [
        ("a home theatre with two rows of recliners", 4),
        ("a home theatre with six recliners", 6),
        ("a media room with three recliners facing the screen", 3),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "recliner"), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "theater seat"), 0, "{prompt}: {:?}", keys(&s));
    }
    let s = plan("a home theatre");
    assert_eq!(number(&s, "theater seat"), 8, "{:?}", keys(&s));
}

#[test]
fn a_sewing_room_cuts_cloth_on_one_big_table() {
    for (prompt, table, not) in [
        ("a sewing room", "cutting table", "craft table"),
        (
            "a dressmaking studio with a mannequin",
            "cutting table",
            "craft table",
        ),
        (
            "a sewing room with a craft table",
            "craft table",
            "cutting table",
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, table), 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, not), 0, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "sewing table"), 1, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn what_holds_only_what_the_text_refuses_goes_with_it() {
    for prompt in [
        "a waiting room with ten chairs, no magazines and a water cooler by the door",
        "a clinic waiting room without magazines",
        "a dentist's waiting room with eight chairs but no magazines",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "magazine"), 0, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "chair") >= 1, "{prompt}: {:?}", keys(&s));
    }
    // a rack named stays, and with nothing refused the place keeps its rack
    let s = plan("a waiting room with a magazine rack and no magazines");
    assert_eq!(number(&s, "magazine rack"), 1, "{:?}", keys(&s));
    let s = plan("a waiting room with ten chairs");
    assert_eq!(number(&s, "magazine rack"), 1, "{:?}", keys(&s));
}

#[test]
fn a_pile_of_books_is_one_stack_of_books() {
    for prompt in [
        "a reading nook by the window with a pile of books",
        "a bedroom with a stack of books on the nightstand",
        "a living room with a sofa and a heap of books on the coffee table",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "book pile"), 1, "{prompt}: {:?}", keys(&s));
        assert!(!s.objects.contains_key("book"), "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_misspelt_object_word_is_the_word_it_misses() {
    for (prompt, want, n) in [
        ("a tabel for six", "chair", 6),
        ("a kitchen with a small tabel and two chairs", "chair", 2),
        (
            "a living room with a sofa and a cofee table",
            "coffee table",
            1,
        ),
        ("a dining room with a sidebaord", "sideboard", 1),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, want), n, "{prompt}: {:?}", keys(&s));
        assert!(
            s.objects
                .keys()
                .all(|c| !c.contains("tabel") && !c.contains("cofee")),
            "{prompt}: {:?}",
            keys(&s)
        );
    }
    // never one letter changed for another, nor a word of grammar made from a name
    let s = plan("a bedroom with a bed and a cable");
    assert_eq!(number(&s, "cable"), 1, "{:?}", keys(&s));
    assert_eq!(number(&s, "dining table"), 0, "{:?}", keys(&s));
    let s = plan("a living room with a sofa shaded by a palm");
    assert_eq!(number(&s, "shade"), 0, "{:?}", keys(&s));
}

#[test]
fn a_known_short_object_word_is_never_mended_into_a_longer_one() {
    // "carts" is a cart's plural, not a slip for "charts" (a flip chart's word)
    // (prompt, category, exact count or None for at least one)
    for (prompt, want, n) in [
        ("a night market with food carts", "hot dog cart", None),
        (
            "a street food court with three food carts",
            "hot dog cart",
            Some(3),
        ),
        ("a farmyard with two carts and a haystack", "cart", Some(2)),
    ] {
        let s = plan(prompt);
        let got = number(&s, want);
        assert!(n.map_or(got >= 1, |n| got == n), "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "flip chart"), 0, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_bare_plural_in_rows_fills_every_row() {
    for (prompt, word, rows) in [
        (
            "a small courtroom with a judge's desk and three rows of benches",
            "bench",
            3,
        ),
        ("a chapel with four rows of pews", "pew", 4),
        ("a lecture room with five rows of chairs", "chair", 5),
    ] {
        let s = plan(prompt);
        let (n, r) = s
            .objects
            .iter()
            .filter(|(c, _)| c.contains(word))
            .map(|(_, o)| (o.number, o.rows))
            .max_by_key(|x| x.0)
            .unwrap_or_else(|| panic!("{prompt}: no {word} in {:?}", keys(&s)));
        assert_eq!(r, rows, "{prompt}: {:?}", keys(&s));
        assert!(n >= 2 * rows, "{prompt}: {n} {word} in {rows} rows");
    }
}

#[test]
fn things_said_to_hang_on_the_wall_are_things_that_hang() {
    for (prompt, cat) in [
        (
            "a classroom with a dozen desks and a map on the wall",
            "wall map",
        ),
        (
            "an office with a desk and a calendar on the wall",
            "calendar",
        ),
        ("a study with a world map above the desk", "wall map"),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, cat), 1, "{prompt}: {:?}", keys(&s));
        let class = dreamscene::plan::gcp::classes::effective_class(&s, cat);
        assert!(
            matches!(class, dreamscene::plan::gcp::classes::Class::OnWall(_)),
            "{prompt}: {class:?}"
        );
    }
}

#[test]
fn a_tea_shop_is_a_cafe() {
    for prompt in [
        "a tea shop with four tables, each with a teapot",
        "a little teashop with a counter",
        "a tea shop",
    ] {
        let s = plan(prompt);
        assert!(number(&s, "cafe") >= 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "display shelf"), 0, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_bare_noun_in_a_place_is_the_place_own_kind_of_it() {
    // a barber's has as many barber chairs as waiting chairs: "chairs" there are its barber chairs
    for (prompt, n) in [
        ("a barber's with four chairs facing mirrors", 4),
        ("a barbershop with two chairs and a sink", 2),
        ("a barbershop with five chairs in a row", 5),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "barber chair"), n, "{prompt}: {:?}", keys(&s));
        assert_ne!(number(&s, "waiting chair"), n, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_lamp_named_on_a_table_is_the_room_lamp_of_its_kind() {
    // a reading lamp on a support is a table lamp, and still the room's standing lamp
    for prompt in [
        "a study with a reading lamp on the desk",
        "a living room with a reading lamp on the side table",
        "a home office with a desk and a reading lamp on the desk",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "table lamp"), 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "floor lamp"), 0, "{prompt}: {:?}", keys(&s));
    }
    // a floor lamp named beside it stays
    let s = plan("a living room with a floor lamp and a reading lamp on the side table");
    assert_eq!(number(&s, "floor lamp"), 1, "{:?}", keys(&s));
}

#[test]
fn seats_named_in_rows_are_the_congregation_in_place_of_the_pews() {
    for prompt in [
        "a church with rows of chairs",
        "a chapel with chairs in rows",
        "a cathedral with four rows of chairs facing the altar",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "pew"), 0, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "dining chair") >= 8, "{prompt}: {:?}", keys(&s));
    }
    // seats not in rows are not the congregation: the pews stay
    let s = plan("a church with two benches");
    assert_eq!(number(&s, "pew"), 6, "{:?}", keys(&s));
}
