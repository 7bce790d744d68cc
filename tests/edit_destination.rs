//! `dreamscene edit move` reads a place as `add` and `plan` read it: "under the window", "next
//! to the door", "into the corner" send the desk there (placed by the layout, the others where
//! they stand), and the chair at the desk goes with it, still at it, whichever way the desk
//! moves (by a place, by a shift, or turned).
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use common::edit;
use dreamscene::export::labels::write_labelled_scene;
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::check::{anchor_holds_in, relation_holds, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{Anchor, Layout, RelationKind, SceneSpec};
use dreamscene::scene::dir::read_scene;
use std::path::{Path, PathBuf};

/// A 4.5 x 4 m study laid out by GCP with `seed`: a desk with its office chair at it, a
/// bookshelf, a filing cabinet and an armchair; one 48² view.
fn draft(name: &str, seed: u64) -> PathBuf {
    let spec: SceneSpec = serde_json::from_str(
        r#"{"scene_type": "indoor", "scene_text": "a study",
            "room": {"size": [4.5, 4.0, 2.6]},
            "objects": {
              "desk": {"number": 1, "size": [1.2, 0.6, 0.75], "description": "a desk"},
              "office chair": {"number": 1, "size": [0.6, 0.6, 1.0], "description": "a chair"},
              "bookshelf": {"number": 1, "size": [0.9, 0.35, 1.8], "description": "a shelf"},
              "filing cabinet": {"number": 1, "size": [0.45, 0.6, 1.0], "description": "a cabinet"},
              "armchair": {"number": 1, "size": [0.8, 0.8, 0.9], "description": "an armchair"}},
            "anchors": {"desk1": "CENTER", "bookshelf1": "SIDE", "filing cabinet1": "SIDE"},
            "relations": [{"subject": "office chair1", "relation": "AT", "object": "desk1"}]}"#,
    )
    .unwrap();
    let l = layout(&spec, LayoutOptions::seeded(seed)).unwrap();
    let d = std::env::temp_dir().join(format!("ds-dest-{name}-{seed}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("renders")).unwrap();
    std::fs::write(d.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&d.join("layout.json")).unwrap();
    write_draft_scene(&d, "a study", seed, &spec, &l, false, &mut |_| {}).unwrap();
    let s = read_scene(&d).unwrap();
    write_labelled_scene(&d, &s).unwrap();
    let mut cam = dreamscene::camera::Camera::look_at(
        [1.6, -1.4, 1.7],
        [0.0, 0.0, 0.5],
        [0.0, 0.0, 1.0],
        48,
        48,
        1.2,
    );
    cam.img_name = "view".into();
    dreamscene::camera::write_cameras(&d.join("renders/cameras.json"), &[cam]).unwrap();
    d
}

fn laid_out(dir: &Path) -> Layout {
    serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json")).unwrap()).unwrap()
}

/// Whether the desk stands at `anchor` and the chair is still AT it.
fn check(dir: &Path, anchor: Anchor, what: &str) {
    let l = laid_out(dir);
    let get = |id: &str| l.objects.iter().find(|o| o.id == id).unwrap();
    let (desk, chair) = (get("desk1"), get("office chair1"));
    assert!(
        anchor_holds_in(
            &Box2::of(desk),
            anchor,
            l.scene_type,
            l.room.size,
            &l.openings
        ),
        "{what}: desk1 at {:?} is not {anchor:?}",
        desk.position
    );
    assert!(
        relation_holds(chair, RelationKind::At, desk),
        "{what}: the chair at {:?} is no longer at the desk at {:?}",
        chair.position,
        desk.position
    );
}

fn run(dir: &Path, args: &[&str]) -> String {
    let o = edit(dir, args);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{args:?}: {err}");
    err
}

#[test]
fn a_move_to_a_place_sends_the_desk_there_and_its_chair_follows() {
    for seed in 0..3 {
        let d = draft("places", seed);
        for (said, anchor) in [
            ("under the window", Anchor::Window),
            ("next to the door", Anchor::Door),
            ("move it into the corner", Anchor::Corner),
            ("over to the window", Anchor::Window),
            ("move the desk by the entrance", Anchor::Door),
        ] {
            let err = run(&d, &["move", "desk", said]);
            check(&d, anchor, &format!("seed {seed}, \"{said}\": {err}"));
        }
    }
}

#[test]
fn the_chair_at_a_desk_goes_with_it_when_it_is_shifted_or_turned() {
    let d = draft("shift", 1);
    let before = laid_out(&d);
    let desk = before.objects.iter().find(|o| o.id == "desk1").unwrap();
    // a shift toward the room's centre, then a quarter turn
    let by = [-desk.position[0] * 0.3, -desk.position[1] * 0.3];
    let err = run(
        &d,
        &["move", "desk1", "--by", &format!("{},{}", by[0], by[1])],
    );
    assert!(err.contains("office chair1"), "{err}");
    check(&d, Anchor::Others, "shifted");
    run(&d, &["move", "desk1", "--rotate", "90", "--force"]);
    check(&d, Anchor::Others, "turned");
}
