//! Layouts of tables, seats and beds. Proportions follow real furniture (seat at ~0.45 of a chair's
//! height, table tops 3-5 cm thick, mattress top at ~0.55 m); the front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use std::f64::consts::{FRAC_PI_2, TAU};

/// Height kept above a table's top for what it holds (books in low stacks, dishes), so the
/// goods stay inside its box: none when it holds nothing.
fn held_room(b: &Builder) -> f64 {
    b.goods.map_or(0.0, |_| (0.12 * b.h).clamp(0.04, 0.1))
}

/// A table on four legs with aprons; what it holds (`Builder::goods`: "a table of new
/// releases") lies on its top.
pub fn table(b: &mut Builder) {
    let room = held_room(b);
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h - room);
    let t = (0.05 * h).clamp(0.025, 0.05);
    b.cuboid(Top, [-hw, -hd, h - t], [hw, hd, h]);
    let s = (0.06 * b.w.min(b.d)).clamp(0.035, 0.08);
    let inset = (0.03 * b.w.min(b.d)).min(0.05);
    b.legs(Frame, s, inset, 0.0, h - t);
    // Apron boards just under the top, between the legs.
    let a = (0.12 * h).min(0.09);
    let (ix, iy) = (hw - inset - s / 2.0, hd - inset - s / 2.0);
    let th = 0.018;
    for sy in [-1.0, 1.0] {
        let y = sy * iy;
        b.cuboid(Frame, [-ix, y - th, h - t - a], [ix, y + th, h - t]);
    }
    for sx in [-1.0, 1.0] {
        let x = sx * ix;
        b.cuboid(Frame, [x - th, -iy, h - t - a], [x + th, iy, h - t]);
    }
    if let Some(g) = b.goods {
        super::wares::on_top(b, g, h, 0.9 * hw, 0.85 * hd, false, room);
    }
}

pub fn round_table(b: &mut Builder) {
    let room = held_room(b);
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h - room);
    let t = (0.05 * h).clamp(0.025, 0.05);
    // Round: a circle as wide as the box's shorter side (an oval is `oval_table`).
    let m = hw.min(hd);
    b.frustum(Top, [0.0, 0.0, h - t], m, m, 1.0, t);
    b.cylinder(Frame, [0.0, 0.0, 0.04], (0.12 * m).max(0.03), h - t - 0.04);
    b.frustum(Frame, [0.0, 0.0, 0.0], 0.6 * m, 0.6 * m, 0.45, 0.05);
    if let Some(g) = b.goods {
        super::wares::on_top(b, g, h, m, m, true, room);
    }
}

pub fn desk(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.035;
    b.cuboid(Top, [-hw, -hd, h - t], [hw, hd, h]);
    // Drawer pedestal on the left, a side panel on the right, a modesty panel at the back.
    let pw = (0.35 * b.w).min(0.45);
    let x0 = -hw + 0.01;
    let front = hd - 0.03;
    b.cuboid(Body, [x0, -hd + 0.02, 0.0], [x0 + pw, front, h - t]);
    let rows = 3;
    let fh = (h - t - 0.03) / rows as f64;
    for r in 0..rows {
        let z0 = 0.02 + r as f64 * fh;
        let (z0, z1) = (z0 + 0.006, z0 + fh - 0.006);
        b.cuboid(
            Door,
            [x0 + 0.01, front, z0],
            [x0 + pw - 0.01, hd - 0.012, z1],
        );
        let zc = 0.5 * (z0 + z1);
        let xc = x0 + pw / 2.0;
        b.cuboid(
            Handle,
            [xc - 0.05, hd - 0.012, zc - 0.008],
            [xc + 0.05, hd, zc + 0.008],
        );
    }
    b.cuboid(
        Frame,
        [hw - 0.045, -hd + 0.02, 0.0],
        [hw - 0.01, hd - 0.02, h - t],
    );
    b.cuboid(
        Body,
        [x0 + pw, -hd + 0.03, 0.3 * h],
        [hw - 0.045, -hd + 0.05, h - t],
    );
}

