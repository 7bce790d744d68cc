//! Small places people name and the things in them: the inside of a boat, a food van, an
//! ambulance, a sleeper compartment, a recording booth, a galley kitchen are small rooms; a
//! room said to be the size of a broom cupboard is tiny; a bunk is one bed of a bunk bed; an
//! unknown thing said bare and put by the door, in a corner or at a wall is a thing, and so is
//! one counted by "a couple of"; "railings" is no slip of "trailing". Plan only; prompts of no
//! corpus.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneType;

fn area(prompt: &str) -> f64 {
    let p = plan_prompt(prompt).expect(prompt);
    assert_eq!(p.spec.scene_type, SceneType::Indoor, "{prompt}");
    let r = p.spec.room.as_ref().expect("room").size;
    r[0] * r[1]
}

#[test]
fn vehicles_and_compartments_are_small_rooms() {
    for (prompt, most) in [
        (
            "a canal boat cabin with a table, a bench on each side and a log burner",
            16.0,
        ),
        (
            "inside a burger van: a fryer, a hotplate and a fridge",
            14.0,
        ),
        (
            "an ambulance interior with a gurney, a bench and an oxygen tank",
            12.0,
        ),
        ("a train compartment with a bunk bed and a little sink", 8.0),
        ("a voice-over booth with a microphone and a stool", 6.0),
        (
            "a narrow galley kitchen with a cooker, a sink and a fridge",
            12.0,
        ),
        ("a shoebox office with a desk and a chair", 8.0),
    ] {
        let a = area(prompt);
        assert!(a <= most, "{prompt}: {a:.1} m² (want <= {most})");
    }
    // the van named as a thing of a street is a thing there
    let p = plan_prompt("a street market with a food truck and four stalls").expect("market");
    assert_eq!(p.spec.scene_type, SceneType::Outdoor);
    assert!(
        p.spec.objects.contains_key("food truck"),
        "{:?}",
        p.spec.objects.keys()
    );
}

#[test]
fn the_things_of_small_places_are_known() {
    for (prompt, cat) in [
        (
            "inside a burger van: a fryer, a hotplate and a fridge",
            "deep fryer",
        ),
        (
            "inside a burger van: a fryer, a hotplate and a fridge",
            "griddle",
        ),
        (
            "an ambulance interior with a gurney, a bench and an oxygen tank",
            "stretcher",
        ),
        (
            "an ambulance interior with a gurney, a bench and an oxygen tank",
            "gas cylinder",
        ),
        (
            "an arcade with a one-armed bandit and a claw machine",
            "slot machine",
        ),
        (
            "a sewing room with my tailor's dummy in the corner",
            "mannequin",
        ),
        (
            "a clinic room with an examination couch and a desk",
            "examination table",
        ),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert!(
            p.spec.objects.contains_key(cat),
            "{prompt}: no {cat} in {:?}",
            p.spec.objects.keys()
        );
    }
}

#[test]
fn a_bunk_is_one_bed_of_a_bunk_bed() {
    let p = plan_prompt("a ship's cabin with four bunks and a small desk").expect("cabin");
    assert_eq!(p.spec.objects.get("bunk bed").map(|o| o.number), Some(2));
    let p = plan_prompt("a dormitory with four bunk beds").expect("dorm");
    assert_eq!(p.spec.objects.get("bunk bed").map(|o| o.number), Some(4));
}

#[test]
fn unknown_things_put_somewhere_or_counted_are_things() {
    for (prompt, word) in [
        (
            "a games room, pool table in the middle, shuffleboard by the door",
            "shuffleboard",
        ),
        (
            "my workshop: a workbench, a bandsaw, spindle sander in the corner",
            "sander",
        ),
        (
            "a balcony with a couple of sunloungers and a plant",
            "sunlounger",
        ),
        (
            "a cellar, wine racks along the walls, cider press against the wall",
            "press",
        ),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert!(
            p.spec.objects.keys().any(|c| c.contains(word)),
            "{prompt}: nothing of {word} in {:?}",
            p.spec.objects.keys()
        );
    }
    // a bare word put nowhere stays a word
    let p = plan_prompt("a study with sunlight, a desk and a chair").expect("study");
    assert!(!p.spec.objects.keys().any(|c| c.contains("sunlight")));
    // what a thing is said to have or be loaded with is no thing put at the wall: the place
    // is said of the thing before
    for (prompt, word) in [
        ("a study with a desk with drawers by the window", "drawer"),
        (
            "a barn with a cart loaded with hay bundles against the wall",
            "bundle",
        ),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert!(
            !p.spec.objects.keys().any(|c| c.contains(word)),
            "{prompt}: {:?}",
            p.spec.objects.keys()
        );
    }
    // and a word of its own is not mended into an object's name
    let p = plan_prompt("a roof terrace with planters along the railings").expect("terrace");
    assert!(
        !p.spec
            .objects
            .keys()
            .any(|c| c.contains("trailing") || c.contains("hanging plant")),
        "{:?}",
        p.spec.objects.keys()
    );
}

/// Everyday names of things and places: an open fire is a fireplace, claw machines are arcade
/// cabinets, an amusement arcade is a games room, not a beach because it is by the sea.
#[test]
fn everyday_names_of_fires_and_arcades() {
    let p = plan_prompt("a snug with two armchairs by a roaring log fire").expect("snug");
    assert!(
        p.spec.objects.contains_key("fireplace"),
        "{:?}",
        p.spec.objects.keys()
    );
    let p = plan_prompt("a seaside amusement arcade with three claw machines").expect("arcade");
    assert_eq!(p.spec.scene_type, SceneType::Indoor);
    assert_eq!(
        p.spec.objects.get("arcade machine").map(|o| o.number),
        Some(3),
        "{:?}",
        p.spec.objects.keys()
    );
}
