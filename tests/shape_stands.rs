//! Things once drawn as a plain box, a cabinet, a floor lamp or an armchair, drawn as what they
//! are and checked on their parts at their knowledge-base size and at a stretched size: a stage
//! has steps up to its deck, a pedestal mouldings at its foot and top, a host stand a sloped top,
//! a jewellery armoire many shallow drawers on legs under a mirrored lid, an examination lamp a
//! round flat head out on an arm, a nursing chair a glider's runners; a totem pole's wings spread
//! wide, a stump's roots flare into the ground, a forge's anvil is full size; the goods of a
//! fruit bowl, coat hooks and a florist's stand are in their own colours, not a shelf's grey and
//! brown; a ballot box has clear walls, slips inside and a slot in its lid; a wall map land
//! on a sea, a calendar a grid of days.
//! Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, runs, sized, within, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{build, Role, ShapeOptions};
use dreamscene::splat::cloud::SH_C0;

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 5)
}

#[test]
fn a_stage_has_steps_up_to_its_deck_and_a_skirt_round_its_face() {
    for name in ["stage", "platform"] {
        for size in sized("stage", [1.0, 1.0, 1.0])
            .into_iter()
            .chain([[6.0, 4.0, 1.0], [2.5, 2.0, 0.45]])
        {
            let s = at(name, size);
            let h = size[2];
            let top = of(&s, Role::Top);
            // The deck covers most of the footprint at the top.
            let deck = within(&top, |p| p[2] > h - 0.01);
            let (x0, x1) = range(&deck, 0);
            let (y0, y1) = range(&deck, 1);
            assert!(
                x1 - x0 > 0.95 * size[0] && y1 - y0 > 0.95 * size[1],
                "{name} {size:?}: its deck is not the stage's"
            );
            // Treads: level tops below the deck, each higher one further back.
            // (The deck is at most 5 cm thick.)
            let treads = within(&top, |p| p[2] < h - 0.06 && p[2] > 0.05);
            let levels = runs(&treads, 2, 0.01);
            assert!(
                levels >= 2,
                "{name} {size:?}: {levels} tread levels below the deck"
            );
            let low = within(&treads, |p| p[2] < 0.5 * h);
            let high = within(&treads, |p| p[2] > 0.5 * h);
            assert!(
                range(&high, 1).0 >= range(&low, 1).0 - 1e-6
                    && range(&high, 1).1 < range(&low, 1).1,
                "{name} {size:?}: the steps do not climb back into the stage"
            );
            // Every riser is at most 20 cm.
            assert!(h / (levels + 1) as f64 <= 0.2 + 1e-9, "{name} {size:?}");
            // The skirt hangs on the face and on both sides.
            let skirt = of(&s, Role::Canvas);
            assert!(
                range(&skirt, 1).1 > size[1] / 2.0 - 0.02,
                "{name}: no skirt on its face"
            );
            let (sx0, sx1) = range(&skirt, 0);
            assert!(
                sx0 < -size[0] / 2.0 + 0.02 && sx1 > size[0] / 2.0 - 0.02,
                "{name}: no skirt on its sides"
            );
        }
    }
}

/// Width of `pts` along x between heights `z0` and `z1`.
fn width(pts: &[[f64; 3]], z0: f64, z1: f64) -> f64 {
    let band = within(pts, |p| p[2] >= z0 && p[2] <= z1);
    let (a, b) = range(&band, 0);
    b - a
}

#[test]
fn a_pedestal_is_a_slim_shaft_between_a_moulded_base_and_a_cap() {
    for name in ["pedestal", "plinth"] {
        for size in sized("pedestal", [1.3, 1.0, 1.4]) {
            let pts = all(&at(name, size));
            let h = size[2];
            let (foot, shaft, cap) = (
                width(&pts, 0.0, 0.01 * h),
                width(&pts, 0.4 * h, 0.6 * h),
                width(&pts, 0.97 * h, h),
            );
            assert!(
                foot > 1.1 * shaft && cap > 1.1 * shaft,
                "{name} {size:?}: foot {foot:.3}, shaft {shaft:.3}, cap {cap:.3}"
            );
            // Two steps in the base: a width between the foot's and the shaft's.
            let step = width(&pts, 0.06 * h, 0.07 * h);
            assert!(
                step < foot - 0.01 && step > shaft + 0.01,
                "{name} {size:?}: one step in its base ({step:.3})"
            );
            // A flat top over the whole of the cap.
            let top = within(&of(&at(name, size), Role::Top), |p| p[2] > h - 0.002);
            assert!(width(&top, h - 0.002, h) > 0.95 * size[0], "{name}: top");
        }
    }
}

