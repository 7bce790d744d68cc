//! Things that borrowed another thing's drawing, each drawn as what it is and checked on its
//! parts at its knowledge-base size and a stretched one: a bicycle repair stand has a tool tray
//! and rubber clamp jaws out in front at its top (not a microphone on a boom), a school desk a
//! metal frame and a book shelf under its top (no drawer pedestal), a potted palm long arching
//! fronds (not the round-leaf plant), a boxing ring ropes round a raised canvas (not a stage's
//! deck and steps), a chest freezer a lid with a handle and no straps (not a treasure chest).
//! Variants: a statue may stand at rest, arms down; the posters, paintings and statues of one
//! scene are drawn in turn in their archetype's variants. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
mod reading;
use common::samples::{all, drawn, of, range, sized, within, Samples};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_offline;
use dreamscene::shape::{
    archetype_described, archetype_of, build, parts_variant, variants, Role, ShapeOptions,
};
use rand::SeedableRng;
use reading::{keys, number, plan};

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 5)
}

#[test]
fn a_repair_stand_clamps_with_rubber_jaws_out_front_over_a_tool_tray() {
    for name in ["repair stand", "bike repair stand", "bicycle work stand"] {
        assert_eq!(archetype_of(name), "repair_stand", "{name}");
        assert_ne!(archetype_of(name), archetype_of("microphone stand"));
    }
    for size in sized("repair stand", [1.3, 0.8, 1.2]) {
        let s = at("repair stand", size);
        let h = size[2];
        // Rubber jaws at the very top, ahead of the post, with a gap between them.
        let jaws = within(&of(&s, Role::Tyre), |p| p[2] > 0.8 * h);
        assert!(jaws.len() > 50, "{size:?}: no clamp jaws at the top");
        let (y0, _) = range(&jaws, 1);
        assert!(y0 > 0.05, "{size:?}: the jaws are not out in front");
        let mid = jaws.iter().map(|p| p[1]).sum::<f64>() / jaws.len() as f64;
        let gap = within(&jaws, |p| (p[1] - mid).abs() < 0.01);
        assert!(
            gap.len() < jaws.len() / 20,
            "{size:?}: no gap between the jaws"
        );
        // A tool tray at hand height, wider than the post by far.
        let tray = of(&s, Role::Top);
        let (x0, x1) = range(&tray, 0);
        let (z0, z1) = range(&tray, 2);
        assert!(x1 - x0 > 0.2, "{size:?}: tray {:.2} wide", x1 - x0);
        assert!(
            z0 > 0.35 * h && z1 < 0.65 * h,
            "{size:?}: tray at {z0:.2}..{z1:.2}"
        );
    }
}

#[test]
fn a_school_desk_is_a_small_top_on_a_metal_frame_with_a_shelf_and_no_drawers() {
    for name in ["school desk", "student desk", "classroom desk"] {
        assert_eq!(archetype_of(name), "school_desk", "{name}");
    }
    for size in sized("school desk", [1.4, 1.2, 1.0]) {
        let s = at("school desk", size);
        let (w, h) = (size[0], size[2]);
        assert!(of(&s, Role::Door).is_empty(), "{size:?}: drawer fronts");
        // Below the shelf there is nothing but the metal frame.
        let low = within(&all(&s), |p| p[2] < 0.5 * h);
        let metal = within(&of(&s, Role::Metal), |p| p[2] < 0.5 * h);
        assert_eq!(low.len(), metal.len(), "{size:?}: not a metal frame below");
        // The shelf under the top spans most of the width.
        let shelf = within(&of(&s, Role::Body), |p| p[2] > 0.6 * h && p[2] < h);
        let (x0, x1) = range(&shelf, 0);
        assert!(
            x1 - x0 > 0.7 * w,
            "{size:?}: shelf {:.2} of {w:.2}",
            x1 - x0
        );
    }
}

