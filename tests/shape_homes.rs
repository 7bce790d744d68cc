//! Things of a home, a nursery, a garden and a workshop once drawn with another thing's
//! archetype (a plain table, a wardrobe, a mailbox post, a pouf), checked on their parts at
//! their knowledge-base size and two other sizes a plan may give: a canopy bed's posts carry a
//! canopy, an ironing board is a narrow board with a pointed nose on crossed legs, a dog bed's
//! bolster dips at the front, a cat tree has platforms at several heights, a grand piano is a
//! wing narrowing to its tail, a workbench has a shelf under its top and a vice on it, a
//! drafting table's board tilts, lockers are a row of narrow doors, rockers curve up at their
//! ends, a birdhouse has a hole under a roof wider than itself, a patio heater a wide hood, a
//! sewing table a machine on its top, and a fridge shows its coil from behind. Host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{drawn, of, range, runs, sizes, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::Role;

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 3)
}

/// The samples of `pts` with `lo <= p[axis] <= hi`.
fn within(pts: &[[f64; 3]], axis: usize, lo: f64, hi: f64) -> Vec<[f64; 3]> {
    pts.iter()
        .filter(|p| (lo..=hi).contains(&p[axis]))
        .cloned()
        .collect()
}

#[test]
fn a_canopy_bed_has_four_posts_under_a_canopy() {
    for size in sizes("canopy bed", [1.1, 0.9, 1.1]) {
        let s = at("canopy bed", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let posts = within(&of(&s, Role::Frame), 2, 0.6 * h, 0.85 * h);
        for (sx, sy) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
            let n = posts
                .iter()
                .filter(|p| p[0] * sx > 0.8 * hw && p[1] * sy > 0.8 * hd)
                .count();
            assert!(
                n > 10,
                "canopy bed {size:?}: no post at corner ({sx}, {sy})"
            );
        }
        let canopy = within(&of(&s, Role::Canvas), 2, 0.85 * h, h);
        let (x0, x1) = range(&canopy, 0);
        let (y0, y1) = range(&canopy, 1);
        assert!(
            x1 - x0 > 0.9 * size[0] && y1 - y0 > 0.9 * size[1],
            "canopy bed {size:?}: the canopy does not cover the bed"
        );
        // The headboard is a bed's, not a wall the full height of the posts.
        let head = within(&of(&s, Role::Frame), 0, -0.5 * hw, 0.5 * hw);
        assert!(
            within(&head, 2, 0.6 * h, 0.85 * h).is_empty(),
            "canopy bed {size:?}: a headboard as tall as the posts"
        );
    }
}

