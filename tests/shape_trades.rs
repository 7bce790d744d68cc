//! Furniture, seats, racks, clocks and instruments of a trade drawn for what they are named,
//! checked on their parts at their knowledge-base size and two other sizes a plan may give
//! them: a wheelchair rolls on big wheels at its sides, a wall clock is a round dial with marks
//! and hands, a hospital bed raises its head, racks hold plates, books and shoes, a folding
//! screen stands in a zigzag. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{of, range, runs};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{parts, Role};
use rand::SeedableRng;

/// Surface samples of `category` at `size`, with their roles.
fn samples_at(category: &str, size: [f64; 3]) -> Vec<([f64; 3], Role)> {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let mut out = vec![];
    for p in parts(category, size).unwrap() {
        let mut s = vec![];
        p.prim.sample(0.01, &mut rng, &mut s);
        out.extend(s.iter().map(|s| (s.pos, p.role)));
    }
    // What the drawn object keeps: samples inside its size box.
    out.retain(|(p, _)| {
        p[0].abs() <= size[0] / 2.0 + 1e-6
            && p[1].abs() <= size[1] / 2.0 + 1e-6
            && (-1e-6..=size[2] + 1e-6).contains(&p[2])
    });
    out
}

/// The knowledge base's size of `category`, that size scaled by `a`, and the size `b`: the
/// sizes a plan may give it.
fn sizes(category: &str, a: [f64; 3], b: [f64; 3]) -> [[f64; 3]; 3] {
    let kb = KnowledgeBase::builtin().object(category).unwrap().size;
    [kb, [kb[0] * a[0], kb[1] * a[1], kb[2] * a[2]], b]
}

#[test]
fn a_wheelchair_rolls_on_big_wheels_at_its_sides_and_castors_in_front() {
    for name in ["wheelchair", "wheel chair"] {
        for size in sizes("wheelchair", [0.95, 0.9, 1.05], [0.7, 1.1, 0.95]) {
            let s = samples_at(name, size);
            let tyres = of(&s, Role::Tyre);
            let (lo, hi) = range(&tyres, 2);
            assert!(lo < 0.01, "{name} {size:?}: tyres off the floor ({lo:.3})");
            assert!(
                hi > 0.6 * size[2],
                "{name} {size:?}: the wheels reach {hi:.2} of {:.2} m",
                size[2]
            );
            // The big wheels stand at the sides; the castors, inboard of them, are small and
            // stand in front of the big wheels' axles.
            let hw = size[0] / 2.0;
            let (big, small): (Vec<[f64; 3]>, Vec<[f64; 3]>) =
                tyres.iter().partition(|p| p[0].abs() > 0.8 * hw);
            let (_, big_top) = range(&big, 2);
            assert!(
                big_top > 0.6 * size[2],
                "{name} {size:?}: big wheels reach {big_top:.2}"
            );
            let (_, small_top) = range(&small, 2);
            let mean_y = |v: &[[f64; 3]]| v.iter().map(|p| p[1]).sum::<f64>() / v.len() as f64;
            assert!(
                !small.is_empty() && small_top < 0.25 * size[2] && mean_y(&small) > mean_y(&big),
                "{name} {size:?}: no small castors in front"
            );
            assert!(!of(&s, Role::Handle).is_empty(), "{name}: no push handles");
        }
    }
}