#[test]
fn a_potted_palm_has_long_arching_fronds_not_round_leaves() {
    assert_eq!(archetype_of("potted palm"), "potted_palm");
    assert_eq!(archetype_of("kentia palm"), "potted_palm");
    for size in sized("potted palm", [1.3, 1.0, 1.25]) {
        let s = at("potted palm", size);
        let (hw, h) = (size[0].min(size[1]) / 2.0, size[2]);
        let leaves = of(&s, Role::Foliage);
        // Fronds reach out to the box's edge all round...
        let far = within(&leaves, |p| p[0].hypot(p[1]) > 0.6 * hw);
        assert!(
            far.len() > leaves.len() / 5,
            "{size:?}: fronds do not reach out"
        );
        // ... and droop: the leaflets at the fronds' tips hang lower than the crown's top.
        let top = range(&leaves, 2).1;
        let tips = within(&leaves, |p| p[0].hypot(p[1]) > 0.85 * hw);
        let tips_z = tips.iter().map(|p| p[2]).sum::<f64>() / tips.len() as f64;
        assert!(tips_z < top - 0.08 * h, "{size:?}: fronds do not arch down");
        // Thin leaflets, not leaf blobs: foliage samples fill little of the crown's volume.
        let core = within(&leaves, |p| p[0].hypot(p[1]) < 0.3 * hw);
        assert!(core.len() < leaves.len() / 3, "{size:?}: a solid crown");
        assert!(!of(&s, Role::Pot).is_empty(), "{size:?}: no pot");
    }
}

#[test]
fn a_potted_palm_is_planned_as_one_in_place_of_the_default_plant() {
    for (prompt, n) in [
        ("a living room with a potted palm in the corner", 1),
        ("a hotel lobby with two potted palms by the door", 2),
        ("an office with a kentia palm next to the desk", 1),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "potted palm"), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "potted plant"), 0, "{prompt}: {:?}", keys(&s));
    }
    // A named potted plant beside it stays.
    let s = plan("a living room with a potted plant and a potted palm");
    assert_eq!(number(&s, "potted plant"), 1, "{:?}", keys(&s));
}

#[test]
fn a_boxing_ring_is_a_raised_canvas_inside_ropes_on_corner_posts() {
    assert_eq!(archetype_of("boxing ring"), "boxing_ring");
    for size in sized("boxing ring", [1.2, 0.8, 1.25]) {
        let s = at("boxing ring", size);
        let (hw, hd, h) = (size[0] / 2.0, size[1] / 2.0, size[2]);
        let canvas = of(&s, Role::Canvas);
        let zc = range(&canvas, 2).1;
        assert!(zc > 0.25 * h && zc < 0.5 * h, "{size:?}: canvas at {zc:.2}");
        let ropes = of(&s, Role::Frame);
        // Three rope heights above the canvas, along each of the four sides.
        for (axis, edge) in [(1, hd), (0, hw)] {
            for sign in [-1.0, 1.0] {
                let side = within(&ropes, |p| (sign * p[axis] - edge).abs() < 0.5);
                let mut zs: Vec<i64> = side.iter().map(|p| (p[2] / 0.1).round() as i64).collect();
                zs.sort_unstable();
                zs.dedup();
                assert!(zs.len() >= 3, "{size:?}: ropes at {zs:?} on a side");
                assert!(range(&side, 2).0 > zc, "{size:?}: a rope below the canvas");
            }
        }
        // Corner posts rise to the top.
        let posts = within(&of(&s, Role::Metal), |p| p[2] > 0.95 * h);
        let corners: Vec<(bool, bool)> = posts.iter().map(|p| (p[0] > 0.0, p[1] > 0.0)).collect();
        for c in [(false, false), (false, true), (true, false), (true, true)] {
            assert!(corners.contains(&c), "{size:?}: no post at {c:?}");
        }
    }
}

