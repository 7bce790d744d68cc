//! Layouts of curtains: the pleated curtain on a rail that booths and hangings share, window
//! curtains (two floor-length panels gathered at either end of a rod, tied back) and a privacy
//! curtain (one pleated curtain drawn along a track hung from the ceiling, as round a hospital
//! bed, its hem down to the floor). The front faces +y, z up, the bottom face's centre at the
//! origin.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_z;
use std::f64::consts::FRAC_PI_2;

/// A pleated curtain from `x0` to `x1` hanging at depth `y` between `z0` and `z1`, on a rail:
/// upright folds of alternating depth.
pub(super) fn curtain(b: &mut Builder, x0: f64, x1: f64, y: f64, z0: f64, z1: f64) {
    let n = (((x1 - x0) / 0.09).round() as usize).max(2);
    let pitch = (x1 - x0) / n as f64;
    for i in 0..n {
        let x = x0 + (i as f64 + 0.5) * pitch;
        let dy = if i % 2 == 0 { 0.012 } else { -0.012 };
        b.frustum(
            Upholstery,
            [x, y + dy, z0],
            0.6 * pitch,
            0.025,
            1.0,
            z1 - z0,
        );
    }
    b.rod(Metal, [x0, y, z1 + 0.015], [x1, y, z1 + 0.015], 0.012);
}

/// Window curtains: a rod across the whole width with a finial at each end, and two pleated
/// panels drawn back to either end (the window between them), each tied back at sill height.
pub fn curtains(b: &mut Builder) {
    let (hw, h) = (b.w / 2.0, b.h);
    let y = 0.0;
    let top = h - 0.05;
    let panel = 0.3 * b.w;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw + 0.03, -hw + panel)
        } else {
            (hw - panel, hw - 0.03)
        };
        curtain(b, x0, x1, y, 0.02, top);
        // the tie-back: a band round the gathered panel
        let zt = 0.45 * h;
        b.cuboid(
            Cushion,
            [x0 - 0.01, y - 0.04, zt],
            [x1 + 0.01, y + 0.04, zt + 0.05],
        );
        b.ellipsoid(
            Metal,
            [sx * (hw - 0.015), y, top + 0.015],
            [0.025, 0.025, 0.025],
        );
    }
    b.rod(Metal, [-hw, y, top + 0.015], [hw, y, top + 0.015], 0.012);
}

/// A privacy curtain: a ceiling track along its longer side on hangers, and one pleated curtain
/// drawn along it, its hem down to the floor and a mesh band along its top (a
/// curtain beside a bed runs along the bed: its size is thin across and long front to back).
pub fn privacy_curtain(b: &mut Builder) {
    let first = b.parts.len();
    let (hl, h) = (b.w.max(b.d) / 2.0, b.h);
    let y = 0.0;
    // the track and the rods that hang it from the ceiling
    b.cuboid(Metal, [-hl, y - 0.02, h - 0.06], [hl, y + 0.02, h]);
    for sx in [-0.9, 0.0, 0.9] {
        b.cylinder(Metal, [sx * hl, y, h - 0.1], 0.008, 0.07);
    }
    let mesh = (0.25 * h).min(0.45);
    curtain(b, -hl + 0.02, hl - 0.02, y, 0.0, h - 0.1 - mesh);
    b.cuboid(
        Canvas,
        [-hl + 0.02, y - 0.012, h - 0.1 - mesh],
        [hl - 0.02, y + 0.012, h - 0.1],
    );
    if b.d > b.w {
        b.turn_from(first, rot_z(FRAC_PI_2));
    }
}
