//! Things everyday prompts name that were read as a near thing of another look, or as nothing:
//! a sectional (an L-shaped corner sofa) was a straight sofa, a pulpit a lectern, a squat rack a
//! dumbbell rack; string lights, a play kitchen (its "kitchen" taken for the place) and a hoard
//! of gold were dropped or drawn as a box; a bowl, toys, a sack of presents and a periscope were
//! boxes. Each is now its own category. And
//! the owner a place is named after ("a horse's stable") is the one the text names again, not a
//! second one. Plan-only, cheap in debug.
mod reading;
use dreamscene::shape::{archetype_of, DEFAULT_ARCHETYPE};
use reading::{keys, number, plan};

/// Every prompt's plan holds `want` and none of `not`.
fn reads(prompts: &[&str], want: &str, not: &[&str]) {
    for prompt in prompts {
        let spec = plan(prompt);
        assert!(
            spec.objects.contains_key(want),
            "{prompt}: no {want}: {:?}",
            keys(&spec)
        );
        for n in not {
            assert!(
                !spec.objects.contains_key(*n),
                "{prompt}: {n}: {:?}",
                keys(&spec)
            );
        }
    }
}

#[test]
fn a_sectional_is_an_l_shaped_sofa_of_its_own() {
    reads(
        &[
            "a den with an l-shaped couch facing the tv",
            "a basement lounge with a corner sofa and a shaggy rug",
            "an open-plan living area with a grey sectional and a coffee table",
        ],
        "sectional sofa",
        &["sofa"],
    );
    assert_ne!(archetype_of("sectional sofa"), archetype_of("sofa"));
}

#[test]
fn a_pulpit_is_raised_and_enclosed_not_a_lectern() {
    reads(
        &[
            "a stone chapel with a carved pulpit and rows of pews",
            "a cathedral nave with a pulpit near the altar",
        ],
        "pulpit",
        &["lectern"],
    );
    assert_ne!(archetype_of("pulpit"), archetype_of("lectern"));
}

#[test]
fn a_hanging_scroll_is_no_framed_painting() {
    reads(
        &["a tea house room with a wall scroll and floor cushions"],
        "hanging scroll",
        &["painting"],
    );
    assert_ne!(archetype_of("hanging scroll"), archetype_of("painting"));
}

#[test]
fn string_lights_a_squat_rack_and_a_play_kitchen_are_things() {
    reads(
        &[
            "a garden patio with festoon lights and a bench",
            "a teenager's bedroom with fairy lights along the wall",
        ],
        "string lights",
        &[],
    );
    reads(
        &["a garage gym with a power rack and a flat bench"],
        "squat rack",
        &[],
    );
    reads(
        &[
            "a nursery with a toy kitchen and a rocking chair",
            "a kids' playroom with a play kitchen and a box of blocks",
        ],
        "play kitchen",
        &["refrigerator", "stove"],
    );
    for c in ["string lights", "squat rack", "play kitchen", "bowl"] {
        assert_ne!(archetype_of(c), DEFAULT_ARCHETYPE, "{c}");
    }
    reads(
        &["an entrance hall with a console table and a bowl for keys"],
        "bowl",
        &[],
    );
}

#[test]
fn a_lair_holds_its_dragon_once_and_its_gold_as_a_hoard() {
    for prompt in [
        "a dragon's cave with a sleeping dragon on a pile of gold",
        "a dragon's cave with a dragon and a hoard of gold",
    ] {
        let spec = plan(prompt);
        assert_eq!(number(&spec, "dragon"), 1, "{prompt}: {:?}", keys(&spec));
        assert!(
            spec.objects.contains_key("treasure hoard"),
            "{prompt}: {:?}",
            keys(&spec)
        );
    }
    let spec = plan("a horse's stable with a horse and a hay bale");
    assert_eq!(number(&spec, "horse"), 1, "{:?}", keys(&spec));
    for c in ["dragon", "treasure hoard"] {
        assert_ne!(archetype_of(c), DEFAULT_ARCHETYPE, "{c}");
    }
}

#[test]
fn toys_a_sack_of_presents_and_a_periscope_are_drawn_as_themselves() {
    reads(
        &["a toymaker's workshop with two workbenches, a wooden toy on each and a sack of presents by the door"],
        "toys",
        &[],
    );
    reads(
        &["a post room at christmas with a sack of gifts and a table"],
        "sack of presents",
        &[],
    );
    reads(
        &["a submarine's control room with a periscope and two consoles"],
        "periscope",
        &[],
    );
    for c in ["toys", "sack of presents", "periscope"] {
        assert_ne!(archetype_of(c), DEFAULT_ARCHETYPE, "{c}");
    }
}
