//! Layouts of cloths and mats that once were a plain bordered rug, and of a paper lantern that
//! once was a table lamp: a beach towel (stripes across its length), a picnic blanket (a
//! two-colour check), a play mat (square foam tiles in many colours) and a paper lantern (a
//! ribbed paper globe on a small foot). Each lies or stands inside its size box, front +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::Mount;

/// A beach towel: stripes across its length in turn of its main colour, white and an accent,
/// the white ones narrower.
pub fn striped_towel(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = h.max(0.003);
    let n = ((b.d / 0.12).round() as usize).max(5);
    let step = b.d / n as f64;
    for k in 0..n {
        let y0 = -hd + k as f64 * step;
        let role = [Body, Canvas, Cushion, Canvas][k % 4];
        b.cuboid(role, [-hw, y0, 0.0], [hw, y0 + step, t]);
    }
}

/// A picnic blanket: a check of its main colour and white in squares of about 15 cm, with the
/// squares where two white bands cross paler still (the weave's overlap).
pub fn checked_blanket(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = h.max(0.003);
    let (nx, ny) = (
        ((b.w / 0.15).round() as usize).max(3),
        ((b.d / 0.15).round() as usize).max(3),
    );
    let (sx, sy) = (b.w / nx as f64, b.d / ny as f64);
    for i in 0..nx {
        for j in 0..ny {
            let role = match (i % 2, j % 2) {
                (0, 0) => Body,
                (1, 1) => Canvas,
                _ => Cushion,
            };
            let (x0, y0) = (-hw + i as f64 * sx, -hd + j as f64 * sy);
            b.cuboid(role, [x0, y0, 0.0], [x0 + sx, y0 + sy, t]);
        }
    }
}

/// A play mat: square foam tiles of about 30 cm, each its own bright colour, a little gap
/// between them.
pub fn tiled_mat(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (nx, ny) = (
        ((b.w / 0.3).round() as usize).max(2),
        ((b.d / 0.3).round() as usize).max(2),
    );
    let (sx, sy) = (b.w / nx as f64, b.d / ny as f64);
    for i in 0..nx {
        for j in 0..ny {
            let (x0, y0) = (-hw + i as f64 * sx, -hd + j as f64 * sy);
            b.cuboid_v(
                Books,
                (3 * i + 5 * j) as u32,
                [x0 + 0.004, y0 + 0.004, 0.0],
                [x0 + sx - 0.004, y0 + sy - 0.004, h],
            );
        }
    }
}

/// A paper lantern: a round paper globe as wide as the box, lit from within, ringed by thin
/// ribs; standing, on a short stem over a small dark foot; hung from the ceiling, at the foot
/// of its box on a cord from a small canopy at its top.
pub fn paper_lantern(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.98 * hw.min(hd)).min(0.45 * h);
    let zc = if b.mount == Mount::Ceiling {
        let zc = 0.95 * r;
        let cord = (0.03 * r).max(0.004);
        b.cylinder(Frame, [0.0, 0.0, zc + 0.85 * r], cord, h - zc - 0.85 * r);
        b.frustum(Frame, [0.0, 0.0, h - 0.025], 0.25 * r, 0.25 * r, 1.0, 0.025);
        zc
    } else {
        let zc = h - r;
        b.frustum(Frame, [0.0, 0.0, 0.0], 0.45 * r, 0.45 * r, 0.8, 0.03);
        b.cylinder(Frame, [0.0, 0.0, 0.0], 0.04 * r, zc - 0.9 * r);
        zc
    };
    b.ellipsoid(Shade, [0.0, 0.0, zc], [r, r, 0.95 * r]);
    for k in 1..8 {
        let z = -0.95 * r + k as f64 * 1.9 * r / 8.0;
        let rr = (r * r - (z / 0.95) * (z / 0.95)).max(0.0).sqrt();
        b.ellipsoid(Metal, [0.0, 0.0, zc + z], [rr + 0.002, rr + 0.002, 0.003]);
    }
}
