//! Layouts of appliances: fridges, washers (a programme dial and a porthole door with a chrome
//! ring; hoses at the back), stoves and small appliances. The front faces +y.
use super::archetypes::Builder;
use super::laundry::{porthole, service_back, BACK};
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};
use std::f64::consts::FRAC_PI_2;

/// Appliance body with the front at `hd - 0.03`; returns the front's y.
fn appliance_body(b: &mut Builder) -> f64 {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd, 0.0],
        [hw - 0.02, hd - 0.06, 0.03],
    );
    b.cuboid(Body, [-hw, -hd + BACK, 0.03], [hw, hd - 0.03, h]);
    hd - 0.03
}

/// A fridge: a freezer door over a taller fridge door (side-by-side doors when wide), a dark
/// gap between them and long bar handles standing off the doors.
pub fn fridge(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.06;
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd + BACK, 0.0],
        [hw - 0.02, face - 0.03, 0.05],
    );
    b.cuboid(Body, [-hw, -hd + BACK, 0.05], [hw, face, h]);
    super::backs::fridge_back(b);
    let door = |b: &mut Builder, x0: f64, x1: f64, z0: f64, z1: f64| {
        b.cuboid(
            Door,
            [x0 + 0.012, face, z0 + 0.012],
            [x1 - 0.012, face + 0.025, z1 - 0.012],
        );
    };
    let bar = |b: &mut Builder, x: f64, z0: f64, z1: f64| {
        let y = face + 0.025;
        // A dark recessed grip behind the bar.
        b.cuboid(Interior, [x - 0.025, y, z0], [x + 0.025, y + 0.002, z1]);
        b.rod(Handle, [x, hd - 0.016, z0], [x, hd - 0.016, z1], 0.016);
        for z in [z0 + 0.02, z1 - 0.02] {
            b.rod(Handle, [x, y, z], [x, hd - 0.016, z], 0.01);
        }
    };
    // The gap between doors shows dark.
    b.cuboid(
        Interior,
        [-hw + 0.01, face, 0.05],
        [hw - 0.01, face + 0.004, h - 0.01],
    );
    if b.w >= 0.85 {
        // Side-by-side: freezer on the left, fridge on the right, handles at the middle.
        door(b, -hw, -0.05 * b.w, 0.05, h);
        door(b, -0.05 * b.w, hw, 0.05, h);
        bar(b, -0.05 * b.w - 0.04, 0.35 * h, 0.8 * h);
        bar(b, -0.05 * b.w + 0.04, 0.35 * h, 0.8 * h);
    } else {
        let split = 0.65 * h;
        door(b, -hw, hw, split, h);
        door(b, -hw, hw, 0.05, split);
        let x = -hw + 0.07;
        bar(b, x, split + 0.04, (split + 0.3 * h).min(h - 0.05));
        bar(b, x, split - 0.35 * h, split - 0.04);
    }
}

pub fn washer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = appliance_body(b);
    b.cuboid(
        Door,
        [-hw + 0.01, y, 0.85 * h],
        [hw - 0.01, hd - 0.02, h - 0.01],
    );
    b.cuboid(
        Screen,
        [0.1 * b.w, hd - 0.02, 0.88 * h],
        [0.35 * b.w, hd - 0.015, h - 0.03],
    );
    b.revolved(
        Metal,
        0,
        [-0.25 * b.w, hd - 0.02, 0.92 * h],
        rot_x(-FRAC_PI_2),
        1.0,
        frustum_profile(0.035, 0.03, 0.015),
    );
    let r = (0.34 * b.w).min(0.32 * h);
    porthole(b, y, 0.45 * h, r, 0.75);
    service_back(b, true);
}

/// A kitchen range: a dark hob with four raised burner rings and grates, a knob strip, and an
/// oven door with a window and a bar handle over a drawer.
pub fn stove(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.04;
    let hob = (0.04 * h).clamp(0.015, 0.03);
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd, 0.0],
        [hw - 0.02, face - 0.03, 0.05],
    );
    b.cuboid(Body, [-hw, -hd, 0.05], [hw, face, h - hob]);
    b.cuboid(Top, [-hw, -hd, h - hob], [hw, face, h - 0.012]);
    // A back guard when the range is tall enough to be free-standing.
    if h > 0.6 {
        b.cuboid(Body, [-hw, -hd, h - hob], [hw, -hd + 0.04, h]);
    }
    let r = (0.16 * b.w).min(0.2 * b.d);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * 0.25 * b.w, 0.5 * (face - hd) + sy * 0.22 * b.d);
        let (x, y) = (x, y.clamp(-hd + 0.05 + r, face - r));
        let rr = if sx * sy > 0.0 { r } else { 0.75 * r };
        b.frustum(Metal, [x, y, h - 0.012], rr, rr, 0.95, 0.008);
        b.frustum(
            Interior,
            [x, y, h - 0.012],
            0.45 * rr,
            0.45 * rr,
            1.0,
            0.012,
        );
    }
    // Knob strip with four knobs.
    let zk = h - hob - 0.06;
    b.cuboid(
        Door,
        [-hw + 0.01, face, zk - 0.04],
        [hw - 0.01, face + 0.015, h - hob - 0.005],
    );
    for k in 0..4 {
        let x = -0.3 * b.w + k as f64 * 0.2 * b.w;
        b.revolved(
            Handle,
            0,
            [x, face + 0.015, zk - 0.015],
            rot_x(-FRAC_PI_2),
            1.0,
            frustum_profile(0.022, 0.018, 0.022),
        );
    }
    // Oven door with its window, and a drawer below.
    oven_door(b, face, 0.2 * h, zk - 0.05, 0.06);
}

/// An oven's door on the front face `face` (its y) from `z0` to `z1`: a dark window, a bar
/// handle on stand-offs near its top, and a drawer front below it from `drawer_z0` up.
pub(super) fn oven_door(b: &mut Builder, face: f64, z0: f64, z1: f64, drawer_z0: f64) {
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    b.cuboid(Door, [-hw + 0.01, face, z0], [hw - 0.01, face + 0.02, z1]);
    b.cuboid(
        Screen,
        [-hw + 0.08, face + 0.02, z0 + 0.06],
        [hw - 0.08, face + 0.024, z1 - 0.12],
    );
    let zh = z1 - 0.05;
    b.rod(
        Handle,
        [-hw + 0.06, hd - 0.008, zh],
        [hw - 0.06, hd - 0.008, zh],
        0.009,
    );
    for x in [-hw + 0.08, hw - 0.08] {
        b.rod(Handle, [x, face + 0.02, zh], [x, hd - 0.008, zh], 0.006);
    }
    b.cuboid(
        Door,
        [-hw + 0.01, face, drawer_z0],
        [hw - 0.01, face + 0.02, z0 - 0.01],
    );
}
