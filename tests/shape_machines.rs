//! Vehicles, appliances, games tables and outdoor things drawn as what they are named, checked
//! on their parts at their knowledge-base size: a bus is long with a row of windows and a van
//! is not, a pickup's bed is open, a seesaw's plank rests on a central pivot, a foosball
//! table's rods stick out past both long sides, a lighthouse tapers under its lantern, a fruit
//! tree bears fruit. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{of, range, round, runs, sized, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{archetype_of, build, parts, Role, ShapeOptions};
use dreamscene::splat::cloud::SH_C0;
use rand::SeedableRng;

/// Surface samples of `category` at `size` (its knowledge-base size when `None`).
fn samples_at(category: &str, size: Option<[f64; 3]>) -> (Samples, [f64; 3]) {
    let size = size.unwrap_or_else(|| KnowledgeBase::builtin().object(category).unwrap().size);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let mut out = vec![];
    let spacing = 0.004 * size.iter().cloned().fold(0.0, f64::max);
    for p in parts(category, size).unwrap() {
        let mut s = vec![];
        p.prim.sample(spacing, &mut rng, &mut s);
        out.extend(s.iter().map(|s| (s.pos, p.role)));
    }
    (out, size)
}

fn samples(category: &str) -> (Samples, [f64; 3]) {
    samples_at(category, None)
}

fn mean(pts: &[[f64; 3]], axis: usize) -> f64 {
    pts.iter().map(|p| p[axis]).sum::<f64>() / pts.len().max(1) as f64
}

#[test]
fn each_vehicle_is_drawn_by_its_own_archetype() {
    let names: Vec<&str> = ["car", "van", "bus", "truck", "lorry"]
        .iter()
        .map(|c| archetype_of(c))
        .collect();
    for (i, a) in names.iter().enumerate() {
        assert!(!names[i + 1..].contains(a), "{a} draws two of {names:?}");
    }
}

#[test]
fn a_bus_has_a_row_of_side_windows_and_a_van_a_panel_side() {
    let side_panes = |category: &str| {
        let (s, size) = samples(category);
        let glass: Vec<[f64; 3]> = of(&s, Role::Glass)
            .into_iter()
            .filter(|p| p[0] > 0.4 * size[0] && p[1].abs() < 0.45 * size[1])
            .collect();
        (runs(&glass, 1, 0.05), size)
    };
    let (bus, bs) = side_panes("bus");
    let (van, vs) = side_panes("van");
    assert!(bus >= 6, "a bus shows {bus} side windows");
    assert!(van <= 2, "a van shows {van} side windows");
    assert!(
        bs[1] > 2.0 * vs[1],
        "a bus ({bs:?}) is longer than a van ({vs:?})"
    );
    // A van's body is one tall box: its roof runs over most of its length.
    let (s, size) = samples("van");
    let roof: Vec<[f64; 3]> = of(&s, Role::Body)
        .into_iter()
        .filter(|p| p[2] > 0.97 * size[2])
        .collect();
    let (y0, y1) = range(&roof, 1);
    assert!(y1 - y0 > 0.7 * size[1], "van roof {:.2} m long", y1 - y0);
}

#[test]
fn a_pickup_has_an_open_bed_behind_its_cab_and_a_lorry_a_tall_box() {
    let (s, size) = samples("truck");
    let bed = of(&s, Role::Interior)
        .into_iter()
        .filter(|p| p[1] < -0.2 * size[1])
        .collect::<Vec<_>>();
    assert!(!bed.is_empty(), "pickup: no bed floor at the back");
    let (_, floor) = range(&bed, 2);
    // Nothing covers the bed: no body above its floor away from its walls.
    let cover = of(&s, Role::Body)
        .into_iter()
        .filter(|p| p[1] < -0.2 * size[1] && p[0].abs() < 0.35 * size[0] && p[1] > -0.45 * size[1])
        .filter(|p| p[2] > floor + 0.05)
        .count();
    assert_eq!(cover, 0, "pickup: its bed is covered");
    let cab = of(&s, Role::Body)
        .into_iter()
        .filter(|p| p[2] > 0.9 * size[2])
        .collect::<Vec<_>>();
    assert!(
        mean(&cab, 1) > -0.15 * size[1],
        "pickup: the cab is not in front of the bed"
    );
    let (s, size) = samples("lorry");
    let (_, box_top) = range(&of(&s, Role::Canvas), 2);
    let (_, cab_top) = range(&of(&s, Role::Body), 2);
    let (_, box_front) = range(&of(&s, Role::Canvas), 1);
    assert!(
        box_top > cab_top + 0.1,
        "lorry: box {box_top:.2} not above cab {cab_top:.2}"
    );
    assert!(
        box_front < 0.3 * size[1],
        "lorry: the box reaches the front"
    );
    // Three axles: a front one and two at the back, every tyre on the ground.
    let tyres = of(&s, Role::Tyre);
    assert_eq!(runs(&tyres, 1, 0.05), 3, "lorry axles");
    assert!(range(&tyres, 2).0 < 0.01, "lorry: tyres off the ground");
}

