//! Things people name that borrowed another thing's drawing, each drawn as what it is and
//! checked on its parts at its knowledge-base size and a stretched one, against the old
//! drawing's defect: a printing press, an x-ray machine and a time machine were one boxy
//! appliance with a door and a window; a folding chair a four-legged chair (no X frame); a loft
//! bed a bunk bed with a lower bunk; a watering can a kettle; a wall mirror a board on a foot;
//! a window seat an open bench on legs. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, sized, within, Samples};
use dreamscene::shape::{archetype_of, Role};

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 3)
}

/// Drawn as none of the old boxy appliance's parts: no door, no window.
fn not_an_appliance(s: &Samples, what: &str) {
    assert!(of(s, Role::Door).is_empty(), "{what}: a door");
    assert!(of(s, Role::Screen).is_empty(), "{what}: a window");
}

#[test]
fn a_printing_press_has_a_platen_over_a_long_bed_and_a_bar_handle() {
    for size in sized("printing press", [1.3, 0.8, 1.2]) {
        let s = at("printing press", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        not_an_appliance(&s, &format!("{size:?}"));
        // A sheet on the bed at waist height, at the front.
        let paper = of(&s, Role::Canvas);
        assert!(!paper.is_empty(), "{size:?}: no sheet");
        let (z0, z1) = range(&paper, 2);
        assert!(
            z0 > 0.4 * h && z1 < 0.65 * h,
            "{size:?}: sheet at {z0:.2}..{z1:.2}"
        );
        assert!(
            range(&paper, 1).1 > 0.6 * hd,
            "{size:?}: sheet not at the front"
        );
        // The bed runs front to back through the staple.
        let bed = of(&s, Role::Body);
        let (y0, y1) = range(&bed, 1);
        assert!(y1 - y0 > 1.6 * hd, "{size:?}: a short bed");
        // The platen hangs over the bed with a gap under it (where the forme goes in).
        let metal = of(&s, Role::Metal);
        let over = within(&metal, |p| p[0].abs() < 0.1 * hw && p[1].abs() < 0.1 * hd);
        let under = within(&over, |p| {
            p[2] > 0.5 * h + 0.02 && p[2] < 0.5 * h + 0.05 * h
        });
        assert!(under.is_empty(), "{size:?}: nothing between bed and platen");
        assert!(
            over.iter().any(|p| (p[2] - 0.6 * h).abs() < 0.05 * h),
            "{size:?}: no platen"
        );
        // The bar handle reaches out past the staple at the right.
        let handle = within(&all(&s), |p| p[0] > 0.75 * hw && p[2] > 0.6 * h);
        assert!(!handle.is_empty(), "{size:?}: no bar handle");
    }
    assert_eq!(archetype_of("printing press"), "printing_press");
}

#[test]
fn an_x_ray_machine_hangs_its_tube_over_an_open_patient_table() {
    for size in sized("x-ray machine", [1.4, 1.2, 0.9]) {
        let s = at("x-ray machine", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        not_an_appliance(&s, &format!("{size:?}"));
        // A padded table top across the width at about a bed's height.
        let pad = of(&s, Role::Cushion);
        assert!(!pad.is_empty(), "{size:?}: no table pad");
        let (x0, x1) = range(&pad, 0);
        assert!(x1 - x0 > 1.6 * hw, "{size:?}: a narrow table");
        let zt = range(&pad, 2).1;
        assert!(zt > 0.3 * h && zt < 0.5 * h, "{size:?}: table at {zt:.2}");
        // The tube's lit window faces down over the table's middle, the space between open.
        let lamp = of(&s, Role::Light);
        assert!(!lamp.is_empty(), "{size:?}: no tube head");
        let (lz, _) = range(&lamp, 2);
        let (ly0, ly1) = range(&lamp, 1);
        let (py0, py1) = range(&pad, 1);
        assert!(
            ly0 > py0 && ly1 < py1,
            "{size:?}: the tube is not over the table"
        );
        assert!(lz > zt + 0.15 * h, "{size:?}: the tube sits on the table");
        let yc = 0.5 * (ly0 + ly1);
        let gap = within(&all(&s), |p| {
            p[0].abs() < 0.1 * hw
                && (p[1] - yc).abs() < 0.05
                && p[2] > zt + 0.02
                && p[2] < lz - 0.02
        });
        assert!(gap.is_empty(), "{size:?}: no room for the patient");
    }
    assert_eq!(archetype_of("xray machine"), "xray_machine");
}

#[test]
fn a_time_machine_is_a_seat_before_a_great_upright_disc() {
    for size in sized("time machine", [1.2, 1.0, 0.8]) {
        let s = at("time machine", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        not_an_appliance(&s, &format!("{size:?}"));
        let seat = of(&s, Role::Upholstery);
        assert!(!seat.is_empty(), "{size:?}: no seat");
        assert!(
            range(&seat, 2).0 < 0.35 * h,
            "{size:?}: the seat is not low on the deck"
        );
        // The disc: a big round upright plate behind the seat.
        let disc = of(&s, Role::Glass);
        assert!(!disc.is_empty(), "{size:?}: no disc");
        assert!(
            range(&disc, 1).1 < range(&seat, 1).0,
            "{size:?}: the disc is not behind"
        );
        let (x0, x1) = range(&disc, 0);
        let (z0, z1) = range(&disc, 2);
        assert!(x1 - x0 > hw, "{size:?}: a small disc");
        assert!(
            ((x1 - x0) / (z1 - z0) - 1.0).abs() < 0.25,
            "{size:?}: not round ({:.2} x {:.2})",
            x1 - x0,
            z1 - z0
        );
        let (y0, y1) = range(&disc, 1);
        assert!(y1 - y0 < 0.15 * size[1], "{size:?}: not upright");
    }
    assert_eq!(archetype_of("tardis"), "time_machine");
}

#[test]
fn a_folding_chair_crosses_its_legs_in_an_x_on_each_side() {
    for size in sized("folding chair", [1.3, 1.2, 1.1]) {
        let s = at("folding chair", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let legs = of(&s, Role::Metal);
        for sx in [-1.0, 1.0] {
            let side = within(&legs, |p| sx * p[0] > 0.8 * hw);
            // at the floor: feet at the front and at the back
            let feet = within(&side, |p| p[2] < 0.03);
            assert!(
                feet.iter().any(|p| p[1] > 0.6 * hd),
                "{size:?}: no front foot"
            );
            assert!(
                feet.iter().any(|p| p[1] < -0.6 * hd),
                "{size:?}: no back foot"
            );
            // halfway up to the seat the legs have met near the middle: the X
            let zs = 0.55 * h;
            let mid = within(&side, |p| (p[2] - 0.45 * zs).abs() < 0.02);
            assert!(!mid.is_empty(), "{size:?}: no legs there");
            assert!(
                mid.iter().all(|p| p[1].abs() < 0.5 * hd),
                "{size:?}: upright corner legs"
            );
        }
    }
    assert_eq!(archetype_of("folding chair"), "folding_chair");
}

#[test]
fn a_loft_bed_sleeps_high_with_a_desk_under_it() {
    for size in sized("loft bed", [1.2, 1.1, 1.15]) {
        let s = at("loft bed", size);
        let h = size[2];
        let mattress = of(&s, Role::Mattress);
        assert!(
            range(&mattress, 2).0 > 0.5 * h,
            "{size:?}: a mattress down low (a lower bunk)"
        );
        let desk = of(&s, Role::Top);
        assert!(!desk.is_empty(), "{size:?}: no desk");
        let (z0, z1) = range(&desk, 2);
        assert!(
            z0 > 0.3 * h && z1 < 0.5 * h,
            "{size:?}: desk at {z0:.2}..{z1:.2}"
        );
    }
    assert_eq!(archetype_of("high sleeper"), "loft_bed");
}

#[test]
fn a_watering_can_has_a_long_spout_rising_from_its_foot_to_a_rose() {
    for size in sized("watering can", [1.3, 1.2, 0.9]) {
        let s = at("watering can", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        // Near the front end everything is high up: the rose, nothing of a body.
        let end = within(&all(&s), |p| p[0] > 0.6 * hw);
        assert!(!end.is_empty(), "{size:?}: nothing reaches the front");
        assert!(
            end.iter().all(|p| p[2] > 0.5 * h),
            "{size:?}: a body at the front"
        );
        // The spout leaves the tank low down.
        let low = within(&all(&s), |p| p[0] > 0.15 * hw && p[0] < 0.35 * hw);
        assert!(
            !low.is_empty() && low.iter().all(|p| p[2] < 0.6 * h),
            "{size:?}: no low spout"
        );
        // The rose's face, and the handle over the tank at its back.
        assert!(!of(&s, Role::Interior).is_empty(), "{size:?}: no rose face");
        let grip = within(&of(&s, Role::Handle), |p| {
            p[0] < -0.2 * hw && p[2] > 0.85 * h
        });
        assert!(!grip.is_empty(), "{size:?}: no handle over the tank");
    }
    assert_eq!(archetype_of("watering pot"), "watering_can");
}

#[test]
fn a_wall_mirror_is_framed_proud_of_its_glass_and_hangs_on_a_wire() {
    for size in sized("mirror", [1.4, 1.0, 1.3]) {
        let s = at("mirror", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let glass = of(&s, Role::Canvas);
        let front = range(&glass, 1).1;
        // The frame stands out in front of the glass on all four sides.
        let proud = within(&of(&s, Role::Frame), |p| p[1] > front + 0.005);
        for (what, side) in [
            (
                "bottom",
                within(&proud, |p| p[2] < 0.1 * h && p[0].abs() < 0.5 * hw),
            ),
            (
                "top",
                within(&proud, |p| p[2] > 0.9 * h && p[0].abs() < 0.5 * hw),
            ),
            (
                "left",
                within(&proud, |p| {
                    p[0] < -0.9 * hw && (p[2] - 0.5 * h).abs() < 0.2 * h
                }),
            ),
            (
                "right",
                within(&proud, |p| {
                    p[0] > 0.9 * hw && (p[2] - 0.5 * h).abs() < 0.2 * h
                }),
            ),
        ] {
            assert!(!side.is_empty(), "{size:?}: no frame at the {what}");
        }
        // Its hanging wire at the back, high up.
        let wire = of(&s, Role::Metal);
        assert!(!wire.is_empty(), "{size:?}: nothing to hang it by");
        assert!(range(&wire, 2).0 > 0.6 * h, "{size:?}: the wire is low");
        assert!(
            range(&wire, 1).1 < range(&glass, 1).0,
            "{size:?}: the wire is not behind"
        );
    }
    for name in ["mirror", "wall mirror", "bathroom mirror"] {
        assert_eq!(archetype_of(name), "wall_mirror", "{name}");
    }
}

#[test]
fn a_window_seat_is_a_built_in_box_between_end_panels() {
    for size in sized("window seat", [1.4, 1.2, 1.0]) {
        let s = at("window seat", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let cushion = of(&s, Role::Cushion);
        assert!(!cushion.is_empty(), "{size:?}: no cushion");
        let zs = range(&cushion, 2).0;
        // Closed under the seat: its front is panelled across the width (no legs).
        let front = within(&all(&s), |p| {
            p[1] > 0.8 * hd && p[2] > 0.15 && p[2] < zs - 0.1
        });
        let (x0, x1) = range(&front, 0);
        assert!(x1 - x0 > 1.6 * hw, "{size:?}: open under the seat");
        let cells: std::collections::BTreeSet<i64> =
            front.iter().map(|p| (p[0] / 0.05).floor() as i64).collect();
        assert!(
            cells.len() as f64 > 0.85 * 2.0 * hw / 0.05,
            "{size:?}: gaps between legs"
        );
        // End panels rise past the cushion at both ends.
        for sx in [-1.0, 1.0] {
            let end = within(&of(&s, Role::Frame), |p| {
                sx * p[0] > 0.9 * hw && p[2] > 0.9 * h
            });
            assert!(!end.is_empty(), "{size:?}: no end panel at {sx}");
        }
        assert!(!of(&s, Role::Pillow).is_empty(), "{size:?}: no pillows");
    }
    assert_eq!(archetype_of("bay window seat"), "window_seat");
}

#[test]
fn a_window_seat_stands_by_a_window_with_its_back_to_the_wall() {
    use dreamscene::plan::check::{anchor_holds_in, Box2};
    use dreamscene::plan::gcp::{layout, LayoutOptions};
    use dreamscene::plan::offline::plan_offline;
    use dreamscene::plan::spec::Anchor;
    for prompt in [
        "a cosy reading nook with a window seat and a bookshelf",
        "a girl's bedroom with a bed, a desk and a window seat",
    ] {
        let spec = plan_offline(prompt);
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).unwrap();
            let seat = l
                .objects
                .iter()
                .find(|o| o.category == "window seat")
                .unwrap();
            let b = Box2::of(seat);
            for anchor in [Anchor::Window, Anchor::Side] {
                assert!(
                    anchor_holds_in(&b, anchor, l.scene_type, l.room.size, &l.openings),
                    "{prompt} seed {seed}: not {anchor:?}: {seat:?} {:?}",
                    l.openings
                );
            }
        }
    }
}
