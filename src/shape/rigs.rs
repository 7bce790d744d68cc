//! Layouts of rigs and props of stories: a forklift (mast and two forks in front, counterweight
//! behind, a seat under an overhead guard), a wizard's staff (a crooked staff with a glowing
//! gem held in its knotted top, upright in a small iron stand) and a pod (a lying stasis pod
//! under a see-through canopy with a sleeper inside, or an upright escape capsule with a window,
//! a hatch and landing legs), with lit trim. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::{self, *};
use super::parts::IDENTITY;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// An open band round the vertical axis at `origin` (x radius `r`, y radius `ay r`), from `z`
/// to `z + t`: a seam of lit trim or a ring.
fn band(b: &mut Builder, role: Role, r: f64, ay: f64, z: f64, t: f64) {
    b.revolved(role, 0, [0.0, 0.0, z], IDENTITY, ay, vec![[r, 0.0], [r, t]]);
}

/// A forklift: two forks on a carriage running up a mast at the front, the body with its
/// wheels, a heavy counterweight at the back, a seat and a steering wheel under an overhead
/// guard of posts and roof bars, a beacon on the roof and headlights on the front posts.
pub fn forklift(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lf = 0.38 * b.d;
    let ym = hd - lf - 0.06 * b.d;
    let yc = ym + 0.04 * b.d;
    let rf = (0.15 * h).min(0.13 * b.d);
    let rr = 0.8 * rf;
    let tw = 0.18 * b.w;
    let (yf, yr) = (ym - 1.2 * rf, -hd + 0.2 * b.d);
    // Wheels.
    for sx in [-1.0, 1.0] {
        for (y, r) in [(yf, rf), (yr, rr)] {
            b.rod(Tyre, [sx * (hw - tw), y, r], [sx * hw, y, r], r);
            b.rod(
                Metal,
                [sx * hw - sx * 0.004, y, r],
                [sx * hw, y, r],
                0.55 * r,
            );
        }
    }
    // The body: a chassis between the wheels, a deck over them, the counterweight behind.
    let deck = 2.0 * rf + 0.03 * h;
    b.cuboid(
        Body,
        [-hw + tw, -hd + 0.1 * b.d, 0.4 * rr],
        [hw - tw, ym, deck],
    );
    b.cuboid(
        Body,
        [-hw, -hd + 0.25 * b.d, deck],
        [hw, ym, deck + 0.06 * h],
    );
    let ycw = -hd + 0.22 * b.d;
    b.cuboid(Body, [-hw, -hd, 0.5 * rr], [hw, ycw, deck + 0.18 * h]);
    b.ellipsoid(
        Body,
        [0.0, ycw - 0.08 * b.d, deck + 0.18 * h],
        [hw, 0.08 * b.d, 0.05 * h],
    );
    // The seat and the steering wheel.
    let zs = deck + 0.06 * h;
    let ys = -hd + 0.3 * b.d;
    b.cuboid(
        Seat,
        [-0.25 * b.w, ys, zs],
        [0.25 * b.w, ys + 0.18 * b.d, zs + 0.05 * h],
    );
    b.cuboid(
        Seat,
        [-0.25 * b.w, ys - 0.03 * b.d, zs],
        [0.25 * b.w, ys, zs + 0.3 * h],
    );
    let ysw = ym - 0.12 * b.d;
    b.rod(
        BlackKeys,
        [0.0, ysw + 0.05 * b.d, zs],
        [0.0, ysw, zs + 0.18 * h],
        0.03,
    );
    b.revolved(
        BlackKeys,
        0,
        [0.0, ysw, zs + 0.18 * h],
        super::parts::rot_x(0.6),
        1.0,
        super::parts::frustum_profile(0.16 * b.w, 0.16 * b.w, 0.03),
    );
    // The overhead guard: four posts and a roof of bars, a beacon on it.
    let zr = h - 0.06 * h;
    let (yb, yg) = (ycw - 0.02 * b.d, ym - 0.03 * b.d);
    let p = 0.04;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.08 * b.w);
        b.rod(Frame, [x, yb, zs - 0.05 * h], [x, yb, zr], p);
        b.rod(Frame, [x, ym - 0.02, deck], [x, yg, zr], p);
        b.cuboid(Frame, [x - p, yb - p, zr], [x + p, yg + p, zr + 0.04]);
        b.cuboid(
            Light,
            [x - 0.05, yg + p - 0.01, zr - 0.1 * h],
            [x + 0.05, yg + p + 0.01, zr - 0.06 * h],
        );
    }
    for k in 0..6 {
        let y = yb + (yg - yb) * k as f64 / 5.0;
        b.cuboid(
            Frame,
            [-hw + 0.08 * b.w, y - 0.02, zr],
            [hw - 0.08 * b.w, y + 0.02, zr + 0.04],
        );
    }
    b.cylinder(Light, [0.3 * hw, yb + 0.1, zr + 0.04], 0.06, h - zr - 0.04);
    // The mast: two channels with cross bars and a lift cylinder between them.
    for sx in [-1.0, 1.0] {
        let x = sx * 0.3 * b.w;
        b.cuboid(Frame, [x - 0.05, ym, 0.1 * h], [x + 0.05, yc, 0.96 * h]);
    }
    for z in [0.3 * h, 0.95 * h - 0.05] {
        b.cuboid(Frame, [-0.3 * b.w, ym, z], [0.3 * b.w, yc, z + 0.05]);
    }
    b.cylinder(Handle, [0.0, 0.5 * (ym + yc), 0.1 * h], 0.05, 0.55 * h);
    // The carriage: a plate with a load guard over it, and the forks.
    let yp = yc + 0.02 * b.d;
    let zc = 0.32 * h;
    b.cuboid(Frame, [-0.42 * b.w, yc, 0.06 * h], [0.42 * b.w, yp, zc]);
    for k in 0..5 {
        let x = -0.38 * b.w + 0.76 * b.w * k as f64 / 4.0;
        b.cuboid(Frame, [x - 0.02, yc, zc], [x + 0.02, yp, zc + 0.25 * h]);
    }
    b.cuboid(
        Frame,
        [-0.42 * b.w, yc, zc + 0.25 * h - 0.04],
        [0.42 * b.w, yp, zc + 0.25 * h],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.22 * b.w;
        b.cuboid(Metal, [x - 0.05, yp, 0.0], [x + 0.05, yp + 0.05, 0.28 * h]);
        b.cuboid(Metal, [x - 0.05, yp, 0.0], [x + 0.05, hd, 0.045]);
    }
}

