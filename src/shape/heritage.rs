//! Layouts of things of a trade or an age that people name in fantastical and old places: a
//! fire pit, a well, a windmill, an anchor, a cannon, a ship's wheel and a spinning wheel (the
//! stall, the shelter, the armour and the barrel are in `market.rs`). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{frustum_profile, rot_x, rot_y, Primitive, V3};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// An oriented box centred at `centre` with half extents `half`, rotated by `rot`.
pub(super) fn slab(
    b: &mut Builder,
    role: Role,
    variant: u32,
    centre: V3,
    half: V3,
    rot: [[f64; 3]; 3],
) {
    b.push(role, variant, Primitive::Cuboid { centre, half, rot });
}

/// A flat disc (a wheel, a lid) of radius `r` and thickness `t` centred at `centre`, its axis
/// along `axis`.
fn disc(b: &mut Builder, role: Role, centre: V3, axis: V3, r: f64, t: f64) {
    let l = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let base = [0, 1, 2].map(|k| centre[k] - 0.5 * t * axis[k] / l);
    b.revolved(
        role,
        0,
        base,
        frame_along(axis),
        1.0,
        frustum_profile(r, r, t),
    );
}

/// A spoked wheel in the plane of the unit vectors `plane` about `centre`: a rim of rods, a hub
/// along their cross product and `spokes` spokes; with `handles` the spokes run on past the rim
/// as turned handles (a ship's wheel).
fn wheel(
    b: &mut Builder,
    role: Role,
    centre: V3,
    plane: [V3; 2],
    radius: f64,
    spokes: usize,
    handles: bool,
) {
    let [u, v] = plane;
    let r = (0.06 * radius).max(0.008);
    let at = |s: f64, t: f64| [0, 1, 2].map(|k| centre[k] + s * (t.cos() * u[k] + t.sin() * v[k]));
    let segs = 24;
    for i in 0..segs {
        let (t0, t1) = (
            i as f64 / segs as f64 * TAU,
            (i + 1) as f64 / segs as f64 * TAU,
        );
        b.rod(role, at(radius, t0), at(radius, t1), r);
    }
    let axis = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    disc(b, role, centre, axis, 2.5 * r, 3.0 * r);
    let reach = if handles { 1.3 * radius } else { radius };
    for k in 0..spokes {
        let t = k as f64 / spokes as f64 * TAU;
        let p = |s: f64| at(s, t);
        b.rod(role, centre, p(reach), 0.5 * r);
        if handles {
            b.rod(role, p(1.08 * radius), p(1.3 * radius), 0.9 * r);
        }
    }
}

/// A fire pit: a ring of stones around a bed of ash, logs leaning into a cone and a flame.
pub fn fire_pit(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let n = 14;
    let stone = 0.16 * hw.min(hd);
    for k in 0..n {
        let a = k as f64 / n as f64 * TAU;
        b.ellipsoid_rot(
            Body,
            k,
            [(hw - stone) * a.cos(), (hd - stone) * a.sin(), 0.22 * h],
            [stone * 1.15, stone, 0.22 * h],
            super::parts::rot_z(a + FRAC_PI_2),
        );
    }
    b.frustum(
        Interior,
        [0.0, 0.0, 0.0],
        hw - stone,
        hd - stone,
        1.0,
        0.05 * h,
    );
    let logs = 5;
    for k in 0..logs {
        let a = k as f64 / logs as f64 * TAU + 0.4;
        let foot = [0.5 * hw * a.cos(), 0.5 * hd * a.sin(), 0.05 * h];
        b.rod(Trunk, foot, [0.0, 0.0, 0.75 * h], 0.05 * hw.min(hd));
    }
    b.frustum(
        Light,
        [0.0, 0.0, 0.05 * h],
        0.3 * hw,
        0.3 * hd,
        0.05,
        0.95 * h,
    );
}

/// A well: a round stone wall with dark water inside, two posts, a crossbar with a rope and
/// a bucket, and a pitched roof.
pub fn well(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let wall = 0.42 * h;
    b.cylinder(Body, [0.0, 0.0, 0.0], 0.8 * hw.min(hd), wall);
    b.frustum(
        Top,
        [0.0, 0.0, wall],
        0.84 * hw.min(hd),
        0.84 * hw.min(hd),
        1.0,
        0.03 * h,
    );
    b.frustum(
        Interior,
        [0.0, 0.0, wall + 0.03 * h],
        0.62 * hw.min(hd),
        0.62 * hw.min(hd),
        1.0,
        0.004,
    );
    let post = 0.05 * hw.max(0.4);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.72 * hw;
        b.cuboid(Frame, [x - post, -post, wall], [x + post, post, 0.8 * h]);
    }
    b.rod(
        Frame,
        [-0.8 * hw, 0.0, 0.68 * h],
        [0.8 * hw, 0.0, 0.68 * h],
        0.6 * post,
    );
    b.rod(Metal, [0.0, 0.0, 0.68 * h], [0.0, 0.0, 0.52 * h], 0.008);
    b.frustum(
        Metal,
        [0.0, 0.0, 0.46 * h],
        0.1 * hw,
        0.1 * hw,
        1.25,
        0.07 * h,
    );
    // Two roof slopes of wooden shingles (the wood role a stone word leaves alone) meeting at a
    // ridge along x.
    let (eave, ridge) = (0.76 * h, h - 0.01);
    let run = 0.95 * hd;
    let slope = (ridge - eave).atan2(run);
    let half_len = 0.5 * run.hypot(ridge - eave);
    for sy in [-1.0, 1.0] {
        slab(
            b,
            Trunk,
            0,
            [0.0, sy * 0.5 * run, 0.5 * (eave + ridge)],
            [0.95 * hw, half_len, 0.012 * h],
            rot_x(-sy * slope),
        );
    }
}