#[test]
fn a_chest_freezer_has_a_lid_with_a_handle_and_no_straps() {
    assert_eq!(archetype_of("chest freezer"), "chest_freezer");
    for size in sized("chest freezer", [1.3, 1.0, 1.1]) {
        let s = at("chest freezer", size);
        let (hd, h) = (size[1] / 2.0, size[2]);
        // No metal strap crosses the lid from front to back.
        let lid_metal = within(&of(&s, Role::Metal), |p| p[2] > h - 0.01);
        assert!(lid_metal.is_empty(), "{size:?}: straps over the lid");
        let handle = of(&s, Role::Handle);
        assert!(!handle.is_empty(), "{size:?}: no lid handle");
        assert!(range(&handle, 1).1 > hd - 0.01 && range(&handle, 2).0 > 0.8 * h);
        let lights = of(&s, Role::Light);
        assert!(
            !lights.is_empty() && range(&lights, 2).1 < 0.5 * h,
            "{size:?}: no controls low"
        );
    }
}

#[test]
fn a_statue_may_stand_at_rest_with_both_arms_down() {
    assert_eq!(
        archetype_described("statue", "a standing statue"),
        "standing_statue"
    );
    assert_eq!(archetype_described("statue", "a marble statue"), "statue");
    for size in sized("statue", [1.5, 1.5, 0.8]) {
        let h = size[2];
        let raised = at("statue", size);
        let mut rest = vec![];
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        for p in parts_variant("statue", size, 1).unwrap() {
            let mut v = vec![];
            p.prim.sample(0.004 * h, &mut rng, &mut v);
            rest.extend(v.iter().map(|q| (q.pos, p.role)));
        }
        // The raised arm holds a torch over the head's side; at rest nothing high is off the
        // head.
        let hw = size[0] / 2.0;
        let off_head =
            |s: &Samples| within(&all(s), |p| p[2] > 0.9 * h && p[0].abs() > 0.3 * hw).len();
        assert!(off_head(&raised) > 20, "{size:?}: no raised arm");
        assert_eq!(off_head(&rest), 0, "{size:?}: an arm still raised");
        // At rest the figure is as wide on both sides.
        let body = of(&rest, Role::Body);
        let upper = within(&body, |p| p[2] > 0.6 * h);
        let (x0, x1) = range(&upper, 0);
        assert!(
            (x0 + x1).abs() < 0.02 * size[0],
            "{size:?}: lopsided {x0:.2}..{x1:.2}"
        );
    }
}

/// The mean colour (DC term) of a category's drawing in `variant`.
fn print_colour(category: &str, size: [f64; 3], variant: u32) -> [f32; 3] {
    let g = build(
        category,
        size,
        "",
        &ShapeOptions {
            gaussians: Some(20_000),
            seed: 1,
            variant,
            mount: None,
        },
    )
    .unwrap();
    let stride = g.sh.len() / g.len();
    let mut sum = [0f32; 3];
    for c in g.sh.chunks(stride) {
        for k in 0..3 {
            sum[k] += c[k];
        }
    }
    sum.map(|v| v / g.len() as f32)
}

#[test]
fn posters_and_paintings_come_in_prints_of_their_own() {
    let (rows, bad) = variants::rows();
    assert!(bad.is_empty(), "{bad:?}");
    for (a, n) in &rows {
        assert!(
            dreamscene::shape::archetype_names().contains(&a.as_str()),
            "{a}"
        );
        assert!(*n >= 2, "{a}: {n}");
    }
    for category in ["poster", "painting"] {
        let size = dreamscene::plan::kb::KnowledgeBase::builtin()
            .object(category)
            .unwrap()
            .size;
        let n = variants::count(archetype_of(category));
        let prints: Vec<[f32; 3]> = (0..n).map(|v| print_colour(category, size, v)).collect();
        for i in 0..prints.len() {
            for j in 0..i {
                let d: f32 = (0..3).map(|k| (prints[i][k] - prints[j][k]).abs()).sum();
                assert!(
                    d > 0.05,
                    "{category}: variants {i} and {j} print alike ({d:.3})"
                );
            }
        }
        // Variant 0 is the usual drawing, and the count wraps round.
        assert_eq!(
            print_colour(category, size, 0),
            print_colour(category, size, n)
        );
    }
}

