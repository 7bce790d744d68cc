//! Relation and anchor semantics, and the GCP layout on a realistic spec and on random specs.
//! Pure host code: no GPU.
mod common;
use common::obj;
use dreamscene::plan::check::{anchor_holds, relation_holds, validity_problems};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::*;
use rand::{Rng, SeedableRng};
use std::collections::BTreeMap;

/// Each directional relation, in the object's own frame, for several object yaws: the subject
/// placed on the named side holds, on the other sides it does not.
#[test]
fn directional_relations_follow_the_objects_frame() {
    use RelationKind::*;
    for yaw in [0.0f64, 90.0, 180.0, -90.0, 30.0, 135.0] {
        let o = obj("sofa1", [2.0, 1.0, 0.8], [0.5, -0.3, 0.0], yaw);
        let (s, c) = yaw.to_radians().sin_cos();
        let (ex, ey) = ([c, s], [-s, c]); // right, facing
        let at = |lx: f64, ly: f64, face: f64| {
            obj(
                "table1",
                [0.6, 0.6, 0.5],
                [
                    0.5 + lx * ex[0] + ly * ey[0],
                    -0.3 + lx * ex[1] + ly * ey[1],
                    0.0,
                ],
                face,
            )
        };
        let cases = [
            (Front, at(0.0, 1.2, yaw)),
            (Behind, at(0.0, -1.2, yaw)),
            (Left, at(-1.6, 0.0, yaw)),
            (Right, at(1.6, 0.0, yaw)),
        ];
        for (rel, subj) in &cases {
            for other in [Front, Behind, Left, Right] {
                assert_eq!(
                    relation_holds(subj, other, &o),
                    other == *rel,
                    "yaw {yaw}: subject placed {rel:?}, checked {other:?}"
                );
            }
        }
        // Too far: 3 m gap limit.
        assert!(!relation_holds(&at(0.0, 4.2, yaw), Front, &o));
        // Off the band the front face sweeps.
        assert!(!relation_holds(&at(1.8, 1.2, yaw), Front, &o));
        // OPPOSITE: in front, 1-5 m, facing the object within 30 degrees.
        let facing_back = at(0.0, 2.5, yaw + 180.0);
        assert!(relation_holds(&facing_back, Opposite, &o), "yaw {yaw}");
        assert!(
            !relation_holds(&at(0.0, 2.5, yaw), Opposite, &o),
            "yaw {yaw}: faces away"
        );
        assert!(
            !relation_holds(&at(0.0, 0.8, yaw + 180.0), Opposite, &o),
            "too close"
        );
        assert!(
            relation_holds(&at(0.0, 0.8, yaw + 180.0), Next, &o),
            "0.3 m gap is next"
        );
        assert!(
            !relation_holds(&at(0.0, 1.6, yaw), Next, &o),
            "1.1 m gap is not next"
        );
    }
}

#[test]
fn over_and_under_need_the_footprint_and_heights() {
    use RelationKind::*;
    let stand = obj("tv stand1", [1.6, 0.45, 0.55], [1.0, 1.0, 0.0], 90.0);
    let tv = obj("tv1", [1.2, 0.1, 0.7], [1.05, 1.3, 0.55], 90.0);
    assert!(relation_holds(&tv, Over, &stand));
    let floating = obj("tv1", [1.2, 0.1, 0.7], [1.05, 1.3, 0.7], 90.0);
    assert!(
        !relation_holds(&floating, Over, &stand),
        "10 cm gap is not resting on top"
    );
    let beside = obj("tv1", [1.2, 0.1, 0.7], [1.5, 1.0, 0.55], 90.0);
    assert!(
        !relation_holds(&beside, Over, &stand),
        "centre outside the footprint (rotated)"
    );
    let table = obj("table1", [1.2, 0.7, 0.45], [0.0, 0.0, 0.0], 0.0);
    let rug = obj("rug1", [2.0, 1.4, 0.01], [0.2, 0.1, 0.0], 0.0);
    assert!(relation_holds(&rug, Under, &table));
    let tall = obj("shelf1", [0.5, 0.5, 1.8], [0.2, 0.1, 0.0], 0.0);
    assert!(
        !relation_holds(&tall, Under, &table),
        "taller than the table"
    );
}

