//! Layouts of things built of many like pieces outdoors and in sheds: a dock (a plank deck on
//! rows of posts), a firewood pile (logs stacked with their round ends out), a slatted compost
//! bin full of compost, a sandbox (a board frame round sand with corner seats), an obelisk (a
//! tapering shaft under a pyramid on a plinth) and a wire dog crate (a cage of bars on a tray).
//! The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::frustum_profile;

/// A dock: deck planks across its width on stringers, carried by rows of round posts that rise
/// a little above the deck at its edges.
pub fn dock(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let deck = 0.1 * h;
    let z1 = h - 0.06 * h;
    let r = (0.05 * b.w).clamp(0.05, 0.12);
    // Posts in two rows down the length, every ~1.5 m.
    let n = ((b.d / 1.5).round() as usize).max(1);
    for i in 0..=n {
        let y = -hd + r + (b.d - 2.0 * r) * i as f64 / n as f64;
        for sx in [-1.0, 1.0] {
            b.cylinder(Trunk, [sx * (hw - r), y, 0.0], r, h);
        }
    }
    // Stringers along the length under the planks, and the planks across.
    for sx in [-1.0, 0.0, 1.0] {
        let x = sx * (hw - 2.0 * r);
        b.cuboid(
            Frame,
            [x - 0.04, -hd, z1 - deck - 0.12],
            [x + 0.04, hd, z1 - deck],
        );
    }
    let pitch = 0.16;
    let m = (b.d / pitch).floor().max(1.0) as usize;
    let p = b.d / m as f64;
    for j in 0..m {
        let y = -hd + j as f64 * p;
        b.cuboid_v(
            Top,
            (j % 3) as u32,
            [-hw, y + 0.006, z1 - deck],
            [hw, y + p - 0.006, z1],
        );
    }
}

/// A firewood pile: rows of split logs lying front to back, each row set half a log over the
/// one below, their pale cut ends showing at front and back.
pub fn firewood_pile(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.06f64).min(0.12 * h).min(0.1 * b.w);
    let rows = ((h - 2.0 * r) / (1.73 * r)).floor() as usize + 1;
    for k in 0..rows {
        let z = r + k as f64 * 1.73 * r;
        let off = if k % 2 == 0 { 0.0 } else { r };
        let n = ((b.w - 2.0 * r - off) / (2.0 * r)).floor() as usize + 1;
        for i in 0..n {
            let x = -hw + r + off + 2.0 * r * i as f64;
            let rr = r * (0.88 + 0.1 * (((i * 7 + k * 3) % 5) as f64 / 4.0));
            let y0 = -hd + 0.01 * ((i + k) % 3) as f64;
            let y1 = hd - 0.01 * ((i * 2 + k) % 3) as f64;
            let e = 0.004;
            b.rod(Trunk, [x, y0 + e, z], [x, y1 - e, z], rr);
            for (ya, yb) in [(y0, y0 + e), (y1 - e, y1)] {
                b.revolved(
                    Top,
                    0,
                    [x, ya, z],
                    frame_along([0.0, 1.0, 0.0]),
                    1.0,
                    frustum_profile(0.95 * rr, 0.95 * rr, yb - ya),
                );
            }
        }
    }
}

/// A compost bin: corner posts, horizontal slats with gaps on every side, and compost heaped
/// inside up to near the top.
pub fn compost_bin(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let p = 0.06;
    super::fittings::corner_posts(b, Frame, p, h);
    let n = ((h / 0.13).round() as usize).max(3);
    let pitch = h / n as f64;
    let t = 0.02;
    for k in 0..n {
        let (z0, z1) = (k as f64 * pitch + 0.015, (k + 1) as f64 * pitch - 0.015);
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - p / 2.0);
            b.cuboid_v(
                Body,
                (k % 2) as u32,
                [-hw + p, y - t / 2.0, z0],
                [hw - p, y + t / 2.0, z1],
            );
        }
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - p / 2.0);
            b.cuboid_v(
                Body,
                (k % 2) as u32,
                [x - t / 2.0, -hd + p, z0],
                [x + t / 2.0, hd - p, z1],
            );
        }
    }
    b.cuboid(Soil, [-hw + p, -hd + p, 0.0], [hw - p, hd - p, 0.8 * h]);
    b.ellipsoid(Soil, [0.0, 0.0, 0.8 * h], [hw - p, hd - p, 0.08 * h]);
}

