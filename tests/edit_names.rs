//! Edit verbs take names as well as ids ("sofa" is sofa1, "the chalkboard menu" its id), an
//! ambiguous name lists the ids to choose from, and `add` reads a count ("two cafe chairs").
//! Host-only.
use dreamscene::edit::parse::{count_of, resolve};

fn scene() -> Vec<(String, String)> {
    [
        ("sofa1", "sofa"),
        ("chair1", "chair"),
        ("chair2", "chair"),
        ("chalkboard menu1", "chalkboard menu"),
        ("blackboard1", "blackboard"),
        ("floor lamp1", "floor lamp"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect()
}

#[test]
fn names_resolve_to_the_one_instance_they_mean() {
    let s = scene();
    for (name, id) in [
        ("sofa1", "sofa1"),
        ("sofa", "sofa1"),
        ("the sofa", "sofa1"),
        ("The big grey couch", "sofa1"),
        ("the chalkboard menu", "chalkboard menu1"),
        ("chalkboard", "blackboard1"),
        ("the lamp", "floor lamp1"),
        ("chair2", "chair2"),
    ] {
        assert_eq!(resolve(name, &s).as_deref(), Ok(id), "{name}");
    }
}

#[test]
fn an_ambiguous_or_unknown_name_lists_the_ids() {
    let s = scene();
    let e = resolve("the chair", &s).unwrap_err();
    assert!(e.contains("chair1") && e.contains("chair2"), "{e}");
    assert!(!e.contains('\n'), "{e}");
    let e = resolve("the piano", &s).unwrap_err();
    assert!(e.contains("piano") && e.contains("sofa1"), "{e}");
}

#[test]
fn add_reads_the_count_of_its_description() {
    for (text, n, rest) in [
        ("two cafe chairs", 2, "cafe chairs"),
        ("3 bar stools", 3, "bar stools"),
        ("a pair of bedside lamps", 2, "bedside lamps"),
        ("a dozen candles", 12, "candles"),
        ("a green armchair", 1, "a green armchair"),
        ("armchair", 1, "armchair"),
    ] {
        assert_eq!(count_of(text), (n, rest.to_string()), "{text}");
    }
}
