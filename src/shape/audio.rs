//! Layouts of sound gear, drawn by what a person sees of it: a loudspeaker's round cones on a
//! dark front baffle (a port below them, terminals and a rear port at the back) and a guitar
//! combo amplifier (grille cloth under a control strip of knobs, a carrying handle on top,
//! metal corners, an open back showing the speaker's magnet) and a pair of over-ear headphones
//! standing on their cups (a padded headband arching over two round cups with soft cushions
//! facing each other). The front faces +y.
use super::archetypes::Builder;
use super::fittings::{band, disc, X, Y};
use super::materials::Role::*;

/// A speaker cone of outer radius `r` at (`x`, `z`) on the front face `y`: a dark cone in a
/// rubber surround, and a metal dust cap at its centre.
pub(super) fn cone(b: &mut Builder, x: f64, y: f64, z: f64, r: f64) {
    band(b, Interior, [x, y + 0.005, z], Y, r, 0.14 * r, 0.01);
    disc(b, Screen, [x, y + 0.003, z], Y, 0.88 * r, 0.006);
    disc(b, Metal, [x, y + 0.008, z], Y, 0.28 * r, 0.01);
}

/// A floor loudspeaker: a wooden cabinet on a plinth, a dark baffle on its front with a small
/// tweeter over two woofers and a bass port below them; at the back a terminal plate with two
/// binding posts and a rear port.
pub fn speaker(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = (0.04 * h).clamp(0.02, 0.05);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, plinth]);
    let face = hd - 0.012;
    b.cuboid(
        Body,
        [-hw + 0.005, -hd + 0.005, plinth],
        [hw - 0.005, face, h],
    );
    b.cuboid(
        Interior,
        [-hw + 0.012, face, plinth + 0.01],
        [hw - 0.012, face + 0.006, h - 0.01],
    );
    let y = face + 0.006;
    let r = (0.38 * b.w).min(0.12 * h);
    let top = h - 0.02;
    let rt = 0.35 * r;
    disc(b, Metal, [0.0, y + 0.004, top - 1.6 * rt], Y, rt, 0.008);
    disc(
        b,
        Screen,
        [0.0, y + 0.008, top - 1.6 * rt],
        Y,
        0.45 * rt,
        0.006,
    );
    let mut z = top - 3.2 * rt - 1.15 * r;
    for _ in 0..2 {
        cone(b, 0.0, y, z, r);
        z -= 2.3 * r;
    }
    // The bass port: a dark round opening with a flared rim.
    let zp = (z + 0.6 * r).max(plinth + 0.6 * r);
    band(b, Metal, [0.0, y + 0.004, zp], Y, 0.45 * r, 0.08 * r, 0.008);
    disc(b, Interior, [0.0, y + 0.001, zp], Y, 0.38 * r, 0.004);
    // The back: a terminal plate with a red and a black binding post, and a rear port.
    let yb = -hd + 0.005;
    b.cuboid(
        Metal,
        [-0.3 * b.w, yb - 0.004, 0.18 * h],
        [0.3 * b.w, yb, 0.28 * h],
    );
    for (x, role) in [(-0.12 * b.w, Handle), (0.12 * b.w, BlackKeys)] {
        disc(b, role, [x, yb - 0.012, 0.23 * h], Y, 0.012, 0.016);
    }
    band(
        b,
        Metal,
        [0.0, yb - 0.004, 0.7 * h],
        Y,
        0.4 * r,
        0.08 * r,
        0.008,
    );
    disc(b, Interior, [0.0, yb - 0.001, 0.7 * h], Y, 0.33 * r, 0.003);
}

