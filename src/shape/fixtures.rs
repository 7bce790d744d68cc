//! Layouts of appliances that are not a box with a window: an air conditioner (a tall slim
//! floor unit with an outlet of louvres over an intake grille, or, when it is wider than tall,
//! a wall-mounted split unit with its louvre slot underneath), a range hood (a canopy over the
//! hob tapering into a chimney up the wall) and a kiln (a round banded chamber with a lid, on a
//! stand, with its control box). The front faces +y; a wall-hung thing's back is at −y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// An air conditioner: a floor unit taller than wide (louvres high up, a display, an intake
/// grille low down, a rounded top), else a split unit (a long rounded box, a louvre flap
/// under its front, a small lamp).
pub fn air_conditioner(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let g = (0.01 * b.w).clamp(0.006, 0.015);
    if h < b.w {
        // The split unit: a box rounded along its length, the outlet slot underneath.
        b.cuboid(Body, [-hw, -hd, 0.25 * h], [hw, 0.6 * hd, h]);
        b.rod(
            Body,
            [-hw, 0.6 * hd - 0.001, 0.625 * h],
            [hw, 0.6 * hd - 0.001, 0.625 * h],
            (0.375 * h).min(0.4 * hd),
        );
        b.cuboid(
            Interior,
            [-0.9 * hw, -hd, 0.18 * h],
            [0.9 * hw, 0.4 * hd, 0.25 * h],
        );
        b.slab(
            Metal,
            [0.0, 0.5 * hd, 0.2 * h],
            [0.88 * hw, 0.35 * hd, 0.01],
            rot_x(-0.5),
        );
        for k in 0..5 {
            let x = -0.6 * hw + 0.3 * hw * k as f64;
            b.cuboid(
                Frame,
                [x - 0.004, -hd, 0.19 * h],
                [x + 0.004, 0.3 * hd, 0.25 * h],
            );
        }
        b.cuboid(
            Light,
            [0.7 * hw, hd - g, 0.35 * h],
            [0.78 * hw, hd, 0.42 * h],
        );
        return;
    }
    // The louvres and the grille stand proud of the front, inside the size box.
    let hd = hd - 3.5 * g;
    b.cuboid(
        Frame,
        [-0.95 * hw, -0.95 * hd, 0.0],
        [0.95 * hw, 0.95 * hd, 0.03 * h],
    );
    b.cuboid(Body, [-hw, -hd, 0.03 * h], [hw, hd, 0.92 * h]);
    b.ellipsoid(Body, [0.0, 0.0, 0.92 * h], [hw, hd, 0.08 * h]);
    // A front panel over the whole face, the outlet and the grille set in it.
    b.cuboid(Door, [-hw, hd, 0.03 * h], [hw, hd + 0.3 * g, 0.92 * h]);
    // The outlet: a dark opening crossed by louvres.
    let (z0, z1) = (0.56 * h, 0.9 * h);
    b.cuboid(Interior, [-0.9 * hw, hd, z0], [0.9 * hw, hd + g, z1]);
    let n = 5;
    for k in 0..n {
        let z = z0 + (z1 - z0) * (k as f64 + 0.5) / n as f64;
        b.slab(
            Metal,
            [0.0, hd + 2.5 * g, z],
            [0.88 * hw, 0.8 * g, 0.4 * (z1 - z0) / n as f64],
            rot_x(0.6),
        );
    }
    // The display and its buttons.
    b.cuboid(
        Screen,
        [-0.9 * hw, hd, 0.48 * h],
        [0.9 * hw, hd + g, 0.555 * h],
    );
    b.cuboid(
        Light,
        [-0.3 * hw, hd + g, 0.52 * h],
        [0.1 * hw, hd + 1.5 * g, 0.545 * h],
    );
    // The intake grille: horizontal bars over a dark panel.
    let (z0, z1) = (0.05 * h, 0.47 * h);
    b.cuboid(Interior, [-0.9 * hw, hd, z0], [0.9 * hw, hd + g, z1]);
    let n = 7;
    for k in 0..n {
        let z = z0 + (z1 - z0) * (k as f64 + 0.5) / n as f64;
        let t = 0.25 * (z1 - z0) / n as f64;
        b.cuboid(
            Frame,
            [-0.9 * hw, hd + g, z - t],
            [0.9 * hw, hd + 2.0 * g, z + t],
        );
    }
}

