//! Layouts of structures people name outdoors and in play rooms: tents, water in a rim,
//! bridges, towers on legs, small castles, post lanterns and palms. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::IDENTITY;
use std::f64::consts::{PI, TAU};

/// A ridge tent: two sloped canvas roofs meeting at a ridge along y, triangular end walls and a
/// dark door opening at the front.
pub fn tent(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let n = 14;
    // Each roof is a stack of thin slats from the eave (x = ±hw, z = 0) to the ridge.
    for sx in [-1.0, 1.0] {
        for i in 0..n {
            let (t0, t1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
            let (x0, x1) = (sx * hw * (1.0 - t0), sx * hw * (1.0 - t1));
            let (z0, z1) = (h * t0, h * t1);
            b.cuboid(
                Shade,
                [x0.min(x1), -hd, z0],
                [x0.max(x1) + 0.002, hd, z1.max(z0 + 0.002)],
            );
        }
    }
    // End walls: stacked strips narrowing to the ridge; the front one has a door.
    for (sy, door) in [(-1.0, false), (1.0, true)] {
        for i in 0..n {
            let (t0, t1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
            let half = hw * (1.0 - t1);
            let y = sy * (hd - 0.004);
            let role = if door && t1 <= 0.7 { Interior } else { Canvas };
            let dw = if door {
                0.32 * hw * (1.0 - t1 / 0.7)
            } else {
                0.0
            };
            if role == Interior {
                b.cuboid(Canvas, [-half, y - 0.002, h * t0], [-dw, y + 0.002, h * t1]);
                b.cuboid(Canvas, [dw, y - 0.002, h * t0], [half, y + 0.002, h * t1]);
                b.cuboid(Interior, [-dw, y - 0.003, h * t0], [dw, y + 0.001, h * t1]);
            } else {
                b.cuboid(
                    Canvas,
                    [-half, y - 0.002, h * t0],
                    [half, y + 0.002, h * t1],
                );
            }
        }
    }
    b.rod(Frame, [0.0, -hd, h], [0.0, hd, h], 0.015);
}

/// Water in a rim: a low stone or tiled coping around a water surface a little below its top;
/// round when the footprint is square-ish, rectangular otherwise (a pool).
pub fn water(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rim = (0.08 * hw.min(hd)).clamp(0.08, 0.35);
    let round = (b.w / b.d).max(b.d / b.w) < 1.6 && b.w.max(b.d) < 5.0;
    // A tall object (a fountain, a font) is a low basin with a central column and a bowl on top.
    let tall = h > 0.5 * b.w.min(b.d) && h > 0.6;
    let wall = if tall { (0.3 * h).clamp(0.3, 0.5) } else { h };
    let surface = 0.75 * wall;
    if round {
        // A ring wall (outer side, top, inner side down to the water) and the water disc.
        let ri = (hw - rim) / hw;
        let ay = hd / hw;
        // A closed solid of revolution from the axis: base, outer wall, rim top, inner wall down
        // to the water level, and the water's bed there.
        let ring = vec![
            [0.0, 0.0],
            [hw, 0.0],
            [hw, wall],
            [ri * hw, wall],
            [ri * hw, surface - 0.01],
            [0.0, surface - 0.01],
        ];
        b.revolved(Top, 0, [0.0, 0.0, 0.0], IDENTITY, ay, ring);
        b.frustum(
            Water,
            [0.0, 0.0, surface - 0.01],
            ri * hw,
            ri * hd,
            1.0,
            0.012,
        );
    } else {
        b.cuboid(
            Water,
            [-hw + rim, -hd + rim, surface - 0.01],
            [hw - rim, hd - rim, surface],
        );
        for (lo, hi) in [
            ([-hw, -hd, 0.0], [hw, -hd + rim, wall]),
            ([-hw, hd - rim, 0.0], [hw, hd, wall]),
            ([-hw, -hd + rim, 0.0], [-hw + rim, hd - rim, wall]),
            ([hw - rim, -hd + rim, 0.0], [hw, hd - rim, wall]),
        ] {
            b.cuboid(Top, lo, hi);
        }
    }
    if tall {
        let m = hw.min(hd);
        b.cylinder(Top, [0.0, 0.0, 0.0], 0.12 * m, h - 0.12 * h);
        let bowl = vec![
            [0.0, h - 0.2 * h],
            [0.45 * m, h - 0.2 * h],
            [0.6 * m, h - 0.05 * h],
        ];
        b.revolved(Top, 0, [0.0, 0.0, 0.0], IDENTITY, hd / hw, bowl);
        b.frustum(
            Water,
            [0.0, 0.0, h - 0.08 * h],
            0.56 * m,
            0.56 * hd.min(hw),
            1.0,
            0.01,
        );
        b.frustum(
            Water,
            [0.0, 0.0, h - 0.08 * h],
            0.05 * m,
            0.05 * m,
            0.3,
            0.08 * h - 0.005,
        );
    }
}

/// A footbridge along y: an arched deck of planks on two stringers, hand rails on posts.
pub fn bridge(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rail_h = (0.45 * h).min(0.9);
    let rise = (h - rail_h - 0.06).max(0.05);
    let deck = |y: f64| rise * (1.0 - (y / hd).powi(2)).max(0.0);
    let n = ((b.d / 0.15) as usize).max(6);
    for i in 0..n {
        let y0 = -hd + i as f64 * b.d / n as f64;
        let y1 = y0 + 0.9 * b.d / n as f64;
        let z = deck(0.5 * (y0 + y1));
        b.cuboid_v(
            Top,
            (i % 3) as u32,
            [-hw + 0.05, y0, z],
            [hw - 0.05, y1, z + 0.05],
        );
    }
    let posts = ((b.d / 0.9) as usize).max(2) + 1;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.04);
        let mut prev: Option<[f64; 3]> = None;
        for i in 0..posts {
            let y = -hd + 0.04 + i as f64 * (b.d - 0.08) / (posts - 1) as f64;
            let z = deck(y);
            b.cuboid(
                Frame,
                [x - 0.04, y - 0.04, 0.0],
                [x + 0.04, y + 0.04, z + 0.05 + rail_h],
            );
            let top = [x, y, z + 0.05 + rail_h];
            if let Some(p) = prev {
                b.rod(Frame, p, top, 0.03);
                b.rod(
                    Frame,
                    [p[0], p[1], p[2] - 0.5 * rail_h],
                    [top[0], top[1], top[2] - 0.5 * rail_h],
                    0.02,
                );
            }
            prev = Some(top);
        }
    }
}

