//! Layouts of scientific and stage instruments on stands: a microscope (a heavy foot, a curved arm at the back
//! holding the stage, the turret of objectives over it and the eyepiece tube leaning back, with
//! focus knobs and a lamp in the foot), a stage spotlight (a can on a yoke, tilted forward,
//! on a column over a tripod) and a photographer's softbox (a wide octagonal diffuser box on the
//! same light stand), and a submarine's periscope (a tube floor to ceiling with a head at eye
//! height). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};
use std::f64::consts::FRAC_PI_2;

/// A microscope: foot, arm, stage, objectives, body tube and eyepiece.
pub fn microscope(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = hw.min(hd);
    // The foot, and the lamp set in it under the stage.
    b.cuboid(Body, [-0.75 * hw, -hd, 0.0], [0.75 * hw, 0.8 * hd, 0.1 * h]);
    let ys = 0.25 * hd;
    b.cylinder(Light, [0.0, ys, 0.1 * h], 0.18 * s, 0.01);
    // The arm: up from the back of the foot, bending forward over the stage.
    let ya = -0.6 * hd;
    let ra = 0.16 * s;
    b.polyline(
        Body,
        &[
            [0.0, ya, 0.08 * h],
            [0.0, ya - 0.05 * hd, 0.4 * h],
            [0.0, ya + 0.05 * hd, 0.66 * h],
            [0.0, ya + 0.45 * hd, 0.8 * h],
        ],
        ra,
    );
    // Focus knobs on both sides of the arm.
    b.rod(
        Metal,
        [-0.7 * hw, ya, 0.3 * h],
        [0.7 * hw, ya, 0.3 * h],
        0.05 * s,
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Handle,
            [sx * 0.5 * hw, ya, 0.3 * h],
            [sx * 0.68 * hw, ya, 0.3 * h],
            0.2 * s,
        );
    }
    // The stage, with its clips, held out from the arm.
    let zs = 0.36 * h;
    b.cuboid(
        Metal,
        [-0.08 * hw, ya, zs - 0.03 * h],
        [0.08 * hw, ys - 0.3 * s, zs],
    );
    b.cuboid(
        Top,
        [-0.6 * hw, ys - 0.55 * s, zs],
        [0.6 * hw, ys + 0.5 * s, zs + 0.025 * h],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [sx * 0.35 * hw - 0.01, ys - 0.2 * s, zs + 0.025 * h],
            [sx * 0.35 * hw + 0.01, ys + 0.3 * s, zs + 0.032 * h],
        );
    }
    // The head over the stage: the turret with three objectives pointing down at it.
    let zt = 0.62 * h;
    b.cuboid(
        Body,
        [-0.25 * hw, ys - 0.35 * s, zt + 0.05 * h],
        [0.25 * hw, ys + 0.25 * s, 0.8 * h],
    );
    b.frustum(Metal, [0.0, ys, zt], 0.3 * s, 0.3 * s, 0.8, 0.05 * h);
    for k in 0..3 {
        let a = (k as f64 - 1.0) * 0.9;
        let (dx, dy) = (0.16 * s * a.sin(), 0.16 * s * a.cos());
        b.revolved(
            Metal,
            0,
            [dx, ys + dy - 0.08 * s, zt - 0.12 * h + 0.01 * k as f64],
            super::parts::IDENTITY,
            1.0,
            frustum_profile(0.05 * s, 0.08 * s, 0.12 * h),
        );
    }
    // The eyepiece tube, leaning back from the head, a dark ocular at its end.
    let tilt = 0.6;
    let base = [0.0, ys - 0.05 * s, 0.78 * h];
    let len = 0.2 * h;
    b.revolved(
        Body,
        0,
        base,
        rot_x(tilt),
        1.0,
        frustum_profile(0.1 * s, 0.09 * s, len),
    );
    let top = [0.0, base[1] - len * tilt.sin(), base[2] + len * tilt.cos()];
    b.revolved(
        BlackKeys,
        0,
        top,
        rot_x(tilt),
        1.0,
        frustum_profile(0.08 * s, 0.08 * s, (h - top[2]).max(0.01) / tilt.cos()),
    );
}