#[test]
fn anchors_follow_walls_and_facing() {
    let room = [5.0, 4.0, 2.8];
    let ind = SceneType::Indoor;
    // Back to the -y wall, facing +y (into the room).
    let sofa = obj("sofa1", [2.0, 0.9, 0.8], [0.0, -2.0 + 0.45 + 0.1, 0.0], 0.0);
    assert!(anchor_holds(&sofa, Anchor::Side, ind, room));
    let turned = obj(
        "sofa1",
        [2.0, 0.9, 0.8],
        [0.0, -2.0 + 0.45 + 0.1, 0.0],
        180.0,
    );
    assert!(
        !anchor_holds(&turned, Anchor::Side, ind, room),
        "faces the wall"
    );
    let off = obj("sofa1", [2.0, 0.9, 0.8], [0.0, -1.0, 0.0], 0.0);
    assert!(
        !anchor_holds(&off, Anchor::Side, ind, room),
        "1 m from the wall"
    );
    // In the +x +y corner facing diagonally out of it.
    let plant = obj("plant1", [0.5, 0.5, 1.2], [2.3, 1.8, 0.0], 135.0);
    assert!(anchor_holds(&plant, Anchor::Corner, ind, room));
    assert!(
        !anchor_holds(&plant, Anchor::Side, ind, room),
        "near two walls is not SIDE"
    );
    assert!(!anchor_holds(
        &plant,
        Anchor::Corner,
        SceneType::Outdoor,
        room
    ));
    let mid = obj("table1", [1.0, 0.6, 0.45], [0.4, -0.3, 0.0], 20.0);
    assert!(anchor_holds(&mid, Anchor::Center, ind, room));
    assert!(!anchor_holds(&plant, Anchor::Center, ind, room));
    assert!(anchor_holds(&plant, Anchor::Others, ind, room));
}

/// Valid, complete, and (returned) the fractions of relations and anchors that hold.
fn check_layout(spec: &SceneSpec, l: &Layout) -> (usize, usize, usize, usize) {
    let ids: Vec<String> = spec.instances().into_iter().map(|i| i.id).collect();
    let got: Vec<String> = l.objects.iter().map(|o| o.id.clone()).collect();
    assert_eq!(got, ids, "every instance placed exactly once");
    let problems = validity_problems(l, spec);
    assert!(problems.is_empty(), "invalid layout: {problems:?}");
    let by_id: BTreeMap<&str, &PlacedObject> =
        l.objects.iter().map(|o| (o.id.as_str(), o)).collect();
    let fails_pairwise: Vec<&Relation> = spec
        .relations
        .iter()
        .filter(|r| {
            !relation_holds(
                by_id[r.subject.as_str()],
                r.relation,
                by_id[r.object.as_str()],
            )
        })
        .collect();
    // `unsatisfied` lists every relation that fails on its pair, and besides those only the
    // stricter layout-wide readings: a lone FRONT / BEHIND out of reach, a blocked OPPOSITE
    for r in &fails_pairwise {
        assert!(l.unsatisfied.contains(r), "{r:?} fails but is not listed");
    }
    for r in &l.unsatisfied {
        assert!(
            fails_pairwise.contains(&r)
                || matches!(
                    r.relation,
                    RelationKind::Front | RelationKind::Behind | RelationKind::Opposite
                ),
            "{r:?} holds but is listed"
        );
    }
    let rel_ok = spec.relations.len() - l.unsatisfied.len();
    let anchor_ok = l
        .objects
        .iter()
        .filter(|o| anchor_holds(o, o.anchor, l.scene_type, l.room.size))
        .count();
    (rel_ok, spec.relations.len(), anchor_ok, l.objects.len())
}

