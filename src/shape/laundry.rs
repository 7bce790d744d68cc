//! Layouts of appliances told apart by one working part, and the back every tall appliance
//! shows: a washer's porthole (a round door with a chrome ring round its window), a wall
//! oven (a built-in oven with no hob: a control strip with knobs and a clock, a tall window door
//! under a bar handle, a warming drawer) and the service back (a screwed panel, a power cord
//! and, for a washer, its inlet and drain hoses). The front faces +y; backs at -y.
use super::archetypes::Builder;
use super::fittings::{band, disc, Y};
use super::materials::Role::*;

/// How far a tall appliance's body is set in from the back of its size box, leaving room for
/// the hoses and ducts of its back.
pub(super) const BACK: f64 = 0.04;

/// The back of an appliance whose body ends at `-hd + BACK`: a screwed service panel, a power
/// cord falling to the floor and, when `hoses`, a washer's hot and cold inlet hoses and its
/// drain hose hooked over the top.
pub(super) fn service_back(b: &mut Builder, hoses: bool) {
    let (hd, h) = (b.d / 2.0, b.h);
    let yb = -hd + BACK;
    b.cuboid(
        Frame,
        [-0.3 * b.w, yb - 0.004, 0.35 * h],
        [0.3 * b.w, yb, 0.8 * h],
    );
    for (x, z) in [(-0.27, 0.38), (0.27, 0.38), (-0.27, 0.77), (0.27, 0.77)] {
        disc(b, Metal, [x * b.w, yb - 0.006, z * h], Y, 0.008, 0.004);
    }
    let yc = -hd + 0.015;
    b.polyline(
        Frame,
        &[
            [0.35 * b.w, yb, 0.15 * h],
            [0.35 * b.w, yc, 0.12 * h],
            [0.4 * b.w, yc, 0.01],
        ],
        0.006,
    );
    if hoses {
        for x in [-0.32 * b.w, -0.22 * b.w] {
            b.polyline(
                Handle,
                &[[x, yb, 0.9 * h], [x, yc, 0.88 * h], [x + 0.03, yc, 0.02]],
                0.01,
            );
        }
        b.polyline(
            Frame,
            &[
                [0.1 * b.w, yb, 0.1 * h],
                [0.1 * b.w, yc, 0.1 * h],
                [0.1 * b.w, yc, 0.97 * h],
                [0.2 * b.w, yc, h - 0.012],
            ],
            0.012,
        );
    }
}

/// A round door with a chrome ring, radius `r`, centred at height `zc` on the face `y`; its
/// window is `glass` of the radius (dark), the rest the door's colour.
pub(super) fn porthole(b: &mut Builder, y: f64, zc: f64, r: f64, glass: f64) {
    disc(b, Door, [0.0, y + 0.01, zc], Y, r, 0.02);
    band(b, Metal, [0.0, y + 0.022, zc], Y, r, 0.18 * r, 0.008);
    disc(b, Screen, [0.0, y + 0.022, zc], Y, glass * r, 0.006);
}

/// A wall oven: a steel box with no hob, a dark control strip with two knobs and a lit clock
/// along its top, a tall door with a wide window under a bar handle, a warming drawer below.
pub fn wall_oven(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.03;
    b.cuboid(Body, [-hw, -hd + BACK, 0.0], [hw, face, h]);
    let strip = (0.12 * h).clamp(0.08, 0.12);
    b.cuboid(
        Screen,
        [-hw + 0.01, face, h - strip],
        [hw - 0.01, face + 0.01, h - 0.01],
    );
    for sx in [-1.0, 1.0] {
        disc(
            b,
            Metal,
            [sx * 0.3 * b.w, face + 0.02, h - 0.5 * strip],
            Y,
            0.025,
            0.02,
        );
    }
    b.cuboid(
        Light,
        [-0.08, face + 0.01, h - 0.65 * strip],
        [0.08, face + 0.013, h - 0.35 * strip],
    );
    let z0 = 0.25 * h;
    super::appliances::oven_door(b, face, z0, h - strip - 0.02, 0.03);
    b.rod(
        Handle,
        [-0.25 * b.w, hd - 0.006, z0 - 0.06],
        [0.25 * b.w, hd - 0.006, z0 - 0.06],
        0.008,
    );
    service_back(b, false);
}

