//! The examples of what people write that the planner must read as a person would: noun
//! phrases, relation phrases, negation, exact counts, units, scene refinements, unreadable
//! prompts, rooms too small for what is named, and functional groups in the laid-out rooms.
use dreamscene::plan::check::{facing_error, relation_holds, validity_problems, walk, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::lang::{is_function_word, is_verb};
use dreamscene::plan::offline::{plan_prompt, PlanError};
use dreamscene::plan::spec::*;
use std::collections::BTreeMap;

fn plan(p: &str) -> SceneSpec {
    plan_prompt(p).unwrap_or_else(|e| panic!("{p}: {e}")).spec
}

fn has(s: &SceneSpec, subject: &str, rel: RelationKind, object: &str) -> bool {
    s.relations
        .iter()
        .any(|r| r.subject == subject && r.relation == rel && r.object == object)
}

/// Every word a description takes from the prompt (those not in the category's own name or
/// knowledge-base description) describes: no verb, no function word.
fn descriptions_are_noun_phrases(s: &SceneSpec) {
    let kb = dreamscene::plan::kb::KnowledgeBase::builtin();
    for (c, o) in &s.objects {
        let body = o
            .description
            .strip_prefix("A DSLR photo of ")
            .unwrap_or_else(|| panic!("{c}: {}", o.description));
        let words: Vec<&str> = body.split_whitespace().collect();
        assert!(["a", "an"].contains(&words[0]), "{}", o.description);
        let own = kb
            .object(c)
            .map(|k| k.description.clone())
            .unwrap_or_default();
        for w in &words[1..] {
            if c.split(' ').any(|x| x == *w) || own.split(' ').any(|x| x == *w) {
                continue;
            }
            assert!(
                !is_function_word(w),
                "{c}: function word `{w}` in {:?}",
                o.description
            );
            assert!(!is_verb(w), "{c}: verb `{w}` in {:?}", o.description);
        }
    }
}

#[test]
fn noun_phrases_and_relation_phrases() {
    let s = plan("I want a living room where the big grey sofa faces the fireplace");
    assert_eq!(
        s.objects["sofa"].description,
        "A DSLR photo of a big grey sofa"
    );
    assert!(s.objects.contains_key("fireplace"));
    assert!(!s.objects["fireplace"].description.contains("faces"));
    assert!(
        has(&s, "sofa1", RelationKind::Opposite, "fireplace1"),
        "{:?}",
        s.relations
    );
    descriptions_are_noun_phrases(&s);
    let l = layout(&s, LayoutOptions::seeded(0)).unwrap();
    assert!(validity_problems(&l, &s).is_empty());

    let s =
        plan("a bedroom with two lamps on either side of the bed and a rug at the foot of the bed");
    assert!(
        has(&s, "rug1", RelationKind::Front, "bed1"),
        "{:?}",
        s.relations
    );
    let s = plan(
        "a study with a lamp on the desk and a plant in the corner, a bookshelf along the wall",
    );
    assert!(
        has(&s, "table lamp1", RelationKind::Over, "desk1"),
        "{:?}",
        s.relations
    );
    assert_eq!(s.anchors["potted plant1"], Anchor::Corner);
    assert_eq!(s.anchors["bookshelf1"], Anchor::Side);
    let s = plan("a living room with an armchair beside the sofa and a coffee table in front of the sofa, a floor lamp behind the armchair");
    assert!(has(&s, "armchair1", RelationKind::Next, "sofa1"));
    assert!(has(&s, "coffee table1", RelationKind::Front, "sofa1"));
    assert!(has(&s, "floor lamp1", RelationKind::Behind, "armchair1"));
    descriptions_are_noun_phrases(&s);
}

#[test]
fn negation_exact_counts_and_clamps() {
    let s = plan("a living room with no tv");
    assert!(!s.objects.contains_key("tv") && s.objects.contains_key("sofa"));
    let s = plan("a living room without a sofa or a rug");
    assert!(!s.objects.contains_key("sofa") && !s.objects.contains_key("rug"));
    assert!(s.objects.contains_key("coffee table"));
    let s = plan("a bedroom with everything except the wardrobe");
    assert!(!s.objects.contains_key("wardrobe") && s.objects.contains_key("bed"));
    let s = plan("a dining room with 0 chairs");
    assert!(
        !s.objects.contains_key("dining chair"),
        "{:?}",
        s.objects.keys()
    );
    assert!(s.objects.contains_key("dining table"));
    let s = plan("a dining room with seven chairs and a dozen candles");
    assert_eq!(s.objects["dining chair"].number, 7);
    assert_eq!(s.objects["candle"].number, 12);
    let p = plan_prompt("a conference room with 500 chairs").unwrap();
    assert_eq!(p.spec.objects["office chair"].number, MAX_NUMBER);
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("500") && n.contains("office chair")),
        "the clamp is a note naming it: {:?}",
        p.notes
    );
}