#[test]
fn living_room_layouts_are_valid_satisfied_and_diverse() {
    let spec = SceneSpec::read(std::path::Path::new("tests/data/living_room.json")).unwrap();
    let mut totals = (0, 0, 0, 0);
    let mut positions = vec![];
    for seed in 0..10 {
        let l = layout(&spec, LayoutOptions::seeded(seed)).unwrap();
        let (a, b, c, d) = check_layout(&spec, &l);
        totals = (totals.0 + a, totals.1 + b, totals.2 + c, totals.3 + d);
        positions.push(l.objects.iter().map(|o| o.position).collect::<Vec<_>>());
        // The room size the spec leaves open fits the furniture at <= 40% occupancy.
        let area: f64 = spec.instances().iter().map(|i| i.size[0] * i.size[1]).sum();
        assert!(area / (l.room.size[0] * l.room.size[1]) <= 0.4 + 1e-9);
    }
    let rel = totals.0 as f64 / totals.1 as f64;
    let anc = totals.2 as f64 / totals.3 as f64;
    eprintln!("relations {:.1}%, anchors {:.1}%", 100.0 * rel, 100.0 * anc);
    assert!(rel >= 0.9 && anc >= 0.9, "relations {rel}, anchors {anc}");
    positions.sort_by(|a, b| a.partial_cmp(b).unwrap());
    positions.dedup();
    assert!(
        positions.len() >= 5,
        "only {} distinct layouts in 10 seeds",
        positions.len()
    );
}

/// Random specs: whatever the constraints, every instance is placed, inside the room, below the
/// ceiling, and nothing interpenetrates.
#[test]
fn random_specs_always_give_valid_layouts() {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(99);
    let anchors = [Anchor::Center, Anchor::Side, Anchor::Corner, Anchor::Others];
    for case in 0..40 {
        let scene_type = if case % 4 == 3 {
            SceneType::Outdoor
        } else {
            SceneType::Indoor
        };
        let mut objects = BTreeMap::new();
        for c in 0..rng.gen_range(1..8) {
            objects.insert(
                format!("thing{}x", (b'a' + c) as char),
                ObjectSpec {
                    number: rng.gen_range(1..4),
                    size: [
                        rng.gen_range(0.2..2.5),
                        rng.gen_range(0.2..2.0),
                        rng.gen_range(0.05..2.2),
                    ],
                    description: "A DSLR photo of a thing".into(),
                    rows: 0,
                    sizes: vec![],
                    on_wall: None,
                },
            );
        }
        let mut spec = SceneSpec {
            scene_type,
            scene_text: format!("random {case}"),
            room: None,
            objects,
            anchors: BTreeMap::new(),
            relations: vec![],
        };
        let ids: Vec<String> = spec.instances().into_iter().map(|i| i.id).collect();
        for id in &ids {
            let mut a = anchors[rng.gen_range(0..4)];
            if scene_type == SceneType::Outdoor && a == Anchor::Corner {
                a = Anchor::Side;
            }
            spec.anchors.insert(id.clone(), a);
        }
        for _ in 0..rng.gen_range(0..ids.len() + 1) {
            let (s, o) = (rng.gen_range(0..ids.len()), rng.gen_range(0..ids.len()));
            if s != o {
                spec.relations.push(Relation {
                    subject: ids[s].clone(),
                    relation: RelationKind::ALL[rng.gen_range(0..8)],
                    object: ids[o].clone(),
                });
            }
        }
        let l = layout(
            &spec,
            LayoutOptions {
                seed: case,
                restarts: 2,
            },
        )
        .unwrap();
        check_layout(&spec, &l);
    }
}

#[test]
fn bad_specs_get_clear_errors() {
    let spec = SceneSpec::read(std::path::Path::new("tests/data/living_room.json")).unwrap();
    let mut s = spec.clone();
    s.relations.push(Relation {
        subject: "sofa7".into(),
        relation: RelationKind::Next,
        object: "rug1".into(),
    });
    let e = s.validate().unwrap_err().to_string();
    assert!(e.contains("sofa7"), "{e}");
    let mut s = spec.clone();
    s.objects.get_mut("rug").unwrap().size[2] = -1.0;
    assert!(s.validate().unwrap_err().to_string().contains("rug"));
    let dir = std::env::temp_dir().join("dreamscene-spec-test");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("broken.json");
    std::fs::write(&p, "{\"scene_type\": \"indoor\", \"objects\": ").unwrap();
    let e = SceneSpec::read(&p).unwrap_err().to_string();
    assert!(e.contains("broken.json") && !e.contains('\n'), "{e}");
}

