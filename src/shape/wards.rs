//! Layouts of seats and tables for a purpose: an operating table (a narrow jointed pad on a
//! single column over a base, arm boards out to the sides), a theatre seat (a folding
//! upholstered seat between side standards that carry the arms) and a nursing chair (a low
//! armless seat under a tall upholstered back, on short legs). Seats face +y; the operating
//! table's length runs along its longer side.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// An operating table: a base plate, one column, a metal frame and a pad in three sections
/// (head, trunk, legs) with gaps at the joints, and arm boards out to either side.
pub fn operating_table(b: &mut Builder) {
    let (w, d) = (b.w, b.d);
    let along_y = d >= w;
    let (len, wid, h) = (w.max(d), w.min(d), b.h);
    let first = b.parts.len();
    let (hl, hwid) = (len / 2.0, wid / 2.0);
    let pad = (0.1 * h).min(0.08);
    let top = h - pad;
    let frame = 0.05;
    // Base under the middle, a little towards the foot; one column.
    b.cuboid(
        Metal,
        [-0.3 * hl, -0.6 * hwid, 0.0],
        [0.3 * hl, 0.6 * hwid, 0.08],
    );
    b.cuboid(
        Metal,
        [-0.08 * hl, -0.35 * hwid, 0.08],
        [0.08 * hl, 0.35 * hwid, top - frame - 0.04],
    );
    b.cuboid(
        Metal,
        [-0.15 * hl, -0.45 * hwid, top - frame - 0.06],
        [0.15 * hl, 0.45 * hwid, top - frame],
    );
    // The frame and the pad in sections, the table narrower than the arm boards.
    let tw = 0.75 * hwid;
    b.cuboid(Frame, [-hl, -tw, top - frame], [hl, tw, top]);
    let cuts = [-hl, -hl + 0.18 * len, -hl + 0.62 * len, hl];
    for k in 0..3 {
        let (x0, x1) = (cuts[k] + 0.01, cuts[k + 1] - 0.01);
        b.cuboid(Upholstery, [x0, -tw, top], [x1, tw, h]);
    }
    // Arm boards level with the pad, out to both sides at the shoulders.
    let xa = -hl + 0.3 * len;
    for s in [-1.0, 1.0] {
        b.cuboid(
            Upholstery,
            [xa - 0.06, s * tw, top + 0.01],
            [xa + 0.06, s * hwid, h - 0.01],
        );
    }
    // Turn the table to lie along y where it is deeper than wide (head towards -y).
    if along_y {
        for p in &mut b.parts[first..] {
            if let super::parts::Primitive::Cuboid { centre, half, .. } = &mut p.prim {
                *centre = [-centre[1], centre[0], centre[2]];
                *half = [half[1], half[0], half[2]];
            }
        }
    }
}

/// A theatre seat: two side standards carrying padded arms, a tall upholstered back leaning
/// a little, and the seat folded up against it on its hinge.
pub fn theater_seat(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.08 * b.w).min(0.06);
    let arm = 0.65 * h;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(
            Frame,
            [x - t / 2.0, -0.8 * hd, 0.0],
            [x + t / 2.0, 0.5 * hd, arm - 0.04],
        );
        b.cuboid(
            Frame,
            [x - t / 2.0 - 0.01, -0.7 * hd, 0.0],
            [x + t / 2.0 + 0.01, 0.3 * hd, 0.03],
        );
        b.cuboid(
            Top,
            [x - t / 2.0 - 0.01, -0.8 * hd, arm - 0.04],
            [x + t / 2.0 + 0.01, 0.8 * hd, arm],
        );
    }
    let (x0, x1) = (-hw + t + 0.01, hw - t - 0.01);
    // The back: a padded panel leaning back about 10°, its shell behind.
    let lean = 0.17f64;
    let bh = 0.62 * h;
    let (s, c) = lean.sin_cos();
    let yb = -0.55 * hd;
    let zb = h - bh;
    let cb = [0.0, yb - 0.5 * bh * s, zb + 0.5 * bh * c];
    b.slab(
        Upholstery,
        cb,
        [0.5 * (x1 - x0), 0.06, 0.5 * bh],
        rot_x(lean),
    );
    b.slab(
        Body,
        [cb[0], cb[1] - 0.07 * c, cb[2] - 0.07 * s],
        [0.5 * (x1 - x0), 0.012, 0.5 * bh],
        rot_x(lean),
    );
    // The seat, folded up on its hinge in front of the back.
    let seat = 0.5 * b.d;
    let ys = yb + 0.14;
    b.cuboid(
        Upholstery,
        [x0, ys, 0.4 * h],
        [x1, ys + 0.08, 0.4 * h + seat],
    );
    b.cuboid(
        Body,
        [x0, ys + 0.08, 0.4 * h],
        [x1, ys + 0.095, 0.4 * h + seat],
    );
    b.rod(
        Metal,
        [x0 - 0.01, ys + 0.05, 0.43 * h],
        [x1 + 0.01, ys + 0.05, 0.43 * h],
        0.015,
    );
}

/// A nursing chair: a low upholstered seat on a plinth with short legs, no arms, and a tall
/// back leaning a little, rounded at the top.
pub fn nursing_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let legs = 0.12 * h;
    let seat = (0.38 * h).min(0.4);
    b.legs(Frame, 0.035, 0.05, 0.0, legs);
    b.cuboid(
        Upholstery,
        [-0.9 * hw, -hd + 0.12, legs],
        [0.9 * hw, hd, seat - 0.08],
    );
    b.cuboid(
        Cushion,
        [-0.88 * hw, -hd + 0.18, seat - 0.08],
        [0.88 * hw, hd - 0.02, seat],
    );
    // The back: tall, slightly reclined, its top rounded.
    let lean = 0.14f64;
    let (s, c) = lean.sin_cos();
    let bh = (h - legs - 0.08) / c;
    let th = 0.12;
    let cb = [0.0, -hd + 0.5 * th + 0.5 * bh * s, legs + 0.5 * bh * c];
    b.slab(Upholstery, cb, [0.85 * hw, 0.5 * th, 0.5 * bh], rot_x(lean));
    let y_top = cb[1] - 0.5 * bh * s;
    b.ellipsoid_rot(
        Upholstery,
        0,
        [0.0, y_top, h - 0.1],
        [0.85 * hw, 0.5 * th, 0.1],
        rot_x(lean),
    );
}
