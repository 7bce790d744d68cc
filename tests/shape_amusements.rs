//! Machines, figures and outdoor things that were drawn as another thing's shape, checked on
//! their parts at their knowledge-base size and a stretched one: a jukebox has a round arched
//! top edged with light tubes, a pinball machine a playfield sloping up to a tall backbox on
//! legs, a slot machine three reels and a lever, a popcorn machine popcorn behind glass on a
//! wheeled cart; a scarecrow is a dressed cross of poles bare below, a statue a figure of one
//! stone on a plinth; a pergola has open rafters, a mailbox a flag, a hot tub water in its rim,
//! a fire engine a ladder and lockers, a surgical light lamp heads hanging from the ceiling,
//! a windmill a stout tower under a cap.
//! Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, runs, sized, within, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{archetype_of, build, Role, ShapeOptions};
use dreamscene::splat::cloud::SH_C0;

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 5)
}

/// Width of `pts` along x between heights `z0` and `z1`.
fn width(pts: &[[f64; 3]], z0: f64, z1: f64) -> f64 {
    let band = within(pts, |p| p[2] >= z0 && p[2] <= z1);
    let (a, b) = range(&band, 0);
    b - a
}

#[test]
fn each_amusement_machine_has_an_archetype_of_its_own() {
    let names = [
        "jukebox",
        "pinball machine",
        "slot machine",
        "popcorn machine",
        "arcade machine",
    ];
    let arch: Vec<&str> = names.iter().map(|c| archetype_of(c)).collect();
    for (i, a) in arch.iter().enumerate() {
        assert!(!arch[i + 1..].contains(a), "{a} draws two of {names:?}");
        if names[i] != "arcade machine" {
            assert_ne!(*a, "appliance", "{} is the generic appliance", names[i]);
        }
    }
}

#[test]
fn a_jukebox_has_a_round_top_edged_with_light_tubes_and_a_record_in_its_window() {
    for name in ["jukebox", "juke box"] {
        for size in sized("jukebox", [1.2, 1.0, 1.1]) {
            let s = at(name, size);
            let body = of(&s, Role::Body);
            let h = size[2];
            // The top is an arch: narrow at its crown, full width at the shoulder.
            let shoulder = width(&body, 0.5 * h, 0.55 * h);
            let crown = width(&body, 0.985 * h, h);
            assert!(
                crown < 0.5 * shoulder,
                "{name} {size:?}: crown {crown:.2} of {shoulder:.2}"
            );
            // Light tubes on the front, up both sides and over the top.
            for role in [Role::Upholstery, Role::Light] {
                let tube = within(&of(&s, role), |p| p[1] > 0.3 * size[1]);
                assert!(
                    width(&tube, 0.0, 0.3 * h) > 0.8 * size[0] && range(&tube, 2).1 > 0.9 * h,
                    "{name} {size:?}: no {role:?} tube round its front"
                );
            }
            // A record behind the window, in the upper half.
            let record = of(&s, Role::BlackKeys);
            assert!(
                !record.is_empty() && range(&record, 2).0 > 0.45 * h,
                "{name}: no record"
            );
        }
    }
}

#[test]
fn a_pinball_machine_slopes_up_to_a_tall_backbox_on_four_legs() {
    for name in ["pinball machine", "pinball"] {
        for size in sized("pinball machine", [1.0, 1.2, 1.0]) {
            let s = at(name, size);
            let (d, h) = (size[1], size[2]);
            let field = of(&s, Role::Canvas);
            let near = within(&field, |p| p[1] > 0.2 * d);
            let far = within(&field, |p| p[1] < -0.1 * d);
            let mean = |v: &[[f64; 3]]| v.iter().map(|p| p[2]).sum::<f64>() / v.len() as f64;
            assert!(
                !near.is_empty() && mean(&far) > mean(&near) + 0.03,
                "{name} {size:?}: the playfield does not rise away from the player"
            );
            assert!(
                mean(&near) < 0.6 * h,
                "{name}: the playfield is not at table height"
            );
            // Everything above the playfield's height stands at the far end: the backbox.
            let high = within(&all(&s), |p| p[2] > 0.8 * h);
            assert!(
                range(&high, 1).1 < -0.25 * d,
                "{name} {size:?}: no backbox at the far end"
            );
            // Four legs: apart along x and along y under the cabinet.
            let legs = within(&of(&s, Role::Metal), |p| p[2] < 0.25 * h);
            assert!(
                runs(&legs, 0, 0.02) == 2 && runs(&legs, 1, 0.02) == 2,
                "{name} {size:?}: not four legs"
            );
        }
    }
}

