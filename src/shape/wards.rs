//! Layouts of seats and tables for a purpose: an operating table (a narrow jointed pad on a
//! single column over a base, arm boards out to the sides), a theatre seat (a folding
//! upholstered seat between side standards that carry the arms), a nursing chair (a glider: a
//! low seat under a tall upholstered back, hung between padded side frames on floor runners)
//! and an examination lamp (a wheeled pole with an arm out to a round flat head). Seats face
//! +y; the operating table's length runs along its longer side.
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

/// A nursing chair: a glider. A low upholstered seat under a tall back leaning a little, its
/// top rounded, hung between two side frames with padded arms that stand on floor runners, so
/// the seat glides back and forth on the swing links between them.
pub fn nursing_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let base = 0.1 * h;
    let seat = (0.42 * h).min(0.45);
    let side = (0.1 * b.w).clamp(0.05, 0.09);
    let arm = seat + 0.2;
    let xi = hw - side;
    // Floor runners, a cross bar between them, and the side frames: two posts and a padded arm.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.5 * side);
        b.cuboid(
            Frame,
            [x - 0.5 * side, -hd, 0.0],
            [x + 0.5 * side, hd, 0.04],
        );
        for y in [-0.7 * hd, 0.75 * hd] {
            b.cuboid(
                Frame,
                [x - 0.02, y - 0.025, 0.04],
                [x + 0.02, y + 0.025, arm - 0.05],
            );
        }
        b.cuboid(
            Upholstery,
            [x - 0.5 * side, -0.85 * hd, arm - 0.05],
            [x + 0.5 * side, hd, arm],
        );
        // The swing links from under the arm down to the seat's rail.
        for y in [-0.5 * hd, 0.5 * hd] {
            let xs = sx * (xi - 0.01);
            b.rod(Metal, [x, y, arm - 0.06], [xs, y - 0.05, base + 0.05], 0.01);
        }
    }
    b.cuboid(Frame, [-xi, -0.1, 0.0], [xi, 0.1, 0.03]);
    // The seat hangs between the side frames on its rail.
    b.cuboid(
        Frame,
        [-xi + 0.01, -hd + 0.1, base + 0.03],
        [xi - 0.01, hd - 0.05, base + 0.07],
    );
    b.cuboid(
        Upholstery,
        [-xi + 0.02, -hd + 0.12, base + 0.07],
        [xi - 0.02, hd - 0.04, seat - 0.08],
    );
    b.cuboid(
        Cushion,
        [-xi + 0.03, -hd + 0.18, seat - 0.08],
        [xi - 0.03, hd - 0.05, seat],
    );
    // The back: tall, slightly reclined, its top rounded.
    let lean = 0.14f64;
    let (s, c) = lean.sin_cos();
    let bh = (h - base - 0.08) / c;
    let th = 0.12;
    let cb = [0.0, -hd + 0.5 * th + 0.5 * bh * s, base + 0.5 * bh * c];
    b.slab(Upholstery, cb, [xi - 0.02, 0.5 * th, 0.5 * bh], rot_x(lean));
    let y_top = cb[1] - 0.5 * bh * s;
    b.ellipsoid_rot(
        Upholstery,
        0,
        [0.0, y_top, h - 0.1],
        [xi - 0.02, 0.5 * th, 0.1],
        rot_x(lean),
    );
}

/// An examination lamp: a five-spoke base on castors at its back, a pole, and a jointed arm
/// reaching forwards from its top to a round flat head facing down, its light on the underside.
pub fn examination_lamp(b: &mut Builder) {
    // Drawn reaching along x, then turned so the arm reaches forwards (+y), towards what the
    // lamp is set beside: its half width along x is the size's half depth.
    let first = b.parts.len();
    let (hw, hd, h) = (b.d / 2.0, b.w / 2.0, b.h);
    // The base and pole stand at one side, so the arm reaches the head across the size box.
    let r = 0.4 * hw.min(hd);
    let xb = -hw + r + 0.03;
    let wheel = 0.025;
    for k in 0..5 {
        let a = k as f64 / 5.0 * std::f64::consts::TAU;
        let (c, s) = (a.cos(), a.sin());
        let (x, y) = (xb + r * c, r * s);
        b.rod(
            Metal,
            [xb, 0.0, 2.0 * wheel + 0.02],
            [x, y, 2.0 * wheel + 0.01],
            0.012,
        );
        b.rod(Tyre, [x - 0.012, y, wheel], [x + 0.012, y, wheel], wheel);
    }
    // The pole, its joint, and the arm up and out across the size box to the head.
    let zp = 0.72 * h;
    b.cylinder(Metal, [xb, 0.0, 2.0 * wheel], 0.018, zp - 2.0 * wheel);
    b.ellipsoid(Frame, [xb, 0.0, zp], [0.03, 0.03, 0.03]);
    let head_r = (0.6 * hw.min(hd)).min(0.25);
    let head_h = (0.3 * head_r).min(0.07);
    let hx = hw - head_r;
    let elbow = [xb + 0.3 * hw, 0.0, h - 0.05];
    b.polyline(Metal, &[[xb, 0.0, zp], elbow, [hx, 0.0, h - 0.01]], 0.012);
    // The head: a shallow dish, its rim a little wider than its crown, the light beneath.
    let zh = h - head_h - 0.02;
    b.revolved(
        Shade,
        0,
        [hx, 0.0, zh],
        super::parts::IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [head_r, 0.0],
            [0.85 * head_r, head_h],
            [0.2 * head_r, head_h + 0.02],
            [0.0, head_h + 0.02],
        ],
    );
    b.cylinder(Light, [hx, 0.0, zh - 0.004], 0.7 * head_r, 0.004);
    b.rod(Handle, [hx, 0.0, zh - 0.004], [hx, 0.0, zh - 0.05], 0.012);
    b.turn_from(first, super::parts::rot_z(std::f64::consts::FRAC_PI_2));
}
