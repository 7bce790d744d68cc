//! The offline planner on free text: scene types and synonyms, named objects with counts and
//! adjectives, room sizes, placement phrases, style words; and layouts of the planned specs.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::plan::check::{anchor_holds, relation_holds, validity_problems};
use dreamscene::plan::gcp::{layout, LayoutOptions, INDOOR_OCCUPANCY};
use dreamscene::plan::offline::{parse_room_size, plan_offline};
use dreamscene::plan::spec::*;
use std::collections::BTreeMap;

#[test]
fn room_sizes_in_the_ways_people_write_them() {
    assert_eq!(parse_room_size("a 4m x 5m office"), Some([4.0, 5.0]));
    assert_eq!(parse_room_size("a study, 5 x 4 m"), Some([5.0, 4.0]));
    assert_eq!(parse_room_size("6 by 3.5 metres"), Some([6.0, 3.5]));
    assert_eq!(parse_room_size("3.2m×4.1m"), Some([3.2, 4.1]));
    let a = parse_room_size("a 20 square meters bedroom").unwrap();
    assert!((a[0] * a[1] - 20.0).abs() < 0.3, "{a:?}");
    assert!(parse_room_size("20 m2 studio").is_some());
    assert_eq!(parse_room_size("two chairs and 3 tables"), None);
}

#[test]
fn scene_types_synonyms_counts_adjectives_and_placements() {
    let s = plan_offline("a lounge with six chairs and a pair of floor lamps");
    assert!(s.objects.contains_key("sofa"), "lounge is a living room");
    assert_eq!(s.objects["dining chair"].number, 6);
    assert_eq!(s.objects["floor lamp"].number, 2);

    let s = plan_offline("a kid's room");
    assert!(s.objects.contains_key("single bed") && s.objects.contains_key("toy chest"));

    let s = plan_offline("a minimalist bedroom with a vintage oak dresser in the corner");
    assert_eq!(s.anchors["dresser1"], Anchor::Corner);
    let d = &s.objects["dresser"].description;
    assert!(
        d.starts_with("A DSLR photo of") && d.contains("vintage oak dresser"),
        "{d}"
    );
    assert!(
        s.objects["bed"].description.contains("minimalist"),
        "style carried to every object"
    );

    let s = plan_offline("a beach-inspired living room with a rattan armchair in front of the loveseat, a lamp next to the sofa, a tv opposite the sofa, and the coffee table centered");
    let rel = |a: &str, r: RelationKind, b: &str| {
        s.relations
            .iter()
            .any(|x| x.subject == a && x.relation == r && x.object == b)
    };
    assert!(
        rel("armchair1", RelationKind::Front, "loveseat1"),
        "{:?}",
        s.relations
    );
    assert!(
        rel("table lamp1", RelationKind::Next, "sofa1"),
        "{:?}",
        s.relations
    );
    assert!(
        rel("tv1", RelationKind::Opposite, "sofa1"),
        "{:?}",
        s.relations
    );
    assert_eq!(s.anchors["coffee table1"], Anchor::Center);
    assert!(s.objects["armchair"]
        .description
        .contains("beach-inspired rattan armchair"));

    let s = plan_offline("a bookcase against one wall");
    assert_eq!(s.anchors["bookshelf1"], Anchor::Side);
    s.validate().unwrap();
}

#[test]
fn unknown_scene_types_still_give_a_room_with_the_named_objects() {
    let s = plan_offline("a wizard's potion laboratory with a cauldron, two barrels and a chest");
    assert_eq!(s.scene_type, SceneType::Indoor);
    assert_eq!(s.objects["barrel"].number, 2);
    assert!(s.objects.contains_key("cauldron") && s.objects.contains_key("chest"));
    s.validate().unwrap();
    let s = plan_offline("something beautiful");
    assert!(!s.objects.is_empty());
    s.validate().unwrap();
    let s = plan_offline("an outdoor area with a tent and a fire pit in the corner");
    assert_eq!(s.scene_type, SceneType::Outdoor);
    assert!(
        s.anchors.values().all(|a| *a != Anchor::Corner),
        "no corners outdoors"
    );
}

