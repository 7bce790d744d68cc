//! Fittings shared by the seats, beds, racks and clocks drawn for their trade (`care.rs`,
//! `salon.rs`, `sleepers.rs`, `holders.rs`, `clocks.rs`, `organs.rs`): a pad laid between two
//! points of the side view, a band (a tyre, a push rim, a bezel), a centred disc, a spoked wheel,
//! a swivel castor, a round pedestal and a clock face. Pure geometry on a [`Builder`]; these are
//! parts, never an archetype of their own.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{frustum_profile, rot_x, V3};
use std::f64::consts::TAU;

/// The x axis, the axle of a wheel that rolls front to back.
pub(super) const X: V3 = [1.0, 0.0, 0.0];
/// The y axis, the axis of a face that looks to the front.
pub(super) const Y: V3 = [0.0, 1.0, 0.0];

/// A flat pad (a seat, a back rest, a tray, a sloped shelf) centred across at `x`, `hw` to either
/// side, `t` thick, its mid-plane running in the side view from `a` to `c` (each `[y, z]`).
pub(super) fn pad(b: &mut Builder, role: Role, x: f64, a: [f64; 2], c: [f64; 2], hw: f64, t: f64) {
    let (dy, dz) = (c[0] - a[0], c[1] - a[1]);
    let l = (dy * dy + dz * dz).sqrt().max(1e-6);
    let centre = [x, 0.5 * (a[0] + c[0]), 0.5 * (a[1] + c[1])];
    b.slab(role, centre, [hw, l / 2.0, t / 2.0], rot_x(dz.atan2(dy)));
}

/// A band about `axis` through `centre`: outer radius `r`, `t` deep towards the axis, `w` wide
/// along it (a tyre, a push rim, a clock's bezel).
pub(super) fn band(b: &mut Builder, role: Role, centre: V3, axis: V3, r: f64, t: f64, w: f64) {
    let (r0, h) = ((r - t).max(0.0), w / 2.0);
    let profile = vec![[r0, -h], [r, -h], [r, h], [r0, h], [r0, -h]];
    b.revolved(role, 0, centre, frame_along(axis), 1.0, profile);
}

/// A closed disc of radius `r` and thickness `t` centred at `centre`, its axis along `axis`.
pub(super) fn disc(b: &mut Builder, role: Role, centre: V3, axis: V3, r: f64, t: f64) {
    let l = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2])
        .sqrt()
        .max(1e-12);
    let base = [0, 1, 2].map(|k| centre[k] - 0.5 * t * axis[k] / l);
    b.revolved(
        role,
        0,
        base,
        frame_along(axis),
        1.0,
        frustum_profile(r, r, t),
    );
}

/// A spoked wheel on an axle along x at `c`: a tyre `w` wide of outer radius `r`, a metal rim
/// inside it, `spokes` wire spokes and a hub.
pub(super) fn spoked_wheel(b: &mut Builder, c: V3, r: f64, w: f64, spokes: usize) {
    let tyre = (0.09 * r).clamp(0.012, 0.03);
    band(b, Tyre, c, X, r, tyre, w);
    band(b, Metal, c, X, r - tyre, 0.012, 0.7 * w);
    let rim = r - tyre - 0.01;
    for k in 0..spokes {
        let a = k as f64 / spokes as f64 * TAU;
        let x = c[0] + if k % 2 == 0 { 0.25 } else { -0.25 } * w;
        b.rod(
            Metal,
            [x, c[1], c[2]],
            [c[0], c[1] + rim * a.cos(), c[2] + rim * a.sin()],
            0.0035,
        );
    }
    disc(b, Metal, c, X, (0.12 * r).max(0.02), w);
}

/// A swivel castor at (`x`, `y`): a wheel of radius `r` standing on the floor in a fork, and a
/// stem from the fork up to `top`.
pub(super) fn castor(b: &mut Builder, x: f64, y: f64, r: f64, top: f64) {
    let w = (0.7 * r).max(0.02);
    disc(b, Tyre, [x, y, r], X, r, w);
    disc(b, Metal, [x, y, r], X, 0.35 * r, w + 0.006);
    let (f, z1) = (0.008, 2.0 * r + 0.012);
    for sx in [-1.0, 1.0] {
        let xf = x + sx * (0.5 * w + f);
        b.cuboid(
            Metal,
            [xf - f / 2.0, y - 0.4 * r, r],
            [xf + f / 2.0, y + 0.2 * r, z1],
        );
    }
    b.cuboid(
        Metal,
        [x - 0.5 * w - 1.5 * f, y - 0.4 * r, z1],
        [x + 0.5 * w + 1.5 * f, y + 0.2 * r, z1 + f],
    );
    if top > z1 + f {
        b.rod(
            Metal,
            [x, y - 0.1 * r, z1 + f],
            [x, y - 0.1 * r, top],
            0.012,
        );
    }
}

/// A round pedestal at `y` on the centre line: a low domed foot of radius `rb` and a column of
/// radius `rc` up to `top` (a barber chair's, a dentist's chair's).
pub(super) fn pedestal(b: &mut Builder, role: Role, y: f64, rb: f64, rc: f64, top: f64) {
    let foot = (0.15 * rb).clamp(0.03, 0.06);
    b.frustum(role, [0.0, y, 0.0], rb, rb, 0.8, foot);
    b.frustum(role, [0.0, y, foot], 0.8 * rb, 0.8 * rb, 0.35, 0.5 * foot);
    b.cylinder(role, [0.0, y, foot], rc, (top - foot).max(0.01));
}

/// A clock face of radius `r` at `c` looking to the front (+y): a white dial, twelve hour
/// marks (the quarters longer), hour and minute hands at ten past ten and a centre boss. The
/// dial's surface is at `c`; the marks and hands stand a few millimetres proud of it.
pub(super) fn clock_face(b: &mut Builder, c: V3, r: f64) {
    disc(b, Canvas, [c[0], c[1] - 0.002, c[2]], Y, r, 0.004);
    // A point on the dial at clock angle `a` (clockwise from twelve as seen from the front,
    // where the viewer's right is -x) and distance `s` from the centre.
    let at = |a: f64, s: f64, y: f64| [c[0] - s * a.sin(), y, c[2] + s * a.cos()];
    let y = c[1] + 0.002;
    for k in 0..12 {
        let a = k as f64 / 12.0 * TAU;
        let inner = if k % 3 == 0 { 0.72 } else { 0.8 };
        b.rod(BlackKeys, at(a, inner * r, y), at(a, 0.9 * r, y), 0.025 * r);
    }
    let hour = (10.0 + 10.0 / 60.0) / 12.0 * TAU;
    let minute = 10.0 / 60.0 * TAU;
    b.rod(
        BlackKeys,
        at(0.0, 0.0, y + 0.002),
        at(hour, 0.5 * r, y + 0.002),
        0.035 * r,
    );
    b.rod(
        BlackKeys,
        at(0.0, 0.0, y + 0.004),
        at(minute, 0.78 * r, y + 0.004),
        0.025 * r,
    );
    disc(b, BlackKeys, [c[0], y + 0.004, c[2]], Y, 0.06 * r, 0.006);
}

/// Four square posts of side `p` and height `h` standing in the corners of the builder's box
/// (a crib's, a compost bin's).
pub(super) fn corner_posts(b: &mut Builder, role: Role, p: f64, h: f64) {
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - p / 2.0), sy * (hd - p / 2.0));
            b.cuboid(
                role,
                [x - p / 2.0, y - p / 2.0, 0.0],
                [x + p / 2.0, y + p / 2.0, h],
            );
        }
    }
}
