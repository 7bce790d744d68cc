//! Drawings of things that were drawn as a neighbour: a desk lamp was a bedside lamp (a drum
//! shade on a bulb base) and is now a task lamp, a foot at the back, an arm up to an elbow and a
//! cone of a shade reaching forward and tipped down; a double vanity had one basin whatever its
//! width and now has two side by side on its long top. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{drawn, of, range, runs, sized};
use dreamscene::shape::{archetype_of, Role};

fn mean(pts: &[[f64; 3]], axis: usize) -> f64 {
    pts.iter().map(|p| p[axis]).sum::<f64>() / pts.len().max(1) as f64
}

#[test]
fn a_desk_lamp_reaches_forward_over_the_desk() {
    assert_ne!(archetype_of("task lamp"), archetype_of("table lamp"));
    for size in sized("task lamp", [1.3, 1.2, 1.2]) {
        let s = drawn("task lamp", size, 3);
        let (hd, h) = (size[1] / 2.0, size[2]);
        let shade = of(&s, Role::Shade);
        let metal = of(&s, Role::Metal);
        assert!(
            shade.len() > 50 && metal.len() > 50,
            "{size:?}: no shade or arm"
        );
        // the shade hangs forward of the middle, high up; the foot stands at the back
        assert!(
            mean(&shade, 1) > 0.25 * hd,
            "{size:?}: the shade is not forward"
        );
        assert!(
            range(&shade, 2).0 > 0.4 * h,
            "{size:?}: the shade is not raised"
        );
        let foot: Vec<_> = metal.iter().filter(|p| p[2] < 0.05).collect();
        assert!(!foot.is_empty(), "{size:?}: no foot");
        assert!(
            foot.iter().all(|p| p[1] < 0.0),
            "{size:?}: the foot is not at the back"
        );
        // the bulb glows in the shade's mouth, below the top of the shade
        let light = of(&s, Role::Light);
        assert!(!light.is_empty(), "{size:?}: no bulb");
        assert!(
            range(&light, 2).1 < range(&shade, 2).1,
            "{size:?}: bulb above the shade"
        );
    }
    // a table lamp's shade stays centred over its base
    let t = drawn("table lamp", [0.3, 0.3, 0.5], 3);
    assert!(mean(&of(&t, Role::Shade), 1).abs() < 0.02);
}

#[test]
fn a_double_vanity_has_two_basins_side_by_side() {
    for size in sized("double vanity", [1.2, 1.1, 1.0]) {
        let s = drawn("double vanity", size, 3);
        let basins = of(&s, Role::Canvas);
        assert_eq!(runs(&basins, 0, 0.04), 2, "{size:?}: not two basins");
        let (lo, hi) = range(&basins, 0);
        assert!(lo < -0.15 * size[0] && hi > 0.15 * size[0], "{size:?}");
    }
    for c in ["bathroom sink", "kitchen sink"] {
        let s = drawn(c, [0.9, 0.55, 0.88], 3);
        assert_eq!(
            runs(&of(&s, Role::Canvas), 0, 0.04),
            1,
            "{c}: not one basin"
        );
    }
}