/// How far a dryer's body is set in from the back of its size box: room for its vent duct.
const DRYER_BACK: f64 = 0.075;

/// A tumble dryer: a white box with a control panel along its top holding one big programme
/// dial and a small display, a large dark round door set high on its front, a lint filter slot
/// under the door; at the back a service panel, a power cord and the wide vent duct that
/// carries its damp air out.
pub fn dryer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.03;
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd + DRYER_BACK, 0.0],
        [hw - 0.02, face - 0.03, 0.03],
    );
    b.cuboid(Body, [-hw, -hd + DRYER_BACK, 0.03], [hw, face, h]);
    let panel = (0.15 * h).clamp(0.08, 0.13);
    b.cuboid(
        Top,
        [-hw + 0.01, face, h - panel],
        [hw - 0.01, hd - 0.015, h - 0.01],
    );
    disc(
        b,
        Metal,
        [0.05 * b.w, hd - 0.005, h - 0.5 * panel],
        Y,
        0.38 * panel,
        0.02,
    );
    disc(
        b,
        Frame,
        [0.05 * b.w, hd, h - 0.5 * panel],
        Y,
        0.1 * panel,
        0.004,
    );
    b.cuboid(
        Screen,
        [0.22 * b.w, hd - 0.015, h - 0.65 * panel],
        [0.4 * b.w, hd - 0.012, h - 0.35 * panel],
    );
    // The door: large and dark, set high, a thin chrome rim round a smoked window.
    let r = (0.36 * b.w).min(0.27 * h);
    let zc = h - panel - 0.02 - r;
    disc(b, Door, [0.0, face + 0.012, zc], Y, r, 0.024);
    band(b, Metal, [0.0, face + 0.025, zc], Y, r, 0.06 * r, 0.006);
    disc(b, Screen, [0.0, face + 0.025, zc], Y, 0.62 * r, 0.006);
    b.cuboid(
        Metal,
        [0.78 * r, face + 0.02, zc - 0.2 * r],
        [0.9 * r, face + 0.035, zc + 0.2 * r],
    );
    // The lint filter slot under the door, and the kick plate.
    let zl = (zc - r - 0.04).max(0.1);
    b.cuboid(
        Interior,
        [-0.3 * b.w, face, zl - 0.025],
        [0.3 * b.w, face + 0.004, zl],
    );
    b.cuboid(
        Frame,
        [-0.06, face + 0.004, zl - 0.02],
        [0.06, face + 0.012, zl - 0.005],
    );
    b.cuboid(
        Frame,
        [-hw + 0.01, face, 0.03],
        [hw - 0.01, face + 0.006, 0.09],
    );
    // The back: a panel and cord, and the vent collar with its duct bent to the floor.
    let yb = -hd + DRYER_BACK;
    b.cuboid(
        Frame,
        [-0.3 * b.w, yb - 0.004, 0.5 * h],
        [0.3 * b.w, yb, 0.85 * h],
    );
    b.polyline(
        Frame,
        &[
            [0.4 * b.w, yb, 0.15 * h],
            [0.4 * b.w, -hd + 0.01, 0.1 * h],
            [0.42 * b.w, -hd + 0.01, 0.01],
        ],
        0.006,
    );
    let rd = 0.45 * DRYER_BACK;
    let (xv, zv) = (-0.15 * b.w, 0.3 * h);
    disc(b, Metal, [xv, yb - 0.005, zv], Y, 1.25 * rd, 0.01);
    let yd = -hd + rd + 0.002;
    let duct = [
        [xv, yb, zv],
        [xv, yd, zv],
        [xv - 0.1 * b.w, yd, 0.15 * h],
        [xv - 0.2 * b.w, yd, rd],
    ];
    b.polyline(Handle, &duct, rd);
    for w in duct[1..].windows(2) {
        for f in [0.25, 0.5, 0.75] {
            let p = [0, 1, 2].map(|i| w[0][i] + f * (w[1][i] - w[0][i]));
            let d = [0, 1, 2].map(|i| w[1][i] - w[0][i]);
            band(b, Handle, p, d, rd * 1.08, 0.2 * rd, 0.012);
        }
    }
}
