//! Things drawn for their own function, checked on their parts at their knowledge-base size:
//! what hangs is clear of the floor, what holds things holds them, what comes in a set is
//! several. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{of, range};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{parts, Role};
use rand::SeedableRng;

/// Surface samples of `category` at its knowledge-base size, with their roles, and the size.
fn samples(category: &str) -> (Vec<([f64; 3], Role)>, [f64; 3]) {
    let size = KnowledgeBase::builtin().object(category).unwrap().size;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let mut out = vec![];
    for p in parts(category, size).unwrap() {
        let mut s = vec![];
        p.prim.sample(0.01, &mut rng, &mut s);
        out.extend(s.iter().map(|s| (s.pos, p.role)));
    }
    (out, size)
}

#[test]
fn hanging_things_are_clear_of_the_floor_on_a_stand_that_is_not() {
    // The bag and the basket hang; their stands reach the floor.
    for (category, hung) in [
        ("punching bag", Role::Upholstery),
        ("hanging chair", Role::Frame),
    ] {
        let (s, size) = samples(category);
        let (lo, _) = range(&of(&s, hung), 2);
        assert!(
            lo > 0.2 * size[2],
            "{category}: its {hung:?} hangs down to {lo:.2} m"
        );
        let stand: Vec<[f64; 3]> = s
            .iter()
            .filter(|(_, r)| matches!(r, Role::Metal | Role::Frame) && *r != hung)
            .map(|(p, _)| *p)
            .collect();
        let (floor, _) = range(&stand, 2);
        assert!(
            floor < 0.01,
            "{category}: nothing stands on the floor ({floor:.3})"
        );
    }
}

#[test]
fn a_wine_rack_holds_bottles_in_most_cells_and_a_pantry_shelf_jars() {
    let kb = KnowledgeBase::builtin();
    let size = kb.object("wine rack").unwrap().size;
    let bottles = parts("wine rack", size)
        .unwrap()
        .iter()
        .filter(|p| matches!(p.role, Role::Glass | Role::BlackKeys))
        .count();
    // Cells of about 10 cm: a 0.6 × 1.2 m rack has about 50.
    let cells = (size[0] / 0.1).floor() * (size[2] / 0.1).floor();
    assert!(
        bottles as f64 > 0.6 * cells,
        "{bottles} bottles for about {cells} cells"
    );
    for category in ["pantry shelf", "spice rack"] {
        let size = kb.object(category).unwrap().size;
        let ps = parts(category, size).unwrap();
        let jars = ps.iter().filter(|p| p.role == Role::Pane).count();
        let lids = ps.iter().filter(|p| p.role == Role::Metal).count();
        assert!(
            jars >= 3 && lids >= jars,
            "{category}: {jars} jars, {lids} lids and ends"
        );
    }
}

#[test]
fn nesting_tables_are_three_tops_each_lower_and_tucked_under_the_last() {
    let size = KnowledgeBase::builtin()
        .object("nesting tables")
        .unwrap()
        .size;
    // Each top: (its upper face, its back, its front).
    let mut tops: Vec<(f64, f64, f64)> = parts("nesting tables", size)
        .unwrap()
        .iter()
        .filter(|p| p.role == Role::Top)
        .map(|p| {
            let c = p.prim.hull_points();
            let (b, f) = range(&c, 1);
            (range(&c, 2).1, b, f)
        })
        .collect();
    tops.sort_by(|a, b| b.0.total_cmp(&a.0));
    assert_eq!(tops.len(), 3, "tops {tops:?}");
    for w in tops.windows(2) {
        let (hi, lo) = (w[0], w[1]);
        assert!(lo.0 < hi.0 - 0.03, "two tops at one height: {tops:?}");
        assert!(
            lo.2 > hi.2,
            "a lower top does not reach further forward: {tops:?}"
        );
        assert!(
            lo.1 < hi.2,
            "a lower top is not tucked under the one above: {tops:?}"
        );
    }
}

#[test]
fn a_recliner_holds_its_footrest_out_in_front_of_its_arms() {
    let (s, size) = samples("recliner");
    let soft = of(&s, Role::Upholstery);
    // The arms (high, at the sides) end well behind the front; the footrest reaches it.
    let arms: Vec<[f64; 3]> = soft
        .iter()
        .filter(|p| p[2] > 0.5 * size[2] && p[0].abs() > 0.4 * size[0])
        .copied()
        .collect();
    let (_, arm_front) = range(&arms, 1);
    let (_, front) = range(&soft, 1);
    assert!(
        front - arm_front > 0.25 * size[1],
        "footrest reaches {front:.2}, arms {arm_front:.2}"
    );
    let under: Vec<[f64; 3]> = soft
        .iter()
        .filter(|p| p[1] > arm_front + 0.05)
        .copied()
        .collect();
    let (lo, _) = range(&under, 2);
    assert!(
        lo > 0.15 * size[2],
        "the footrest stands on the floor ({lo:.2})"
    );
}

#[test]
fn a_weight_bench_has_a_loaded_bar_above_its_pads() {
    let (s, size) = samples("weight bench");
    let (_, pad_top) = range(&of(&s, Role::Upholstery), 2);
    let bar = of(&s, Role::Handle);
    let (x0, x1) = range(&bar, 0);
    let (z0, _) = range(&bar, 2);
    assert!(x1 - x0 > 0.8 * size[0], "bar spans {:.2} m", x1 - x0);
    assert!(
        z0 > pad_top + 0.3,
        "bar at {z0:.2}, pads up to {pad_top:.2}"
    );
    let (p0, p1) = range(&of(&s, Role::Metal), 2);
    assert!(p1 - p0 > 0.25, "plates {:.2} m tall", p1 - p0);
}

