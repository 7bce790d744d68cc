//! Things on a pole in a garden or by a pool, each with the head that says what it is, not the
//! mailbox of `structures.rs`: a birdhouse (a little house with a pitched roof, a round entrance
//! hole and a perch, on a wooden post), a bird feeder (a roofed tray of seed with a clear hopper), a patio heater
//! (a tall column on a weighted base under a wide reflector hood, a glow under the hood) and an
//! outdoor shower (a post with a shower head on an arm over a slatted floor tray, a tap on the
//! post). The front is +y.
use super::archetypes::Builder;
use super::fittings::{disc, Y};
use super::materials::Role::*;
use super::parts::{frustum_profile, IDENTITY};

/// The pole: a foot plate and a round post of radius `r` up to `top`.
fn pole(b: &mut Builder, m: f64, r: f64, top: f64) {
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.8 * m, 0.8 * m, 0.6, 0.04);
    b.cylinder(Frame, [0.0, 0.0, 0.0], r, top);
}

/// A gabled roof over `[-hw, hw] × [-hd, hd]` from eaves at `z` up to a ridge along y at
/// `z + rise`.
fn gable(b: &mut Builder, hw: f64, hd: f64, z: f64, rise: f64) {
    let l = (hw * hw + rise * rise).sqrt();
    let a = rise.atan2(hw);
    for s in [-1.0, 1.0] {
        b.slab(
            Top,
            [s * hw / 2.0, 0.0, z + rise / 2.0],
            [l / 2.0 + 0.01, hd, 0.008],
            super::parts::rot_y(s * a),
        );
    }
}

/// A birdhouse: a little house on a pole, its entrance hole and perch to the front.
pub fn birdhouse(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let (s, hh) = (0.6 * m, (0.16 * h).clamp(0.12, 0.35));
    let rise = 0.5 * s;
    let z0 = h - hh - rise;
    // A square wooden post driven into the ground, with no foot plate.
    let p = (0.1 * m).max(0.025);
    b.cuboid(Trunk, [-p, -p, 0.0], [p, p, z0]);
    b.cuboid(Body, [-s, -s, z0], [s, s, z0 + hh]);
    // The gable ends filled in under the roof.
    b.slab(
        Body,
        [0.0, 0.0, z0 + hh + 0.3 * rise],
        [0.7 * s, 0.98 * s, 0.3 * rise],
        IDENTITY,
    );
    gable(b, 1.25 * s, 1.2 * s, z0 + hh - 0.1 * rise, 1.1 * rise);
    disc(
        b,
        Interior,
        [0.0, s + 0.002, z0 + 0.62 * hh],
        Y,
        0.3 * s,
        0.004,
    );
    b.rod(
        Metal,
        [0.0, s, z0 + 0.35 * hh],
        [0.0, s + 0.35 * s, z0 + 0.35 * hh],
        0.006,
    );
}

/// A bird feeder: a clear hopper of seed on a tray, under a little roof, on a pole.
pub fn bird_feeder(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let (s, hh) = (0.55 * m, (0.14 * h).clamp(0.1, 0.3));
    let rise = 0.45 * s;
    let z0 = h - hh - rise - 0.03;
    pole(b, m, (0.05 * m).max(0.012), z0);
    // The tray with a lip, seed in the hopper, the hopper's clear walls.
    b.cuboid(Top, [-1.3 * s, -1.3 * s, z0], [1.3 * s, 1.3 * s, z0 + 0.02]);
    b.cuboid(
        Soil,
        [-0.6 * s, -0.6 * s, z0 + 0.02],
        [0.6 * s, 0.6 * s, z0 + 0.6 * hh],
    );
    b.cuboid(
        Pane,
        [-0.7 * s, -0.7 * s, z0 + 0.02],
        [0.7 * s, 0.7 * s, z0 + hh],
    );
    for (x, y) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
        b.cylinder(Frame, [0.75 * s * x, 0.75 * s * y, z0 + 0.02], 0.008, hh);
    }
    gable(b, 1.35 * s, 1.3 * s, z0 + hh, rise);
}

/// A patio heater: a weighted base, a tall column, the burner head glowing under a wide
/// reflector hood.
pub fn patio_heater(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let rb = 0.45 * m;
    // The base: a squat round housing for the gas bottle, wider than the column.
    b.revolved(
        Body,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        frustum_profile(rb, 0.8 * rb, 0.3 * h),
    );
    b.cylinder(Body, [0.0, 0.0, 0.3 * h], 0.06 * m.max(0.4), 0.5 * h);
    // The burner head: a mesh cylinder glowing, a guard round it.
    let zb = 0.8 * h;
    b.cylinder(Light, [0.0, 0.0, zb], 0.16 * m, 0.1 * h);
    for k in 0..6 {
        let a = std::f64::consts::TAU * k as f64 / 6.0;
        let (x, y) = (0.2 * m * a.cos(), 0.2 * m * a.sin());
        b.rod(Metal, [x, y, zb], [x, y, zb + 0.1 * h], 0.006);
    }
    // The reflector hood: a wide shallow cone over the head.
    b.revolved(
        Shade,
        0,
        [0.0, 0.0, zb + 0.1 * h],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.1 * h - 0.02],
            [0.2 * m, 0.1 * h - 0.02],
            [m, 0.0],
            [m, 0.02],
            [0.2 * m, 0.1 * h],
            [0.0, 0.1 * h],
        ],
    );
}

/// An outdoor shower: a post on a slatted tray, an arm at the top with a wide shower head, a tap
/// half way up.
pub fn shower_post(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.03;
    // The slatted floor tray.
    let n = 7;
    for i in 0..n {
        let x0 = -hw + i as f64 * b.w / n as f64;
        b.cuboid(
            Top,
            [x0 + 0.01, -hd, 0.0],
            [x0 + b.w / n as f64 - 0.01, hd, 0.04],
        );
    }
    let (px, py) = (0.0, -hd + 0.08);
    b.cylinder(Metal, [px, py, 0.04], r, h - 0.04 - r);
    // The arm out over the tray and the head hanging from it.
    let arm = 0.5 * b.d;
    b.rod(
        Metal,
        [px, py, h - 1.5 * r],
        [px, py + arm, h - 1.5 * r],
        0.8 * r,
    );
    b.revolved(
        Metal,
        0,
        [px, py + arm, h - 0.12],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [0.1, 0.0],
            [0.1, 0.015],
            [0.03, 0.1],
            [0.0, 0.1],
        ],
    );
    // A tap and a foot tap on the post.
    for z in [0.5 * h, 0.25 * h] {
        b.rod(Handle, [px, py, z], [px, py + 0.08, z], 0.012);
        b.cylinder(Handle, [px, py + 0.08, z - 0.03], 0.02, 0.06);
    }
}
