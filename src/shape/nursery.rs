//! A baby's beds and a rocking toy, each drawn with what sets it apart from a grown-up bed or a
//! live animal: a bassinet (an oval basket on a stand, a hood over the head end), a cradle (a
//! slatted wooden box between two taller ends, on rockers) and a rocking horse (the animal of
//! `things.rs` on two bow rockers, with a saddle and handles). The front is +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::IDENTITY;
use std::f64::consts::PI;

/// A bow rocker in the plane x = `x`, from y = -`l` to `l`, its lowest point on the floor and its
/// tips `rise` above it.
fn rocker_along_y(b: &mut Builder, x: f64, l: f64, rise: f64, r: f64) {
    let n = 14;
    let pts: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let t = -1.0 + 2.0 * i as f64 / n as f64;
            [x, t * (l - r), r + rise * t * t]
        })
        .collect();
    b.polyline(Frame, &pts, r);
}

/// A bassinet: an oval basket with a soft lining on legs, its hood over the head end (-y).
pub fn bassinet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.45 * h;
    let (rx, ry) = (0.9 * hw, 0.9 * hd);
    // The basket: an open oval tub, wider at the rim.
    b.revolved(
        Body,
        0,
        [0.0, 0.0, zb],
        IDENTITY,
        ry / rx,
        vec![
            [0.0, 0.0],
            [0.85 * rx, 0.0],
            [rx, 0.3 * h],
            [0.94 * rx, 0.3 * h],
            [0.8 * rx, 0.04],
        ],
    );
    b.ellipsoid(Mattress, [0.0, 0.0, zb + 0.05], [0.78 * rx, 0.8 * ry, 0.04]);
    b.ellipsoid(
        Pillow,
        [0.0, -0.55 * ry, zb + 0.09],
        [0.4 * rx, 0.12 * ry, 0.03],
    );
    // The hood: a quarter shell over the head end.
    let hood: Vec<[f64; 2]> = (0..=8)
        .map(|i| {
            let a = 0.5 * PI * i as f64 / 8.0;
            [rx * a.cos(), 0.45 * (h - zb - 0.3 * h) * a.sin()]
        })
        .collect();
    b.revolved(
        Shade,
        0,
        [0.0, -0.45 * ry, zb + 0.3 * h],
        IDENTITY,
        0.55 * ry / rx,
        hood,
    );
    // Four splayed legs and a shelf between them.
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.rod(
                Frame,
                [sx * 0.5 * hw, sy * 0.55 * hd, zb],
                [sx * 0.9 * hw, sy * 0.9 * hd, 0.0],
                0.015,
            );
        }
    }
    b.cuboid(
        Frame,
        [-0.6 * hw, -0.65 * hd, 0.15 * h],
        [0.6 * hw, 0.65 * hd, 0.15 * h + 0.02],
    );
}

/// A cradle: a slatted box between a taller head and foot board, on rockers under each end.
pub fn cradle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rock = 0.12 * h;
    let zb = rock + 0.1 * h;
    let ze = h;
    let zs = 0.8 * h;
    let t = 0.03;
    // Head and foot boards with rounded tops, standing on the rockers.
    for sy in [-1.0, 1.0] {
        let y = sy * (0.8 * hd);
        b.cuboid(
            Top,
            [-hw + 0.02, y - t / 2.0, rock],
            [hw - 0.02, y + t / 2.0, ze - 0.12 * h],
        );
        b.ellipsoid(Top, [0.0, y, ze - 0.12 * h], [hw - 0.02, t / 2.0, 0.12 * h]);
        rocker_along_y_x(b, y, hw, 0.5 * rock, 0.02);
    }
    // The box: a floor, a mattress and slatted long sides.
    b.cuboid(
        Frame,
        [-hw + 0.05, -0.8 * hd, zb],
        [hw - 0.05, 0.8 * hd, zb + 0.03],
    );
    b.cuboid(
        Mattress,
        [-hw + 0.07, -0.78 * hd, zb + 0.03],
        [hw - 0.07, 0.78 * hd, zb + 0.1],
    );
    b.ellipsoid(
        Pillow,
        [0.0, -0.6 * hd, zb + 0.12],
        [0.5 * hw, 0.1 * hd, 0.03],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.06);
        b.cuboid(
            Frame,
            [x - 0.015, -0.8 * hd, zs - 0.03],
            [x + 0.015, 0.8 * hd, zs],
        );
        b.cuboid(
            Frame,
            [x - 0.015, -0.8 * hd, zb],
            [x + 0.015, 0.8 * hd, zb + 0.04],
        );
        let n = ((1.6 * hd) / 0.08).floor() as usize;
        for i in 1..n {
            let y = -0.8 * hd + i as f64 * 1.6 * hd / n as f64;
            b.rod(Frame, [x, y, zb + 0.04], [x, y, zs - 0.03], 0.01);
        }
    }
}

