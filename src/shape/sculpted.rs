//! Layouts of a concert harp, a portrait bust on its plinth, an altar and a modern art
//! installation (a ring, a tipped cube and a ball on a plinth). The front faces +y, z up, the
//! bottom face's centre at the origin.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::{frustum_profile, IDENTITY, V3};

/// A concert harp, its frame in the y-z plane: a pedestal, an upright column at the front, a
/// sound box leaning back from the column's foot, a curved neck joining their tops, and
/// upright strings between the sound box and the neck (longest by the column).
pub fn harp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yc = 0.78 * hd;
    let zp = 0.07 * h;
    b.cuboid(Frame, [-0.6 * hw, -0.1 * hd, 0.0], [0.6 * hw, hd, zp]);
    // The column and its crown.
    let rc = (0.05 * h).min(0.2 * hd).min(0.5 * hw);
    b.cylinder(Frame, [0.0, yc, zp], rc, 0.88 * h - zp);
    b.ellipsoid(Frame, [0.0, yc, 0.93 * h], [1.4 * rc, 1.4 * rc, 0.07 * h]);
    // The sound box: a tapering body from the pedestal up and back.
    let foot: V3 = [0.0, 0.3 * hd, zp];
    let head: V3 = [0.0, -0.85 * hd, 0.72 * h];
    let dir = [head[0] - foot[0], head[1] - foot[1], head[2] - foot[2]];
    let len = (dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
    let rb = (0.9 * hw).min(0.12 * len);
    b.revolved(
        Frame,
        0,
        foot,
        frame_along(dir),
        0.6,
        frustum_profile(rb, 0.35 * rb, len),
    );
    // The neck: an S curve from the sound box's top to the column's top.
    let neck = |t: f64| -> V3 {
        let y = head[1] + t * (yc - head[1]);
        let z = 0.75 * h
            + t * (0.86 * h - 0.75 * h)
            + 0.06 * h * (2.0 * std::f64::consts::PI * t).sin();
        [0.0, y, z]
    };
    let pts: Vec<V3> = (0..=16).map(|i| neck(i as f64 / 16.0)).collect();
    b.polyline(Frame, &pts, 0.7 * rc);
    // Strings: upright from the sound box's face to the neck.
    let n = 18;
    for i in 0..n {
        let t = 0.04 + 0.9 * i as f64 / (n - 1) as f64;
        let y = head[1] + t * (foot[1] - head[1]);
        let s = (y - foot[1]) / (head[1] - foot[1]);
        let z0 = foot[2] + s * dir[2] + 0.5 * rb;
        let tn = (y - head[1]) / (yc - head[1]);
        let z1 = neck(tn)[2] - 0.6 * rc;
        if z1 > z0 {
            b.rod(Canvas, [0.0, y, z0], [0.0, y, z1], 0.005);
        }
    }
}

/// A portrait bust: head, neck and shoulders on a round socle, on a square stone plinth with a
/// base and a cap moulding.
pub fn bust(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The bust's share of the height: a life-size head and shoulders, about 0.6 m.
    let zb = (h - 0.6).clamp(0.35 * h, 0.75 * h);
    let s = (h - zb) / 0.6;
    let pw = 0.7 * hw.min(hd);
    b.cuboid(
        Top,
        [-hw * 0.95, -hd * 0.95, 0.0],
        [hw * 0.95, hd * 0.95, 0.08 * zb],
    );
    b.cuboid(Top, [-pw, -pw, 0.08 * zb], [pw, pw, 0.92 * zb]);
    b.cuboid(
        Top,
        [-0.9 * hw, -0.9 * hd, 0.92 * zb],
        [0.9 * hw, 0.9 * hd, zb],
    );
    // The socle, then the chest and shoulders: a flat-bottomed shell, widest at the shoulders.
    let z0 = zb + 0.07 * s;
    b.frustum(Body, [0.0, 0.0, zb], 0.3 * hw, 0.3 * hw, 0.8, 0.07 * s);
    let ay = (0.55f64).min(0.95 * hd / hw);
    b.revolved(
        Body,
        0,
        [0.0, 0.0, z0],
        IDENTITY,
        ay,
        vec![
            [0.0, 0.0],
            [0.55 * hw, 0.0],
            [0.85 * hw, 0.08 * s],
            [0.98 * hw, 0.15 * s],
            [0.9 * hw, 0.19 * s],
            [0.5 * hw, 0.24 * s],
            [0.2 * hw, 0.27 * s],
            [0.0, 0.27 * s],
        ],
    );
    // The neck and the head (an egg, a nose at its front).
    let zn = z0 + 0.24 * s;
    b.cylinder(Body, [0.0, 0.0, zn], 0.055 * s, 0.1 * s);
    let rh = [0.09 * s, 0.11 * s, 0.125 * s];
    let zh = (zn + 0.08 * s + rh[2]).min(h - rh[2]);
    b.ellipsoid(Body, [0.0, 0.01 * s, zh], rh);
    b.ellipsoid(
        Body,
        [0.0, 0.06 * s, zh - 0.07 * s],
        [0.05 * s, 0.05 * s, 0.05 * s],
    );
    b.ellipsoid(
        Body,
        [0.0, 0.01 * s + 0.97 * rh[1], zh - 0.015 * s],
        [0.014 * s, 0.03 * s, 0.028 * s],
    );
}

