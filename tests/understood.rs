//! "Say what was understood": every object of a plan with its count and why it is there, the
//! words of the request that were not used, and the same in spec.json and on `plan`'s output.
use dreamscene::plan::offline::{plan_prompt, Plan};
use dreamscene::plan::understood::Because;

fn plan(p: &str) -> Plan {
    plan_prompt(p).unwrap_or_else(|e| panic!("{p}: {e}"))
}

fn why<'a>(p: &'a Plan, category: &str) -> &'a Because {
    p.understood
        .objects
        .iter()
        .find(|b| b.category == category)
        .unwrap_or_else(|| panic!("no {category} in {:?}", p.understood.objects))
}

#[test]
fn every_object_of_the_plan_is_explained_with_its_count() {
    for prompt in [
        "a guest bedroom with a reading chair",
        "a cafe terrace with 5 round tables and two chairs at each",
        "a classroom for 18 pupils",
    ] {
        let p = plan(prompt);
        let listed: Vec<(&str, u32)> = p
            .understood
            .objects
            .iter()
            .map(|b| (b.category.as_str(), b.count))
            .collect();
        let planned: Vec<(&str, u32)> = p
            .spec
            .objects
            .iter()
            .map(|(c, o)| (c.as_str(), o.number))
            .collect();
        assert_eq!(listed, planned, "{prompt}");
        for b in &p.understood.objects {
            assert!(!b.why.is_empty(), "{prompt}: {b:?}");
        }
    }
}

#[test]
fn named_default_and_inferred_are_told_apart() {
    let p = plan("a kitchen with a table for four and a tall fridge");
    assert_eq!(why(&p, "refrigerator").why, "named", "{:?}", p.understood);
    let chairs = p
        .understood
        .objects
        .iter()
        .find(|b| b.why.starts_with("inferred from") && b.why.contains("for four"))
        .unwrap_or_else(|| panic!("no seat inferred from \"for four\": {:?}", p.understood));
    assert_eq!(chairs.count, 4, "{chairs:?}");
    assert!(
        p.understood
            .objects
            .iter()
            .any(|b| b.why == "default for a kitchen"),
        "{:?}",
        p.understood
    );

    let p = plan("a patio with three small tables, each with two stools");
    let stools = why(&p, "stool");
    assert_eq!(stools.count, 6, "{stools:?}");
    assert!(
        stools.why.starts_with("inferred from") && stools.why.contains("two stools"),
        "{stools:?}"
    );
}

#[test]
fn words_the_plan_does_not_use_are_listed_and_no_others() {
    let p = plan("a haunted bedroom with a sofa that smells of ozone");
    let unused = &p.understood.unused;
    for w in ["haunted", "ozone"] {
        assert!(unused.iter().any(|u| u == w), "{w} not in {unused:?}");
    }
    for w in ["bedroom", "sofa", "a", "with", "that"] {
        assert!(!unused.iter().any(|u| u == w), "{w} in {unused:?}");
    }
    let p = plan("a small modern living room with two grey armchairs by the window");
    assert!(p.understood.unused.is_empty(), "{:?}", p.understood.unused);
    // a placement word the relations read is used
    let p = plan("a hallway with a console table and a mirror above it");
    assert!(
        !p.understood.unused.iter().any(|u| u == "above"),
        "{:?}",
        p.understood.unused
    );
    // the ground a place stands on is read (a rooftop's parapet is drawn round it)
    let p = plan("a rooftop terrace with two bistro tables and a parasol");
    assert!(p.understood.unused.is_empty(), "{:?}", p.understood.unused);
}

#[test]
fn plan_prints_and_records_what_was_understood() {
    let dir = std::env::temp_dir().join(format!("dreamscene-understood-{}", std::process::id()));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(["plan", "a study with a desk for two and a globe of brass"])
        .arg("--out")
        .arg(dir.as_path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("understood:"), "{stdout}");
    assert!(stdout.contains("1 desk: named"), "{stdout}");
    let spec: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.as_path().join("spec.json")).unwrap())
            .unwrap();
    let objects = spec["understood"]["objects"].as_array().unwrap();
    assert_eq!(objects.len(), spec["objects"].as_object().unwrap().len());
    assert!(objects
        .iter()
        .any(|o| o["category"] == "desk" && o["count"] == 1 && o["why"] == "named"));
    assert!(spec["unsatisfied"].is_array());
    // spec.json with the added keys still reads as a SceneSpec
    dreamscene::plan::spec::SceneSpec::read(&dir.as_path().join("spec.json")).unwrap();
    std::fs::remove_dir_all(&dir).ok();
}

/// A description says each word once: the adjectives the user gave, minus those the category's
/// name already has ("a big potted palm" is not "a big potted potted plant").
#[test]
fn descriptions_do_not_repeat_the_name_s_words() {
    for prompt in [
        "a florist's with a counter and a big potted palm by the window",
        "a hallway with a tall potted fern and a coat rack",
        "a kitchen with a big wooden dining table",
    ] {
        let p = plan(prompt);
        for (c, o) in &p.spec.objects {
            let words: Vec<&str> = o.description.split_whitespace().collect();
            for pair in words.windows(2) {
                assert_ne!(pair[0], pair[1], "{prompt}: {c}: {}", o.description);
            }
        }
    }
}

/// "A wall of mirrors" is one mirror panel over a wall, not two small mirrors. Prompts written
/// before the category.
#[test]
fn a_wall_of_mirrors_is_one_mirror_wall() {
    for prompt in [
        "a gym with three treadmills and a wall of mirrors",
        "a dance room with a mirrored wall",
        "a hallway with a wall-to-wall mirror and a bench",
    ] {
        let p = plan(prompt);
        assert_eq!(why(&p, "mirror wall").count, 1, "{prompt}");
        assert!(
            !p.spec.objects.contains_key("mirror"),
            "{prompt}: no small mirrors"
        );
    }
}

/// "Buckets of flowers" are flower buckets (a bucket holding cut flowers), not empty pails; a
/// bucket alone stays a bucket. Prompts written before the category.
#[test]
fn buckets_of_flowers_hold_flowers() {
    let p = plan("a flower stall with four buckets of flowers and a counter");
    assert_eq!(why(&p, "flower bucket").count, 4, "four flower buckets");
    assert!(!p.spec.objects.contains_key("bucket"), "no empty pails");
    let p = plan("a utility room with a washing machine and a bucket");
    assert_eq!(why(&p, "bucket").count, 1, "a bucket alone");
}

#[test]
fn a_room_for_so_many_people_is_told_without_the_next_words() {
    for (prompt, said) in [
        ("a dining room for eight", "inferred from \"for eight\""),
        (
            "a dining room for eight, a sideboard",
            "inferred from \"for eight\"",
        ),
        (
            "a dining room for ten and a rug",
            "inferred from \"for ten\"",
        ),
        (
            "a meeting room for 6 people",
            "inferred from \"for 6 people\"",
        ),
    ] {
        let p = plan(prompt);
        let seats: Vec<&Because> = p
            .understood
            .objects
            .iter()
            .filter(|b| b.why.starts_with("inferred from"))
            .collect();
        assert!(!seats.is_empty(), "{prompt}: {:?}", p.understood);
        for b in seats {
            assert_eq!(b.why, said, "{prompt}: {b:?}");
        }
    }
}
