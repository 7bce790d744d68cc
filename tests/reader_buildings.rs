//! A building one is inside stays indoors wherever it stands ("a cabin in the forest", "a chapel
//! on the hill"), while a place that is a room by default said to be in an outdoor ground is out
//! of doors ("a wedding ceremony in a garden"); a cabin's stove is a wood stove ("log burner",
//! "pot-belly stove"), a kitchen's stove still its range.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{SceneSpec, SceneType};

fn spec(prompt: &str) -> SceneSpec {
    plan_prompt(prompt)
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
        .spec
}

#[test]
fn a_building_in_an_outdoor_place_is_indoors() {
    for (prompt, has) in [
        ("a cabin in the forest with a bunk bed", "bunk bed"),
        ("a log cabin in the mountains", "wood stove"),
        (
            "a hunting cabin in the woods with a rocking chair",
            "rocking chair",
        ),
        ("a ski chalet in the snow with two sofas", "sofa"),
        ("a small chapel on the hill with six pews", "pew"),
    ] {
        let s = spec(prompt);
        assert_eq!(s.scene_type, SceneType::Indoor, "{prompt}");
        assert!(
            s.objects.contains_key(has),
            "{prompt}: {:?}",
            s.objects.keys()
        );
        // no forest inside the room
        assert!(
            !s.objects.contains_key("tree"),
            "{prompt}: {:?}",
            s.objects.keys()
        );
    }
    for prompt in [
        "a wedding ceremony in a garden",
        "a yoga class on the beach",
    ] {
        assert_eq!(spec(prompt).scene_type, SceneType::Outdoor, "{prompt}");
    }
}

#[test]
fn a_wood_stove_is_its_own_kind() {
    for prompt in [
        "a living room with a log burner and two armchairs",
        "a cabin with a pot-belly stove",
        "a den with a wood-burning stove",
    ] {
        let s = spec(prompt);
        assert!(
            s.objects.contains_key("wood stove"),
            "{prompt}: {:?}",
            s.objects.keys()
        );
        assert!(!s.objects.contains_key("stove"), "{prompt}");
    }
    let s = spec("a kitchen with a stove and a fridge");
    assert!(s.objects.contains_key("stove") && !s.objects.contains_key("wood stove"));
}
