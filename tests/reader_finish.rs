//! The finish a place gives its furniture: in a clinical place (named so by its kind or by the
//! words naming the place) the cabinets and stools the knowledge base describes as wooden are
//! white steel, while a home's, a garage's (even one holding something medical) stay wooden and
//! an object the text describes keeps its words; an operating room hangs a surgical light over
//! its table. Prompts of no corpus.
mod reading;
use dreamscene::plan::spec::{RelationKind, SceneSpec};
use reading::{keys, plan};

fn description(spec: &SceneSpec, category: &str) -> String {
    spec.objects
        .get(category)
        .map(|o| o.description.clone())
        .unwrap_or_else(|| panic!("no {category}: {:?}", keys(spec)))
}

#[test]
fn a_clinical_place_has_white_steel_cabinets_not_wooden_ones() {
    for prompt in [
        "an operating room",
        "a dental clinic",
        "a hospital ward with a cabinet",
        "a vet's surgery with two cabinets and a stool",
    ] {
        let s = plan(prompt);
        let d = description(&s, "cabinet");
        assert!(
            d.contains("white steel") && !d.contains("wooden"),
            "{prompt}: {d}"
        );
    }
    let s = plan("an operating room");
    let d = description(&s, "stool");
    assert!(d.contains("white steel"), "an operating room: {d}");
}

#[test]
fn other_places_and_described_objects_keep_their_wood() {
    for (prompt, category) in [
        ("a living room with a cabinet", "cabinet"),
        ("a garage with a medical cart and a stool", "stool"),
        ("a kitchen with a cabinet and a first aid kit", "cabinet"),
    ] {
        let s = plan(prompt);
        let d = description(&s, category);
        assert!(
            d.contains("wooden") && !d.contains("steel"),
            "{prompt}: {d}"
        );
    }
    let s = plan("an operating room with an oak cabinet");
    let d = description(&s, "cabinet");
    assert!(d.contains("oak") && !d.contains("steel"), "{d}");
}

#[test]
fn an_operating_room_hangs_a_surgical_light_over_its_table() {
    for prompt in [
        "an operating room",
        "a surgical theatre with two medical carts",
        "an operating theater with an operating light",
    ] {
        let s = plan(prompt);
        assert_eq!(
            s.objects.get("surgical light").map(|o| o.number),
            Some(1),
            "{prompt}: {:?}",
            keys(&s)
        );
        let over = s.relations.iter().any(|r| {
            r.subject == "surgical light1"
                && r.relation == RelationKind::Over
                && r.object == "operating table1"
        });
        assert!(over, "{prompt}: {:?}", s.relations);
        assert!(!s.objects.contains_key("examination lamp"), "{prompt}");
    }
}