#[test]
fn an_ironing_board_is_a_narrow_pointed_board_on_crossed_legs() {
    for size in sizes("ironing board", [1.15, 0.9, 1.05]) {
        let s = at("ironing board", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let board = of(&s, Role::Canvas);
        assert!(
            range(&board, 2).0 > 0.7 * h,
            "ironing board {size:?}: board low"
        );
        let width = |x: f64| {
            let r = range(&within(&board, 0, x - 0.02, x + 0.02), 1);
            r.1 - r.0
        };
        assert!(
            width(0.85 * hw) < 0.6 * width(-0.5 * hw),
            "ironing board {size:?}: no pointed nose"
        );
        // Legs cross: at mid-height the legs are near the middle, at the floor far apart.
        let legs = of(&s, Role::Metal);
        let mid = within(&legs, 2, 0.45 * h, 0.55 * h);
        let foot = within(&legs, 2, 0.0, 0.1 * h);
        let spread = |p: &[[f64; 3]]| {
            let r = range(p, 0);
            r.1 - r.0
        };
        assert!(
            spread(&foot) > 2.0 * spread(&mid),
            "ironing board {size:?}: the legs do not cross"
        );
    }
}

#[test]
fn a_dog_bed_has_a_bolster_lower_at_the_front() {
    for size in sizes("dog bed", [1.2, 1.1, 1.2]) {
        let s = at("dog bed", size);
        let hd = size[1] / 2.0;
        let bolster = of(&s, Role::Upholstery);
        let back = range(&within(&bolster, 1, -hd, -0.7 * hd), 2).1;
        let front = range(&within(&bolster, 1, 0.7 * hd, hd), 2).1;
        assert!(
            front < 0.8 * back,
            "dog bed {size:?}: front {front:.2} m, back {back:.2} m"
        );
        assert!(
            !of(&s, Role::Cushion).is_empty(),
            "dog bed: no cushion inside"
        );
    }
}

#[test]
fn a_cat_tree_has_posts_and_platforms_at_several_heights() {
    for size in sizes("cat tree", [1.1, 1.1, 1.2]) {
        let s = at("cat tree", size);
        let h = size[2];
        // Flat carpeted levels: cells of height where carpet spans most of a platform.
        let carpet = of(&s, Role::Upholstery);
        let mut levels = 0;
        let n = 40;
        for i in 0..n {
            let z = i as f64 * h / n as f64;
            let band = within(&carpet, 2, z, z + h / n as f64);
            let r = range(&band, 0);
            if band.len() > 200 && r.1 - r.0 > 0.3 * size[0] {
                levels += 1;
            }
        }
        assert!(levels >= 4, "cat tree {size:?}: {levels} carpeted levels");
        let posts = of(&s, Role::Frame);
        assert!(
            range(&posts, 2).1 > 0.75 * h && runs(&posts, 0, 0.02) >= 2,
            "cat tree {size:?}: no tall sisal posts"
        );
    }
}

#[test]
fn a_grand_piano_is_a_wing_narrowing_to_its_tail() {
    for size in sizes("grand piano", [1.1, 1.1, 1.0]) {
        let s = at("grand piano", size);
        let (hw, hd) = (size[0] / 2.0, size[1] / 2.0);
        let case = of(&s, Role::Top);
        let width = |y: f64| {
            let r = range(&within(&case, 1, y - 0.03, y + 0.03), 0);
            r.1 - r.0
        };
        let (front, tail) = (width(0.3 * hd), width(-0.9 * hd));
        assert!(
            front > 0.9 * size[0] && tail < 0.45 * size[0],
            "grand piano {size:?}: {front:.2} m wide at the keys, {tail:.2} m at the tail"
        );
        // The straight side is the bass side (+x): the tail keeps to it.
        let r = range(&within(&case, 1, -hd, -0.85 * hd), 0);
        assert!(
            r.1 > 0.9 * hw,
            "grand piano {size:?}: the tail is not on the straight side"
        );
    }
}

#[test]
fn a_workbench_has_a_shelf_below_and_a_vice_and_tools_on_top() {
    for size in sizes("workbench", [1.2, 1.0, 1.05]) {
        let s = at("workbench", size);
        let h = size[2];
        let top = of(&s, Role::Top);
        let low = within(&top, 2, 0.0, 0.4 * h);
        let high = within(&top, 2, 0.6 * h, h);
        assert!(
            !low.is_empty() && !high.is_empty(),
            "workbench {size:?}: no shelf under the top"
        );
        let worktop = range(&high, 2).0;
        let on_top: Vec<[f64; 3]> = s
            .iter()
            .filter(|(p, r)| *r != Role::Top && p[2] > worktop + 0.05)
            .map(|(p, _)| *p)
            .collect();
        assert!(
            runs(&on_top, 0, 0.03) >= 2,
            "workbench {size:?}: nothing (vice, toolbox) on its top"
        );
    }
}

#[test]
fn a_drafting_tables_board_tilts_up_to_the_back() {
    for size in sizes("drafting table", [1.1, 1.1, 1.05]) {
        let s = at("drafting table", size);
        let hd = size[1] / 2.0;
        let board = within(&of(&s, Role::Top), 2, 0.5 * size[2], size[2]);
        let z = |y0: f64, y1: f64| {
            let r = range(&within(&board, 1, y0, y1), 2);
            0.5 * (r.0 + r.1)
        };
        let (front, back) = (z(0.7 * hd, hd), z(-hd, -0.7 * hd));
        assert!(
            back - front > 0.12 * size[2],
            "drafting table {size:?}: board at {front:.2} m in front, {back:.2} m behind"
        );
        assert!(!of(&s, Role::Canvas).is_empty(), "drafting table: no sheet");
    }
}

#[test]
fn lockers_are_a_row_of_narrow_vented_doors() {
    for size in sizes("locker", [1.4, 1.0, 1.0]) {
        let s = at("locker", size);
        let doors = of(&s, Role::Door);
        let n = runs(&doors, 0, 0.004);
        let expect = ((size[0] / 0.3).round() as usize).max(1);
        assert_eq!(n, expect, "lockers {size:?}: {n} doors");
        let hd = size[1] / 2.0;
        let vents = within(&of(&s, Role::Interior), 1, hd - 0.001, hd + 0.01);
        assert!(
            runs(&vents, 2, 0.004) >= 8,
            "lockers {size:?}: no vent slots on the doors"
        );
    }
}

/// The rockers (`Frame`) of `category` at `size`, along `axis`: higher at their ends than in
/// the middle, touching the floor.
fn rocks(category: &str, size: [f64; 3], axis: usize) {
    let s = at(category, size);
    let half = size[axis] / 2.0;
    let low = within(&of(&s, Role::Frame), 2, 0.0, 0.25 * size[2]);
    let mid = range(&within(&low, axis, -0.1 * half, 0.1 * half), 2).0;
    let end = range(&within(&low, axis, 0.85 * half, half), 2).0;
    assert!(
        mid < 0.01,
        "{category} {size:?}: the rockers do not touch the floor"
    );
    assert!(
        end > mid + 0.03,
        "{category} {size:?}: rockers flat ({mid:.3} m in the middle, {end:.3} m at the end)"
    );
}

#[test]
fn a_rocking_horse_and_a_cradle_stand_on_curved_rockers() {
    for size in sizes("rocking horse", [1.2, 1.1, 1.1]) {
        rocks("rocking horse", size, 0);
    }
    for size in sizes("cradle", [1.1, 1.1, 1.0]) {
        rocks("cradle", size, 0);
    }
}

#[test]
fn a_bassinet_is_a_basket_on_legs_hooded_at_its_head() {
    for size in sizes("bassinet", [1.1, 1.1, 1.0]) {
        let s = at("bassinet", size);
        let hood = of(&s, Role::Shade);
        assert!(
            range(&hood, 1).1 < 0.1 * size[1],
            "bassinet {size:?}: hood over the foot"
        );
        let basket = of(&s, Role::Body);
        assert!(
            range(&basket, 2).0 > 0.3 * size[2],
            "bassinet {size:?}: basket on the floor"
        );
    }
}

#[test]
fn a_birdhouse_has_a_hole_under_a_wide_roof_and_a_heater_a_wide_hood() {
    for size in sizes("birdhouse", [1.2, 1.2, 1.1]) {
        let s = at("birdhouse", size);
        let roof = of(&s, Role::Top);
        let house = of(&s, Role::Body);
        let (r, b) = (range(&roof, 1), range(&house, 1));
        assert!(
            r.1 - r.0 > 1.1 * (b.1 - b.0),
            "birdhouse {size:?}: no eaves"
        );
        let hole = within(&of(&s, Role::Interior), 1, b.1 - 0.001, b.1 + 0.01);
        assert!(!hole.is_empty(), "birdhouse {size:?}: no entrance hole");
    }
    for size in sizes("outdoor heater", [1.1, 1.1, 1.1]) {
        let s = at("outdoor heater", size);
        let hood = range(&of(&s, Role::Shade), 0);
        let column = range(
            &within(&of(&s, Role::Body), 2, 0.4 * size[2], 0.7 * size[2]),
            0,
        );
        assert!(
            hood.1 - hood.0 > 5.0 * (column.1 - column.0),
            "outdoor heater {size:?}: hood no wider than its column"
        );
        assert!(!of(&s, Role::Light).is_empty(), "outdoor heater: no glow");
    }
}

#[test]
fn a_sewing_table_carries_a_sewing_machine() {
    for size in sizes("sewing table", [1.2, 1.1, 1.0]) {
        let s = at("sewing table", size);
        let top = range(&of(&s, Role::Top), 2).1;
        let machine = within(&of(&s, Role::Body), 2, top + 0.02, size[2]);
        assert!(
            range(&machine, 2).1 > top + 0.15,
            "sewing table {size:?}: no machine standing on the top"
        );
    }
    let s = at(
        "sewing machine",
        KnowledgeBase::builtin()
            .object("sewing machine")
            .unwrap()
            .size,
    );
    assert!(!of(&s, Role::Metal).is_empty(), "sewing machine: no needle");
}

#[test]
fn a_fridge_shows_its_condenser_coil_from_behind() {
    for name in ["refrigerator", "drinks fridge", "wine fridge"] {
        for size in sizes(name, [1.1, 1.0, 1.1]) {
            let s = at(name, size);
            let hd = size[1] / 2.0;
            let coil = within(&of(&s, Role::Interior), 1, -hd, -hd + 0.03);
            let (x, z) = (range(&coil, 0), range(&coil, 2));
            assert!(
                x.1 - x.0 > 0.6 * size[0] && z.1 - z.0 > 0.5 * size[2],
                "{name} {size:?}: no coil across its back"
            );
        }
    }
}

#[test]
fn a_chess_table_has_a_board_of_squares_and_an_air_hockey_table_a_railed_field() {
    for size in sizes("chess table", [1.2, 1.2, 1.0]) {
        let s = at("chess table", size);
        let dark = of(&s, Role::Interior);
        let z0 = range(&of(&s, Role::Canvas), 2).0;
        // The third rank from one side holds no pieces: four dark squares across it.
        let side = 0.8 * size[0].min(size[1]);
        let y = -side / 2.0 + 2.5 * side / 8.0;
        let rank = within(
            &within(&dark, 1, y - 0.01, y + 0.01),
            2,
            z0 - 1e-3,
            z0 + 0.004,
        );
        assert_eq!(
            runs(&rank, 0, 0.005),
            4,
            "chess table {size:?}: no board of squares"
        );
        assert!(
            range(&dark, 2).1 > z0 + 0.02,
            "chess table {size:?}: no pieces"
        );
    }
    for size in sizes("air hockey table", [1.1, 1.1, 1.0]) {
        let s = at("air hockey table", size);
        let field = range(&of(&s, Role::Canvas), 2).1;
        assert!(
            range(&of(&s, Role::Frame), 2).1 > field + 0.02,
            "air hockey {size:?}: no rails"
        );
        let hw = size[0] / 2.0;
        let goals = within(&of(&s, Role::Interior), 2, field - 0.05, field + 0.01);
        let ends = goals.iter().filter(|p| p[0].abs() > 0.9 * hw).count();
        assert!(ends > 20, "air hockey {size:?}: no goal slots at the ends");
    }
}
