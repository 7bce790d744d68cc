//! Layouts of everyday household and garden things people name that had no drawing of their
//! own (drawn as a plain box, or not read at all): an air purifier (a tall rounded tower with a
//! grille round it and an outlet on top), a knife block (a slanted wooden block with knife
//! handles out of its top), a paper towel holder (a roll on an upright post), a tricycle (a big
//! front wheel with pedals, two small back wheels), a clothesline (two T-posts with lines and
//! washing pegged on them) and a hose reel (a drum of coiled hose on an A-frame with a crank).
//! The front faces +y; each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;
use std::f64::consts::TAU;

/// An air purifier: a rounded tower (an elliptic frustum), a dark grille band round its lower
/// two thirds, the outlet grille on top and a lit control ring at the front of the top.
pub fn air_purifier(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Body, [0.0, 0.0, 0.0], hw, hd, 0.94, h);
    b.frustum(
        Interior,
        [0.0, 0.0, 0.08 * h],
        1.005 * hw,
        1.005 * hd,
        0.97,
        0.55 * h,
    );
    b.cylinder(Interior, [0.0, 0.0, h], 0.75 * hw.min(hd), 0.002);
    b.cylinder(
        Light,
        [0.0, 0.8 * 0.94 * hd, h],
        0.05 * hw.min(hd).max(0.2),
        0.003,
    );
}

/// A knife block: a wooden block leaning back on a foot, knife handles coming out of slots in
/// its sloping top, a pair of scissors' loop at the side.
pub fn knife_block(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.62 * h;
    // the block: a box tilted back, its top sloping down to the front
    let tilt = 0.35;
    let half = [0.9 * hw, 0.45 * hd, 0.5 * zt];
    b.slab(Body, [0.0, -0.05 * hd, 0.5 * zt], half, rot_x(tilt));
    b.cuboid(
        Body,
        [-0.9 * hw, -0.9 * hd, 0.0],
        [0.9 * hw, 0.9 * hd, 0.06 * h],
    );
    // the handles: out of the top along its slope, side by side
    let n = 5;
    let top = [
        0.0,
        -0.05 * hd - zt * 0.5 * tilt.sin(),
        zt * (0.5 + 0.5 * tilt.cos()),
    ];
    for k in 0..n {
        let x = (k as f64 - 0.5 * (n - 1) as f64) * 1.6 * hw / n as f64;
        let a = [x, top[1], top[2] - 0.02];
        let e = [x, a[1] - 0.3 * (h - a[2]) * tilt.tan(), h - 0.01];
        b.rod(Handle, a, e, (0.25 * hw / n as f64 * 2.0).min(0.015));
    }
}

/// A paper towel holder: a round weighted base, an upright post, the white roll on it and a
/// knob on the post's top.
pub fn towel_roll(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    b.cylinder(Metal, [0.0, 0.0, 0.0], r, 0.05 * h);
    b.cylinder(Metal, [0.0, 0.0, 0.05 * h], 0.1 * r, 0.9 * h);
    b.cylinder(Canvas, [0.0, 0.0, 0.07 * h], 0.8 * r, 0.82 * h);
    b.cylinder(Interior, [0.0, 0.0, 0.89 * h], 0.25 * r, 0.002);
    b.ellipsoid(Handle, [0.0, 0.0, 0.96 * h], [0.18 * r, 0.18 * r, 0.04 * h]);
}

/// A wheel of radius `r` turning about x at `c`: a tyre ring and a hub with spokes.
fn wheel(b: &mut Builder, c: [f64; 3], r: f64, t: f64) {
    let ring = 24;
    let pts: Vec<[f64; 3]> = (0..=ring)
        .map(|k| {
            let a = k as f64 / ring as f64 * TAU;
            [c[0], c[1] + (r - t) * a.cos(), c[2] + (r - t) * a.sin()]
        })
        .collect();
    b.polyline(Tyre, &pts, t);
    b.rod(
        Metal,
        [c[0] - 0.02, c[1], c[2]],
        [c[0] + 0.02, c[1], c[2]],
        0.15 * r,
    );
    for k in 0..6 {
        let a = k as f64 / 6.0 * TAU;
        b.rod(
            Metal,
            c,
            [c[0], c[1] + (r - t) * a.cos(), c[2] + (r - t) * a.sin()],
            0.004,
        );
    }
}