#[test]
fn a_seesaw_plank_rests_on_a_central_pivot_and_tilts() {
    for (category, size) in [
        ("seesaw", None),
        ("seesaw", Some([4.0, 0.5, 1.0])),
        ("seesaw", Some([2.0, 0.4, 0.7])),
    ] {
        let (s, size) = samples_at(category, size);
        let plank = of(&s, Role::Top);
        let axle = of(&s, Role::Metal)
            .into_iter()
            .filter(|p| p[0].abs() < 0.06)
            .collect::<Vec<_>>();
        let (_, pivot_top) = range(&axle, 2);
        assert!(
            mean(&plank, 0).abs() < 0.05 * size[0],
            "{size:?}: plank off centre"
        );
        let (x0, x1) = range(&plank, 0);
        assert!(x1 - x0 > 0.85 * size[0], "{size:?}: plank {:.2} m", x1 - x0);
        // The plank's underside over the pivot touches it.
        let over = plank
            .iter()
            .filter(|p| p[0].abs() < 0.03)
            .map(|p| p[2])
            .fold(f64::INFINITY, f64::min);
        assert!(
            (over - pivot_top).abs() < 0.03,
            "{size:?}: plank {over:.2} over pivot {pivot_top:.2}"
        );
        // One end low, the other high.
        let end = |sx: f64| {
            let e: Vec<[f64; 3]> = plank
                .iter()
                .filter(|p| sx * p[0] > 0.45 * size[0])
                .cloned()
                .collect();
            mean(&e, 2)
        };
        assert!(
            (end(1.0) - end(-1.0)).abs() > 0.2 * size[2],
            "{size:?}: the plank is level"
        );
        assert!(
            end(1.0).min(end(-1.0)) < 0.2 * size[2],
            "{size:?}: no end near the ground"
        );
    }
}

#[test]
fn foosball_rods_stick_out_past_both_long_sides() {
    for size in [None, Some([1.2, 0.7, 0.85]), Some([1.6, 0.9, 0.95])] {
        let (s, size) = samples_at("foosball table", size);
        let cabinet = of(&s, Role::Body);
        let (c0, c1) = range(&cabinet, 1);
        let rods = of(&s, Role::Metal);
        let past = |f: &dyn Fn(f64) -> bool| {
            let out: Vec<[f64; 3]> = rods.iter().filter(|p| f(p[1])).cloned().collect();
            runs(&out, 0, 0.02)
        };
        let front = past(&|y| y > c1 + 0.02);
        let back = past(&|y| y < c0 - 0.02);
        assert!(
            front >= 8 && back >= 8,
            "{size:?}: rods past the sides {front} / {back}"
        );
        // Each rod has a handle on one side, the two teams' on opposite sides.
        let h = of(&s, Role::Handle);
        assert!(
            h.iter().any(|p| p[1] > c1) && h.iter().any(|p| p[1] < c0),
            "handles"
        );
    }
}

