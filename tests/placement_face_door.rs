//! A thing "facing the door" faces it from the room, clear of the door's zone: an armchair or a
//! sofa turned to the door, a desk whose chair faces the door across it (the desk between them,
//! its back to the door), on every seed, placed by its constraints. Prompts of no corpus.
use dreamscene::plan::check::{door_zone, overlap_depth, validity_problems, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Anchor, OpeningKind, PlacedBy, PlacedObject};

/// Degrees between `o`'s facing and the way to the nearest door's centre, and that door.
fn off_door(o: &PlacedObject, l: &dreamscene::plan::spec::Layout) -> f64 {
    let door = l
        .openings
        .iter()
        .filter(|d| d.kind == OpeningKind::Door)
        .min_by(|a, b| {
            let d = |d: &&dreamscene::plan::spec::Opening| {
                (d.position[0] - o.position[0]).hypot(d.position[1] - o.position[1])
            };
            d(a).total_cmp(&d(b))
        })
        .expect("a door");
    let to = [
        door.position[0] - o.position[0],
        door.position[1] - o.position[1],
    ];
    let f = [-o.yaw.to_radians().sin(), o.yaw.to_radians().cos()];
    let c = (to[0] * f[0] + to[1] * f[1]) / to[0].hypot(to[1]);
    c.clamp(-1.0, 1.0).acos().to_degrees()
}

#[test]
fn a_thing_facing_the_door_faces_it_clear_of_its_zone() {
    for (prompt, what) in [
        (
            "a reading corner with an armchair facing the door",
            "armchair",
        ),
        ("a den where the couch faces the door", "sofa"),
        ("a study where the desk faces the door", "office chair"),
        (
            "a home office with a writing desk facing the door",
            "office chair",
        ),
    ] {
        let spec = plan_prompt(prompt).expect("planned").spec;
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).expect("laid out");
            assert!(
                validity_problems(&l, &spec).is_empty(),
                "{prompt} seed {seed}"
            );
            let o = l
                .objects
                .iter()
                .find(|o| o.category == what)
                .unwrap_or_else(|| panic!("{prompt}: no {what}"));
            assert_eq!(o.anchor, Anchor::FaceDoor, "{prompt}");
            assert_eq!(o.placed_by, PlacedBy::Constraint, "{prompt} seed {seed}");
            let off = off_door(o, &l);
            assert!(
                off <= 30.0,
                "{prompt} seed {seed}: {} {off:.0}° off the door",
                o.id
            );
            for d in l.openings.iter().filter(|d| d.kind == OpeningKind::Door) {
                assert!(
                    overlap_depth(&Box2::of(o), &door_zone(d)) <= 0.0,
                    "{prompt} seed {seed}: {} in the door's way",
                    o.id
                );
            }
            // a desk stands between its chair and the door, its back to the door
            if let Some(desk) = l.objects.iter().find(|o| o.category.contains("desk")) {
                assert!(
                    off_door(desk, &l) >= 150.0,
                    "{prompt} seed {seed}: the desk's back"
                );
            }
        }
    }
}
