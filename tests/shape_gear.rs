//! Racks, tubes, sound gear and appliances drawn as what they are named, checked on their parts
//! at their knowledge-base size and two other sizes a plan may give: a canoe rack's boats are
//! longer than its frame is deep, a speaker shows round cones on its front, a server rack is
//! tall, dark and lit, a dryer's dark door sits higher than a washer's and it vents at the back,
//! a dishwasher and a microwave are no blank boxes from behind, coat hooks hold coats, and
//! categories once drawn as a plain tube have parts of their own, a bucket is an open pail
//! under its bail, and a headset carries a boom microphone to the front where headphones have none. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{drawn, of, range, round, runs, sizes, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{archetype_of, build, parts, Role, ShapeOptions};
use dreamscene::splat::cloud::SH_C0;

/// Surface samples of `category` at `size`.
fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 5)
}

#[test]
fn a_canoe_rack_holds_boats_longer_than_its_frame_is_deep() {
    for name in ["canoe rack", "kayak rack"] {
        for size in sizes(name, [1.2, 0.8, 1.1]) {
            let s = at(name, size);
            let frame = of(&s, Role::Frame);
            let (y0, y1) = range(&frame, 1);
            for role in [Role::Body, Role::Upholstery] {
                let hull = of(&s, role);
                let (x0, x1) = range(&hull, 0);
                assert!(
                    x1 - x0 > 1.25 * (y1 - y0),
                    "{name} {size:?}: a {:.2} m boat on a frame {:.2} m deep",
                    x1 - x0,
                    y1 - y0
                );
                // Resting up on the arms, not on the floor.
                assert!(
                    range(&hull, 2).0 > 0.2 * size[2],
                    "{name}: a boat on the floor"
                );
            }
        }
    }
}

#[test]
fn a_speaker_shows_round_cones_on_its_front_and_an_amp_a_grille_under_knobs() {
    for name in ["speaker", "loudspeaker"] {
        for size in sizes(name, [1.2, 1.0, 0.8]) {
            let s = at(name, size);
            let cones: Vec<[f64; 3]> = of(&s, Role::Screen)
                .into_iter()
                .filter(|p| p[1] > 0.3 * size[1])
                .collect();
            let n = runs(&cones, 2, 0.01);
            assert!(
                n >= 3,
                "{name} {size:?}: {n} cones and tweeters on the front"
            );
            let lowest: Vec<[f64; 3]> = {
                let z0 = range(&cones, 2).0;
                let r = 0.5 * (range(&cones, 0).1 - range(&cones, 0).0);
                cones
                    .iter()
                    .filter(|p| p[2] < z0 + 2.05 * r)
                    .cloned()
                    .collect()
            };
            assert!(round(&lowest), "{name} {size:?}: the woofer is not round");
        }
    }
    for name in ["amplifier", "guitar amp"] {
        for size in sizes(name, [1.2, 1.0, 0.8]) {
            let s = at(name, size);
            let front = |p: &[f64; 3]| p[1] > 0.4 * size[1];
            let cloth: Vec<_> = of(&s, Role::Upholstery).into_iter().filter(front).collect();
            let (x0, x1) = range(&cloth, 0);
            assert!(
                x1 - x0 > 0.8 * size[0],
                "{name}: no grille across the front"
            );
            let knobs: Vec<_> = of(&s, Role::Handle).into_iter().filter(front).collect();
            assert!(runs(&knobs, 0, 0.005) >= 4, "{name}: no row of knobs");
            assert!(
                range(&knobs, 2).0 > range(&cloth, 2).1,
                "{name}: the knobs are not above the grille"
            );
        }
    }
}

/// Mean brightness of `category`'s Gaussians drawn at `size` with its description.
fn brightness(category: &str, size: [f64; 3]) -> f64 {
    let o = KnowledgeBase::builtin().object(category).unwrap();
    let g = build(category, size, &o.description, &ShapeOptions::default()).unwrap();
    let sum: f64 = (0..g.len() * 3).map(|i| 0.5 + SH_C0 * g.sh[i] as f64).sum();
    sum / (3 * g.len()) as f64
}

#[test]
fn a_server_rack_is_taller_than_wide_dark_and_lit_row_by_row() {
    for name in ["server rack", "server cabinet"] {
        for size in sizes(name, [1.2, 1.0, 0.9]) {
            let s = at(name, size);
            let (z0, z1) = range(&s.iter().map(|p| p.0).collect::<Vec<_>>(), 2);
            assert!(z1 - z0 > 1.5 * size[0], "{name}: not tall");
            let b = brightness(name, size);
            assert!(b < 0.25, "{name} {size:?}: mean brightness {b:.2}");
            let lights: Vec<_> = of(&s, Role::Light)
                .into_iter()
                .filter(|p| p[1] > 0.3 * size[1])
                .collect();
            let rows = runs(&lights, 2, 0.01);
            assert!(rows >= 10, "{name} {size:?}: {rows} rows of lights");
            // The front door is mesh: a pane over the units, not a solid slab.
            let pane = of(&s, Role::Pane)
                .into_iter()
                .filter(|p| p[1] > 0.4 * size[1])
                .count();
            assert!(pane > 100, "{name}: no mesh door");
        }
    }
}