#[test]
fn a_roulette_table_has_its_wheel_at_one_end_and_the_layout_at_the_other() {
    let (s, size) = samples("roulette table");
    let top = of(&s, Role::Metal);
    let (_, felt_top) = range(&of(&s, Role::Canvas), 2);
    assert!(
        mean(&top, 0) < -0.2 * size[0],
        "the wheel's spindle is not at the −x end"
    );
    assert!(
        range(&top, 2).1 > felt_top + 0.05,
        "the wheel does not stand over the felt"
    );
    let black = of(&s, Role::BlackKeys);
    let cells_right = black.iter().filter(|p| p[0] > 0.0).count();
    assert!(
        cells_right > black.len() / 2,
        "the layout is not at the +x end"
    );
}

#[test]
fn a_lighthouse_tapers_in_bands_under_a_glazed_lantern() {
    let (s, size) = samples("lighthouse");
    let tower: Vec<[f64; 3]> = s
        .iter()
        .filter(|(_, r)| matches!(r, Role::Body | Role::Upholstery))
        .map(|(p, _)| *p)
        .collect();
    let radius_at = |z: f64| {
        tower
            .iter()
            .filter(|p| (p[2] - z).abs() < 0.02 * size[2])
            .map(|p| p[0].hypot(p[1]))
            .fold(0.0, f64::max)
    };
    let (low, high) = (radius_at(0.1 * size[2]), radius_at(0.65 * size[2]));
    assert!(
        high < 0.8 * low,
        "tower radius {low:.2} at the foot, {high:.2} high up"
    );
    let bands = of(&s, Role::Upholstery);
    assert!(runs(&bands, 2, 0.1) >= 2, "no bands of a second colour");
    let (g0, _) = range(&of(&s, Role::Glass), 2);
    let (_, b1) = range(&bands, 2);
    assert!(g0 > b1, "the lantern is not above the tower");
}

#[test]
fn a_garden_gnome_wears_a_tall_hat_over_a_beard() {
    let (s, size) = samples("garden gnome");
    let (hat0, hat1) = range(&of(&s, Role::Upholstery), 2);
    assert!(hat1 > 0.95 * size[2], "the hat is not on top");
    assert!(
        hat1 - hat0 > 0.3 * size[2],
        "the hat is {:.2} m tall",
        hat1 - hat0
    );
    let beard = of(&s, Role::Canvas);
    assert!(mean(&beard, 1) > 0.1 * size[1], "the beard is not in front");
    assert!(
        range(&beard, 2).1 < hat0 + 0.01,
        "the beard is above the hat's brim"
    );
}

#[test]
fn a_lawn_mower_has_a_low_deck_on_wheels_and_a_long_handle_back() {
    let (s, size) = samples("lawn mower");
    let deck = of(&s, Role::Body);
    assert!(range(&deck, 2).1 < 0.3 * size[2], "the deck is not low");
    assert!(mean(&deck, 1) > 0.0, "the deck is not at the front");
    let tyres = of(&s, Role::Tyre);
    assert_eq!(
        runs(&tyres, 1, 0.03) * runs(&tyres, 0, 0.03),
        4,
        "four wheels"
    );
    let grip = of(&s, Role::Handle)
        .into_iter()
        .filter(|p| p[2] > 0.9 * size[2])
        .collect::<Vec<_>>();
    assert!(
        !grip.is_empty() && mean(&grip, 1) < -0.3 * size[1],
        "the grip is not high at the back"
    );
    assert!(!of(&s, Role::Canvas).is_empty(), "no grass bag");
}

#[test]
fn a_shopping_cart_is_a_wire_basket_on_casters_with_a_handle_at_the_back() {
    let (s, size) = samples("shopping cart");
    let tyres = of(&s, Role::Tyre);
    assert!(range(&tyres, 2).0 < 0.005, "casters off the floor");
    assert_eq!(runs(&tyres, 1, 0.03), 2, "front and back casters");
    // The basket's sides are a grid: some level slice through a side crosses many bars.
    let side: Vec<[f64; 3]> = of(&s, Role::Metal)
        .into_iter()
        .filter(|p| p[0] > 0.3 * size[0])
        .collect();
    let bars = (55..90)
        .map(|k| {
            let z = 0.01 * k as f64 * size[2];
            let slice: Vec<[f64; 3]> = side
                .iter()
                .filter(|p| (p[2] - z).abs() < 0.003)
                .cloned()
                .collect();
            if slice.is_empty() {
                0
            } else {
                runs(&slice, 1, 0.01)
            }
        })
        .max()
        .unwrap();
    assert!(bars >= 8, "basket sides are not a grid ({bars} bars)");
    let handle = of(&s, Role::Handle);
    assert!(mean(&handle, 1) < -0.4 * size[1] && range(&handle, 2).1 > 0.9 * size[2]);
}

