//! Layouts of things played: a pool table with its rails and six pockets, a table-tennis table
//! with its lines and net, a drum kit. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};
use std::f64::consts::FRAC_PI_2;

/// A pool table: heavy legs, a wooden body, padded rails round a felt bed, six pockets (four at
/// the corners, two at the middle of the long sides) and a few balls.
pub fn pool_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rail = (0.08 * b.d).clamp(0.06, 0.12);
    let zb = 0.62 * h;
    b.legs(Frame, 0.12, 0.06, 0.0, zb);
    b.cuboid(
        Body,
        [-hw + 0.03, -hd + 0.03, zb],
        [hw - 0.03, hd - 0.03, h - 0.05],
    );
    // Rails on the four sides and the felt between them.
    b.cuboid(Frame, [-hw, -hd, h - 0.05], [hw, -hd + rail, h]);
    b.cuboid(Frame, [-hw, hd - rail, h - 0.05], [hw, hd, h]);
    b.cuboid(
        Frame,
        [-hw, -hd + rail, h - 0.05],
        [-hw + rail, hd - rail, h],
    );
    b.cuboid(Frame, [hw - rail, -hd + rail, h - 0.05], [hw, hd - rail, h]);
    b.cuboid(
        Upholstery,
        [-hw + rail, -hd + rail, h - 0.05],
        [hw - rail, hd - rail, h - 0.02],
    );
    let c = 0.03;
    b.cuboid(
        Cushion,
        [-hw + rail, -hd + rail, h - 0.02],
        [hw - rail, -hd + rail + c, h - 0.005],
    );
    b.cuboid(
        Cushion,
        [-hw + rail, hd - rail - c, h - 0.02],
        [hw - rail, hd - rail, h - 0.005],
    );
    b.cuboid(
        Cushion,
        [-hw + rail, -hd + rail, h - 0.02],
        [-hw + rail + c, hd - rail, h - 0.005],
    );
    b.cuboid(
        Cushion,
        [hw - rail - c, -hd + rail, h - 0.02],
        [hw - rail, hd - rail, h - 0.005],
    );
    let pr = 0.6 * rail;
    let (px, py) = (hw - 0.7 * rail, hd - 0.7 * rail);
    for (x, y) in [
        (-px, -py),
        (0.0, -py),
        (px, -py),
        (-px, py),
        (0.0, py),
        (px, py),
    ] {
        b.cylinder(Interior, [x, y, h - 0.045], pr, 0.046);
    }
    // A few balls on the felt: a triangle of them and the white.
    let br = 0.03;
    let z = h - 0.02 + br;
    let mut v = 0;
    for row in 0..3 {
        for k in 0..=row {
            let x = 0.45 * hw + row as f64 * 1.8 * br;
            let y = (k as f64 - row as f64 / 2.0) * 2.1 * br;
            b.ellipsoid_rot(Books, v, [x, y, z], [br, br, br], super::parts::IDENTITY);
            v += 1;
        }
    }
    b.ellipsoid(Canvas, [-0.5 * hw, 0.0, z], [br, br, br]);
}

/// A table-tennis table: a coloured top with white edge and centre lines, a net across its
/// middle on two posts, folding leg frames.
pub fn ping_pong_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let net = (0.2 * h).min(0.16);
    let zt = h - net;
    let t = 0.03;
    b.cuboid(Top, [-hw, -hd, zt - t], [hw, hd, zt]);
    let l = 0.02;
    b.cuboid(Canvas, [-hw, -hd, zt], [hw, -hd + l, zt + 0.002]);
    b.cuboid(Canvas, [-hw, hd - l, zt], [hw, hd, zt + 0.002]);
    b.cuboid(Canvas, [-hw, -hd + l, zt], [-hw + l, hd - l, zt + 0.002]);
    b.cuboid(Canvas, [hw - l, -hd + l, zt], [hw, hd - l, zt + 0.002]);
    b.cuboid(Canvas, [-hw + l, -0.003, zt], [hw - l, 0.003, zt + 0.002]);
    // The net across the length's middle, white band on top, posts at its ends.
    b.cuboid(Interior, [-0.004, -hd, zt + 0.01], [0.004, hd, h - 0.02]);
    b.cuboid(Canvas, [-0.006, -hd, h - 0.02], [0.006, hd, h]);
    for sy in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [-0.015, sy * hd - 0.015 * sy - 0.015, zt],
            [0.015, sy * hd - 0.015 * sy + 0.015, h],
        );
    }
    // Leg frames under each half.
    for sx in [-1.0, 1.0] {
        let x = sx * 0.6 * hw;
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - 0.12);
            b.rod(Metal, [x, y, 0.05], [x, y, zt - t], 0.02);
            b.cylinder(Tyre, [x, y, 0.0], 0.04, 0.05);
        }
        b.rod(
            Metal,
            [x, -hd + 0.12, 0.3 * zt],
            [x, hd - 0.12, 0.3 * zt],
            0.015,
        );
    }
}