/// A light stand: three splayed legs on rubber feet meeting a sleeve a quarter of the way up,
/// a column rising from it to `top`, and the extension's lock handle.
fn light_stand(b: &mut Builder, top: f64) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = hw.min(hd);
    let zc = 0.25 * h;
    for k in 0..3 {
        let a = std::f64::consts::TAU * k as f64 / 3.0 + 0.5;
        b.rod(
            Metal,
            [0.0, 0.0, zc],
            [0.95 * s * a.sin(), 0.95 * s * a.cos(), 0.0],
            0.012,
        );
        b.cylinder(
            Tyre,
            [0.95 * s * a.sin(), 0.95 * s * a.cos(), 0.0],
            0.02,
            0.015,
        );
    }
    let r = (0.05 * s).max(0.015);
    b.cylinder(Metal, [0.0, 0.0, zc - 0.05 * h], 1.2 * r, 0.35 * h);
    b.cylinder(Metal, [0.0, 0.0, zc], r, top - zc);
    b.rod(
        Handle,
        [0.0, 0.0, zc + 0.33 * h],
        [0.12 * s, 0.0, zc + 0.33 * h],
        0.6 * r,
    );
}

/// A photographer's softbox light: a light stand and on it a wide octagonal box of black
/// cloth, narrow at its back where the lamp mounts, open to the front and a little down, its
/// whole front face a white diffuser.
pub fn softbox(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rc = 0.95 * hw.min(0.5 * h);
    let len = (0.9 * hd).min(1.2 * rc);
    let zax = h - rc;
    light_stand(b, zax);
    let t = 0.15f64;
    let rot = rot_x(-(FRAC_PI_2 + t));
    let dir = [0.0, t.cos(), -t.sin()];
    let back = [0.0, -0.5 * len * dir[1], zax - 0.5 * len * dir[2]];
    // The lamp's housing behind the box, on a bracket from the column.
    b.cuboid(
        Frame,
        [-0.04, -0.03, zax - 0.05],
        [0.04, back[1] + 0.02, zax + 0.03],
    );
    let housing = [0.0, back[1] - 0.08 * dir[1], back[2] - 0.08 * dir[2]];
    b.revolved(
        Metal,
        0,
        housing,
        rot,
        1.0,
        frustum_profile(0.08, 0.08, 0.1),
    );
    b.revolved(Body, 0, back, rot, 1.0, frustum_profile(0.2 * rc, rc, len));
    let front = [0.0, back[1] + len * dir[1], back[2] + len * dir[2]];
    b.revolved(Light, 0, front, rot, 1.0, vec![[0.0, 0.0], [rc, 0.0]]);
}