#[test]
fn a_ships_mast_is_tall_with_yards_and_rigging_to_both_sides() {
    let (s, size) = samples("mast");
    let wood = of(&s, Role::Trunk);
    assert!(range(&wood, 2).1 > 0.9 * size[2], "the pole is short");
    let yards = wood.iter().filter(|p| p[0].abs() > 0.3 * size[0]).count();
    assert!(yards > 0, "no yards across the mast");
    let rig = of(&s, Role::BlackKeys);
    assert!(rig.iter().any(|p| p[0] > 0.4 * size[0]) && rig.iter().any(|p| p[0] < -0.4 * size[0]));
}

#[test]
fn machines_on_stands_stand_on_their_feet() {
    // A spotlight's can (lens in front) rides above a tripod; a microscope's eyepiece is its
    // top, over the stage; a kiln's chamber stands on legs; a floor air conditioner has its
    // louvres over its grille, and a split unit its slot underneath.
    let (s, size) = samples("spotlight");
    assert!(
        range(&of(&s, Role::Body), 2).0 > 0.6 * size[2],
        "spotlight: can low"
    );
    assert!(
        mean(&of(&s, Role::Light), 1) > mean(&of(&s, Role::Body), 1),
        "lens behind"
    );
    let feet = of(&s, Role::Tyre);
    assert_eq!(
        runs(&feet, 0, 0.02).max(runs(&feet, 1, 0.02)),
        3,
        "three feet"
    );
    let (s, size) = samples("microscope");
    let (_, eye) = range(&of(&s, Role::BlackKeys), 2);
    let (_, stage) = range(&of(&s, Role::Top), 2);
    assert!(eye > 0.95 * size[2] && stage < 0.5 * size[2]);
    let (s, size) = samples("kiln");
    assert!(
        range(&of(&s, Role::Body), 2).0 > 0.15 * size[2],
        "kiln: chamber on the floor"
    );
    assert!(range(&of(&s, Role::Frame), 2).0 < 0.005, "kiln: no legs");
    let (s, _) = samples("air conditioner");
    assert!(mean(&of(&s, Role::Metal), 2) > mean(&of(&s, Role::Frame), 2) + 0.3);
    let (s, size) = samples_at("air conditioner", Some([0.9, 0.25, 0.3]));
    let slot = of(&s, Role::Interior);
    assert!(
        range(&slot, 2).1 < 0.3 * size[2],
        "split unit: the slot is not underneath"
    );
    // A range hood's chimney is far narrower than its canopy, both flush with the wall.
    let (s, size) = samples("range hood");
    let body: Vec<[f64; 3]> = s
        .iter()
        .filter(|(_, r)| matches!(r, Role::Body | Role::Metal))
        .map(|(p, _)| *p)
        .collect();
    let width_at = |z: f64| {
        let w: Vec<[f64; 3]> = body
            .iter()
            .filter(|p| (p[2] - z).abs() < 0.03)
            .cloned()
            .collect();
        let (a, b) = range(&w, 0);
        b - a
    };
    assert!(width_at(0.9 * size[2]) < 0.5 * width_at(0.05 * size[2]));
    assert!(range(&body, 1).0 < -0.49 * size[1]);
}

/// Mean colour of the Gaussians of `category` (its kb description) whose colour `pick` keeps,
/// and their share.
fn share(category: &str, pick: impl Fn([f64; 3]) -> bool) -> f64 {
    let o = KnowledgeBase::builtin().object(category).unwrap();
    let g = build(category, o.size, &o.description, &ShapeOptions::default()).unwrap();
    let n = (0..g.len())
        .filter(|&i| pick([0, 1, 2].map(|k| 0.5 + SH_C0 * g.sh[i * 3 + k] as f64)))
        .count();
    n as f64 / g.len() as f64
}

