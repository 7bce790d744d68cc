//! What a thing is said with and where: a placement after "X, each with Y," is said of the Xs;
//! "w/" is "with"; seats said with a table are its seats whatever the place's usual seat; "of
//! eight for the guests" seats eight; "a vase on each" and "a sink at each" are on or beside
//! each of the things before; a thing named in a question and again in its answer is one thing;
//! a window or door said with a corner or wall says which; a thing of the walls said in the
//! middle of the room stands there; bare "stools" said with a breakfast bar or a counter are its
//! bar stools, and no default stools come besides. Plan and layout only; prompts of no corpus.
mod common;
use common::placed::{all, lay, SEEDS};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Anchor, RelationKind, SceneSpec};

/// How many relations `kind` the spec has from instances of `subject` to instances of `object`.
fn related(spec: &SceneSpec, subject: &str, kind: RelationKind, object: &str) -> usize {
    let of = |id: &str, cat: &str| {
        id.strip_prefix(cat)
            .is_some_and(|k| k.parse::<u32>().is_ok())
    };
    spec.relations
        .iter()
        .filter(|r| r.relation == kind && of(&r.subject, subject) && of(&r.object, object))
        .count()
}

/// How many things the spec has of the categories `pick` takes.
fn total(spec: &SceneSpec, pick: impl Fn(&str) -> bool) -> u32 {
    spec.objects
        .iter()
        .filter(|(c, _)| pick(c))
        .map(|(_, o)| o.number)
        .sum()
}

/// The spec's category `pick` takes (`what` names it in the message when there is none).
fn category_where(spec: &SceneSpec, pick: impl Fn(&str) -> bool, what: &str) -> String {
    spec.objects
        .keys()
        .find(|c| pick(c))
        .unwrap_or_else(|| panic!("no {what} in {:?}", spec.objects.keys()))
        .clone()
}

fn count(spec: &SceneSpec, category: &str) -> u32 {
    spec.objects.get(category).map_or(0, |o| o.number)
}

#[test]
fn a_placement_after_each_with_is_said_of_the_things_before() {
    let p =
        plan_prompt("a beer garden: six picnic tables, each with two benches, under a big gazebo")
            .expect("planned");
    let s = &p.spec;
    let tables = count(s, "picnic table");
    assert_eq!(tables, 6, "{:?}", s.objects.keys());
    let under = s
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Under && r.subject.starts_with("picnic table"))
        .count();
    assert_eq!(under, 6, "every table under the gazebo: {:?}", s.relations);
    // and the benches stand at their tables (under the roof with them)
    let bench = category_where(s, |c| c.ends_with("bench"), "benches");
    assert_eq!(related(s, &bench, RelationKind::Around, "picnic table"), 12);
}

#[test]
fn a_placement_after_with_so_many_each_is_said_of_the_things_before() {
    // "each" closes what every one has; the place after it is the tables', and the chairs
    // stand at their tables there
    for (prompt, table, seat, per, want) in [
        (
            "a deli with a serving counter and 3 small tables with 2 chairs each by the window",
            "table",
            "chair",
            2,
            Anchor::Window,
        ),
        (
            "juice bar: a bar counter, two high tables with three stools apiece along the wall",
            "table",
            "stool",
            3,
            Anchor::Side,
        ),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let s = &p.spec;
        let t = category_where(s, |c| c.ends_with(table) && !c.contains("side"), table);
        let c = category_where(s, |c| c.ends_with(seat), seat);
        assert_eq!(
            s.anchors.get(&format!("{t}1")),
            Some(&want),
            "{prompt}: {:?}",
            s.anchors
        );
        assert_ne!(
            s.anchors.get(&format!("{c}1")),
            Some(&want),
            "{prompt}: {:?}",
            s.anchors
        );
        let n = count(s, &t);
        let seated =
            related(s, &c, RelationKind::Around, &t) + related(s, &c, RelationKind::At, &t);
        assert_eq!(seated as u32, per * n, "{prompt}: {:?}", s.relations);
    }
}