/// A tower on four splayed legs with braces, a platform with a railing, a hut and a roof, and a
/// ladder at the front (lifeguard towers, watch towers, tree-house platforms).
pub fn tower(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let deck = 0.5 * h;
    let top = 0.7 * hw.min(hd);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let foot = [sx * (hw - 0.06), sy * (hd - 0.06), 0.0];
            let head = [sx * top, sy * top, deck];
            b.rod(Frame, foot, head, 0.05);
            let mid = [0, 1, 2].map(|k| 0.5 * (foot[k] + head[k]));
            b.rod(Frame, mid, [-sx * mid[0], mid[1], mid[2]], 0.025);
        }
    }
    b.cuboid(
        Top,
        [-top - 0.1, -top - 0.1, deck],
        [top + 0.1, top + 0.1, deck + 0.08],
    );
    let hut = 0.75 * top;
    b.cuboid(
        Body,
        [-hut, -hut, deck + 0.08],
        [hut, hut, deck + 0.08 + 0.55 * (h - deck)],
    );
    let wz = deck + 0.08 + 0.25 * (h - deck);
    b.cuboid(
        Interior,
        [-0.6 * hut, hut, wz],
        [0.6 * hut, hut + 0.004, wz + 0.2 * (h - deck)],
    );
    let rz = deck + 0.08 + 0.55 * (h - deck);
    b.frustum(Shade, [0.0, 0.0, rz], top + 0.15, top + 0.15, 0.05, h - rz);
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [sx * 0.22, hd - 0.05, 0.0],
            [sx * 0.22, top + 0.1, deck + 0.08],
            0.02,
        );
    }
    for i in 1..8 {
        let t = i as f64 / 8.0;
        let y = hd - 0.05 + t * (top + 0.15 - hd);
        b.rod(Metal, [-0.22, y, t * deck], [0.22, y, t * deck], 0.015);
    }
}

/// A small castle: a walled base, four round corner towers with conical caps and a keep.
pub fn castle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.22 * hw.min(hd);
    b.cuboid(Body, [-hw + r, -hd + r, 0.0], [hw - r, hd - r, 0.4 * h]);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let c = [sx * (hw - r), sy * (hd - r), 0.0];
            b.cylinder(Body, c, r, 0.6 * h);
            b.frustum(Top, [c[0], c[1], 0.6 * h], 1.1 * r, 1.1 * r, 0.05, 0.25 * h);
        }
    }
    b.cuboid(
        Body,
        [-0.4 * hw, -0.4 * hd, 0.4 * h],
        [0.4 * hw, 0.4 * hd, 0.75 * h],
    );
    b.frustum(
        Top,
        [0.0, 0.0, 0.75 * h],
        0.3 * hw,
        0.3 * hd,
        0.05,
        0.25 * h,
    );
    b.cuboid(
        Interior,
        [-0.15 * hw, hd - r - 0.004, 0.0],
        [0.15 * hw, hd - r, 0.25 * h],
    );
}

