//! The backs of kitchen appliances that a person sees when one stands free or is drawn turned
//! round, so they never read as a plain box from behind: a fridge's condenser (a black coil of
//! tube zigzagging over wire fins across most of its back) and its compressor dome at the foot,
//! (a glass-door drinks fridge has the same), a dishwasher's tub wrapped in a dark insulating
//! blanket, its drain hose looped high up its back, its hoses and cord along the floor. Both
//! draw behind a body that ends at `-hd + BACK` (`laundry.rs`).
use super::archetypes::Builder;
use super::laundry::BACK;
use super::materials::Role::*;

/// A fridge's condenser coil and compressor behind its body.
pub(super) fn fridge_back(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yb = -hd + BACK;
    let y = yb - 0.02;
    let (x0, x1) = (-0.4 * b.w, 0.4 * b.w);
    let (z0, z1) = (0.22 * h, 0.92 * h);
    // Wire fins: vertical rods on the tube, the tube running back and forth across them.
    let n = 12;
    for i in 0..=n {
        let x = x0 + (x1 - x0) * i as f64 / n as f64;
        b.rod(Interior, [x, y, z0], [x, y, z1], 0.003);
    }
    let rows = 14;
    let mut pts = vec![];
    for k in 0..=rows {
        let z = z0 + (z1 - z0) * k as f64 / rows as f64;
        let (a, c) = if k % 2 == 0 { (x0, x1) } else { (x1, x0) };
        pts.push([a, y - 0.006, z]);
        pts.push([c, y - 0.006, z]);
    }
    b.polyline(Interior, &pts, 0.006);
    // Brackets holding the coil off the back.
    for (x, z) in [(x0, z0), (x1, z0), (x0, z1), (x1, z1)] {
        b.rod(Metal, [x, yb, z], [x, y, z], 0.005);
    }
    // The compressor: a black dome on a bracket at the foot, its pipes running up.
    let (cx, cr) = (-0.2 * b.w, (0.14 * b.w).min(0.1));
    b.cuboid(Metal, [-hw + 0.04, -hd, 0.02], [hw - 0.04, yb, 0.04]);
    b.ellipsoid(
        Interior,
        [cx, -hd + cr, 0.04 + 0.8 * cr],
        [cr, cr.min(BACK + 0.5 * cr), 0.8 * cr],
    );
    b.polyline(
        Metal,
        &[
            [cx + cr, -hd + 0.02, 0.08],
            [0.3 * b.w, -hd + 0.02, 0.12],
            [0.3 * b.w, y, z0],
        ],
        0.005,
    );
}

/// A dishwasher's back: the tub in a dark insulating blanket, the drain and inlet hoses and the
/// cord leaving along the floor to one side.
pub(super) fn dishwasher_back(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yb = -hd + BACK;
    // The blanket wraps the tub in two panels over the back and round the top, short of the
    // base, either side of the drain hose's high loop; straps hold each panel.
    let g = 0.06_f64.min(0.1 * b.w);
    for (x0, x1) in [(-hw + 0.03, -g), (g, hw - 0.03)] {
        b.cuboid(Interior, [x0, yb - 0.012, 0.2 * h], [x1, yb, h - 0.03]);
        b.cuboid(Interior, [x0, yb, h - 0.012], [x1, 0.4 * hd, h - 0.004]);
        for z in [0.45 * h, 0.75 * h] {
            b.cuboid(Metal, [x0, yb - 0.016, z], [x1, yb - 0.012, z + 0.02]);
        }
    }
    b.polyline(
        Handle,
        &[
            [0.0, yb - 0.012, 0.15 * h],
            [0.0, yb - 0.014, 0.85 * h],
            [0.0, yb - 0.02, 0.9 * h],
        ],
        0.012,
    );
    // Hoses and cord along the floor to the left.
    let yc = -hd + 0.015;
    for (k, role) in [(0.0, Frame), (0.05, Handle), (0.1, Frame)] {
        b.polyline(
            role,
            &[
                [0.25 * b.w - k, yb, 0.12 * h],
                [0.25 * b.w - k, yc, 0.03],
                [-hw + 0.02, yc, 0.03 + k * 0.1],
            ],
            0.01,
        );
    }
}