#[test]
fn a_wall_clock_is_a_round_face_with_marks_and_hands() {
    for name in ["wall clock", "clock", "kitchen clock"] {
        for size in sizes("wall clock", [1.4, 1.0, 1.4], [0.3, 0.04, 0.3]) {
            let s = samples_at(name, size);
            let (r, zc) = (0.5 * size[0].min(size[2]), size[2] / 2.0);
            // Round: nothing in the corners of its square.
            let off = s
                .iter()
                .filter(|(p, _)| (p[0] * p[0] + (p[2] - zc).powi(2)).sqrt() > 1.02 * r)
                .count();
            assert_eq!(off, 0, "{name} {size:?}: {off} samples outside its round");
            let dial = of(&s, Role::Canvas);
            let (x0, x1) = range(&dial, 0);
            assert!(x1 - x0 > 1.5 * r, "{name} {size:?}: no dial");
            // Hands from the centre and twelve marks round the rim, on the dial's front.
            let marks = of(&s, Role::BlackKeys);
            let mean_y = |v: &[[f64; 3]]| v.iter().map(|p| p[1]).sum::<f64>() / v.len() as f64;
            assert!(
                mean_y(&marks) > mean_y(&dial),
                "{name}: marks behind the dial"
            );
            let dist = |p: &[f64; 3]| (p[0] * p[0] + (p[2] - zc).powi(2)).sqrt();
            assert!(marks.iter().any(|p| dist(p) < 0.1 * r), "{name}: no hands");
            let rim: Vec<_> = marks.iter().filter(|p| dist(p) > 0.75 * r).collect();
            let hours: std::collections::BTreeSet<i64> = rim
                .iter()
                .map(|p| ((-p[0]).atan2(p[2] - zc) / std::f64::consts::TAU * 12.0).round() as i64)
                .map(|h| h.rem_euclid(12))
                .collect();
            assert_eq!(hours.len(), 12, "{name} {size:?}: marks at {hours:?}");
        }
    }
}

#[test]
fn a_grandfather_clock_shows_its_dial_high_up_and_its_pendulum_below() {
    for name in ["grandfather clock", "longcase clock"] {
        for size in sizes("grandfather clock", [1.1, 1.0, 0.9], [0.45, 0.25, 2.2]) {
            let s = samples_at(name, size);
            let (z0, _) = range(&of(&s, Role::Canvas), 2);
            assert!(z0 > 0.62 * size[2], "{name} {size:?}: dial down at {z0:.2}");
            let (p0, p1) = range(&of(&s, Role::Metal), 2);
            assert!(
                p0 < 0.5 * size[2] && p1 > 0.6 * size[2],
                "{name} {size:?}: no pendulum hanging in the waist ({p0:.2}..{p1:.2})"
            );
            assert!(!of(&s, Role::Pane).is_empty(), "{name}: no window on it");
        }
    }
}

#[test]
fn beds_of_care_and_of_children_show_their_kind() {
    // A hospital bed: the head section raised, rails at the sides, on castors.
    for size in sizes("hospital bed", [0.9, 1.0, 1.1], [1.1, 2.2, 0.9]) {
        let s = samples_at("hospital bed", size);
        let m = of(&s, Role::Mattress);
        let top = |f: &dyn Fn(f64) -> bool| {
            m.iter()
                .filter(|p| f(p[1]))
                .map(|p| p[2])
                .fold(0.0, f64::max)
        };
        let (head, foot) = (top(&|y| y < -0.3 * size[1]), top(&|y| y > 0.0));
        assert!(
            head > foot + 0.15,
            "{size:?}: head {head:.2}, foot {foot:.2}"
        );
        let (lo, _) = range(&of(&s, Role::Tyre), 2);
        assert!(lo < 0.01, "hospital bed {size:?}: not on castors");
        let rails = of(&s, Role::Metal);
        for sx in [-1.0, 1.0] {
            assert!(
                rails
                    .iter()
                    .any(|p| sx * p[0] > 0.4 * size[0] && p[2] > foot + 0.1),
                "hospital bed {size:?}: no rail at side {sx}"
            );
        }
    }
    // A cabin bed: its mattress well above the floor, a ladder from the floor to its deck.
    for name in ["cabin bed", "mid-sleeper"] {
        for size in sizes("cabin bed", [0.9, 1.0, 1.2], [1.2, 2.1, 1.1]) {
            let s = samples_at(name, size);
            let (m0, _) = range(&of(&s, Role::Mattress), 2);
            assert!(m0 > 0.5 * size[2], "{name} {size:?}: mattress at {m0:.2}");
            let (l0, l1) = range(&of(&s, Role::Top), 2);
            assert!(l0 < 0.01 && l1 > m0, "{name} {size:?}: no ladder up to it");
        }
    }
}