#[test]
fn w_slash_is_with_and_its_seats_sit_at_each_table() {
    let p =
        plan_prompt("a tiny cafe, five small round tables each w/ three chairs").expect("planned");
    let s = &p.spec;
    assert_eq!(count(s, "round table"), 5, "{:?}", s.objects.keys());
    let seats = total(s, |c| c.ends_with("chair"));
    assert_eq!(seats, 15, "{:?}", s.objects);
    let at = s
        .relations
        .iter()
        .filter(|r| {
            r.subject.contains("chair")
                && r.object.starts_with("round table")
                && matches!(r.relation, RelationKind::At | RelationKind::Around)
        })
        .count();
    assert_eq!(at, 15);
    let p = plan_prompt("a bedroom w/o a rug, a bed and a wardrobe").expect("planned");
    assert!(
        !p.spec.objects.contains_key("rug"),
        "{:?}",
        p.spec.objects.keys()
    );
}

#[test]
fn seats_said_with_a_table_are_its_seats_in_any_place() {
    // a study's usual seat is an office chair, which calls for desks; these sit at the table
    let p = plan_prompt("a study with a long table by the window with six chairs").expect("plan");
    let s = &p.spec;
    assert_eq!(
        count(s, "office chair") + count(s, "desk"),
        2,
        "{:?}",
        s.objects
    );
    let seated = s
        .relations
        .iter()
        .filter(|r| {
            r.subject.contains("chair")
                && matches!(r.relation, RelationKind::At | RelationKind::Around)
                && !r.object.starts_with("desk")
        })
        .count();
    assert_eq!(seated, 6, "{:?}", s.relations);
}

#[test]
fn bare_stools_said_with_a_bar_are_its_bar_stools() {
    for (prompt, n) in [
        ("a galley kitchen with a breakfast bar with two stools", 2),
        (
            "open plan kitchen: hob, oven, fridge and a breakfast bar with 4 stools",
            4,
        ),
        (
            "a kitchen diner, no island, a peninsula breakfast bar with three stools",
            3,
        ),
    ] {
        let s = plan_prompt(prompt).expect("plan").spec;
        let stools = total(&s, |c| c.ends_with("stool"));
        assert_eq!(stools, n, "{prompt}: {:?}", s.objects.keys());
        assert_eq!(
            count(&s, "bar stool"),
            n,
            "{prompt}: {:?}",
            s.objects.keys()
        );
    }
}

#[test]
fn tables_of_n_for_the_guests_seat_n() {
    let p = plan_prompt("a banquet hall: twelve round tables of ten for the guests and a stage")
        .expect("planned");
    let s = &p.spec;
    // the place's own round tables
    assert_eq!(count(s, "round banquet table"), 12);
    let around = s
        .relations
        .iter()
        .filter(|r| r.object.starts_with("round") && r.relation == RelationKind::Around)
        .count();
    assert_eq!(around, 120, "{:?}", s.objects);
}

#[test]
fn on_each_and_at_each_are_said_of_every_one() {
    let p = plan_prompt("an office with three desks, a lamp on each").expect("planned");
    let s = &p.spec;
    assert_eq!(count(s, "desk"), 3);
    let lamps: Vec<_> = s
        .relations
        .iter()
        .filter(|r| r.subject.contains("lamp") && r.relation == RelationKind::Over)
        .map(|r| r.object.clone())
        .collect();
    assert_eq!(lamps.len(), 3, "{:?}", s.relations);
    let mut on: Vec<_> = lamps.clone();
    on.sort();
    on.dedup();
    assert_eq!(on.len(), 3, "one on each desk: {lamps:?}");
    let p = plan_prompt("a chemistry lab: five lab benches, a sink at each, and a fume cupboard")
        .expect("planned");
    let s = &p.spec;
    let sink = category_where(s, |c| c.ends_with("sink"), "sinks");
    let bench = category_where(s, |c| c.contains("bench"), "benches");
    assert_eq!(count(s, &sink), count(s, &bench), "{:?}", s.objects);
    assert_eq!(
        related(s, &sink, RelationKind::Next, &bench),
        count(s, &bench) as usize
    );
    assert!(
        s.objects.contains_key("fume hood"),
        "a fume cupboard is a fume hood"
    );
}

