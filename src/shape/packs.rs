//! Layouts of small carried and household things that are not boxes: a backpack (a rounded pack
//! with a flap, shoulder straps and a front pocket), a bathroom scale (a flat slab with a dial),
//! a bread bin (a roll top over a base), a covered litter box (a tray under a rounded hood with
//! a door), a stack of magazines (thin covers fanned a little) and a shopping basket (a wire
//! body under two raised handles), and a sack of presents (a tied burlap sack with wrapped boxes
//! heaped out of its mouth). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::{frustum_profile, mat_mul, rot_x, rot_z, IDENTITY};
use std::f64::consts::FRAC_PI_2;

/// A roll top: an elliptic half-cylinder along x over `[-hw, hw]`, its axis at height `z`,
/// `ry` deep each way and rising `rz` above the axis (the part below lies inside what it sits
/// on).
pub fn roll_top(b: &mut Builder, role: super::materials::Role, hw: f64, z: f64, ry: f64, rz: f64) {
    b.revolved(
        role,
        0,
        [-hw, 0.0, z],
        frame_along([1.0, 0.0, 0.0]),
        rz / ry,
        frustum_profile(ry, ry, 2.0 * hw),
    );
}

/// A backpack: a pack rounded at the top and deeper at the bottom, a flap over its top, a
/// front pocket, a grab loop and two shoulder straps down its back (-y).
pub fn backpack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The pack, its back flat against the wearer (-y), its front bulging low down.
    let (rx, ry) = (0.92 * hw, 0.62 * hd);
    let yc = -hd + 0.12 * b.d + ry;
    let body_h = 0.78 * h;
    b.frustum(Body, [0.0, yc, 0.0], rx, ry, 0.8, body_h);
    b.ellipsoid(Body, [0.0, yc, body_h], [0.8 * rx, 0.8 * ry, 0.2 * h]);
    // The flap over the top, falling down the front.
    b.ellipsoid(
        Top,
        [0.0, yc + 0.05 * ry, body_h + 0.02 * h],
        [0.84 * rx, 0.86 * ry, 0.17 * h],
    );
    b.cuboid(
        Top,
        [-0.45 * rx, yc + 0.6 * ry, 0.6 * h],
        [0.45 * rx, yc + 0.86 * ry, body_h + 0.05 * h],
    );
    // The front pocket, low on the front.
    b.ellipsoid(
        Cushion,
        [0.0, yc + 0.75 * ry, 0.24 * h],
        [0.7 * rx, 0.5 * ry, 0.2 * h],
    );
    // A grab loop on top and two shoulder straps bowing out behind.
    b.polyline(
        Handle,
        &[
            [-0.2 * rx, yc - 0.3 * ry, 0.95 * h],
            [0.0, yc - 0.3 * ry, h - 0.01],
            [0.2 * rx, yc - 0.3 * ry, 0.95 * h],
        ],
        0.012,
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.45 * rx;
        b.polyline(
            Handle,
            &[
                [x, yc - 0.9 * ry, 0.88 * h],
                [x, -hd + 0.015, 0.7 * h],
                [x * 1.1, -hd + 0.015, 0.35 * h],
                [x * 1.2, yc - 0.9 * ry, 0.12 * h],
            ],
            0.014,
        );
    }
}

/// A bathroom scale: a flat slab with rounded ends, a platform on top, and a round dial with a
/// needle near its front edge.
pub fn bathroom_scale(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(
        Body,
        [-hw, -hd + 0.06 * b.d, 0.0],
        [hw, hd - 0.06 * b.d, 0.85 * h],
    );
    b.frustum(Body, [0.0, 0.0, 0.0], hw, hd, 1.0, 0.85 * h);
    b.cuboid(
        Glass,
        [-0.8 * hw, -0.85 * hd, 0.85 * h],
        [0.8 * hw, 0.45 * hd, h],
    );
    let r = (0.2 * hd).min(0.4 * hw);
    let yc = hd - 0.05 * b.d - r;
    b.cylinder(Screen, [0.0, yc, 0.85 * h], r, 0.15 * h);
    b.cylinder(Canvas, [0.0, yc, h - 0.004], 0.85 * r, 0.004);
    b.cuboid(Handle, [-0.006, yc, h - 0.002], [0.006, yc + 0.8 * r, h]);
}