/// Seat and back of a chair: seat top at `zs`, back posts at −y.
pub fn chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = (0.5 * h).min(0.47);
    let st = 0.045;
    let l = (0.08 * b.w).clamp(0.03, 0.05);
    b.cuboid(Seat, [-hw, -hd, zs - st], [hw, hd, zs]);
    let mut xs = vec![-hw, hw - l];
    if b.w > 1.4 {
        xs.push(-l / 2.0);
    }
    for &x in &xs {
        b.cuboid(Frame, [x, hd - l, 0.0], [x + l, hd, zs - st]);
        b.cuboid(Frame, [x, -hd, 0.0], [x + l, -hd + l, h]);
        // Side stretcher between front and back legs.
        b.cuboid(
            Frame,
            [x + 0.2 * l, -hd + l, 0.14 * zs],
            [x + 0.8 * l, hd - l, 0.14 * zs + 0.025],
        );
    }
    let tb = (0.07 * b.d).clamp(0.02, 0.04);
    b.cuboid(
        Seat,
        [-hw + l, -hd + 0.003, zs + 0.3 * (h - zs)],
        [hw - l, -hd + tb, h - 0.01],
    );
    b.cuboid(
        Frame,
        [-hw + l, -hd + 0.005, zs + 0.08],
        [hw - l, -hd + l - 0.005, zs + 0.12],
    );
}

/// Upholstered seat: base, back at −y, two arms, seat and back cushions, short legs.
fn upholstered(b: &mut Builder, arm: f64, seats: usize) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lh = (0.1 * h).min(0.1);
    let base_top = 0.42 * h;
    let back = (0.22 * b.d).min(0.25);
    let leg = 0.05;
    b.legs(Frame, leg, 0.03, 0.0, lh);
    b.cuboid(
        Upholstery,
        [-hw + arm, -hd, lh],
        [hw - arm, hd - 0.02, base_top],
    );
    b.cuboid(Upholstery, [-hw, -hd, lh], [hw, -hd + back, h]);
    let arm_top = 0.68 * h;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw, -hw + arm)
        } else {
            (hw - arm, hw)
        };
        b.cuboid(
            Upholstery,
            [x0, -hd + back, lh],
            [x1, hd, arm_top - arm / 2.0],
        );
        // Rolled arm top.
        b.rod(
            Upholstery,
            [0.5 * (x0 + x1), -hd + back, arm_top - arm / 2.0],
            [0.5 * (x0 + x1), hd, arm_top - arm / 2.0],
            arm / 2.0,
        );
    }
    let inner = b.w - 2.0 * arm;
    let cw = inner / seats as f64;
    let gap = 0.006;
    for i in 0..seats {
        let x0 = -hw + arm + i as f64 * cw;
        b.cuboid(
            Cushion,
            [x0 + gap, -hd + back, base_top],
            [x0 + cw - gap, hd - 0.01, base_top + 0.12 * h],
        );
        b.cuboid(
            Cushion,
            [x0 + gap, -hd + back, base_top + 0.12 * h],
            [x0 + cw - gap, -hd + back + 0.16 * b.d, 0.93 * h],
        );
    }
}

pub fn armchair(b: &mut Builder) {
    let arm = (0.16 * b.w).min(0.18);
    upholstered(b, arm, 1);
}

pub fn sofa(b: &mut Builder) {
    let arm = (0.1 * b.w).clamp(0.12, 0.22);
    let seats = (((b.w - 2.0 * arm) / 0.6).round() as usize).clamp(1, 4);
    upholstered(b, arm, seats);
}

