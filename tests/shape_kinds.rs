//! Things drawn for their own function, checked on their parts at their knowledge-base size:
//! what hangs is clear of the floor, what holds things holds them, what comes in a set is
//! several. Host-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
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

fn of(s: &[([f64; 3], Role)], role: Role) -> Vec<[f64; 3]> {
    s.iter()
        .filter(|(_, r)| *r == role)
        .map(|(p, _)| *p)
        .collect()
}

fn range(pts: &[[f64; 3]], axis: usize) -> (f64, f64) {
    pts.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p[axis]), hi.max(p[axis]))
        })
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
    for category in ["painting", "tapestry", "hanging scroll"] {
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