/// A wizard's staff: a crooked shaft of knotty wood rising from a small iron stand of three
/// splayed legs and a ring, its top splitting into claws round a glowing gem.
pub fn staff(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let reach = 0.95 * hw.min(hd);
    let r = (0.2 * reach).clamp(0.012, 0.025);
    // The stand.
    let zr = (0.22 * h).min(0.45);
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU + FRAC_PI_2;
        let foot = [reach * a.cos(), reach * a.sin(), 0.01];
        b.polyline(
            Metal,
            &[
                [1.6 * r * a.cos(), 1.6 * r * a.sin(), zr],
                [0.6 * foot[0], 0.6 * foot[1], 0.3 * zr],
                foot,
            ],
            0.2 * r + 0.003,
        );
    }
    band(b, Metal, 1.6 * r, 1.0, zr - 0.01, 0.03);
    b.cylinder(Metal, [0.0, 0.0, 0.0], 1.7 * r, 0.04 * zr + 0.01);
    // The shaft: bends every span, a knot at some of them.
    let top = h - 5.0 * r;
    let n = 8;
    let wobble = (0.5 * reach - r).max(0.0).min(2.0 * r);
    let pts: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let s = if i == 0 || i == n { 0.0 } else { 1.0 };
            [
                s * wobble * (2.7 * i as f64).sin(),
                s * wobble * (1.9 * i as f64 + 1.0).cos(),
                0.01 + t * (top - 0.01),
            ]
        })
        .collect();
    b.polyline(Trunk, &pts, r);
    for p in pts.iter().skip(2).step_by(3) {
        b.ellipsoid(Trunk, *p, [1.5 * r, 1.5 * r, 2.0 * r]);
    }
    // The head: a knot, claws curling up round the gem.
    let t = pts[n];
    b.ellipsoid(Trunk, [t[0], t[1], t[2]], [1.8 * r, 1.8 * r, 1.5 * r]);
    let g = 2.0 * r;
    let zg = top + 2.5 * r;
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU;
        let (c, s) = (a.cos(), a.sin());
        b.polyline(
            Trunk,
            &[
                [t[0] + 0.8 * r * c, t[1] + 0.8 * r * s, top],
                [t[0] + 1.9 * r * c, t[1] + 1.9 * r * s, zg - 0.5 * g],
                [t[0] + 1.6 * r * c, t[1] + 1.6 * r * s, zg + 0.8 * g],
                [t[0] + 0.6 * r * c, t[1] + 0.6 * r * s, h - 0.3 * r],
            ],
            0.35 * r,
        );
    }
    b.ellipsoid(Light, [t[0], t[1], zg], [g, g, 1.2 * g]);
}