/// A guitar combo amplifier: a box covered in dark tolex with metal corners, a grille cloth
/// over most of its front, a chrome control strip of knobs along the top of the front, a
/// leather carrying handle on top; the back is open below a rail, showing the speaker's
/// magnet.
pub fn amp_combo(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let feet = 0.015;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(Tyre, [sx * (hw - 0.04), sy * (hd - 0.04), 0.0], 0.015, feet);
        }
    }
    let (z0, top) = (feet, h - 0.035);
    let t = 0.02;
    // The shell: two sides, a bottom and a top; the front and the back are panels in it.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Body, [x - t / 2.0, -hd, z0], [x + t / 2.0, hd, top]);
    }
    b.cuboid(Body, [-hw, -hd, z0], [hw, hd, z0 + t]);
    b.cuboid(Body, [-hw, -hd, top - t], [hw, hd, top]);
    let face = hd - 0.01;
    let strip = (0.2 * h).clamp(0.06, 0.12);
    b.cuboid(
        Upholstery,
        [-hw + t, face - 0.01, z0 + t],
        [hw - t, face, top - t - strip],
    );
    // The grille's piping round the cloth.
    b.cuboid(
        Canvas,
        [-hw + t, face, top - t - strip - 0.006],
        [hw - t, face + 0.003, top - t - strip],
    );
    b.cuboid(
        Metal,
        [-hw + t, face - 0.02, top - t - strip],
        [hw - t, face, top - t],
    );
    let zk = top - t - 0.5 * strip;
    let n = 6;
    for k in 0..n {
        let x = -hw + t + (k as f64 + 0.8) / (n as f64 + 0.6) * (b.w - 2.0 * t);
        disc(b, Handle, [x, face + 0.01, zk], Y, 0.017, 0.02);
        disc(b, Canvas, [x, face + 0.021, zk + 0.008], Y, 0.003, 0.002);
    }
    disc(
        b,
        Light,
        [-hw + t + 0.03, face + 0.004, zk],
        Y,
        0.007,
        0.008,
    );
    // Metal corner caps.
    let c = 0.03;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for z in [z0, top - c] {
                let (x, y) = (sx * (hw - c / 2.0), sy * (hd - c / 2.0));
                b.cuboid(
                    Metal,
                    [x - c / 2.0, y - c / 2.0, z],
                    [x + c / 2.0, y + c / 2.0, z + c],
                );
            }
        }
    }
    // The carrying handle: a strap on two end caps.
    let hl = 0.22 * b.w;
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [sx * hl - 0.02, -0.025, top],
            [sx * hl + 0.02, 0.025, top + 0.012],
        );
    }
    b.polyline(
        Frame,
        &[
            [-hl, 0.0, top + 0.008],
            [-0.6 * hl, 0.0, h - 0.012],
            [0.6 * hl, 0.0, h - 0.012],
            [hl, 0.0, top + 0.008],
        ],
        0.012,
    );
    // The back: a rail under the top, then open, the speaker's magnet seen inside.
    let yb = -hd + 0.01;
    b.cuboid(
        Body,
        [-hw + t, yb - 0.01, top - t - strip],
        [hw - t, yb, top - t],
    );
    b.cuboid(
        Interior,
        [-hw + t, face - 0.03, z0 + t],
        [hw - t, face - 0.02, top - t - strip],
    );
    let zc = 0.5 * (z0 + t + top - t - strip);
    let rm = (0.18 * b.w).min(0.2 * h);
    disc(b, Metal, [0.0, -0.2 * hd, zc], Y, rm, 0.05);
    b.cuboid(
        Body,
        [-hw + t, yb - 0.01, z0 + t],
        [hw - t, yb, z0 + t + 0.06],
    );
}

/// A pair of over-ear headphones set down upright, seen from the front: two round ear cups on
/// the sides of the box (their soft cushions facing inwards, a metal ring round each cup),
/// joined by a headband that arches over the top from one cup's yoke to the other, padded
/// under its crown.
pub fn headphones(b: &mut Builder) {
    let (hw, h) = (b.w / 2.0, b.h);
    let r_cup = (0.5 * b.d).min(0.3 * h).max(0.01);
    let t_cup = (0.22 * b.w).max(0.01);
    let zc = r_cup;
    for s in [-1.0, 1.0] {
        let xo = s * (hw - 0.5 * t_cup);
        disc(b, Body, [xo, 0.0, zc], X, r_cup, t_cup);
        band(
            b,
            Metal,
            [xo, 0.0, zc],
            X,
            0.8 * r_cup,
            0.12 * r_cup,
            0.25 * t_cup,
        );
        let xi = s * (hw - t_cup - 0.12 * t_cup);
        disc(b, Cushion, [xi, 0.0, zc], X, 0.9 * r_cup, 0.25 * t_cup);
    }
    // The headband: a half ellipse from the top of one cup's yoke to the other.
    let (ax, z0) = (hw - 0.5 * t_cup, zc + 0.6 * r_cup);
    let az = (h - z0 - 0.015).max(0.01);
    let rb = (0.08 * b.d).clamp(0.004, 0.012);
    let n = 16;
    let arc: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let a = std::f64::consts::PI * i as f64 / n as f64;
            [ax * a.cos(), 0.0, z0 + az * a.sin()]
        })
        .collect();
    b.polyline(Frame, &arc, rb);
    for s in [-1.0, 1.0] {
        b.rod(Metal, [s * ax, 0.0, zc], [s * ax, 0.0, z0], 0.8 * rb);
    }
    let pad: Vec<[f64; 3]> = (n / 2 - 3..=n / 2 + 3).map(|i| arc[i]).collect();
    let pad: Vec<[f64; 3]> = pad.iter().map(|p| [p[0], p[1], p[2] - 1.2 * rb]).collect();
    b.polyline(Cushion, &pad, 1.4 * rb);
}

/// A telephone headset: headphones at the back of its box and, from the left cup, a boom
/// microphone curving forwards and down to a foam tip in front of the mouth.
pub fn headset(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (first, d) = (b.parts.len(), b.d);
    b.d = 0.45 * d;
    headphones(b);
    b.d = d;
    let back = -hd + 0.45 * hd;
    b.translate_from(first, [0.0, back, 0.0]);
    let zc = (0.225 * d).min(0.3 * h).max(0.01);
    let x = -(hw - 0.05 * b.w);
    let r = (0.04 * hd).clamp(0.002, 0.005);
    let tip = [-0.35 * hw, hd - 0.012, 0.55 * zc];
    let boom = [
        [x, back, zc],
        [x, back + 0.6 * (tip[1] - back), 0.8 * zc],
        [0.5 * (x + tip[0]), tip[1] - 0.1 * hd, 0.62 * zc],
        tip,
    ];
    b.polyline(Frame, &boom, r);
    b.ellipsoid(Cushion, tip, [0.012, 0.012, 0.012]);
}
