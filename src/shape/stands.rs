//! Layouts of things on a pole that a plain post cannot show: a music stand (tripod, pole and a
//! tilted desk with a lip and sheet music), an IV stand (a wheeled star base, a pole and a hook
//! bar with a drip bag and its line), a traffic light (a pole and a dark housing of red, amber
//! and green lamps under visors) and a gramophone (a wooden case with a turntable, a tone arm
//! and a big flared horn). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::rot_x;
use std::f64::consts::{FRAC_PI_2, TAU};

/// A music stand: three splayed legs, a thin pole, and at the top a desk tilted back with a
/// lip along its foot holding two open sheets of music.
pub fn music_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let reach = 0.9 * hw.min(hd);
    let hub = 0.2 * h;
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU + FRAC_PI_2;
        b.rod(
            Metal,
            [0.0, 0.0, hub],
            [reach * a.cos(), reach * a.sin(), 0.01],
            0.008,
        );
    }
    let (dh, tilt) = ((0.3 * h).min(0.4), 0.35f64);
    let zd = h - 0.5 * dh * tilt.cos();
    b.cylinder(Metal, [0.0, 0.0, 0.0], 0.01, zd);
    // The desk: a plate tilted back about x, its lip, the sheets on it.
    let half = [hw - 0.01, 0.004, 0.5 * dh];
    // Tilted back: its top leans away from the player, who stands at +y.
    let c = [0.0, 0.0, zd];
    let rot = rot_x(tilt);
    b.slab(Metal, c, half, rot);
    let up = [0.0, -tilt.sin(), tilt.cos()];
    let normal = [0.0, tilt.cos(), tilt.sin()];
    let at = |s: f64, n: f64, u: f64| {
        [
            c[0] + s,
            c[1] + n * normal[1] + u * up[1],
            c[2] + n * normal[2] + u * up[2],
        ]
    };
    b.slab(
        Metal,
        at(0.0, 0.02, -0.5 * dh),
        [hw - 0.01, 0.02, 0.006],
        rot,
    );
    for x in [-0.5 * (hw - 0.02), 0.5 * (hw - 0.02)] {
        b.slab(
            Canvas,
            at(x, 0.006, 0.02),
            [0.48 * (hw - 0.02), 0.002, 0.42 * dh],
            rot,
        );
        // Staves: dark lines across each sheet.
        for k in 0..5 {
            let u = -0.3 * dh + k as f64 * 0.16 * dh;
            b.slab(
                BlackKeys,
                at(x, 0.009, u),
                [0.4 * (hw - 0.02), 0.001, 0.004],
                rot,
            );
        }
    }
}

/// An IV stand: a five-legged star base on castors, a tall pole, a cross bar with hooks at the
/// top, a drip bag hanging from one hook with its line down past a pump clamped to the pole.
pub fn iv_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let reach = 0.92 * hw.min(hd);
    for k in 0..5 {
        let a = k as f64 / 5.0 * TAU + FRAC_PI_2;
        let foot = [reach * a.cos(), reach * a.sin()];
        b.rod(Metal, [0.0, 0.0, 0.08], [foot[0], foot[1], 0.06], 0.015);
        b.rod(
            Tyre,
            [foot[0], foot[1] - 0.02, 0.025],
            [foot[0], foot[1] + 0.02, 0.025],
            0.025,
        );
    }
    b.cylinder(Metal, [0.0, 0.0, 0.0], 0.014, h - 0.02);
    // The hook bar and the hooks.
    let zb = h - 0.1;
    let arm = 0.85 * hw;
    b.rod(Metal, [-arm, 0.0, zb], [arm, 0.0, zb], 0.008);
    for x in [-arm, arm] {
        b.polyline(
            Metal,
            &[[x, 0.0, zb], [x, 0.0, h - 0.01], [0.9 * x, 0.0, h - 0.04]],
            0.006,
        );
    }
    // The bag: a flat pouch under the right hook, its line down to the pump.
    let (bw, bh) = ((0.35 * arm).min(0.1), 0.22);
    let zt = zb - 0.03;
    b.ellipsoid(Pane, [arm, 0.0, zt - 0.5 * bh], [bw, 0.025, 0.5 * bh]);
    b.ellipsoid(
        Water,
        [arm, 0.0, zt - 0.6 * bh],
        [0.85 * bw, 0.02, 0.35 * bh],
    );
    let zp = 0.55 * h;
    b.polyline(
        Canvas,
        &[
            [arm, 0.0, zt - bh],
            [0.8 * arm, 0.02, zt - bh - 0.15],
            [0.05, 0.04, zp + 0.12],
        ],
        0.003,
    );
    b.cuboid(Body, [-0.06, 0.015, zp - 0.08], [0.06, 0.08, zp + 0.08]);
    b.cuboid(Screen, [-0.045, 0.08, zp], [0.045, 0.082, zp + 0.06]);
}

