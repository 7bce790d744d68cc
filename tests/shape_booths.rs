//! Things once drawn as a plain box (or as a fireplace, a kitchen range, a massage bench, an
//! armchair, a whiteboard or a bedroom dresser) drawn as what they are, checked on their parts
//! at their knowledge-base size and at a stretched size: a backpack is deeper at the bottom, a
//! turnstile's arms reach out of its pedestal, a photo backdrop's paper curves onto the floor,
//! a dog crate has bars, a forge an anvil beside its hearth, an operating table one column.
//! Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, runs, sized, within, Samples};
use dreamscene::shape::{archetype_of, Role};

/// Surface samples of `category` at `size`.
fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 3)
}

#[test]
fn none_of_these_is_drawn_by_the_archetype_of_another_thing() {
    let borrowed = [
        ("backpack", "box"),
        ("bathroom scale", "box"),
        ("bread bin", "box"),
        ("compost bin", "box"),
        ("dock", "box"),
        ("dog crate", "box"),
        ("firewood pile", "box"),
        ("fitting room", "box"),
        ("litter box", "box"),
        ("magazine", "box"),
        ("obelisk", "box"),
        ("photo booth", "box"),
        ("sandbox", "box"),
        ("security gate", "box"),
        ("shopping basket", "box"),
        ("stage monitor", "box"),
        ("train set", "box"),
        ("turnstile", "box"),
        ("workbench vise", "box"),
        ("cardboard box", "box"),
        ("crate", "box"),
        ("cargo container", "box"),
        ("hay bale", "box"),
        ("forge", "fireplace"),
        ("furnace", "fireplace"),
        ("camping stove", "stove"),
        ("operating table", "padded_table"),
        ("theater seat", "armchair"),
        ("nursing chair", "armchair"),
        ("photo backdrop", "board"),
        ("card catalog", "dresser"),
        ("medical cart", "dresser"),
        ("tool cabinet", "dresser"),
        ("changing table", "dresser"),
        ("stage", "box"),
        ("pedestal", "box"),
        ("hostess stand", "cabinet"),
        ("jewelry armoire", "cabinet"),
        ("examination lamp", "floor_lamp"),
    ];
    let wrong: Vec<String> = borrowed
        .iter()
        .filter(|(c, a)| archetype_of(c) == *a)
        .map(|(c, a)| format!("{c} is still a {a}"))
        .collect();
    assert!(wrong.is_empty(), "{wrong:#?}");
}

/// Real boxes keep a box's outline (their parts fill the size box's footprint at its foot and
/// reach its top) and show what box they are: tape on cardboard, gaps between a crate's boards,
/// ribs down a container's sides, twine round a bale.
#[test]
fn real_boxes_stay_boxes_with_the_marks_of_their_kind() {
    for c in ["cardboard box", "crate", "cargo container", "hay bale"] {
        for size in sized(c, [1.2, 0.9, 1.1]) {
            let s = at(c, size);
            let pts = all(&s);
            let low = within(&pts, |p| p[2] < 0.05 * size[2]);
            let (x0, x1) = range(&low, 0);
            let (y0, y1) = range(&low, 1);
            assert!(
                x1 - x0 > 0.9 * size[0] && y1 - y0 > 0.9 * size[1],
                "{c} {size:?}: its foot is not the box's"
            );
            assert!(range(&pts, 2).1 > 0.98 * size[2], "{c} {size:?}: low");
        }
    }
    let size = sized("cardboard box", [1.0; 3])[0];
    let tape = of(&at("cardboard box", size), Role::Handle);
    assert_eq!(runs(&tape, 2, 0.01), 2, "tape on two boxes' lids");
    let size = sized("crate", [1.0; 3])[0];
    let gaps = within(&of(&at("crate", size), Role::Interior), |p| {
        p[1] < -0.45 * size[1]
    });
    assert!(!gaps.is_empty(), "no gaps between a crate's boards");
    let size = sized("cargo container", [1.0; 3])[0];
    let side = within(&all(&at("cargo container", size)), |p| {
        p[0] > size[0] / 2.0 - 0.015 && (p[2] - 0.5 * size[2]).abs() < 0.05
    });
    assert!(runs(&side, 1, 0.04) >= 12, "{} ribs", runs(&side, 1, 0.04));
    let size = sized("hay bale", [1.0; 3])[0];
    let twine = within(&of(&at("hay bale", size), Role::Handle), |p| {
        p[2] > 0.99 * size[2]
    });
    assert_eq!(runs(&twine, 0, 0.02), 2, "two twines");
}