#[test]
fn a_host_stand_has_a_sloped_top_a_lamp_and_menus_at_its_side() {
    for name in ["hostess stand", "host stand"] {
        for size in sized("hostess stand", [1.3, 1.2, 1.1]) {
            let s = at(name, size);
            let (hd, h) = (size[1] / 2.0, size[2]);
            // The top slopes down towards the host behind it.
            let top = within(&of(&s, Role::Top), |p| p[2] > 0.8 * h);
            let front = within(&top, |p| p[1] > 0.6 * hd);
            let back = within(&top, |p| p[1] < -0.6 * hd);
            let (fz, bz) = (range(&front, 2).1, range(&back, 2).1);
            assert!(
                fz > bz + 0.05,
                "{name} {size:?}: top {fz:.3} at the front, {bz:.3} at the back"
            );
            // A lamp's shade above the top, and menus standing beside the body.
            let shade = of(&s, Role::Shade);
            assert!(!shade.is_empty() && range(&shade, 2).0 > bz, "{name}: lamp");
            let body = of(&s, Role::Body);
            let menus = of(&s, Role::Canvas);
            assert!(
                range(&menus, 0).0 >= range(&body, 0).1 - 1e-6,
                "{name} {size:?}: the menus are not beside the body"
            );
            assert!(runs(&menus, 1, 0.01) >= 2, "{name}: menus");
        }
    }
}

#[test]
fn a_jewellery_armoire_is_many_shallow_drawers_on_legs_under_a_mirrored_lid() {
    for name in ["jewelry armoire", "jewellery cabinet"] {
        for size in sized("jewelry armoire", [1.2, 1.0, 1.3]) {
            let s = at(name, size);
            let (hd, h) = (size[1] / 2.0, size[2]);
            let fronts = within(&of(&s, Role::Door), |p| p[1] > hd - 0.02);
            let drawers = runs(&fronts, 2, 0.004);
            assert!(drawers >= 6, "{name} {size:?}: {drawers} drawers");
            // Four legs under the case.
            let low = within(&all(&s), |p| p[2] < 0.05 * h);
            assert_eq!(runs(&low, 0, 0.01), 2, "{name} {size:?}: legs across");
            assert_eq!(runs(&low, 1, 0.01), 2, "{name} {size:?}: legs deep");
            // Side doors, and a mirror standing above the case's top.
            let doors = within(&of(&s, Role::Door), |p| p[1] < hd - 0.03);
            assert_eq!(runs(&doors, 0, 0.01), 2, "{name}: a door each side");
            let mirror = of(&s, Role::Glass);
            let case_top = range(&within(&of(&s, Role::Top), |p| p[1] > 0.0), 2).1;
            assert!(
                !mirror.is_empty() && range(&mirror, 2).0 > case_top,
                "{name} {size:?}: no mirror over the case"
            );
        }
    }
}

#[test]
fn an_examination_lamp_has_a_round_flat_head_out_on_an_arm_over_castors() {
    for name in ["examination lamp", "exam lamp", "examination light"] {
        for size in sized("examination lamp", [1.3, 1.0, 1.2]) {
            let s = at(name, size);
            let head = of(&s, Role::Shade);
            let (x0, x1) = range(&head, 0);
            let (y0, y1) = range(&head, 1);
            let (z0, z1) = range(&head, 2);
            let d = x1 - x0;
            assert!(
                ((y1 - y0) / d - 1.0).abs() < 0.1,
                "{name} {size:?}: the head is not round"
            );
            assert!(z1 - z0 < 0.4 * d, "{name} {size:?}: the head is not flat");
            assert!(z0 > 0.85 * size[2], "{name}: the head is low");
            // The light is under the head, the pole beside it.
            let light = of(&s, Role::Light);
            assert!(
                range(&light, 2).1 <= z0 + 0.005,
                "{name}: light under the head"
            );
            let pole = within(&of(&s, Role::Metal), |p| {
                p[2] > 0.3 * size[2] && p[2] < 0.6 * size[2]
            });
            // The arm reaches forwards, towards what the lamp stands beside.
            assert!(
                range(&pole, 1).1 < y0,
                "{name} {size:?}: no arm out forwards to the head"
            );
            let wheels = of(&s, Role::Tyre);
            assert!(runs(&wheels, 1, 0.01) >= 3, "{name}: castors");
        }
    }
}