#[test]
fn a_slot_machine_shows_three_reels_and_has_a_lever_at_its_side() {
    for name in ["slot machine", "slots"] {
        for size in sized("slot machine", [1.3, 1.0, 1.0]) {
            let s = at(name, size);
            let h = size[2];
            let reels = within(&of(&s, Role::Canvas), |p| p[1] > 0.2 * size[1]);
            assert_eq!(runs(&reels, 0, 0.01), 3, "{name} {size:?}: reels");
            assert!(range(&reels, 2).0 > 0.5 * h, "{name}: the reels are low");
            // The lever's knob out at the right, over the reels' foot, clear of the cabinet.
            let knob = of(&s, Role::Handle);
            let cabinet = of(&s, Role::Body);
            assert!(
                range(&knob, 0).0 > range(&cabinet, 0).1 && range(&knob, 2).0 > 0.6 * h,
                "{name} {size:?}: no lever at its side"
            );
        }
    }
}

#[test]
fn a_popcorn_machine_is_popcorn_behind_glass_on_a_wheeled_cart() {
    for name in ["popcorn machine", "popcorn cart"] {
        for size in sized("popcorn machine", [1.2, 1.2, 1.0]) {
            let s = at(name, size);
            let glass = of(&s, Role::Pane);
            let corn = of(&s, Role::Cushion);
            let (g0, g1) = range(&glass, 2);
            assert!(!corn.is_empty(), "{name}: no popcorn");
            let (c0, c1) = range(&corn, 2);
            assert!(
                c0 >= g0 - 0.01 && c1 < g1,
                "{name} {size:?}: popcorn outside the glass box"
            );
            // Inside the panes' footprint.
            assert!(
                range(&corn, 0).1 <= range(&glass, 0).1 && range(&corn, 1).1 <= range(&glass, 1).1,
                "{name} {size:?}: popcorn through the glass"
            );
            // The box stands on the cart, wheels at the cart's sides.
            assert!(g0 > 0.4 * size[2], "{name}: the glass box is low");
            let wheels = of(&s, Role::Tyre);
            assert_eq!(runs(&wheels, 0, 0.01), 2, "{name} {size:?}: wheels");
        }
    }
}

#[test]
fn a_scarecrow_is_a_dressed_cross_of_poles_bare_below_the_shirt() {
    for name in ["scarecrow", "scare crow"] {
        for size in sized("scarecrow", [1.2, 1.0, 1.1]) {
            let s = at(name, size);
            let h = size[2];
            // Below the shirt's hem, only the pole.
            let low = within(&all(&s), |p| p[2] < 0.3 * h);
            assert!(
                width(&low, 0.0, 0.3 * h) < 0.12,
                "{name} {size:?}: more than a pole below"
            );
            let dressed = s
                .iter()
                .filter(|(p, r)| p[2] < 0.3 * h && *r != Role::Trunk);
            assert_eq!(dressed.count(), 0, "{name} {size:?}: not a bare pole below");
            // Arms out along the crossbar nearly the full width, straw at the cuffs.
            let shirt = of(&s, Role::Duvet);
            assert!(
                width(&shirt, 0.65 * h, 0.85 * h) > 0.75 * size[0],
                "{name}: no sleeves"
            );
            let straw = of(&s, Role::Cushion);
            assert!(
                width(&straw, 0.65 * h, 0.85 * h) > 0.9 * size[0],
                "{name}: no straw at cuffs"
            );
            // A hat on top.
            assert!(range(&of(&s, Role::Top), 2).1 > 0.97 * h, "{name}: no hat");
        }
    }
    // "Straw" is the stuffing and the hat's stuff: the shirt keeps its cloth's colour.
    let size = KnowledgeBase::builtin().object("scarecrow").unwrap().size;
    let g = build(
        "scarecrow",
        size,
        "A DSLR photo of a straw scarecrow",
        &ShapeOptions::default(),
    )
    .unwrap();
    let reddish = (0..g.len())
        .filter(|&i| {
            let z = g.means[i][2] as f64;
            (0.5 * size[2]..0.6 * size[2]).contains(&z)
        })
        .map(|i| [0, 1, 2].map(|k| SH_C0 * g.sh[i * 3 + k] as f64 + 0.5))
        .filter(|c| c[0] > c[1] + 0.15)
        .count();
    assert!(
        reddish > 100,
        "a straw scarecrow's shirt is straw-coloured ({reddish})"
    );
}