/// A bread bin: a low base, a roll top over it with a knob at its front, and feet.
pub fn bread_bin(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let z = 0.45 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, z]);
    roll_top(b, Top, 0.97 * hw, z, 0.98 * hd, h - z);
    // The end caps, proud of the roll.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.01);
        b.revolved(
            Body,
            0,
            [x - 0.01, 0.0, z],
            frame_along([1.0, 0.0, 0.0]),
            (h - z) / hd,
            frustum_profile(hd, hd, 0.02),
        );
    }
    b.ellipsoid(Handle, [0.0, hd - 0.012, 0.62 * h], [0.03, 0.012, 0.012]);
}

/// A covered litter box: a deep tray, a rounded hood over it and a round door in its front.
pub fn litter_box(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tray = 0.28 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, tray]);
    let z = 0.62 * h;
    b.cuboid(
        Top,
        [-0.96 * hw, -0.96 * hd, tray],
        [0.96 * hw, 0.96 * hd, z],
    );
    roll_top(b, Top, 0.96 * hw, z, 0.96 * hd, h - z);
    // The door: a dark oval opening with a swinging flap's frame.
    let r = (0.45 * hw).min(0.38 * h);
    b.revolved(
        Interior,
        0,
        [0.0, 0.96 * hd, tray + 0.04 + r],
        frame_along([0.0, 1.0, 0.0]),
        1.0,
        frustum_profile(r, r, 0.04 * hd),
    );
    b.cuboid(
        Handle,
        [-0.3 * hw, -0.4 * hd, h - 0.02],
        [0.3 * hw, 0.4 * hd, h],
    );
}

/// A stack of magazines: thin covers, each a little turned from the one below, on white pages.
pub fn magazines(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let n = ((h / 0.008).floor() as usize).clamp(1, 5);
    let t = h / n as f64;
    for k in 0..n {
        let a: f64 = [0.0, 0.09, -0.06, 0.13, -0.1][k];
        let (s, c) = a.sin_cos();
        // Shrunk so the turned magazine stays inside the footprint.
        let (mx, my) = (
            (hw - s.abs() * hd) / c.max(0.5),
            (hd - s.abs() * hw) / c.max(0.5),
        );
        let (mx, my) = (mx.min(hw) * 0.98, my.min(hd) * 0.98);
        let z = k as f64 * t;
        b.slab(Canvas, [0.0, 0.0, z + 0.4 * t], [mx, my, 0.4 * t], rot_z(a));
        b.slab_v(
            Books,
            k as u32,
            [0.0, 0.0, z + 0.9 * t],
            [mx, my, 0.1 * t],
            rot_z(a),
        );
    }
}

