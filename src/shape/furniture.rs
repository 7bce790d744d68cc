//! Layouts of furniture archetypes: tables, seats, beds, case goods, shelves, lamps, rugs,
//! kitchen and bathroom fixtures. Proportions follow real furniture (seat at ~0.45 of a chair's
//! height, table tops 3-5 cm thick, mattress top at ~0.55 m); the front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, IDENTITY};
use std::f64::consts::{FRAC_PI_2, TAU};

pub fn table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
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
}

pub fn round_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.05 * h).clamp(0.025, 0.05);
    let m = hw.min(hd);
    b.frustum(Top, [0.0, 0.0, h - t], hw, hd, 1.0, t);
    b.cylinder(Frame, [0.0, 0.0, 0.04], (0.12 * m).max(0.03), h - t - 0.04);
    b.frustum(Frame, [0.0, 0.0, 0.0], 0.6 * hw, 0.6 * hd, 0.45, 0.05);
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

pub fn bench(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.1 * h).clamp(0.03, 0.06);
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

/// A case (cabinet, dresser, wardrobe): carcass on a plinth or legs, top, fronts with handles.
/// `drawers` rows of drawers above `doors` doors (side by side); `legs` lifts it on legs.
fn case(b: &mut Builder, doors: usize, drawers: usize, legs: bool) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let base = if legs {
        (0.15 * h).min(0.15)
    } else {
        (0.06 * h).min(0.08)
    };
    let top = 0.025;
    let face = hd - 0.035;
    if legs {
        b.legs(Frame, 0.04, 0.03, 0.0, base);
    } else {
        b.cuboid(
            Frame,
            [-hw + 0.02, -hd + 0.02, 0.0],
            [hw - 0.02, face - 0.02, base],
        );
    }
    b.cuboid(Body, [-hw, -hd, base], [hw, face, h - top]);
    b.cuboid(Top, [-hw, -hd, h - top], [hw, hd - 0.01, h]);
    let (z_lo, z_hi) = (base + 0.01, h - top - 0.01);
    let gap = 0.005;
    let cols = if b.w > 1.0 && doors == 0 { 2 } else { 1 };
    let front = |b: &mut Builder, x0: f64, x1: f64, z0: f64, z1: f64| {
        b.cuboid(
            Door,
            [x0 + gap, face, z0 + gap],
            [x1 - gap, hd - 0.014, z1 - gap],
        );
    };
    let drawer_h = if doors > 0 {
        ((z_hi - z_lo) * 0.18).min(0.2)
    } else {
        (z_hi - z_lo) / drawers.max(1) as f64
    };
    let mut z = z_hi;
    for _ in 0..drawers {
        let cw = (b.w - 0.02) / cols as f64;
        for c in 0..cols {
            let x0 = -hw + 0.01 + c as f64 * cw;
            front(b, x0, x0 + cw, z - drawer_h, z);
            let (xc, zc) = (x0 + cw / 2.0, z - drawer_h / 2.0);
            let hl = (0.15 * cw).min(0.07);
            b.cuboid(
                Handle,
                [xc - hl, hd - 0.014, zc - 0.008],
                [xc + hl, hd, zc + 0.008],
            );
        }
        z -= drawer_h;
    }
    if doors > 0 {
        let dw = (b.w - 0.02) / doors as f64;
        for i in 0..doors {
            let x0 = -hw + 0.01 + i as f64 * dw;
            front(b, x0, x0 + dw, z_lo, z);
            // Handle on the door's inner edge (towards the centre), at a comfortable height.
            let xc = if x0 + dw / 2.0 < 0.0 {
                x0 + dw - 0.04
            } else {
                x0 + 0.04
            };
            let zc = (z_lo + 0.55 * (z - z_lo)).min(1.1);
            let hl = (0.06 * (z - z_lo)).clamp(0.03, 0.12);
            b.cuboid(
                Handle,
                [xc - 0.008, hd - 0.014, zc - hl],
                [xc + 0.008, hd, zc + hl],
            );
        }
    }
}

pub fn cabinet(b: &mut Builder) {
    let doors = if b.w < 0.6 { 1 } else { 2 };
    case(b, doors, 0, false);
}

pub fn dresser(b: &mut Builder) {
    let rows = ((b.h / 0.22).round() as usize).clamp(2, 6);
    case(b, 0, rows, b.h < 1.2);
}

pub fn wardrobe(b: &mut Builder) {
    let doors = ((b.w / 0.5).round() as usize).clamp(1, 4);
    case(b, doors, 1, false);
}