#[test]
fn a_backpack_is_deeper_low_down_than_at_its_top_with_straps_behind() {
    for name in ["backpack", "rucksack"] {
        for size in sized("backpack", [1.2, 1.0, 1.3]) {
            let s = at(name, size);
            let pack: Vec<[f64; 3]> = s
                .iter()
                .filter(|(_, r)| matches!(r, Role::Body | Role::Top | Role::Cushion))
                .map(|(p, _)| *p)
                .collect();
            let depth = |z0: f64, z1: f64| {
                let band = within(&pack, |p| p[2] > z0 * size[2] && p[2] < z1 * size[2]);
                let (y0, y1) = range(&band, 1);
                y1 - y0
            };
            let (low, high) = (depth(0.15, 0.3), depth(0.88, 0.95));
            assert!(
                low > 1.3 * high,
                "{name} {size:?}: {low:.3} deep low, {high:.3} at the top"
            );
            // Straps run down the back, behind the pack's middle.
            let straps = of(&s, Role::Handle);
            let behind = within(&straps, |p| p[1] < -0.3 * size[1]);
            assert!(!behind.is_empty(), "{name} {size:?}: no straps behind");
            assert_eq!(runs(&behind, 0, 0.02), 2, "{name} {size:?}: two straps");
        }
    }
}

#[test]
fn a_turnstiles_arms_reach_out_of_its_pedestal() {
    for size in sized("turnstile", [1.2, 1.0, 1.1]) {
        let s = at("turnstile", size);
        let pedestal = of(&s, Role::Body);
        let (_, px) = range(&pedestal, 0);
        assert!(px < 0.0, "{size:?}: the pedestal fills the passage");
        let arms = of(&s, Role::Metal);
        // One arm level across the passage, reaching most of the way to the far side.
        let level = within(&arms, |p| {
            p[0] > px + 0.1 && (p[2] - range(&arms, 2).1).abs() < 0.5
        });
        let (_, reach) = range(&level, 0);
        assert!(
            reach - px > 0.45 * size[0],
            "{size:?}: arms reach {:.2} out of the pedestal",
            reach - px
        );
        // Three arms: out of the hub, they lie apart (front, back and level).
        let out = within(&arms, |p| p[0] > px + 0.12);
        assert_eq!(
            runs(&out, 1, 0.03),
            3,
            "{size:?}: three arms seen from the side"
        );
    }
}

#[test]
fn a_photo_backdrops_paper_hangs_from_a_bar_and_curves_onto_the_floor() {
    for name in ["photo backdrop", "studio backdrop"] {
        for size in sized("photo backdrop", [1.0, 2.0, 1.0]) {
            let s = at(name, size);
            let paper = of(&s, Role::Canvas);
            let (hd, h) = (size[1] / 2.0, size[2]);
            let floor = within(&paper, |p| p[2] < 0.01);
            let (f0, f1) = range(&floor, 1);
            assert!(
                f1 > 0.9 * hd,
                "{name} {size:?}: the sweep stops at y = {f1:.2}"
            );
            let hanging = within(&paper, |p| p[2] > 0.5 * h);
            let (_, hy) = range(&hanging, 1);
            assert!(
                hy < f0 + 0.02,
                "{name} {size:?}: the upright paper is in front of the floor part"
            );
            // Between them a curve: paper both low and between the two.
            let curve = within(&paper, |p| {
                p[2] > 0.02 && p[2] < 0.15 * h && p[1] > hy + 0.01
            });
            assert!(!curve.is_empty(), "{name} {size:?}: a corner, not a curve");
            // Two stands carry it.
            let stands = within(&of(&s, Role::Metal), |p| p[2] > 0.3 * h && p[2] < 0.8 * h);
            assert_eq!(runs(&stands, 0, 0.05), 2, "{name} {size:?}: two stands");
        }
    }
}

#[test]
fn a_dog_crate_is_a_cage_of_bars_and_a_firewood_pile_shows_round_ends() {
    for size in sized("dog crate", [1.3, 1.2, 1.1]) {
        let s = at("dog crate", size);
        let front = within(&of(&s, Role::Metal), |p| {
            p[1] > 0.45 * size[1] && (p[2] - 0.3 * size[2]).abs() < 0.02
        });
        assert!(
            runs(&front, 0, 0.01) >= 12,
            "{size:?}: {} bars across the front",
            runs(&front, 0, 0.01)
        );
    }
    for size in sized("firewood pile", [1.5, 1.0, 1.2]) {
        let s = at("firewood pile", size);
        let ends = within(&of(&s, Role::Top), |p| p[1] > 0.4 * size[1]);
        let row = within(&ends, |p| p[2] < 0.03);
        assert!(
            runs(&row, 0, 0.01) >= 6,
            "{size:?}: {} log ends in the bottom row",
            runs(&row, 0, 0.01)
        );
        assert!(
            range(&ends, 2).1 > 0.85 * size[2],
            "{size:?}: log ends stop short of the top"
        );
    }
}