/// A pod. Longer than it is tall: a stasis pod, a capsule lying on a plinth, its white lower
/// shell under a see-through canopy, a sleeper lying on a glowing bed inside, lit trim along
/// the seam and the plinth, a panel at its foot. Taller: an escape pod, an upright capsule
/// tapering to a docking ring, on landing legs over a heat shield, with a lit window, a hatch
/// and lit trim rings.
pub fn pod(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    if h < b.d.max(b.w) {
        lying_pod(b, hw, hd, h);
    } else {
        upright_pod(b, hw, hd, h);
    }
}

fn lying_pod(b: &mut Builder, hw: f64, hd: f64, h: f64) {
    let zp = 0.25 * h;
    b.cuboid(
        Frame,
        [-0.8 * hw, -0.85 * hd, 0.0],
        [0.8 * hw, 0.85 * hd, zp],
    );
    for x in [-0.8 * hw - 0.004, 0.8 * hw] {
        b.cuboid(
            Light,
            [x, -0.8 * hd, 0.7 * zp],
            [x + 0.004, 0.8 * hd, 0.8 * zp],
        );
    }
    b.cuboid(
        Screen,
        [-0.4 * hw, 0.85 * hd, 0.3 * zp],
        [0.4 * hw, 0.85 * hd + 0.004, 0.85 * zp],
    );
    // The lower shell: the bottom half of an ellipsoid, long along y.
    let rz = 0.3 * h;
    let zc = zp + rz;
    let ay = hd / hw;
    let lower: Vec<[f64; 2]> = (0..=12)
        .map(|i| {
            let a = i as f64 / 12.0 * FRAC_PI_2;
            [hw * a.sin(), -rz * a.cos()]
        })
        .chain(std::iter::once([0.0, 0.0]))
        .collect();
    b.revolved(Body, 0, [0.0, 0.0, zc], IDENTITY, ay, lower);
    band(b, Light, 1.005 * hw, ay, zc - 0.02, 0.025);
    // The bed and the sleeper: head to the back, a suit, feet to the front.
    b.revolved(
        Light,
        0,
        [0.0, 0.0, zc + 0.002],
        IDENTITY,
        ay,
        vec![[0.0, 0.0], [0.8 * hw, 0.0], [0.8 * hw, 0.005], [0.0, 0.005]],
    );
    let s = (0.25 * hw).min(0.12 * hd).min(0.5 * (h - zc));
    let zb = zc + 0.5 * s;
    b.ellipsoid(
        Skin,
        [0.0, -0.7 * hd, zb + 0.2 * s],
        [0.5 * s, 0.6 * s, 0.5 * s],
    );
    b.ellipsoid(Canvas, [0.0, -0.3 * hd, zb], [1.0 * s, 0.35 * hd, 0.5 * s]);
    for x in [-0.45 * s, 0.45 * s] {
        b.rod(Canvas, [x, 0.0, zb], [x, 0.6 * hd, zb - 0.1 * s], 0.35 * s);
    }
    // The canopy.
    let upper: Vec<[f64; 2]> = (0..=12)
        .map(|i| {
            let a = i as f64 / 12.0 * FRAC_PI_2;
            [0.98 * hw * a.cos(), (h - zc) * a.sin()]
        })
        .collect();
    b.revolved(Pane, 0, [0.0, 0.0, zc], IDENTITY, ay, upper);
}

