//! Layouts of glazed things whose glass shows what is inside ([`Role::Pane`]): a china or curio
//! cabinet (plates standing on shelves and cups in front of them, behind glazed doors over a
//! cupboard) and a telephone box (a red kiosk of many small panes, a lit sign under the roof, the
//! telephone on its back wall), a fish bowl (water, gravel and a goldfish in a glass globe).
//! The front faces +y.
//!
//! [`Role::Pane`]: super::materials::Role::Pane
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x, IDENTITY};
use std::f64::consts::FRAC_PI_2;

/// A china cabinet: a cupboard with two doors and a top, a glazed hutch above it set back a
/// little, with glass sides, glazing bars, a cornice, and on each shelf upright plates at the
/// back (white with a blue glazed centre) and cups before them.
pub fn china_cabinet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = if h > 1.2 { 0.42 * h } else { 0.15 * h };
    let t = 0.03;
    // The cupboard.
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.01, zb - 0.03]);
    for (x0, x1) in [(-hw + 0.02, -0.005), (0.005, hw - 0.02)] {
        b.cuboid(Door, [x0, hd - 0.01, 0.06], [x1, hd, zb - 0.06]);
    }
    for x in [-0.04, 0.04] {
        b.cylinder(Handle, [x, hd, 0.7 * zb], 0.012, 0.06);
    }
    b.cuboid(Body, [-hw, -hd, zb - 0.03], [hw, hd, zb]);
    // The hutch: set back, with a back, corner posts and a cornice.
    let yf = hd - 0.25 * b.d;
    let zc = h - 0.06;
    b.cuboid(Interior, [-hw + t, -hd, zb], [hw - t, -hd + 0.012, zc]);
    for x in [-hw, hw - t] {
        for y in [-hd, yf - t] {
            b.cuboid(Frame, [x, y, zb], [x + t, y + t, zc]);
        }
    }
    b.cuboid(Body, [-hw, -hd, zc], [hw, yf, h]);
    // Shelves with their china.
    let levels = (((zc - zb) / 0.38).round() as usize).clamp(1, 4);
    let pitch = (zc - zb) / levels as f64;
    let depth = yf - t - (-hd + 0.012);
    for k in 0..levels {
        let z = zb + k as f64 * pitch;
        if k > 0 {
            b.cuboid(Body, [-hw + t, -hd + 0.012, z - 0.015], [hw - t, yf - t, z]);
        }
        let r = (0.36 * pitch).clamp(0.05, 0.13);
        let n = ((b.w - 2.0 * t) / (2.3 * r)).floor().max(1.0) as usize;
        let step = (b.w - 2.0 * t) / n as f64;
        let yp = -hd + 0.03;
        for i in 0..n {
            let x = -hw + t + (i as f64 + 0.5) * step;
            b.rod(Canvas, [x, yp, z + r], [x, yp + 0.012, z + r], r);
            // The blue centre: the goods palette's blue (variant 1), which no word recolours.
            let rim = frustum_profile(0.55 * r, 0.55 * r, 0.002);
            b.revolved(
                Books,
                1,
                [x, yp + 0.012, z + r],
                rot_x(-FRAC_PI_2),
                1.0,
                rim,
            );
        }
        // Cups between the plates, nearer the glass.
        let rc = (0.3 * r).min(0.2 * depth);
        for i in 0..n {
            let x = -hw + t + (i as f64 + 1.0) * step;
            if x < hw - t - rc {
                b.frustum(
                    Canvas,
                    [x, yp + 0.5 * depth, z],
                    0.7 * rc,
                    0.7 * rc,
                    1.4,
                    1.4 * rc,
                );
            }
        }
    }
    // The glass: the front of two doors with a bar across each, and the sides.
    b.cuboid(Pane, [-hw + t, yf - 0.006, zb], [hw - t, yf, zc]);
    for x in [-hw, hw - 0.006] {
        b.cuboid(Pane, [x, -hd + t, zb], [x + 0.006, yf - t, zc]);
    }
    b.cuboid(Frame, [-0.5 * t, yf - t, zb], [0.5 * t, yf, zc]);
    for k in 1..levels {
        let z = zb + k as f64 * pitch;
        b.cuboid(Frame, [-hw + t, yf - 0.012, z - 0.015], [hw - t, yf, z]);
    }
    b.cuboid(Frame, [-hw, yf - t, zb], [hw, yf, zb + t]);
}

