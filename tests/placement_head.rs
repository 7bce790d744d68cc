//! Placement faults of round 16: a small lounge's seat faces its wall TV; a head table's party
//! sits along its back, facing the room with it, backs to a wall; the head table's seats come
//! on top of the seats said for the round tables.
use dreamscene::plan::check::{validity_problems, wall_distances, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject, RelationKind, SceneSpec};

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

fn placed<'a>(l: &'a Layout, id: &str) -> &'a PlacedObject {
    l.objects
        .iter()
        .find(|o| o.id == id)
        .unwrap_or_else(|| panic!("no {id} in {:?}", l.objects))
}

/// The facing direction of `o`.
fn facing(o: &PlacedObject) -> [f64; 2] {
    let a = o.yaw.to_radians();
    [-a.sin(), a.cos()]
}

#[test]
fn a_head_tables_party_sits_behind_it_backs_to_the_wall_facing_the_room() {
    for (prompt, seed) in [
        (
            "a wedding reception with a head table and six round tables",
            0,
        ),
        (
            "a wedding dinner with a bridal table and six round tables",
            1,
        ),
        (
            "an event hall with a top table, a buffet table and five round tables",
            2,
        ),
    ] {
        let (l, spec) = lay(prompt, seed);
        let table = placed(&l, "top table1");
        let seats: Vec<&str> = spec
            .relations
            .iter()
            .filter(|r| r.object == "top table1")
            .map(|r| {
                assert_eq!(r.relation, RelationKind::AtBack, "{prompt}: {r:?}");
                r.subject.as_str()
            })
            .collect();
        assert!(seats.len() >= 4, "{prompt}: {seats:?}");
        let f = facing(table);
        for s in &seats {
            let c = placed(&l, s);
            let d = [
                c.position[0] - table.position[0],
                c.position[1] - table.position[1],
            ];
            // behind the table, turned the way it faces
            assert!(
                d[0] * f[0] + d[1] * f[1] < -0.5 * table.size[1],
                "{prompt}: {s}"
            );
            let g = facing(c);
            assert!(
                g[0] * f[0] + g[1] * f[1] > 0.95,
                "{prompt}: {s} turned away"
            );
            // its back to a wall
            let wd = wall_distances(&Box2::of(c), l.room.size);
            assert!(
                wd.iter().any(|&v| v <= 0.3),
                "{prompt}: {s} off the wall {wd:?}"
            );
        }
        assert!(l.unsatisfied.is_empty(), "{prompt}: {:?}", l.unsatisfied);
    }
}

#[test]
fn a_head_tables_seats_come_on_top_of_the_round_tables_seats() {
    for (prompt, round, per) in [
        (
            "a gala dinner with a top table and ten round tables for eight",
            10,
            8,
        ),
        (
            "a banquet hall with a head table and five round tables for ten",
            5,
            10,
        ),
        (
            "a wedding with a bridal table and six round tables for six",
            6,
            6,
        ),
    ] {
        let (_, spec) = lay(prompt, 0);
        let at = |table: &str| {
            spec.relations
                .iter()
                .filter(|r| r.object.starts_with(table))
                .filter(|r| matches!(r.relation, RelationKind::Around | RelationKind::AtBack))
                .count()
        };
        assert_eq!(at("round"), round * per, "{prompt}");
        assert!(at("top table") >= 4, "{prompt}");
    }
}

#[test]
fn a_small_lounges_seat_faces_its_wall_tv() {
    // the seat stands where the wall it faces can take the TV clear of the door and windows,
    // centred on a short wall when only there it keeps clear of both end walls
    for prompt in [
        "a small lounge with a loveseat, a tv on the wall and a floor lamp",
        "a snug with a small sofa, a wall-mounted tv and a side table",
        "a little sitting room with a small sofa, a wall-mounted tv and a plant",
    ] {
        for seed in 0..3 {
            let (l, _) = lay(prompt, seed);
            let seat = placed(&l, "loveseat1");
            let tv = placed(&l, "tv1");
            let f = facing(seat);
            let d = [
                tv.position[0] - seat.position[0],
                tv.position[1] - seat.position[1],
            ];
            let cos = (d[0] * f[0] + d[1] * f[1]) / d[0].hypot(d[1]);
            assert!(
                cos > 0.85,
                "{prompt} (seed {seed}): the TV is off the seat's axis"
            );
            assert!(
                l.unsatisfied.is_empty(),
                "{prompt} (seed {seed}): {:?}",
                l.unsatisfied
            );
        }
    }
}
