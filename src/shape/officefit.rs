//! Office and wall fittings: a cubicle (fabric partition panels on three sides round an
//! L-shaped desk with a drawer pedestal and a monitor), a cork board (a framed cork panel with
//! pinned notes) and a ladder shelf (two rails leaning on the wall, shelves growing shallower
//! upwards). Layout only: colours come from the archetype table.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A cubicle: partition panels (fabric in a metal trim) along the back and both sides, an L of
/// desk top along the back and the right side, a drawer pedestal under the return, a monitor
/// and a pinned note board on the back panel. Open towards +y.
pub fn cubicle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.03;
    let trim = 0.025;
    // The panels: back, left, right, each framed.
    let panels = [
        ([-hw, -hd, 0.0], [hw, -hd + t, h]),
        ([-hw, -hd + t, 0.0], [-hw + t, hd, h]),
        ([hw - t, -hd + t, 0.0], [hw, hd, h]),
    ];
    for (lo, hi) in panels {
        b.cuboid(Upholstery, [lo[0], lo[1], 0.06], [hi[0], hi[1], h - trim]);
        b.cuboid(
            Metal,
            [lo[0] - 0.002, lo[1] - 0.002, h - trim],
            [hi[0] + 0.002, hi[1] + 0.002, h],
        );
        b.cuboid(Metal, [lo[0], lo[1], 0.0], [hi[0], hi[1], 0.06]);
    }
    // End posts where the side panels stop at the open front.
    for x in [-hw, hw - t] {
        b.cuboid(Metal, [x - 0.003, hd - 0.03, 0.0], [x + t + 0.003, hd, h]);
    }
    // The L-shaped desk top.
    let zt = 0.74_f64.min(0.55 * h);
    let deep = (0.4 * b.d).min(0.7);
    b.cuboid(
        Top,
        [-hw + t, -hd + t, zt - 0.03],
        [hw - t, -hd + t + deep, zt],
    );
    let ret = (0.35 * b.w).min(0.6);
    b.cuboid(
        Top,
        [hw - t - ret, -hd + t + deep, zt - 0.03],
        [hw - t, hd - 0.2, zt],
    );
    // A drawer pedestal under the return, its fronts facing into the cubicle (-x).
    let (py0, py1) = (-hd + t + deep + 0.05, (-hd + t + deep + 0.5).min(hd - 0.25));
    let px = hw - t - 0.45;
    b.cuboid(Body, [px + 0.02, py0, 0.02], [hw - t, py1, zt - 0.04]);
    let rows = 3;
    let fh = (zt - 0.08) / rows as f64;
    for r in 0..rows {
        let (z0, z1) = (
            0.03 + r as f64 * fh + 0.006,
            0.03 + (r + 1) as f64 * fh - 0.006,
        );
        b.cuboid(Door, [px, py0 + 0.01, z0], [px + 0.02, py1 - 0.01, z1]);
        let zc = 0.5 * (z0 + z1);
        let yc = 0.5 * (py0 + py1);
        b.cuboid(
            Handle,
            [px - 0.012, yc - 0.05, zc - 0.008],
            [px, yc + 0.05, zc + 0.008],
        );
    }
    // The monitor on its foot, a keyboard before it.
    let my = -hd + t + 0.2;
    b.cuboid(Metal, [-0.12, my - 0.08, zt], [0.12, my + 0.08, zt + 0.015]);
    b.cuboid(Metal, [-0.025, my - 0.02, zt], [0.025, my + 0.0, zt + 0.2]);
    b.cuboid(
        Body,
        [-0.3, my + 0.0, zt + 0.12],
        [0.3, my + 0.03, zt + 0.47],
    );
    b.cuboid(
        Interior,
        [-0.28, my + 0.03, zt + 0.14],
        [0.28, my + 0.034, zt + 0.45],
    );
    b.cuboid(Body, [-0.22, my + 0.16, zt], [0.22, my + 0.3, zt + 0.02]);
    // Pinned notes on the back panel above the desk, left of the monitor.
    for k in 0..4 {
        let x = -hw + 0.15 + k as f64 * 0.13;
        let z = zt + 0.3 + 0.08 * (k % 2) as f64;
        if x + 0.05 < -0.32 {
            b.cuboid_v(
                Canvas,
                k,
                [x - 0.05, -hd + t, z - 0.05],
                [x + 0.05, -hd + t + 0.003, z + 0.05],
            );
        }
    }
}

