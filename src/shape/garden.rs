//! Layouts of garden things people hang in or walk through: a hammock on its stand, a porch
//! swing on an A-frame, and a garden arch with climbing roses. The front faces +y, z up, the
//! bottom face's centre at the origin.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{rot_x, V3};
use std::f64::consts::PI;

/// A hammock on its stand: a floor beam front to back with two feet, two arms rising to the
/// ends, and a sagging cloth bed between spreader bars, hung by ropes from the arms' tips.
pub fn hammock(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (long, half) = if b.d >= b.w { (1, hd) } else { (0, hw) };
    let across = if long == 1 { hw } else { hd };
    // Points along the hammock's length `s` and across it `c` at height `z`.
    let at = |s: f64, c: f64, z: f64| -> V3 {
        if long == 1 {
            [c, s, z]
        } else {
            [s, c, z]
        }
    };
    let t = 0.04f64.min(0.1 * across);
    b.cuboid(
        Frame,
        at(-0.45 * half, -t, 0.0),
        at(0.45 * half, t, 2.0 * t),
    );
    for s in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            at(s * 0.45 * half - t, -0.9 * across, 0.0),
            at(s * 0.45 * half + t, 0.9 * across, 1.5 * t),
        );
        b.rod(
            Frame,
            at(s * 0.4 * half, 0.0, t),
            at(s * (half - t), 0.0, h - t),
            t,
        );
    }
    // The bed: a cloth sagging from its spreader bars at 0.8 of the length to its middle.
    let (ze, zm) = (0.72 * h, 0.4 * h);
    let se = 0.72 * half;
    let n = 12;
    let z_of = |s: f64| zm + (ze - zm) * (s / se).powi(2);
    let bw = 0.8 * across;
    for i in 0..n {
        let (s0, s1) = (
            -se + 2.0 * se * i as f64 / n as f64,
            -se + 2.0 * se * (i + 1) as f64 / n as f64,
        );
        let (z0, z1) = (z_of(s0), z_of(s1));
        let len = ((s1 - s0).powi(2) + (z1 - z0).powi(2)).sqrt();
        let a = (z1 - z0).atan2(s1 - s0);
        let c = at(0.5 * (s0 + s1), 0.0, 0.5 * (z0 + z1));
        if long == 1 {
            b.slab(Canvas, c, [bw, 0.5 * len + 0.005, 0.006], rot_x(a));
        } else {
            b.slab(
                Canvas,
                c,
                [0.5 * len + 0.005, bw, 0.006],
                super::parts::rot_y(-a),
            );
        }
    }
    for s in [-1.0, 1.0] {
        let z = z_of(s * se);
        b.rod(
            Frame,
            at(s * se, -bw - 0.03, z),
            at(s * se, bw + 0.03, z),
            0.015,
        );
        let tip = at(s * (half - t), 0.0, h - 2.5 * t);
        for c in [-bw, 0.0, bw] {
            b.rod(Metal, at(s * se, c, z), tip, 0.006);
        }
    }
}

