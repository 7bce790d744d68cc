//! Things that used to share another thing's shape each look like what was named, checked on
//! their surface samples at their knowledge-base size and a stretched one: an arcade cabinet
//! has a screen leaning back over a control panel that juts out with a joystick and buttons, art
//! on both sides and a lit marquee; a cash machine a small screen over a keypad and a card slot,
//! and no lit header; a brazier flames rising out of a fire bowl on splayed legs. Host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, sized, within};
use dreamscene::shape::Role;

#[test]
fn an_arcade_cabinet_leans_its_screen_back_over_a_jutting_control_panel() {
    for size in sized("arcade machine", [1.2, 1.1, 0.9]) {
        let s = drawn("arcade machine", size, 5);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let screen = of(&s, Role::Screen);
        let low = within(&screen, |p| p[2] < 0.66 * h);
        let high = within(&screen, |p| p[2] > 0.76 * h);
        let (y_low, y_high) = (range(&low, 1).1, range(&high, 1).1);
        assert!(y_low > y_high + 0.02, "{size:?}: screen not leaning back");
        let controls: Vec<[f64; 3]> = [Role::Handle, Role::Light]
            .iter()
            .flat_map(|r| of(&s, *r))
            .filter(|p| (0.45 * h..0.7 * h).contains(&p[2]))
            .collect();
        assert!(
            range(&controls, 1).0 > range(&screen, 1).1,
            "{size:?}: joystick and buttons not ahead of the screen"
        );
        let art = of(&s, Role::Canvas);
        let (x0, x1) = range(&art, 0);
        assert!(
            x0 < -0.9 * hw && x1 > 0.9 * hw,
            "{size:?}: no art on both sides"
        );
        let marquee = within(&of(&s, Role::Light), |p| p[2] > 0.8 * h);
        assert!(!marquee.is_empty(), "{size:?}: no lit marquee");
    }
}

#[test]
fn a_cash_machine_has_a_small_screen_a_keypad_and_a_card_slot_and_no_lit_header() {
    for size in sized("atm", [1.2, 1.1, 0.9]) {
        let s = drawn("atm", size, 5);
        let (w, h) = (size[0], size[2]);
        let screen = of(&s, Role::Screen);
        let (x0, x1) = range(&screen, 0);
        assert!(x1 - x0 < 0.5 * w, "{size:?}: screen {:.2} wide", x1 - x0);
        let keys = of(&s, Role::Keys);
        let pad = within(&keys, |p| p[2] < range(&screen, 2).0);
        assert!(pad.len() > 50, "{size:?}: no keypad under the screen");
        let lit = of(&s, Role::Light);
        assert!(!lit.is_empty(), "{size:?}: no card slot light");
        assert!(range(&lit, 2).1 < 0.8 * h, "{size:?}: a lit header");
        let slot = within(&of(&s, Role::Interior), |p| p[1] > 0.4 * size[1]);
        assert!(!slot.is_empty(), "{size:?}: no slots at the front");
    }
}

#[test]
fn a_brazier_is_fire_in_a_bowl_on_splayed_legs() {
    for size in sized("iron chandelier stand", [1.3, 1.3, 0.8]) {
        let s = drawn("iron chandelier stand", size, 5);
        let h = size[2];
        let flames = of(&s, Role::Light);
        let (z0, z1) = range(&flames, 2);
        assert!(
            z1 > 0.9 * h && z0 > 0.5 * h,
            "{size:?}: flames {z0:.2}..{z1:.2}"
        );
        let coals = of(&s, Role::Top);
        assert!(!coals.is_empty(), "{size:?}: no glowing coals");
        // Legs splay out to the floor: iron low down spans most of the width, the bowl's
        // foot above them does not.
        let iron = of(&s, Role::Metal);
        let feet = within(&iron, |p| p[2] < 0.05 * h);
        let (x0, x1) = range(&feet, 0);
        assert!(x1 - x0 > 0.7 * size[0], "{size:?}: feet {:.2}", x1 - x0);
        let waist = within(&all(&s), |p| (0.25 * h..0.4 * h).contains(&p[2]));
        let solid = within(&waist, |p| {
            p[0].abs() < 0.2 * size[0] && p[1].abs() < 0.2 * size[1]
        });
        assert!(solid.is_empty(), "{size:?}: a post, not legs");
    }
}