#[test]
fn a_thing_asked_about_and_answered_is_one_thing() {
    let p = plan_prompt(
        "A: Kitchen for a family of four. B: Table for four? A: Yes, table for four by the window.",
    )
    .expect("planned");
    let s = &p.spec;
    let tables = total(s, |c| c.ends_with("table") && !c.contains("side"));
    assert_eq!(tables, 1, "{:?}", s.objects);
    let chairs = total(s, |c| c.ends_with("chair"));
    assert_eq!(chairs, 4, "{:?}", s.objects);
    let p = plan_prompt("A: a bedroom with a double bed. B: A rug? A: No. B: A desk? A: Yes.")
        .expect("planned");
    assert!(!p.spec.objects.contains_key("rug"), "{:?}", p.spec.objects);
    assert!(p.spec.objects.contains_key("desk"), "{:?}", p.spec.objects);
}

#[test]
fn a_window_or_door_says_which_corner_or_wall() {
    for (prompt, cat, want) in [
        (
            "a lounge with a sofa and a christmas tree in the corner by the window",
            "christmas tree",
            Anchor::Window,
        ),
        (
            "a hallway with a coat stand in the corner by the door",
            "coat rack",
            Anchor::Door,
        ),
        (
            "a gift shop with flower buckets along the shop window",
            "flower bucket",
            Anchor::Window,
        ),
    ] {
        let p = plan_prompt(prompt).expect(prompt);
        let id = format!("{cat}1");
        assert_eq!(
            p.spec.anchors.get(&id),
            Some(&want),
            "{prompt}: {:?}",
            p.spec.anchors
        );
    }
}

#[test]
fn a_thing_of_the_walls_said_in_the_middle_stands_there() {
    let prompt = "a carpentry shop with a big workbench in the middle of the room and tools";
    for seed in SEEDS {
        let (l, spec) = lay(prompt, seed);
        assert_eq!(spec.anchors.get("workbench1"), Some(&Anchor::Center));
        let b = all(&l, "workbench")[0];
        let [w, d, _] = l.room.size;
        let off = b.position[0].hypot(b.position[1]);
        assert!(
            off <= 0.25 * w.min(d) + 0.3,
            "seed {seed}: {off:.2} m off the middle"
        );
    }
    // the middle of a wall is at that wall
    let p = plan_prompt("a living room with a bookcase in the middle of the back wall")
        .expect("planned");
    assert_eq!(
        p.spec
            .anchors
            .get("bookcase1")
            .or(p.spec.anchors.get("bookshelf1")),
        Some(&Anchor::Side)
    );
}

#[test]
fn a_thing_of_tops_said_at_a_wall_stands_on_a_support_there() {
    let prompt = "a study with two rows of two desks, a sideboard and a printer against the wall";
    for seed in SEEDS {
        let (l, _) = lay(prompt, seed);
        let p = all(&l, "printer")[0];
        let [w, d, _] = l.room.size;
        let box2 = dreamscene::plan::check::Box2::of(p);
        let off = box2
            .corners()
            .iter()
            .map(|c| (0.5 * w - c[0].abs()).min(0.5 * d - c[1].abs()))
            .fold(f64::INFINITY, f64::min);
        // on the sideboard at the wall (whose own gap is the layout's), not on a desk of the rows
        assert!(
            off <= 0.5,
            "seed {seed}: the printer is {off:.2} m from a wall"
        );
        let on_desk = all(&l, "desk")
            .iter()
            .any(|d| common::placed::stands_on(p, d));
        assert!(
            !on_desk,
            "seed {seed}: the printer stands on a desk in the rows"
        );
        assert!(p.position[2] > 0.3, "seed {seed}: it stands on a top");
    }
}
