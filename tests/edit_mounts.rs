//! An edit that redraws an instance draws it held up as the scene holds it, not as the
//! knowledge base would on its own: a TV in a room with no stand for it hangs on the wall, so a
//! restyle of it ("a red tv") is the wall TV recoloured part by part (its screen stays dark), not
//! the standing TV's drawing on its foot, which no longer matches the scene's cloud and left only
//! a tint over the whole set, screen included. Shape prior, no GPU; a few seconds in debug.
#![allow(clippy::unwrap_used, reason = "tests")]
use dreamscene::edit::reopt::ReoptConfig;
use dreamscene::edit::restyle::restyle;
use dreamscene::edit::state::SceneState;
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::SceneSpec;
use dreamscene::shape::Mount;
use dreamscene::splat::cloud::SH_C0;
use std::path::PathBuf;

/// A small den with a TV and an armchair; `extra` adds objects to the spec, `anchors` are its
/// anchors.
fn den(name: &str, extra: &str, anchors: &str) -> PathBuf {
    let spec: SceneSpec = serde_json::from_str(&format!(
        r#"{{"scene_type": "indoor", "scene_text": "a small den",
            "room": {{"size": [3.6, 3.2, 2.5]}},
            "objects": {{
              "tv": {{"number": 1, "size": [1.0, 0.08, 0.6], "description": "a flat tv"}},
              "armchair": {{"number": 1, "size": [0.8, 0.8, 0.9], "description": "an armchair"}}{extra}}},
            "anchors": {{{anchors}}},
            "relations": []}}"#
    ))
    .unwrap();
    let l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
    let d = std::env::temp_dir().join(format!("ds-edit-mounts-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    std::fs::write(d.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&d.join("layout.json")).unwrap();
    write_draft_scene(&d, "a small den", 0, &spec, &l, false, &mut |_| {}).unwrap();
    d
}

/// Share of the cloud's Gaussians darker than 0.2 in every channel (a TV's screen and set).
fn dark_share(g: &dreamscene::splat::Gaussians) -> f64 {
    let dark = (0..g.len())
        .filter(|&i| (0..3).all(|c| 0.5 + SH_C0 * (g.sh[i * 3 + c] as f64) < 0.2))
        .count();
    dark as f64 / g.len() as f64
}

#[test]
fn a_restyled_wall_tv_is_the_wall_tv_recoloured() {
    // nothing to stand the TV on: it hangs on the wall
    let d = den("wall-tv", "", "");
    let st = SceneState::open(&d).unwrap();
    // the scene holds its TV on the wall; the knowledge base alone would stand it on a foot
    assert_eq!(st.mount("tv"), Mount::Wall);
    assert_eq!(Mount::of_category("tv"), Mount::Stand);
    let ply = st.object("tv1").unwrap().ply.clone();
    let old = dreamscene::splat::ply::read_ply(&d.join(&ply)).unwrap();
    let e = restyle(None, &st, "tv1", "a red tv", None, &ReoptConfig::default()).unwrap();
    assert!(
        e.notes
            .iter()
            .any(|n| n.contains("shape prior: recoloured") && n.contains("red")),
        "the wall TV was not redrawn as it hangs: {:?}",
        e.notes
    );
    let new = &e.files[&ply];
    assert_eq!(new.means, old.means, "geometry kept");
    // the set turns red, its screen stays dark (a tint over the whole reddened the screen too)
    let (before, after) = (dark_share(&old), dark_share(new));
    assert!(
        after > 0.3 && after < 0.9 * before,
        "dark before {before:.2}, after {after:.2}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_tv_on_its_stand_keeps_its_foot_when_restyled() {
    let d = den(
        "stand-tv",
        r#", "tv stand": {"number": 1, "size": [1.2, 0.4, 0.5], "description": "a tv stand"}"#,
        "",
    );
    let st = SceneState::open(&d).unwrap();
    assert_eq!(st.mount("tv"), Mount::Stand);
    let e = restyle(
        None,
        &st,
        "tv1",
        "a white tv",
        None,
        &ReoptConfig::default(),
    )
    .unwrap();
    assert!(
        e.notes
            .iter()
            .any(|n| n.contains("shape prior: recoloured")),
        "{:?}",
        e.notes
    );
    let _ = std::fs::remove_dir_all(&d);
}
