//! `dreamscene edit move` carries what rests on the moved object: a printer and a lamp on a desk
//! move and turn with it (a lamp on a book on the desk too), a chair beside it stays, and a rug
//! carries nothing (the armchair on it stays). A move that would end where the object already
//! stands is refused in one line and changes nothing, history included. `edit add` reads where
//! the description puts the new thing: "a potted plant next to the armchair" adds a plant by the
//! armchair (not a second armchair), "a laptop on the desk" a laptop on the desk's top, and a
//! partner the scene lacks is refused in one line. An edit whose new layout gives fewer good
//! preview views than there were names the views it removed.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use common::edit;
use dreamscene::export::labels::write_labelled_scene;
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::SceneSpec;
use dreamscene::scene::dir::read_scene;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-riders-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A 4 x 3.5 m study: a desk at the room's centre with a printer, a book and a lamp (on the
/// book) on it, a chair beside it, a rug with an armchair on it; one 48² view.
fn draft(name: &str) -> PathBuf {
    let spec: SceneSpec = serde_json::from_str(
        r#"{"scene_type": "indoor", "scene_text": "a study",
            "room": {"size": [4.0, 3.5, 2.5]},
            "objects": {
              "desk": {"number": 1, "size": [1.6, 0.7, 0.75], "description": "a desk"},
              "printer": {"number": 1, "size": [0.4, 0.35, 0.25], "description": "a printer"},
              "book": {"number": 1, "size": [0.2, 0.15, 0.04], "description": "a book"},
              "table lamp": {"number": 1, "size": [0.25, 0.25, 0.45], "description": "a lamp"},
              "chair": {"number": 1, "size": [0.45, 0.45, 0.85], "description": "a chair"},
              "rug": {"number": 1, "size": [1.6, 1.0, 0.01], "description": "a rug"},
              "armchair": {"number": 1, "size": [0.8, 0.8, 0.9], "description": "an armchair"}},
            "relations": []}"#,
    )
    .unwrap();
    let mut l = layout(&spec, LayoutOptions::seeded(1)).unwrap();
    for o in &mut l.objects {
        let (p, yaw) = match o.id.as_str() {
            "desk1" => ([0.0, 0.3, 0.0], 0.0),
            "printer1" => ([0.55, 0.3, 0.75], 0.0),
            "book1" => ([-0.3, 0.35, 0.75], 0.0),
            "table lamp1" => ([-0.3, 0.35, 0.79], 0.0),
            "chair1" => ([0.0, -0.35, 0.0], 180.0),
            "rug1" => ([0.0, -1.1, 0.0], 0.0),
            "armchair1" => ([0.5, -1.1, 0.0], 0.0),
            other => panic!("unexpected {other}"),
        };
        o.position = p;
        o.yaw = yaw;
    }
    let d = tmp(name);
    std::fs::write(d.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&d.join("layout.json")).unwrap();
    write_draft_scene(&d, "a study", 0, &spec, &l, false, &mut |_| {}).unwrap();
    let s = read_scene(&d).unwrap();
    write_labelled_scene(&d, &s).unwrap();
    std::fs::create_dir_all(d.join("renders")).unwrap();
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

fn pose(dir: &Path, id: &str) -> ([f64; 3], f64) {
    let s = read_scene(dir).unwrap();
    let o = s.objects.iter().find(|o| o.id == id).unwrap();
    (o.position, o.yaw)
}

fn near(a: [f64; 3], b: [f64; 3]) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() < 1e-3)
}