fn upright_pod(b: &mut Builder, hw: f64, hd: f64, h: f64) {
    let r = 0.8 * hw.min(hd);
    let z0 = 0.12 * h;
    // Legs with pads, and the heat shield.
    for k in 0..4 {
        let a = k as f64 / 4.0 * TAU + PI / 4.0;
        let (c, s) = (a.cos(), a.sin());
        let foot = [0.95 * hw.min(hd) * c, 0.95 * hw.min(hd) * s, 0.02];
        b.rod(Metal, [0.85 * r * c, 0.85 * r * s, 0.35 * h], foot, 0.03);
        b.cylinder(Metal, [foot[0], foot[1], 0.0], 0.08, 0.03);
    }
    b.frustum(
        Frame,
        [0.0, 0.0, 0.5 * z0],
        0.7 * r,
        0.7 * r,
        1.25,
        0.5 * z0 + 0.02,
    );
    // The shell: wide above the shield, tapering to the docking ring.
    let profile = |t: f64| -> f64 {
        // Radius at height fraction t of the shell (0 at its foot, 1 at its top).
        if t < 0.2 {
            r * (0.88 + 0.6 * t)
        } else {
            r * (1.0 - 0.7 * ((t - 0.2) / 0.8).powf(1.3))
        }
    };
    let zt = h - 0.06 * h;
    let shell = zt - z0;
    let mut pts = vec![[0.0, 0.0]];
    for i in 0..=16 {
        let t = i as f64 / 16.0;
        pts.push([profile(t), t * shell]);
    }
    pts.push([0.0, shell]);
    b.revolved(Body, 0, [0.0, 0.0, z0], IDENTITY, 1.0, pts);
    for t in [0.17, 0.62] {
        band(b, Light, 1.01 * profile(t), 1.0, z0 + t * shell, 0.025 * h);
    }
    b.cylinder(Metal, [0.0, 0.0, zt - 0.01], 0.3 * r, h - zt + 0.01);
    // The window and the hatch on the front.
    let tw = 0.45;
    let zw = z0 + tw * shell;
    let rw = 0.22 * r;
    b.ellipsoid(
        Frame,
        [0.0, 0.97 * profile(tw), zw],
        [1.2 * rw, 0.06 * r, 1.2 * rw],
    );
    b.ellipsoid(Glass, [0.0, 0.99 * profile(tw), zw], [rw, 0.06 * r, rw]);
    let (th0, th1) = (0.2, 0.36);
    let yh = profile(th0).min(profile(th1));
    b.cuboid(
        Door,
        [-0.3 * r, yh - 0.02, z0 + th0 * shell],
        [0.3 * r, yh + 0.02, z0 + th1 * shell],
    );
    b.cuboid(
        Handle,
        [-0.1 * r, yh + 0.02, z0 + 0.26 * shell],
        [0.1 * r, yh + 0.035, z0 + 0.28 * shell],
    );
}