pub fn office_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd) - 0.03;
    let zs = (0.45 * h).min(0.5);
    for k in 0..5 {
        let a = k as f64 / 5.0 * TAU + FRAC_PI_2;
        let (s, c) = a.sin_cos();
        b.rod(Metal, [0.0, 0.0, 0.07], [r * c, r * s, 0.05], 0.018);
        b.ellipsoid(Metal, [r * c, r * s, 0.025], [0.025, 0.025, 0.025]);
    }
    b.cylinder(Metal, [0.0, 0.0, 0.05], 0.03, 0.04);
    b.cylinder(Metal, [0.0, 0.0, 0.08], 0.022, zs - 0.14);
    b.cuboid(
        Upholstery,
        [-0.42 * b.w, -0.38 * b.d, zs - 0.07],
        [0.42 * b.w, hd - 0.01, zs],
    );
    b.cuboid(
        Metal,
        [-0.2 * b.w, -0.2 * b.d, zs - 0.1],
        [0.2 * b.w, 0.2 * b.d, zs - 0.07],
    );
    b.cuboid(
        Metal,
        [-0.03, -hd, zs - 0.09],
        [0.03, -hd + 0.04, zs + 0.12],
    );
    b.cuboid(
        Metal,
        [-0.03, -hd + 0.02, zs - 0.1],
        [0.03, -0.2 * b.d, zs - 0.07],
    );
    b.cuboid(
        Upholstery,
        [-0.36 * b.w, -hd + 0.03, zs + 0.08],
        [0.36 * b.w, -hd + 0.1, h],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.44 * b.w;
        b.cuboid(
            Metal,
            [x - 0.015, -0.1 * b.d, zs - 0.05],
            [x + 0.015, -0.05 * b.d, zs + 0.2],
        );
        b.cuboid(
            Upholstery,
            [x - 0.03, -0.25 * b.d, zs + 0.2],
            [x + 0.03, 0.2 * b.d, zs + 0.23],
        );
    }
}

pub fn stool(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.05;
    b.frustum(Seat, [0.0, 0.0, h - t], hw, hd, 1.0, t);
    let r = 0.02_f64.max(0.04 * hw);
    for k in 0..4 {
        let a = (k as f64 + 0.5) / 4.0 * TAU;
        let (s, c) = a.sin_cos();
        let foot = [(hw - r) * c, (hd - r) * s, 0.0];
        let top = [0.6 * hw * c, 0.6 * hd * s, h - t];
        b.rod(Frame, foot, top, r);
        let a2 = (k as f64 + 1.5) / 4.0 * TAU;
        let (s2, c2) = a2.sin_cos();
        let f = 0.3;
        let p = |c: f64, s: f64| {
            [
                (hw - r) * c * (1.0 - f) + 0.6 * hw * c * f,
                (hd - r) * s * (1.0 - f) + 0.6 * hd * s * f,
                f * (h - t),
            ]
        };
        b.rod(Frame, p(c, s), p(c2, s2), 0.7 * r);
    }
}

/// A bench: a slab seat on two end frames; taller than 0.65 m it is a seat at 0.45 m with a
/// backrest of slats at the back (−y), as park benches and pews have.
pub fn bench(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.1 * h).clamp(0.03, 0.06);
    if h > 0.65 && b.d < 1.2 {
        let seat = 0.45f64.min(0.55 * h);
        b.cuboid(Seat, [-hw, -hd + 0.06, seat - t], [hw, hd, seat]);
        for k in 0..3 {
            let z0 = seat + 0.08 + k as f64 * (h - seat - 0.08) / 3.0;
            let z1 = z0 + 0.7 * (h - seat - 0.08) / 3.0;
            b.cuboid(Seat, [-hw, -hd, z0], [hw, -hd + 0.04, z1]);
        }
        let inset = (0.08 * b.w).min(0.12);
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - inset);
            b.cuboid(
                Frame,
                [x - 0.03, -hd + 0.02, 0.0],
                [x + 0.03, hd - 0.03, seat - t],
            );
            b.cuboid(
                Frame,
                [x - 0.03, -hd + 0.04, seat - t],
                [x + 0.03, -hd + 0.1, h],
            );
        }
        return;
    }
    if h > 0.65 {
        // Deep and tall: tiers of seats rising to the back (bleachers, stepped seating).
        let n = ((h / 0.45).round() as usize).clamp(2, 8);
        for k in 0..n {
            let z = h * (k + 1) as f64 / n as f64;
            let y0 = hd - b.d * (k + 1) as f64 / n as f64;
            b.cuboid(Frame, [-hw, y0, 0.0], [hw, y0 + b.d / n as f64, z - t]);
            b.cuboid(Seat, [-hw, y0, z - t], [hw, y0 + b.d / n as f64, z]);
        }
        return;
    }
    b.cuboid(Seat, [-hw, -hd, h - t], [hw, hd, h]);
    let inset = (0.08 * b.w).min(0.12);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - inset);
        b.cuboid(
            Frame,
            [x - 0.025, -hd + 0.03, 0.0],
            [x + 0.025, hd - 0.03, h - t],
        );
    }
    b.cuboid(
        Frame,
        [-hw + inset, -0.02, 0.25 * h],
        [hw - inset, 0.02, 0.25 * h + 0.04],
    );
}

