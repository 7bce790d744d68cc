//! Tests of the functional groups: which relations `apply` adds, keeps and drops.
use super::*;

fn spec(objects: &[(&str, u32, [f64; 3])], relations: &[(&str, &str, &str)]) -> SceneSpec {
    let objects: Vec<String> = objects
        .iter()
        .map(|(c, n, s)| format!(r#""{c}":{{"number":{n},"size":{s:?},"description":"d"}}"#))
        .collect();
    let relations: Vec<String> = relations
        .iter()
        .map(|(s, r, o)| format!(r#"{{"subject":"{s}","relation":"{r}","object":"{o}"}}"#))
        .collect();
    let text = format!(
        r#"{{"scene_type":"outdoor","scene_text":"t","objects":{{{}}},"relations":[{}]}}"#,
        objects.join(","),
        relations.join(",")
    );
    serde_json::from_str(&text).expect("spec")
}

/// Every relation of `s` as the text's own (kept by `apply`).
fn user_pairs(s: &SceneSpec) -> BTreeSet<(String, String)> {
    s.relations
        .iter()
        .map(|r| (r.subject.clone(), r.object.clone()))
        .collect()
}

fn has(spec: &SceneSpec, s: &str, rel: RelationKind, o: &str) -> bool {
    spec.relations
        .iter()
        .any(|r| r.subject == s && r.relation == rel && r.object == o)
}

#[test]
fn every_line_of_the_groups_table_reads() {
    let lines = include_str!("../kb/groups.txt")
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .count();
    assert_eq!(
        rules().len(),
        lines,
        "a line of kb/groups.txt does not read"
    );
}

#[test]
fn a_broken_groups_table_names_its_file_line_and_word() {
    let kb = super::super::kb::KnowledgeBase::builtin();
    let e = |t: &'static str| super::parse(t, kb).err();
    assert_eq!(
        e("# seats\noffice chair | AT | desk, craft bench | 1").as_deref(),
        Some("groups.txt line 2: unknown object `craft bench`")
    );
    assert_eq!(
        e("office chair | AROUND | meeting table | size").as_deref(),
        Some("groups.txt line 1: `meeting table` is a name of `conference table`")
    );
    assert_eq!(
        e("office chair | NEAR-ISH | desk | 1").as_deref(),
        Some("groups.txt line 1: unknown relation `NEAR-ISH`")
    );
    assert_eq!(
        e("any pond | UNDER | any gazebo roof | 1").as_deref(),
        Some("groups.txt line 1: no category is `gazebo roof` or ends in it")
    );
    assert!(
        e("office chair | AT | desk").is_some_and(|e| e.starts_with("groups.txt line 1: expected")),
        "a short line is an error"
    );
    assert!(
        super::parse("any pond | UNDER | any bridge | 1", kb).is_ok(),
        "`any` names a head noun"
    );
}

#[test]
fn any_kind_of_bridge_crosses_the_pond() {
    for bridge in ["wooden bridge", "bridge", "stone bridge"] {
        let mut s = spec(
            &[("pond", 1, [3.0, 2.0, 0.3]), (bridge, 1, [1.2, 3.5, 1.0])],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        assert!(
            has(&s, "pond1", RelationKind::Under, &format!("{bridge}1")),
            "{bridge}: {:?}",
            s.relations
        );
    }
    let mut s = spec(
        &[
            ("pond", 1, [3.0, 2.0, 0.3]),
            ("bridge table", 1, [1.0, 1.0, 1.0]),
        ],
        &[],
    );
    apply(&mut s, &BTreeSet::new());
    assert!(
        s.relations.is_empty(),
        "a bridge table is no bridge: {:?}",
        s.relations
    );
}

#[test]
fn things_around_a_fire_form_a_ring_and_seats_spread_over_every_table() {
    let mut s = spec(
        &[
            ("tent", 3, [2.5, 2.5, 1.5]),
            ("fire pit", 1, [1.0, 1.0, 0.4]),
        ],
        &[
            ("tent1", "AROUND", "fire pit1"),
            ("tent2", "AROUND", "fire pit1"),
        ],
    );
    let keep = user_pairs(&s);
    apply(&mut s, &keep);
    assert!(
        has(&s, "tent1", RelationKind::Circle, "fire pit1"),
        "{:?}",
        s.relations
    );
    // a table is no ring centre: chairs around it stay at its sides
    let mut s = spec(
        &[
            ("dining chair", 10, [0.45, 0.5, 0.9]),
            ("dining table", 1, [1.8, 0.9, 0.75]),
            ("reading table", 1, [1.2, 0.8, 0.75]),
        ],
        &[],
    );
    apply(&mut s, &BTreeSet::new());
    let at = |t: &str| {
        s.relations
            .iter()
            .filter(|r| r.relation == RelationKind::Around && r.object == t)
            .count()
    };
    assert_eq!(
        (at("dining table1"), at("reading table1")),
        (5, 5),
        "{:?}",
        s.relations
    );
    // benches down the sides of a table
    let mut s = spec(
        &[
            ("bench", 2, [1.2, 0.4, 0.45]),
            ("dining table", 1, [2.2, 1.0, 0.75]),
        ],
        &[],
    );
    apply(&mut s, &BTreeSet::new());
    assert!(
        has(&s, "bench2", RelationKind::Around, "dining table1"),
        "{:?}",
        s.relations
    );
}

#[test]
fn one_nightstand_for_twin_beds_stands_between_them_and_two_beds_keep_their_own() {
    let beds = |nightstands: u32| {
        let mut s = spec(
            &[
                ("single bed", 2, [1.0, 2.0, 0.9]),
                ("nightstand", nightstands, [0.5, 0.4, 0.55]),
            ],
            &[],
        );
        apply(&mut s, &BTreeSet::new());
        s
    };
    let s = beds(1);
    for bed in ["single bed1", "single bed2"] {
        assert!(
            has(&s, "nightstand1", RelationKind::Flank, bed),
            "{bed}: {:?}",
            s.relations
        );
    }
    let s = beds(2);
    assert!(
        has(&s, "nightstand1", RelationKind::Flank, "single bed1")
            && has(&s, "nightstand2", RelationKind::Flank, "single bed2"),
        "{:?}",
        s.relations
    );
    assert_eq!(s.relations.len(), 2, "{:?}", s.relations);
}

#[test]
fn hosts_and_supports_grow_to_what_they_hold_and_no_further() {
    // eight stools at one bar: the bar grows to seat them
    let mut s = spec(
        &[
            ("bar counter", 1, [3.0, 0.7, 1.1]),
            ("bar stool", 8, [0.4, 0.4, 0.75]),
        ],
        &[],
    );
    apply(&mut s, &BTreeSet::new());
    let bar = s.objects["bar counter"].size;
    assert!(counter_seats(bar) >= 8 && bar[0] < 4.5, "{bar:?}");
    // a bar that seats them already keeps its size
    let mut s = spec(
        &[
            ("bar counter", 1, [3.0, 0.7, 1.1]),
            ("bar stool", 4, [0.4, 0.4, 0.75]),
        ],
        &[],
    );
    apply(&mut s, &BTreeSet::new());
    assert_eq!(s.objects["bar counter"].size, [3.0, 0.7, 1.1]);
    // ten round tables for eighty chairs: each seats eight and stays square
    let mut s = spec(
        &[
            ("round table", 10, [1.0, 1.0, 0.75]),
            ("dining chair", 80, [0.45, 0.5, 0.9]),
        ],
        &[],
    );
    apply(&mut s, &BTreeSet::new());
    let t = s.objects["round table"].size;
    assert!(table_seats(t) >= 8 && t[0] == t[1], "{t:?}");
    // four computers on a 1.2 m bench: the bench grows; one monitor on a desk grows nothing
    let mut s = spec(
        &[
            ("science bench", 1, [1.2, 0.8, 0.9]),
            ("computer", 4, [0.6, 0.25, 0.5]),
        ],
        &(1..=4)
            .map(|k| {
                (
                    ["computer1", "computer2", "computer3", "computer4"][k - 1],
                    "OVER",
                    "science bench1",
                )
            })
            .collect::<Vec<_>>(),
    );
    apply(&mut s, &BTreeSet::new());
    let b = s.objects["science bench"].size;
    assert!(b[0] >= 4.0 * 0.6 && b[0] <= 3.6 + 1e-9, "{b:?}");
    let mut s = spec(
        &[("tv stand", 1, [1.2, 0.4, 0.5]), ("tv", 1, [1.4, 0.1, 0.8])],
        &[("tv1", "OVER", "tv stand1")],
    );
    apply(&mut s, &BTreeSet::new());
    assert_eq!(s.objects["tv stand"].size[0], 1.2);
}

#[test]
fn seats_bind_to_the_tables_named_before_default_desks() {
    let objects = [
        ("dining chair", 8, [0.45, 0.5, 0.9]),
        ("dining table", 2, [1.8, 0.9, 0.75]),
        ("school desk", 8, [0.7, 0.5, 0.75]),
    ];
    let mut s = spec(&objects, &[]);
    let named: BTreeSet<String> = ["dining chair", "dining table"].map(String::from).into();
    apply_named(&mut s, &BTreeSet::new(), &named);
    let at_tables = s
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Around && r.object.starts_with("dining table"))
        .count();
    assert_eq!(at_tables, 8, "{:?}", s.relations);
    // nothing named: the rules' order (a classroom's pupils at their desks)
    let mut s = spec(&objects, &[]);
    apply(&mut s, &BTreeSet::new());
    assert!(
        has(&s, "dining chair1", RelationKind::AtBack, "school desk1"),
        "{:?}",
        s.relations
    );
}

#[test]
fn a_seat_in_front_of_a_console_sits_at_it() {
    let mut s = spec(
        &[
            ("spaceship console", 2, [1.6, 0.8, 1.1]),
            ("office chair", 2, [0.65, 0.65, 1.1]),
        ],
        &[
            ("office chair1", "FRONT", "spaceship console1"),
            ("office chair2", "FRONT", "spaceship console2"),
        ],
    );
    let keep = user_pairs(&s);
    apply(&mut s, &keep);
    assert!(
        has(&s, "office chair1", RelationKind::At, "spaceship console1")
            && has(&s, "office chair2", RelationKind::At, "spaceship console2"),
        "{:?}",
        s.relations
    );
}

#[test]
fn what_the_sentence_places_drops_the_defaults_that_pull_it_elsewhere() {
    let mut s = spec(
        &[
            ("armchair", 2, [0.85, 0.85, 0.9]),
            ("fireplace", 1, [1.5, 0.5, 1.1]),
            ("coffee table", 1, [1.1, 0.6, 0.45]),
            ("floor lamp", 1, [0.4, 0.4, 1.6]),
            ("rug", 1, [2.0, 1.4, 0.01]),
        ],
        &[
            ("armchair1", "FLANK", "fireplace1"),
            ("armchair2", "FLANK", "fireplace1"),
            ("armchair1", "NEXT", "coffee table1"),
            ("armchair2", "NEXT", "coffee table1"),
            ("floor lamp1", "NEXT", "armchair1"),
            ("rug1", "UNDER", "armchair1"),
        ],
    );
    // the text's own: the armchairs either side of the fire
    let keep: BTreeSet<(String, String)> =
        [("armchair1", "fireplace1"), ("armchair2", "fireplace1")]
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect();
    apply(&mut s, &keep);
    for a in ["armchair1", "armchair2"] {
        assert!(has(&s, a, RelationKind::Flank, "fireplace1"), "{a} kept");
        assert!(
            !has(&s, a, RelationKind::Next, "coffee table1"),
            "{a} still pulled to the coffee table: {:?}",
            s.relations
        );
    }
    // defaults of other subjects, and stacking, stay
    assert!(has(&s, "floor lamp1", RelationKind::Next, "armchair1"));
    assert!(has(&s, "rug1", RelationKind::Under, "armchair1"));
}

#[test]
fn seats_put_in_front_of_a_counter_sit_at_it_as_many_as_it_seats() {
    let stools: Vec<String> = (1..=6).map(|k| format!("bar stool{k}")).collect();
    let relations: Vec<(&str, &str, &str)> = stools
        .iter()
        .map(|s| (s.as_str(), "FRONT", "bar counter1"))
        .collect();
    let mut s = spec(
        &[
            ("bar stool", 6, [0.4, 0.4, 0.75]),
            ("bar counter", 1, [2.0, 0.7, 1.1]),
        ],
        &relations,
    );
    let keep = user_pairs(&s);
    apply(&mut s, &keep);
    // all six sit at it in a row (the counter grows to seat them), not one
    for st in &stools {
        assert!(
            has(&s, st, RelationKind::At, "bar counter1"),
            "{st}: {:?}",
            s.relations
        );
    }
    assert!(s.objects["bar counter"].size[0] >= 6.0 * 0.55 - 0.1);
    // a desk seats one: the second chair in front of it stays in front
    let mut s = spec(
        &[
            ("office chair", 2, [0.6, 0.6, 1.0]),
            ("desk", 1, [1.4, 0.7, 0.75]),
        ],
        &[
            ("office chair1", "FRONT", "desk1"),
            ("office chair2", "FRONT", "desk1"),
        ],
    );
    let keep = user_pairs(&s);
    apply(&mut s, &keep);
    let at = ["office chair1", "office chair2"]
        .iter()
        .filter(|c| has(&s, c, RelationKind::At, "desk1"))
        .count();
    assert_eq!(at, 1, "{:?}", s.relations);
}