/// A shopping basket: a tray, wire walls (rails round it and bars up its sides) under a rim,
/// and two handles raised to meet over the middle.
pub fn shopping_basket(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rim = 0.68 * h;
    let r = 0.005;
    b.cuboid(
        Body,
        [-0.9 * hw, -0.85 * hd, 0.0],
        [0.9 * hw, 0.85 * hd, 0.02],
    );
    // Walls flare out a little from the tray to the rim.
    let at = |z: f64| 0.9 + 0.1 * (z / rim);
    let rows = 4;
    for i in 1..=rows {
        let z = i as f64 * rim / rows as f64;
        let (x, y) = (at(z) * hw - r, at(z) * hd - r);
        let role = if i == rows { Top } else { Frame };
        let rr = if i == rows { 2.5 * r } else { r };
        b.polyline(
            role,
            &[[-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z], [-x, -y, z]],
            rr,
        );
    }
    let bars = |n: usize| n.max(2);
    let nx = bars((b.w / 0.035) as usize);
    let ny = bars((b.d / 0.035) as usize);
    for i in 0..=nx {
        let f = -1.0 + 2.0 * i as f64 / nx as f64;
        for sy in [-1.0, 1.0] {
            b.rod(
                Frame,
                [f * 0.9 * hw, sy * (0.85 * hd - r), 0.0],
                [f * (hw - r), sy * (hd - r), rim],
                r,
            );
        }
    }
    for j in 0..=ny {
        let f = -1.0 + 2.0 * j as f64 / ny as f64;
        for sx in [-1.0, 1.0] {
            b.rod(
                Frame,
                [sx * (0.9 * hw - r), f * 0.85 * hd, 0.0],
                [sx * (hw - r), f * (hd - r), rim],
                r,
            );
        }
    }
    // Handles hinged on the long sides, raised and leaning in to meet over the middle.
    for sy in [-1.0, 1.0] {
        let y0 = sy * (hd - 3.0 * r);
        let y1 = sy * 0.06 * hd;
        b.polyline(
            Handle,
            &[
                [-0.45 * hw, y0, rim],
                [-0.3 * hw, 0.5 * (y0 + y1), 0.5 * (rim + h)],
                [-0.15 * hw, y1, h - 0.012],
                [0.15 * hw, y1, h - 0.012],
                [0.3 * hw, 0.5 * (y0 + y1), 0.5 * (rim + h)],
                [0.45 * hw, y0, rim],
            ],
            0.011,
        );
    }
}

/// A sack of presents: a bulging burlap sack standing open, a cord tied round it under a mouth
/// of loose folds, wrapped boxes in bright papers with ribbons heaped out of the top.
pub fn sack_of_presents(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ay = hd / hw;
    let zb = 0.68 * h;
    b.revolved(
        Canvas,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        ay,
        vec![
            [0.0, 0.0],
            [0.8 * hw, 0.0],
            [0.98 * hw, 0.25 * zb],
            [0.97 * hw, 0.6 * zb],
            [0.82 * hw, 0.9 * zb],
            [0.74 * hw, zb],
            [0.0, zb - 0.02],
        ],
    );
    // The cord tied round under the mouth; loose folds of cloth round the rim.
    b.revolved(
        Frame,
        0,
        [0.0, 0.0, 0.9 * zb],
        IDENTITY,
        ay,
        vec![
            [0.8 * hw, 0.0],
            [0.835 * hw, 0.0],
            [0.835 * hw, 0.025 * h],
            [0.8 * hw, 0.025 * h],
        ],
    );
    for k in 0..8 {
        let a = k as f64 / 8.0 * std::f64::consts::TAU;
        let (x, y) = (0.72 * hw * a.cos(), 0.72 * hd * a.sin());
        b.ellipsoid_rot(
            Canvas,
            0,
            [x, y, zb],
            [0.16 * hw, 0.05 * hw, 0.07 * h],
            rot_z(a + FRAC_PI_2),
        );
    }
    // Presents heaped in the mouth, tilted, each with a ribbon across its top.
    let top = h - zb;
    let boxes = [
        (Cushion, 0.0, 0.05, 0.55, 0.2),
        (Top, -0.35, -0.1, 0.42, -0.4),
        (Pillow, 0.35, -0.15, 0.4, 0.7),
        (Shade, 0.1, 0.4, 0.35, 1.1),
    ];
    for (k, (role, fx, fy, s, a)) in boxes.into_iter().enumerate() {
        let e = (s * hw).min(0.32 * top);
        let c = [fx * hw, fy * hd, zb - 0.2 * e + e];
        let rot = mat_mul(&rot_z(a), &rot_x(0.2 * (k as f64 - 1.5)));
        b.slab(role, c, [e, e, e], rot);
        b.slab(Handle, c, [0.2 * e, 1.02 * e, 1.02 * e], rot);
    }
}
