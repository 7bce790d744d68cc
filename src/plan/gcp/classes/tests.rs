//! Tests of the placement classes and of [`super::apply`].
use super::*;
use crate::plan::kb::KnowledgeBase;

#[test]
fn every_category_has_a_placement_class() {
    let table = Placements::builtin();
    let missing: Vec<&str> = KnowledgeBase::builtin()
        .objects
        .iter()
        .map(|o| o.category.as_str())
        .filter(|c| table.get(c).is_none())
        .collect();
    assert!(missing.is_empty(), "no placement class: {missing:?}");
}

#[test]
fn classes_of_the_issue() {
    let t = Placements::builtin();
    for c in [
        "whiteboard",
        "blackboard",
        "painting",
        "projector screen",
        "wall shelf",
    ] {
        assert!(matches!(t.class(c), Class::OnWall(h) if h >= 0.4), "{c}");
    }
    for c in [
        "wardrobe",
        "bookshelf",
        "fireplace",
        "stove",
        "refrigerator",
        "dresser",
    ] {
        assert_eq!(t.class(c), Class::AgainstWall, "{c}");
    }
    for (c, s) in [
        ("table lamp", "nightstand"),
        ("laptop", "desk"),
        ("microscope", "science bench"),
        ("toaster", "kitchen counter"),
        ("cash register", "counter"),
        ("vase", "dining table"),
    ] {
        let p = t.get(c).expect(c);
        assert!(p.supports.iter().any(|x| x == s), "{c} on {s}");
    }
}

#[test]
fn malformed_lines_are_named() {
    let e = Placements::parse("lamp | on_surface | - | -\n").unwrap_err();
    assert!(e.contains("line 1"), "{e}");
    let e = Placements::parse("# c\nclock | on_wall | high | -\n").unwrap_err();
    assert!(e.contains("line 2") && e.contains("high"), "{e}");
}

/// A spec of 0.6 × 0.6 × 0.8 m objects (one of each), anchors and relations as JSON; the
/// layout tests of `gcp` share it.
pub(in crate::plan::gcp) fn spec(objects: &[&str], anchors: &str, relations: &str) -> SceneSpec {
    let objects: Vec<String> = objects
        .iter()
        .map(|c| format!(r#""{c}":{{"number":1,"size":[0.6,0.6,0.8],"description":"d"}}"#))
        .collect();
    let text = format!(
        r#"{{"scene_type":"indoor","scene_text":"t","objects":{{{}}},"anchors":{{{anchors}}},"relations":[{relations}]}}"#,
        objects.join(",")
    );
    serde_json::from_str(&text).expect("spec")
}

#[test]
fn a_thing_on_two_supports_keeps_the_one_its_class_names() {
    let mut s = spec(
        &["coffee machine", "cafe table", "counter"],
        "",
        r#"{"subject":"coffee machine1","relation":"OVER","object":"cafe table1"},
           {"subject":"coffee machine1","relation":"OVER","object":"counter1"}"#,
    );
    apply(&mut s);
    let on: Vec<&str> = s
        .relations
        .iter()
        .filter(|r| r.subject == "coffee machine1" && r.relation == RelationKind::Over)
        .map(|r| r.object.as_str())
        .collect();
    assert_eq!(on, ["counter1"]);
    // one support the class does not name is kept
    let mut s = spec(
        &["coffee machine", "cafe table"],
        "",
        r#"{"subject":"coffee machine1","relation":"OVER","object":"cafe table1"}"#,
    );
    apply(&mut s);
    assert_eq!(s.relations.len(), 1, "{:?}", s.relations);
}

#[test]
fn the_middle_gives_way_before_a_thing_at_a_window() {
    let rels = r#"{"subject":"coffee table1","relation":"FRONT","object":"sofa1"},
           {"subject":"rug1","relation":"UNDER","object":"coffee table1"}"#;
    let mut s = spec(
        &["sofa", "coffee table", "rug"],
        r#""sofa1":"FACE_WINDOW","coffee table1":"CENTER","rug1":"CENTER""#,
        rels,
    );
    apply(&mut s);
    assert_eq!(s.anchors["coffee table1"], Anchor::Others);
    assert_eq!(s.anchors["rug1"], Anchor::Others);
    // before a sofa against a wall, the coffee table keeps the middle
    let mut s = spec(
        &["sofa", "coffee table", "rug"],
        r#""sofa1":"SIDE","coffee table1":"CENTER","rug1":"CENTER""#,
        rels,
    );
    apply(&mut s);
    assert_eq!(s.anchors["coffee table1"], Anchor::Center);
    assert_eq!(s.anchors["rug1"], Anchor::Center);
}