#[test]
fn a_food_cart_has_wheels_a_push_bar_and_an_umbrella() {
    for c in ["hot dog cart", "ice cream cart"] {
        for size in sized(c, [1.2, 1.1, 0.9]) {
            let s = drawn(c, size, 5);
            let h = size[2];
            let wheels = of(&s, Role::Tyre);
            assert!(!wheels.is_empty(), "{c} {size:?}: no wheels");
            assert!(
                range(&wheels, 2).0 < 0.01 * h,
                "{c} {size:?}: wheels off the ground"
            );
            let umbrella = of(&s, Role::Shade);
            let (x0, x1) = range(&umbrella, 0);
            assert!(
                range(&umbrella, 2).0 > 0.7 * h,
                "{c} {size:?}: umbrella low"
            );
            assert!(
                x1 - x0 > 0.8 * size[0],
                "{c} {size:?}: umbrella {:.2}",
                x1 - x0
            );
            // The push bar sticks out past the end of the body.
            let body = of(&s, Role::Body);
            let bar = of(&s, Role::Handle);
            assert!(
                range(&bar, 0).0 < range(&body, 0).0 - 0.05 * size[0],
                "{c} {size:?}: no push bar"
            );
        }
    }
}

#[test]
fn a_ticket_booth_is_a_closed_cabin_with_a_window_over_a_counter() {
    for size in sized("ticket booth", [1.2, 1.1, 0.9]) {
        let s = drawn("ticket booth", size, 5);
        let (d, h) = (size[1], size[2]);
        let window = of(&s, Role::Glass);
        assert!(!window.is_empty(), "{size:?}: no window");
        assert!(
            range(&window, 1).0 > 0.3 * d,
            "{size:?}: window not at the front"
        );
        let (z0, z1) = range(&window, 2);
        assert!(
            z0 > 0.3 * h && z1 < 0.8 * h,
            "{size:?}: window {z0:.2}..{z1:.2}"
        );
        // Walls all round: the back wall reaches up to the roof.
        let back = within(&of(&s, Role::Body), |p| p[1] < -0.4 * d);
        assert!(range(&back, 2).1 > 0.75 * h, "{size:?}: open at the back");
        assert!(of(&s, Role::Tyre).is_empty(), "{size:?}: wheels");
    }
}

#[test]
fn a_pergolas_climber_is_leaves_along_a_post_and_the_rafters_not_balls() {
    for size in sized("pergola structure", [1.3, 1.4, 1.0]) {
        let ps = dreamscene::shape::parts("pergola structure", size).unwrap();
        let leaves: Vec<_> = ps.iter().filter(|p| p.role == Role::Foliage).collect();
        assert!(leaves.len() > 40, "{size:?}: {} leaves", leaves.len());
        for p in &leaves {
            let pts = p.prim.hull_points();
            let ext = (0..3)
                .map(|a| range(&pts, a))
                .map(|(lo, hi)| hi - lo)
                .fold(0.0, f64::max);
            assert!(ext < 0.2, "{size:?}: a leaf {ext:.2} m across");
        }
        let s = drawn("pergola structure", size, 5);
        let green = of(&s, Role::Foliage);
        let (z0, z1) = range(&green, 2);
        assert!(
            z0 < 0.2 * size[2] && z1 > 0.9 * size[2],
            "{size:?}: leaves {z0:.2}..{z1:.2}"
        );
    }
}

#[test]
fn a_surgical_lights_heads_are_deep_domes_over_their_lit_faces() {
    for size in sized("surgical light", [1.2, 1.1, 1.2]) {
        let s = drawn("surgical light", size, 5);
        let shade = of(&s, Role::Shade);
        for side in [-1.0, 1.0] {
            let dome = within(&shade, |p| p[0] * side > 0.0);
            let (z0, z1) = range(&dome, 2);
            let (d0, d1) = range(&dome, 0);
            assert!(
                z1 - z0 > 0.25 * (d1 - d0),
                "{size:?}: a flat plate, not a dome"
            );
            // Highest at its middle, down to a rim round the lit face.
            let mid = 0.5 * (d0 + d1);
            let crown = within(&dome, |p| (p[0] - mid).abs() < 0.1 * (d1 - d0));
            let rim = within(&dome, |p| (p[0] - mid).abs() > 0.4 * (d1 - d0));
            assert!(
                range(&crown, 2).1 > range(&rim, 2).1 + 0.2 * (z1 - z0),
                "{size:?}: no crown"
            );
        }
    }
}
