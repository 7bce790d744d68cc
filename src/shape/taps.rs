//! The beer tap of a bar, drawn as what a drinker sees: a chrome T-shaped font standing on a
//! slotted drip tray, its spouts bent down over the tray at the front and a tall tap handle
//! over each (coloured by variant, as each beer has its own), the lines going down at the back.
//! The front faces +y.
use super::archetypes::Builder;
use super::fittings::{disc, Y};
use super::materials::Role::*;

/// A beer tap (see the module docs).
pub fn beer_tap(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tray = (0.05 * h).clamp(0.015, 0.03);
    b.cuboid(Metal, [-hw, -hd, 0.0], [hw, hd, tray]);
    for k in 0..8 {
        let y = -hd + 0.02 + (k as f64 + 0.5) / 8.0 * (b.d - 0.04);
        b.cuboid(
            Interior,
            [-hw + 0.02, y - 0.003, tray],
            [hw - 0.02, y + 0.003, tray + 0.001],
        );
    }
    // The font: a column on the tray carrying a bar along x.
    let rc = (0.1 * b.w).min(0.35 * hd).max(0.015);
    let zb = 0.55 * h;
    b.cylinder(Metal, [0.0, -0.3 * hd, tray], rc, zb - tray);
    b.rod(
        Metal,
        [-hw + 0.03, -0.3 * hd, zb],
        [hw - 0.03, -0.3 * hd, zb],
        0.9 * rc,
    );
    for sx in [-1.0, 1.0] {
        disc(
            b,
            Metal,
            [sx * (hw - 0.03), -0.3 * hd, zb],
            [1.0, 0.0, 0.0],
            0.9 * rc,
            0.006,
        );
    }
    // Spouts, each with its handle.
    let n = 3;
    for k in 0..n {
        let x = (k as f64 - 1.0) * 0.32 * b.w;
        let yb = -0.3 * hd + 0.9 * rc;
        let ys = 0.55 * hd;
        b.cylinder(Metal, [x, yb - 0.01, zb - 0.02], 0.018, 0.04);
        disc(b, Metal, [x, yb + 0.01, zb], Y, 0.016, 0.03);
        b.polyline(
            Metal,
            &[[x, yb + 0.02, zb], [x, ys, zb], [x, ys, zb - 0.09 * h]],
            0.01,
        );
        b.cylinder(Metal, [x, yb, zb + 0.02], 0.012, 0.03);
        // The handle: a tall tapered knob, its badge on the front.
        let z0 = zb + 0.05;
        b.frustum(Handle, [x, yb, z0], 0.012, 0.012, 1.6, h - z0 - 0.005);
        b.cuboid_v(
            Books,
            k as u32,
            [x - 0.014, yb + 0.014, z0 + 0.5 * (h - z0)],
            [x + 0.014, yb + 0.022, h - 0.03],
        );
    }
    // The beer lines down the back into the counter.
    for k in 0..2 {
        let x = (k as f64 - 0.5) * 0.2 * b.w;
        b.rod(
            Canvas,
            [x, -0.3 * hd - rc, zb - 0.05],
            [x, -hd + 0.01, tray + 0.01],
            0.006,
        );
    }
}