pub fn sideboard(b: &mut Builder) {
    let doors = ((b.w / 0.45).round() as usize).clamp(1, 5);
    case(b, doors, 0, true);
}

/// A glass-fronted cabinet: closed base, glass upper case with shelves inside.
pub fn glass_cabinet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = if h > 1.4 { 0.4 * h } else { 0.1 * h };
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, zb]);
    b.cuboid(Top, [-hw, -hd, h - 0.04], [hw, hd, h]);
    let f = 0.03;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - f / 2.0);
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - f / 2.0);
            b.cuboid(
                Body,
                [x - f / 2.0, y - f / 2.0, zb],
                [x + f / 2.0, y + f / 2.0, h - 0.04],
            );
        }
    }
    b.cuboid(Interior, [-hw + f, -hd, zb], [hw - f, -hd + 0.01, h - 0.04]);
    let mut z = zb + 0.3;
    let mut v = 0;
    while z < h - 0.1 {
        b.cuboid(Body, [-hw + f, -hd + 0.01, z], [hw - f, hd - f, z + 0.015]);
        let mut x = -hw + f + 0.05;
        while x < hw - f - 0.12 {
            b.ellipsoid_rot(
                Books,
                v,
                [x + 0.05, -hd * 0.2, z + 0.08],
                [0.045, 0.045, 0.065],
                IDENTITY,
            );
            x += 0.14;
            v += 1;
        }
        z += 0.35;
    }
    b.cuboid(Glass, [-hw + f, hd - 0.006, zb], [hw - f, hd, h - 0.04]);
    b.cuboid(Glass, [-hw, -hd + f, zb], [-hw + 0.006, hd - f, h - 0.04]);
    b.cuboid(Glass, [hw - 0.006, -hd + f, zb], [hw, hd - f, h - 0.04]);
}

/// Shelves filled with items `item` wide on average (books ~4 cm, boxes ~25 cm).
fn shelves(b: &mut Builder, item: f64, back: bool) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.025;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Frame, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, hd, h]);
    }
    if back {
        b.cuboid(Interior, [-hw + t, -hd, 0.0], [hw - t, -hd + 0.012, h]);
    }
    let rows = ((h / 0.38).round() as usize).max(2);
    let plinth = 0.06;
    let pitch = (h - plinth - t) / rows as f64;
    b.cuboid(Frame, [-hw + t, -hd + 0.012, 0.0], [hw - t, hd, plinth]);
    let mut rng = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng % 10_000) as f64 / 10_000.0
    };
    let mut v = 0;
    for r in 0..=rows {
        let z = plinth + r as f64 * pitch;
        b.cuboid(
            Frame,
            [-hw + t, -hd + 0.012, z.min(h - t)],
            [hw - t, hd, (z + t).min(h)],
        );
        if r == rows {
            break;
        }
        let mut x = -hw + t + 0.01;
        let end = hw - t - 0.01;
        let room = pitch - t - 0.02;
        while x < end - 0.02 {
            let bw = (item * (0.6 + 0.8 * next())).min(end - x);
            if next() < 0.08 {
                x += bw;
                continue;
            }
            let bh = room * (0.65 + 0.3 * next());
            let depth = (0.8 * b.d).min(0.3);
            b.cuboid_v(
                Books,
                v,
                [x, -hd + 0.014, z + t],
                [x + bw - 0.002, -hd + 0.014 + depth, z + t + bh],
            );
            v += 1 + (next() * 3.0) as u32;
            x += bw;
        }
    }
}

pub fn shelf(b: &mut Builder) {
    shelves(b, 0.04, true);
}

pub fn rack(b: &mut Builder) {
    shelves(b, 0.25, false);
}

pub fn floor_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.7 * hw, 0.7 * hd, 0.8, 0.03);
    let sh = (0.22 * h).min(0.4);
    b.cylinder(Metal, [0.0, 0.0, 0.03], 0.012, h - sh - 0.02);
    b.frustum(Shade, [0.0, 0.0, h - sh], hw, hd, 0.7, sh);
    b.cylinder(Light, [0.0, 0.0, h - sh - 0.03], 0.03, 0.04);
}

pub fn table_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.42 * h;
    b.cylinder(Metal, [0.0, 0.0, 0.0], 0.45 * hw.min(hd), 0.02);
    b.ellipsoid(
        Body,
        [0.0, 0.0, zb / 2.0 + 0.01],
        [0.55 * hw, 0.55 * hd, zb / 2.0],
    );
    b.cylinder(Metal, [0.0, 0.0, zb], 0.008, 0.12 * h);
    let sh = 0.45 * h;
    b.frustum(Shade, [0.0, 0.0, h - sh], hw, hd, 0.65, sh);
}