#[test]
fn units_people_write() {
    let room = |p: &str| plan(p).room.unwrap().size;
    assert_eq!(room("a bedroom, 400cm x 300cm")[..2], [4.0, 3.0]);
    let r = room("a 15 ft x 12 ft living room");
    assert!(
        (r[0] - 4.57).abs() < 0.01 && (r[1] - 3.66).abs() < 0.01,
        "{r:?}"
    );
    let r = room("a 12' x 10' bedroom");
    assert!(
        (r[0] - 3.66).abs() < 0.01 && (r[1] - 3.05).abs() < 0.01,
        "{r:?}"
    );
    assert_eq!(room("an office 5 by 4 metres")[..2], [5.0, 4.0]);
    assert_eq!(room("a kitchen 3500mm x 2800mm")[..2], [3.5, 2.8]);
    assert_eq!(room("a studio 6 × 4.5 × 3 m"), [6.0, 4.5, 3.0]);
    let a = room("a 200 sq ft bedroom");
    assert!((a[0] * a[1] - 18.58).abs() < 0.3, "{a:?}");
    // A size before an object sizes the object, not the room.
    let s = plan("a dining room with a 2.4 m table");
    assert_eq!(s.objects["dining table"].size[0], 2.4);
    let s = plan("a living room with a 3 x 2 m rug");
    assert_eq!(s.objects["rug"].size[..2], [3.0, 2.0]);
}

#[test]
fn scene_refinements() {
    let s = plan("a kid's bedroom");
    assert!(s.objects.contains_key("single bed") && !s.objects.contains_key("bed"));
    let s = plan("a Japanese zen garden");
    assert_eq!(s.scene_type, SceneType::Outdoor);
    assert!(s.objects.contains_key("raked sand bed") && s.objects.contains_key("stone lantern"));
    let s = plan("a small cafe terrace");
    assert!(s.objects.contains_key("cafe table"));
    assert!(!s.objects.contains_key("sun lounger") && !s.objects.contains_key("barbecue grill"));
    let s = plan("a classroom for 16 students");
    assert_eq!(s.objects["school desk"].number, 16);
    assert_eq!(s.objects["dining chair"].number, 16);
    let s = plan("a medieval tavern");
    assert!(s.objects.contains_key("bar counter") && s.objects["bar stool"].number >= 3);
}

#[test]
fn unreadable_prompts_are_errors_that_suggest_an_llm() {
    for p in [
        "asdkj qwe zzzx",
        "something beautiful",
        "un salón acogedor con un sofá y dos sillas",
        "ein gemütliches Wohnzimmer mit einem Sofa",
        "居心地の良いリビングルーム",
    ] {
        let e = plan_prompt(p).expect_err(p);
        assert!(
            matches!(
                e,
                PlanError::NothingRecognised(_) | PlanError::NotEnglish(_)
            ),
            "{p}: {e}"
        );
        assert!(e.to_string().contains("--llm-url"), "{e}");
    }
}

