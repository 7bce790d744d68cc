//! Things of a boathouse drawn as what they are: a canoe rack (two H-frames with padded arms
//! and the boats resting upside down across them, longer than the frame is deep), an oar (a
//! long shaft with a flat blade, a collar and a grip) and a fishing rod (a tapering rod with a
//! cork grip, a reel under it, line guides and its line). The rod and the oar lie along y.
use super::archetypes::{frame_along, Builder};
use super::fittings::{band, disc};
use super::materials::Role::*;
use super::parts::frustum_profile;

/// A canoe rack: two H-frames standing across the depth, each with padded arms at two
/// levels; a canoe lies upside down on the lower arms and a kayak on the upper ones.
pub fn canoe_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.05;
    let xf = 0.32 * b.w;
    let levels = [0.4 * h, 0.8 * h];
    for sx in [-1.0, 1.0] {
        let x = sx * xf;
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - 0.08);
            b.cuboid(
                Frame,
                [x - s / 2.0, y - s / 2.0, 0.0],
                [x + s / 2.0, y + s / 2.0, 0.88 * h],
            );
            b.cuboid(Frame, [x - s, y - 0.08, 0.0], [x + s, y + 0.08, 0.02]);
        }
        for z in levels {
            b.cuboid(
                Frame,
                [x - s / 2.0, -hd + 0.02, z - s],
                [x + s / 2.0, hd - 0.02, z],
            );
            // The pads the hulls rest on.
            for sy in [-1.0, 1.0] {
                let y = sy * 0.25 * b.d;
                b.cuboid(
                    Cushion,
                    [x - 0.04, y - 0.12 * b.d, z],
                    [x + 0.04, y + 0.12 * b.d, z + 0.02],
                );
            }
        }
    }
    // The hulls: long pointed shells upside down over the arms.
    let hulls = [
        (levels[0], Body, 0.8 * hd, 0.1 * h),
        (levels[1], Upholstery, 0.55 * hd, 0.07 * h),
    ];
    for (z, role, r, t) in hulls {
        let z = z + 0.02;
        hull(b, role, z + 0.2 * t, hw, r, t);
    }
}

/// A boat's hull lying along x at height `z`: `hl` half long, `r` half beam, `t` half deep,
/// pointed at both ends.
fn hull(b: &mut Builder, role: super::materials::Role, z: f64, hl: f64, r: f64, t: f64) {
    let l = 2.0 * hl;
    let profile = [
        (0.0, 0.0),
        (0.15, 0.03),
        (0.42, 0.1),
        (0.75, 0.22),
        (1.0, 0.4),
        (1.0, 0.6),
        (0.75, 0.78),
        (0.42, 0.9),
        (0.15, 0.97),
        (0.0, 1.0),
    ]
    .map(|(p, a)| [p * r, a * l])
    .to_vec();
    b.revolved(
        role,
        0,
        [-hl, 0.0, z],
        frame_along([1.0, 0.0, 0.0]),
        t / r,
        profile,
    );
}

/// An oar lying flat along y: a round shaft from a grip at -y to a flat blade at +y, with a
/// leather collar and a button where it rests in the rowlock.
pub fn oar(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let z = h / 2.0;
    let r = (0.4 * h).min(0.018);
    let blade = 0.3 * b.d;
    let yb = hd - blade;
    b.rod(Frame, [0.0, -hd + 0.12, z], [0.0, yb + 0.05, z], r);
    b.rod(Handle, [0.0, -hd, z], [0.0, -hd + 0.14, z], 0.9 * r);
    let yc = -hd + 0.32 * b.d;
    b.rod(Upholstery, [0.0, yc, z], [0.0, yc + 0.18, z], 1.15 * r);
    disc(
        b,
        Upholstery,
        [0.0, yc + 0.19, z],
        [0.0, 1.0, 0.0],
        1.6 * r,
        0.015,
    );
    // The blade: a flat loom widening towards a rounded tip.
    let t = (0.35 * h).min(0.012);
    b.slab(
        Top,
        [0.0, yb + 0.45 * blade, z],
        [0.6 * hw, 0.45 * blade, t],
        super::parts::IDENTITY,
    );
    b.slab(
        Top,
        [0.0, yb + 0.1 * blade, z],
        [0.35 * hw, 0.12 * blade, t],
        super::parts::IDENTITY,
    );
    b.ellipsoid(Top, [0.0, hd - 0.12 * blade, z], [hw, 0.12 * blade, t]);
}

/// A fishing rod lying along y: a rod tapering from the butt at -y to its tip, a cork grip, a
/// spinning reel hanging under the rod above the grip, line guides along it and the line.
pub fn fishing_rod(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let z = 0.72 * h;
    let r0 = (0.1 * h).min(0.009);
    let y0 = -hd + 0.01;
    b.revolved(
        Frame,
        0,
        [0.0, y0, z],
        frame_along([0.0, 1.0, 0.0]),
        1.0,
        frustum_profile(r0, 0.15 * r0, b.d - 0.02),
    );
    b.revolved(
        Cushion,
        0,
        [0.0, y0, z],
        frame_along([0.0, 1.0, 0.0]),
        1.0,
        frustum_profile(1.9 * r0, 1.7 * r0, 0.14 * b.d),
    );
    disc(b, Metal, [0.0, y0, z], [0.0, 1.0, 0.0], 2.0 * r0, 0.01);
    // The reel under the rod: a foot, a spool, a crank.
    let yr = y0 + 0.16 * b.d;
    let rr = (0.3 * h).min(0.7 * hw);
    b.rod(
        Metal,
        [0.0, yr, z - r0],
        [0.0, yr + 0.02, z - 0.45 * h],
        0.004,
    );
    disc(
        b,
        Metal,
        [0.0, yr + 0.01, z - 0.45 * h],
        [0.0, 1.0, 0.0],
        rr,
        0.05,
    );
    disc(
        b,
        Handle,
        [0.0, yr + 0.04, z - 0.45 * h],
        [0.0, 1.0, 0.0],
        0.7 * rr,
        0.012,
    );
    b.rod(
        Metal,
        [0.0, yr + 0.01, z - 0.45 * h],
        [0.6 * hw, yr + 0.01, z - 0.45 * h],
        0.003,
    );
    b.cylinder(Handle, [0.6 * hw, yr + 0.01, z - 0.55 * h], 0.006, 0.08 * h);
    // Guides from the reel to the tip, smaller towards it, and the line through them.
    let n = 6;
    for k in 0..n {
        let f = (k as f64 + 1.0) / (n as f64 + 0.5);
        let y = yr + f * (hd - yr - 0.05);
        let rg = 0.018 * (1.0 - 0.6 * f);
        b.rod(Metal, [0.0, y, z - r0], [0.0, y, z - r0 - rg], 0.0015);
        band(
            b,
            Metal,
            [0.0, y, z - r0 - rg - 0.5 * rg],
            [0.0, 1.0, 0.0],
            0.5 * rg + 0.003,
            0.002,
            0.002,
        );
    }
    b.rod(
        Canvas,
        [0.0, yr + 0.04, z - 0.45 * h],
        [0.0, hd - 0.01, z - 0.3 * r0],
        0.0012,
    );
}
