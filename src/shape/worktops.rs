//! Work surfaces drawn for the work done on them, not as a plain table: a workbench (a thick top
//! on stout legs with a lower shelf, a vice clamped at its front corner, a toolbox and a hammer on
//! top), a drafting table (a board tilted up towards the back on a trestle, a sheet pinned on it,
//! a parallel rule across it and a pencil ledge at its front edge) and an ironing board (a padded
//! board with a pointed nose on crossed legs, an iron standing on the rest at its square end).
//! The front is +y.
use super::archetypes::Builder;
use super::fittings::pad;
use super::materials::Role::*;

/// A workbench: top, legs, stretchers and a lower shelf; a vice, a toolbox and a hammer on top.
pub fn workbench(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.8 * h;
    let top = 0.07_f64.min(0.1 * h);
    let leg = 0.08_f64.min(0.12 * hw.min(hd));
    b.cuboid(Top, [-hw, -hd, zt - top], [hw, hd, zt]);
    b.legs(Frame, leg, 0.03, 0.0, zt - top);
    // Stretchers at the ends and the lower shelf, with a few boxes on it.
    let zs = 0.15 * h;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.03 - leg / 2.0);
        b.cuboid(
            Frame,
            [x - leg / 3.0, -hd + 0.03, zs - 0.03],
            [x + leg / 3.0, hd - 0.03, zs],
        );
    }
    b.cuboid(
        Top,
        [-hw + 0.03, -hd + 0.05, zs],
        [hw - 0.03, hd - 0.05, zs + 0.025],
    );
    for (i, x0) in [-0.8, -0.45, 0.3].iter().enumerate() {
        let x0 = x0 * hw;
        b.cuboid_v(
            Books,
            i as u32,
            [x0, -0.6 * hd, zs + 0.025],
            [
                x0 + 0.28 * hw,
                0.4 * hd,
                zs + 0.025 + (0.16 + 0.05 * i as f64) * h,
            ],
        );
    }
    // A vice at the front right corner, its jaws over the front edge.
    let first = b.parts.len();
    let (w, d, hh) = (b.w, b.d, b.h);
    b.w = 0.3_f64.min(0.3 * w);
    b.d = 0.2_f64.min(0.45 * d);
    b.h = h - zt;
    super::smithy::vise(b);
    let vy = hd - b.d / 2.0;
    (b.w, b.d, b.h) = (w, d, hh);
    b.translate_from(first, [hw - 0.25 * hw, vy, zt]);
    // A toolbox at the back left, a hammer lying in front of it.
    let (tx, ty) = (-0.55 * hw, -0.45 * hd);
    let (bw, bd, bh) = (0.22 * hw, 0.3 * hd, 0.6 * (h - zt));
    b.cuboid(Body, [tx - bw, ty - bd, zt], [tx + bw, ty + bd, zt + bh]);
    b.cuboid(
        Top,
        [tx - bw, ty - bd, zt + bh],
        [tx + bw, ty + bd, zt + 1.1 * bh],
    );
    b.rod(
        Handle,
        [tx - 0.6 * bw, ty, zt + 1.1 * bh],
        [tx + 0.6 * bw, ty, zt + 1.1 * bh],
        0.012,
    );
    b.rod(
        Handle,
        [tx - 0.6 * bw, ty, zt + 1.1 * bh],
        [tx - 0.6 * bw, ty, zt + 1.5 * bh],
        0.01,
    );
    b.rod(
        Handle,
        [tx + 0.6 * bw, ty, zt + 1.1 * bh],
        [tx + 0.6 * bw, ty, zt + 1.5 * bh],
        0.01,
    );
    b.rod(
        Handle,
        [tx - 0.6 * bw, ty, zt + 1.5 * bh],
        [tx + 0.6 * bw, ty, zt + 1.5 * bh],
        0.01,
    );
    let hy = 0.35 * hd;
    b.rod(
        Frame,
        [-0.3 * hw, hy, zt + 0.015],
        [0.0, hy, zt + 0.015],
        0.015,
    );
    b.cuboid(Metal, [-0.02, hy - 0.05, zt], [0.02, hy + 0.05, zt + 0.035]);
}