#[test]
fn named_objects_are_never_dropped_and_what_cannot_fit_is_refused() {
    let e = plan_prompt("a living room, 1m x 1m, with a sofa, a piano and a bed").unwrap_err();
    let m = e.to_string();
    assert!(
        m.contains("does not fit") && m.contains("smallest room"),
        "{m}"
    );
    // The smallest room it names does take them.
    let s = plan("a living room with a sofa, a piano and a bed");
    layout(&s, LayoutOptions::seeded(0)).unwrap();
    // Defaults are trimmed in a small stated room; what is named stays.
    let p = plan_prompt("a 3m x 3m living room with a piano").unwrap();
    assert!(p.spec.objects.contains_key("piano"));
    assert!(!p.notes.is_empty(), "defaults trimmed with a note");
    let l = layout(&p.spec, LayoutOptions::seeded(0)).unwrap();
    assert!(validity_problems(&l, &p.spec).is_empty());
    // A wizard's harp the knowledge base lacks is kept, sized from a size class.
    let p = plan_prompt("a music room with a golden lyre").unwrap();
    assert!(
        p.spec.objects.contains_key("lyre"),
        "{:?}",
        p.spec.objects.keys()
    );
    assert!(p.notes.iter().any(|n| n.contains("lyre")));

    // 60 objects in 2 x 2 m: refused, naming what does not fit and a room that does.
    let mut objects = BTreeMap::new();
    objects.insert(
        "crate".to_string(),
        ObjectSpec {
            number: 20,
            size: [0.6, 0.5, 0.5],
            description: "A DSLR photo of a crate".into(),
            rows: 0,
            sizes: vec![],
            on_wall: None,
        },
    );
    objects.insert(
        "barrel".to_string(),
        ObjectSpec {
            number: 20,
            size: [0.6, 0.6, 0.9],
            description: "A DSLR photo of a barrel".into(),
            rows: 0,
            sizes: vec![],
            on_wall: None,
        },
    );
    objects.insert(
        "chest".to_string(),
        ObjectSpec {
            number: 20,
            size: [0.9, 0.5, 0.55],
            description: "A DSLR photo of a chest".into(),
            rows: 0,
            sizes: vec![],
            on_wall: None,
        },
    );
    let mut spec = SceneSpec {
        scene_type: SceneType::Indoor,
        scene_text: "crowded".into(),
        room: Some(Room {
            size: [2.0, 2.0, 2.8],
        }),
        objects,
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    let e = layout(&spec, LayoutOptions::seeded(0))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("do not fit") && e.contains("smallest room"),
        "{e}"
    );
    let dims: Vec<f64> = e
        .rsplit("smallest room that takes everything is ")
        .next()
        .unwrap()
        .trim_end_matches(" m")
        .split(" x ")
        .map(|v| v.parse().unwrap())
        .collect();
    spec.room = Some(Room {
        size: [dims[0], dims[1], dims[2]],
    });
    let l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
    assert!(
        validity_problems(&l, &spec).is_empty(),
        "the room it names takes them"
    );
    // An object larger than its room is refused the same way.
    spec.room = Some(Room {
        size: [0.8, 0.8, 2.8],
    });
    let e = layout(&spec, LayoutOptions::seeded(0))
        .unwrap_err()
        .to_string();
    assert!(e.contains("chest") && e.contains("larger than"), "{e}");
}

fn laid_out(p: &str, seed: u64) -> (SceneSpec, Layout, BTreeMap<String, PlacedObject>) {
    let s = plan(p);
    let l = layout(&s, LayoutOptions::seeded(seed)).unwrap_or_else(|e| panic!("{p}: {e}"));
    let problems = validity_problems(&l, &s);
    assert!(problems.is_empty(), "{p}: {problems:?}");
    let by = l
        .objects
        .iter()
        .map(|o| (o.id.clone(), o.clone()))
        .collect();
    (s, l, by)
}

