//! Layouts of frames and a few small things whose archetype had another function: swings,
//! slides, climbing frames, ladders, laptops and vases. The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{Primitive, IDENTITY, V3};

/// A flat board of `width` (along x) and `thick`ness whose centre line runs from `a` to `c`
/// (both in a plane x = const).
fn plank(b: &mut Builder, role: Role, a: V3, c: V3, width: f64, thick: f64) {
    let d = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-6);
    // Local x stays the world's x (the width); z runs along the board, y = z × x.
    let z = d.map(|v| v / len);
    let y = [0.0, z[2], -z[1]];
    let rot = if z[0].abs() < 1e-9 {
        [[1.0, y[0], z[0]], [0.0, y[1], z[1]], [0.0, y[2], z[2]]]
    } else {
        frame_along(d)
    };
    b.push(
        role,
        0,
        Primitive::Cuboid {
            centre: [0, 1, 2].map(|i| 0.5 * (a[i] + c[i])),
            half: [0.5 * width, 0.5 * thick, 0.5 * len],
            rot,
        },
    );
}

/// Two rails from `(±x, y0, 0)` to `(±x, y1, top)` with rungs (round) or treads (flat).
fn ladder_frame(b: &mut Builder, x: f64, y0: f64, y1: f64, top: f64, treads: bool) {
    let r = 0.02_f64.min(0.1 * x);
    for sx in [-1.0, 1.0] {
        b.rod(Frame, [sx * x, y0, 0.0], [sx * x, y1, top], r);
    }
    let n = ((top / 0.28).floor() as usize).max(2);
    for k in 1..=n {
        let t = k as f64 / (n as f64 + 0.5);
        let (y, z) = (y0 + (y1 - y0) * t, top * t);
        if treads {
            b.cuboid(
                Seat,
                [-x + r, y - 0.06, z - 0.012],
                [x - r, y + 0.06, z + 0.012],
            );
        } else {
            b.rod(Frame, [-x, y, z], [x, y, z], 0.6 * r);
        }
    }
}

/// A swing set: an A-frame at each end, a top beam and seats hanging on chains.
pub fn swing(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.045;
    let top = h - r;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - r);
        for sy in [-1.0, 1.0] {
            b.rod(Frame, [x, sy * (hd - r), 0.0], [x, 0.0, top], r);
        }
    }
    b.rod(Top, [-hw, 0.0, top], [hw, 0.0, top], r);
    let seats = ((b.w / 1.2).floor() as usize).clamp(1, 4);
    let pitch = (b.w - 4.0 * r) / seats as f64;
    for k in 0..seats {
        let x = -hw + 2.0 * r + (k as f64 + 0.5) * pitch;
        let half = (0.22f64).min(0.35 * pitch);
        for sx in [-1.0, 1.0] {
            b.rod(
                Metal,
                [x + sx * half, 0.0, 0.45],
                [x + sx * half, 0.0, top - r],
                0.008,
            );
        }
        b.cuboid(
            Seat,
            [x - half - 0.02, -0.1, 0.4],
            [x + half + 0.02, 0.1, 0.44],
        );
    }
}

/// A playground slide: a platform on posts at the back with a ladder, a chute with side walls
/// running down to the front.
pub fn slide(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let hp = 0.6 * h;
    let (p0, p1) = (-hd + 0.25, -hd + 0.25 + 0.6f64.min(0.3 * b.d));
    let xp = 0.8 * hw;
    for x in [-xp, xp] {
        for y in [p0, p1] {
            b.rod(Frame, [x, y, 0.0], [x, y, h - 0.02], 0.03);
        }
        // Guard rails round the platform.
        b.rod(Frame, [x, p0, h - 0.03], [x, p1, h - 0.03], 0.02);
    }
    b.cuboid(Top, [-xp, p0, hp - 0.04], [xp, p1, hp]);
    ladder_frame(b, 0.7 * xp, -hd + 0.02, p0, hp, false);
    // The chute: from the platform's front edge down to a short run-out at the front.
    let cw = 0.55 * b.w;
    let (a, c) = ([0.0, p1, hp - 0.02], [0.0, hd - 0.35, 0.3]);
    plank(b, Body, a, c, cw, 0.03);
    for sx in [-1.0, 1.0] {
        let x = sx * (0.5 * cw + 0.015);
        plank(
            b,
            Body,
            [x, a[1], a[2] + 0.06],
            [x, c[1], c[2] + 0.06],
            0.03,
            0.15,
        );
    }
    b.cuboid(Body, [-0.5 * cw, hd - 0.36, 0.27], [0.5 * cw, hd, 0.31]);
    for sx in [-1.0, 1.0] {
        b.rod(
            Frame,
            [sx * 0.4 * cw, hd - 0.1, 0.0],
            [sx * 0.4 * cw, hd - 0.1, 0.27],
            0.025,
        );
    }
}