/// A drafting table: a trestle carrying a board tilted up towards the back, with a sheet, a
/// parallel rule and a pencil ledge.
pub fn drafting_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (zf, zb) = (0.72 * h, h - 0.02);
    let t = 0.03;
    // The trestle: an upright at each end on a foot running front to back, a rail between
    // the feet, and a bar under the board.
    let post = 0.05_f64.min(0.1 * hw);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.12 * hw);
        b.cuboid(
            Frame,
            [x - post, -0.9 * hd, 0.0],
            [x + post, 0.9 * hd, 0.05],
        );
        b.cuboid(
            Frame,
            [x - post / 2.0, -0.1 * hd, 0.05],
            [x + post / 2.0, 0.1 * hd, zf - 0.05],
        );
        b.rod(Frame, [x, 0.0, 0.4 * h], [x, -0.7 * hd, zb - 0.05], 0.015);
    }
    b.rod(
        Frame,
        [-0.88 * hw, 0.0, 0.18 * h],
        [0.88 * hw, 0.0, 0.18 * h],
        0.02,
    );
    b.rod(
        Metal,
        [-0.88 * hw, 0.0, zf - 0.05],
        [0.88 * hw, 0.0, zf - 0.05],
        0.02,
    );
    // The board, rising from the front edge to the back.
    pad(b, Top, 0.0, [hd, zf], [-hd, zb], hw, t);
    let along = |f: f64| [hd - f * 2.0 * hd, zf + f * (zb - zf)];
    let lift = t / 2.0 + 0.003;
    // A sheet pinned to it.
    let (a, c) = (along(0.2), along(0.85));
    pad(
        b,
        Canvas,
        -0.1 * hw,
        [a[0], a[1] + lift],
        [c[0], c[1] + lift],
        0.55 * hw,
        0.004,
    );
    // A parallel rule across the board, and the pencil ledge along its front edge.
    let r = along(0.35);
    b.rod(
        Metal,
        [-hw, r[0], r[1] + lift + 0.01],
        [hw, r[0], r[1] + lift + 0.01],
        0.012,
    );
    let f = along(0.0);
    b.cuboid(
        Frame,
        [-hw, f[0] - 0.02, f[1]],
        [hw, f[0] + 0.01, f[1] + 0.04],
    );
}

/// An ironing board: a padded board with a pointed nose at +x, on crossed legs, an iron on the
/// rest at its square end.
pub fn ironing_board(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (bw, t) = (0.85 * hd, 0.03);
    let zt = h - t - 0.13_f64.min(0.2 * h);
    // The board: a square end and a nose that narrows to a point (a half ellipse).
    let xn = -0.25 * hw;
    b.cuboid(Canvas, [-0.85 * hw, -bw, zt], [xn, bw, zt + t]);
    b.frustum(Canvas, [xn, 0.0, zt], hw - xn, bw, 1.0, t);
    b.cuboid(
        Frame,
        [-0.85 * hw, -0.8 * bw, zt - 0.02],
        [0.55 * hw, 0.8 * bw, zt],
    );
    // Crossed legs under it, one pair a side, with rubber feet.
    for sy in [-1.0, 1.0] {
        let y = sy * 0.55 * bw;
        for (x0, x1) in [(-0.6 * hw, 0.45 * hw), (0.45 * hw, -0.6 * hw)] {
            b.rod(Metal, [x0, y, 0.02], [x1, y, zt - 0.02], 0.012);
            b.cuboid(
                Tyre,
                [x0 - 0.03, y - 0.02, 0.0],
                [x0 + 0.03, y + 0.02, 0.03],
            );
        }
    }
    // The iron rest beyond the square end, and the iron standing on its heel there.
    let xr = -0.85 * hw;
    b.rod(
        Metal,
        [xr, -0.7 * bw, zt + t / 2.0],
        [-hw + 0.01, -0.7 * bw, zt + t / 2.0],
        0.006,
    );
    b.rod(
        Metal,
        [xr, 0.7 * bw, zt + t / 2.0],
        [-hw + 0.01, 0.7 * bw, zt + t / 2.0],
        0.006,
    );
    b.rod(
        Metal,
        [-hw + 0.01, -0.7 * bw, zt + t / 2.0],
        [-hw + 0.01, 0.7 * bw, zt + t / 2.0],
        0.006,
    );
    let ix = -0.7 * hw;
    let top = h - zt - t;
    b.frustum(
        Body,
        [ix, 0.0, zt + t],
        0.12 * hw,
        0.4 * bw,
        0.7,
        0.35 * top,
    );
    b.rod(
        Handle,
        [ix - 0.08 * hw, 0.0, zt + t + 0.75 * top],
        [ix + 0.08 * hw, 0.0, zt + t + 0.75 * top],
        0.012,
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Handle,
            [ix + sx * 0.08 * hw, 0.0, zt + t + 0.75 * top],
            [ix + sx * 0.06 * hw, 0.0, zt + t + 0.3 * top],
            0.01,
        );
    }
}