/// Height of the centre of the round door on the front (its dark window) over the height.
fn window_height(s: &Samples, size: [f64; 3]) -> f64 {
    let glass: Vec<_> = of(s, Role::Screen)
        .into_iter()
        .filter(|p| p[1] > 0.4 * size[1] && p[2] < 0.8 * size[2])
        .collect();
    assert!(round(&glass), "no round window");
    let (z0, z1) = range(&glass, 2);
    0.5 * (z0 + z1) / size[2]
}

#[test]
fn a_dryer_has_its_door_higher_than_a_washer_and_a_vent_duct_at_the_back() {
    for name in ["dryer", "tumble dryer"] {
        for size in sizes(name, [1.0, 1.1, 1.15]) {
            let (dryer, washer) = (at(name, size), at("washing machine", size));
            let (d, w) = (window_height(&dryer, size), window_height(&washer, size));
            assert!(
                d > w + 0.05,
                "{name} {size:?}: door at {d:.2} of the height, a washer's at {w:.2}"
            );
            // Behind the body: the wide vent duct, and no cold and hot water hoses.
            let duct: Vec<_> = of(&dryer, Role::Handle)
                .into_iter()
                .filter(|p| p[1] < -0.5 * size[1] + 0.075)
                .collect();
            let (x0, x1) = range(&duct, 0);
            assert!(
                duct.len() > 50 && x1 - x0 > 0.15 * size[0],
                "{name}: no vent duct"
            );
            assert_ne!(archetype_of(name), archetype_of("washing machine"));
        }
    }
}

#[test]
fn a_dishwasher_and_a_microwave_show_their_backs() {
    for name in ["dishwasher", "microwave", "microwave oven"] {
        for size in sizes(name, [1.2, 1.0, 0.9]) {
            let s = at(name, size);
            // What lies in the back tenth of the depth and is not the carcass.
            let back = s
                .iter()
                .filter(|(p, r)| p[1] < -0.45 * size[1] && *r != Role::Body && *r != Role::Interior)
                .count();
            assert!(back > 30, "{name} {size:?}: a blank back ({back} samples)");
            let slots = s
                .iter()
                .filter(|(p, r)| p[1] < -0.4 * size[1] && p[2] > 0.15 * size[2] && *r != Role::Body)
                .map(|(p, _)| *p)
                .collect::<Vec<_>>();
            assert!(runs(&slots, 0, 0.004) >= 2, "{name}: nothing on its back");
        }
    }
}

#[test]
fn coat_hooks_hold_coats_and_a_pegboard_hangs_tools() {
    for name in ["coat hooks", "hook rack"] {
        for size in sizes(name, [1.5, 1.0, 1.1]) {
            let s = at(name, size);
            let rail = of(&s, Role::Top);
            let coats = of(&s, Role::Books);
            assert!(
                runs(&coats, 0, 0.01) >= 3,
                "{name} {size:?}: no coats side by side"
            );
            assert!(
                range(&coats, 2).0 < range(&rail, 2).0 - 0.3 * size[2],
                "{name}: the coats do not hang below the rail"
            );
        }
    }
    for name in ["pegboard", "tool wall"] {
        for size in sizes(name, [1.3, 1.0, 1.2]) {
            let s = at(name, size);
            let panel = range(&of(&s, Role::Top), 1).1;
            let tools: Vec<_> = of(&s, Role::Metal)
                .into_iter()
                .filter(|p| p[1] > panel)
                .collect();
            assert!(
                runs(&tools, 0, 0.01) >= 5,
                "{name} {size:?}: no tools on pegs"
            );
        }
    }
}