#[test]
fn the_posters_of_one_scene_take_the_variants_in_turn() {
    for (prompt, category, n) in [
        (
            "a teenager's bedroom with four posters on the wall",
            "poster",
            4,
        ),
        ("an art gallery with six paintings", "painting", 6),
        ("a sculpture garden with three statues", "statue", 3),
    ] {
        let spec = plan_offline(prompt);
        let l = layout(&spec, LayoutOptions::seeded(0)).unwrap();
        let prior = dreamscene::scene::dir::Prior {
            kind: "shape".into(),
            models: None,
        };
        let scene = dreamscene::generate::scene::scene_file(prompt, 0, &spec, &l, prior);
        let v = dreamscene::generate::variants::instance_variants(&scene);
        let mine: Vec<u32> = scene
            .objects
            .iter()
            .zip(&v)
            .filter(|(o, _)| o.category == category)
            .map(|(_, v)| *v)
            .collect();
        assert_eq!(mine.len(), n, "{prompt}: {mine:?}");
        let count = variants::count(archetype_of(category));
        let want: Vec<u32> = (0..n as u32).map(|k| k % count).collect();
        assert_eq!(mine, want, "{prompt}");
        // Everything else is drawn once, as before.
        assert!(scene
            .objects
            .iter()
            .zip(&v)
            .all(|(o, v)| *v == 0 || variants::count(archetype_of(&o.category)) > 1));
    }
}

#[test]
fn a_dartboard_is_a_round_ringed_board_not_a_whiteboard() {
    assert_eq!(archetype_of("dartboard"), "dartboard");
    for size in sized("dartboard", [1.2, 1.0, 0.8]) {
        let s = at("dartboard", size);
        let h = size[2];
        // Its rings: red and green rings round a black board, one above the other in front.
        let red = of(&s, Role::Handle);
        let green = of(&s, Role::Top);
        assert!(!red.is_empty() && !green.is_empty(), "{size:?}: no rings");
        let board = of(&s, Role::Body);
        let (x0, x1) = range(&board, 0);
        let (z0, z1) = range(&board, 2);
        assert!(
            ((x1 - x0) / (z1 - z0) - 1.0).abs() < 0.1,
            "{size:?}: not round"
        );
        assert!(z0 > 0.4 * h, "{size:?}: board low at {z0:.2}");
        assert!(
            range(&red, 1).1 > range(&of(&s, Role::Frame), 1).1,
            "{size:?}: rings behind"
        );
        assert!(
            of(&s, Role::Canvas).len() > 20,
            "{size:?}: no pale segments"
        );
    }
}

#[test]
fn stepping_stones_are_separate_stones_along_the_path() {
    assert_eq!(archetype_of("stepping stones"), "stepping_stones");
    for size in sized("stepping stones", [1.5, 0.6, 2.0]) {
        let s = at("stepping stones", size);
        let stones = of(&s, Role::Stone);
        assert_eq!(
            stones.len(),
            s.len(),
            "{size:?}: something else than stones"
        );
        let n = common::samples::runs(&stones, 1, 0.02);
        assert!(n >= 3, "{size:?}: {n} stones");
    }
}