/// A sandbox: four boards round a square of sand, a triangular seat across each corner and a
/// bucket in the sand.
pub fn sandbox(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.05;
    for sy in [-1.0, 1.0] {
        let y = sy * (hd - t / 2.0);
        b.cuboid(Frame, [-hw, y - t / 2.0, 0.0], [hw, y + t / 2.0, 0.9 * h]);
    }
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Frame, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, hd, 0.9 * h]);
    }
    b.cuboid(Soil, [-hw + t, -hd + t, 0.0], [hw - t, hd - t, 0.6 * h]);
    // Corner seats: boards laid diagonally across each corner.
    let s = (0.3 * b.w.min(b.d)).min(0.4);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let c = [sx * (hw - 0.57 * s), sy * (hd - 0.57 * s)];
            let a = if sx * sy > 0.0 { -1.0 } else { 1.0 } * std::f64::consts::FRAC_PI_4;
            b.slab(
                Top,
                [c[0], c[1], h - 0.05 * h],
                [0.5 * s, 0.3 * s, 0.05 * h],
                super::parts::rot_z(a),
            );
        }
    }
    let r = (0.1 * h).max(0.05);
    b.frustum(
        Seat,
        [0.25 * hw, -0.2 * hd, 0.6 * h],
        0.8 * r,
        0.8 * r,
        1.25,
        (0.4 * h).min(1.5 * r),
    );
}

/// An obelisk: a stepped plinth, a square shaft tapering as it rises, and a pyramid on top.
pub fn obelisk(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = 0.08 * h;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.5 * plinth]);
    b.cuboid(
        Frame,
        [-0.85 * hw, -0.85 * hd, 0.5 * plinth],
        [0.85 * hw, 0.85 * hd, plinth],
    );
    let cap = 0.08 * h;
    let (r0, r1) = (0.6, 0.4);
    let steps = 24;
    let shaft = h - plinth - cap;
    for k in 0..steps {
        let f = (k as f64 + 0.5) / steps as f64;
        let s = r0 + (r1 - r0) * f;
        let z = plinth + k as f64 * shaft / steps as f64;
        b.cuboid(
            Stone,
            [-s * hw, -s * hd, z],
            [s * hw, s * hd, z + shaft / steps as f64 + 0.002],
        );
    }
    let steps = 10;
    for k in 0..steps {
        let s = r1 * (1.0 - k as f64 / steps as f64);
        let z = h - cap + k as f64 * cap / steps as f64;
        b.cuboid(
            Top,
            [-s * hw, -s * hd, z],
            [s * hw, s * hd, z + cap / steps as f64],
        );
    }
}

/// A wire dog crate: a plastic tray, a frame of rods along its edges, upright bars on every side
/// and across the top, a door in the front with a latch.
pub fn dog_crate(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.005;
    let (x, y) = (hw - r, hd - r);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, 0.05]);
    for z in [0.05, 0.5 * h, h - r] {
        b.polyline(
            Metal,
            &[[-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z], [-x, -y, z]],
            1.5 * r,
        );
    }
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.rod(Metal, [sx * x, sy * y, 0.0], [sx * x, sy * y, h], 1.5 * r);
        }
    }
    let pitch = 0.05;
    let nx = (b.w / pitch).round() as usize;
    let ny = (b.d / pitch).round() as usize;
    for i in 1..nx {
        let xi = -hw + i as f64 * b.w / nx as f64;
        for sy in [-1.0, 1.0] {
            b.rod(Metal, [xi, sy * y, 0.05], [xi, sy * y, h], r);
        }
        b.rod(Metal, [xi, -y, h - r], [xi, y, h - r], r);
    }
    for j in 1..ny {
        let yj = -hd + j as f64 * b.d / ny as f64;
        for sx in [-1.0, 1.0] {
            b.rod(Metal, [sx * x, yj, 0.05], [sx * x, yj, h], r);
        }
    }
    // The door: a frame in the front's middle with a latch on its right edge.
    let dw = 0.3 * b.w;
    let d = [
        [-dw, y - r, 0.08],
        [dw, y - r, 0.08],
        [dw, y - r, 0.85 * h],
        [-dw, y - r, 0.85 * h],
        [-dw, y - r, 0.08],
    ];
    b.polyline(Metal, &d, 2.0 * r);
    b.cuboid(
        Handle,
        [dw - 0.02, y - 0.005, 0.45 * h],
        [dw + 0.02, hd, 0.5 * h],
    );
}