#[test]
fn an_obelisk_tapers_to_a_point_and_a_stage_monitor_slopes_back() {
    for size in sized("obelisk", [0.8, 0.8, 1.5]) {
        let s = all(&at("obelisk", size));
        let width = |z: f64| {
            let band = within(&s, |p| (p[2] - z * size[2]).abs() < 0.01 * size[2]);
            let (x0, x1) = range(&band, 0);
            x1 - x0
        };
        assert!(width(0.2) > 1.2 * width(0.85), "{size:?}: no taper");
        assert!(width(0.99) < 0.3 * width(0.2), "{size:?}: no pointed top");
    }
    for size in sized("stage monitor", [1.4, 1.0, 1.0]) {
        let s = all(&at("stage monitor", size));
        let top_at = |y: f64| {
            let band = within(&s, |p| (p[1] - y * size[1]).abs() < 0.03 * size[1]);
            range(&band, 2).1
        };
        assert!(
            top_at(0.45) < 0.45 * size[2] && top_at(-0.45) > 0.95 * size[2],
            "{size:?}: front {:.2}, back {:.2}",
            top_at(0.45),
            top_at(-0.45)
        );
    }
}

#[test]
fn a_forge_has_a_hood_over_its_fire_and_an_anvil_beside_it() {
    for name in ["forge", "blacksmith forge"] {
        for size in sized("forge", [1.3, 1.0, 1.1]) {
            let s = at(name, size);
            let fire = of(&s, Role::Light);
            let (f0, f1) = range(&fire, 0);
            let hearth_top = range(&fire, 2).0;
            // The hood's flue reaches the top over the fire.
            let flue = within(&of(&s, Role::Metal), |p| p[2] > 0.97 * size[2]);
            let (u0, u1) = range(&flue, 0);
            assert!(
                !flue.is_empty() && u0 > f0 - 0.1 && u1 < f1 + 0.1,
                "{name} {size:?}: no flue over the fire"
            );
            // The anvil (iron on a stump) stands to the side of the fire, about hearth high.
            let stump = of(&s, Role::Trunk);
            let (sx0, _) = range(&stump, 0);
            assert!(
                sx0 > f1,
                "{name} {size:?}: the anvil is not beside the fire"
            );
            assert!(
                (range(&stump, 2).1 - 0.7 * hearth_top).abs() < 0.5 * hearth_top,
                "{name} {size:?}: stump height"
            );
        }
    }
}

#[test]
fn a_camping_stove_is_low_with_two_burners_and_a_furnace_a_flue() {
    for name in ["camping stove", "camp stove"] {
        for size in sized("camping stove", [1.3, 1.2, 1.0]) {
            let s = at(name, size);
            let flames = of(&s, Role::Light);
            assert_eq!(runs(&flames, 0, 0.01), 2, "{name} {size:?}: two burners");
            assert!(
                range(&flames, 2).1 < 0.5 * size[2],
                "{name} {size:?}: burners high up"
            );
        }
    }
    for size in sized("furnace", [1.0, 1.2, 1.2]) {
        let s = at("furnace", size);
        let body = of(&s, Role::Body);
        let flue = of(&s, Role::Metal);
        assert!(range(&body, 2).1 < 0.7 * size[2], "{size:?}: not squat");
        assert!(range(&flue, 2).1 > 0.98 * size[2], "{size:?}: no flue");
        let (x0, x1) = range(&flue, 0);
        assert!(x1 - x0 < 0.5 * size[0], "{size:?}: the flue is a pipe");
    }
}

#[test]
fn an_operating_table_stands_on_one_column_under_a_long_pad() {
    for name in ["operating table", "surgical table"] {
        for size in sized("operating table", [1.2, 1.1, 1.0]) {
            let s = at(name, size);
            let mid = within(&all(&s), |p| (p[2] - 0.4 * size[2]).abs() < 0.05 * size[2]);
            let (y0, y1) = range(&mid, 1);
            let (x0, x1) = range(&mid, 0);
            assert!(
                y1 - y0 < 0.25 * size[1] && x1 - x0 < 0.6 * size[0],
                "{name} {size:?}: the support is {:.2} × {:.2}",
                x1 - x0,
                y1 - y0
            );
            assert_eq!(
                runs(&mid, 1, 0.02),
                1,
                "{name} {size:?}: more than one column"
            );
            let pad = of(&s, Role::Upholstery);
            let (p0, p1) = range(&pad, 1);
            assert!(p1 - p0 > 0.95 * size[1], "{name} {size:?}: short pad");
            // The pad's sections: head, trunk, legs.
            let on_top = within(&pad, |p| p[2] > 0.99 * size[2] && p[0].abs() < 0.1);
            assert_eq!(runs(&on_top, 1, 0.008), 3, "{name} {size:?}: pad sections");
        }
    }
}