#[test]
fn a_nursing_chair_is_a_glider_on_floor_runners() {
    for name in ["nursing chair", "glider"] {
        for size in sized("nursing chair", [1.2, 1.1, 1.0]) {
            let s = at(name, size);
            // Two runners along the floor, most of the depth long.
            let runners = within(&of(&s, Role::Frame), |p| p[2] < 0.03 && p[1].abs() > 0.15);
            assert_eq!(runs(&runners, 0, 0.01), 2, "{name} {size:?}: runners");
            let one = within(&runners, |p| p[0] > 0.4 * size[0]);
            let (y0, y1) = range(&one, 1);
            assert!(y1 - y0 > 0.9 * size[1], "{name} {size:?}: short runner");
            // The seat hangs clear of the floor on swing links.
            let seat = of(&s, Role::Cushion);
            assert!(range(&seat, 2).0 > 0.3 * size[2], "{name}: seat low");
            let links = of(&s, Role::Metal);
            assert_eq!(runs(&links, 0, 0.01), 2, "{name} {size:?}: links each side");
        }
    }
}

/// The share of `category`'s Gaussians with a strong colour (channels spread by more than
/// `spread`) above `z` (a share of its height), and how many of six hue sectors they fill.
fn vivid(category: &str, description: &str, z: f64, spread: f64) -> (f64, usize) {
    let size = KnowledgeBase::builtin().object(category).unwrap().size;
    let g = build(category, size, description, &ShapeOptions::default()).unwrap();
    let mut hues = [0usize; 6];
    let (mut n, mut strong) = (0, 0);
    for i in 0..g.len() {
        if (g.means[i][2] as f64) < z * size[2] {
            continue;
        }
        n += 1;
        let c = [0, 1, 2].map(|k| SH_C0 * g.sh[i * 3 + k] as f64 + 0.5);
        let (lo, hi) = (
            c.iter().cloned().fold(1.0, f64::min),
            c.iter().cloned().fold(0.0, f64::max),
        );
        if hi - lo > spread {
            strong += 1;
            let d = hi - lo;
            let h = if hi == c[0] {
                ((c[1] - c[2]) / d).rem_euclid(6.0)
            } else if hi == c[1] {
                (c[2] - c[0]) / d + 2.0
            } else {
                (c[0] - c[1]) / d + 4.0
            };
            hues[(h as usize).min(5)] += 1;
        }
    }
    let filled = hues.iter().filter(|k| **k * 50 > strong).count();
    (strong as f64 / n.max(1) as f64, filled)
}

#[test]
fn fruit_coats_and_flowers_are_in_their_own_colours_not_a_shelfs_greys() {
    // Fruit and flowers are bright; coats are cloth colours, duller but of several hues.
    for (c, d, z, spread, hues) in [
        ("fruit bowl", "ceramic fruit bowl", 0.5, 0.25, 3),
        ("fruit bowl", "white fruit bowl", 0.5, 0.25, 3),
        (
            "flower bucket stand",
            "florist's stand with buckets of flowers",
            0.8,
            0.25,
            3,
        ),
        ("coat hooks", "row of coat hooks with coats", 0.0, 0.1, 2),
    ] {
        let (share, filled) = vivid(c, d, z, spread);
        assert!(
            share > 0.15,
            "{c} ({d}): {share:.3} of it in strong colours"
        );
        assert!(filled >= hues, "{c} ({d}): {filled} hues");
    }
}