#[test]
fn a_statue_is_a_figure_of_one_stone_on_a_plinth() {
    for name in ["statue", "sculpture"] {
        for size in sized("statue", [1.2, 1.0, 1.2]) {
            let s = at(name, size);
            let h = size[2];
            // One stone: no skin, no cloth; only the stone's two shades.
            assert!(
                s.iter().all(|(_, r)| matches!(r, Role::Body | Role::Top)),
                "{name}: parts not of stone"
            );
            // The plinth is full width at the foot; the figure narrower above it.
            let pts = all(&s);
            let foot = width(&pts, 0.0, 0.02 * h);
            assert!(foot > 0.95 * size[0], "{name} {size:?}: no plinth");
            assert!(
                width(&pts, 0.5 * h, 0.55 * h) < 0.7 * foot,
                "{name}: no figure on it"
            );
            // Something of the figure reaches the top: it stands on the plinth, not in it.
            assert!(range(&pts, 2).1 > 0.97 * h, "{name}: short figure");
        }
    }
}

/// Half-widths of the figure's left side (x < 0, away from a raised right arm) in slices from
/// the top down: the profile a head, a neck and shoulders make.
fn left_profile(pts: &[[f64; 3]], h: f64) -> Vec<f64> {
    (0..50)
        .map(|k| {
            let z1 = h - k as f64 * 0.01 * h;
            let band = within(pts, |p| p[0] <= 0.0 && p[2] > z1 - 0.01 * h && p[2] <= z1);
            band.iter().map(|p| -p[0]).fold(0.0, f64::max)
        })
        .collect()
}

#[test]
fn a_statues_head_stands_on_a_neck_between_square_shoulders_and_it_holds_up_a_torch() {
    for name in ["statue", "sculpture"] {
        for size in sized("statue", [1.2, 1.0, 1.2]) {
            let s = at(name, size);
            let prof = left_profile(&all(&s), size[2]);
            // From the top: the head, then a neck narrower than it, then shoulders (with the
            // arm hanging from them) over twice its width.
            let mut head: f64 = 0.0;
            let mut neck = None;
            let mut shoulders = false;
            for &w in &prof {
                match neck {
                    None if head > 0.0 && w < 0.75 * head => neck = Some(w),
                    None => head = head.max(w),
                    Some(_) if w > 2.0 * head => shoulders = true,
                    Some(_) => {}
                }
            }
            assert!(neck.is_some(), "{name} {size:?}: no neck under the head");
            assert!(shoulders, "{name} {size:?}: no shoulders ({prof:.2?})");
            // The raised hand holds a torch (in the lighter stone) above the head, to one side.
            let torch = within(&of(&s, Role::Top), |p| p[2] > 0.98 * size[2]);
            assert!(!torch.is_empty(), "{name} {size:?}: no torch held up");
            assert!(
                range(&torch, 0).0 > 0.0,
                "{name} {size:?}: torch over the head"
            );
        }
    }
}