/// A prompt, the room size it states, and objects it must contain.
type Case = (&'static str, Option<[f64; 2]>, &'static [&'static str]);

/// Prompts a user would write, planned and laid out: valid, rooms as stated, objects as named,
/// and at least 90% of relations and anchors satisfied over the set.
#[test]
fn planned_prompts_lay_out_validly() {
    let prompts: &[Case] = &[
        ("a cozy living room", None, &["sofa"]),
        (
            "a minimalist bedroom, 4m x 5m, with a desk by the window",
            Some([4.0, 5.0]),
            &["bed", "desk"],
        ),
        (
            "a dining room with six chairs around a round table",
            None,
            &["round table", "dining chair"],
        ),
        (
            "a scandinavian kitchen with an island and three bar stools",
            None,
            &["kitchen island", "bar stool"],
        ),
        ("a small bathroom with a bathtub", None, &["bathtub"]),
        (
            "a home office, 3 x 3.5 m, with two bookshelves against one wall",
            Some([3.0, 3.5]),
            &["desk", "bookshelf"],
        ),
        ("a cafe with four tables", None, &["cafe table"]),
        ("a classroom", None, &["blackboard"]),
        ("a gym with two treadmills", None, &["treadmill"]),
        (
            "a garden with a fountain in the middle and three benches",
            None,
            &["fountain", "park bench"],
        ),
        (
            "a beach with palm trees and two sun loungers",
            None,
            &["palm tree", "sun lounger"],
        ),
        (
            "a campsite with a tent next to the fire pit",
            None,
            &["tent", "fire pit"],
        ),
        (
            "a 30 square meters game room with a pool table",
            None,
            &["pool table"],
        ),
        ("a library with a globe", None, &["globe", "library shelf"]),
        (
            "a nursery with a rocking chair",
            None,
            &["crib", "rocking chair"],
        ),
    ];
    let (mut rel_ok, mut rel_n, mut anc_ok, mut anc_n) = (0, 0, 0, 0);
    let start = std::time::Instant::now();
    for (p, size, named) in prompts {
        let spec = plan_offline(p);
        spec.validate().unwrap_or_else(|e| panic!("{p}: {e}"));
        for n in *named {
            assert!(
                spec.objects.contains_key(*n),
                "{p}: no {n} in {:?}",
                spec.objects.keys()
            );
        }
        let room = spec.room.unwrap().size;
        if let Some([w, d]) = size {
            assert_eq!([room[0], room[1]], [*w, *d], "{p}: room size kept");
        } else if spec.scene_type == SceneType::Indoor && !p.contains("square") {
            // A room asked small is trimmed to the capacity's occupancy (floor footprints).
            let small = ["small", "tiny", "cramped"].iter().any(|w| p.contains(w));
            let (area, limit) = if small {
                (
                    dreamscene::plan::capacity::floor_area(&spec),
                    dreamscene::plan::capacity::TRIM_OCCUPANCY,
                )
            } else {
                (
                    spec.instances().iter().map(|i| i.size[0] * i.size[1]).sum(),
                    INDOOR_OCCUPANCY,
                )
            };
            assert!(area / (room[0] * room[1]) <= limit + 1e-9, "{p}: occupancy");
        }
        let l = layout(&spec, LayoutOptions::seeded(1)).unwrap();
        let problems = validity_problems(&l, &spec);
        assert!(problems.is_empty(), "{p}: {problems:?}");
        assert_eq!(
            l.objects.len(),
            spec.instances().len(),
            "{p}: nothing dropped"
        );
        let by: BTreeMap<&str, &PlacedObject> =
            l.objects.iter().map(|o| (o.id.as_str(), o)).collect();
        for r in &spec.relations {
            rel_n += 1;
            rel_ok +=
                relation_holds(by[r.subject.as_str()], r.relation, by[r.object.as_str()]) as usize;
        }
        for o in &l.objects {
            anc_n += 1;
            anc_ok += anchor_holds(o, o.anchor, l.scene_type, l.room.size) as usize;
        }
    }
    let (r, a) = (rel_ok as f64 / rel_n as f64, anc_ok as f64 / anc_n as f64);
    eprintln!(
        "{} prompts: relations {rel_ok}/{rel_n} = {:.1}%, anchors {anc_ok}/{anc_n} = {:.1}%, {:.2} s",
        prompts.len(),
        100.0 * r,
        100.0 * a,
        start.elapsed().as_secs_f64()
    );
    assert!(r >= 0.9 && a >= 0.9, "relations {r:.3}, anchors {a:.3}");
}

/// Runs the binary with `args` and fails the test with its stderr unless it succeeds.
fn plan_ok(exe: &str, args: &[&str]) {
    let out = std::process::Command::new(exe).args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The `plan` verb end to end: spec.json, layout.json and a decodable layout.png; bad input
/// gets one line and a non-zero exit.
#[test]
fn plan_verb_writes_spec_layout_and_picture() {
    let exe = env!("CARGO_BIN_EXE_dreamscene");
    let dir = std::env::temp_dir().join(format!("dreamscene-plan-{}", std::process::id()));
    let out_dir = dir.to_str().unwrap();
    plan_ok(
        exe,
        &[
            "plan",
            "a cozy living room, 5m x 4m",
            "--seed",
            "3",
            "--out",
            out_dir,
        ],
    );
    let spec = SceneSpec::read(&dir.join("spec.json")).unwrap();
    assert_eq!(spec.room.unwrap().size[..2], [5.0, 4.0]);
    let l: Layout =
        serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json")).unwrap()).unwrap();
    assert_eq!(l.seed, 3);
    assert_eq!(l.objects.len(), spec.instances().len());
    let img = image::open(dir.join("layout.png")).unwrap();
    assert!(img.width() > 500 && img.height() > 400);

    let dlg = dir.join("dialogue.json");
    std::fs::write(&dlg, r#"[{"role": "user", "content": "I want a bedroom"}, {"role": "assistant", "content": "Which style?"}, {"role": "user", "content": "rustic, with a desk"}]"#).unwrap();
    let (dlg_s, d) = (dlg.to_str().unwrap(), dir.join("d"));
    plan_ok(
        exe,
        &["plan", "--dialogue", dlg_s, "--out", d.to_str().unwrap()],
    );
    let spec = SceneSpec::read(&dir.join("d/spec.json")).unwrap();
    assert!(spec.objects.contains_key("bed") && spec.objects.contains_key("desk"));
    assert!(spec.objects["bed"].description.contains("rustic"));

    std::fs::write(&dlg, "[{\"role\": \"user\"").unwrap();
    let out = std::process::Command::new(exe)
        .args(["plan", "--dialogue"])
        .arg(&dlg)
        .arg("--out")
        .arg(dir.join("e"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("dialogue.json") && err.trim().lines().count() == 1,
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// layout.png's numbered markers never overlap one another, even on stacked and crowded
/// objects, and stay inside the picture; the legend lists every object.
#[test]
fn layout_labels_never_overlap() {
    for p in [
        "a bedroom with a lamp on each nightstand",
        "a restaurant",
        "a classroom for 20 students",
        "a living room, 3m x 3m, with a sofa",
    ] {
        let spec = dreamscene::plan::offline::plan_prompt(p).unwrap().spec;
        let l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
        let boxes = dreamscene::plan::draw::label_boxes(&l);
        assert_eq!(boxes.len(), l.objects.len());
        let img = dreamscene::plan::draw::draw_layout(&l);
        for (i, (a, _)) in boxes.iter().enumerate() {
            assert!(
                a[0] >= 0 && a[1] >= 0 && a[2] <= img.width() as i64 && a[3] <= img.height() as i64
            );
            for (b, _) in &boxes[i + 1..] {
                let apart = a[2] <= b[0] || b[2] <= a[0] || a[3] <= b[1] || b[3] <= a[1];
                assert!(apart, "{p}: markers {a:?} and {b:?} overlap");
            }
        }
        // Objects that share a centre (a lamp centred on its nightstand): one of each such pair
        // had to move (with a leader line).
        let shared = l.objects.iter().enumerate().any(|(i, a)| {
            l.objects[i + 1..].iter().any(|b| {
                (a.position[0] - b.position[0]).hypot(a.position[1] - b.position[1]) < 0.01
            })
        });
        if shared {
            assert!(
                boxes.iter().any(|(_, moved)| *moved),
                "{p}: stacked markers moved"
            );
        }
    }
}

#[test]
fn a_spec_may_give_each_instance_its_own_size_one_for_each() {
    let text = |sizes: &str| {
        format!(
            r#"{{"scene_type":"indoor","scene_text":"t","objects":{{
            "table":{{"number":2,"size":[1.8,0.9,0.75],"description":"d"{sizes}}}}}}}"#
        )
    };
    // without `sizes` every instance has `size`, and none is written back
    let plain = SceneSpec::parse(text("").as_bytes()).unwrap();
    assert!(plain.instances().iter().all(|i| i.size == [1.8, 0.9, 0.75]));
    assert!(!serde_json::to_string(&plain).unwrap().contains("sizes"));
    let own =
        SceneSpec::parse(text(r#","sizes":[[0.8,0.8,0.75],[1.8,0.9,0.75]]"#).as_bytes()).unwrap();
    let sizes: Vec<[f64; 3]> = own.instances().iter().map(|i| i.size).collect();
    assert_eq!(sizes, [[0.8, 0.8, 0.75], [1.8, 0.9, 0.75]]);
    assert_eq!(own.size_of("table1"), Some([0.8, 0.8, 0.75]));
    // one size for two tables, or a side of no length: one clear line
    let e = SceneSpec::parse(text(r#","sizes":[[0.8,0.8,0.75]]"#).as_bytes()).unwrap_err();
    assert!(e.contains("1 sizes for 2 instances"), "{e}");
    let e = SceneSpec::parse(text(r#","sizes":[[0.8,0.0,0.75],[1,1,1]]"#).as_bytes()).unwrap_err();
    assert!(e.contains("`table`: size") && !e.contains('\n'), "{e}");
}