/// A telephone box: a red kiosk on a plinth, corner posts, a domed roof over a lit sign band
/// on every side, three walls of small panes in glazing bars and a solid back with the
/// telephone inside, a door handle at the front.
pub fn phone_box(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = 0.08;
    let p = 0.08 * b.w.min(b.d);
    let zs = h - 0.3;
    let zsign = zs - 0.15;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, plinth]);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - p / 2.0), sy * (hd - p / 2.0));
            b.cuboid(
                Body,
                [x - p / 2.0, y - p / 2.0, plinth],
                [x + p / 2.0, y + p / 2.0, zs],
            );
        }
    }
    // The back wall, solid, with the telephone on it.
    b.cuboid(Body, [-hw + p, -hd, plinth], [hw - p, -hd + 0.03, zsign]);
    let (pw, pd) = (0.12 * b.w, 0.1 * b.d);
    b.cuboid(
        BlackKeys,
        [-pw, -hd + 0.03, 0.44 * h],
        [pw, -hd + 0.03 + pd, 0.56 * h],
    );
    b.cuboid(
        Metal,
        [-1.2 * pw, -hd + 0.03, 0.36 * h],
        [1.2 * pw, -hd + 0.03 + 2.0 * pd, 0.37 * h],
    );
    // Lit sign bands under the roof.
    b.cuboid(Light, [-hw + p, hd - 0.02, zsign], [hw - p, hd, zs]);
    b.cuboid(Light, [-hw + p, -hd, zsign], [hw - p, -hd + 0.02, zs]);
    b.cuboid(Light, [-hw, -hd + p, zsign], [-hw + 0.02, hd - p, zs]);
    b.cuboid(Light, [hw - 0.02, -hd + p, zsign], [hw, hd - p, zs]);
    // The roof: a stepped cap and a low dome.
    b.cuboid(Top, [-hw, -hd, zs], [hw, hd, zs + 0.1]);
    b.cuboid(
        Top,
        [-0.9 * hw, -0.9 * hd, zs + 0.1],
        [0.9 * hw, 0.9 * hd, zs + 0.16],
    );
    b.ellipsoid(
        Top,
        [0.0, 0.0, zs + 0.16],
        [0.85 * hw, 0.85 * hd, h - zs - 0.16],
    );
    // Glazed sides: front and both ends, panes in a grid of bars, a rail at waist height.
    let (z0, z1) = (plinth + 0.5, zsign - 0.04);
    let bar = 0.025;
    let rows = 8;
    for side in 0..3 {
        // side 0: the front (y = hd), 1 and 2: the ends (x = -hw, x = hw).
        let span = if side == 0 { hw - p } else { hd - p };
        let wall = |u: f64, v0: f64, v1: f64, z0: f64, z1: f64| -> ([f64; 3], [f64; 3]) {
            match side {
                0 => ([u - v0, hd - v1, z0], [u + v0, hd, z1]),
                1 => ([-hw, u - v0, z0], [-hw + v1, u + v0, z1]),
                _ => ([hw - v1, u - v0, z0], [hw, u + v0, z1]),
            }
        };
        let (lo, hi) = wall(0.0, span, 0.03, plinth, z0);
        b.cuboid(Body, lo, hi);
        let (lo, hi) = wall(0.0, span, 0.01, z0, z1);
        b.cuboid(Pane, lo, hi);
        for k in 0..=3 {
            let u = -span + 2.0 * span * k as f64 / 3.0;
            let (lo, hi) = wall(u, bar / 2.0, 0.03, z0, z1);
            b.cuboid(Frame, lo, hi);
        }
        for k in 0..=rows {
            let z = z0 + (z1 - z0) * k as f64 / rows as f64;
            let (lo, hi) = wall(0.0, span, 0.03, z - bar / 2.0, z + bar / 2.0);
            b.cuboid(Frame, lo, hi);
        }
    }
    b.rod(
        Handle,
        [hw - p - 0.08, hd - 0.016, 0.4 * h],
        [hw - p - 0.08, hd - 0.016, 0.48 * h],
        0.015,
    );
}

/// A round fish bowl: a glass globe open at its neck, the water's surface at its shoulder,
/// gravel on the bottom, a water plant and a goldfish seen through the glass.
pub fn fish_bowl(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    // The globe's profile from its flat foot round its belly to the neck.
    let globe = || -> Vec<[f64; 2]> {
        let n = 16;
        let mut p = vec![[0.0, 0.0]];
        for i in 0..=n {
            let z = h * i as f64 / n as f64;
            let t = z / h;
            // A circle through the foot (ρ = 0.55 r at t = 0) and the neck (0.65 r at t = 1).
            let rho = r * (1.0 - (2.0 * t - 1.0).powi(2)).max(0.0).sqrt();
            p.push([rho.max(if t < 0.5 { 0.55 } else { 0.65 } * r), z]);
        }
        p
    };
    // The water's surface at the shoulder; below it the glass shows what swims inside.
    let zw = 0.72 * h;
    let rw = 0.97 * r * (1.0 - (2.0 * 0.72 - 1.0f64).powi(2)).sqrt();
    b.cylinder(Water, [0.0, 0.0, zw - 0.002], rw, 0.002);
    b.cylinder(Soil, [0.0, 0.0, 0.002], 0.6 * r, 0.08 * h);
    b.ellipsoid(
        Foliage,
        [-0.3 * r, -0.2 * r, 0.35 * h],
        [0.08 * r, 0.08 * r, 0.25 * h],
    );
    // The goldfish: a body and a tail, facing along x, a little in front of the middle.
    let f = 0.35 * r;
    let c = [0.05 * r, 0.25 * r, 0.45 * h];
    b.ellipsoid_rot(Books, 8, c, [0.5 * f, 0.2 * f, 0.3 * f], IDENTITY);
    b.ellipsoid_rot(
        Books,
        8,
        [c[0] - 0.6 * f, c[1], c[2]],
        [0.15 * f, 0.06 * f, 0.25 * f],
        IDENTITY,
    );
    b.revolved(Pane, 0, [0.0, 0.0, 0.0], IDENTITY, 1.0, globe());
}