/// A range hood: a wide shallow canopy over the hob, its front sloping back as it rises in
/// steps to a slim chimney that runs up the wall to the top; lamps and filters underneath, a
/// strip of buttons on the canopy's front edge.
pub fn range_hood(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zc = 0.12 * h;
    // The canopy's rim, with the filters and lamps under it.
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, zc]);
    b.cuboid(
        Interior,
        [-0.92 * hw, -0.92 * hd, -0.001],
        [0.92 * hw, 0.88 * hd, 0.0],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [sx * 0.85 * hw, -0.7 * hd, -0.003],
            [sx * 0.1 * hw, 0.6 * hd, -0.002],
        );
        b.cylinder(Light, [sx * 0.5 * hw, 0.75 * hd, -0.004], 0.03, 0.004);
    }
    b.cuboid(
        Handle,
        [-0.3 * hw, hd, 0.3 * zc],
        [0.3 * hw, hd + 0.006, 0.7 * zc],
    );
    // The taper: slices each narrower and shallower, from the canopy to the chimney.
    let (cw, cd) = (0.32 * hw, 0.55 * hd);
    let zt = 0.42 * h;
    let n = 10;
    for k in 0..n {
        let t = (k as f64 + 1.0) / n as f64;
        let x = hw + (cw - hw) * t;
        let y = -hd + 2.0 * hd + (2.0 * cd - 2.0 * hd) * t;
        let za = zc + (zt - zc) * k as f64 / n as f64;
        b.cuboid(Body, [-x, -hd, za], [x, y, za + (zt - zc) / n as f64]);
    }
    // The chimney up the wall, with a seam where its two sleeves meet.
    b.cuboid(Metal, [-cw, -hd, zt], [cw, -hd + 2.0 * cd, h]);
    b.cuboid(
        Interior,
        [-cw, -hd + 2.0 * cd, 0.75 * h],
        [cw, -hd + 2.0 * cd + 0.004, 0.755 * h],
    );
}

/// A kiln: a round chamber of firebrick under a steel jacket held by bands, a domed lid with a
/// handle, a control box on its front with a spy hole, all on a stand of four legs.
pub fn kiln(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.86 * hw.min(hd);
    let ay = hd / hw;
    let (z0, z1) = (0.22 * h, 0.86 * h);
    // The stand.
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        let (x, y) = (sx * 0.6 * r, sy * 0.6 * r * ay);
        b.rod(Frame, [x, y, 0.0], [x, y, z0], 0.025);
    }
    b.frustum(
        Frame,
        [0.0, 0.0, z0 - 0.03],
        0.8 * r,
        0.8 * r * ay,
        1.0,
        0.03,
    );
    // The chamber and its bands.
    b.frustum(Body, [0.0, 0.0, z0], r, r * ay, 1.0, z1 - z0);
    for t in [0.08, 0.5, 0.92] {
        let z = z0 + t * (z1 - z0);
        b.frustum(
            Metal,
            [0.0, 0.0, z - 0.015],
            1.03 * r,
            1.03 * r * ay,
            1.0,
            0.03,
        );
    }
    // The lid: a rim and a low dome, a handle on top.
    b.frustum(Top, [0.0, 0.0, z1], 1.02 * r, 1.02 * r * ay, 1.0, 0.04 * h);
    b.ellipsoid(
        Top,
        [0.0, 0.0, z1 + 0.04 * h],
        [0.95 * r, 0.95 * r * ay, 0.06 * h],
    );
    b.polyline(
        Handle,
        &[
            [-0.3 * r, 0.0, z1 + 0.08 * h],
            [-0.3 * r, 0.0, h - 0.01],
            [0.3 * r, 0.0, h - 0.01],
            [0.3 * r, 0.0, z1 + 0.08 * h],
        ],
        0.012,
    );
    // The control box on the front, with a dial, lamps and a spy hole beside it.
    let yf = r * ay;
    let (bw, bz) = (0.35 * r, 0.25 * (z1 - z0));
    let zb = z0 + 0.45 * (z1 - z0);
    b.cuboid(Screen, [-bw, yf - 0.02, zb], [bw, yf + 0.08, zb + bz]);
    b.rod(
        Metal,
        [0.0, yf + 0.08, zb + 0.5 * bz],
        [0.0, yf + 0.1, zb + 0.5 * bz],
        0.3 * bz,
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Light,
            [sx * 0.7 * bw - 0.01, yf + 0.08, zb + 0.75 * bz],
            [sx * 0.7 * bw + 0.01, yf + 0.085, zb + 0.85 * bz],
        );
    }
    let a = 0.6f64;
    b.rod(
        Interior,
        [a.sin() * r, a.cos() * r * ay, z0 + 0.25 * (z1 - z0)],
        [
            1.05 * a.sin() * r,
            1.05 * a.cos() * r * ay,
            z0 + 0.25 * (z1 - z0),
        ],
        0.02,
    );
}
