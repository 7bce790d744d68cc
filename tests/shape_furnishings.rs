//! Furnishings once drawn with another thing's archetype (a desk, a plain table, a whiteboard,
//! a bookcase, a cylinder, a bar cart, a lantern), checked on their parts at their
//! knowledge-base size and two other sizes a plan may give: a vanity table has a mirror over
//! its top, a salon station a mirror ringed by bulbs over a counter, a produce stand tiers of
//! produce under a sign, a cutting table a gridded mat, a grooming table an arm with a loop, a
//! poker table a padded rail round its felt, a cubicle panels on three sides, a bulletin board
//! notes pinned to cork, a ladder shelf shelves growing shallower upwards, an ottoman and a
//! vanity stool legs under a buttoned cushion, a kitchen cart a wooden top on casters, a candle
//! stand candles on arms, and a grand piano its lid propped open. Host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{drawn, of, range, runs, sizes, within, Samples};
use dreamscene::shape::{goods_of, Goods, Role};

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 3)
}

/// The highest sample of a role's points (the floor where there are none).
fn top_of(pts: &[[f64; 3]]) -> f64 {
    range(pts, 2).1.max(0.0)
}

#[test]
fn a_vanity_table_has_a_mirror_over_its_top_and_drawers_below() {
    for size in sizes("vanity table", [1.15, 1.1, 1.1]) {
        let s = at("vanity table", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let top = range(&of(&s, Role::Top), 2).1;
        assert!(top < 0.65 * h, "vanity table {size:?}: top at {top:.2}");
        let glass = of(&s, Role::Canvas);
        assert!(!glass.is_empty(), "vanity table {size:?}: no mirror");
        let (g0, g1) = range(&glass, 2);
        assert!(
            g0 > top && g1 > top + 0.5 * (h - top),
            "vanity table {size:?}: mirror {g0:.2}..{g1:.2} not above the top {top:.2}"
        );
        let (x0, x1) = range(&glass, 0);
        assert!(
            x0 < -0.2 * hw && x1 > 0.2 * hw,
            "vanity table {size:?}: mirror off-centre"
        );
        let fronts = within(&of(&s, Role::Door), |p| p[2] < top - 0.15);
        assert!(
            runs(&fronts, 0, 0.02) >= 2,
            "vanity table {size:?}: drawers not either side of a knee gap"
        );
    }
}

#[test]
fn a_salon_station_has_a_mirror_ringed_by_bulbs_over_a_counter() {
    for size in sizes("salon station", [1.2, 1.1, 0.9]) {
        let s = at("salon station", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let counter = range(&of(&s, Role::Top), 2).1;
        assert!(
            counter < 0.55 * h,
            "salon station {size:?}: counter at {counter:.2}"
        );
        let glass = of(&s, Role::Canvas);
        let (g0, g1) = range(&glass, 2);
        assert!(
            g0 > counter && g1 > 0.85 * h,
            "salon station {size:?}: no tall mirror above the counter"
        );
        let bulbs = of(&s, Role::Light);
        let (b0, b1) = range(&bulbs, 0);
        let (gx0, gx1) = range(&glass, 0);
        assert!(
            b0 < gx0 && b1 > gx1 && runs(&bulbs, 2, 0.01) >= 3,
            "salon station {size:?}: no bulbs down both sides of the mirror"
        );
        // Tool shelves of bottles beside the mirror, above the counter.
        let beside = within(&of(&s, Role::Books), |p| {
            p[2] > counter && (p[0] < gx0 || p[0] > gx1)
        });
        assert!(
            beside.iter().any(|p| p[0] < -0.5 * hw) && beside.iter().any(|p| p[0] > 0.5 * hw),
            "salon station {size:?}: no tool shelves either side"
        );
    }
}

#[test]
fn a_produce_stand_shows_tiers_of_produce_under_a_sign() {
    assert_eq!(goods_of("produce stand"), Some(Goods::Produce));
    for size in sizes("produce stand", [1.2, 0.9, 1.1]) {
        let s = at("produce stand", size);
        let (hd, h) = (size[1] / 2.0, size[2]);
        let produce = of(&s, Role::Books);
        let front = within(&produce, |p| p[1] > 0.2 * hd);
        let back = within(&produce, |p| p[1] < -0.2 * hd);
        assert!(
            !front.is_empty() && !back.is_empty(),
            "produce stand {size:?}: produce not in a front and a back tier"
        );
        assert!(
            range(&back, 2).0 > range(&front, 2).0 + 0.1 * h,
            "produce stand {size:?}: the back tier is not higher"
        );
        // Each tier is several crates: runs of produce across x.
        assert!(
            runs(&front, 0, 0.02) >= 2,
            "produce stand {size:?}: one heap"
        );
        let sign = of(&s, Role::Canvas);
        assert!(
            range(&sign, 2).0 > range(&produce, 2).1 - 0.1 * h && range(&sign, 1).1 < 0.0,
            "produce stand {size:?}: no sign above the produce at the back"
        );
    }
}

#[test]
fn a_cutting_table_has_a_gridded_mat_and_fabric_below() {
    for size in sizes("cutting table", [1.2, 1.1, 1.05]) {
        let s = at("cutting table", size);
        let h = size[2];
        let mat = within(&of(&s, Role::Canvas), |p| p[2] > 0.85 * h);
        let (x0, x1) = range(&mat, 0);
        let (y0, y1) = range(&mat, 1);
        assert!(
            x1 - x0 > 0.85 * size[0] && y1 - y0 > 0.8 * size[1],
            "cutting table {size:?}: no mat over the top"
        );
        let lines = within(&of(&s, Role::Handle), |p| {
            p[2] > 0.85 * h && (0.03..0.07).contains(&p[1])
        });
        assert!(
            runs(&lines, 0, 0.01) >= 5,
            "cutting table {size:?}: the mat is not ruled in a grid"
        );
        let fabric = within(&of(&s, Role::Books), |p| p[2] < 0.8 * h);
        assert!(
            runs(&fabric, 2, 0.02) >= 2,
            "cutting table {size:?}: no shelves of fabric under the top"
        );
    }
}

#[test]
fn a_grooming_table_has_an_arm_with_a_loop_over_its_top() {
    for size in sizes("grooming table", [1.1, 1.15, 1.1]) {
        let s = at("grooming table", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let top = top_of(&of(&s, Role::Upholstery));
        assert!(top < 0.6 * h, "grooming table {size:?}: top at {top:.2}");
        // The arm rises at a side and reaches over the middle of the top.
        let arm = within(&of(&s, Role::Metal), |p| p[2] > top + 0.6 * (h - top));
        let (x0, x1) = range(&arm, 0);
        assert!(
            x0 < 0.1 * hw && x1 > 0.7 * hw,
            "grooming table {size:?}: no arm over the top"
        );
        let noose = of(&s, Role::Canvas);
        let (z0, z1) = range(&noose, 2);
        assert!(
            z0 > top + 0.1 && z1 < h && range(&noose, 0).0 < 0.1 * hw,
            "grooming table {size:?}: no loop hanging over the top"
        );
    }
}

#[test]
fn a_poker_table_has_a_padded_rail_round_its_felt() {
    for size in sizes("poker table", [1.15, 1.1, 1.05]) {
        let s = at("poker table", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let rail = of(&s, Role::Cushion);
        for (sx, sy) in [(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
            let near = rail
                .iter()
                .filter(|p| {
                    (sx == 0.0 || p[0] * sx > 0.8 * hw) && (sy == 0.0 || p[1] * sy > 0.75 * hd)
                })
                .count();
            assert!(
                near > 10,
                "poker table {size:?}: no rail towards ({sx}, {sy})"
            );
        }
        let felt = of(&s, Role::Upholstery);
        assert!(
            top_of(&felt) < top_of(&rail) - 0.02 && top_of(&felt) > 0.8 * h,
            "poker table {size:?}: felt not sunk inside the rail"
        );
        // Chips on the felt at the seats (the back half, away from the dealer's tray).
        let chips = within(&of(&s, Role::Books), |p| {
            p[2] > top_of(&felt) - 0.01 && p[1] < -0.2 * hd
        });
        assert!(
            runs(&chips, 0, 0.02) >= 4,
            "poker table {size:?}: no chip stacks"
        );
    }
}

#[test]
fn a_cubicle_is_a_desk_inside_panels_on_three_sides() {
    for size in sizes("cubicle", [1.1, 0.9, 1.1]) {
        let s = at("cubicle", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let panels = of(&s, Role::Upholstery);
        let tall = |f: &dyn Fn(&[f64; 3]) -> bool| top_of(&within(&panels, |p| f(p))) > 0.9 * h;
        assert!(
            tall(&|p| p[1] < -0.9 * hd),
            "cubicle {size:?}: no back panel"
        );
        assert!(
            tall(&|p| p[0] < -0.9 * hw),
            "cubicle {size:?}: no left panel"
        );
        assert!(
            tall(&|p| p[0] > 0.9 * hw),
            "cubicle {size:?}: no right panel"
        );
        let open = within(&panels, |p| p[1] > 0.5 * hd && p[0].abs() < 0.5 * hw);
        assert!(open.is_empty(), "cubicle {size:?}: closed at the front");
        let desk = top_of(&of(&s, Role::Top));
        assert!(
            desk > 0.35 * h && desk < 0.7 * h,
            "cubicle {size:?}: desk top at {desk:.2}"
        );
    }
}

#[test]
fn a_bulletin_board_is_cork_with_pinned_notes() {
    for size in sizes("bulletin board", [1.2, 1.0, 0.85]) {
        let s = at("bulletin board", size);
        let cork = of(&s, Role::Canvas);
        let notes = of(&s, Role::Books);
        assert!(!notes.is_empty(), "bulletin board {size:?}: no notes");
        assert!(
            range(&notes, 1).1 > range(&cork, 1).1,
            "bulletin board {size:?}: notes not in front of the cork"
        );
        assert!(
            runs(&notes, 0, 0.005) >= 3 && runs(&notes, 2, 0.005) >= 2,
            "bulletin board {size:?}: notes not spread over the board"
        );
        assert!(
            runs(&of(&s, Role::Handle), 0, 0.005) >= 3,
            "bulletin board {size:?}: no pins"
        );
    }
}

#[test]
fn a_ladder_shelf_grows_shallower_upwards() {
    for size in sizes("ladder shelf", [1.2, 1.1, 1.1]) {
        let s = at("ladder shelf", size);
        let h = size[2];
        let shelves = of(&s, Role::Top);
        let depth = |z0: f64, z1: f64| {
            let r = range(&within(&shelves, |p| (z0..z1).contains(&p[2])), 1);
            r.1 - r.0
        };
        let (low, high) = (depth(0.0, 0.2 * h), depth(0.75 * h, h));
        assert!(
            low > 0.8 * size[1] && high < 0.5 * low,
            "ladder shelf {size:?}: shelf depths {low:.2} low, {high:.2} high"
        );
        // The rails lean: at the floor in front, at the top against the wall.
        let rails = of(&s, Role::Frame);
        let y_at = |z0: f64, z1: f64| range(&within(&rails, |p| (z0..z1).contains(&p[2])), 1).1;
        assert!(
            y_at(0.0, 0.05 * h) > y_at(0.9 * h, h) + 0.5 * size[1],
            "ladder shelf {size:?}: the rails do not lean"
        );
    }
}

/// Whether the samples of a band about the floor stand only at the corners (legs): none of
/// them towards the middle of each side.
fn on_legs(category: &str, size: [f64; 3]) -> bool {
    let s = at(category, size);
    let (hw, hd) = (size[0] / 2.0, size[1] / 2.0);
    let low = within(&of(&s, Role::Frame), |p| (0.01..0.05).contains(&p[2]));
    let mid_side = low
        .iter()
        .filter(|p| p[0].abs() < 0.2 * hw || p[1].abs() < 0.2 * hd)
        .count();
    let corners = [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)]
        .iter()
        .all(|(sx, sy)| {
            low.iter()
                .any(|p| p[0] * sx > 0.3 * hw && p[1] * sy > 0.3 * hd)
        });
    mid_side == 0 && corners
}

#[test]
fn an_ottoman_and_a_vanity_stool_stand_on_legs_under_a_buttoned_cushion() {
    let mut legs = vec![];
    for category in ["ottoman", "vanity stool"] {
        for size in sizes(category, [1.2, 1.1, 1.1]) {
            assert!(on_legs(category, size), "{category} {size:?}: not on legs");
            let s = at(category, size);
            let cushion = of(&s, Role::Upholstery);
            let z0 = range(&cushion, 2).0;
            assert!(
                z0 > 0.15 * size[2],
                "{category} {size:?}: cushion to the floor"
            );
            let buttons = within(&of(&s, Role::Cushion), |p| {
                p[2] > size[2] - 0.02 && p[0].abs() < 0.3 * size[0]
            });
            assert!(
                runs(&buttons, 0, 0.005) >= 3,
                "{category} {size:?}: no buttons on the top"
            );
            if size == sizes(category, [1.0; 3])[0] {
                legs.push(z0 / size[2]);
            }
        }
    }
    // The small stool stands higher on its legs than the wide footstool.
    assert!(legs[1] > legs[0] + 0.15, "leg shares {legs:?}");
}

#[test]
fn a_kitchen_cart_is_a_wooden_block_on_casters_not_a_bar_cart() {
    for size in sizes("kitchen cart", [1.2, 1.1, 1.05]) {
        let s = at("kitchen cart", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let top = of(&s, Role::Top);
        let (z0, z1) = range(&top, 2);
        assert!(
            z1 > 0.98 * h && z1 - z0 > 0.035,
            "kitchen cart {size:?}: no thick block top"
        );
        let (x0, x1) = range(&top, 0);
        assert!(
            x1 - x0 > 0.95 * size[0],
            "kitchen cart {size:?}: top not full width"
        );
        let wheels = of(&s, Role::Tyre);
        for (sx, sy) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
            assert!(
                wheels
                    .iter()
                    .any(|p| p[0] * sx > 0.6 * hw && p[1] * sy > 0.5 * hd),
                "kitchen cart {size:?}: no caster at ({sx}, {sy})"
            );
        }
        assert!(
            of(&s, Role::Glass).is_empty() && of(&s, Role::BlackKeys).is_empty(),
            "kitchen cart {size:?}: bottles of a bar cart"
        );
        assert!(
            !of(&s, Role::Door).is_empty(),
            "kitchen cart {size:?}: no drawer"
        );
    }
}

#[test]
fn a_candle_stand_holds_candles_on_arms_round_a_slender_stem() {
    for size in sizes("candle stand", [1.2, 1.2, 1.1]) {
        let s = at("candle stand", size);
        let h = size[2];
        let flames = of(&s, Role::Light);
        assert!(
            range(&flames, 2).0 > 0.8 * h,
            "candle stand {size:?}: flames not at the top"
        );
        assert!(
            runs(&flames, 0, 0.01) >= 3,
            "candle stand {size:?}: not several candles"
        );
        let stem = within(&of(&s, Role::Metal), |p| (0.3 * h..0.5 * h).contains(&p[2]));
        let (x0, x1) = range(&stem, 0);
        assert!(
            x1 - x0 < 0.3 * size[0],
            "candle stand {size:?}: not a slender stem"
        );
    }
}

#[test]
fn a_grand_piano_lid_is_propped_open() {
    for size in sizes("grand piano", [1.1, 1.1, 1.08]) {
        let s = at("grand piano", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let lid = of(&s, Role::Top);
        let z_at = |x0: f64, x1: f64| top_of(&within(&lid, |p| (x0..x1).contains(&p[0])));
        let (treble, bass) = (z_at(-0.95 * hw, -0.7 * hw), z_at(0.7 * hw, 0.95 * hw));
        assert!(
            treble > bass + 0.25 * (h - 1.0).max(0.5),
            "grand piano {size:?}: lid at {treble:.2} over the treble, {bass:.2} over the bass"
        );
        // The stick stands between the case and the lid.
        let stick = within(&of(&s, Role::Frame), |p| p[2] > bass);
        assert!(!stick.is_empty(), "grand piano {size:?}: no stick");
    }
}