#[test]
fn fruit_trees_bear_red_fruit_and_cherries_blossom_pink() {
    let red = |c: [f64; 3]| c[0] > 0.5 && c[1] < 0.3 && c[2] < 0.3;
    let green = |c: [f64; 3]| c[1] > c[0] + 0.1 && c[1] > c[2] + 0.1;
    let pink = |c: [f64; 3]| c[0] > 0.6 && c[0] > c[1] + 0.1 && c[2] > 0.5;
    let apple = (share("apple tree", red), share("apple tree", green));
    assert!(
        apple.0 > 0.01 && apple.0 < 0.3,
        "apple tree: {:.3} red",
        apple.0
    );
    assert!(apple.1 > 0.4, "apple tree: {:.3} green leaves", apple.1);
    let cherry = (share("cherry tree", pink), share("cherry tree", green));
    assert!(cherry.0 > 0.5, "cherry tree: {:.3} pink", cherry.0);
    assert!(cherry.1 < 0.05, "cherry tree: {:.3} green", cherry.1);
    let plain = share("tree", red);
    assert!(plain < 0.005, "a plain tree bears fruit ({plain:.3})");
}

/// The samples of `category` drawn at `size`, for the vehicle and appliance checks below.
fn at(category: &str, size: [f64; 3]) -> Samples {
    samples_at(category, Some(size)).0
}

#[test]
fn a_tram_carries_a_pantograph_over_its_roof_and_is_alike_at_both_ends() {
    for name in ["streetcar", "tram"] {
        for size in sized(name, [1.0, 1.6, 1.1]) {
            let s = at(name, size);
            let body = of(&s, Role::Body);
            let roof = range(&body, 2).1;
            let over: Vec<[f64; 3]> = of(&s, Role::Metal)
                .into_iter()
                .filter(|p| p[2] > roof + 0.3 && p[1].abs() < 0.25 * size[1])
                .collect();
            assert!(!over.is_empty(), "{name} {size:?}: nothing over the roof");
            let (x0, x1) = range(&over, 0);
            assert!(
                x1 - x0 > 0.4 * size[0],
                "{name} {size:?}: no collector bar across ({x0:.2}..{x1:.2})"
            );
            // A destination sign and a windscreen at both ends.
            for end in [-1.0, 1.0] {
                let near = |r: Role| {
                    of(&s, r)
                        .into_iter()
                        .filter(|p| end * p[1] > 0.48 * size[1])
                        .count()
                };
                assert!(
                    near(Role::Light) > 10 && near(Role::Glass) > 10,
                    "{name} {size:?}: the end at {end} has no sign or windscreen"
                );
            }
        }
    }
    // A bus has no pantograph: nothing metal rides on its roof.
    let (s, size) = samples("bus");
    let high = of(&s, Role::Metal)
        .into_iter()
        .filter(|p| p[2] > 0.9 * size[2])
        .count();
    assert_eq!(high, 0, "a bus carries metal on its roof");
}

#[test]
fn a_food_truck_opens_a_serving_hatch_under_an_awning_on_its_side() {
    for name in ["food truck", "snack van"] {
        for size in sized(name, [0.9, 1.3, 1.0]) {
            let s = at(name, size);
            let body = of(&s, Role::Body);
            let side = range(&body, 0).1;
            // The hatch: a dark opening on the right side, at counter height.
            let hatch: Vec<[f64; 3]> = of(&s, Role::Interior)
                .into_iter()
                .filter(|p| p[0] > side - 0.05 && p[1].abs() < 0.4 * size[1])
                .collect();
            let (z0, z1) = range(&hatch, 2);
            let (y0, y1) = range(&hatch, 1);
            assert!(
                z1 - z0 > 0.25 * size[2] && y1 - y0 > 0.25 * size[1],
                "{name} {size:?}: hatch {y0:.2}..{y1:.2} × {z0:.2}..{z1:.2}"
            );
            // The awning stands out past the side, above the hatch; the counter under it.
            let awning = of(&s, Role::Canvas);
            assert!(
                range(&awning, 0).1 > side + 0.1 && range(&awning, 2).0 > z1 - 0.05,
                "{name} {size:?}: no awning out over the hatch"
            );
            let counter = of(&s, Role::Top);
            assert!(
                range(&counter, 0).1 > side + 0.1 && range(&counter, 2).1 < z0 + 0.05,
                "{name} {size:?}: no counter under the hatch"
            );
        }
    }
    let (van, _) = samples("van");
    assert!(of(&van, Role::Canvas).is_empty(), "a van has an awning");
}

