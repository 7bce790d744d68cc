//! The place a request is inside: "my garden shed" or "the tool shed" is the shed's inside,
//! not a garden with a shed in it; a camper van's or caravan's inside is a small room; the
//! aisle between pews or chairs is a way between things, not a thing. And a thing that stands
//! on a top, said to be on the wall ("a monitor on the wall"), hangs there. Plan and layout
//! only; prompts of no corpus.
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneType;

#[test]
fn a_named_shed_or_van_is_the_room() {
    for prompt in [
        "my garden shed: a potting bench along the back wall and a stool in the corner",
        "the old tool shed, with a workbench, a lawnmower and shelves on the wall",
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert_eq!(p.spec.scene_type, SceneType::Indoor, "{prompt}");
        assert!(
            !p.spec.objects.contains_key("shed"),
            "{prompt}: a shed inside the shed"
        );
        let room = p.spec.room.as_ref().expect("room").size;
        assert!(room[0] * room[1] <= 16.0, "{prompt}: {room:?}");
    }
    // a garden that has a shed keeps it as a thing
    let p = plan_prompt("a garden with a garden shed in the corner and a lawn").expect("garden");
    assert_eq!(p.spec.scene_type, SceneType::Outdoor);
    assert!(p.spec.objects.contains_key("shed"));
    for prompt in [
        "inside our caravan: a little table with two benches and a bed at the back",
        "a motorhome with a bed, a small stove and a sink",
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert_eq!(p.spec.scene_type, SceneType::Indoor, "{prompt}");
        let room = p.spec.room.as_ref().expect("room").size;
        assert!(room[0] * room[1] <= 16.0, "{prompt}: {room:?}");
        assert!(!p.spec.objects.contains_key("van"), "{prompt}");
    }
}

#[test]
fn an_aisle_is_no_thing() {
    for prompt in [
        "a small church with six pews either side of the aisle and an altar",
        "a wedding venue with rows of chairs and an aisle down the middle to an arch",
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        assert!(
            !p.spec.objects.keys().any(|c| c.contains("aisle")),
            "{prompt}: {:?}",
            p.spec.objects.keys().collect::<Vec<_>>()
        );
    }
}

#[test]
fn a_thing_of_a_top_said_on_the_wall_hangs() {
    for (prompt, cat) in [
        (
            "a security office with a desk, two chairs and a monitor on the wall",
            "monitor",
        ),
        (
            "a garage with a workbench and a small speaker mounted on the wall",
            "speaker",
        ),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        let l = layout(&p.spec, LayoutOptions::seeded(0)).expect(prompt);
        let hung: Vec<_> = l.objects.iter().filter(|o| o.category == cat).collect();
        assert!(!hung.is_empty(), "{prompt}: no {cat}");
        for o in hung {
            assert!(
                o.position[2] > 0.8,
                "{prompt}: {} at z={}",
                o.id,
                o.position[2]
            );
        }
    }
}