/// Which side of `table` (0 front, 1 back, 2 right, 3 left, in its frame) `o` is on.
fn side_of(table: &PlacedObject, o: &PlacedObject) -> usize {
    let b = Box2::of(table);
    let l = b.local([o.position[0], o.position[1]]);
    if l[1].abs() * b.half[0] >= l[0].abs() * b.half[1] {
        if l[1] > 0.0 {
            0
        } else {
            1
        }
    } else if l[0] > 0.0 {
        2
    } else {
        3
    }
}

#[test]
fn functional_groups_are_laid_out_as_people_furnish() {
    // Classroom: 12 school desks (no office desks), one chair each at its back, desks in rows
    // turned the same way, facing the board.
    let (s, l, by) = laid_out("a classroom with 12 desks", 0);
    assert_eq!(s.objects["school desk"].number, 12);
    assert_eq!(s.objects["dining chair"].number, 12);
    assert!(!s.objects.contains_key("desk"));
    let yaws: Vec<f64> = l
        .objects
        .iter()
        .filter(|o| o.category == "school desk")
        .map(|o| o.yaw)
        .collect();
    assert!(
        yaws.iter().all(|y| (y - yaws[0]).abs() < 1.0),
        "rows: {yaws:?}"
    );
    let held = |s: &SceneSpec, kind: RelationKind| {
        let rs: Vec<&Relation> = s.relations.iter().filter(|r| r.relation == kind).collect();
        let ok = rs
            .iter()
            .filter(|r| relation_holds(&by_id(&l, &r.subject), r.relation, &by_id(&l, &r.object)))
            .count();
        (ok, rs.len())
    };
    fn by_id(l: &Layout, id: &str) -> PlacedObject {
        l.objects.iter().find(|o| o.id == id).unwrap().clone()
    }
    let (ok, n) = held(&s, RelationKind::AtBack);
    assert!(
        n == 13 && ok == n,
        "12 chairs at desks and the teacher's: {ok}/{n}"
    );
    let (ok, n) = held(&s, RelationKind::Row);
    assert!(
        n == 12 && ok == n,
        "desks in rows before the board: {ok}/{n}"
    );
    drop(by);

    // Bedroom: nightstands flush on both sides of the bed's head.
    let (s, _, by) = laid_out("a bedroom", 0);
    for k in 1..=2 {
        assert!(has(
            &s,
            &format!("nightstand{k}"),
            RelationKind::Flank,
            "bed1"
        ));
        assert!(relation_holds(
            &by[&format!("nightstand{k}")],
            RelationKind::Flank,
            &by["bed1"]
        ));
    }
    let b = Box2::of(&by["bed1"]);
    let x1 = b.local([by["nightstand1"].position[0], by["nightstand1"].position[1]])[0];
    let x2 = b.local([by["nightstand2"].position[0], by["nightstand2"].position[1]])[0];
    assert!(x1 * x2 < 0.0, "one on each side");

    // Dining room: six chairs round the table within 0.3 m, facing it, over both long sides.
    let (s, _, by) = laid_out("a dining room", 2);
    let mut sides = [0; 4];
    for k in 1..=s.objects["dining chair"].number {
        let c = &by[&format!("dining chair{k}")];
        assert!(
            relation_holds(c, RelationKind::Around, &by["dining table1"]),
            "chair {k}"
        );
        sides[side_of(&by["dining table1"], c)] += 1;
    }
    assert!(sides[0] >= 2 && sides[1] >= 2, "long sides: {sides:?}");

    // Tavern: stools at the counter facing it; chairs spread over the tables.
    let (s, _, by) = laid_out("a medieval tavern", 0);
    for k in 1..=s.objects["bar stool"].number {
        assert!(relation_holds(
            &by[&format!("bar stool{k}")],
            RelationKind::At,
            &by["bar counter1"]
        ));
    }
    let mut per_table: BTreeMap<String, u32> = BTreeMap::new();
    for r in s
        .relations
        .iter()
        .filter(|r| r.subject.starts_with("cafe chair"))
    {
        *per_table.entry(r.object.clone()).or_default() += 1;
    }
    assert_eq!(
        per_table.len() as u32,
        s.objects["cafe table"].number,
        "{per_table:?}"
    );

    // Kitchen: stools on one side of the island, facing it.
    let (s, _, by) = laid_out("a kitchen", 0);
    let island = &by["kitchen island1"];
    let sides: std::collections::BTreeSet<usize> = (1..=s.objects["bar stool"].number)
        .map(|k| side_of(island, &by[&format!("bar stool{k}")]))
        .collect();
    assert_eq!(sides.len(), 1, "stools on one side");

    // Campsite: seats 0.6-1.5 m round the fire, facing it.
    let (s, _, by) = laid_out("a campsite", 0);
    for r in s.relations.iter().filter(|r| r.object == "fire pit1") {
        assert_eq!(r.relation, RelationKind::Circle);
        assert!(
            relation_holds(&by[&r.subject], RelationKind::Circle, &by["fire pit1"]),
            "{}",
            r.subject
        );
    }
}

