//! A sewing machine and the table it stands on: the machine's flat bed, the pillar at its right
//! rising to the arm that runs left over the bed to the head, the needle under the head, a
//! handwheel on the right end and a spool of thread on top; a sewing table is a desk with such
//! a machine standing on its top. The front (the sewer's side) is +y.
use super::archetypes::Builder;
use super::fittings::{disc, X};
use super::materials::Role::*;

/// The machine in `[x0, x1] × [y0, y1]` standing on `z0`, `h` tall.
fn machine(b: &mut Builder, [x0, x1]: [f64; 2], [y0, y1]: [f64; 2], z0: f64, h: f64) {
    let (w, d) = (x1 - x0, y1 - y0);
    let yc = 0.5 * (y0 + y1);
    // The bed.
    b.cuboid(Body, [x0, y0, z0], [x1, y1, z0 + 0.22 * h]);
    b.cuboid(
        Metal,
        [x0 + 0.2 * w, yc - 0.15 * d, z0 + 0.22 * h],
        [x0 + 0.4 * w, yc + 0.25 * d, z0 + 0.23 * h],
    );
    // The pillar on the right and the arm over the bed, a little behind its middle.
    let (ya, yb) = (y0 + 0.15 * d, y0 + 0.75 * d);
    b.cuboid(
        Body,
        [x1 - 0.28 * w, ya, z0 + 0.22 * h],
        [x1 - 0.02 * w, yb, h + z0 - 0.05 * h],
    );
    b.cuboid(
        Body,
        [x0 + 0.1 * w, ya, z0 + 0.7 * h],
        [x1 - 0.1 * w, yb, z0 + 0.95 * h],
    );
    // The head at the left end, coming down towards the needle.
    b.cuboid(
        Body,
        [x0 + 0.05 * w, ya - 0.05 * d, z0 + 0.5 * h],
        [x0 + 0.3 * w, yb + 0.05 * d, z0 + 0.95 * h],
    );
    b.rod(
        Metal,
        [x0 + 0.2 * w, yc, z0 + 0.5 * h],
        [x0 + 0.2 * w, yc, z0 + 0.25 * h],
        0.004,
    );
    b.cuboid(
        Metal,
        [x0 + 0.15 * w, yc - 0.05 * d, z0 + 0.25 * h],
        [x0 + 0.25 * w, yc + 0.05 * d, z0 + 0.3 * h],
    );
    // A dial on the arm's front, the handwheel on the right end, a spool on top.
    disc(
        b,
        Handle,
        [x1 - 0.45 * w, yb + 0.005, z0 + 0.82 * h],
        [0.0, 1.0, 0.0],
        0.07 * h,
        0.01,
    );
    disc(
        b,
        Handle,
        [x1 + 0.001 - 0.02 * w, yc, z0 + 0.75 * h],
        X,
        0.16 * h,
        0.04 * w,
    );
    b.cylinder(
        Books,
        [x1 - 0.45 * w, yc, z0 + 0.95 * h],
        0.05 * h,
        0.05 * h,
    );
}

/// A sewing machine on its own.
pub fn sewing_machine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    machine(b, [-hw, hw], [-hd, hd], 0.0, h);
}

/// A sewing table: a desk with a machine standing on its top, a little left of the middle.
pub fn sewing_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.72 * h;
    b.h = zt;
    super::furniture::desk(b);
    b.h = h;
    let (mw, md) = ((0.45 * b.w).min(0.45), (0.5 * b.d).min(0.2));
    let x0 = -0.1 * hw - mw / 2.0;
    machine(
        b,
        [x0, x0 + mw],
        [-hd + 0.1 * b.d, -hd + 0.1 * b.d + md],
        zt,
        h - zt,
    );
}