#[test]
fn chairs_of_a_trade_carry_their_fittings() {
    // A barber chair on a pedestal with a footrest in front; a dentist's chair with a lamp over
    // its couch; a pedicure chair with a basin of water in front of its seat; a high chair with
    // a tray in front over splayed legs.
    for size in sizes("barber chair", [1.1, 1.0, 1.0], [0.65, 0.85, 1.2]) {
        let s = samples_at("barber chair", size);
        let base: Vec<_> = of(&s, Role::Metal)
            .into_iter()
            .filter(|p| p[2] < 0.02)
            .collect();
        assert!(
            !base.is_empty() && base.iter().all(|p| p[0].abs() < 0.45 * size[0]),
            "barber chair {size:?}: no pedestal"
        );
        let (_, yf) = range(&of(&s, Role::Upholstery), 1);
        let foot: Vec<_> = of(&s, Role::Handle)
            .into_iter()
            .filter(|p| p[1] > yf && p[2] < 0.25)
            .collect();
        assert!(!foot.is_empty(), "barber chair {size:?}: no footrest");
    }
    for size in sizes("dentist chair", [1.0, 0.9, 1.1], [0.9, 2.0, 1.3]) {
        let s = samples_at("dentist chair", size);
        let (l0, _) = range(&of(&s, Role::Light), 2);
        let (_, u1) = range(&of(&s, Role::Upholstery), 2);
        assert!(
            l0 > u1 + 0.1,
            "dentist chair {size:?}: lamp at {l0:.2}, couch up to {u1:.2}"
        );
        let (c0, c1) = range(&of(&s, Role::Cushion), 1);
        assert!(
            c1 < -0.2 * size[1] && c0 < c1,
            "dentist chair: headrest not at the back"
        );
    }
    for size in sizes("pedicure chair", [1.0, 1.1, 0.9], [0.8, 1.3, 1.3]) {
        let s = samples_at("pedicure chair", size);
        let water = of(&s, Role::Water);
        let (_, yseat) = range(&of(&s, Role::Upholstery), 1);
        assert!(
            !water.is_empty() && water.iter().all(|p| p[1] > yseat),
            "pedicure chair {size:?}: no basin in front"
        );
    }
    for size in sizes("high chair", [0.9, 1.0, 1.1], [0.55, 0.7, 1.05]) {
        let s = samples_at("high chair", size);
        let (t0, _) = range(&of(&s, Role::Top), 2);
        let (_, ty) = range(&of(&s, Role::Top), 1);
        let (_, sy) = range(&of(&s, Role::Cushion), 1);
        let (z_seat, _) = range(&of(&s, Role::Cushion), 2);
        assert!(
            ty > sy + 0.1,
            "high chair {size:?}: the tray is not in front"
        );
        let legs = of(&s, Role::Frame);
        let (x0, x1) = range(&legs, 0);
        let (sx0, sx1) = range(&of(&s, Role::Cushion), 0);
        assert!(
            x1 - x0 > 1.3 * (sx1 - sx0) && z_seat > 0.45 * size[2] && t0 < size[2],
            "high chair {size:?}: legs {:.2} wide under a seat {:.2} wide at {z_seat:.2}",
            x1 - x0,
            sx1 - sx0
        );
    }
}