#[test]
fn a_washer_shows_a_round_door_and_its_hoses_at_the_back() {
    // A tumble dryer has a round door too but is drawn on its own (tests/shape_gear.rs).
    for name in ["washing machine", "washer"] {
        for size in sized(name, [1.0, 1.0, 1.2]) {
            let s = at(name, size);
            // The door's chrome ring, on the front below the control strip.
            let ring: Vec<[f64; 3]> = of(&s, Role::Metal)
                .into_iter()
                .filter(|p| p[1] > 0.4 * size[1] && p[2] < 0.8 * size[2])
                .collect();
            assert!(
                ring.len() > 20 && round(&ring),
                "{name} {size:?}: no round door"
            );
            // Behind the body: the inlet and drain hoses.
            let hoses = of(&s, Role::Handle)
                .into_iter()
                .filter(|p| p[1] < -0.5 * size[1] + 0.035)
                .count();
            assert!(hoses > 10, "{name}: no hoses at the back");
        }
    }
}

#[test]
fn a_wall_oven_has_no_hob_and_a_range_has_rings() {
    for (name, hob) in [
        ("wall oven", false),
        ("built-in oven", false),
        ("stove", true),
        ("cooker", true),
    ] {
        let (s, size) = samples(name);
        let rings = of(&s, Role::Metal)
            .into_iter()
            .filter(|p| p[2] > 0.95 * size[2] && p[1].abs() < 0.4 * size[1])
            .count();
        assert_eq!(rings > 0, hob, "{name}: {rings} samples of hob rings");
        // Both have an oven door with a window under a bar handle.
        assert!(of(&s, Role::Screen).len() > 20, "{name}: no oven window");
    }
}

#[test]
fn a_pizza_oven_is_a_dome_with_an_arched_mouth_not_a_fireplace() {
    assert_ne!(archetype_of("pizza oven"), archetype_of("fireplace"));
    for name in ["pizza oven", "wood-fired oven"] {
        for size in sized(name, [1.2, 0.9, 0.8]) {
            let s = at(name, size);
            // The dome above the hearth slab (what lies under the slab is hidden).
            let zb = range(&of(&s, Role::Top), 2).1;
            let dome: Vec<[f64; 3]> = of(&s, Role::Body)
                .into_iter()
                .filter(|p| p[2] >= zb)
                .collect();
            let zt = range(&dome, 2).1;
            // Rounded: near its top the dome is far narrower than at its foot.
            let width = |z0: f64, z1: f64| {
                let band: Vec<[f64; 3]> = dome
                    .iter()
                    .filter(|p| (z0..z1).contains(&p[2]))
                    .cloned()
                    .collect();
                let (a, b) = range(&band, 0);
                b - a
            };
            let low = width(zb, zb + 0.1 * (zt - zb));
            let high = width(zt - 0.1 * (zt - zb), zt);
            assert!(high < 0.6 * low, "{name} {size:?}: {high:.2} vs {low:.2}");
            // A dark mouth on the front, rounded at its top, and a flue above the dome.
            let mouth: Vec<[f64; 3]> = of(&s, Role::Interior)
                .into_iter()
                .filter(|p| p[2] > zb)
                .collect();
            assert!(
                range(&mouth, 1).0 > 0.3 * size[1],
                "{name}: no mouth in front"
            );
            assert!(
                range(&of(&s, Role::Metal), 2).1 > zt,
                "{name}: no flue above the dome"
            );
        }
    }
}