/// A climbing frame: posts on a grid, rails round it at three heights and monkey bars on top.
pub fn climbing_frame(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.03;
    let nx = ((b.w / 1.0).round() as usize).max(1);
    let ny = ((b.d / 1.0).round() as usize).max(1);
    let xs: Vec<f64> = (0..=nx)
        .map(|i| -hw + r + i as f64 * (b.w - 2.0 * r) / nx as f64)
        .collect();
    let ys: Vec<f64> = (0..=ny)
        .map(|j| -hd + r + j as f64 * (b.d - 2.0 * r) / ny as f64)
        .collect();
    for &x in &xs {
        for &y in &ys {
            b.rod(Frame, [x, y, 0.0], [x, y, h - r], r);
        }
    }
    for z in [0.35 * h, 0.7 * h, h - r] {
        for &y in [ys[0], ys[ny]].iter() {
            b.rod(Metal, [xs[0], y, z], [xs[nx], y, z], 0.7 * r);
        }
        for &x in [xs[0], xs[nx]].iter() {
            b.rod(Metal, [x, ys[0], z], [x, ys[ny], z], 0.7 * r);
        }
    }
    let bars = ((b.w / 0.3) as usize).max(2);
    for i in 1..bars {
        let x = -hw + r + i as f64 * (b.w - 2.0 * r) / bars as f64;
        b.rod(Metal, [x, ys[0], h - r], [x, ys[ny], h - r], 0.6 * r);
    }
}

/// A ladder: a step ladder (treads in front, a back frame) when deep, else a leaning ladder
/// with round rungs (blanket ladders).
pub fn ladder(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let x = hw - 0.025;
    if b.d > 0.45 {
        ladder_frame(b, x, hd - 0.03, -0.05, h - 0.03, true);
        for sx in [-1.0, 1.0] {
            b.rod(
                Frame,
                [sx * x, -hd + 0.03, 0.0],
                [sx * x, -0.1, h - 0.06],
                0.02,
            );
        }
        b.cuboid(Top, [-x, -0.15, h - 0.03], [x, 0.05, h]);
    } else {
        ladder_frame(b, x, hd - 0.03, -hd + 0.03, h, false);
    }
}

/// An open laptop: a thin base with a keyboard, the lid raised at its back with a dark screen.
pub fn laptop(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.08 * h).clamp(0.008, 0.02);
    let hinge = -hd + (0.15 * b.d).min(0.06);
    b.cuboid(Body, [-hw, hinge, 0.0], [hw, hd, t]);
    b.cuboid(
        BlackKeys,
        [-0.85 * hw, hinge + 0.02, t],
        [0.85 * hw, hinge + 0.55 * (hd - hinge), t + 0.002],
    );
    let (a, c) = ([0.0, hinge + 0.5 * t, t], [0.0, -hd + 0.5 * t, h - 0.002]);
    plank(b, Body, a, c, b.w, t);
    // The screen on the lid's face towards the user (dark like an opening: the lid stands at
    // the back, where fronts are not).
    let dy = [c[1] - a[1], c[2] - a[2]];
    let l = (dy[0] * dy[0] + dy[1] * dy[1]).sqrt().max(1e-9);
    let n = [0.0, dy[1] / l, -dy[0] / l];
    let off = 0.5 * t + 0.001;
    let lift = |p: V3, k: f64| {
        [
            p[0],
            p[1] + n[1] * off + dy[0] * k,
            p[2] + n[2] * off + dy[1] * k,
        ]
    };
    plank(b, Interior, lift(a, 0.08), lift(c, -0.06), 0.9 * b.w, 0.002);
}

/// A vase: a turned body swelling above its foot, narrowing to a neck with a flared lip; one
/// holding flowers (`Builder::goods`) is the lower part of its box, a bouquet rising from its
/// neck above it.
pub fn vase(b: &mut Builder) {
    let flowers = b.goods == Some(super::goods::Goods::Flowers);
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    let h = if flowers { 0.55 * b.h } else { b.h };
    let r = if flowers { 0.8 * hw } else { hw };
    let profile = vec![
        [0.0, 0.0],
        [0.55 * r, 0.0],
        [0.9 * r, 0.2 * h],
        [r, 0.4 * h],
        [0.8 * r, 0.65 * h],
        [0.4 * r, 0.85 * h],
        [0.38 * r, 0.93 * h],
        [0.5 * r, h],
        [0.0, h],
    ];
    b.revolved(Body, 0, [0.0, 0.0, 0.0], IDENTITY, hd / hw, profile);
    if flowers {
        super::wares::bouquet(b, 0.9 * h, 0.38 * r, b.h);
    }
}
