//! Seats OPPOSITE a screen see it: a seat counts as facing the screen only when it faces both the
//! screen's centre and the nearest point of its footprint, so a sofa put beside a wide screen's
//! end and turned to its centre is not taken for one in front of it; two sofas asked to face
//! one screen both see it on every seed.
use dreamscene::plan::check::{facing_footprint_error, relation_holds_box, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::RelationKind;

#[test]
fn a_sofa_beside_a_screens_end_is_not_opposite_it() {
    // a 3.1 m screen on the south wall, facing +y
    let screen = Box2::new([0.2, -2.2], 0.0, [3.1, 0.13], 0.6, 2.6);
    // centred in front, facing it
    let front = Box2::new([0.2, 0.4], 180.0, [2.1, 0.95], 0.0, 0.85);
    assert!(relation_holds_box(&front, RelationKind::Opposite, &screen));
    // along the west wall beside the screen's end, facing +x: its centre 29° off
    let beside = Box2::new([-1.83, -1.07], -90.0, [2.1, 0.95], 0.0, 0.85);
    assert!(!relation_holds_box(
        &beside,
        RelationKind::Opposite,
        &screen
    ));
}

#[test]
fn sofas_asked_to_face_a_screen_see_it() {
    for prompt in [
        "a karaoke room. Two sofas facing a big screen on the wall, a coffee table between them and a microphone stand",
        "a media room with two sofas facing a projector screen",
        "a living room with two sofas facing the tv",
    ] {
        let spec = plan_prompt(prompt).expect("planned").spec;
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).expect("laid out");
            let screen = l
                .objects
                .iter()
                .find(|o| o.category.contains("screen") || o.category == "tv")
                .expect("a screen");
            for sofa in l.objects.iter().filter(|o| o.category == "sofa") {
                let off = facing_footprint_error(&Box2::of(sofa), &Box2::of(screen));
                assert!(off <= 40.0, "{prompt} seed {seed}: {} {off:.0}° off", sofa.id);
            }
        }
    }
}