#[test]
fn a_cooler_has_a_lid_under_a_swing_handle_and_no_straps() {
    assert_eq!(archetype_of("cooler"), "cooler");
    assert_eq!(archetype_of("ice chest"), "cooler");
    for size in sized("cooler", [1.4, 1.2, 1.0]) {
        let s = at("cooler", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        assert!(of(&s, Role::Metal).is_empty(), "{size:?}: metal straps");
        let lid = of(&s, Role::Top);
        assert!(range(&lid, 2).0 > 0.55 * h, "{size:?}: lid low");
        // A swing handle from end to end, arching over the lid.
        let handles = of(&s, Role::Handle);
        let (x0, x1) = range(&handles, 0);
        assert!(
            x0 < -0.9 * hw && x1 > 0.9 * hw,
            "{size:?}: no handle at each end"
        );
        let grip = within(&handles, |p| p[2] > range(&lid, 2).1 + 0.02);
        let (g0, g1) = range(&grip, 0);
        assert!(g1 - g0 > 1.5 * hw, "{size:?}: no grip over the lid");
    }
}

#[test]
fn a_standing_desk_stands_on_two_columns_with_no_drawers() {
    assert_eq!(archetype_of("standing desk"), "standing_desk");
    for size in sized("standing desk", [1.2, 1.0, 0.7]) {
        let s = at("standing desk", size);
        let (w, h) = (size[0], size[2]);
        assert!(of(&s, Role::Door).is_empty(), "{size:?}: drawers");
        // Halfway up only the two columns stand, one near each end.
        let waist = within(&all(&s), |p| (0.3 * h..0.6 * h).contains(&p[2]));
        let n = common::samples::runs(&waist, 0, 0.02);
        assert_eq!(n, 2, "{size:?}: {n} things standing at mid height");
        let (x0, x1) = range(&waist, 0);
        assert!(x1 - x0 > 0.6 * w, "{size:?}: columns not at the ends");
    }
}

#[test]
fn a_beach_towel_is_striped_and_a_picnic_blanket_checked_not_a_bordered_rug() {
    for (name, arch) in [
        ("beach towel", "striped_towel"),
        ("picnic blanket", "checked_blanket"),
        ("play mat", "tiled_mat"),
    ] {
        assert_eq!(archetype_of(name), arch, "{name}");
        assert_ne!(archetype_of(name), archetype_of("rug"), "{name}");
    }
    for size in sized("beach towel", [1.3, 0.8, 1.0]) {
        let s = at("beach towel", size);
        // Stripes across the length: the main colour comes back again and again along y.
        let n = common::samples::runs(&of(&s, Role::Body), 1, 0.02);
        assert!(n >= 3, "{size:?}: {n} stripes of its colour");
        assert_eq!(common::samples::runs(&of(&s, Role::Body), 0, 0.02), 1);
    }
    for size in sized("picnic blanket", [1.3, 0.8, 1.0]) {
        let s = at("picnic blanket", size);
        // A check: its colour's squares repeat along both sides.
        let body = of(&s, Role::Body);
        for axis in [0, 1] {
            let n = common::samples::runs(&body, axis, 0.02);
            assert!(n >= 3, "{size:?}: {n} squares along axis {axis}");
        }
        assert!(
            !of(&s, Role::Canvas).is_empty(),
            "{size:?}: no white squares"
        );
    }
    for size in sized("play mat", [1.3, 0.8, 1.0]) {
        let s = at("play mat", size);
        let tiles = of(&s, Role::Books);
        assert_eq!(tiles.len(), s.len(), "{size:?}: something else than tiles");
        assert!(
            common::samples::runs(&tiles, 0, 0.004) >= 3,
            "{size:?}: one tile"
        );
    }
}

#[test]
fn a_paper_lantern_is_a_round_ribbed_globe_not_a_lamp_with_a_shade() {
    assert_eq!(archetype_of("paper lantern"), "paper_lantern");
    for size in sized("paper lantern", [1.2, 1.2, 1.3]) {
        let s = at("paper lantern", size);
        let (w, h) = (size[0].min(size[1]), size[2]);
        let globe = of(&s, Role::Shade);
        let (x0, x1) = range(&globe, 0);
        let (z0, z1) = range(&globe, 2);
        assert!(
            x1 - x0 > 0.8 * w.min(0.9 * h),
            "{size:?}: globe {:.2} wide",
            x1 - x0
        );
        assert!(
            ((x1 - x0) / (z1 - z0) - 1.0).abs() < 0.15,
            "{size:?}: not round"
        );
        // hung from the ceiling (its placement class), at the foot of its box below its cord
        assert!(
            z0 < 0.05 * h,
            "{size:?}: the globe is not at the foot of its cord"
        );
        let _ = z1;
        let ribs = of(&s, Role::Metal);
        assert!(
            common::samples::runs(&ribs, 2, 0.004) >= 5,
            "{size:?}: no ribs"
        );
    }
}