/// A child's tricycle: a big front wheel with pedals on its hub, a fork up to the handlebar,
/// a frame back to the axle of two small back wheels, a seat over them.
pub fn tricycle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rf = (0.32 * h).min(0.45 * hd);
    let rb = 0.6 * rf;
    let t = 0.12 * rf;
    let yf = hd - rf;
    wheel(b, [0.0, yf, rf], rf, t);
    let yb = -hd + rb;
    for sx in [-1.0, 1.0] {
        wheel(b, [sx * (hw - 0.03), yb, rb], rb, t);
    }
    b.rod(Metal, [-(hw - 0.03), yb, rb], [hw - 0.03, yb, rb], 0.012);
    // pedals on the front hub
    for sx in [-1.0, 1.0] {
        let p = [sx * 0.12 * hw.max(0.2), yf + sx * 0.4 * rf, rf];
        b.rod(Metal, [0.0, yf, rf], p, 0.008);
        b.cuboid(
            Handle,
            [p[0] - 0.03, p[1] - 0.02, p[2] - 0.01],
            [p[0] + 0.03, p[1] + 0.02, p[2] + 0.01],
        );
    }
    // the fork, the frame and the seat
    let zh = 0.9 * h;
    let head = [0.0, yf - 0.15 * rf, 0.75 * h];
    b.rod(Body, [0.0, yf, rf], head, 0.018);
    b.rod(Body, head, [0.0, head[1], zh], 0.015);
    b.rod(
        Handle,
        [-0.6 * hw, head[1] - 0.05, zh],
        [0.6 * hw, head[1] - 0.05, zh],
        0.014,
    );
    let seat = [0.0, yb + 0.3 * rb, 0.62 * h];
    b.polyline(
        Body,
        &[head, [0.0, 0.0, 0.45 * h], [0.0, yb, rb + 0.05]],
        0.02,
    );
    b.rod(
        Body,
        [0.0, 0.0, 0.45 * h],
        [0.0, seat[1], seat[2] - 0.03],
        0.015,
    );
    b.ellipsoid(Seat, seat, [0.14 * hw.max(0.3), 0.12 * hd.max(0.3), 0.03]);
}

/// A clothesline: a T-post at each end, lines strung between the arms, washing pegged along
/// them (towels and shirts in a few colours).
pub fn clothesline(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let x = hw - 0.04;
    let arm = 0.9 * hd;
    for sx in [-1.0, 1.0] {
        b.rod(Frame, [sx * x, 0.0, 0.0], [sx * x, 0.0, h - 0.03], 0.035);
        b.rod(
            Frame,
            [sx * x, -arm, h - 0.08],
            [sx * x, arm, h - 0.08],
            0.025,
        );
    }
    let lines = [-0.6 * arm, 0.0, 0.6 * arm];
    let zl = h - 0.1;
    for y in lines {
        b.rod(Metal, [-x, y, zl], [x, y, zl], 0.004);
    }
    // washing on the front and back lines
    let n = ((2.0 * x) / 0.55).floor().max(1.0) as usize;
    for (row, y) in [lines[0], lines[2]].into_iter().enumerate() {
        for k in 0..n {
            if (k + row) % 3 == 2 {
                continue;
            }
            let xc = -x + (k as f64 + 0.5) * 2.0 * x / n as f64;
            let wide = 0.18 + 0.06 * ((k + row) % 2) as f64;
            let long: f64 = if (k + row) % 2 == 0 { 0.55 } else { 0.7 };
            b.cuboid_v(
                Books,
                (k + 2 * row) as u32 % 4,
                [xc - wide, y - 0.004, zl - long.min(0.6 * h)],
                [xc + wide, y + 0.004, zl],
            );
            for dx in [-0.8 * wide, 0.8 * wide] {
                b.cuboid(
                    Handle,
                    [xc + dx - 0.01, y - 0.008, zl - 0.02],
                    [xc + dx + 0.01, y + 0.008, zl + 0.02],
                );
            }
        }
    }
}

/// A hose reel: an A-frame of two legs each side on the ground, a drum between them turning
/// about x with the green hose coiled on it, a crank on the right and the hose's end with its
/// nozzle lying in front.
pub fn hose_reel(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.36 * h).min(0.8 * hd);
    let zc = h - r - 0.03 * h;
    let xs = hw - 0.04;
    for sx in [-1.0, 1.0] {
        let x = sx * xs;
        for sy in [-1.0, 1.0] {
            b.rod(Frame, [x, sy * 0.85 * hd, 0.0], [x, 0.0, zc], 0.015);
        }
        b.rod(Frame, [x, -0.85 * hd, 0.02], [x, 0.85 * hd, 0.02], 0.015);
    }
    // the drum's flanges and the coiled hose between them
    let xf = 0.7 * xs;
    for sx in [-1.0, 1.0] {
        b.rod(
            Body,
            [sx * xf - 0.005, 0.0, zc],
            [sx * xf + 0.005, 0.0, zc],
            r,
        );
    }
    b.rod(Metal, [-xs, 0.0, zc], [xs, 0.0, zc], 0.02);
    let coils = ((2.0 * xf) / 0.03).floor() as usize;
    for k in 0..coils {
        let x = -xf + 0.015 + k as f64 * 0.03;
        b.rod(Pot, [x - 0.014, 0.0, zc], [x + 0.014, 0.0, zc], 0.75 * r);
    }
    // the crank on the right
    b.polyline(
        Handle,
        &[
            [xs, 0.0, zc],
            [xs + 0.02, 0.0, zc],
            [xs + 0.02, 0.0, zc + 0.5 * r],
        ],
        0.012,
    );
    // the hose's end lying out in front, its nozzle
    b.polyline(
        Pot,
        &[
            [0.0, 0.2 * r, zc - 0.75 * r],
            [0.0, 0.6 * hd, 0.03],
            [0.3 * hw, 0.85 * hd, 0.03],
        ],
        0.012,
    );
    b.rod(
        Handle,
        [0.3 * hw, 0.85 * hd, 0.03],
        [0.5 * hw, 0.95 * hd, 0.03],
        0.02,
    );
}