/// A porch swing: a slatted bench with a back and arms, hung by four chains from the top beam
/// of an A-frame stand.
pub fn swing_bench(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.05f64.min(0.05 * b.w);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t);
        for sy in [-1.0, 1.0] {
            b.rod(Frame, [x, sy * (hd - t), 0.0], [x, 0.0, h - 2.0 * t], t);
        }
        b.cuboid(
            Frame,
            [x - t, -0.5 * hd, 0.35 * h],
            [x + t, 0.5 * hd, 0.35 * h + t],
        );
    }
    b.cuboid(Top, [-hw, -1.2 * t, h - 2.0 * t], [hw, 1.2 * t, h]);
    // The bench.
    let bw = 0.68 * hw;
    let (zs, ds) = (0.28 * h, 0.55 * hd);
    let slats = 5;
    for i in 0..slats {
        let y0 = -ds + 2.0 * ds * i as f64 / slats as f64;
        b.cuboid(
            Seat,
            [-bw, y0 + 0.01, zs],
            [bw, y0 + 2.0 * ds / slats as f64 - 0.01, zs + 0.03],
        );
    }
    let zb = zs + 0.25 * h;
    for i in 0..4 {
        let z0 = zs + 0.05 + (zb - zs - 0.05) * i as f64 / 4.0;
        b.cuboid(
            Seat,
            [-bw, -ds - 0.03, z0 + 0.01],
            [bw, -ds, z0 + (zb - zs - 0.05) / 4.0 - 0.01],
        );
    }
    for sx in [-1.0, 1.0] {
        let x = sx * bw;
        b.cuboid(
            Frame,
            [x - 0.02, -ds - 0.03, zs - 0.04],
            [x + 0.02, -ds, zb],
        );
        b.cuboid(Frame, [x - 0.02, -ds, zs + 0.18], [x + 0.02, ds, zs + 0.21]);
        b.cuboid(
            Frame,
            [x - 0.02, ds - 0.04, zs - 0.04],
            [x + 0.02, ds, zs + 0.18],
        );
        // Chains from the arm's front and the back's top to the beam.
        let top = [x, 0.0, h - 2.0 * t];
        b.rod(Metal, [x, ds - 0.02, zs + 0.21], top, 0.006);
        b.rod(Metal, [x, -ds - 0.015, zb], top, 0.006);
    }
}

/// A garden arch: two lattice sides of slim posts and rungs, a round arch over the path
/// joining them, and climbing roses (leaf clumps with flowers) up one side and over the top.
pub fn garden_arch(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.025f64.min(0.05 * hd);
    let r = (hw - t).min(0.4 * h);
    let zc = h - t - r;
    for sy in [-1.0, 1.0] {
        let y = sy * (hd - t);
        for sx in [-1.0, 1.0] {
            b.cuboid(Frame, [sx * r - t, y - t, 0.0], [sx * r + t, y + t, zc]);
        }
        let arc: Vec<V3> = (0..=12)
            .map(|k| {
                let a = PI * k as f64 / 12.0;
                [r * a.cos(), y, zc + r * a.sin()]
            })
            .collect();
        b.polyline(Frame, &arc, t);
    }
    // Rungs across each side and across the arch.
    for sx in [-1.0, 1.0] {
        let x = sx * r;
        let rungs = ((zc / 0.3).round() as usize).max(3);
        for i in 1..=rungs {
            let z = zc * i as f64 / rungs as f64;
            b.rod(Frame, [x, -hd + t, z], [x, hd - t, z], 0.6 * t);
        }
    }
    for k in 1..8 {
        let a = PI * k as f64 / 8.0;
        let (x, z) = (r * a.cos(), zc + r * a.sin());
        b.rod(Frame, [x, -hd + t, z], [x, hd - t, z], 0.6 * t);
    }
    // Roses: clumps up the left side and over the arch's left half, flowers among them.
    let clumps: Vec<V3> = (0..6)
        .map(|i| [-r, 0.0, 0.25 * zc + 0.75 * zc * i as f64 / 5.0])
        .chain((1..6).map(|k| {
            let a = PI - 0.5 * PI * k as f64 / 5.0;
            [r * a.cos(), 0.0, zc + r * a.sin()]
        }))
        .collect();
    let s = (0.12 * b.w).min(0.9 * hd).min(0.15);
    for (i, c) in clumps.iter().enumerate() {
        let side = if i % 2 == 0 { 0.35 } else { -0.35 };
        let c = [
            (c[0] + 0.3 * side * s).clamp(-hw + s, hw - s),
            side * hd,
            c[2].min(h - s),
        ];
        b.ellipsoid(Foliage, c, [s, (hd - 0.01).min(1.2 * s), 0.9 * s]);
        for (j, off) in [[0.4, 0.8, 0.3], [-0.5, -0.7, -0.2]].iter().enumerate() {
            let p = [
                c[0] + off[0] * s,
                c[1] + off[1] * (hd - 0.01).min(1.2 * s),
                c[2] + off[2] * s,
            ];
            let role = if (i + j) % 2 == 0 { Pillow } else { Cushion };
            b.ellipsoid(role, p, [0.3 * s, 0.3 * s, 0.3 * s]);
        }
    }
}
