//! A bare singular noun after a preposition, said in passing ("so we can watch from bed", "a
//! lamp to read in bed"), is the thing already named: no second one. Prompts of no corpus.
mod reading;
use dreamscene::plan::offline::plan_prompt;
use reading::{keys, number};

#[test]
fn a_thing_said_in_passing_after_a_preposition_is_the_one_named() {
    for (prompt, cat, n) in [
        (
            "master bedroom: a queen bed, a dresser and a tv on the wall to watch from bed",
            "bed",
            1,
        ),
        (
            "a guest room with a single bed and a lamp for reading in bed",
            "bed",
            1,
        ),
        (
            "a study with a desk by the window, and a shelf I can reach from desk",
            "desk",
            1,
        ),
    ] {
        let s = plan_prompt(prompt)
            .unwrap_or_else(|e| panic!("{prompt}: {e}"))
            .spec;
        assert_eq!(number(&s, cat), n, "{prompt}: {:?}", keys(&s));
    }
}