#[test]
fn a_pergola_is_open_rafters_on_posts_with_no_roof() {
    for name in ["pergola structure", "pergola"] {
        for size in sized("pergola structure", [1.3, 1.6, 1.0]) {
            let s = at(name, size);
            let h = size[2];
            let rafters = within(&of(&s, Role::Frame), |p| p[2] > 0.95 * h);
            let n = runs(&rafters, 1, 0.02);
            assert!(n >= 6, "{name} {size:?}: {n} rafters");
            // Open: the rafters cover under a third of the footprint's depth.
            let cells = {
                let mut c: Vec<i64> = rafters
                    .iter()
                    .map(|p| (p[1] / 0.02).floor() as i64)
                    .collect();
                c.sort_unstable();
                c.dedup();
                c.len() as f64 * 0.02
            };
            assert!(
                cells < 0.33 * size[1],
                "{name} {size:?}: a roof ({cells:.2} m of {:.2})",
                size[1]
            );
            // Posts at the corners under it.
            let posts = within(&of(&s, Role::Frame), |p| p[2] < 0.5 * h);
            assert!(
                runs(&posts, 0, 0.02) == 2 && runs(&posts, 1, 0.02) >= 2,
                "{name} {size:?}: no posts at its corners"
            );
        }
    }
}

#[test]
fn a_mailbox_is_a_box_on_a_post_with_a_flag_at_its_side() {
    for name in ["mailbox", "letterbox"] {
        for size in sized("mailbox", [1.2, 1.3, 1.0]) {
            let s = at(name, size);
            let h = size[2];
            let boxed = of(&s, Role::Body);
            assert!(
                range(&boxed, 2).0 > 0.7 * h,
                "{name} {size:?}: the box is not on a post"
            );
            let post = within(&of(&s, Role::Frame), |p| p[2] < 0.5 * h);
            assert!(
                width(&post, 0.0, 0.5 * h) < 0.5 * size[0],
                "{name}: no post"
            );
            let flag = of(&s, Role::Handle);
            assert!(
                range(&flag, 0).0 > range(&boxed, 0).1 - 0.001 && range(&flag, 2).1 > 0.95 * h,
                "{name} {size:?}: no flag up at its side"
            );
        }
    }
}

#[test]
fn a_hot_tub_holds_water_just_under_its_rim() {
    for name in ["hot tub", "jacuzzi", "spa tub"] {
        for size in sized("hot tub", [1.3, 1.0, 1.2]) {
            let s = at(name, size);
            let h = size[2];
            let water = of(&s, Role::Water);
            assert!(!water.is_empty(), "{name}: no water");
            let (z0, _) = range(&water, 2);
            assert!(z0 > h - 0.15, "{name} {size:?}: the water is low");
            assert!(
                range(&water, 0).1 - range(&water, 0).0 > 0.6 * size[0],
                "{name} {size:?}: a puddle"
            );
            // Nothing solid over the water but its bubbles and headrests.
            let over = s.iter().filter(|(p, r)| {
                p[2] > z0 + 0.04
                    && !matches!(r, Role::Top | Role::Canvas | Role::Cushion)
                    && p[0].abs() < 0.3 * size[0]
                    && p[1].abs() < 0.2 * size[1]
            });
            assert_eq!(over.count(), 0, "{name} {size:?}: the water is covered");
        }
    }
}

#[test]
fn a_fire_engine_carries_a_ladder_over_lockers_on_both_sides() {
    for name in ["fire engine", "fire truck"] {
        for size in sized("fire engine", [1.0, 1.2, 1.0]) {
            let s = at(name, size);
            let h = size[2];
            let ladder = within(&of(&s, Role::Metal), |p| p[2] > 0.95 * h);
            assert!(
                range(&ladder, 1).1 - range(&ladder, 1).0 > 0.6 * size[1],
                "{name} {size:?}: no ladder along its roof"
            );
            let rungs = within(&ladder, |p| p[0].abs() < 0.05);
            assert!(
                runs(&rungs, 1, 0.05) >= 10,
                "{name} {size:?}: a ladder without rungs"
            );
            let lockers = of(&s, Role::Top);
            for sx in [-1.0, 1.0] {
                let side = within(&lockers, |p| sx * p[0] > 0.45 * size[0]);
                assert!(
                    runs(&side, 1, 0.02) >= 3,
                    "{name} {size:?}: no lockers on side {sx}"
                );
            }
        }
    }
}