/// An altar: a stone block on a plinth under a white cloth that hangs down its front, with two
/// candlesticks and a cross standing on it.
pub fn altar(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.7 * h;
    b.cuboid(Top, [-hw, -hd, 0.0], [hw, hd, 0.06 * h]);
    b.cuboid(
        Body,
        [-0.94 * hw, -0.9 * hd, 0.06 * h],
        [0.94 * hw, 0.9 * hd, top],
    );
    // The cloth: over the top, down the front to a third of the height, a little down the sides.
    b.cuboid(
        Canvas,
        [-0.96 * hw, -0.92 * hd, top],
        [0.96 * hw, 0.92 * hd, top + 0.01],
    );
    b.cuboid(
        Canvas,
        [-0.96 * hw, 0.9 * hd, 0.45 * top],
        [0.96 * hw, 0.92 * hd, top],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Canvas,
            [sx * 0.94 * hw - 0.01, -0.92 * hd, 0.7 * top],
            [sx * 0.94 * hw + 0.01, 0.92 * hd, top],
        );
    }
    // Two candlesticks with lit candles and a cross between them.
    let z = top + 0.01;
    let rest = (h - z).max(0.02);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.6 * hw;
        b.frustum(Metal, [x, -0.3 * hd, z], 0.05, 0.05, 0.3, 0.45 * rest);
        b.cylinder(Canvas, [x, -0.3 * hd, z + 0.45 * rest], 0.02, 0.45 * rest);
        b.ellipsoid(
            Light,
            [x, -0.3 * hd, z + 0.95 * rest],
            [0.012, 0.012, 0.04 * rest],
        );
    }
    let arm = 0.22 * rest;
    b.cuboid(Metal, [-0.02, -0.5 * hd, z], [0.02, -0.5 * hd + 0.03, h]);
    b.cuboid(
        Metal,
        [-arm, -0.5 * hd, z + 0.6 * rest],
        [arm, -0.5 * hd + 0.03, z + 0.68 * rest],
    );
}

/// A modern art installation: on a low white plinth, a large steel ring standing upright, a
/// cube tipped onto its edge and a ball, in bold colours.
pub fn installation(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zp = 0.08 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, zp]);
    // The ring in the x-z plane towards the back.
    let rr = (0.5 * (h - zp)).min(0.85 * hw) - 0.03;
    let (cx, cy, cz) = (-0.2 * hw, -0.35 * hd, zp + rr + 0.03);
    let pts: Vec<V3> = (0..=32)
        .map(|i| {
            let a = i as f64 / 32.0 * std::f64::consts::TAU;
            [cx + rr * a.cos(), cy, cz + rr * a.sin()]
        })
        .collect();
    b.polyline(Metal, &pts, 0.03);
    // A cube tipped onto one edge, its diagonal upright, in front to the right.
    let s = 0.3 * b.w.min(b.d);
    let c = [
        0.35 * hw,
        0.25 * hd,
        zp + s * std::f64::consts::SQRT_2 / 2.0,
    ];
    let rot = super::parts::mat_mul(
        &super::parts::rot_z(0.5),
        &super::parts::rot_y(std::f64::consts::FRAC_PI_4),
    );
    b.slab(Top, c, [s / 2.0, s / 2.0, s / 2.0], rot);
    // A ball at the front left.
    let rb = 0.15 * b.w.min(b.d);
    b.ellipsoid(Cushion, [-0.45 * hw, 0.5 * hd, zp + rb], [rb, rb, rb]);
}
