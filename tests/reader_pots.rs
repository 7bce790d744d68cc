//! A pot is what the place makes it: a plant pot on a balcony, a patio or in a potting shed, a
//! cooking pot in a kitchen (on the stove), a cauldron only when said; a potting shed and a
//! greenhouse are places of their own (a bench of pots, plants, a watering can), not a garden
//! shed standing in a room; each kind has a drawing of its own function.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;
use dreamscene::shape::archetype_of;

fn spec(prompt: &str) -> SceneSpec {
    plan_prompt(prompt)
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
        .spec
}

fn has(s: &SceneSpec, c: &str) -> bool {
    s.objects.get(c).is_some_and(|o| o.number > 0)
}

#[test]
fn a_pot_is_what_its_place_makes_it() {
    for (prompt, kind) in [
        ("a sunny terrace with clay pots of geraniums", "plant pot"),
        (
            "a roof garden with flowerpots along the railing",
            "plant pot",
        ),
        ("a small kitchen with a saucepan on the hob", "cooking pot"),
        (
            "a restaurant kitchen with big pots on the stoves",
            "cooking pot",
        ),
    ] {
        let s = spec(prompt);
        let keys: Vec<&String> = s.objects.keys().collect();
        assert!(has(&s, kind), "{prompt}: {keys:?}");
        assert!(!has(&s, "cauldron"), "{prompt}: a cauldron: {keys:?}");
    }
    assert!(has(
        &spec("a witch's cottage with a cauldron by the fire"),
        "cauldron"
    ));
}

#[test]
fn a_potting_shed_and_a_greenhouse_are_places() {
    for prompt in [
        "a cluttered potting shed",
        "a gardener's shed with seed trays and pots",
        "a warm greenhouse with rows of seedlings",
        "a glasshouse full of orchids",
    ] {
        let s = spec(prompt);
        let keys: Vec<&String> = s.objects.keys().collect();
        assert!(
            !has(&s, "shed") && !has(&s, "greenhouse"),
            "{prompt}: {keys:?}"
        );
        assert!(
            has(&s, "workbench") || has(&s, "potted plant"),
            "{prompt}: {keys:?}"
        );
        assert!(
            s.room.is_some_and(|r| r.size[0] * r.size[1] < 40.0),
            "{prompt}: {:?}",
            s.room
        );
    }
    // a garden keeps its shed and a greenhouse standing in it
    let s = spec("a garden with a greenhouse and a shed");
    assert!(
        has(&s, "greenhouse") && has(&s, "shed"),
        "{:?}",
        s.objects.keys()
    );
}

#[test]
fn pots_are_drawn_as_what_they_are() {
    assert_eq!(archetype_of("plant pot"), archetype_of("potted plant"));
    assert_ne!(archetype_of("cooking pot"), archetype_of("cauldron"));
    assert_ne!(archetype_of("cooking pot"), archetype_of("pail"));
}
