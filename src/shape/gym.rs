//! Layouts of gym things: a dumbbell rack (a low frame with two tiers of dumbbells, round heads
//! on short bars), a yoga mat (a thin mat with its end still rolled) and a clothes rail with
//! garments on hangers. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A dumbbell lying front to back on a tier: two round heads of radius `r` joined by a bar,
/// centred at (`x`, `y`), resting on `z`, `len` long.
fn dumbbell(b: &mut Builder, x: f64, y: f64, z: f64, r: f64, len: f64) {
    let zc = z + r;
    let head = (0.55 * r).clamp(0.03, 0.07);
    let y0 = y - len / 2.0;
    let y1 = y + len / 2.0;
    b.rod(Metal, [x, y0, zc], [x, y0 + head, zc], r);
    b.rod(Metal, [x, y1 - head, zc], [x, y1, zc], r);
    b.rod(
        Handle,
        [x, y0 + head, zc],
        [x, y1 - head, zc],
        0.3 * r.min(0.06),
    );
}

/// A dumbbell rack: two end frames on feet, two tiers of rails (the lower at the front, the
/// upper behind and higher), each with a row of dumbbells from light to heavy.
pub fn dumbbell_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.04;
    // Heaviest head radius; dumbbells lie front to back within half the depth and a bit.
    let rmax = (0.14 * h).clamp(0.04, 0.11);
    let len = (0.62 * b.d).min(0.42);
    let z_up = h - 2.0 * rmax - 0.01;
    let z_low = 0.5 * z_up;
    let tiers = [
        (z_low, hd - len / 2.0 - 0.01),
        (z_up, -hd + len / 2.0 + 0.01),
    ];
    // End frames: a foot along the depth, posts under each tier, a brace between them.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        let (x0, x1) = (x - t / 2.0, x + t / 2.0);
        b.cuboid(Frame, [x0, -hd, 0.0], [x1, hd, t]);
        for (z, y) in tiers {
            for dy in [-0.3 * len, 0.3 * len] {
                let yc = y + dy;
                b.cuboid(Frame, [x0, yc - t / 2.0, t], [x1, yc + t / 2.0, z]);
            }
        }
        b.cuboid(
            Frame,
            [x0, -hd + t, 0.45 * z_low],
            [x1, hd - t, 0.45 * z_low + t],
        );
    }
    // Each tier: two rails along the width carrying the dumbbells.
    let n = ((b.w - 2.0 * t) / (2.6 * rmax)).floor().clamp(2.0, 10.0) as usize;
    let pitch = (b.w - 2.0 * t) / n as f64;
    for (k, (z, y)) in tiers.into_iter().enumerate() {
        for dy in [-0.3 * len, 0.3 * len] {
            b.cuboid(
                Frame,
                [-hw + t, y + dy - t / 2.0, z - t],
                [hw - t, y + dy + t / 2.0, z],
            );
        }
        for i in 0..n {
            // Lighter on the left of each tier, heavier on the upper tier.
            let heavy = (i as f64 + k as f64 * n as f64) / (2 * n - 1).max(1) as f64;
            let r = (0.55 + 0.45 * heavy) * rmax.min(0.45 * pitch);
            let x = -hw + t + (i as f64 + 0.5) * pitch;
            dumbbell(b, x, y, z, r, len);
        }
    }
}

/// A yoga mat lying out, its far end still rolled up: a thin sheet and a roll as high as the
/// size box, with the roll's spiral ends in a darker shade.
pub fn yoga_mat(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.5 * h;
    let sheet = (0.15 * h).clamp(0.003, 0.008);
    b.cuboid(Upholstery, [-hw, -hd + r, 0.0], [hw, hd, sheet]);
    let y = -hd + r;
    b.rod(Upholstery, [-hw + 0.004, y, r], [hw - 0.004, y, r], r);
    for x in [-hw, hw - 0.004] {
        b.rod(Cushion, [x, y, r], [x + 0.004, y, r], 0.8 * r);
    }
}

/// A clothes rail: a bar on two uprights standing on feet with castors, a row of garments of
/// several colours hanging from it on hangers.
pub fn clothes_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.015;
    let zr = h - r;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - r);
        b.rod(Frame, [x, 0.0, 0.05], [x, 0.0, zr], r);
        b.rod(Frame, [x, -hd + r, 0.05], [x, hd - r, 0.05], r);
        for y in [-hd + 0.03, hd - 0.03] {
            b.ellipsoid(Tyre, [x, y, 0.025], [0.025, 0.025, 0.025]);
        }
    }
    b.rod(Frame, [-hw + r, 0.0, zr], [hw - r, 0.0, zr], r);
    // Garments: hangers' hooks on the bar, shoulders and bodies hanging, side by side.
    let n = ((b.w - 0.1) / 0.09).floor().max(1.0) as usize;
    let pitch = (b.w - 0.1) / n as f64;
    let len = (0.55 * h).min(1.0);
    for i in 0..n {
        let x = -hw + 0.05 + (i as f64 + 0.5) * pitch;
        let long = if i % 3 == 1 { 1.0 } else { 0.75 };
        let zt = zr - 0.06;
        b.rod(Metal, [x, 0.0, zt], [x, 0.0, zr], 0.004);
        b.cuboid_v(
            Books,
            i as u32,
            [x - 0.35 * pitch, -0.8 * hd.min(0.25), zt - long * len],
            [x + 0.35 * pitch, 0.8 * hd.min(0.25), zt],
        );
    }
}
