//! Plain-language move and motion commands, parsed as a person means them: who moves, the
//! steps, distances with units, angles and their sense, relative places and durations. Then the
//! keyframes of written motions at chosen times, the timeline that `compose_at` plays, and the
//! shape prior's restyle (recolouring).
//! Host-only (no device).
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::edit::animate::{animate, final_pose, keyframes};
use dreamscene::edit::parse::{ambiguous, parse, Step, DEFAULT_DISTANCE, SMALL_DISTANCE};
use dreamscene::edit::SceneState;
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{RelationKind, SceneSpec};
use dreamscene::scene::timeline::{compose_at, sample};
use std::path::PathBuf;

fn objects() -> Vec<(String, String)> {
    [
        ("sofa1", "sofa"),
        ("tv1", "tv"),
        ("chair1", "chair"),
        ("chair2", "chair"),
        ("coffee table1", "coffee table"),
        ("car1", "car"),
        ("dog1", "dog"),
        ("door1", "door"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

/// What a sentence should give: subject and steps (durations as given).
fn check(text: &str, default: Option<&str>, subject: &str, want: &[(Step, Option<f64>)]) {
    let c = parse(text, &objects(), default).unwrap_or_else(|e| panic!("{text}: {e}"));
    assert_eq!(c.subject.as_deref(), Some(subject), "{text}");
    assert_eq!(c.steps.len(), want.len(), "{text}: {:?}", c.steps);
    for ((got, gs), (w, ws)) in c.steps.iter().zip(want) {
        let same = match (got, w) {
            (
                Step::Shift {
                    forward: a,
                    left: b,
                },
                Step::Shift {
                    forward: c,
                    left: d,
                },
            ) => close(*a, *c) && close(*b, *d),
            (Step::Turn { degrees: a }, Step::Turn { degrees: b }) => close(*a, *b),
            (Step::Scale { factor: a }, Step::Scale { factor: b }) => close(*a, *b),
            (
                Step::Circle {
                    target: a,
                    turns: x,
                },
                Step::Circle {
                    target: b,
                    turns: y,
                },
            ) => a == b && close(*x, *y),
            (
                Step::Approach {
                    target: a,
                    distance: x,
                },
                Step::Approach {
                    target: b,
                    distance: y,
                },
            ) => {
                a == b
                    && x.zip(*y)
                        .map_or(x.is_none() && y.is_none(), |(p, q)| close(p, q))
            }
            (g, w) => g == w,
        };
        assert!(same, "{text}: got {got:?}, want {w:?}");
        assert_eq!(gs, ws, "{text}: duration");
    }
}

/// A sentence, the instance the caller names, who should move, and the steps meant.
type Case = (
    &'static str,
    Option<&'static str>,
    &'static str,
    Vec<(Step, Option<f64>)>,
);

fn shift(forward: f64, left: f64) -> (Step, Option<f64>) {
    (Step::Shift { forward, left }, None)
}
fn turn(degrees: f64) -> (Step, Option<f64>) {
    (Step::Turn { degrees }, None)
}
fn face(t: &str) -> (Step, Option<f64>) {
    (
        Step::Face {
            target: t.into(),
            away: false,
        },
        None,
    )
}
fn place(t: &str, relation: RelationKind) -> (Step, Option<f64>) {
    (
        Step::Place {
            target: t.into(),
            relation,
        },
        None,
    )
}

#[test]
fn move_sentences_mean_what_they_say() {
    let sentences: Vec<Case> = vec![
        (
            "move the sofa back half a metre",
            None,
            "sofa1",
            vec![shift(-0.5, 0.0)],
        ),
        (
            "Move the sofa forward 1 m.",
            None,
            "sofa1",
            vec![shift(1.0, 0.0)],
        ),
        (
            "push the coffee table 30 cm to the left",
            None,
            "coffee table1",
            vec![shift(0.0, 0.3)],
        ),
        (
            "slide the chair two metres to the right",
            None,
            "chair1",
            vec![shift(0.0, -2.0)],
        ),
        (
            "move chair2 backwards 50cm",
            None,
            "chair2",
            vec![shift(-0.5, 0.0)],
        ),
        (
            "move it a bit to the left",
            Some("tv1"),
            "tv1",
            vec![shift(0.0, SMALL_DISTANCE)],
        ),
        (
            "nudge the tv forward slightly",
            None,
            "tv1",
            vec![shift(SMALL_DISTANCE, 0.0)],
        ),
        (
            "move the sofa back",
            None,
            "sofa1",
            vec![shift(-DEFAULT_DISTANCE, 0.0)],
        ),
        (
            "move the sofa 3 feet forward",
            None,
            "sofa1",
            vec![shift(3.0 * 0.3048, 0.0)],
        ),
        (
            "move the chair a metre and a half ahead",
            None,
            "chair1",
            vec![shift(1.5, 0.0)],
        ),
        (
            "turn the chair to face the tv",
            None,
            "chair1",
            vec![face("tv1")],
        ),
        (
            "rotate the sofa 90 degrees clockwise",
            None,
            "sofa1",
            vec![turn(-90.0)],
        ),
        (
            "rotate the sofa 45° counterclockwise",
            None,
            "sofa1",
            vec![turn(45.0)],
        ),
        ("turn the chair left", None, "chair1", vec![turn(90.0)]),
        (
            "turn the chair right by 30 degrees",
            None,
            "chair1",
            vec![turn(-30.0)],
        ),
        ("turn the tv around", None, "tv1", vec![turn(180.0)]),
        (
            "give the sofa a quarter turn",
            None,
            "sofa1",
            vec![turn(90.0)],
        ),
        (
            "move the chair next to the sofa",
            None,
            "chair1",
            vec![place("sofa1", RelationKind::Next)],
        ),
        (
            "put chair2 in front of the tv",
            None,
            "chair2",
            vec![place("tv1", RelationKind::Front)],
        ),
        (
            "move the coffee table behind the sofa",
            None,
            "coffee table1",
            vec![place("sofa1", RelationKind::Behind)],
        ),
        (
            "place it to the left of the sofa",
            Some("chair1"),
            "chair1",
            vec![place("sofa1", RelationKind::Left)],
        ),
        (
            "move the chair closer to the tv",
            None,
            "chair1",
            vec![(
                Step::Approach {
                    target: "tv1".into(),
                    distance: Some(DEFAULT_DISTANCE),
                },
                None,
            )],
        ),
        (
            "move the chair away from the sofa by 1 m",
            None,
            "chair1",
            vec![(
                Step::Retreat {
                    target: "sofa1".into(),
                    distance: 1.0,
                },
                None,
            )],
        ),
        (
            "make the sofa twice as big",
            None,
            "sofa1",
            vec![(Step::Scale { factor: 2.0 }, None)],
        ),
        (
            "shrink the tv by 20%",
            None,
            "tv1",
            vec![(Step::Scale { factor: 0.8 }, None)],
        ),
        (
            "move the chair to the middle of the room",
            None,
            "chair1",
            vec![(Step::Centre, None)],
        ),
        (
            "move the sofa forward 1 m and turn it left",
            None,
            "sofa1",
            vec![shift(1.0, 0.0), turn(90.0)],
        ),
    ];
    for (text, default, subject, want) in &sentences {
        check(text, *default, subject, want);
    }
}

#[test]
fn motion_sentences_mean_what_they_say() {
    let seq: Vec<Case> = vec![
        (
            "the car drives forward 3 m",
            None,
            "car1",
            vec![shift(3.0, 0.0)],
        ),
        (
            "drive forward 3 metres then turn left",
            Some("car1"),
            "car1",
            vec![shift(3.0, 0.0), turn(90.0)],
        ),
        (
            "the dog walks to the sofa",
            None,
            "dog1",
            vec![(
                Step::Approach {
                    target: "sofa1".into(),
                    distance: None,
                },
                None,
            )],
        ),
        (
            "walk from here to the door in 4 seconds",
            Some("dog1"),
            "dog1",
            vec![(
                Step::Approach {
                    target: "door1".into(),
                    distance: None,
                },
                Some(4.0),
            )],
        ),
        ("spin twice", Some("chair1"), "chair1", vec![turn(720.0)]),
        (
            "spin around 3 times clockwise",
            Some("chair1"),
            "chair1",
            vec![turn(-1080.0)],
        ),
        (
            "turn 90 degrees in 2 seconds",
            Some("car1"),
            "car1",
            vec![(Step::Turn { degrees: 90.0 }, Some(2.0))],
        ),
        (
            "the dog circles around the coffee table",
            None,
            "dog1",
            vec![(
                Step::Circle {
                    target: "coffee table1".into(),
                    turns: 1.0,
                },
                None,
            )],
        ),
        (
            "circle the coffee table twice",
            Some("dog1"),
            "dog1",
            vec![(
                Step::Circle {
                    target: "coffee table1".into(),
                    turns: 2.0,
                },
                None,
            )],
        ),
        (
            "the dog bounces three times",
            None,
            "dog1",
            vec![(
                Step::Bounce {
                    height: 0.3,
                    times: 3,
                },
                None,
            )],
        ),
        (
            "jump 50 cm high twice",
            Some("dog1"),
            "dog1",
            vec![(
                Step::Bounce {
                    height: 0.5,
                    times: 2,
                },
                None,
            )],
        ),
        (
            "grow to twice its size",
            Some("tv1"),
            "tv1",
            vec![(Step::Scale { factor: 2.0 }, None)],
        ),
        (
            "shrink to half its size over 3 seconds",
            Some("tv1"),
            "tv1",
            vec![(Step::Scale { factor: 0.5 }, Some(3.0))],
        ),
        (
            "move left 1 m, wait 2 seconds, then move right 1 m",
            Some("car1"),
            "car1",
            vec![shift(0.0, 1.0), (Step::Pause, Some(2.0)), shift(0.0, -1.0)],
        ),
        (
            "drive backwards 2 m and then turn around",
            Some("car1"),
            "car1",
            vec![shift(-2.0, 0.0), turn(180.0)],
        ),
        (
            "the car reverses 1.5 m",
            None,
            "car1",
            vec![shift(-1.5, 0.0)],
        ),
    ];
    for (text, default, subject, want) in &seq {
        check(text, *default, subject, want);
    }
}

#[test]
fn sentences_that_say_nothing_or_name_nothing_are_refused() {
    let o = objects();
    assert!(parse("please", &o, Some("sofa1")).is_err());
    assert!(parse("move the piano back", &o, None)
        .map(|c| c.subject.is_none())
        .unwrap_or(true));
    assert!(parse("move the sofa next to the sofa", &o, None).is_err());
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-edit-lang-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A 6 x 5 m room with a sofa against a wall, a coffee table, a chair; the sofa1 faces +y.
fn scene_dir(name: &str) -> PathBuf {
    let spec: SceneSpec = serde_json::from_str(
        r#"{"scene_type": "indoor", "scene_text": "a living room",
            "room": {"size": [6.0, 5.0, 2.6]},
            "objects": {
              "sofa": {"number": 1, "size": [2.0, 0.9, 0.8], "description": "a grey sofa"},
              "coffee table": {"number": 1, "size": [1.0, 0.6, 0.45], "description": "an oak coffee table"},
              "chair": {"number": 1, "size": [0.5, 0.5, 0.9], "description": "a chair"}},
            "anchors": {"sofa1": "SIDE"},
            "relations": [{"subject": "coffee table1", "relation": "FRONT", "object": "sofa1"}]}"#,
    )
    .unwrap();
    let l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
    let d = tmp(name);
    std::fs::write(d.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&d.join("layout.json")).unwrap();
    write_draft_scene(&d, "a living room", 0, &spec, &l, false, &mut |_| {}).unwrap();
    d
}

#[test]
fn keyframes_at_chosen_times_follow_the_sentence() {
    let d = scene_dir("keys");
    let st = SceneState::open(&d).unwrap();
    let chair = st.object("chair1").unwrap().clone();
    let objs: Vec<(String, String)> = st
        .scene
        .objects
        .iter()
        .map(|o| (o.id.clone(), o.category.clone()))
        .collect();
    let f = {
        let (s, c) = chair.yaw.to_radians().sin_cos();
        [-s, c]
    };
    // "forward 1 m in 2 seconds, then turn left 90 degrees in 1 second"
    let cmd = parse(
        "move forward 1 m in 2 seconds then turn left 90 degrees in 1 second",
        &objs,
        Some("chair1"),
    )
    .unwrap();
    let keys = keyframes(&st, "chair1", &cmd, None).unwrap();
    let track = dreamscene::scene::dir::Track {
        id: "chair1".into(),
        interpolation: "linear".into(),
        keys: keys
            .iter()
            .map(|(t, p)| dreamscene::scene::dir::Key {
                t: *t,
                position: p.position,
                yaw: p.yaw,
                scale: p.scale,
            })
            .collect(),
    };
    let at = |t: f64| sample(&track, t).unwrap();
    let p1 = at(1.0);
    assert!((p1.position[0] - (chair.position[0] + 0.5 * f[0])).abs() < 1e-9);
    assert!((p1.position[1] - (chair.position[1] + 0.5 * f[1])).abs() < 1e-9);
    assert!((at(2.5).yaw - (chair.yaw + 45.0)).abs() < 1e-9);
    assert!((at(3.0).yaw - (chair.yaw + 90.0)).abs() < 1e-9);
    assert!((at(9.0).position[0] - (chair.position[0] + f[0])).abs() < 1e-9);
    // A move in words ends where its last key is, the yaw wrapped.
    let end = final_pose(&st, "chair1", &cmd).unwrap();
    assert!((end.position[1] - (chair.position[1] + f[1])).abs() < 1e-9);
    // Circling keeps the distance to the centre it goes round.
    let table = st.object("coffee table1").unwrap().clone();
    let cmd = parse("circle around the coffee table", &objs, Some("chair1")).unwrap();
    let r0 = (chair.position[0] - table.position[0]).hypot(chair.position[1] - table.position[1]);
    for (_, p) in keyframes(&st, "chair1", &cmd, Some(4.0)).unwrap() {
        let r = (p.position[0] - table.position[0]).hypot(p.position[1] - table.position[1]);
        assert!((r - r0).abs() < 1e-6, "radius {r} vs {r0}");
    }
    // Walking to an object stops beside it, not in it.
    let cmd = parse("walk to the sofa", &objs, Some("chair1")).unwrap();
    let end = final_pose(&st, "chair1", &cmd).unwrap();
    let moved = dreamscene::edit::ops::with_pose(&st, "chair1", end).unwrap();
    let g = dreamscene::plan::check::gap(
        &moved.box_of(moved.object("chair1").unwrap()),
        &moved.box_of(moved.object("sofa1").unwrap()),
    );
    assert!((g - 0.2).abs() < 0.02, "gap {g}");
    // Moved beside the sofa, the chair joins its group: turned to the coffee table in front
    // of the sofa, not left facing where it faced.
    let cmd = parse("move the chair next to the sofa", &objs, None).unwrap();
    let end = final_pose(&st, "chair1", &cmd).unwrap();
    let to = [
        table.position[0] - end.position[0],
        table.position[1] - end.position[1],
    ];
    let want = (-to[0]).atan2(to[1]).to_degrees();
    let off = ((end.yaw - want + 540.0) % 360.0 - 180.0).abs();
    assert!(
        off < 1.0,
        "chair turned {:.0}°, the table is at {want:.0}°",
        end.yaw
    );
    let moved = dreamscene::edit::ops::with_pose(&st, "chair1", end).unwrap();
    let sofa = moved.box_of(moved.object("sofa1").unwrap());
    let g = dreamscene::plan::check::gap(&moved.box_of(moved.object("chair1").unwrap()), &sofa);
    assert!(g <= 0.5, "gap {g} to the sofa");
}

#[test]
fn animation_timeline_plays_through_compose_at_and_warns_of_walls() {
    let d = scene_dir("anim");
    let st = SceneState::open(&d).unwrap();
    let chair = st.object("chair1").unwrap().clone();
    // A static scene composes at any time to what scene.ply holds.
    let still = compose_at(&d, 1.0).unwrap();
    let ply = dreamscene::splat::ply::read_ply(&d.join("scene.ply")).unwrap();
    assert!(still.means == ply.means && still.sh == ply.sh);
    let e = animate(
        &st,
        "chair1",
        "move forward 1 m then spin once",
        Some(3.0),
        10.0,
    )
    .unwrap();
    let tl = e.scene.timeline.clone().unwrap();
    assert!((tl.duration - 3.0).abs() < 1e-9, "{}", tl.duration);
    assert_eq!(tl.tracks.len(), 1);
    // Static transform unchanged; only the track moves it.
    assert_eq!(e.scene.objects, st.scene.objects);
    dreamscene::edit::apply_edit(&st, e, None).unwrap();
    // The chair's Gaussians (placed in scene.json order) move with the track.
    let idx = st
        .scene
        .objects
        .iter()
        .position(|o| o.id == "chair1")
        .unwrap();
    let counts: Vec<usize> = st
        .scene
        .objects
        .iter()
        .map(|o| {
            dreamscene::splat::ply::read_ply(&d.join(&o.ply))
                .unwrap()
                .len()
        })
        .collect();
    let start: usize = counts[..idx].iter().sum();
    let centroid = |t: f64| {
        let g = compose_at(&d, t).unwrap();
        let m = &g.means[start..start + counts[idx]];
        let n = m.len() as f64;
        [0, 1].map(|a| m.iter().map(|p| p[a] as f64).sum::<f64>() / n)
    };
    let (c0, c1) = (centroid(0.0), centroid(3.0));
    let moved = (c1[0] - c0[0]).hypot(c1[1] - c0[1]);
    assert!((moved - 1.0).abs() < 0.02, "moved {moved}");
    let f = {
        let (s, c) = chair.yaw.to_radians().sin_cos();
        [-s, c]
    };
    assert!(((c1[0] - c0[0]) * f[0] + (c1[1] - c0[1]) * f[1] - 1.0).abs() < 0.02);
    // A path through a wall is reported with its time.
    let st = SceneState::open(&d).unwrap();
    let e = animate(&st, "chair1", "move forward 20 m in 4 seconds", None, 10.0).unwrap();
    assert!(
        e.notes
            .iter()
            .any(|n| n.starts_with("warning: at t = ") && n.contains("wall")),
        "{:?}",
        e.notes
    );
}

#[test]
fn shape_prior_restyle_recolours_from_colour_words_and_says_so() {
    use dreamscene::edit::reopt::ReoptConfig;
    use dreamscene::edit::restyle::restyle;
    use dreamscene::splat::cloud::SH_C0;
    let d = scene_dir("restyle");
    let st = SceneState::open(&d).unwrap();
    let cfg = ReoptConfig::default();
    let old = dreamscene::splat::ply::read_ply(&d.join("objects/chair.ply")).unwrap();
    let e = restyle(
        None,
        &st,
        "chair1",
        "a bright red leather chair",
        None,
        &cfg,
    )
    .unwrap();
    assert!(
        e.notes
            .iter()
            .any(|n| n.contains("shape prior: recoloured") && n.contains("red")),
        "{:?}",
        e.notes
    );
    let new = &e.files["objects/chair.ply"];
    assert_eq!(new.means, old.means, "geometry kept");
    assert_eq!(new.scales, old.scales);
    let mean = |g: &dreamscene::splat::Gaussians, c: usize| {
        g.sh.iter()
            .skip(c)
            .step_by(3)
            .map(|v| 0.5 + SH_C0 * *v as f64)
            .sum::<f64>()
            / g.len() as f64
    };
    assert!(mean(new, 0) > mean(new, 1) + 0.2 && mean(new, 0) > mean(new, 2) + 0.2);
    // The floor: only Gaussians below 5 cm change.
    let env = dreamscene::splat::ply::read_ply(&d.join("environment.ply")).unwrap();
    let e = restyle(None, &st, "floor", "a dark green carpet", None, &cfg).unwrap();
    let out = &e.files["environment.ply"];
    let (mut changed, mut kept) = (0, 0);
    for i in 0..env.len() {
        if env.means[i][2] < 0.05 {
            changed += (out.sh[i * 3..i * 3 + 3] != env.sh[i * 3..i * 3 + 3]) as usize;
        } else {
            assert_eq!(out.sh[i * 3..i * 3 + 3], env.sh[i * 3..i * 3 + 3]);
            kept += 1;
        }
    }
    assert!(changed > 1000 && kept > 1000, "{changed} {kept}");
    // Without a colour or material word the shape prior has nothing to do.
    let err = restyle(None, &st, "chair1", "a nicer chair", None, &cfg).unwrap_err();
    assert!(err.to_string().contains("can only recolour"), "{err}");
}

/// "move the sofa" in a lobby of two lobby sofas names no one instance: the answer says which
/// ones it could be; a sentence naming one instance (or none) has no such answer.
#[test]
fn a_name_shared_by_two_instances_says_which_it_could_be() {
    let objects: Vec<(String, String)> = [
        ("lobby sofa1", "lobby sofa"),
        ("lobby sofa2", "lobby sofa"),
        ("coffee table1", "coffee table"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    let text = "move the sofa 1 m to the right";
    // the parse finds no subject
    let cmd = parse(text, &objects, None);
    assert!(
        cmd.map_or(true, |c| c.subject.is_none()),
        "no one sofa is the subject"
    );
    let said = ambiguous(text, &objects).unwrap_or_default();
    assert!(
        said.contains("lobby sofa1") && said.contains("lobby sofa2"),
        "the two sofas are named: {said:?}"
    );
    assert_eq!(ambiguous("move the coffee table 1 m left", &objects), None);
    assert_eq!(ambiguous("turn it round", &objects), None);
}
