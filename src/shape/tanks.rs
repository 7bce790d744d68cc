//! Tanks and towers that are more than a tube: an air compressor (a tank lying on wheels and a
//! foot, a motor and pump on top, a pressure gauge and a handle), a grain silo (a ribbed steel
//! drum under a conical roof, a caged ladder up its front, a chute at its foot) and a reactor
//! core (a glowing column in a cage of rings on a plinth, pipes from its cap). The front +y.
use super::archetypes::{frame_along, Builder};
use super::fittings::{band, disc, X, Y};
use super::materials::Role::*;
use super::parts::frustum_profile;

const Z: [f64; 3] = [0.0, 0.0, 1.0];

/// An air compressor: a tank lying along x on two wheels at one end and a rubber foot at the
/// other, a motor and a finned pump on a plate over it, a belt guard, a pressure gauge and a
/// hose outlet on the front, and a handle rising from the wheel end.
pub fn compressor(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rw = (0.16 * h).min(0.3 * b.d).max(0.04);
    let rt = (0.45 * hd).min(0.22 * h);
    let zt = rt + 0.05;
    let xe = hw - 0.06;
    b.revolved(
        Body,
        0,
        [-xe + rt * 0.2, 0.0, zt],
        frame_along(X),
        1.0,
        vec![
            [0.0, 0.0],
            [0.8 * rt, 0.0],
            [rt, 0.2 * rt],
            [rt, 2.0 * xe - 0.6 * rt],
            [0.8 * rt, 2.0 * xe - 0.4 * rt],
            [0.0, 2.0 * xe - 0.4 * rt],
        ],
    );
    // Wheels at -x, a foot at +x.
    for sy in [-1.0, 1.0] {
        let y = sy * (hd - 0.03);
        disc(b, Tyre, [-hw + rw, y, rw], Y, rw, 0.04);
        disc(
            b,
            Metal,
            [-hw + rw, y + sy * 0.021, rw],
            Y,
            0.45 * rw,
            0.004,
        );
    }
    b.rod(
        Metal,
        [-hw + rw, -hd + 0.05, rw],
        [-hw + rw, hd - 0.05, rw],
        0.012,
    );
    b.cuboid(
        Tyre,
        [hw - 0.16, -0.35 * b.d, 0.0],
        [hw - 0.1, 0.35 * b.d, zt - 0.8 * rt],
    );
    // A plate on the tank, the motor and the pump on it.
    let zp = zt + rt;
    b.cuboid(
        Metal,
        [-0.35 * b.w, -0.6 * hd, zp - 0.01],
        [0.35 * b.w, 0.6 * hd, zp + 0.01],
    );
    let rm = (0.16 * h).min(0.5 * hd);
    b.revolved(
        Frame,
        0,
        [-0.3 * b.w, -0.2 * hd, zp + rm],
        frame_along(X),
        1.0,
        frustum_profile(rm, rm, 0.3 * b.w),
    );
    let (xp, zpp) = (0.15 * b.w, zp + 0.01);
    let hp = (h - zpp - 0.02).max(0.05);
    for k in 0..5 {
        let z = zpp + (k as f64 + 0.5) / 5.0 * 0.6 * hp;
        disc(b, Metal, [xp, -0.2 * hd, z], Z, 0.6 * rm, 0.01);
    }
    b.cylinder(Metal, [xp, -0.2 * hd, zpp], 0.35 * rm, 0.7 * hp);
    b.cuboid(
        Canvas,
        [0.0, 0.3 * hd, zpp],
        [0.05 * b.w, 0.55 * hd, zpp + 0.6 * hp],
    );
    // The belt guard between motor and pump, at the back.
    b.cuboid(
        Handle,
        [-0.3 * b.w, -0.8 * hd, zpp],
        [0.25 * b.w, -0.6 * hd, zpp + 0.9 * rm * 2.0],
    );
    // The gauge on the front, on a short pipe, and the outlet.
    let (xg, zg) = (0.3 * b.w, zp + 0.06);
    let rg = (0.045_f64).min(0.2 * hd);
    b.rod(Metal, [xg, 0.3 * hd, zp], [xg, 0.55 * hd, zg], 0.008);
    disc(b, Metal, [xg, hd - 0.03, zg], Y, rg, 0.03);
    disc(b, Canvas, [xg, hd - 0.013, zg], Y, 0.85 * rg, 0.004);
    b.rod(
        BlackKeys,
        [xg, hd - 0.01, zg],
        [xg + 0.6 * rg, hd - 0.01, zg + 0.4 * rg],
        0.003,
    );
    b.rod(
        Metal,
        [0.15 * b.w, 0.5 * hd, zp],
        [0.15 * b.w, hd - 0.02, zp - 0.02],
        0.012,
    );
    // The handle: up from the wheel end over the motor.
    b.polyline(
        Metal,
        &[
            [-hw + 0.12, -0.5 * hd, zt],
            [-hw + 0.04, -0.5 * hd, h - 0.02],
            [-hw + 0.04, 0.5 * hd, h - 0.02],
            [-hw + 0.12, 0.5 * hd, zt],
        ],
        0.012,
    );
}

