//! What "no X" takes away: every kind of a noun said alone ("no chairs": an office's visitor
//! chairs as well as its office chairs, a living room's floor lamp with "no lamps"), only the
//! kind said in full ("no dining table" leaves a kitchen's island and its stools), and with it
//! what served only that thing (the visitor chairs around an office's meeting table). And "the
//! desk" the text sets in the room ("an office where the desk faces the window") is its one
//! desk. Prompts of no corpus.
mod reading;
use reading::{keys, number, plan};

#[test]
fn a_negated_noun_takes_every_kind_of_it() {
    for (prompt, word) in [
        ("a coworking space without chairs", "chair"),
        ("a startup office, no chairs please", "chair"),
        ("a family room with no lamps", "lamp"),
        ("a bakery with no tables at all", "table"),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, word), 0, "{prompt}: {:?}", keys(&s));
    }
    // the rest of the place stays
    let s = plan("a coworking space without chairs");
    assert!(number(&s, "desk") >= 2, "{:?}", keys(&s));
    // a noun said alone still names its role ("no bath": no tub of any kind)
    let s = plan("a family bathroom with no bath");
    assert_eq!(number(&s, "tub"), 0, "{:?}", keys(&s));
}

#[test]
fn a_kind_said_in_full_leaves_its_siblings() {
    for prompt in [
        "a farmhouse kitchen with no dining table",
        "a kitchenette but no dining table, please",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "dining table"), 0, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "kitchen island"), 1, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "bar stool") >= 2, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn what_served_only_the_negated_thing_goes_with_it() {
    for prompt in [
        "an open-plan office with no meeting table",
        "a corporate office without a conference table",
    ] {
        let s = plan(prompt);
        assert_eq!(
            number(&s, "conference table"),
            0,
            "{prompt}: {:?}",
            keys(&s)
        );
        assert_eq!(number(&s, "visitor chair"), 0, "{prompt}: {:?}", keys(&s));
        // the desks keep their chairs
        assert_eq!(
            number(&s, "office chair"),
            number(&s, "desk"),
            "{prompt}: {:?}",
            keys(&s)
        );
    }
}

#[test]
fn the_desk_the_text_sets_in_the_room_is_its_one_desk() {
    for prompt in [
        "an open-plan office where the desk faces the window",
        "a workplace where the desk stands by the window",
        "a coworking space where the desk is in the corner",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "desk"), 1, "{prompt}: {:?}", keys(&s));
    }
    // a place's desks said in the plural stay its desks
    let s = plan("an office where the desks face the window");
    assert!(number(&s, "desk") >= 2, "{:?}", keys(&s));
}

/// "no X, Y facing Z": a comma alone carries "no" only through a list an "or" or "nor" ends
/// ("no rugs, curtains or lamps"); what follows "no X," without one is there.
#[test]
fn a_comma_after_what_is_not_there_lists_what_is() {
    for (prompt, word) in [
        (
            "snug den, no television, sofa under the window and a bookcase",
            "sofa",
        ),
        (
            "attic bedroom - no wardrobe, double bed under the skylight",
            "bed",
        ),
    ] {
        let s = plan(prompt);
        assert!(number(&s, word) >= 1, "{prompt}: {:?}", keys(&s));
    }
    for (prompt, gone) in [
        (
            "a study with no rug, curtains or lamps, just a desk and a chair",
            ["rug", "curtain", "lamp"],
        ),
        (
            "a guest room without a tv, a mirror, nor a rug",
            ["tv", "mirror", "rug"],
        ),
    ] {
        let s = plan(prompt);
        for w in gone {
            assert_eq!(number(&s, w), 0, "{prompt}: {w} in {:?}", keys(&s));
        }
        assert!(
            number(&s, "desk") + number(&s, "bed") >= 1,
            "{prompt}: {:?}",
            keys(&s)
        );
    }
}

/// "it's not a sports bar": what the place is said not to be takes no thing of it away (the
/// bar counter of a pub stays).
#[test]
fn what_the_place_is_not_takes_nothing_away() {
    for prompt in [
        "a cosy wine bar with a few tables, no telly - it's not a sports bar",
        "a quiet village pub, open fire, and no it isn't a cocktail bar",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "bar counter"), 1, "{prompt}: {:?}", keys(&s));
    }
    // "no bar" still takes it away
    let s = plan("a pub with no bar, just tables");
    assert_eq!(number(&s, "bar counter"), 0, "{:?}", keys(&s));
}
