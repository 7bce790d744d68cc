//! Layouts of appliances: fridges, washers, stoves and small appliances. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};
use std::f64::consts::FRAC_PI_2;

/// Appliance body with the front at `hd - 0.03`; returns the front's y.
fn appliance_body(b: &mut Builder) -> f64 {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd, 0.0],
        [hw - 0.02, hd - 0.06, 0.03],
    );
    b.cuboid(Body, [-hw, -hd, 0.03], [hw, hd - 0.03, h]);
    hd - 0.03
}

pub fn fridge(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = appliance_body(b);
    let split = 0.62 * h;
    for (z0, z1) in [(0.04, split - 0.005), (split + 0.005, h - 0.01)] {
        b.cuboid(Door, [-hw + 0.005, y, z0], [hw - 0.005, hd - 0.012, z1]);
        let (za, zb) = if z0 < 0.1 {
            (z1 - 0.45, z1 - 0.08)
        } else {
            (z0 + 0.06, (z0 + 0.35).min(z1 - 0.05))
        };
        b.cuboid(Handle, [-hw + 0.05, hd - 0.012, za], [-hw + 0.075, hd, zb]);
    }
}

pub fn washer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = appliance_body(b);
    b.cuboid(
        Door,
        [-hw + 0.01, y, 0.85 * h],
        [hw - 0.01, hd - 0.02, h - 0.01],
    );
    b.cuboid(
        Screen,
        [0.1 * b.w, hd - 0.02, 0.88 * h],
        [0.35 * b.w, hd - 0.015, h - 0.03],
    );
    let r = (0.34 * b.w).min(0.32 * h);
    let zc = 0.45 * h;
    b.revolved(
        Handle,
        0,
        [0.0, y, zc],
        rot_x(-FRAC_PI_2),
        1.0,
        frustum_profile(r, r, 0.015),
    );
    b.revolved(
        Screen,
        0,
        [0.0, y, zc],
        rot_x(-FRAC_PI_2),
        1.0,
        frustum_profile(0.75 * r, 0.75 * r, 0.025),
    );
}

pub fn stove(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = appliance_body(b);
    b.cuboid(Top, [-hw, -hd, h - 0.01], [hw, hd - 0.03, h]);
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)] {
        b.frustum(
            Metal,
            [sx * 0.25 * b.w, sy * 0.22 * b.d - 0.02, h],
            0.09,
            0.09,
            0.9,
            0.008,
        );
    }
    b.cuboid(
        Door,
        [-hw + 0.01, y, 0.75 * h],
        [hw - 0.01, hd - 0.02, h - 0.03],
    );
    for k in 0..4 {
        let x = -0.3 * b.w + k as f64 * 0.2 * b.w;
        b.revolved(
            Handle,
            0,
            [x, hd - 0.02, 0.82 * h],
            rot_x(-FRAC_PI_2),
            1.0,
            frustum_profile(0.02, 0.02, 0.02),
        );
    }
    b.cuboid(Door, [-hw + 0.01, y, 0.06], [hw - 0.01, hd - 0.02, 0.7 * h]);
    b.cuboid(
        Screen,
        [-hw + 0.08, hd - 0.02, 0.2 * h],
        [hw - 0.08, hd - 0.015, 0.55 * h],
    );
    b.rod(
        Handle,
        [-hw + 0.06, hd - 0.008, 0.64 * h],
        [hw - 0.06, hd - 0.008, 0.64 * h],
        0.008,
    );
}

pub fn appliance(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = appliance_body(b);
    if h < 0.6 {
        // Counter-top appliance: a window door and a control panel on the right.
        b.cuboid(
            Door,
            [-hw + 0.01, y, 0.05 * h],
            [0.3 * b.w, hd - 0.015, 0.95 * h],
        );
        b.cuboid(
            Screen,
            [-hw + 0.05, hd - 0.015, 0.2 * h],
            [0.2 * b.w, hd - 0.01, 0.8 * h],
        );
        b.cuboid(
            Interior,
            [0.32 * b.w, y, 0.1 * h],
            [hw - 0.02, hd - 0.02, 0.9 * h],
        );
    } else {
        b.cuboid(
            Door,
            [-hw + 0.01, y, 0.05],
            [hw - 0.01, hd - 0.015, 0.85 * h],
        );
        b.cuboid(
            Interior,
            [-hw + 0.01, y, 0.87 * h],
            [hw - 0.01, hd - 0.02, h - 0.01],
        );
        b.rod(
            Handle,
            [-0.3 * b.w, hd - 0.008, 0.8 * h],
            [0.3 * b.w, hd - 0.008, 0.8 * h],
            0.008,
        );
    }
}
