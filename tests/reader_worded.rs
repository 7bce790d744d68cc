//! Requests whose wording the reader must read whole: the desks the text counts each keep their
//! chair in a small room, a room size said with its unit ("3 by 4 metres", "12 x 10 ft") leaves
//! no word unused, and a place named like a thing that stands in other places ("a changing
//! room", the fitting room of a shop) is the place, not one of its objects; what is said "instead
//! of" is not wanted, however counted; "a coffe table" is a coffee table. Prompts of no corpus.
mod reading;
use dreamscene::plan::offline::plan_prompt;
use reading::{keys, number, plan};

#[test]
fn each_desk_the_text_counts_keeps_its_chair_in_a_small_room() {
    for (prompt, n) in [
        ("a small office with three desks and a lamp on the desk", 3),
        ("a small study with two desks", 2),
        ("a compact office with four desks and a bookshelf", 4),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "desk"), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "office chair"), n, "{prompt}: {:?}", keys(&s));
    }
    // a seat the text names at the desk takes the chair's place
    let s = plan("a small office with two desks and a gaming chair");
    assert_eq!(
        number(&s, "office chair") + number(&s, "gaming chair"),
        2,
        "{:?}",
        keys(&s)
    );
}

#[test]
fn a_room_size_with_its_unit_leaves_no_word_unused() {
    for (prompt, w) in [
        ("an office of 3 by 4 metres with a desk", 3.0),
        ("a bedroom 12 by 10 feet with a bed", 3.66),
        ("a kitchen of 3 x 4 meters with a table", 3.0),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        assert!(
            p.understood.unused.is_empty(),
            "{prompt}: {:?}",
            p.understood.unused
        );
        let room = p.spec.room.expect("a room").size;
        assert!((room[0] - w).abs() < 0.05, "{prompt}: {room:?}");
    }
}

#[test]
fn a_changing_room_is_the_place_not_a_fitting_room_in_it() {
    for (prompt, lockers) in [
        ("a changing room with three rows of lockers", 6),
        ("a locker room with benches and two showers", 4),
        ("a gym changing room with six lockers and a mirror", 6),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "fitting room"), 0, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "locker") >= lockers, "{prompt}: {:?}", keys(&s));
    }
    // a shop's changing rooms are its fitting rooms
    let s = plan("a clothes shop with two changing rooms and a mirror");
    assert_eq!(number(&s, "fitting room"), 2, "{:?}", keys(&s));
}

#[test]
fn what_is_said_instead_of_is_not_wanted_whatever_its_count() {
    for (prompt, wanted, replaced) in [
        (
            "a bedroom with a double bed instead of two single beds",
            "bed",
            "single bed",
        ),
        (
            "a kids room with a bunk bed instead of two single beds",
            "bunk bed",
            "single bed",
        ),
        (
            "a living room with two armchairs instead of the two sofas",
            "armchair",
            "sofa",
        ),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let s = &p.spec;
        assert_eq!(number(s, replaced), 0, "{prompt}: {:?}", keys(s));
        assert!(number(s, wanted) >= 1, "{prompt}: {:?}", keys(s));
        assert!(
            p.understood.unused.is_empty(),
            "{prompt}: {:?}",
            p.understood.unused
        );
    }
}

/// When what replaces is the same kind as what is replaced ("a rug instead of a carpet": both
/// are rugs to the knowledge base), the words choose which one: the kind is wanted, once.
#[test]
fn a_thing_said_instead_of_one_of_its_own_kind_stays() {
    for prompt in [
        "a kids bedroom with bunk beds, a toy chest and a rug instead of a carpet",
        "a bedroom with a wool rug rather than a carpet",
        "a study where, instead of a carpet, a round rug",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "rug"), 1, "{prompt}: {:?}", keys(&s));
    }
    // another kind said instead is still not wanted
    let s = plan("a living room with a sofa bed instead of a sofa");
    assert!(!s.objects.contains_key("sofa"), "{:?}", keys(&s));
    assert_eq!(number(&s, "sofa bed"), 1, "{:?}", keys(&s));
}

#[test]
fn a_slip_at_a_words_end_is_mended_when_the_next_word_completes_a_name() {
    for prompt in [
        "a livng room with a sofa, an armchiar and a coffe table",
        "a living room with a sofa and a coffe table",
        "a bedroom with a coffe table and a bed",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "coffee table"), 1, "{prompt}: {:?}", keys(&s));
    }
}