#[test]
fn things_once_drawn_as_a_plain_tube_have_parts_of_their_own() {
    let names = [
        "beer tap",
        "compressor",
        "sundial",
        "totem pole",
        "silo",
        "reactor core",
        "fishing rod",
        "oar",
        "laundry basket",
        "pet bowl",
        "water jug",
        "fruit bowl",
        "tree stump",
        "bollard",
    ];
    let kb = KnowledgeBase::builtin();
    for name in names {
        assert_ne!(archetype_of(name), "pail", "{name}");
        let size = kb.object(name).unwrap().size;
        let roles: std::collections::BTreeSet<String> = parts(name, size)
            .unwrap()
            .iter()
            .map(|p| format!("{:?}", p.role))
            .collect();
        assert!(roles.len() >= 3, "{name}: parts of {roles:?} only");
    }
    // A fruit bowl holds fruit above its rim; a silo wears a roof narrower than its drum.
    let size = kb.object("fruit bowl").unwrap().size;
    let s = at("fruit bowl", size);
    assert!(range(&of(&s, Role::Books), 2).1 > range(&of(&s, Role::Body), 2).1);
    let size = kb.object("silo").unwrap().size;
    let s = at("silo", size);
    let roof = of(&s, Role::Top);
    let top: Vec<_> = roof
        .iter()
        .filter(|p| p[2] > 0.95 * size[2])
        .cloned()
        .collect();
    assert!(
        range(&top, 0).1 < 0.3 * range(&roof, 0).1,
        "silo: no conical roof"
    );
}

#[test]
fn a_flower_bucket_stand_holds_buckets_of_blooms_on_tiers_rising_to_the_back() {
    for name in ["flower bucket stand", "flower stand"] {
        for size in sizes(name, [1.3, 1.0, 0.9]) {
            let s = at(name, size);
            let buckets = of(&s, Role::Metal);
            let blooms = of(&s, Role::Books);
            // Separate buckets along the front row, counted at their feet (their rims may touch).
            let z0 = range(&buckets, 2).0;
            let feet: Vec<_> = buckets
                .iter()
                .filter(|p| p[1] > 0.25 * size[1] && p[2] < z0 + 0.03)
                .cloned()
                .collect();
            assert!(
                runs(&feet, 0, 0.01) >= 3,
                "{name} {size:?}: no row of buckets"
            );
            assert!(
                range(&blooms, 2).1 > range(&buckets, 2).1,
                "{name}: no flowers over the buckets"
            );
            // The back row stands higher than the front row.
            let lowest = |pick: &dyn Fn(&[f64; 3]) -> bool| {
                let row: Vec<_> = buckets.iter().filter(|p| pick(p)).cloned().collect();
                range(&row, 2).0
            };
            let front = lowest(&|p| p[1] > 0.25 * size[1]);
            let back = lowest(&|p| p[1] < -0.25 * size[1]);
            assert!(
                back > front + 0.2 * size[2],
                "{name}: tiers do not rise to the back"
            );
        }
    }
}

#[test]
fn a_bucket_is_an_open_pail_widening_to_its_rim_under_a_bail() {
    for size in sizes("bucket", [1.4, 1.0, 0.8]) {
        let s = at("bucket", size);
        let body = of(&s, Role::Metal);
        let rim = range(&body, 2).1;
        // Open: the inside shows from above, below the rim.
        let inside = of(&s, Role::Interior);
        assert!(!inside.is_empty(), "{size:?}: no inside");
        assert!(range(&inside, 2).1 <= rim + 1e-6, "{size:?}");
        // Wider at the rim than at the foot.
        let width_at = |z0: f64, z1: f64| {
            let band: Vec<_> = body
                .iter()
                .filter(|p| (z0..z1).contains(&p[2]))
                .cloned()
                .collect();
            range(&band, 0).1 - range(&band, 0).0
        };
        assert!(
            width_at(0.0, 0.1 * rim) < 0.9 * width_at(0.8 * rim, 0.95 * rim),
            "{size:?}: not widening to the rim"
        );
        // A bail arches over the mouth up to the top, reaching both sides.
        let bail = of(&s, Role::Handle);
        assert!(range(&bail, 2).1 > rim + 0.5 * (size[2] - rim), "{size:?}");
        let (x0, x1) = range(&bail, 0);
        assert!(
            x1 - x0 > 0.8 * size[0].min(size[1]),
            "{size:?}: bail too short"
        );
    }
}

#[test]
fn a_headset_has_a_boom_microphone_in_front_and_headphones_none() {
    // The boom reaches well ahead of the ear cups, below the headband.
    let tip = |c: &str, size: [f64; 3]| {
        let s = at(c, size);
        let cups = range(&of(&s, Role::Body), 1).1;
        of(&s, Role::Cushion)
            .into_iter()
            .chain(of(&s, Role::Frame))
            .filter(|p| p[1] > cups + 0.2 * size[1] && p[2] < 0.5 * size[2])
            .count()
    };
    for size in sizes("headset", [1.2, 1.3, 0.9]) {
        assert!(
            tip("headset", size) > 20,
            "headset {size:?}: no boom microphone"
        );
    }
    for c in ["headset", "telephone headset", "call center headset"] {
        assert_eq!(archetype_of(c), "headset", "{c}");
    }
    let size = KnowledgeBase::builtin().object("headphones").unwrap().size;
    assert_eq!(tip("headphones", size), 0, "headphones with a microphone");
}
