//! The place a compound names: the last noun is the place ("a city hall meeting room" is a
//! meeting room, "a village hall kitchen" a kitchen); "hall" after a noun is a large hall of
//! that kind ("a music hall", "a yoga hall"), or a hall where people gather when no place
//! starts with the noun ("an expo hall"), while "a narrow hall" and "an entrance hall" stay the
//! hallway; open-air words put a room out of doors ("an open-air yoga class"); a ceremony is
//! rows of chairs facing an arch, split by an aisle. Prompts of no corpus.
mod reading;
use dreamscene::plan::check::validity_problems;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::plan::spec::{SceneSpec, SceneType};
use reading::{keys, number, plan};

fn scene_of(prompt: &str) -> String {
    let kb = KnowledgeBase::builtin();
    let r = dreamscene::plan::lang::read(kb, prompt);
    r.scene
        .map(|(i, _, _)| kb.scenes[i].name.clone())
        .unwrap_or_default()
}

fn area(s: &SceneSpec) -> f64 {
    let r = s.room.as_ref().expect("a room").size;
    r[0] * r[1]
}

#[test]
fn the_last_place_noun_of_a_compound_is_the_place() {
    for (prompt, scene) in [
        ("a city hall meeting room", "conference room"),
        ("a village hall kitchen", "kitchen"),
        ("a museum cafe with six tables", "cafe"),
        ("a school library reading room", "library"),
        ("an expo hall", "assembly hall"),
        ("a congress hall with a stage", "assembly hall"),
        ("a music hall", "music room"),
        ("a yoga hall", "yoga studio"),
        ("a long narrow hall with a coat rack", "hallway"),
        ("an entrance hall", "hallway"),
    ] {
        assert_eq!(scene_of(prompt), scene, "{prompt}");
    }
}

#[test]
fn a_hall_of_a_kind_is_larger_than_the_room_of_it() {
    for (hall, room) in [
        ("a music hall", "a music room"),
        ("a yoga hall", "a yoga studio"),
        ("a gallery hall", "a gallery"),
    ] {
        let (h, r) = (plan(hall), plan(room));
        assert!(
            area(&h) >= 1.8 * area(&r),
            "{hall}: {:.1} m² against {room}: {:.1} m²",
            area(&h),
            area(&r)
        );
    }
    // a hallway is no large hall, and a hall said small stays small
    let (h, r) = (plan("a long narrow hall"), plan("a hallway"));
    assert!(
        area(&h) <= area(&r) + 0.01,
        "{:.1} {:.1}",
        area(&h),
        area(&r)
    );
    let (h, r) = (plan("a small music hall"), plan("a music hall"));
    assert!(area(&h) < area(&r), "{:.1} {:.1}", area(&h), area(&r));
}

#[test]
fn open_air_words_put_a_room_out_of_doors() {
    for prompt in [
        "an open-air yoga class",
        "an outdoor cinema with a big screen",
        "a wedding ceremony outdoors",
        "an alfresco ceremony with sixty chairs",
    ] {
        assert_eq!(plan(prompt).scene_type, SceneType::Outdoor, "{prompt}");
    }
    // said of a thing, not of the place
    for prompt in ["a kitchen that opens onto an outdoor patio", "a classroom"] {
        assert_eq!(plan(prompt).scene_type, SceneType::Indoor, "{prompt}");
    }
}

#[test]
fn a_ceremony_is_rows_of_chairs_facing_an_arch_with_an_aisle() {
    for prompt in [
        "an open-air wedding ceremony on the lawn",
        "a small civil ceremony",
        "a wedding ceremony with a floral arch and rows of chairs",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "arch"), 1, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "chair") >= 8, "{prompt}: {:?}", keys(&s));
        assert_eq!(
            number(&s, "dance floor") + number(&s, "dj booth"),
            0,
            "{prompt}"
        );
        for seed in 0..3 {
            let l = layout(&s, LayoutOptions::seeded(seed)).expect("laid out");
            assert!(validity_problems(&l, &s).is_empty(), "{prompt} seed {seed}");
            assert!(
                l.unsatisfied.is_empty(),
                "{prompt} seed {seed}: {:?}",
                l.unsatisfied
            );
            let arch = l
                .objects
                .iter()
                .find(|o| o.category.contains("arch"))
                .expect("arch");
            // an aisle from the arch: no chair on the arch's centre line
            let (ax, ay) = (arch.position[0], arch.position[1]);
            let (fx, fy) = (-arch.yaw.to_radians().sin(), arch.yaw.to_radians().cos());
            for c in l.objects.iter().filter(|o| o.category.contains("chair")) {
                let (dx, dy) = (c.position[0] - ax, c.position[1] - ay);
                let across = (dx * fy - dy * fx).abs();
                assert!(across > 0.45, "{prompt} seed {seed}: {} in the aisle", c.id);
            }
        }
    }
}