/// A stage spotlight: three splayed legs, a column rising from them, a U-shaped yoke at the
/// top and between its arms a cylindrical can tilted a little down, with a lens at its front,
/// cooling fins round its back and a handle on top.
pub fn spotlight(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = hw.min(hd);
    let zy = 0.72 * h;
    light_stand(b, zy);
    // The yoke.
    let rc = 0.6 * s;
    let xa = rc + 0.15 * s;
    let zax = zy + 0.55 * (h - zy);
    b.cuboid(Frame, [-xa, -0.04 * s, zy], [xa, 0.04 * s, zy + 0.02 * h]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [sx * xa - 0.02 * s, -0.04 * s, zy],
            [sx * xa + 0.02 * s, 0.04 * s, zax],
        );
        b.rod(
            Handle,
            [sx * xa, 0.0, zax],
            [sx * (xa + 0.05 * s), 0.0, zax],
            0.08 * s,
        );
    }
    // The can, tilted forward and down about the yoke's axis.
    let t = 0.25f64;
    let rot = rot_x(-(FRAC_PI_2 + t));
    let len = 1.7 * s;
    let dir = [0.0, t.cos(), -t.sin()];
    let back = [0.0, -0.5 * len * dir[1], zax - 0.5 * len * dir[2]];
    b.revolved(Body, 0, back, rot, 1.0, frustum_profile(rc, 0.9 * rc, len));
    let front = [0.0, back[1] + len * dir[1], back[2] + len * dir[2]];
    b.revolved(
        Light,
        0,
        front,
        rot,
        1.0,
        vec![[0.0, 0.0], [0.82 * rc, 0.0]],
    );
    b.revolved(
        Interior,
        0,
        front,
        rot,
        1.0,
        vec![[0.82 * rc, 0.0], [0.9 * rc, 0.0], [0.9 * rc, 0.05 * len]],
    );
    for k in 1..4 {
        let t = 0.08 * k as f64;
        let c = [0.0, back[1] + t * len * dir[1], back[2] + t * len * dir[2]];
        b.revolved(
            Metal,
            0,
            c,
            rot,
            1.0,
            vec![[1.08 * rc, 0.0], [1.08 * rc, 0.02 * len]],
        );
    }
    let mid = [
        0.0,
        back[1] + 0.5 * len * dir[1],
        back[2] + 0.5 * len * dir[2],
    ];
    b.polyline(
        Handle,
        &[
            [0.0, mid[1] - 0.25 * len, mid[2] + rc],
            [0.0, mid[1] - 0.2 * len, mid[2] + rc + 0.1 * s],
            [0.0, mid[1] + 0.2 * len, mid[2] + rc + 0.1 * s],
            [0.0, mid[1] + 0.25 * len, mid[2] + rc],
        ],
        0.03 * s,
    );
}

/// A periscope: a thick steel tube standing from a collar in the floor up to the ceiling
/// (banded where its sections join), and at eye height its head: a wide box round the tube
/// with a hooded eyepiece towards the front (two dark lenses) and a long training handle
/// folded down at each side, as an officer grips them.
pub fn periscope(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.3 * hw.min(hd)).clamp(0.06, 0.11);
    // the well collar in the floor, the tube, its bands
    b.cylinder(Frame, [0.0, 0.0, 0.0], (2.0 * r).min(hd - 0.01), 0.08);
    b.cylinder(Metal, [0.0, 0.0, 0.08], r, h - 0.08);
    for z in [0.35 * h, h - 0.1] {
        b.cylinder(Frame, [0.0, 0.0, z], 1.25 * r, 0.05);
    }
    // The head at eye height: wider than the tube all round, the hood at its front.
    let ze = (0.68 * h).min(1.6);
    let (bw, front) = ((2.0 * r).min(hw - 0.02), (2.2 * r).min(hd - 0.02));
    b.cuboid(Body, [-bw, -1.6 * r, ze - 0.3], [bw, front, ze + 0.12]);
    let hood = (front + 0.6 * r).min(hd - 0.004);
    b.cuboid(
        Body,
        [-1.2 * r, front, ze - 0.1],
        [1.2 * r, hood, ze + 0.08],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.55 * r;
        b.cuboid(
            Screen,
            [x - 0.4 * r, hood, ze - 0.05],
            [x + 0.4 * r, hood + 0.003, ze + 0.04],
        );
    }
    // the training handles: an arm out of each side of the head, a grip hanging from it
    for sx in [-1.0, 1.0] {
        let x0 = sx * bw;
        let x1 = sx * (hw - 0.03).max(bw + 0.05);
        b.rod(Metal, [x0, 0.0, ze - 0.1], [x1, 0.0, ze - 0.1], 0.025);
        b.rod(Handle, [x1, 0.0, ze - 0.1], [x1, 0.0, ze - 0.4], 0.03);
    }
}