#[test]
fn a_nursing_chair_is_low_under_a_high_back_and_a_theatre_seat_folds_between_arms() {
    for size in sized("nursing chair", [1.1, 1.0, 1.1]) {
        let s = at("nursing chair", size);
        let soft: Vec<[f64; 3]> = s
            .iter()
            .filter(|(_, r)| matches!(r, Role::Upholstery | Role::Cushion))
            .map(|(p, _)| *p)
            .collect();
        let seat = range(&of(&s, Role::Cushion), 2).1;
        assert!(seat < 0.46 * size[2], "{size:?}: seat at {seat:.2}");
        // Its arms (a glider's side frames) stay low beside the seat, well under the back.
        let arms = within(&all(&s), |p| p[1] > -0.1 * size[1] && p[2] > seat + 0.25);
        assert!(
            arms.is_empty(),
            "{size:?}: {} samples of high arms",
            arms.len()
        );
        assert!(range(&soft, 2).1 > 0.97 * size[2], "{size:?}: low back");
    }
    for name in ["theater seat", "cinema seat"] {
        for size in sized("theater seat", [1.2, 1.0, 1.0]) {
            let s = at(name, size);
            let arms = of(&s, Role::Top);
            assert_eq!(runs(&arms, 0, 0.01), 2, "{name} {size:?}: two arms");
            // The seat is folded up: its cushion stands upright in front of the back.
            let soft = of(&s, Role::Upholstery);
            let front = within(&soft, |p| p[1] > -0.15 * size[1]);
            let (z0, z1) = range(&front, 2);
            let (y0, y1) = range(&front, 1);
            assert!(
                z1 - z0 > 2.0 * (y1 - y0),
                "{name} {size:?}: the seat lies flat"
            );
        }
    }
}

#[test]
fn drawer_cases_of_other_trades_differ_from_a_dresser() {
    let fronts = |c: &str, size: [f64; 3]| {
        let handles = within(&of(&at(c, size), Role::Handle), |p| p[1] > 0.45 * size[1]);
        (runs(&handles, 0, 0.01), runs(&handles, 2, 0.005))
    };
    for size in sized("card catalog", [1.2, 1.0, 1.0]) {
        let (cols, rows) = fronts("card catalog", size);
        assert!(cols * rows >= 30, "{size:?}: {cols} × {rows} drawers");
    }
    for size in sized("tool cabinet", [1.0, 1.0, 1.2]) {
        let (_, rows) = fronts("tool cabinet", size);
        assert!(rows >= 8, "{size:?}: {rows} rows of drawers");
        let s = at("tool cabinet", size);
        assert!(
            runs(&of(&s, Role::Tyre), 0, 0.02) >= 2,
            "{size:?}: no castors"
        );
    }
    for size in sized("medical cart", [1.2, 1.0, 1.0]) {
        let s = at("medical cart", size);
        let rail = within(&of(&s, Role::Metal), |p| p[2] > 0.95 * size[2]);
        let (y0, y1) = range(&rail, 1);
        assert!(y1 - y0 > 0.8 * size[1], "{size:?}: no rail round the top");
        assert!(!of(&s, Role::Tyre).is_empty(), "{size:?}: no castors");
    }
    for size in sized("changing table", [1.2, 1.0, 1.0]) {
        let s = at("changing table", size);
        let mat = of(&s, Role::Cushion);
        // The mat's edges stand higher than its middle.
        let top_at = |y: f64| {
            let band = within(&mat, |p| (p[1] - y * size[1]).abs() < 0.04 * size[1]);
            range(&band, 2).1
        };
        assert!(
            top_at(-0.35) > top_at(0.0) + 0.03 && top_at(0.35) > top_at(0.0) + 0.03,
            "{size:?}: a flat mat"
        );
    }
}

#[test]
fn a_train_set_is_a_loop_of_track_with_a_train_on_it() {
    for size in sized("train set", [1.5, 1.2, 1.0]) {
        let s = at("train set", size);
        let track = of(&s, Role::Top);
        // The loop leaves its middle open.
        let middle = within(&track, |p| {
            p[0].abs() < 0.2 * size[0] && p[1].abs() < 0.3 * size[1]
        });
        assert!(middle.is_empty(), "{size:?}: the middle is filled");
        let (x0, x1) = range(&track, 0);
        let (y0, y1) = range(&track, 1);
        assert!(
            x1 - x0 > 0.95 * size[0] && y1 - y0 > 0.95 * size[1],
            "{size:?}"
        );
        let train = of(&s, Role::Body);
        assert!(
            !train.is_empty() && range(&train, 2).1 > 0.4 * size[2],
            "{size:?}: no train"
        );
    }
}