/// A windmill: a stout tapering tower with a door and a window, a conical cap, and four lattice
/// sails on a hub at the front.
pub fn windmill(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let hub_z = 0.72 * h;
    // A stout tower, about half as wide as the sails reach, tapering to a conical cap.
    let r0 = 0.45 * hw.min(hd);
    let r1 = 0.6 * r0;
    b.frustum(Body, [0.0, 0.0, 0.0], r0, r0, r1 / r0, hub_z);
    b.frustum(
        Top,
        [0.0, 0.0, hub_z - 0.02 * h],
        1.12 * r1,
        1.12 * r1,
        0.15,
        0.16 * h,
    );
    b.cuboid(
        Door,
        [-0.25 * r0, r0 - 0.02, 0.0],
        [0.25 * r0, r0 + 0.01, 0.22 * h],
    );
    b.cuboid(
        Glass,
        [-0.15 * r0, 0.8 * r0, 0.45 * h],
        [0.15 * r0, 0.9 * r0, 0.52 * h],
    );
    let hub = [0.0, r1 + 0.06 * hw, hub_z];
    b.rod(Frame, [0.0, 0.0, hub_z], hub, 0.05 * r0);
    b.ellipsoid(Frame, hub, [0.08 * r0, 0.08 * r0, 0.08 * r0]);
    // A sail reaches at most to the ground's clearance and the footprint's edge.
    let len = (0.95 * hw).min(hub_z - 0.08 * h);
    for k in 0..4 {
        let a = PI / 4.0 + k as f64 * FRAC_PI_2;
        let (c, s) = (a.cos(), a.sin());
        let tip = [hub[0] + len * c, hub[1], hub[2] + len * s];
        b.rod(Frame, hub, tip, 0.025 * r0 + 0.01);
        // The lattice: a cloth panel beside the outer two thirds of the stock.
        let mid = 0.6 * len;
        let side = 0.13 * len;
        let centre = [
            hub[0] + mid * c - side * s,
            hub[1] + 0.01,
            hub[2] + mid * s + side * c,
        ];
        slab(
            b,
            Canvas,
            0,
            centre,
            [0.38 * len, 0.006, 0.12 * len],
            rot_y(-a),
        );
    }
}

/// An anchor: a shank with a ring at the top, a stock across it, and curved arms ending in
/// flukes.
pub fn anchor(b: &mut Builder) {
    let (hw, _hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.04 * h).min(0.12 * hw);
    let ring_r = (0.07 * h).min(0.3 * hw);
    b.rod(Metal, [0.0, 0.0, r], [0.0, 0.0, h - 2.0 * ring_r - r], r);
    // The ring and the arms are beads along their curves: round in every direction, so the
    // curve reads the same from any side.
    let ring_c = [0.0, 0.0, h - ring_r - 0.6 * r];
    for k in 0..20 {
        let t = k as f64 / 20.0 * TAU;
        let p = [ring_r * t.cos(), 0.0, ring_c[2] + ring_r * t.sin()];
        b.ellipsoid(Metal, p, [0.6 * r, 0.6 * r, 0.6 * r]);
    }
    b.rod(
        Metal,
        [-0.55 * hw, 0.0, 0.78 * h],
        [0.55 * hw, 0.0, 0.78 * h],
        0.8 * r,
    );
    // Arms: an arc below the crown, from one fluke to the other.
    let arm = hw - 1.5 * r;
    let c = r + arm;
    let at = |t: f64| [arm * t.sin(), 0.0, c - arm * t.cos()];
    let (t0, t1) = (-0.42 * PI, 0.42 * PI);
    let beads = 28;
    for i in 0..=beads {
        let t = t0 + (t1 - t0) * i as f64 / beads as f64;
        b.ellipsoid(Metal, at(t), [r, r, r]);
    }
    for t in [t0, t1] {
        let p = at(t);
        slab(
            b,
            Metal,
            0,
            [p[0] - 0.1 * arm * t.signum(), 0.0, p[2] + 0.05 * h],
            [0.09 * arm, 0.6 * r, 0.07 * h],
            rot_y(t),
        );
    }
}