#[test]
fn a_totem_spreads_its_wings_a_stump_flares_into_roots_and_a_forges_anvil_is_full_size() {
    for size in sized("totem pole", [1.2, 1.0, 1.1]) {
        let s = at("totem pole", size);
        let h = size[2];
        let pole = width(&of(&s, Role::Body), 0.4 * h, 0.6 * h);
        let wings = width(&all(&s), 0.88 * h, h);
        assert!(
            wings > 2.5 * pole,
            "totem {size:?}: wings {wings:.2} over a pole {pole:.2} wide"
        );
    }
    for name in ["tree stump", "stump seat"] {
        for size in sized("tree stump", [1.2, 1.0, 1.3]) {
            let s = at(name, size);
            let h = size[2];
            let trunk = width(&of(&s, Role::Trunk), 0.5 * h, 0.6 * h);
            let foot = width(&of(&s, Role::Trunk), 0.0, 0.01 * h);
            assert!(
                foot > 1.5 * trunk,
                "{name} {size:?}: roots spread {foot:.2} under a trunk {trunk:.2} wide"
            );
            // The roots leave the trunk thick: just above the ground they still stand out of it
            // all round, not as thin pegs.
            let low = within(&of(&s, Role::Trunk), |p| {
                (0.08 * h..0.12 * h).contains(&p[2]) && p[0].hypot(p[1]) > 0.6 * trunk
            });
            assert!(
                low.len() > 200,
                "{name} {size:?}: {} root samples low down",
                low.len()
            );
        }
    }
    for size in sized("forge", [1.2, 1.0, 1.0]) {
        let s = at("forge", size);
        let anvil = at("anvil", sized("anvil", [1.0; 3])[0]);
        // The anvil beside the hearth: its face is level and long, like the anvil's own.
        let face = within(&of(&s, Role::Metal), |p| {
            p[0] > 0.2 * size[0] && p[2] < 0.9 * size[2] && p[2] > 0.5 * size[2]
        });
        let (y0, y1) = range(&face, 1);
        let (a0, a1) = range(&of(&anvil, Role::Metal), 0);
        assert!(
            y1 - y0 > 0.7 * (a1 - a0).min(size[1]),
            "forge {size:?}: its anvil is {:.2} long, an anvil {:.2}",
            y1 - y0,
            a1 - a0
        );
    }
}

#[test]
fn a_ballot_box_is_see_through_with_slips_inside_and_a_slot_in_its_lid() {
    for name in ["ballot box", "voting box"] {
        for size in sized("ballot box", [1.0, 1.0, 1.0])
            .into_iter()
            .chain([[0.6, 0.4, 0.5]])
        {
            let s = at(name, size);
            let h = size[2];
            let panes = of(&s, Role::Pane);
            // Clear walls on all four sides.
            let (x0, x1) = range(&panes, 0);
            let (y0, y1) = range(&panes, 1);
            assert!(
                x1 - x0 > 0.9 * size[0] && y1 - y0 > 0.9 * size[1],
                "{name} {size:?}: its walls are not clear"
            );
            // Slips lie low inside.
            let slips = of(&s, Role::Books);
            assert!(
                !slips.is_empty() && range(&slips, 2).1 < 0.25 * h,
                "{name} {size:?}: no ballot papers lie inside"
            );
            // A dark slot on the lid's top, narrower than the lid.
            let slot = within(&of(&s, Role::Interior), |p| p[2] > h - 0.01);
            let (sx0, sx1) = range(&slot, 0);
            assert!(
                !slot.is_empty() && sx1 - sx0 < 0.8 * size[0] && sx1 - sx0 > 0.3 * size[0],
                "{name} {size:?}: no slot in the lid"
            );
        }
    }
}

#[test]
fn a_wall_map_shows_land_on_sea_and_a_calendar_a_grid_of_days() {
    for size in sized("wall map", [1.0, 1.0, 1.0]) {
        let s = at("world map", size);
        let (sea, green, sand) = (
            of(&s, Role::Water),
            of(&s, Role::Foliage),
            of(&s, Role::Soil),
        );
        assert!(
            !sea.is_empty() && !green.is_empty() && !sand.is_empty(),
            "{size:?}: no sea with land on it"
        );
        // Land lies in several separate masses across the sea.
        assert!(
            runs(&green, 0, 0.02) + runs(&sand, 0, 0.02) >= 3,
            "{size:?}: one land mass"
        );
    }
    for size in sized("calendar", [1.0, 1.0, 1.0]) {
        let s = at("wall calendar", size);
        let days = within(&of(&s, Role::Frame), |p| p[2] < 0.45 * size[2]);
        // Six weekday columns of boxes (Sundays in their own colour) in five rows.
        assert!(
            runs(&days, 0, 0.003) == 6 && runs(&days, 2, 0.003) == 5,
            "{size:?}: {} columns and {} rows of day boxes",
            runs(&days, 0, 0.003),
            runs(&days, 2, 0.003)
        );
        assert!(
            !of(&s, Role::Handle).is_empty(),
            "{size:?}: no Sunday column"
        );
    }
}
