//! Ponds that lie in the ground, not tubs: a water surface a few centimetres above the ground,
//! an uneven ring of low edging stones round it, lily pads on the water and a few orange and
//! white fish just under the surface.
//! The front faces +y; each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::named::wobble;
use super::parts::{rot_z, IDENTITY};
use std::f64::consts::TAU;

/// Height of the water surface over the ground (m): the pond lies in it.
const SURFACE: f64 = 0.03;

/// A pond in the ground: a few fish, orange and white with an orange head (koi, goldfish), just
/// under the surface.
pub fn pond(b: &mut Builder) {
    let (rx, ry) = basin(b);
    let len = (0.14 * rx.min(ry)).clamp(0.12, 0.35);
    let thick = (0.14 * len).min(0.02);
    for k in 0..5 {
        let a = TAU * (k as f64 / 5.0 + 0.1 * wobble(k, 3));
        let r = 0.25 + 0.35 * wobble(k, 4);
        let z = SURFACE - 0.005;
        let c = [r * rx * a.cos(), r * ry * a.sin(), z];
        // each fish swims round the pond: along the tangent, body then tail
        let t = [-a.sin(), a.cos()];
        let rot = rot_z(t[1].atan2(t[0]));
        let skin = if k % 2 == 0 { Body } else { Canvas };
        b.ellipsoid_rot(skin, 0, c, [len, 0.3 * len, thick], rot);
        let head = [
            c[0] + 0.6 * len * t[0],
            c[1] + 0.6 * len * t[1],
            z + 0.2 * thick,
        ];
        b.ellipsoid_rot(Body, 0, head, [0.35 * len, 0.22 * len, thick], rot);
        let tail = [c[0] - 1.1 * len * t[0], c[1] - 1.1 * len * t[1], z];
        b.ellipsoid_rot(Body, 0, tail, [0.3 * len, 0.25 * len, 0.5 * thick], rot);
    }
}

/// The water, its edging stones and lily pads, for the size box; returns the water's half axes.
fn basin(b: &mut Builder) -> (f64, f64) {
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    let stone = (0.1 * hw.min(hd)).clamp(0.1, 0.3);
    // the water to the stones' middle line, the stones reaching the box's edge
    let (rx, ry) = (hw - 1.1 * stone, hd - 1.1 * stone);
    // the water, a closed flat disc reaching under the stones
    let water = vec![
        [0.0, 0.0],
        [rx + 0.5 * stone, 0.0],
        [rx + 0.5 * stone, SURFACE],
        [0.0, SURFACE],
    ];
    b.revolved(
        Water,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        (ry + 0.5 * stone) / (rx + 0.5 * stone),
        water,
    );
    // edging stones: low, uneven lumps side by side round the water
    let perimeter = TAU * ((rx * rx + ry * ry) / 2.0).sqrt();
    let n = ((perimeter / (1.3 * stone)) as usize).max(8);
    let top = (0.45 * b.h).min(0.18);
    for k in 0..n {
        let a = TAU * (k as f64 + 0.3 * wobble(k, 1)) / n as f64;
        let s = 0.8 + 0.4 * wobble(k, 2);
        let c = [
            (rx + 0.5 * stone) * a.cos(),
            (ry + 0.5 * stone) * a.sin(),
            0.0,
        ];
        let rot = rot_z(a);
        let half = [
            0.5 * stone * s,
            0.9 * stone * s,
            0.5 * top * (0.6 + 0.4 * wobble(k, 5)),
        ];
        b.ellipsoid_rot(Stone, k as u32, [c[0], c[1], half[2]], half, rot);
    }
    // lily pads: flat green discs on the water
    for k in 0..4 {
        let a = TAU * (k as f64 / 4.0 + 0.2 * wobble(k, 11));
        let r = 0.35 + 0.35 * wobble(k, 12);
        let c = [r * rx * a.cos(), r * ry * a.sin(), SURFACE];
        let pad = 0.09 * rx.min(ry).min(2.0);
        b.frustum(Foliage, c, pad, pad, 1.0, 0.008);
    }
    (rx, ry)
}