/// A grain silo: a ribbed steel drum on a concrete ring, a conical roof with a vent cap, a
/// caged ladder up its front and an unloading chute at its foot.
pub fn silo(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.85 * hw.min(hd);
    let base = 0.03 * h;
    b.cylinder(Stone, [0.0, 0.0, 0.0], hw.min(hd), base);
    let wall = 0.78 * h;
    b.cylinder(Body, [0.0, 0.0, base], r, wall - base);
    let n = 10;
    for k in 1..n {
        let z = base + k as f64 / n as f64 * (wall - base);
        band(
            b,
            Metal,
            [0.0, 0.0, z],
            Z,
            r + 0.015 * r,
            0.03 * r,
            0.015 * h,
        );
    }
    let cap = 0.05 * h;
    b.frustum(
        Top,
        [0.0, 0.0, wall],
        r * 1.02,
        r * 1.02,
        0.12,
        h - wall - cap,
    );
    b.cylinder(Metal, [0.0, 0.0, h - cap], 0.1 * r, cap);
    b.frustum(
        Top,
        [0.0, 0.0, h - 0.3 * cap],
        0.2 * r,
        0.2 * r,
        0.3,
        0.3 * cap,
    );
    // The ladder up the front, with hoops of its cage.
    let y = 1.06 * r;
    let lw = 0.12 * r;
    for sx in [-1.0, 1.0] {
        b.rod(
            Frame,
            [sx * lw, y, base],
            [sx * lw, y, wall + 0.02 * h],
            0.012 * r,
        );
    }
    let rungs = 18;
    for k in 0..rungs {
        let z = base + (k as f64 + 0.5) / rungs as f64 * (wall - base);
        b.rod(Frame, [-lw, y, z], [lw, y, z], 0.008 * r);
        if k > 3 && k % 2 == 0 {
            b.polyline(
                Frame,
                &[
                    [-lw, y, z],
                    [-lw, y + 0.1 * r, z],
                    [lw, y + 0.1 * r, z],
                    [lw, y, z],
                ],
                0.008 * r,
            );
        }
    }
    // The chute at the foot, to one side of the ladder.
    b.polyline(
        Metal,
        &[
            [0.5 * r, 0.6 * r, 0.12 * h],
            [0.6 * r, 0.8 * r, 0.08 * h],
            [0.65 * r, 0.9 * r, 0.04 * h],
        ],
        0.06 * r,
    );
}

/// A reactor core: a stepped plinth, a glowing column in a cage of four pillars and metal
/// rings, a domed cap with pipes running down to the plinth.
pub fn reactor_core(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    b.cylinder(Metal, [0.0, 0.0, 0.0], r, 0.06 * h);
    b.cylinder(Frame, [0.0, 0.0, 0.06 * h], 0.85 * r, 0.05 * h);
    let (z0, z1) = (0.11 * h, 0.82 * h);
    b.cylinder(Light, [0.0, 0.0, z0], 0.45 * r, z1 - z0);
    for k in 0..5 {
        let z = z0 + (k as f64 + 0.5) / 5.0 * (z1 - z0);
        band(b, Metal, [0.0, 0.0, z], Z, 0.6 * r, 0.1 * r, 0.03 * h);
    }
    for k in 0..4 {
        let a = std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
        let (x, y) = (0.72 * r * a.cos(), 0.72 * r * a.sin());
        b.cylinder(Frame, [x, y, z0], 0.07 * r, z1 - z0);
    }
    b.cylinder(Frame, [0.0, 0.0, z1], 0.85 * r, 0.04 * h);
    b.ellipsoid(
        Metal,
        [0.0, 0.0, z1 + 0.04 * h],
        [0.7 * r, 0.7 * r, h - z1 - 0.04 * h],
    );
    for k in 0..3 {
        let a = 0.4 + k as f64 * 2.1;
        let (c, s) = (a.cos(), a.sin());
        b.polyline(
            Handle,
            &[
                [0.6 * r * c, 0.6 * r * s, z1 + 0.06 * h],
                [0.95 * r * c, 0.95 * r * s, z1],
                [0.95 * r * c, 0.95 * r * s, 0.11 * h],
            ],
            0.05 * r,
        );
    }
}

/// A steel bollard: a stout post on a bolted base flange, a domed cap and two reflective bands
/// under it.
pub fn bollard(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = 0.62 * m;
    b.cylinder(Metal, [0.0, 0.0, 0.0], m, 0.025);
    for k in 0..4 {
        let a = std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
        b.cylinder(
            Frame,
            [0.8 * m * a.cos(), 0.8 * m * a.sin(), 0.025],
            0.1 * m,
            0.015,
        );
    }
    let top = h - r;
    b.cylinder(Body, [0.0, 0.0, 0.025], r, top - 0.025);
    b.ellipsoid(Top, [0.0, 0.0, top], [r, r, r]);
    for z in [0.62, 0.78] {
        band(
            b,
            Canvas,
            [0.0, 0.0, z * h],
            Z,
            1.03 * r,
            0.05 * r,
            0.08 * h,
        );
    }
}
