//! An object word said before a person who works with it ("a piano teacher's studio", "the
//! bike mechanic") names no object: the person is no thing of the place (WordNet's nouns whose
//! first sense is a person). A runner is a long narrow rug, and a named one fits a narrow
//! stated hallway. Pictures and photos are framed pictures on a wall, and said ones are the
//! place's wall pictures (no default paintings besides). Prompts of no corpus.
mod reading;
use reading::{keys, number, plan};

#[test]
fn an_object_word_before_a_person_names_no_object() {
    for (prompt, cat, n) in [
        (
            "a piano teacher's studio with an upright piano, a stool and a sofa",
            "piano",
            1,
        ),
        (
            "a guitar teacher's room with two guitars on stands and two chairs",
            "guitar",
            2,
        ),
        (
            "bike mechanic's workshop: a workbench, a stool and a parts shelf",
            "bicycle",
            0,
        ),
        (
            "a room for the drum tutor: one drum kit, a stool and a speaker",
            "drum kit",
            1,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, cat), n, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_runner_is_a_long_narrow_rug_that_a_narrow_hallway_takes() {
    for prompt in [
        "narrow hallway 1.1 x 4 m with a hall runner down the middle and a coat rack",
        "entrance corridor, 1 by 6 metres: a runner rug, a shoe bench and two pictures",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "runner rug"), 1, "{prompt}: {:?}", keys(&s));
        assert!(!s.objects.contains_key("rug"), "{prompt}: {:?}", keys(&s));
        let l = dreamscene::plan::gcp::layout(&s, dreamscene::plan::gcp::LayoutOptions::seeded(0))
            .unwrap_or_else(|e| panic!("{prompt}: {e}"));
        assert!(dreamscene::plan::check::validity_problems(&l, &s).is_empty());
    }
}

#[test]
fn pictures_and_photos_are_framed_pictures_that_stand_for_the_default_paintings() {
    for (prompt, n) in [
        ("a landing with two pictures and a small table", 2),
        (
            "a nail bar with framed photos of nails on the wall and two manicure tables",
            2,
        ),
        ("gallery corner: five framed prints and a bench", 5),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "picture"), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "painting"), 0, "{prompt}: {:?}", keys(&s));
    }
}