/// The functional-group relations mean what ARCHITECTURE.md says, and each part of a meaning
/// can fail on its own.
#[test]
fn functional_relations_follow_their_definitions() {
    use RelationKind::*;
    let holds = |s: &PlacedObject, r, o: &PlacedObject| relation_holds(s, r, o);
    // AROUND: beside one of the table's sides, gap <= 0.3 m, facing it.
    let table = obj("table1", [1.8, 0.9, 0.75], [0.0, 0.0, 0.0], 0.0);
    let chair = |x: f64, y: f64, yaw: f64| obj("chair1", [0.45, 0.5, 0.9], [x, y, 0.0], yaw);
    assert!(holds(&chair(0.3, 0.8, 180.0), Around, &table));
    assert!(holds(&chair(0.0, -0.8, 0.0), Around, &table));
    assert!(holds(&chair(1.25, 0.0, 90.0), Around, &table), "short side");
    assert!(!holds(&chair(0.3, 0.8, 0.0), Around, &table), "facing away");
    assert!(!holds(&chair(0.3, 1.2, 180.0), Around, &table), "0.5 m gap");
    assert!(
        !holds(&chair(1.25, 0.8, 135.0), Around, &table),
        "at a corner"
    );
    // AT: in front of the desk, gap <= 0.3 m, facing it.
    let desk = obj("desk1", [1.4, 0.7, 0.75], [0.0, 0.0, 0.0], 90.0);
    assert!(holds(&chair(-0.65, 0.0, -90.0), At, &desk));
    assert!(
        !holds(&chair(0.65, 0.0, 90.0), At, &desk),
        "behind the desk"
    );
    assert!(!holds(&chair(-1.2, 0.0, -90.0), At, &desk), "too far");
    // FLANK: beside the bed's head end, flush, turned as the bed.
    let bed = obj("bed1", [1.6, 2.1, 1.0], [0.0, 0.0, 0.0], 0.0);
    let stand = |x: f64, y: f64, yaw: f64| obj("nightstand1", [0.5, 0.4, 0.55], [x, y, 0.0], yaw);
    assert!(holds(&stand(1.1, -0.85, 0.0), Flank, &bed));
    assert!(holds(&stand(-1.08, -0.85, 0.0), Flank, &bed));
    assert!(!holds(&stand(1.1, 0.85, 0.0), Flank, &bed), "at the foot");
    assert!(
        !holds(&stand(1.1, -0.85, 180.0), Flank, &bed),
        "turned round"
    );
    assert!(!holds(&stand(1.4, -0.85, 0.0), Flank, &bed), "0.35 m away");
    // CIRCLE: 0.6-1.5 m from the fire, facing it.
    let fire = obj("fire pit1", [1.0, 1.0, 0.4], [0.0, 0.0, 0.0], 0.0);
    let log = |y: f64, yaw: f64| obj("log1", [1.5, 0.4, 0.4], [0.0, y, 0.0], yaw);
    assert!(holds(&log(1.7, 180.0), Circle, &fire));
    assert!(!holds(&log(0.9, 180.0), Circle, &fire), "touching the fire");
    assert!(!holds(&log(2.6, 180.0), Circle, &fire), "1.9 m away");
    assert!(!holds(&log(1.7, 0.0), Circle, &fire), "facing away");
    // ROW: in front of the board, facing it (turned opposite to it, within 30°).
    let board = obj("board1", [3.0, 0.1, 1.2], [0.0, -3.0, 0.0], 0.0);
    let d = |x: f64, y: f64, yaw: f64| obj("desk2", [0.7, 0.5, 0.75], [x, y, 0.0], yaw);
    assert!(holds(&d(2.5, 1.0, 180.0), Row, &board));
    assert!(holds(&d(2.5, 1.0, 160.0), Row, &board), "20° off");
    assert!(
        !holds(&d(2.5, 1.0, 0.0), Row, &board),
        "turned as the board, away from it"
    );
    assert!(!holds(&d(2.5, 1.0, 130.0), Row, &board), "50° off");
    assert!(
        !holds(&d(0.0, -3.6, 180.0), Row, &board),
        "behind the board"
    );
    // Names as the file writes them.
    assert_eq!(Around.to_string(), "AROUND");
    assert_eq!(Opposite.to_string(), "OPPOSITE");
    let r: Relation =
        serde_json::from_str(r#"{"subject": "a1", "relation": "FLANK", "object": "b1"}"#).unwrap();
    assert_eq!(r.relation, Flank);
}