/// A traffic light: a pole on a base, a dark housing near the top facing +y with three round
/// lamps (red over amber over green) each under a visor, a backplate round the housing.
pub fn traffic_light(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let hh = (0.3 * h).min(1.0).min(3.2 * m);
    let hwid = (0.35 * hh).min(0.9 * hw);
    let z0 = h - hh;
    b.frustum(Frame, [0.0, 0.0, 0.0], 0.6 * m, 0.6 * m, 0.6, 0.08);
    b.cylinder(
        Frame,
        [0.0, -0.3 * hd, 0.0],
        0.05_f64.min(0.25 * m),
        z0 + 0.1,
    );
    let (yb, yf) = (-0.1 * hd, 0.45 * hd);
    b.cuboid(Body, [-hwid, yb, z0], [hwid, yf, h]);
    b.cuboid(
        Frame,
        [-1.25 * hwid, yb - 0.02, z0 - 0.05],
        [1.25 * hwid, yb, h],
    );
    let r = 0.36 * hwid;
    for (k, role) in [Light, Top, Seat].into_iter().enumerate() {
        let z = h - (k as f64 + 0.5) * hh / 3.0;
        b.revolved(
            role,
            0,
            [0.0, yf, z],
            rot_x(-FRAC_PI_2),
            1.0,
            vec![[0.0, 0.0], [r, 0.0], [r, 0.01], [0.0, 0.012]],
        );
        // The visor: a half tube over the lamp.
        b.revolved(
            Body,
            0,
            [0.0, yf, z],
            rot_x(-FRAC_PI_2),
            1.0,
            vec![[1.1 * r, 0.0], [1.1 * r, (hd - yf).max(0.01)]],
        );
    }
}

/// A gramophone: a wooden case with a turntable and a record, a crank at its side, a tone arm
/// rising into the narrow end of a horn that flares up and forward to a wide bell.
pub fn gramophone(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zc = 0.3 * h;
    let cw = 0.85 * hw;
    b.cuboid(Trunk, [-cw, -hd, 0.0], [cw, 0.5 * hd, zc]);
    b.cuboid(
        Frame,
        [-cw - 0.01, -hd, zc - 0.02],
        [cw + 0.01, 0.5 * hd, zc],
    );
    let rp = 0.8 * cw.min(0.75 * hd);
    let yp = -0.25 * hd;
    b.cylinder(Metal, [0.0, yp, zc], rp, 0.01);
    b.cylinder(BlackKeys, [0.0, yp, zc + 0.01], 0.95 * rp, 0.006);
    b.cylinder(Canvas, [0.0, yp, zc + 0.016], 0.3 * rp, 0.002);
    b.polyline(
        Metal,
        &[
            [cw, -0.2 * hd, 0.5 * zc],
            [cw + 0.04, -0.2 * hd, 0.5 * zc],
            [cw + 0.04, -0.2 * hd, 0.7 * zc],
        ],
        0.008,
    );
    // The tone arm up to the horn's throat.
    let throat = [0.6 * rp, yp - 0.6 * rp, zc + 0.12 * h];
    b.polyline(
        Metal,
        &[
            [0.6 * rp, yp - 0.6 * rp, zc],
            throat,
            [0.3 * rp, yp, zc + 0.04],
        ],
        0.012,
    );
    // The horn: a flared surface along a direction up and forward to the bell.
    let bell_r = (0.95 * hw).min(0.45 * (h - zc));
    let bell = [0.0, hd - 0.6 * bell_r, h - bell_r];
    let dir = [
        bell[0] - throat[0],
        bell[1] - throat[1],
        bell[2] - throat[2],
    ];
    let len = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
    let profile: Vec<[f64; 2]> = (0..=12)
        .map(|i| {
            let t = i as f64 / 12.0;
            [0.02 + (bell_r - 0.02) * t.powf(2.5), t * len]
        })
        .collect();
    b.revolved(Metal, 0, throat, frame_along(dir), 1.0, profile);
    b.revolved(
        Interior,
        0,
        bell,
        frame_along(dir),
        1.0,
        vec![[0.0, -0.01], [0.9 * bell_r, -0.01]],
    );
}