/// A classroom as a person furnishes it: the board on a wall; the teacher's desk between the
/// board and the rows, turned to the class, the teacher's chair behind it; every pupil's desk
/// turned to the board with the pupil's chair at its back, so every pupil faces the board; and
/// a way in from the door to every seat.
#[test]
fn a_classroom_faces_its_board_and_every_seat_is_reached() {
    for (p, seed) in [
        ("a classroom for 24 students", 0),
        ("a schoolroom with ten desks and a whiteboard", 1),
        ("a classroom for 30 pupils", 2),
    ] {
        let (_, l, by) = laid_out(p, seed);
        let of = |c: &str| -> Vec<&PlacedObject> {
            l.objects.iter().filter(|o| o.category == c).collect()
        };
        let board = *of("blackboard")
            .first()
            .or(of("whiteboard").first())
            .unwrap_or_else(|| panic!("{p}: no board"));
        let bb = Box2::of(board);
        assert!(
            board.position[2] >= 0.4,
            "{p}: the board stands on the floor"
        );
        let pupils = of("dining chair");
        assert!(pupils.len() >= 10, "{p}: {} pupils' chairs", pupils.len());
        for c in &pupils {
            let e = facing_error(&Box2::of(c), &bb);
            assert!(e <= 40.0, "{p}: {} turned {e:.0} deg from the board", c.id);
        }
        for d in of("school desk") {
            let e = facing_error(&Box2::of(d), &bb);
            assert!(e <= 40.0, "{p}: {} turned {e:.0} deg from the board", d.id);
        }
        // the teacher's desk: before the board, nearer it than any pupil's desk, turned as
        // the board (to the class), its chair between it and the board
        let t = by["teacher desk1"].clone();
        let tb = Box2::of(&t);
        let to_board = |o: &PlacedObject| bb.local([o.position[0], o.position[1]])[1];
        let nearest_pupil = of("school desk")
            .iter()
            .map(|d| to_board(d))
            .fold(f64::INFINITY, f64::min);
        assert!(
            to_board(&t) > 0.0 && to_board(&t) < nearest_pupil,
            "{p}: the teacher's desk is not between the board and the rows"
        );
        assert!(
            dreamscene::plan::check::yaw_difference(&tb, &bb) <= 30.0,
            "{p}: the teacher's desk is not turned to the class"
        );
        let chair = by["office chair1"].clone();
        assert!(
            to_board(&chair) < to_board(&t),
            "{p}: the teacher's chair is not behind the desk"
        );
        let lost = walk::unreachable(&l);
        assert!(lost.is_empty(), "{p}: no way to {lost:?}");
    }
}