#[test]
fn what_rests_on_a_desk_moves_and_turns_with_it_and_a_rug_carries_nothing() {
    let d = draft("desk");
    let o = edit(&d, &["move", "desk1", "--by", "0.4,0.2"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    let shift = [0.4, 0.2, 0.0];
    for (id, was) in [
        ("printer1", [0.55, 0.3, 0.75]),
        ("book1", [-0.3, 0.35, 0.75]),
        ("table lamp1", [-0.3, 0.35, 0.79]),
    ] {
        let want = [was[0] + shift[0], was[1] + shift[1], was[2]];
        assert!(near(pose(&d, id).0, want), "{id}: {:?} {err}", pose(&d, id));
    }
    assert!(near(pose(&d, "chair1").0, [0.0, -0.35, 0.0]), "{err}");
    assert!(err.contains("rest on it"), "{err}");
    // a quarter turn about the desk's centre (0.4, 0.5): the printer 0.55 m to its right goes
    // 0.55 m in front (+y), turned with it
    let o = edit(&d, &["move", "desk1", "--rotate", "90", "--force"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (p, yaw) = pose(&d, "printer1");
    assert!(near(p, [0.4, 1.05, 0.75]), "{p:?}");
    assert!((yaw - 90.0).abs() < 1e-6, "{yaw}");
    // the rug moves alone
    let o = edit(&d, &["move", "rug1", "--by", "-0.3,0", "--force"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(near(pose(&d, "rug1").0, [-0.3, -1.1, 0.0]));
    assert!(near(pose(&d, "armchair1").0, [0.5, -1.1, 0.0]));
}

#[test]
fn a_move_that_ends_where_the_object_stands_is_refused_and_changes_nothing() {
    let d = draft("stay");
    // set against the south wall, then asked 0.3 m into it: the only free pose within reach
    // is where it stands
    let o = edit(&d, &["move", "armchair1", "--by", "0,-0.25", "--force"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let before = std::fs::read(d.join("scene.json")).unwrap();
    let o = edit(&d, &["move", "armchair1", "--by", "0,-0.3"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(!o.status.success(), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(
        err.contains("armchair1") && err.contains("south wall"),
        "{err}"
    );
    let o = edit(&d, &["move", "chair1", "--by", "0,0"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(
        !o.status.success() && err.contains("nothing to move"),
        "{err}"
    );
    assert_eq!(std::fs::read(d.join("scene.json")).unwrap(), before);
    let h = edit(&d, &["history"]);
    let out = String::from_utf8_lossy(&h.stdout).to_string() + &String::from_utf8_lossy(&h.stderr);
    assert_eq!(out.matches("move").count(), 1, "{out}");
}

fn category_count(dir: &Path, cat: &str) -> usize {
    read_scene(dir)
        .unwrap()
        .objects
        .iter()
        .filter(|o| o.category == cat)
        .count()
}

#[test]
fn add_reads_where_the_description_puts_the_new_thing() {
    let d = draft("add");
    let o = edit(&d, &["add", "a potted plant next to the armchair"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    assert_eq!(category_count(&d, "armchair"), 1, "{err}");
    assert_eq!(category_count(&d, "potted plant"), 1, "{err}");
    let (plant, _) = pose(&d, "potted plant1");
    let (arm, _) = pose(&d, "armchair1");
    let gap = (plant[0] - arm[0]).hypot(plant[1] - arm[1]);
    assert!(gap < 1.3, "plant {plant:?} armchair {arm:?}");
    let o = edit(&d, &["add", "a laptop on the desk"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    assert_eq!(category_count(&d, "desk"), 1, "{err}");
    let (laptop, _) = pose(&d, "laptop1");
    assert!((laptop[2] - 0.75).abs() < 0.02, "{laptop:?}");
    assert!(
        laptop[0].abs() < 0.8 && (laptop[1] - 0.3).abs() < 0.3,
        "{laptop:?}"
    );
    let before = std::fs::read(d.join("scene.json")).unwrap();
    let o = edit(&d, &["add", "a floor lamp next to the sofa"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(!o.status.success(), "{err}");
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("sofa"), "{err}");
    assert_eq!(std::fs::read(d.join("scene.json")).unwrap(), before);
}

/// Eight preview views (as `generate` names them) over the study, each with its picture.
fn eight_views(d: &Path) -> Vec<String> {
    let mut cams = vec![];
    for k in 0..8u32 {
        let a = f64::from(k) * std::f64::consts::PI / 4.0;
        let mut cam = dreamscene::camera::Camera::look_at(
            [1.5 * a.cos(), 1.3 * a.sin(), 1.6],
            [0.0, 0.0, 0.5],
            [0.0, 0.0, 1.0],
            32,
            32,
            1.2,
        );
        cam.img_name = format!("view_{k:04}");
        image::RgbImage::new(32, 32)
            .save(d.join(format!("renders/{}.png", cam.img_name)))
            .unwrap();
        cams.push(cam);
    }
    dreamscene::camera::write_cameras(&d.join("renders/cameras.json"), &cams).unwrap();
    cams.iter().map(|c| c.img_name.clone()).collect()
}

#[test]
fn views_the_new_layout_cannot_fill_are_named_when_an_edit_removes_them() {
    let d = draft("views");
    let before = eight_views(&d);
    let o = edit(&d, &["remove", "armchair1"]);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    let kept: Vec<String> = dreamscene::camera::read_cameras(&d.join("renders/cameras.json"))
        .unwrap()
        .into_iter()
        .map(|c| c.img_name)
        .collect();
    // Every view cameras.json names has its picture, and no picture is left without its view.
    for v in &before {
        let png = d.join(format!("renders/{v}.png")).is_file();
        assert_eq!(png, kept.contains(v), "{v}: picture {png}, kept {kept:?}");
    }
    // A 4 x 3.5 m study gives fewer than eight distinct good views: the ones removed are said.
    let gone: Vec<&String> = before.iter().filter(|v| !kept.contains(v)).collect();
    assert!(!gone.is_empty(), "all eight views kept: {kept:?}");
    for v in gone {
        assert!(
            err.contains(v.as_str()),
            "{v} removed without a word: {err}"
        );
    }
    // Undo brings every picture back.
    assert!(edit(&d, &["undo"]).status.success());
    for v in &before {
        assert!(
            d.join(format!("renders/{v}.png")).is_file(),
            "{v} not restored"
        );
    }
}
