//! "each" that distributes and "each" that does not: "next to each other" and "facing each
//! other" are reciprocal (three booths next to each other are three booths, not three per desk
//! named before), and an item of a list after "X each with Y" that the text sets by the room's
//! walls, corners or door is an item of its own. Prompts of no corpus.
mod reading;
use reading::{keys, number, plan};

#[test]
fn each_other_is_reciprocal_not_distributive() {
    for (prompt, word, n) in [
        (
            "an office with eight standing desks, three phone booths next to each other",
            "phone booth",
            3,
        ),
        (
            "a library with six reading tables and two armchairs facing each other",
            "armchair",
            2,
        ),
        (
            "a games room with four pool tables, two arcade machines side by side and two sofas facing one another",
            "sofa",
            2,
        ),
        (
            "a lounge with five coffee tables and three beanbags next to each other",
            "bean bag",
            3,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, word), n, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_list_item_set_by_the_room_is_not_each_owners() {
    for (prompt, word, n) in [
        (
            "an office with eight desks each with a laptop and three phone booths along the east wall",
            "phone booth",
            3,
        ),
        (
            "a classroom with twenty desks each with a chair and a whiteboard on the front wall",
            "whiteboard",
            1,
        ),
        (
            "a studio with four easels each with a stool and two sinks in the corner",
            "sink",
            2,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, word), n, "{prompt}: {:?}", keys(&s));
    }
    // what each owner has is still each owner's
    let s = plan(
        "an office with eight desks each with a laptop and three phone booths along the east wall",
    );
    assert_eq!(number(&s, "laptop"), 8, "{:?}", keys(&s));
    let s = plan("a cafe with four tables each with a vase and two chairs");
    assert_eq!(number(&s, "vase"), 4, "{:?}", keys(&s));
    assert_eq!(number(&s, "chair"), 8, "{:?}", keys(&s));
}
