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
