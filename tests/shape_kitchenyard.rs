//! Everyday kitchen, workshop and nursery things that had no object of their own: the reader
//! took a dish rack for a rack, a cutting board for a board, a baby gate for a garden gate and
//! a step stool for a stool, dropped a pot rack, and made a sawhorse a 1.7 m horse. Each is now
//! its own category, planned at a fitting size and place and drawn as what it is. Plan-only
//! and host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
mod reading;
use common::samples::{all, drawn, of, range, runs, sized, within, Samples};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_offline;
use dreamscene::shape::{archetype_of, Role};
use reading::{keys, plan};

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 4)
}

/// The plan of `prompt` holds `n` of exactly `category` and none of the `not` categories.
fn holds(prompt: &str, category: &str, n: u32, not: &[&str]) {
    let s = plan(prompt);
    let got = s.objects.get(category).map_or(0, |o| o.number);
    assert_eq!(got, n, "{prompt}: {:?}", keys(&s));
    for c in not {
        assert!(
            !s.objects.contains_key(*c),
            "{prompt}: {c} in {:?}",
            keys(&s)
        );
    }
}

#[test]
fn kitchen_things_are_read_as_what_they_are() {
    for prompt in [
        "a small kitchen with a dish rack next to the sink",
        "a bright kitchen, a dish drying rack and a wooden cutting board on the counter",
    ] {
        holds(prompt, "plate rack", 1, &["rack", "board"]);
    }
    for prompt in [
        "a rustic kitchen with a chopping board and a bread bin",
        "a cutting board with some vegetables in a cottage kitchen",
    ] {
        holds(prompt, "cutting board", 1, &["board"]);
        let s = plan(prompt);
        let size = s.objects["cutting board"].size;
        assert!(size[2] < 0.1, "{prompt}: {size:?}");
    }
    for prompt in [
        "a farmhouse kitchen with a pot rack hanging over the island",
        "a chef's kitchen with a copper pot rack",
    ] {
        holds(prompt, "pot rack", 1, &["rack"]);
        // hung from the ceiling, over the people under it
        let spec = plan_offline(prompt);
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).unwrap();
            let r = l.objects.iter().find(|o| o.category == "pot rack").unwrap();
            assert!(
                r.position[2] > 1.6,
                "{prompt} seed {seed}: {:?}",
                r.position
            );
        }
    }
}

#[test]
fn workshop_and_nursery_things_are_read_as_what_they_are() {
    for prompt in [
        "a carpenter's workshop with two sawhorses and a workbench",
        "a garage with a sawhorse and a ladder",
    ] {
        let s = plan(prompt);
        let h = s.objects.get("sawhorse").map(|o| o.size[2]);
        assert!(h.is_some_and(|h| h < 1.0), "{prompt}: {:?}", keys(&s));
    }
    for prompt in [
        "a toddler's playroom with a baby gate",
        "a hallway with a stair gate and a shoe rack",
    ] {
        holds(prompt, "baby gate", 1, &["gate", "fence"]);
    }
    for prompt in [
        "a kitchen with a step stool by the fridge",
        "a kid's bathroom with a step stool at the sink",
    ] {
        holds(prompt, "step stool", 1, &["stool"]);
    }
}

#[test]
fn a_cutting_board_is_a_flat_board_with_a_handle_and_a_knife() {
    for size in sized("cutting board", [1.3, 1.2, 1.0]) {
        let s = at("cutting board", size);
        let (hw, hd) = (size[0] / 2.0, size[1] / 2.0);
        let board = of(&s, Role::Top);
        let (y0, y1) = range(&board, 1);
        assert!(y1 - y0 > 1.9 * hd, "{size:?}");
        // the handle: the board narrows at its right end
        let tab = within(&board, |p| p[0] > 0.9 * hw);
        assert!(
            !tab.is_empty() && range(&tab, 1).1 < 0.6 * hd,
            "{size:?}: no handle"
        );
        assert!(!of(&s, Role::Metal).is_empty(), "{size:?}: no knife");
    }
    assert_eq!(archetype_of("chopping board"), "cutting_board");
}

#[test]
fn a_pot_rack_hangs_pans_below_its_rail() {
    for size in sized("pot rack", [1.5, 1.2, 1.2]) {
        let s = at("pot rack", size);
        let h = size[2];
        let rail = within(&of(&s, Role::Frame), |p| p[2] < 0.9 * h);
        let pans = of(&s, Role::Pot);
        assert!(pans.len() > 100, "{size:?}: no pans");
        assert!(
            range(&pans, 2).1 < range(&rail, 2).0,
            "{size:?}: pans not under the rail"
        );
        // chains up to the ceiling
        assert!(
            range(&of(&s, Role::Frame), 2).1 > 0.98 * h,
            "{size:?}: no chains"
        );
    }
}

#[test]
fn a_sawhorse_is_a_beam_on_splayed_legs() {
    for size in sized("sawhorse", [1.4, 1.2, 0.9]) {
        let s = at("sawhorse", size);
        let (hd, h) = (size[1] / 2.0, size[2]);
        assert!(of(&s, Role::Skin).is_empty(), "{size:?}: an animal");
        let beam = of(&s, Role::Top);
        assert!(range(&beam, 2).0 > 0.8 * h, "{size:?}: no beam on top");
        assert!(range(&beam, 1).1 < 0.4 * hd, "{size:?}: a wide top");
        let feet = within(&of(&s, Role::Frame), |p| p[2] < 0.02);
        assert!(feet.iter().any(|p| p[1] > 0.7 * hd), "{size:?}");
        assert!(feet.iter().any(|p| p[1] < -0.7 * hd), "{size:?}");
    }
    assert_eq!(archetype_of("saw horse"), "sawhorse");
}

#[test]
fn a_baby_gate_has_close_bars_too_narrow_to_pass() {
    for size in sized("baby gate", [1.4, 1.0, 1.1]) {
        let s = at("baby gate", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let band = within(&all(&s), |p| {
            (p[2] - 0.5 * h).abs() < 0.02 && p[0].abs() < 0.85 * hw
        });
        let n = runs(&band, 0, 0.005);
        let span = range(&band, 0).1 - range(&band, 0).0;
        assert!(n >= 5, "{size:?}: {n} bars");
        assert!(
            span / (n as f64) < 0.09,
            "{size:?}: bars {:.3} apart",
            span / n as f64
        );
        assert!(!of(&s, Role::Handle).is_empty(), "{size:?}: no latch");
    }
    assert_eq!(archetype_of("stair gate"), "baby_gate");
}

#[test]
fn a_step_stool_has_a_low_front_tread_and_a_high_back_one() {
    for size in sized("step stool", [1.2, 1.2, 1.3]) {
        let s = at("step stool", size);
        let h = size[2];
        let treads = of(&s, Role::Top);
        let low = within(&treads, |p| p[2] < 0.7 * h);
        let high = within(&treads, |p| p[2] > 0.9 * h);
        assert!(!low.is_empty() && !high.is_empty(), "{size:?}: one tread");
        assert!(
            range(&low, 1).0 > range(&high, 1).0,
            "{size:?}: the low tread is not in front"
        );
        assert!(
            range(&low, 2).1 > 0.3 * h,
            "{size:?}: the low tread on the floor"
        );
    }
    assert_eq!(archetype_of("stepstool"), "step_stool");
}