/// A cannon: an iron barrel along y on a wooden carriage with two spoked wheels.
pub fn cannon(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let wheel_r = (0.42 * h).min(0.3 * hd);
    for sx in [-1.0, 1.0] {
        // The carriage is wood whatever the barrel's metal word says.
        b.cuboid(
            Trunk,
            [sx * 0.42 * hw - 0.06 * hw, -0.85 * hd, 0.0],
            [sx * 0.42 * hw + 0.06 * hw, 0.25 * hd, 0.55 * h],
        );
        let c = [sx * 0.85 * hw, 0.05 * hd, wheel_r];
        wheel(
            b,
            Tyre,
            c,
            [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            0.92 * wheel_r,
            8,
            false,
        );
    }
    b.rod(
        Metal,
        [-0.9 * hw, 0.05 * hd, wheel_r],
        [0.9 * hw, 0.05 * hd, wheel_r],
        0.05 * hw,
    );
    let (back, front) = ([0.0, -0.6 * hd, 0.62 * h], [0.0, hd - 0.02, 0.72 * h]);
    let dir = [0, 1, 2].map(|k| front[k] - back[k]);
    let len = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
    let rb = (0.3 * hw).min(0.35 * h);
    b.revolved(
        Metal,
        0,
        back,
        frame_along(dir),
        1.0,
        frustum_profile(rb, 0.7 * rb, len),
    );
    b.ellipsoid(Metal, back, [0.8 * rb, 0.8 * rb, 0.8 * rb]);
    let muzzle = [0, 1, 2].map(|k| back[k] + dir[k] * (1.0 - 0.06));
    disc(b, Metal, muzzle, dir, 0.85 * rb, 0.06 * len);
    disc(
        b,
        Interior,
        [front[0], front[1] + 0.002, front[2]],
        dir,
        0.45 * rb,
        0.004,
    );
}

/// A ship's wheel: a spoked wheel with handles standing upright on a pedestal.
pub fn helm(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let radius = (hw / 1.3).min(0.3 * h);
    let centre = [0.0, 0.4 * hd, h - 1.3 * radius];
    b.cuboid(
        Frame,
        [-0.5 * hw, -0.8 * hd, 0.0],
        [0.5 * hw, 0.8 * hd, 0.04 * h],
    );
    b.cuboid(
        Frame,
        [-0.12 * hw, -0.25 * hd, 0.0],
        [0.12 * hw, 0.25 * hd, centre[2]],
    );
    b.rod(Metal, [0.0, 0.0, centre[2]], centre, 0.05 * radius);
    wheel(
        b,
        Frame,
        centre,
        [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        radius,
        8,
        true,
    );
}

/// A spinning wheel: a low bench on three splayed legs, a large spoked wheel between two
/// uprights at one end, a treadle below and the flyer with its bobbin of wool at the other end.
pub fn spinning_wheel(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let bench_z = 0.32 * h;
    b.cuboid(
        Frame,
        [-hw, -0.3 * hd, bench_z - 0.03 * h],
        [0.8 * hw, 0.3 * hd, bench_z + 0.03 * h],
    );
    for (x, y) in [
        (-0.85 * hw, 0.0),
        (0.7 * hw, -0.8 * hd),
        (0.7 * hw, 0.8 * hd),
    ] {
        b.rod(Frame, [x, y, 0.0], [0.9 * x, 0.3 * y, bench_z], 0.025 * h);
    }
    let radius = (0.32 * h).min(0.42 * hw);
    let centre = [-0.35 * hw, 0.0, h - radius - 0.02 * h];
    for sy in [-1.0, 1.0] {
        b.rod(
            Frame,
            [centre[0], sy * 0.25 * hd, bench_z],
            [centre[0], sy * 0.25 * hd, centre[2] + 0.05 * h],
            0.02 * h,
        );
    }
    wheel(
        b,
        Frame,
        centre,
        [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        radius,
        10,
        false,
    );
    b.cuboid(
        Frame,
        [-0.6 * hw, -0.5 * hd, 0.02 * h],
        [0.1 * hw, 0.5 * hd, 0.05 * h],
    );
    b.rod(
        Frame,
        [-0.2 * hw, 0.0, 0.05 * h],
        [centre[0] + 0.15 * radius, 0.0, centre[2]],
        0.01 * h,
    );
    // The flyer: a post with a spindle and a bobbin of wool.
    let fx = 0.6 * hw;
    b.rod(Frame, [fx, 0.0, bench_z], [fx, 0.0, 0.62 * h], 0.025 * h);
    let spindle = 0.6 * h;
    b.rod(
        Frame,
        [0.2 * hw, 0.0, spindle],
        [0.95 * hw, 0.0, spindle],
        0.012 * h,
    );
    b.ellipsoid(
        Cushion,
        [0.4 * hw, 0.0, spindle],
        [0.12 * hw, 0.06 * h, 0.06 * h],
    );
}
