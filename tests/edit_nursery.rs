//! Edit verbs on a drafted nursery whose dresser stands under the window: a small thing asked
//! "on the dresser" stands on it (the window does not push it off, as a lamp on a sill); a
//! refused add names no `--force` it does not have; "back and forth three times" is three
//! swings that end where they began, and a count a motion cannot read is said; a move that ends
//! a centimetre through a wall stops at it.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use common::edit;
use dreamscene::edit::parse::{parse, Step};
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::gcp::{layout_pinned, LayoutOptions, Pin};
use dreamscene::plan::spec::{Layout, PlacedBy, SceneSpec};
use dreamscene::scene::dir::read_scene;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const ROOM: &str = r#"{"size": [5.3, 4.2, 2.8]}"#;
const OPENINGS: &str = r#"[
  {"kind": "door", "wall": "south", "position": [-1.0, -2.1, 0.0], "width": 0.9, "height": 2.1},
  {"kind": "window", "wall": "north", "position": [0.0, 2.1, 0.9], "width": 1.4, "height": 1.3}]"#;

/// A nursery drafted by hand: a dresser with its back to the north wall under the window, a
/// changing table on the east wall, a rocking chair whose left side is 0.49 m from the west wall.
fn draft(name: &str) -> PathBuf {
    let spec: SceneSpec = serde_json::from_str(&format!(
        r#"{{"scene_type": "indoor", "scene_text": "a nursery", "room": {ROOM},
            "objects": {{
              "dresser": {{"number": 1, "size": [1.2, 0.5, 0.85], "description": "a dresser"}},
              "changing table": {{"number": 1, "size": [0.9, 0.55, 0.95], "description": "a table"}},
              "rocking chair": {{"number": 1, "size": [0.7, 0.9, 1.0], "description": "a chair"}}}},
            "anchors": {{"dresser1": "SIDE", "changing table1": "SIDE"}}, "relations": []}}"#
    ))
    .unwrap();
    let l: Layout = serde_json::from_str(&format!(
        r#"{{"scene_type": "indoor", "room": {ROOM}, "seed": 0, "openings": {OPENINGS},
            "objects": [
             {{"id": "dresser1", "category": "dresser", "size": [1.2, 0.5, 0.85],
               "position": [-0.09, 1.83, 0.0], "yaw": 180.0, "anchor": "SIDE", "placed_by": "constraint"}},
             {{"id": "changing table1", "category": "changing table", "size": [0.9, 0.55, 0.95],
               "position": [2.355, 0.87, 0.0], "yaw": 90.0, "anchor": "SIDE", "placed_by": "constraint"}},
             {{"id": "rocking chair1", "category": "rocking chair", "size": [0.7, 0.9, 1.0],
               "position": [-1.81, -0.14, 0.0], "yaw": 0.0, "anchor": "OTHERS", "placed_by": "constraint"}}],
            "unsatisfied": []}}"#
    ))
    .unwrap();
    let d = std::env::temp_dir().join(format!("ds-nursery-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("renders")).unwrap();
    std::fs::write(d.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&d.join("layout.json")).unwrap();
    write_draft_scene(&d, "a nursery", 0, &spec, &l, false, &mut |_| {}).unwrap();
    let mut cam = dreamscene::camera::Camera::look_at(
        [1.6, -1.4, 1.7],
        [0.0, 0.0, 0.5],
        [0.0, 0.0, 1.0],
        32,
        32,
        1.2,
    );
    cam.img_name = "view".into();
    dreamscene::camera::write_cameras(&d.join("renders/cameras.json"), &[cam]).unwrap();
    d
}

fn run(dir: &Path, args: &[&str]) -> (bool, String) {
    let o = edit(dir, args);
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    (o.status.success(), text)
}

fn position(dir: &Path, id: &str) -> [f64; 3] {
    let s = read_scene(dir).unwrap();
    s.objects.iter().find(|o| o.id == id).unwrap().position
}

/// The layout of an add, as `edit add` asks it (every present instance pinned, the new one OVER
/// the support): a small thing on a support that stands under a window rests on its top.
#[test]
fn a_small_thing_on_a_support_under_a_window_rests_on_it() {
    let room: serde_json::Value = serde_json::from_str(ROOM).unwrap();
    let openings: Vec<dreamscene::plan::spec::Opening> = serde_json::from_str(OPENINGS).unwrap();
    for (cat, size) in [
        ("table lamp", [0.3, 0.3, 0.5]),
        ("vase", [0.2, 0.2, 0.35]),
        ("teddy bear", [0.35, 0.3, 0.45]),
    ] {
        let spec: SceneSpec = serde_json::from_value(serde_json::json!({
            "scene_type": "indoor", "scene_text": "a nursery", "room": room,
            "objects": {
                "dresser": {"number": 1, "size": [1.2, 0.5, 0.85], "description": "a dresser"},
                cat: {"number": 1, "size": size, "description": cat}},
            "anchors": {"dresser1": "SIDE"},
            "relations": [{"subject": format!("{cat}1"), "relation": "OVER", "object": "dresser1"}]
        }))
        .unwrap();
        let pins: BTreeMap<String, Pin> = [(
            "dresser1".to_string(),
            Pin {
                position: [-0.09, 1.83, 0.0],
                yaw: 180.0,
            },
        )]
        .into();
        for seed in 0..3 {
            let l =
                layout_pinned(&spec, LayoutOptions::seeded(seed), &pins, Some(&openings)).unwrap();
            let o = l
                .objects
                .iter()
                .find(|o| o.id == format!("{cat}1"))
                .unwrap();
            let on = (o.position[2] - 0.85).abs() < 0.05
                && (o.position[0] + 0.09).abs() <= 0.6
                && (o.position[1] - 1.83).abs() <= 0.25;
            assert!(
                on && o.placed_by == PlacedBy::Constraint,
                "seed {seed}: {cat} at {:?} ({:?}), not on the dresser",
                o.position,
                o.placed_by
            );
        }
    }
}

#[test]
fn edit_verbs_on_the_nursery() {
    let dir = draft("verbs");
    // on the dresser under the window
    let (ok, text) = run(&dir, &["add", "a teddy bear on the dresser"]);
    assert!(ok, "{text}");
    let p = position(&dir, "teddy bear1");
    assert!((p[2] - 0.85).abs() < 0.05, "teddy bear at {p:?}: {text}");
    // a refused add names no --force: add has none
    let (ok, text) = run(&dir, &["add", "a king size bed on the changing table"]);
    if !ok {
        assert!(!text.contains("--force"), "{text}");
    }
    // three swings back and forth, ending where it began
    let (ok, text) = run(
        &dir,
        &[
            "animate",
            "rocking chair1",
            "rock back and forth three times",
            "--seconds",
            "3",
        ],
    );
    assert!(ok, "{text}");
    let s = read_scene(&dir).unwrap();
    let tl = s.timeline.unwrap();
    let track = tl.tracks.iter().find(|t| t.id == "rocking chair1").unwrap();
    let start = track.keys[0].position;
    let off: Vec<bool> = track
        .keys
        .iter()
        .map(|k| (k.position[1] - start[1]).abs() > 0.05)
        .collect();
    let swings = off.windows(2).filter(|w| !w[0] && w[1]).count();
    let end = track.keys.last().unwrap();
    assert!(
        swings == 3 && (end.position[1] - start[1]).abs() < 1e-6 && (end.t - 3.0).abs() < 1e-3,
        "{swings} swings, ending at {:?} at {} s",
        end.position,
        end.t
    );
    // a count a slide cannot read is said
    let (ok, text) = run(
        &dir,
        &["animate", "rocking chair1", "slide back three times"],
    );
    assert!(ok && text.contains("\"three times\""), "{text}");
    // 0.50 m to its left from 0.49 m off the west wall: it stops at the wall
    let (ok, text) = run(&dir, &["move", "move the rocking chair 50 cm to the left"]);
    assert!(ok, "{text}");
    let p = position(&dir, "rocking chair1");
    assert!(
        p[0] - 0.35 >= -2.65 - 1e-6 && text.contains("stops at the wall"),
        "rocking chair at {p:?}: {text}"
    );
}

#[test]
fn to_and_fro_side_to_side_and_counts_are_read() {
    let objects = vec![("rocking horse1".to_string(), "rocking horse".to_string())];
    let cases: [(&str, u32, bool); 4] = [
        ("rock to and fro twice", 2, false),
        ("sway from side to side 4 times", 4, true),
        ("rock backwards and forwards", 1, false),
        ("wobble left and right three times", 3, true),
    ];
    for (text, n, sideways) in cases {
        let c = parse(text, &objects, Some("rocking horse1")).unwrap();
        assert!(
            matches!(c.steps[0].0, Step::Sway { times, across, .. } if times == n && across == sideways)
                && c.unread.is_empty(),
            "{text}: {:?} unread {:?}",
            c.steps,
            c.unread
        );
    }
    let c = parse("turn left twice", &objects, Some("rocking horse1")).unwrap();
    assert_eq!(c.unread, vec!["twice".to_string()]);
}