/// A bow rocker across the cradle (along x) at y, `hw` half long.
fn rocker_along_y_x(b: &mut Builder, y: f64, hw: f64, rise: f64, r: f64) {
    let n = 12;
    let pts: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let t = -1.0 + 2.0 * i as f64 / n as f64;
            [t * (hw - r), y, r + rise * t * t]
        })
        .collect();
    b.polyline(Frame, &pts, r);
}

/// A rocking horse: a horse on two bow rockers along its length, a mane down its neck, a saddle
/// on its back.
pub fn rocking_horse(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let along_x = b.w > b.d;
    let rock = 0.2 * h;
    let first = b.parts.len();
    // A slimmer animal than the generic one: a toy horse is narrow across its back.
    let (w, d) = (b.w, b.d);
    if along_x {
        b.d = 0.6 * d;
    } else {
        b.w = 0.6 * w;
    }
    b.h = h - rock;
    super::things::quadruped(b);
    (b.w, b.d, b.h) = (w, d, h);
    b.translate_from(first, [0.0, 0.0, rock]);
    let (half_len, half_across) = if along_x { (hw, hd) } else { (hd, hw) };
    // A mane along the top of the neck, from the withers to behind the ears (the neck and
    // head as the quadruped draws them, in its along/across measures).
    let (ha, hh) = (0.6 * half_across, h - rock);
    let map = |along: f64, z: f64| {
        if along_x {
            [along, 0.0, z]
        } else {
            [0.0, along, z]
        }
    };
    let (a0, z0) = (0.55 * half_len, 0.71 * hh);
    let (a1, z1) = (0.82 * half_len, 0.86 * hh);
    for k in 0..7 {
        let t = k as f64 / 6.0;
        let along = a0 + t * (a1 - a0) - 0.35 * ha;
        let z = rock + z0 + t * (z1 - z0) + 0.35 * ha;
        let r = [0.3 * ha, 0.07 * half_len, 0.07 * hh];
        let r = if along_x { [r[1], r[0], r[2]] } else { r };
        b.ellipsoid(Cushion, map(along, z), r);
    }
    let r = 0.025_f64.min(0.1 * half_across);
    for s in [-1.0, 1.0] {
        let c = s * 0.3 * half_across;
        if along_x {
            let n = 14;
            let pts: Vec<[f64; 3]> = (0..=n)
                .map(|i| {
                    let t = -1.0 + 2.0 * i as f64 / n as f64;
                    [t * (half_len - r), c, r + 0.6 * rock * t * t]
                })
                .collect();
            b.polyline(Frame, &pts, r);
        } else {
            rocker_along_y(b, c, half_len, 0.6 * rock, r);
        }
    }
    // Cross bars joining the rockers under the hooves.
    for t in [-0.6, 0.55] {
        let (a, c) = if along_x {
            (
                [t * half_len, -0.3 * half_across, 0.3 * rock],
                [t * half_len, 0.3 * half_across, 0.3 * rock],
            )
        } else {
            (
                [-0.3 * half_across, t * half_len, 0.3 * rock],
                [0.3 * half_across, t * half_len, 0.3 * rock],
            )
        };
        b.rod(Frame, a, c, 0.8 * r);
    }
    // A saddle over the middle of the back.
    let zb = rock + 0.66 * (h - rock) + 0.2 * (h - rock) * 0.9;
    let (sx, sy) = if along_x {
        (0.18 * half_len, 0.6 * half_across)
    } else {
        (0.6 * half_across, 0.18 * half_len)
    };
    b.ellipsoid(Seat, [0.0, 0.0, zb], [sx, sy, 0.04 * h]);
}