/// A drum from `c` (the centre of one head), `r` in radius, `len` long along its axis, the
/// vertical turned by `a` about x (−π/2: lying along +y): a shell and a pale batter head at the
/// far end.
fn drum(b: &mut Builder, c: [f64; 3], r: f64, len: f64, a: f64) {
    let rot = rot_x(a);
    b.revolved(Body, 0, c, rot, 1.0, frustum_profile(r, r, len));
    let head = super::parts::mul(&rot, [0.0, 0.0, len]);
    b.revolved(
        Canvas,
        0,
        [c[0] + head[0], c[1] + head[1], c[2] + head[2]],
        rot,
        1.0,
        frustum_profile(0.97 * r, 0.97 * r, 0.004),
    );
}

/// A cymbal of radius `r` on a stand at `(x, y)`, `z` high.
fn cymbal(b: &mut Builder, x: f64, y: f64, z: f64, r: f64) {
    b.rod(Metal, [x, y, 0.0], [x, y, z], 0.01);
    for a in [0.0f64, 2.1, 4.2] {
        b.rod(
            Metal,
            [x, y, 0.25],
            [x + 0.15 * a.cos(), y + 0.15 * a.sin(), 0.0],
            0.007,
        );
    }
    b.frustum(Top, [x, y, z], r, r, 0.12, 0.025);
}

/// A drum kit seen from the audience: the bass drum's head at the front, two toms on it, a floor
/// tom and a snare, a hi-hat and two cymbals on stands, the player's stool at the back.
pub fn drum_kit(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = (b.w / 1.6).min(b.d / 1.4).min(h / 1.2);
    let rb = 0.28 * s;
    drum(b, [0.0, 0.05 * b.d - 0.2 * s, rb], rb, 0.4 * s, -FRAC_PI_2);
    for x in [-0.16 * s, 0.16 * s] {
        b.rod(
            Metal,
            [x * 0.5, 0.2 * b.d, 2.0 * rb - 0.02],
            [x, 0.1 * b.d, 2.0 * rb + 0.1 * s],
            0.01,
        );
        drum(
            b,
            [x, 0.05 * b.d, 2.0 * rb + 0.04 * s],
            0.11 * s,
            0.2 * s,
            0.5,
        );
    }
    // Floor tom on the right (seen from the front: the player's right, at -x), snare on the left.
    let (xf, yf) = (-0.42 * b.w, -0.1 * b.d);
    for a in [0.0f64, 2.1, 4.2] {
        let (dx, dy) = (0.14 * s * a.cos(), 0.14 * s * a.sin());
        b.rod(
            Metal,
            [xf + dx, yf + dy, 0.0],
            [xf + dx, yf + dy, 0.3 * s],
            0.008,
        );
    }
    b.cylinder(Body, [xf, yf, 0.2 * s], 0.16 * s, 0.3 * s);
    b.cylinder(Canvas, [xf, yf, 0.5 * s], 0.155 * s, 0.004);
    let (xs, ys) = (0.3 * b.w, -0.15 * b.d);
    b.rod(Metal, [xs, ys, 0.0], [xs, ys, 0.55 * s], 0.01);
    b.cylinder(Body, [xs, ys, 0.55 * s], 0.15 * s, 0.13 * s);
    b.cylinder(Canvas, [xs, ys, 0.68 * s], 0.145 * s, 0.004);
    // Hi-hat beside the snare, crash and ride above the kit.
    let (xh, yh) = (hw - 0.2 * s, -0.05 * b.d);
    cymbal(b, xh, yh, 0.85 * s, 0.17 * s);
    b.frustum(Top, [xh, yh, 0.82 * s], 0.17 * s, 0.17 * s, 0.12, 0.02);
    cymbal(b, 0.3 * b.w, 0.2 * b.d, h - 0.03, 0.22 * s);
    cymbal(b, -0.3 * b.w, 0.15 * b.d, h - 0.1 * s, 0.24 * s);
    // The stool.
    let yst = -hd + 0.2 * s;
    b.rod(Metal, [0.0, yst, 0.0], [0.0, yst, 0.48 * s], 0.02);
    b.cylinder(Upholstery, [0.0, yst, 0.48 * s], 0.17 * s, 0.08 * s);
}