#[test]
fn a_sauna_stove_is_a_heap_of_stones_on_a_firebox_not_a_range() {
    assert_ne!(archetype_of("sauna stove"), archetype_of("stove"));
    for name in ["sauna stove", "sauna heater", "kiuas"] {
        for size in sized(name, [1.3, 1.2, 1.25]) {
            let s = at(name, size);
            // Stones fill the upper part of the box, across most of its width.
            let stones = of(&s, Role::Stone);
            assert!(stones.len() > 200, "{name} {size:?}: no stones");
            let (z0, z1) = range(&stones, 2);
            assert!(z0 > 0.4 * size[2], "{name} {size:?}: stones from {z0:.2}");
            assert!(z1 > 0.85 * size[2], "{name} {size:?}: stones up to {z1:.2}");
            let (x0, x1) = range(&stones, 0);
            assert!(
                x1 - x0 > 0.6 * size[0],
                "{name} {size:?}: heap {:.2}",
                x1 - x0
            );
            // A glowing fire door on the front of the firebox, under the stones.
            let glow = of(&s, Role::Light);
            assert!(!glow.is_empty(), "{name}: no fire door");
            assert!(
                range(&glow, 2).1 < z0,
                "{name}: the fire door is not under the stones"
            );
            assert!(
                range(&glow, 1).0 > 0.4 * size[1],
                "{name}: the fire door is not in front"
            );
        }
    }
    // A kitchen range has no stones.
    assert!(of(&at("stove", sized("stove", [1.0; 3])[0]), Role::Stone).is_empty());
}

#[test]
fn a_softbox_is_a_wide_diffuser_on_a_light_stand_not_a_lampshade() {
    assert_ne!(archetype_of("softbox light"), archetype_of("floor lamp"));
    for name in ["softbox light", "softbox", "studio light"] {
        for size in sized(name, [1.2, 1.0, 1.2]) {
            let s = at(name, size);
            // The diffuser: one wide face high on the stand, facing the front.
            let face = of(&s, Role::Light);
            assert!(face.len() > 100, "{name} {size:?}: no diffuser");
            let (x0, x1) = range(&face, 0);
            assert!(
                x1 - x0 > 0.6 * size[0],
                "{name} {size:?}: face {:.2}",
                x1 - x0
            );
            assert!(
                range(&face, 2).0 > 0.5 * size[2],
                "{name} {size:?}: face low"
            );
            assert!(
                mean(&face, 1) > 0.0,
                "{name} {size:?}: face not at the front"
            );
            // The cloth box behind it narrows to the back.
            let body = of(&s, Role::Body);
            let back: Vec<[f64; 3]> = body
                .iter()
                .filter(|p| p[1] < -0.15 * size[1])
                .cloned()
                .collect();
            let (bx0, bx1) = range(&back, 0);
            assert!(
                bx1 - bx0 < 0.6 * (x1 - x0),
                "{name} {size:?}: box does not narrow"
            );
        }
    }
}

#[test]
fn a_tea_set_is_a_teapot_and_cups_on_a_tray_not_a_kettle() {
    assert_ne!(archetype_of("tea set"), archetype_of("kettle"));
    for name in ["tea set", "tea service"] {
        for size in sized(name, [1.3, 1.2, 1.0]) {
            let s = at(name, size);
            // A low tray under everything, over most of the footprint.
            let tray = of(&s, Role::Top);
            let (x0, x1) = range(&tray, 0);
            assert!(
                x1 - x0 > 0.9 * size[0],
                "{name} {size:?}: tray {:.2}",
                x1 - x0
            );
            assert!(
                range(&tray, 2).1 < 0.15 * size[2],
                "{name} {size:?}: tray high"
            );
            // Tea in at least two cups, apart from each other and from the pot.
            let tea = of(&s, Role::Interior);
            assert!(
                runs(&tea, 1, 0.01) >= 2,
                "{name} {size:?}: fewer than two cups"
            );
            // The pot stands far taller than the cups.
            let porcelain = of(&s, Role::Body);
            let (zc0, zc1) = range(&tea, 2);
            assert!(
                range(&porcelain, 2).1 > 2.0 * zc1.max(zc0),
                "{name} {size:?}: no pot"
            );
        }
    }
}
