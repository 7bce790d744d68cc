//! Requests that change what they said before, as a user does in a dialogue: a later count of
//! the same thing replaces the earlier ("four chairs. Actually make it six chairs"), "swap X for
//! Y" / "replace X with Y" takes X away and puts Y in; what a named thing is said to hold ("a
//! rack of paint cans") is said back with it. Prompts of no corpus.
mod reading;
use dreamscene::plan::offline::plan_prompt;
use reading::{keys, number, plan};

#[test]
fn a_later_count_of_the_same_thing_replaces_the_earlier() {
    for (prompt, cat, n) in [
        (
            "A dining room with a table and four chairs. Actually make it six chairs, and swap the rug for a sideboard.",
            "dining chair",
            6,
        ),
        (
            "A dining room with a table and four chairs. Change that to eight chairs.",
            "dining chair",
            8,
        ),
        (
            "A kitchen with a table and two stools. Actually make it three stools.",
            "bar stool",
            3,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, cat), n, "{prompt}: {:?}", keys(&s));
    }
    // counts that are no restatement still add up
    let s = plan("An office with two desks, two chairs by the desk and two chairs by the window");
    assert_eq!(number(&s, "office chair"), 4, "{:?}", keys(&s));
}

#[test]
fn swap_and_replace_take_the_first_away_and_put_the_second_in() {
    for prompt in [
        "A dining room with a table and four chairs. Actually make it six chairs, and swap the rug for a sideboard.",
        "A dining room with a table, chairs and a rug. Replace the rug with a sideboard.",
        "A living room with a sofa and a rug; swap the rug for a bookshelf.",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "rug"), 0, "{prompt}: {:?}", keys(&s));
        assert!(
            number(&s, "sideboard") + number(&s, "bookshelf") >= 1,
            "{prompt}: {:?}",
            keys(&s)
        );
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        assert!(
            p.understood.unused.is_empty(),
            "{prompt}: {:?}",
            p.understood.unused
        );
    }
}

#[test]
fn what_a_named_thing_holds_is_said_back_with_it() {
    for (prompt, cat, what) in [
        (
            "a hardware store with a rack of paint cans",
            "rack",
            "paint cans",
        ),
        (
            "a study with a crate of old records",
            "crate",
            "old records",
        ),
        (
            "a library with a bookcase full of books",
            "bookshelf",
            "books",
        ),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let b = p
            .understood
            .objects
            .iter()
            .find(|b| b.category.contains(cat))
            .unwrap_or_else(|| panic!("{prompt}: {:?}", p.understood.objects));
        assert!(
            b.why.ends_with(&format!("full of {what}")),
            "{prompt}: {}",
            b.why
        );
    }
}

#[test]
fn a_bare_restated_number_counts_the_last_counted_thing() {
    for (prompt, cat, n) in [
        (
            "A dining room with a table and four chairs. Actually make it six.",
            "dining chair",
            6,
        ),
        (
            "A cafe with four tables and a sofa. Make it six tables and lose the sofa.",
            "cafe table",
            6,
        ),
        (
            "A classroom with a teacher's desk and twenty desks. Change that to twelve.",
            "desk",
            13,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, cat), n, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn the_words_of_a_remover_of_two_words_are_used() {
    for (prompt, gone) in [
        ("a bedroom with a bed and a tv; take out the tv", "tv"),
        (
            "a living room with a sofa and a rug; swap out the rug for a bookshelf",
            "rug",
        ),
        (
            "a study with a desk and a globe, leave out the globe",
            "globe",
        ),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        assert!(
            p.understood.unused.is_empty(),
            "{prompt}: {:?}",
            p.understood.unused
        );
        assert_eq!(number(&p.spec, gone), 0, "{prompt}: {:?}", keys(&p.spec));
    }
}
