//! A newsstand, a tiki bar and a street lamp drawn as what they are (once a market stall, a
//! market stall and a stone garden lantern), checked on their parts at their knowledge-base size
//! and a stretched one: a newsstand shows magazines standing face-out on its front under a roof
//! and a door and a poster on its back,
//! a tiki bar a thatch over its whole footprint and stools in front of its counter, a street lamp
//! a lit head at the top of a slender post. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, sized, within};
use dreamscene::shape::{archetype_of, Role};

#[test]
fn none_of_these_is_a_market_stall_or_a_garden_lantern() {
    for (c, not) in [
        ("newspaper stand", "stall"),
        ("tiki bar", "stall"),
        ("street lamp", "lantern"),
    ] {
        assert_ne!(archetype_of(c), not, "{c}");
    }
}

#[test]
fn a_newsstand_shows_magazines_face_out_on_its_front_under_a_roof() {
    for size in sized("newspaper stand", [1.3, 0.8, 1.1]) {
        let s = drawn("newspaper stand", size, 3);
        let mags = of(&s, Role::Books);
        assert!(!mags.is_empty(), "{size:?}: no magazines");
        // Standing up in rows on the front wall, not lying on a counter.
        let (z0, z1) = range(&mags, 2);
        assert!(
            z1 - z0 > 0.15 * size[2],
            "{size:?}: magazines {z0:.2}..{z1:.2}"
        );
        assert!(
            range(&mags, 1).0 > 0.0,
            "{size:?}: magazines behind the middle"
        );
        // A roof over the whole kiosk at the top.
        let roof = within(&of(&s, Role::Top), |p| p[2] > 0.85 * size[2]);
        let (y0, y1) = range(&roof, 1);
        assert!(y1 - y0 > 0.9 * size[1], "{size:?}: roof {y0:.2}..{y1:.2}");
    }
}

#[test]
fn a_newsstands_back_shows_a_door_and_a_poster_not_a_blank_wall() {
    for size in sized("newspaper stand", [1.3, 0.8, 1.1]) {
        let s = drawn("newspaper stand", size, 3);
        // Under the roof, within a few centimetres of the back face.
        let near = |r: Role| {
            within(&of(&s, r), |p| {
                p[1] < -size[1] / 2.0 + 0.02 && p[2] < 0.8 * size[2]
            })
            .len()
        };
        let shown: Vec<Role> = [Role::Top, Role::Frame, Role::Cushion, Role::Canvas]
            .into_iter()
            .filter(|r| near(*r) > 20)
            .collect();
        assert_eq!(shown.len(), 4, "{size:?}: the back shows only {shown:?}");
    }
}

#[test]
fn a_tiki_bar_has_a_thatch_over_all_of_it_and_stools_at_its_counter() {
    for size in sized("tiki bar", [1.4, 1.2, 1.0]) {
        let s = drawn("tiki bar", size, 3);
        let thatch = of(&s, Role::Shade);
        let (x0, x1) = range(&thatch, 0);
        assert!(x1 - x0 > 0.9 * size[0], "{size:?}: thatch {x0:.2}..{x1:.2}");
        assert!(range(&thatch, 2).1 > 0.95 * size[2], "{size:?}: no peak");
        let stools = of(&s, Role::Seat);
        assert!(!stools.is_empty(), "{size:?}: no stools");
        let counter = of(&s, Role::Top);
        let front = range(&within(&counter, |p| p[2] < 0.5 * size[2]), 1).1;
        assert!(
            range(&stools, 1).0 > front,
            "{size:?}: stools not in front of the counter"
        );
    }
}

#[test]
fn a_street_lamp_is_a_lit_head_on_a_slender_post() {
    for size in sized("street lamp", [1.5, 1.5, 1.2]) {
        let s = drawn("street lamp", size, 3);
        let light = of(&s, Role::Light);
        assert!(
            range(&light, 2).0 > 0.75 * size[2],
            "{size:?}: light too low"
        );
        // Between the base and the head only the post: narrow.
        let post = within(&all(&s), |p| p[2] > 0.2 * size[2] && p[2] < 0.65 * size[2]);
        let (x0, x1) = range(&post, 0);
        assert!(
            x1 - x0 < 0.35 * size[0],
            "{size:?}: post {:.2} wide",
            x1 - x0
        );
    }
}