pub fn rug(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let bw = (0.08 * b.w.min(b.d)).min(0.15);
    b.cuboid(Cushion, [-hw, -hd, 0.0], [hw, -hd + bw, h]);
    b.cuboid(Cushion, [-hw, hd - bw, 0.0], [hw, hd, h]);
    b.cuboid(Cushion, [-hw, -hd + bw, 0.0], [-hw + bw, hd - bw, h]);
    b.cuboid(Cushion, [hw - bw, -hd + bw, 0.0], [hw, hd - bw, h]);
    b.cuboid(Upholstery, [-hw + bw, -hd + bw, 0.0], [hw - bw, hd - bw, h]);
}

/// Base cabinets with doors and a top: the top's thickness is `top`.
fn base_cabinets(b: &mut Builder, top_z: f64) {
    let (hw, hd) = b.half();
    let face = hd - 0.045;
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd, 0.0],
        [hw - 0.02, face - 0.04, 0.09],
    );
    b.cuboid(Body, [-hw, -hd, 0.09], [hw, face, top_z]);
    let doors = ((b.w / 0.55).round() as usize).max(1);
    let dw = (b.w - 0.01) / doors as f64;
    for i in 0..doors {
        let x0 = -hw + 0.005 + i as f64 * dw;
        b.cuboid(
            Door,
            [x0 + 0.004, face, 0.1],
            [x0 + dw - 0.004, hd - 0.025, top_z - 0.01],
        );
        let xc = x0 + dw / 2.0;
        b.cuboid(
            Handle,
            [xc - 0.07, hd - 0.025, top_z - 0.07],
            [xc + 0.07, hd - 0.01, top_z - 0.055],
        );
    }
}

pub fn counter(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    base_cabinets(b, h - 0.04);
    b.cuboid(Top, [-hw, -hd, h - 0.04], [hw, hd, h]);
}

pub fn sink(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // A vessel basin on the counter (bathroom) or an inset tub with a rim (kitchen).
    let bowl = (0.16 * h).min(0.15);
    let zt = h - bowl;
    base_cabinets(b, zt - 0.035);
    b.cuboid(Top, [-hw, -hd, zt - 0.035], [hw, hd, zt]);
    let (rx, ry) = ((0.3 * b.w).min(0.3), (0.32 * b.d).min(0.22));
    let yc = 0.05 * b.d;
    let profile = vec![
        [0.6 * rx, 0.0],
        [rx, bowl * 0.7],
        [rx, bowl],
        [0.9 * rx, bowl],
        [0.55 * rx, 0.02],
        [0.0, 0.02],
    ];
    b.revolved(Canvas, 0, [0.0, yc, zt], IDENTITY, ry / rx, profile);
    let yf = yc - ry - 0.05;
    b.cylinder(
        Metal,
        [0.0, yf, zt],
        0.018,
        bowl + 0.1_f64.min(h - zt - bowl) - 0.005,
    );
    b.rod(
        Metal,
        [0.0, yf, h - 0.02],
        [0.0, yf + 0.12, h - 0.02],
        0.012,
    );
}

pub fn fireplace(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let mantel = 0.06;
    b.cuboid(
        Body,
        [-hw + 0.05, -hd, 0.0],
        [hw - 0.05, hd - 0.12, h - mantel],
    );
    b.cuboid(Top, [-hw, -hd, h - mantel], [hw, hd - 0.05, h]);
    b.cuboid(Body, [-hw + 0.02, -hd, 0.0], [hw - 0.02, hd, 0.08]);
    let (ow, oh) = (0.55 * b.w, 0.6 * (h - mantel));
    b.cuboid(
        Interior,
        [-ow / 2.0, hd - 0.125, 0.08],
        [ow / 2.0, hd - 0.115, 0.08 + oh],
    );
    for k in 0..3 {
        let x = (k as f64 - 1.0) * 0.12 * b.w;
        b.ellipsoid(Light, [x, hd - 0.2, 0.16], [0.05 * b.w, 0.04, 0.07 * h]);
    }
}