#[test]
fn racks_hold_what_they_are_named_for() {
    // A plate rack holds plates on edge; a book cart has books on both faces and castors; a
    // shoe rack holds shoes on each tier; a magazine rack holds magazines standing up.
    for size in sizes("plate rack", [1.2, 1.0, 1.1], [0.4, 0.25, 0.25]) {
        let on_edge = parts("plate rack", size)
            .unwrap()
            .iter()
            .filter(|p| p.role == Role::Canvas)
            .filter(|p| {
                let h = p.prim.hull_points();
                let ext = |a: usize| {
                    h.iter().map(|q| q[a]).fold(f64::NEG_INFINITY, f64::max)
                        - h.iter().map(|q| q[a]).fold(f64::INFINITY, f64::min)
                };
                ext(2) > 5.0 * ext(0) && ext(1) > 5.0 * ext(0)
            })
            .count();
        assert!(
            on_edge >= 4,
            "plate rack {size:?}: {on_edge} plates on edge"
        );
    }
    for size in sizes("book cart", [1.0, 1.2, 1.0], [0.8, 0.5, 1.1]) {
        let s = samples_at("book cart", size);
        let books = of(&s, Role::Books);
        assert!(books.iter().any(|p| p[1] > 0.05) && books.iter().any(|p| p[1] < -0.05));
        let (lo, _) = range(&of(&s, Role::Tyre), 2);
        assert!(lo < 0.01, "book cart {size:?}: not on castors");
    }
    for (name, size) in [
        ("shoe rack", [0.8, 0.3, 0.9]),
        ("magazine rack", [0.4, 0.3, 0.5]),
    ] {
        let s = samples_at(name, size);
        let things = of(&s, Role::Books);
        let (z0, z1) = range(&things, 2);
        assert!(
            z1 - z0 > 0.4 * size[2],
            "{name}: what it holds spans {z0:.2}..{z1:.2}"
        );
    }
}

#[test]
fn a_folding_screen_stands_in_a_zigzag() {
    // Panels turn alternately: across each panel's width, its depth runs one way then the
    // other; a flat board would not.
    for name in ["room divider", "folding screen", "privacy screen"] {
        let size = KnowledgeBase::builtin().object(name).unwrap().size;
        let s = samples_at(name, size);
        let n = if size[0] > 1.3 { 4 } else { 3 };
        let mut slopes = vec![];
        for k in 0..n {
            let (a, b) = (
                -size[0] / 2.0 + (k as f64 + 0.2) * size[0] / n as f64,
                -size[0] / 2.0 + (k as f64 + 0.8) * size[0] / n as f64,
            );
            let pts: Vec<_> = s
                .iter()
                .filter(|(p, r)| *r == Role::Canvas && (a..b).contains(&p[0]))
                .map(|(p, _)| *p)
                .collect();
            let m = pts.len() as f64;
            let (mx, my) = (
                pts.iter().map(|p| p[0]).sum::<f64>() / m,
                pts.iter().map(|p| p[1]).sum::<f64>() / m,
            );
            let cov: f64 = pts.iter().map(|p| (p[0] - mx) * (p[1] - my)).sum();
            let var: f64 = pts.iter().map(|p| (p[0] - mx).powi(2)).sum();
            slopes.push(cov / var);
        }
        assert!(
            slopes.iter().all(|s| s.abs() > 0.2)
                && slopes.windows(2).all(|w| w[0].signum() != w[1].signum()),
            "{name}: panel slopes {slopes:?}"
        );
    }
}

#[test]
fn an_organ_has_pipes_above_its_keys_and_a_cello_stands_on_its_pin() {
    for size in sizes("church organ", [1.2, 1.0, 1.0], [1.6, 1.0, 2.2]) {
        let s = samples_at("church organ", size);
        let pipes = of(&s, Role::Metal);
        let (k0, k1) = range(&of(&s, Role::Keys), 2);
        let (p0, p1) = range(&pipes, 2);
        assert!(
            p0 > k1 && p1 > 0.85 * size[2] && k0 < 0.5 * size[2],
            "church organ {size:?}: pipes {p0:.2}..{p1:.2}, keys {k0:.2}..{k1:.2}"
        );
    }
    for name in ["cello", "double bass"] {
        let s = samples_at(name, [0.5, 0.4, 1.3]);
        let (b0, _) = range(&of(&s, Role::Body), 2);
        let pin: Vec<_> = of(&s, Role::Metal)
            .into_iter()
            .filter(|p| p[2] < b0 && p[0].abs() < 0.02 && p[1].abs() < 0.02)
            .collect();
        assert!(
            b0 > 0.05 && !pin.is_empty(),
            "{name}: body down to {b0:.2}, no end pin"
        );
        let (_, top) = range(&of(&s, Role::Frame), 2);
        assert!(top > 0.95 * 1.3, "{name}: no scroll at the top ({top:.2})");
    }
}

