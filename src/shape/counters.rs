//! Counters people are served across (a shop's or a bakery's counter, a reception desk, a
//! checkout, a bar), drawn apart from a kitchen's run of base cabinets: the customer's side (the
//! front, +y) is a closed front of upright slats over a dark recessed plinth under a top that
//! overhangs it, with no doors or handles; the staff side (−y) is open bays with a shelf in
//! each. A bar has a brass foot rail along its front on brackets.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A service counter (see the module docs).
pub fn service_counter(b: &mut Builder) {
    counter_body(b, false);
}

/// A bar counter: a service counter with a foot rail along its front.
pub fn bar_counter(b: &mut Builder) {
    counter_body(b, true);
}

fn counter_body(b: &mut Builder, rail: bool) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.045_f64.min(0.06 * h);
    // The top overhangs the front by a hand's width (more over a bar's foot rail).
    let over = if rail {
        (0.18 * b.d).min(0.12)
    } else {
        (0.08 * b.d).min(0.05)
    };
    let kick = (0.1 * h).min(0.1);
    let side = 0.03_f64.min(0.1 * b.w);
    let face = hd - over;
    let panel = 0.025_f64.min(0.1 * b.d);
    let zt = h - top;
    b.cuboid(Top, [-hw, -hd, zt], [hw, hd, h]);
    // End panels, the front panel and the dark plinth set back under it.
    for x in [-hw, hw - side] {
        b.cuboid(Body, [x, -hd, 0.0], [x + side, face, zt]);
    }
    b.cuboid(
        Body,
        [-hw + side, face - panel, kick],
        [hw - side, face, zt],
    );
    b.cuboid(
        Interior,
        [-hw + side, face - panel - 0.04, 0.0],
        [hw - side, face - panel - 0.02, kick],
    );
    // Upright slats proud of the front panel, a dark gap between each two.
    let slat = 0.06;
    let n = ((b.w - 2.0 * side) / (1.6 * slat)).floor().max(1.0) as usize;
    let pitch = (b.w - 2.0 * side) / n as f64;
    let proud = (0.4 * (hd - face)).clamp(0.004, 0.015);
    for i in 0..n {
        let x0 = -hw + side + i as f64 * pitch + 0.5 * (pitch - slat.min(0.8 * pitch));
        b.cuboid(
            Door,
            [x0, face, kick + 0.02],
            [x0 + slat.min(0.8 * pitch), face + proud, zt - 0.03],
        );
    }
    // The staff side: open bays, the back of the front panel dark, a shelf and a floor board
    // in each, a divider between bays.
    let back = -hd + 0.01;
    b.cuboid(
        Interior,
        [-hw + side, face - panel - 0.002, kick],
        [hw - side, face - panel, zt],
    );
    b.cuboid(
        Top,
        [-hw + side, back, 0.0],
        [hw - side, face - panel, kick],
    );
    let zs = kick + 0.5 * (zt - kick);
    b.cuboid(
        Top,
        [-hw + side, back, zs - 0.02],
        [hw - side, face - panel, zs],
    );
    let bays = ((b.w / 0.8).round() as usize).max(1);
    for i in 1..bays {
        let x = -hw + i as f64 * b.w / bays as f64;
        b.cuboid(Body, [x - 0.01, back, kick], [x + 0.01, face - panel, zt]);
    }
    if rail {
        let (y, z, r) = (hd - 0.03, (0.2 * h).min(0.25), 0.02);
        b.rod(
            Metal,
            [-hw + side + 0.05, y, z],
            [hw - side - 0.05, y, z],
            r,
        );
        let brackets = ((b.w / 1.0).round() as usize).max(2);
        for i in 0..brackets {
            let x = -hw + side + 0.1 + i as f64 * (b.w - 2.0 * side - 0.2) / (brackets - 1) as f64;
            b.rod(Metal, [x, face + proud, z], [x, y, z], 0.5 * r);
        }
    }
}
