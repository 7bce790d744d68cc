//! Layouts of a wind turbine, a throne and a weaving loom: things with a shape of their own
//! that no furniture or post archetype shows. The front faces +y, z up, the bottom face's
//! centre at the origin.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use std::f64::consts::{FRAC_PI_2, TAU};

/// A wind turbine: a tapering white tower, a nacelle on top with a spinner at its front, and
/// three long blades in the plane facing +y.
pub fn wind_turbine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // A blade reaches at most to the footprint's side and leaves the tower's lower part clear.
    let blade = (0.97 * hw).min(0.4 * h);
    let hub_z = h - blade - 0.02 * h;
    let r0 = (0.025 * h).min(0.35 * hd);
    let nacelle = [1.1 * r0, (0.9 * hd).min(4.0 * r0), 0.9 * r0];
    b.frustum(Body, [0.0, 0.0, 0.0], r0, r0, 0.55, hub_z - nacelle[2]);
    b.cuboid(
        Body,
        [-nacelle[0], -0.6 * nacelle[1], hub_z - nacelle[2]],
        [nacelle[0], 0.4 * nacelle[1], hub_z + nacelle[2]],
    );
    let front = 0.4 * nacelle[1];
    let spinner = [0.0, front + 0.5 * r0, hub_z];
    b.ellipsoid(
        Metal,
        spinner,
        [0.8 * r0, (0.9 * r0).min(hd - front - 0.5 * r0), 0.8 * r0],
    );
    // Each blade: a flat section (chord in the rotor plane, 4× its thickness) widest near
    // the root, tapering to the tip.
    for k in 0..3 {
        let a = FRAC_PI_2 + k as f64 * TAU / 3.0;
        let dir = [a.cos(), 0.0, a.sin()];
        let root = [
            spinner[0] + 0.5 * r0 * dir[0],
            spinner[1],
            hub_z + 0.5 * r0 * dir[2],
        ];
        let len = blade - 0.5 * r0;
        let t = 0.02 * len;
        let profile = vec![
            [0.0, 0.0],
            [0.6 * t, 0.0],
            [t, 0.2 * len],
            [0.45 * t, 0.85 * len],
            [0.15 * t, len],
            [0.0, len],
        ];
        b.revolved(Body, 0, root, frame_along(dir), 4.0, profile);
    }
}

/// A throne: a tall upholstered back under a rounded crest with finials, solid arms ending in
/// round knobs, a deep seat on a carved base.
pub fn throne(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = (0.3 * h).clamp(0.4, 0.55);
    let back = (0.15 * b.d).min(0.14);
    let arm = (0.14 * b.w).min(0.14);
    // The base and its bun feet.
    b.cuboid(
        Frame,
        [-hw + 0.03, -hd + 0.02, 0.08],
        [hw - 0.03, hd - 0.03, zs - 0.1],
    );
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.ellipsoid(
                Frame,
                [sx * (hw - 0.07), sy * (hd - 0.07), 0.05],
                [0.05, 0.05, 0.05],
            );
        }
    }
    b.cuboid(
        Upholstery,
        [-hw + arm, -hd + back, zs - 0.1],
        [hw - arm, hd - 0.02, zs],
    );
    for sx in [-1.0, 1.0] {
        let (x0, x1) = (sx * hw, sx * (hw - arm));
        b.cuboid(
            Frame,
            [x0.min(x1), -hd + back, zs - 0.1],
            [x0.max(x1), hd - 0.08, zs + 0.22],
        );
        b.ellipsoid(
            Frame,
            [sx * (hw - 0.5 * arm), hd - 0.08, zs + 0.2],
            [0.5 * arm, 0.07, 0.07],
        );
    }
    // The back: a frame with an upholstered panel on its front, a crest and two finials.
    let crest = 0.86 * h;
    b.cuboid(
        Frame,
        [-hw + 0.03, -hd, zs - 0.1],
        [hw - 0.03, -hd + back, crest],
    );
    b.cuboid(
        Upholstery,
        [-hw + arm + 0.02, -hd + back, zs + 0.02],
        [hw - arm - 0.02, -hd + back + 0.03, crest - 0.06],
    );
    b.ellipsoid(
        Frame,
        [0.0, -hd + 0.5 * back, crest],
        [hw - 0.1, 0.5 * back, 0.1 * h],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.06);
        b.cylinder(Frame, [x, -hd + 0.5 * back, crest], 0.035, 0.06 * h);
        b.ellipsoid(Frame, [x, -hd + 0.5 * back, h - 0.04], [0.04, 0.04, 0.04]);
    }
}

/// A floor loom: a wooden frame with a breast beam at the front and a warp beam at the back,
/// the warp threads stretched between them (woven cloth at the front), two shafts of heddles
/// hanging from the castle on top, and treadles on the floor.
pub fn loom(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.06;
    let zb = 0.6 * h;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - s / 2.0);
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - s / 2.0);
            b.cuboid(
                Frame,
                [x - s / 2.0, y - s / 2.0, 0.0],
                [x + s / 2.0, y + s / 2.0, zb + 0.03],
            );
        }
        for z in [0.12, zb - 0.12] {
            b.cuboid(
                Frame,
                [x - s / 2.0, -hd, z - s / 2.0],
                [x + s / 2.0, hd, z + s / 2.0],
            );
        }
        // The castle's upright in the middle of the side.
        b.cuboid(
            Frame,
            [x - s / 2.0, -0.1 - s / 2.0, zb - 0.12],
            [x + s / 2.0, -0.1 + s / 2.0, h],
        );
    }
    b.cuboid(Frame, [-hw, -0.1 - s / 2.0, h - s], [hw, -0.1 + s / 2.0, h]);
    let beam = 0.045;
    for y in [hd - beam, -hd + beam] {
        b.rod(Frame, [-hw + s, y, zb], [hw - s, y, zb], beam);
    }
    // The warp: threads from the back beam to the front one; the front third is woven.
    let span = hw - s - 0.08;
    let n = 36;
    for i in 0..n {
        let x = -span + 2.0 * span * i as f64 / (n - 1) as f64;
        b.rod(
            Canvas,
            [x, -hd + beam, zb + beam],
            [x, hd - beam, zb + beam],
            0.005,
        );
    }
    b.cuboid(
        Upholstery,
        [-span - 0.01, 0.25 * hd, zb + beam - 0.006],
        [span + 0.01, hd - beam, zb + beam + 0.006],
    );
    // Two shafts: a top and bottom bar with a comb of heddles between.
    for (k, y) in [-0.02, -0.18].into_iter().enumerate() {
        let (z0, z1) = (zb - 0.15, zb + 0.22 + 0.02 * k as f64);
        for z in [z0, z1] {
            b.cuboid(
                Frame,
                [-span, y - 0.01, z - 0.015],
                [span, y + 0.01, z + 0.015],
            );
        }
        for i in 0..24 {
            let x = -span + 2.0 * span * (i as f64 + 0.5) / 24.0;
            b.rod(Metal, [x, y, z0], [x, y, z1], 0.004);
        }
        b.rod(
            Metal,
            [-0.4 * span, y, z1],
            [-0.4 * span, -0.1, h - s],
            0.006,
        );
        b.rod(Metal, [0.4 * span, y, z1], [0.4 * span, -0.1, h - s], 0.006);
    }
    // Treadles.
    for i in 0..4 {
        let x = -0.3 * span + 0.2 * span * i as f64;
        b.cuboid(
            Frame,
            [x - 0.025, -0.3 * hd, 0.0],
            [x + 0.025, hd - s, 0.05],
        );
    }
}