/// A post lantern: a plinth or base, a post, a lamp housing with lit panes and a roof (stone
/// lanterns, garden and street lanterns, post lights).
pub fn lantern(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    b.cuboid(Body, [-0.7 * m, -0.7 * m, 0.0], [0.7 * m, 0.7 * m, 0.1 * h]);
    let post = (0.25 * m).max(0.03);
    b.cuboid(Body, [-post, -post, 0.1 * h], [post, post, 0.55 * h]);
    b.cuboid(
        Body,
        [-0.8 * m, -0.8 * m, 0.55 * h],
        [0.8 * m, 0.8 * m, 0.6 * h],
    );
    let lamp = 0.6 * m;
    b.cuboid(Light, [-lamp, -lamp, 0.6 * h], [lamp, lamp, 0.8 * h]);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let c = [sx * lamp, sy * lamp];
            b.cuboid(
                Body,
                [c[0] - 0.1 * m, c[1] - 0.1 * m, 0.6 * h],
                [c[0] + 0.1 * m, c[1] + 0.1 * m, 0.8 * h],
            );
        }
    }
    b.frustum(Top, [0.0, 0.0, 0.8 * h], hw, hd, 0.12, 0.16 * h);
    b.ellipsoid(Top, [0.0, 0.0, 0.97 * h], [0.12 * m, 0.12 * m, 0.03 * h]);
}

/// A palm: a tall bare trunk curving gently to one side, ringed where old fronds fell, under
/// one crown of long fronds that arch out and droop, each a midrib with narrow leaflets down
/// both sides (feathers, not the stacked discs of a conifer's tiers), a few coconuts under it.
pub fn palm(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let crown = [0.2 * hw, 0.0, 0.8 * h];
    let r = (0.04 * h).clamp(0.03, 0.16).min(0.25 * m);
    let segs = 12;
    let bend = |t: f64| crown[0] * t * t;
    for i in 0..segs {
        let (t0, t1) = (i as f64 / segs as f64, (i + 1) as f64 / segs as f64);
        let (r0, r1) = (r * (1.0 - 0.3 * t0), r * (1.0 - 0.3 * t1));
        let (a, c) = (
            [bend(t0), 0.0, t0 * crown[2]],
            [bend(t1), 0.0, t1 * crown[2]],
        );
        b.rod(Trunk, a, c, r0.min(r1));
        // a ring where a frond fell
        b.ellipsoid(Trunk, c, [1.12 * r1, 1.12 * r1, 0.02 * h]);
    }
    let fronds = 9;
    let reach = 0.97 * m;
    for k in 0..fronds {
        let a = k as f64 / fronds as f64 * TAU + 0.3;
        let (c, s) = (a.cos(), a.sin());
        // up a little, then out and down: the tip hangs well below the crown
        let at = |t: f64| {
            [
                crown[0] + c * reach * t,
                crown[1] + s * reach * t * (hd / hw),
                (crown[2] + 0.12 * h * (PI * t).sin().min(1.0) * (1.0 - t) - 0.28 * h * t * t)
                    .min(h - 0.03),
            ]
        };
        let n = 9;
        for j in 0..n {
            let (p, q) = (at(j as f64 / n as f64), at((j + 1) as f64 / n as f64));
            b.rod(Foliage, p, q, 0.012 + 0.006 * m);
            // leaflets from the midrib's middle out to its tip, both sides, hanging down
            let t = (j as f64 + 0.5) / n as f64;
            if t < 0.15 {
                continue;
            }
            let len = 0.28 * reach * (1.0 - 0.55 * t);
            let mid = [0, 1, 2].map(|x| 0.5 * (p[x] + q[x]));
            for side in [-1.0, 1.0] {
                let tip = [
                    mid[0] - side * s * len * 0.8 + c * 0.3 * len,
                    mid[1] + side * c * len * 0.8 * (hd / hw) + s * 0.3 * len,
                    (mid[2] - 0.55 * len).max(0.02),
                ];
                b.rod(Foliage, mid, tip, 0.01 + 0.008 * m);
            }
        }
    }
    b.ellipsoid(Trunk, crown, [1.5 * r, 1.5 * r, 1.3 * r]);
    for k in 0..3 {
        let a = TAU * k as f64 / 3.0;
        let c = [
            crown[0] + 1.4 * r * a.cos(),
            1.4 * r * a.sin(),
            crown[2] - 1.2 * r,
        ];
        b.ellipsoid(Body, c, [0.9 * r, 0.9 * r, 0.95 * r]);
    }
}
