//! Layouts of tall things of the coast and the sea: a lighthouse (a tapering tower in bands of
//! two colours, a door and small windows, a gallery with its railing, the glazed lantern room
//! with its light and a domed cap) and a ship's mast (a tall tapering pole with two yards
//! across it, a square sail furled under each, a crow's nest, and shrouds from the masthead
//! down to both sides). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{ellipsoid_profile, frustum_profile, IDENTITY};

/// A lighthouse.
pub fn lighthouse(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ay = hd / hw;
    let r0 = 0.8 * hw;
    let r1 = 0.5 * hw;
    let zg = 0.74 * h;
    // A low plinth, then the tower in bands.
    b.frustum(Stone, [0.0, 0.0, 0.0], hw, hd, 0.97, 0.03 * h);
    let bands = 5;
    for k in 0..bands {
        let (t0, t1) = (k as f64 / bands as f64, (k + 1) as f64 / bands as f64);
        let (za, zb) = (
            0.03 * h + t0 * (zg - 0.03 * h),
            0.03 * h + t1 * (zg - 0.03 * h),
        );
        let (ra, rb) = (r0 + (r1 - r0) * t0, r0 + (r1 - r0) * t1);
        let role = if k % 2 == 0 { Body } else { Upholstery };
        b.revolved(
            role,
            0,
            [0.0, 0.0, za],
            IDENTITY,
            ay,
            vec![[ra, 0.0], [rb, zb - za]],
        );
    }
    // A door at the foot and small windows up the front.
    let yr = |z: f64| (r0 + (r1 - r0) * (z - 0.03 * h) / (zg - 0.03 * h)) * ay;
    let dw = 0.15 * r0;
    b.cuboid(
        Door,
        [-dw, yr(0.1 * h) - 0.02, 0.03 * h],
        [dw, yr(0.03 * h) + 0.03, 0.1 * h],
    );
    for z in [0.3 * h, 0.5 * h] {
        b.cuboid(
            Interior,
            [-0.08 * r0, yr(z) - 0.02, z],
            [0.08 * r0, yr(z) + 0.03, z + 0.04 * h],
        );
    }
    // The gallery: a deck wider than the tower, a railing of posts and a rail.
    let rg = 0.95 * hw;
    b.frustum(Frame, [0.0, 0.0, zg], rg, rg * ay, 1.0, 0.015 * h);
    let zr = zg + 0.05 * h;
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, zr],
        IDENTITY,
        ay,
        vec![[rg, 0.0], [rg, 0.006 * h]],
    );
    for k in 0..16 {
        let a = std::f64::consts::TAU * k as f64 / 16.0;
        let (x, y) = (rg * a.cos(), rg * ay * a.sin());
        b.rod(
            Metal,
            [x, y, zg + 0.015 * h],
            [x, y, zr],
            0.015 * hw.min(1.0),
        );
    }
    // The lantern room: a wall, the glass with the light in it, the cap and a vane.
    let rl = 0.42 * hw;
    let zl = zg + 0.015 * h;
    b.frustum(Body, [0.0, 0.0, zl], rl, rl * ay, 1.0, 0.03 * h);
    let zglass = zl + 0.03 * h;
    let hg = 0.11 * h;
    b.revolved(
        Glass,
        0,
        [0.0, 0.0, zglass],
        IDENTITY,
        ay,
        vec![[rl, 0.0], [rl, hg]],
    );
    b.ellipsoid(
        Light,
        [0.0, 0.0, zglass + 0.5 * hg],
        [0.5 * rl, 0.5 * rl * ay, 0.35 * hg],
    );
    for k in 0..8 {
        let a = std::f64::consts::TAU * k as f64 / 8.0;
        let (x, y) = (1.01 * rl * a.cos(), 1.01 * rl * ay * a.sin());
        b.rod(Frame, [x, y, zglass], [x, y, zglass + hg], 0.02 * rl);
    }
    let zc = zglass + hg;
    b.frustum(Top, [0.0, 0.0, zc], 1.1 * rl, 1.1 * rl * ay, 1.0, 0.01 * h);
    b.revolved(
        Top,
        0,
        [0.0, 0.0, zc + 0.01 * h],
        IDENTITY,
        ay,
        ellipsoid_profile(1.05 * rl, 0.06 * h),
    );
    b.rod(Frame, [0.0, 0.0, zc + 0.06 * h], [0.0, 0.0, h], 0.04 * rl);
    b.ellipsoid(
        Frame,
        [0.0, 0.0, h - 0.01 * h],
        [0.1 * rl, 0.1 * rl, 0.01 * h],
    );
}

/// A ship's mast: a pole tapering up from a step on the deck, a lower and an upper yard across
/// it with their sails furled along them, a crow's nest between them, shrouds from near the
/// top out to both sides of the base, with ratlines across them, and a pennant at the masthead.
pub fn mast(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.025 * h).min(0.3 * hd);
    b.cuboid(
        Frame,
        [-1.6 * r, -1.6 * r, 0.0],
        [1.6 * r, 1.6 * r, 0.04 * h],
    );
    b.revolved(
        Trunk,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        frustum_profile(r, 0.45 * r, 0.97 * h),
    );
    // Yards: each a spar across the ship with a sail rolled under it and a square of sail
    // hanging from the lower one.
    let yards = [(0.45 * h, 0.98 * hw), (0.78 * h, 0.7 * hw)];
    for (z, l) in yards {
        b.rod(Trunk, [-l, 0.0, z], [l, 0.0, z], 0.4 * r);
        b.rod(
            Canvas,
            [-0.9 * l, 0.6 * r, z - 0.6 * r],
            [0.9 * l, 0.6 * r, z - 0.6 * r],
            0.55 * r,
        );
    }
    let (z0, l0) = yards[0];
    b.cuboid(
        Canvas,
        [-0.88 * l0, 0.5 * r, 0.14 * h],
        [0.88 * l0, 0.5 * r + 0.02, z0 - 1.1 * r],
    );
    // The crow's nest: a round platform with a low rim.
    let zn = 0.62 * h;
    let rn = 3.2 * r;
    b.frustum(Frame, [0.0, 0.0, zn], rn, rn.min(hd), 1.0, 0.015 * h);
    b.revolved(
        Frame,
        0,
        [0.0, 0.0, zn],
        IDENTITY,
        rn.min(hd) / rn,
        vec![[rn, 0.0], [rn, 0.04 * h]],
    );
    // Shrouds and ratlines on both sides.
    let top = 0.9 * h;
    let rr = 0.07 * r;
    for sx in [-1.0, 1.0] {
        for dy in [-0.6 * hd, 0.0, 0.6 * hd] {
            b.rod(
                BlackKeys,
                [0.0, 0.0, top],
                [sx * 0.95 * hw, dy, 0.02 * h],
                rr,
            );
        }
        for k in 1..10 {
            let t = k as f64 / 10.0;
            let z = top + (0.02 * h - top) * t;
            let x = sx * 0.95 * hw * t;
            b.rod(
                BlackKeys,
                [x, -0.6 * hd * t, z],
                [x, 0.6 * hd * t, z],
                0.6 * rr,
            );
        }
    }
    b.rod(
        BlackKeys,
        [0.0, 0.0, 0.95 * h],
        [0.0, hd - 0.01, 0.02 * h],
        rr,
    );
    b.cuboid(
        Upholstery,
        [0.0, -0.01, 0.9 * h],
        [0.4 * hw, 0.01, 0.94 * h],
    );
}