#[test]
fn a_surgical_light_hangs_lamp_heads_down_from_the_ceiling() {
    for name in ["surgical light", "operating light", "surgical lamp"] {
        for size in sized("surgical light", [1.2, 1.0, 1.2]) {
            let s = at(name, size);
            let h = size[2];
            let heads = of(&s, Role::Shade);
            assert_eq!(runs(&heads, 0, 0.02), 2, "{name} {size:?}: lamp heads");
            assert!(
                range(&heads, 2).1 < 0.35 * h,
                "{name} {size:?}: the heads are high"
            );
            // The lit faces under the heads, and the mount at the top.
            let light = of(&s, Role::Light);
            assert!(
                range(&light, 2).1 <= range(&heads, 2).0 + 0.005,
                "{name}: light not under"
            );
            let mount = within(&of(&s, Role::Metal), |p| p[2] > 0.98 * h);
            assert!(!mount.is_empty(), "{name}: not hung from the ceiling");
        }
    }
}

#[test]
fn a_windmill_is_a_stout_tower_under_a_cap_with_sails_wider_than_it() {
    for name in ["windmill", "wind mill"] {
        for size in sized("windmill", [1.0, 1.0, 1.2]) {
            let s = at(name, size);
            let h = size[2];
            let tower = of(&s, Role::Body);
            let foot = width(&tower, 0.0, 0.1 * h);
            // Stout: its foot about half the sails' reach, not a post.
            assert!(
                foot > 0.35 * size[0],
                "{name} {size:?}: a post {foot:.2} wide"
            );
            let sails = of(&s, Role::Canvas);
            let reach = range(&sails, 0).1 - range(&sails, 0).0;
            assert!(
                reach > 1.5 * foot,
                "{name} {size:?}: sails {reach:.2} by a {foot:.2} tower"
            );
            // A cap over the tower, narrowing to its point.
            let cap = of(&s, Role::Top);
            assert!(
                width(&cap, 0.95 * range(&cap, 2).1, h)
                    < 0.5 * width(&cap, 0.0, range(&cap, 2).0 + 0.05),
                "{name} {size:?}: no conical cap"
            );
        }
    }
}

#[test]
fn a_rocking_horse_has_a_mane_down_its_neck() {
    for name in ["rocking horse", "hobby horse"] {
        for size in sized("rocking horse", [1.2, 1.0, 1.0]) {
            let s = at(name, size);
            let h = size[2];
            let mane = of(&s, Role::Cushion);
            assert!(!mane.is_empty(), "{name}: no mane");
            // Over the front half, high up between the back and the ears.
            let (x0, x1) = range(&mane, 0);
            assert!(
                x0 > 0.1 * size[0] && x1 < 0.5 * size[0],
                "{name} {size:?}: mane at {x0:.2}..{x1:.2}"
            );
            assert!(range(&mane, 2).0 > 0.6 * h, "{name} {size:?}: mane low");
        }
    }
}

#[test]
fn a_seated_statue_sits_with_its_knees_forward_and_a_standing_one_does_not() {
    use dreamscene::shape::{archetype_described, parts_described};
    for d in [
        "a seated statue",
        "a seated marble statue",
        "an enthroned statue",
    ] {
        assert_eq!(archetype_described("statue", d), "seated_statue", "{d}");
    }
    assert_eq!(archetype_described("statue", "a marble statue"), "statue");
    // Front reach of the figure at seat height (40–55% of the height) over the depth.
    let reach = |d: &str, size: [f64; 3]| {
        let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(3);
        let mut pts = vec![];
        for p in parts_described("statue", size, d).unwrap() {
            let mut s = vec![];
            p.prim.sample(0.004 * size[2], &mut rng, &mut s);
            pts.extend(s.iter().map(|s| s.pos));
        }
        let band = within(&pts, |p| p[2] > 0.4 * size[2] && p[2] < 0.55 * size[2]);
        range(&band, 1).1 / size[1]
    };
    for size in sized("statue", [1.2, 1.0, 1.2]) {
        let seated = reach("a seated statue", size);
        let standing = reach("a statue", size);
        assert!(
            seated > 0.25 && seated > standing + 0.08,
            "{size:?}: seated knees reach {seated:.2}, a standing figure {standing:.2}"
        );
    }
}