pub fn ottoman(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Upholstery, [0.0, 0.0, 0.04], hw, hd, 1.0, h - 0.04);
    b.frustum(Frame, [0.0, 0.0, 0.0], 0.85 * hw, 0.85 * hd, 1.0, 0.04);
}

/// Mattress top height of a bed of height `h`.
fn mattress_top(h: f64) -> f64 {
    (0.55_f64).min(0.6 * h)
}

pub fn bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zm = mattress_top(h);
    let zf = zm - 0.22;
    let head = 0.06;
    b.legs(Frame, 0.06, 0.0, 0.0, zf);
    b.cuboid(Frame, [-hw, -hd + head, 0.08], [hw, hd - 0.04, zf]);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + head, h]);
    b.cuboid(Frame, [-hw, hd - 0.04, 0.0], [hw, hd, zf + 0.08]);
    b.cuboid(
        Mattress,
        [-hw + 0.03, -hd + head, zf],
        [hw - 0.03, hd - 0.05, zm - 0.02],
    );
    let duvet_back = -hd + head + 0.3 * b.d;
    b.cuboid(
        Duvet,
        [-hw + 0.015, duvet_back, zm - 0.14],
        [hw - 0.015, hd - 0.045, zm],
    );
    let pillows = if b.w > 1.3 { 2 } else { 1 };
    let pw = (b.w - 0.12) / pillows as f64;
    for i in 0..pillows {
        let x = -hw + 0.06 + (i as f64 + 0.5) * pw;
        b.ellipsoid(
            Pillow,
            [x, -hd + head + 0.2, zm + 0.03],
            [0.45 * pw, 0.17, 0.07],
        );
    }
}

pub fn bunk_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let p = 0.06;
    b.legs(Frame, p, 0.0, 0.0, h);
    for z in [0.12, 0.58 * h] {
        b.cuboid(Frame, [-hw + p, -hd, z], [hw - p, hd, z + 0.1]);
        b.cuboid(
            Mattress,
            [-hw + p, -hd + p, z + 0.1],
            [hw - p, hd - p, z + 0.22],
        );
        b.cuboid(
            Duvet,
            [-hw + p, -hd + 0.6, z + 0.22],
            [hw - p, hd - p, z + 0.25],
        );
        b.ellipsoid(
            Pillow,
            [0.0, -hd + p + 0.18, z + 0.27],
            [0.3 * b.w, 0.14, 0.05],
        );
    }
    b.cuboid(Frame, [-hw, -hd, h - 0.12], [hw, -hd + p, h - 0.04]);
    b.cuboid(Frame, [-hw, hd - p, h - 0.12], [hw, hd, h - 0.04]);
    // Guard rail and ladder on the front (+x side is the room side of a bunk bed's long edge).
    b.cuboid(
        Frame,
        [hw - 0.04, -hd + p, 0.58 * h + 0.32],
        [hw, hd - p, 0.58 * h + 0.38],
    );
    let ly = hd - 0.45;
    for dy in [-0.18, 0.18] {
        b.cuboid(
            Frame,
            [hw - 0.04, ly + dy - 0.02, 0.0],
            [hw, ly + dy + 0.02, 0.58 * h + 0.1],
        );
    }
    let mut z = 0.3;
    while z < 0.58 * h {
        b.rod(
            Frame,
            [hw - 0.02, ly - 0.18, z],
            [hw - 0.02, ly + 0.18, z],
            0.015,
        );
        z += 0.28;
    }
}
