//! Layouts of things made of several like pieces: nesting tables (three tables of falling size,
//! each pulled half out from under the next larger), a pallet (deck slats on three runners over
//! bottom boards) and a murphy bed folded up into its wall unit (the bed's panel face, with its
//! folded legs and pull bar, between shelves of books). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A small table: a top `t` thick over four slim legs, inside the box `lo`..`hi`.
fn little_table(b: &mut Builder, lo: [f64; 3], hi: [f64; 3]) {
    let t = 0.02;
    let s = 0.022;
    b.cuboid(Top, [lo[0], lo[1], hi[2] - t], hi);
    for x in [lo[0] + 0.01, hi[0] - 0.01 - s] {
        for y in [lo[1] + 0.01, hi[1] - 0.01 - s] {
            b.cuboid(Frame, [x, y, lo[2]], [x + s, y + s, hi[2] - t]);
        }
    }
}

/// Nesting tables: the largest at the back, the two smaller ones lower and narrower, each
/// pulled forward from under the one behind it.
pub fn nesting_tables(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    for k in 0..3 {
        let f = k as f64;
        let w = hw * (1.0 - 0.12 * f);
        let depth = b.d * (0.62 - 0.04 * f);
        let front = -hd + b.d * (0.62 + 0.19 * f);
        let top = h * (1.0 - 0.13 * f);
        little_table(b, [-w, front - depth, 0.0], [w, front, top]);
    }
}

/// A pallet: deck slats across the width on three runners front to back, three bottom boards.
pub fn pallet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.15 * h;
    let slats = ((b.d / 0.2).round() as usize).clamp(3, 9);
    let sw = (b.d - 0.02 * (slats - 1) as f64) / slats as f64;
    let sw = sw.min(0.12);
    let pitch = (b.d - sw) / (slats - 1) as f64;
    for i in 0..slats {
        let y = -hd + i as f64 * pitch;
        b.cuboid_v(Top, i as u32, [-hw, y, h - t], [hw, y + sw, h]);
    }
    let rw = (0.09 * b.w).min(0.1);
    for x in [-hw, -rw / 2.0, hw - rw] {
        b.cuboid(Frame, [x, -hd, t], [x + rw, hd, h - t]);
    }
    for y in [-hd, -sw / 2.0, hd - sw] {
        b.cuboid(Frame, [-hw, y, 0.0], [hw, y + sw, t]);
    }
}

/// A murphy bed folded up: a tall unit with a crown and plinth; in the middle the bed's
/// underside as a framed panel with a rail across it, the folded legs and a pull bar near its
/// top; on each side a column of shelves with books.
pub fn murphy_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.03;
    let side = (0.17 * b.w).min(0.3);
    let plinth = 0.08;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.03, plinth]);
    b.cuboid(Top, [-hw, -hd, h - 0.08], [hw, hd, h]);
    b.cuboid(Body, [-hw, -hd, plinth], [hw, -hd + 0.015, h - 0.08]);
    for x in [-hw, -hw + side, hw - side - t, hw - t] {
        b.cuboid(Body, [x, -hd, plinth], [x + t, hd, h - 0.08]);
    }
    // The shelves either side.
    let shelves = 5;
    let pitch = (h - 0.08 - plinth) / shelves as f64;
    for (i, x0) in [-hw + t, hw - side].into_iter().enumerate() {
        let x1 = x0 + side - t;
        b.cuboid(Interior, [x0, -hd, plinth], [x1, -hd + 0.01, h - 0.08]);
        for k in 0..shelves {
            let z = plinth + k as f64 * pitch;
            b.cuboid(Frame, [x0, -hd, z], [x1, hd - 0.02, z + 0.02]);
            let n = 4;
            let bw = (x1 - x0 - 0.02) / n as f64;
            for j in 0..n {
                let tall = 0.55 + 0.1 * ((j + k + i) % 3) as f64;
                let xb = x0 + 0.01 + j as f64 * bw;
                b.cuboid_v(
                    Books,
                    (i * 17 + k * 5 + j) as u32,
                    [xb, -hd + 0.04, z + 0.02],
                    [xb + 0.9 * bw, hd - 0.12, z + 0.02 + tall * pitch],
                );
            }
        }
    }
    // The bed's panel face between them, standing proud of the unit.
    let (x0, x1) = (-hw + side + t, hw - side - t);
    let (z0, z1) = (plinth + 0.01, h - 0.09);
    b.cuboid(Mattress, [x0, -hd + 0.02, z0], [x1, hd - 0.06, z1]);
    b.cuboid(
        Door,
        [x0 + 0.005, hd - 0.06, z0],
        [x1 - 0.005, hd - 0.02, z1],
    );
    let m = 0.05;
    for (lo, hi) in [
        ([x0, hd - 0.02, z0], [x0 + m, hd, z1]),
        ([x1 - m, hd - 0.02, z0], [x1, hd, z1]),
        ([x0, hd - 0.02, z0], [x1, hd, z0 + m]),
        ([x0, hd - 0.02, z1 - m], [x1, hd, z1]),
        ([x0, hd - 0.02, 0.45 * h], [x1, hd, 0.45 * h + m]),
    ] {
        b.cuboid(Frame, lo, hi);
    }
    // The folded legs lie along the top of the panel, the pull bar below them.
    let zl = z1 - 0.22;
    b.cuboid(Metal, [x0 + 0.1, hd - 0.02, zl], [x1 - 0.1, hd, zl + 0.04]);
    for x in [x0 + 0.1, x1 - 0.14] {
        b.cuboid(Metal, [x, hd - 0.02, zl - 0.14], [x + 0.04, hd, zl]);
    }
    b.rod(
        Handle,
        [-0.25 * (x1 - x0), hd - 0.016, zl - 0.25],
        [0.25 * (x1 - x0), hd - 0.016, zl - 0.25],
        0.015,
    );
}