pub fn piano(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zk = 0.58 * h.min(1.25);
    let body_front = -hd + 0.55 * b.d;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, body_front, h]);
    // Keyboard shelf, white and black keys, legs under it.
    b.cuboid(
        Body,
        [-hw, body_front, zk - 0.08],
        [hw, hd - 0.02, zk - 0.02],
    );
    b.cuboid(
        Keys,
        [-hw + 0.08, body_front, zk - 0.02],
        [hw - 0.08, hd - 0.04, zk],
    );
    let n = ((b.w - 0.16) / 0.0235 * 5.0 / 7.0) as usize;
    let kw = (b.w - 0.16) / n as f64;
    for i in 0..n {
        if [1, 3, 6, 8, 10].contains(&(i % 12)) || i % 2 == 1 {
            continue;
        }
        let x = -hw + 0.08 + (i as f64 + 0.75) * kw;
        b.cuboid(
            BlackKeys,
            [x, body_front + 0.01, zk],
            [x + 0.6 * kw, body_front + 0.09, zk + 0.012],
        );
    }
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.05);
        b.cuboid(Frame, [x - 0.03, hd - 0.06, 0.0], [x + 0.03, hd, zk - 0.08]);
    }
    b.cuboid(
        Frame,
        [-0.25 * b.w, body_front, 0.08],
        [0.25 * b.w, body_front + 0.04, 0.12],
    );
}

pub fn grand_piano(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.6 * h;
    let kd = 0.25;
    // Curved case behind the keyboard (keyboard at +y).
    let (rx, ry) = (hw, (b.d - kd) / 2.0);
    let yc = hd - kd - ry;
    b.frustum(Body, [0.0, yc, zb], rx, ry, 1.0, h - zb);
    b.cuboid(Body, [-hw, hd - kd - 0.1, zb], [hw, hd - 0.05, zb + 0.12]);
    b.cuboid(
        Keys,
        [-hw + 0.1, hd - kd, zb + 0.1],
        [hw - 0.1, hd - 0.03, zb + 0.12],
    );
    for (x, y) in [
        (-hw + 0.08, hd - kd),
        (hw - 0.08, hd - kd),
        (0.0, -hd + 0.1),
    ] {
        b.cylinder(Frame, [x, y, 0.0], 0.05, zb);
    }
    b.cuboid(Frame, [-0.12, hd - 0.2, 0.0], [0.12, hd - 0.1, 0.05]);
}

pub fn bathtub(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rim = 0.05;
    let profile = vec![
        [0.0, 0.06],
        [0.8 * hw, 0.06],
        [hw, h],
        [hw - rim, h],
        [0.85 * (hw - rim), 0.2 * h],
        [0.0, 0.2 * h],
    ];
    b.revolved(Body, 0, [0.0, 0.0, 0.0], IDENTITY, hd / hw, profile);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(Metal, [sx * 0.6 * hw, sy * 0.55 * hd, 0.0], 0.03, 0.08);
        }
    }
    b.revolved(
        Canvas,
        0,
        [0.0, 0.0, 0.2 * h + 0.005],
        IDENTITY,
        hd / hw,
        frustum_profile(0.8 * (hw - rim), 0.8 * (hw - rim), 0.002),
    );
}

pub fn toilet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = 0.42_f64.min(0.52 * h);
    let tank_d = 0.2 * b.d;
    b.cuboid(Body, [-hw, -hd, zs - 0.05], [hw, -hd + tank_d, h]);
    b.cuboid(Top, [-hw, -hd, h - 0.03], [hw, -hd + tank_d + 0.01, h]);
    let yc = -hd + tank_d + 0.5 * (b.d - tank_d) - 0.01;
    let (rx, ry) = (hw * 0.95, 0.5 * (b.d - tank_d) - 0.01);
    b.frustum(
        Body,
        [0.0, yc - 0.05, 0.0],
        0.5 * rx,
        0.5 * ry,
        1.2,
        zs * 0.7,
    );
    let profile = vec![
        [0.6 * rx, 0.0],
        [rx, 0.75 * (zs - 0.7 * zs)],
        [rx, zs * 0.3 - 0.02],
        [0.7 * rx, zs * 0.3 - 0.02],
        [0.4 * rx, 0.0],
        [0.0, 0.0],
    ];
    b.revolved(Body, 0, [0.0, yc, zs * 0.7], IDENTITY, ry / rx, profile);
    let seat = vec![[rx, 0.0], [rx, 0.02], [0.68 * rx, 0.02], [0.68 * rx, 0.0]];
    b.revolved(Top, 0, [0.0, yc, zs - 0.02], IDENTITY, ry / rx, seat);
}