#[test]
fn treatment_recliners_lean_back_on_a_pedestal_and_a_tattoo_chair_has_a_long_arm_rest() {
    for name in [
        "patient chair",
        "treatment chair",
        "tattoo chair",
        "tattoo bed",
    ] {
        for size in sizes(name, [1.1, 1.1, 1.0], [0.9, 1.8, 1.2]) {
            let s = samples_at(name, size);
            // The couch's middle, between its arm rests.
            let pad: Vec<[f64; 3]> = of(&s, Role::Upholstery)
                .into_iter()
                .filter(|p| p[0].abs() < 0.15 * size[0])
                .collect();
            // The back rest rises behind the seat: the pad is higher at its back than its middle.
            let height = |y0: f64, y1: f64| {
                let part: Vec<[f64; 3]> = pad
                    .iter()
                    .filter(|p| (y0..y1).contains(&p[1]))
                    .cloned()
                    .collect();
                range(&part, 2).1
            };
            let back = height(-0.5 * size[1], -0.2 * size[1]);
            let seat = height(-0.05 * size[1], 0.1 * size[1]);
            assert!(
                back > seat + 0.05,
                "{name} {size:?}: back {back:.2}, seat {seat:.2}"
            );
            // It stands on a narrow pedestal, not on four legs at its corners.
            let foot: Vec<[f64; 3]> = s
                .iter()
                .filter(|(p, _)| p[2] < 0.05)
                .map(|(p, _)| *p)
                .collect();
            let (x0, x1) = range(&foot, 0);
            assert!(
                x1 - x0 < 0.75 * size[0],
                "{name} {size:?}: feet {x0:.2}..{x1:.2}"
            );
            if name.starts_with("tattoo") {
                let arm: Vec<[f64; 3]> = of(&s, Role::Cushion)
                    .into_iter()
                    .filter(|p| p[0] > 0.2 * size[0])
                    .collect();
                let (y0, y1) = range(&arm, 1);
                assert!(y1 - y0 > 0.5, "{name} {size:?}: arm rest {y0:.2}..{y1:.2}");
            }
        }
    }
}

#[test]
fn an_organ_and_a_pedicure_chair_show_their_works_from_behind() {
    for size in sizes("church organ", [1.2, 1.0, 1.1], [1.6, 1.0, 2.6]) {
        let s = samples_at("church organ", size);
        let behind: Vec<[f64; 3]> = of(&s, Role::Frame)
            .into_iter()
            .filter(|p| p[1] < -0.5 * size[1] + 0.04 && p[2] > 0.55 * size[2])
            .collect();
        assert!(
            runs(&behind, 0, 0.02) >= 5,
            "church organ {size:?}: no rank of pipes at the back"
        );
    }
    for size in sizes("pedicure chair", [1.0, 1.1, 0.9], [0.8, 1.3, 1.3]) {
        let s = samples_at("pedicure chair", size);
        let pipes = of(&s, Role::Metal)
            .into_iter()
            .filter(|p| p[1] < -0.5 * size[1] + 0.06)
            .count();
        assert!(
            pipes > 20,
            "pedicure chair {size:?}: no plumbing at the back"
        );
    }
}

#[test]
fn a_hood_dryer_chair_leans_its_hood_over_the_seat() {
    for name in ["hair dryer chair", "hood dryer"] {
        for size in sizes(name, [1.1, 1.0, 1.1], [0.8, 1.0, 1.4]) {
            let s = samples_at(name, size);
            let seat = of(&s, Role::Upholstery);
            let back_top = range(&seat, 2).1;
            let hood: Vec<[f64; 3]> = of(&s, Role::Body)
                .into_iter()
                .filter(|p| p[2] > back_top + 0.1)
                .collect();
            assert!(hood.len() > 50, "{name} {size:?}: no hood over the chair");
            // Over the seat, in front of the back rest, not behind it.
            let y = hood.iter().map(|p| p[1]).sum::<f64>() / hood.len() as f64;
            assert!(y > -0.25 * size[1], "{name} {size:?}: hood at y {y:.2}");
        }
    }
}