#[test]
fn an_exercise_bike_stands_on_its_frame_not_on_wheels() {
    // No tyres touch the floor: the flywheel turns clear of it, in the front half, and the
    // frame's stabilisers carry the bike; a bicycle rides on its tyres.
    let (s, size) = samples("exercise bike");
    let fly = of(&s, Role::Metal);
    let tyres = of(&s, Role::Tyre);
    let (lo, _) = range(&tyres, 2);
    assert!(lo > 0.05, "exercise bike: a tyre reaches down to {lo:.2} m");
    let (y_lo, _) = range(&tyres, 1);
    assert!(
        y_lo > 0.0,
        "exercise bike: the flywheel is not at the front ({y_lo:.2})"
    );
    let (floor, _) = range(&of(&s, Role::Frame), 2);
    assert!(
        floor < 0.01,
        "exercise bike: its frame is off the floor ({floor:.3})"
    );
    assert!(!fly.is_empty() && size[2] > 1.0, "exercise bike: parts");
    let (s, _) = samples("bicycle");
    let (lo, _) = range(&of(&s, Role::Tyre), 2);
    assert!(lo < 0.01, "a bicycle stands on its tyres ({lo:.3})");
}

#[test]
fn pictures_hang_flat_on_their_wall() {
    // A painting, a tapestry and a hanging scroll are hung (placement: on the wall): the whole
    // picture lies within a few centimetres of its back, with no posts or feet standing out.
    for category in ["painting", "tapestry", "hanging scroll", "poster"] {
        let (s, size) = samples(category);
        let back = -size[1] / 2.0;
        let (_, front) = range(&s.iter().map(|(p, _)| *p).collect::<Vec<_>>(), 1);
        assert!(
            front - back < 0.06,
            "{category}: stands {:.2} m out from its wall",
            front - back
        );
    }
}

#[test]
fn a_poster_is_a_print_to_its_edges_not_a_framed_glass() {
    // A poster's sheet has no frame round it: what lies at its side edges is paper, and its
    // printed field spans most of its width and height (a mirror or a painting would show a
    // frame at the edge, a blank sheet no print).
    let (s, size) = samples("poster");
    let hw = size[0] / 2.0;
    let edge: Vec<Role> = s
        .iter()
        .filter(|(p, _)| p[0].abs() > hw - 0.005)
        .map(|(_, r)| *r)
        .collect();
    assert!(!edge.is_empty(), "no samples at the edge");
    assert!(
        edge.iter().all(|r| *r == Role::Canvas),
        "a poster's edge is paper: {edge:?}"
    );
    let print = of(&s, Role::Body);
    let (x0, x1) = range(&print, 0);
    let (z0, z1) = range(&print, 2);
    assert!(
        x1 - x0 > 0.8 * size[0],
        "print spans {:.2} of {:.2} m",
        x1 - x0,
        size[0]
    );
    assert!(
        z1 - z0 > 0.6 * size[2],
        "print spans {:.2} of {:.2} m",
        z1 - z0,
        size[2]
    );
}

#[test]
fn a_mirror_wall_is_glass_edge_to_edge_in_a_thin_metal_trim() {
    // A mirror wall (a dance studio's, a gym's) is glass across the whole wall with a metal
    // edge a finger wide; before, it was drawn as a framed mirror, its wooden frame 4 cm wide
    // and a foot at the bottom. Its synonyms and a wider wall read the same.
    let kb = KnowledgeBase::builtin();
    for (category, width) in [("mirror wall", None), ("wall of mirrors", Some(6.0))] {
        let entry = kb.object(category).unwrap();
        let mut size = entry.size;
        if let Some(w) = width {
            size[0] = w;
        }
        let ps = parts(&entry.category, size).unwrap();
        let roles: Vec<Role> = ps.iter().map(|p| p.role).collect();
        assert!(
            roles
                .iter()
                .all(|r| matches!(r, Role::Canvas | Role::Metal)),
            "{category}: only glass and metal, got {roles:?}"
        );
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let (mut glass, mut metal) = (vec![], vec![]);
        for p in &ps {
            let mut s = vec![];
            p.prim.sample(0.01, &mut rng, &mut s);
            // What faces the room: the samples of faces turned to +y, weighed by their area.
            let front = s
                .iter()
                .filter(|s| s.normal()[1] > 0.9)
                .map(|s| (s.pos, s.du * s.dv));
            match p.role {
                Role::Canvas => glass.extend(front),
                _ => metal.extend(front),
            }
        }
        let pts: Vec<[f64; 3]> = glass.iter().map(|g| g.0).collect();
        let (x0, x1) = range(&pts, 0);
        let (z0, z1) = range(&pts, 2);
        assert!(
            x1 - x0 > 0.97 * size[0] && z1 - z0 > 0.97 * size[2],
            "{category}: the glass spans {:.2} x {:.2} m of {:.2} x {:.2}",
            x1 - x0,
            z1 - z0,
            size[0],
            size[2]
        );
        let area = |v: &[([f64; 3], f64)]| v.iter().map(|g| g.1).sum::<f64>();
        let share = area(&metal) / (area(&metal) + area(&glass)).max(1e-9);
        assert!(
            share < 0.05,
            "{category}: {:.0}% of the face is trim",
            100.0 * share
        );
    }
    // An ordinary wall mirror keeps its frame.
    let size = kb.object("mirror").unwrap().size;
    assert!(parts("mirror", size)
        .unwrap()
        .iter()
        .any(|p| p.role == Role::Frame));
}
