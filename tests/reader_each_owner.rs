//! Whose "each" it is: "X by the window each with Y" gives every X its Y and does not make X
//! a count per something named before ("bread shelves ... two tables each with 2 chairs" are two
//! tables, not two per shelf); and "a nightstand on either side of it, a lamp on each
//! nightstand" counts two nightstands, one a side of the bed, not nightstands per nightstand.
//! Prompts of no corpus.
mod reading;
use reading::{keys, number, plan};

#[test]
fn each_with_after_a_placement_is_what_each_has() {
    for (prompt, word, n, seat, per) in [
        (
            "a bakery with bread shelves on the back wall and two little tables by the window each with 2 chairs",
            "table",
            2,
            "chair",
            2,
        ),
        (
            "a library with tall bookcases along the walls and three study tables in the middle each with four chairs",
            "table",
            3,
            "dining chair",
            4,
        ),
        (
            "a terrace with planters along the railing and two tables near the door each with three chairs",
            "table",
            2,
            "chair",
            3,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, word), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, seat), n * per, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn either_side_of_it_is_the_thing_just_named() {
    for (prompt, word, n, on, k) in [
        (
            "a bedroom with a king bed with a nightstand on either side of it, a lamp on each nightstand",
            "nightstand",
            2,
            "lamp",
            2,
        ),
        (
            "a living room: a sofa with a side table on either side of it and a lamp on each side table",
            "side table",
            2,
            "lamp",
            2,
        ),
        (
            "a hall with a console table, a vase on each end of it",
            "vase",
            2,
            "console table",
            1,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, word), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, on), k, "{prompt}: {:?}", keys(&s));
    }
}