/// A cork board: a wooden frame round a cork panel, notes and cards of several colours pinned
/// to it at small angles, a round pin on each.
pub fn corkboard(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let f = (0.05 * b.w.min(h)).clamp(0.025, 0.05);
    let t = (2.0 * hd).min(0.03);
    let yb = -hd;
    for (lo, hi) in [
        ([-hw, yb, 0.0], [hw, yb + t, f]),
        ([-hw, yb, h - f], [hw, yb + t, h]),
        ([-hw, yb, f], [-hw + f, yb + t, h - f]),
        ([hw - f, yb, f], [hw, yb + t, h - f]),
    ] {
        b.cuboid(Frame, lo, hi);
    }
    let yc = yb + t - 0.008;
    b.cuboid(Canvas, [-hw + f, yb, f], [hw - f, yc, h - f]);
    // Notes in a loose grid, each a little turned, with a pin.
    let (cols, rows) = (
        ((b.w - 2.0 * f) / 0.22).floor().max(2.0) as usize,
        ((h - 2.0 * f) / 0.22).floor().max(2.0) as usize,
    );
    let (pw, ph) = ((b.w - 2.0 * f) / cols as f64, (h - 2.0 * f) / rows as f64);
    let mut k = 0u32;
    for i in 0..cols {
        for j in 0..rows {
            k += 1;
            // Leave some cork bare: skip every third cell.
            if (i + 2 * j) % 3 == 2 {
                continue;
            }
            let x = -hw + f + (i as f64 + 0.5) * pw + 0.05 * pw * ((k % 3) as f64 - 1.0);
            let z = f + (j as f64 + 0.5) * ph + 0.06 * ph * ((k % 2) as f64 - 0.5);
            let (nw, nh) = (0.3 * pw * (1.0 + 0.15 * (k % 2) as f64), 0.32 * ph);
            let a = 0.08 * ((k % 5) as f64 - 2.0);
            let rot = super::parts::rot_y(a);
            b.slab_v(Books, k, [x, yc + 0.002, z], [nw, 0.0015, nh], rot);
            b.ellipsoid(
                Handle,
                [x, yc + 0.008, z + 0.75 * nh],
                [0.009, 0.006, 0.009],
            );
        }
    }
}

/// A ladder shelf: two rails leaning from the floor at the front to the wall at the top, rungs
/// across them, and shelves from the rails back to the wall, shallower the higher they sit,
/// holding a few books and boxes.
pub fn ladder_shelf(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.02;
    // The rail's front edge at height z (leaning back from +y at the floor to -y at the top).
    let d = b.d;
    let rail_y = |z: f64| hd - r - (z / h) * (d - 2.0 * r - 0.04);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - r);
        b.rod(
            Frame,
            [x, rail_y(0.0), 0.0],
            [x, rail_y(h - 0.01), h - 0.01],
            r,
        );
    }
    let n = ((h / 0.38).floor() as usize).clamp(3, 6);
    for k in 0..n {
        let z = 0.08 + k as f64 * (h - 0.2) / (n - 1) as f64;
        let yf = rail_y(z) + r;
        let depth = yf + hd;
        b.cuboid(Top, [-hw + 2.0 * r, -hd, z - 0.018], [hw - 2.0 * r, yf, z]);
        // A rung just under the shelf's front.
        b.rod(
            Frame,
            [-hw + r, yf - r, z - 0.04],
            [hw - r, yf - r, z - 0.04],
            0.6 * r,
        );
        // Books standing on the shelf, a box beside them; fewer on the shallow shelves.
        if k + 1 < n && depth > 0.12 {
            let bh = (0.6 * (h - 0.2) / (n - 1) as f64).min(0.28);
            let count = ((0.5 * b.w) / 0.035).floor() as usize;
            for i in 0..count {
                let x = -hw + 3.0 * r + i as f64 * 0.035;
                let hh = bh * (0.8 + 0.2 * ((i * 7 + k) % 3) as f64 / 2.0);
                b.cuboid_v(
                    Books,
                    (i + 3 * k) as u32,
                    [x, -hd + 0.01, z],
                    [x + 0.03, -hd + 0.01 + (0.8 * depth).min(0.22), z + hh],
                );
            }
            let bx = 0.3 * hw;
            b.cuboid_v(
                Books,
                (7 + k) as u32,
                [bx - 0.08, -hd + 0.02, z],
                [bx + 0.08, -hd + 0.02 + 0.6 * depth, z + 0.6 * bh],
            );
        }
    }
}
