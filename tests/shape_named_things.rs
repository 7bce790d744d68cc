//! Drawings of things that were drawn as a near thing of another look or as a plain box, each
//! checked on its parts at its knowledge-base size and a stretched one: a sectional is an L seen
//! from above (a chaise forward at one end, the other front corner open); a pulpit is a box
//! raised on a pedestal with steps up to it; a hanging scroll has rollers at its top and foot
//! and no frame down its sides; string lights are a row of bulbs across the width; a squat rack
//! is a cage with a bar across it at shoulder height; a play kitchen is child high with a hob;
//! a dragon has its head raised at the front and wings; a hoard of gold is a low heap of coins.
//! Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, runs, sized, within, Samples};
use dreamscene::shape::Role;

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 7)
}

#[test]
fn a_sectional_is_an_l_seen_from_above() {
    for size in sized("sectional sofa", [1.2, 1.1, 1.0]) {
        let s = all(&at("sectional sofa", size));
        let (hw, hd) = (size[0] / 2.0, size[1] / 2.0);
        let front = |left: bool| {
            within(&s, |p| {
                p[1] > 0.6 * hd && p[2] > 0.2 && (p[0] < -0.5 * hw) == left && p[0].abs() > 0.5 * hw
            })
            .len()
        };
        assert_eq!(front(true), 0, "{size:?}: the left front corner is seated");
        assert!(front(false) > 50, "{size:?}: no chaise at the right front");
    }
}

#[test]
fn a_pulpit_is_a_raised_box_with_steps() {
    for size in sized("pulpit", [1.2, 1.0, 1.1]) {
        let s = at("pulpit", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        // The box's parapet reaches head height of a person standing on its raised floor.
        let body = of(&s, Role::Body);
        assert!(range(&body, 2).1 > 0.9 * h, "{size:?}: low parapet");
        // Treads at several heights on the left, climbing to the right.
        let x0 = hw - size[1].min(0.55 * size[0]);
        let treads = within(&of(&s, Role::Top), |p| p[0] < x0 - 0.02);
        assert!(
            runs(&treads, 2, 0.05) >= 3,
            "{size:?}: {} treads",
            runs(&treads, 2, 0.05)
        );
    }
}

#[test]
fn a_hanging_scroll_has_rollers_and_no_side_frame() {
    for size in sized("hanging scroll", [1.0, 1.0, 1.2]) {
        let s = at("hanging scroll", size);
        let h = size[2];
        let frame = of(&s, Role::Frame);
        assert!(!frame.is_empty());
        assert!(
            frame.iter().all(|p| p[2] < 0.1 * h || p[2] > 0.8 * h),
            "{size:?}: a frame down the sides"
        );
        assert!(!of(&s, Role::Canvas).is_empty() && !of(&s, Role::Interior).is_empty());
        // The foot roller's knobs stand out past the silk.
        let silk = range(&of(&s, Role::Body), 0);
        let knobs = range(&of(&s, Role::Handle), 0);
        assert!(knobs.1 > silk.1 + 0.02, "{size:?}: no roller ends");
    }
}

#[test]
fn string_lights_are_a_row_of_bulbs_across_the_width() {
    for size in sized("string lights", [1.5, 1.0, 1.0]) {
        let bulbs = of(&at("string lights", size), Role::Light);
        let (lo, hi) = range(&bulbs, 0);
        assert!(hi - lo > 0.9 * size[0], "{size:?}: bulbs over {}", hi - lo);
        assert!(
            runs(&bulbs, 0, 0.02) >= 10,
            "{size:?}: {} bulbs",
            runs(&bulbs, 0, 0.02)
        );
    }
}

#[test]
fn a_squat_rack_is_a_cage_holding_a_bar_at_shoulder_height() {
    for size in sized("squat rack", [1.0, 1.2, 1.0]) {
        let s = at("squat rack", size);
        let h = size[2];
        let frame = of(&s, Role::Frame);
        assert!(range(&frame, 2).1 > 0.97 * h, "{size:?}: low uprights");
        let bar = within(&of(&s, Role::Handle), |p| p[2] > 0.4 * h && p[2] < 0.75 * h);
        let (lo, hi) = range(&bar, 0);
        assert!(hi - lo > 0.9 * size[0], "{size:?}: no bar across");
    }
}

#[test]
fn a_play_kitchen_is_child_high_with_a_hob_and_an_oven_door() {
    let size = sized("play kitchen", [1.0, 1.0, 1.0])[0];
    assert!(size[2] < 1.1);
    let s = at("play kitchen", size);
    let hob = of(&s, Role::BlackKeys);
    assert!(!hob.is_empty() && range(&hob, 2).0 > 0.4 * size[2]);
    assert!(!of(&s, Role::Screen).is_empty(), "no oven window");
    assert!(!of(&s, Role::Door).is_empty());
}

#[test]
fn a_dragon_lies_long_with_its_head_raised_and_wings() {
    for size in sized("dragon", [1.0, 1.2, 1.0]) {
        let s = at("dragon", size);
        let (hd, h) = (size[1] / 2.0, size[2]);
        assert!(size[1] > 1.5 * size[0]);
        let head = within(&all(&s), |p| p[1] > 0.6 * hd);
        assert!(range(&head, 2).1 > 0.6 * h, "{size:?}: the head is down");
        assert!(of(&s, Role::Canvas).len() > 100, "{size:?}: no wings");
        // The belly rests on the ground.
        assert!(range(&of(&s, Role::Body), 2).0 < 0.02);
    }
}

#[test]
fn a_hoard_of_gold_is_a_low_heap_of_coins() {
    for size in sized("treasure hoard", [1.3, 1.0, 1.0]) {
        let s = at("treasure hoard", size);
        let heap = of(&s, Role::Metal);
        assert!(range(&heap, 2).1 < 0.8 * size[2]);
        let (lo, hi) = range(&heap, 0);
        assert!(hi - lo > 0.75 * size[0]);
        let coins = of(&s, Role::Handle);
        let (lo, hi) = range(&coins, 0);
        assert!(hi - lo > 0.7 * size[0], "{size:?}: few coins");
    }
}
