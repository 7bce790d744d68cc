//! Layouts of a story's lair: a dragon lying curled on the ground (a long scaled body, a neck
//! raised to a horned head, folded bat wings, a spined tail curling round its side) and a hoard
//! of treasure (a low heap of gold coins with coins strewn over it, goblets and gems). The front
//! faces +y (the dragon's head); each stays inside its size box.
use super::archetypes::{frame_along, Builder};
use super::beasts::taper;
use super::materials::Role::{self, *};
use super::parts::{rot_z, IDENTITY, V3};
use std::f64::consts::FRAC_PI_2;

/// Fills the triangle `a`, `p`, `q` with strips fanning from `a` (a wing's membrane).
fn fan(b: &mut Builder, role: Role, a: V3, p: V3, q: V3) {
    let n = 8;
    for i in 0..n {
        let f = (i as f64 + 0.5) / n as f64;
        let e = [0, 1, 2].map(|k| p[k] + f * (q[k] - p[k]));
        let d = [0, 1, 2].map(|k| e[k] - a[k]);
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let span = [0, 1, 2].map(|k| (q[k] - p[k]) / n as f64);
        let sw = (span[0] * span[0] + span[1] * span[1] + span[2] * span[2]).sqrt();
        let c = [0, 1, 2].map(|k| 0.5 * (a[k] + e[k]));
        // A strip along `d`, as wide at its outer end as the edge's step.
        let rot = frame_along(d);
        b.slab(role, c, [0.3 * sw, 0.004, 0.5 * l], rot);
    }
}

/// A dragon lying down (see the module docs), its length along y.
pub fn dragon(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (l, w) = (b.d, b.w);
    // The body: a long belly resting on the ground, a paler underside.
    let (by, bz, br) = (-0.05 * l, 0.2 * h, [0.3 * w, 0.22 * l, 0.2 * h]);
    b.ellipsoid(Body, [0.0, by, bz], br);
    b.ellipsoid(
        Upholstery,
        [0.0, by + 0.02 * l, 0.6 * bz],
        [0.85 * br[0], 0.9 * br[1], 0.6 * bz],
    );
    // Haunches and folded forelegs with claws at the front.
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Body,
            [sx * 0.28 * w, by - 0.12 * l, 0.14 * h],
            [0.1 * w, 0.1 * l, 0.14 * h],
        );
        let hip = [sx * 0.3 * w, by - 0.05 * l, 0.06 * h];
        taper(
            b,
            Body,
            hip,
            [sx * 0.3 * w, by + 0.06 * l, 0.04 * h],
            0.05 * w,
            0.035 * w,
        );
        let sh = [sx * 0.2 * w, by + 0.17 * l, 0.14 * h];
        let paw = [sx * 0.22 * w, by + 0.3 * l, 0.03 * h];
        taper(b, Body, sh, paw, 0.06 * w, 0.04 * w);
        for k in -1..=1 {
            let c = [paw[0] + k as f64 * 0.025 * w, paw[1] + 0.03 * l, 0.012];
            taper(
                b,
                Keys,
                [paw[0] + k as f64 * 0.02 * w, paw[1], 0.03],
                c,
                0.012,
                0.003,
            );
        }
    }
    // The neck rising from the chest to the head, held up and forward.
    let neck = [
        [0.0, by + 0.18 * l, 0.28 * h],
        [0.0, 0.22 * l, 0.5 * h],
        [0.0, 0.3 * l, 0.68 * h],
    ];
    taper(b, Body, neck[0], neck[1], 0.12 * w, 0.085 * w);
    taper(b, Body, neck[1], neck[2], 0.085 * w, 0.06 * w);
    // The head: a skull, a long snout tapering forward, a lower jaw, eyes, two swept horns.
    let hc = [0.0, 0.34 * l, 0.72 * h];
    b.ellipsoid(Body, hc, [0.08 * w, 0.06 * l, 0.08 * h]);
    taper(b, Body, hc, [0.0, hd - 0.01, 0.66 * h], 0.06 * w, 0.03 * w);
    taper(
        b,
        Upholstery,
        [0.0, hc[1], 0.64 * h],
        [0.0, hd - 0.04, 0.61 * h],
        0.04 * w,
        0.02 * w,
    );
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Light,
            [sx * 0.06 * w, hc[1] + 0.03 * l, 0.76 * h],
            [0.012, 0.02, 0.012],
        );
        let root = [sx * 0.05 * w, hc[1] - 0.02 * l, 0.78 * h];
        let mid = [sx * 0.09 * w, hc[1] - 0.07 * l, 0.9 * h];
        taper(b, Keys, root, mid, 0.025 * w, 0.015 * w);
        taper(
            b,
            Keys,
            mid,
            [sx * 0.1 * w, hc[1] - 0.12 * l, 0.98 * h],
            0.015 * w,
            0.002,
        );
    }
    // Folded wings: a bone from the shoulder up to the wrist and back down to the tip, the
    // membrane between them and the back.
    for sx in [-1.0, 1.0] {
        let shoulder = [sx * 0.15 * w, by + 0.12 * l, 0.36 * h];
        let wrist = [sx * 0.36 * w, by + 0.02 * l, 0.95 * h];
        let tip = [sx * 0.42 * w, by - 0.3 * l, 0.3 * h];
        let root = [sx * 0.18 * w, by - 0.15 * l, 0.3 * h];
        taper(b, Frame, shoulder, wrist, 0.03 * w, 0.02 * w);
        taper(b, Frame, wrist, tip, 0.02 * w, 0.006);
        taper(
            b,
            Frame,
            wrist,
            [sx * 0.4 * w, by - 0.1 * l, 0.3 * h],
            0.015 * w,
            0.005,
        );
        fan(b, Canvas, wrist, shoulder, root);
        fan(b, Canvas, wrist, root, tip);
    }
    // The tail: out behind, then curling round the right side towards the front, tapering.
    let tail_r = |k: usize| 0.1 * w * (1.0 - k as f64 / 10.5) + 0.004;
    let pts: Vec<V3> = (0..=10)
        .map(|i| {
            let t = i as f64 / 10.0;
            let a = t * 0.85 * std::f64::consts::PI;
            let (cx, cy, r) = (0.05 * w, by - 0.05 * l, 0.4 * l);
            let x = cx + (hw - 0.15 * w - cx) * a.sin();
            let y = (cy - r * a.cos()).max(-hd + 0.04);
            // Lying on the ground: its underside at the floor.
            [x, y, tail_r(i)]
        })
        .collect();
    for (i, s) in pts.windows(2).enumerate() {
        taper(b, Body, s[0], s[1], tail_r(i), tail_r(i + 1));
    }
    // Spines along the back and the tail.
    for k in 0..6 {
        let y = by + 0.15 * l - k as f64 * 0.07 * l;
        let u = (y - by) / br[1];
        let z = bz + br[2] * (1.0 - u * u).max(0.0).sqrt();
        taper(
            b,
            Top,
            [0.0, y, z - 0.02],
            [0.0, y - 0.03 * l, z + 0.08 * h],
            0.03 * w,
            0.002,
        );
    }
    for s in pts.iter().take(8).skip(1) {
        let top = [s[0], s[1], s[2] + 0.1 * h];
        taper(b, Top, [s[0], s[1], s[2]], top, 0.02 * w, 0.002);
    }
}

/// A gold coin lying tilted at `c`, radius `r`.
fn coin(b: &mut Builder, c: V3, r: f64, tilt: f64, turn: f64) {
    let axis = [tilt.sin() * turn.cos(), tilt.sin() * turn.sin(), tilt.cos()];
    b.revolved(
        Handle,
        0,
        c,
        frame_along(axis),
        1.0,
        super::parts::frustum_profile(r, r, 0.003),
    );
}

/// A hoard of treasure (see the module docs).
pub fn treasure_hoard(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ay = hd / hw;
    // The heap: a low dome of coins with lumps slid down its sides, lower than the box so
    // goblets stand proud of it.
    let hh = 0.6 * h;
    let dome = |r: f64, top: f64| -> Vec<[f64; 2]> {
        std::iter::once([0.0, 0.0])
            .chain((0..=8).map(|i| {
                let a = i as f64 / 8.0 * FRAC_PI_2;
                [r * a.cos(), top * a.sin().powf(0.7)]
            }))
            .collect()
    };
    b.revolved(Metal, 0, [0.0, 0.0, 0.0], IDENTITY, ay, dome(0.8 * hw, hh));
    let lumps = [
        (0.45, 0.3, 0.45),
        (-0.5, 0.2, 0.4),
        (0.1, -0.5, 0.45),
        (-0.3, -0.35, 0.35),
        (0.55, -0.3, 0.3),
    ];
    for (fx, fy, s) in lumps {
        let r = s * hw;
        let c = [fx * (hw - r), fy * (hd - r * ay), 0.0];
        b.revolved(Metal, 0, c, IDENTITY, ay, dome(r, s * 1.2 * hh));
    }
    let height = |x: f64, y: f64| {
        let mut z = 0.0f64;
        let mut one = |cx: f64, cy: f64, r: f64, top: f64| {
            let q = (((x - cx) / r).powi(2) + ((y - cy) / (r * ay)).powi(2)).sqrt();
            if q < 1.0 {
                z = z.max(top * (1.0 - q * q).powf(0.35));
            }
        };
        one(0.0, 0.0, 0.8 * hw, hh);
        for (fx, fy, s) in lumps {
            let r = s * hw;
            one(fx * (hw - r), fy * (hd - r * ay), r, s * 1.2 * hh);
        }
        z
    };
    // Coins strewn over the heap and round its foot, bright against it.
    let cr = (0.035 * b.w.min(b.d)).clamp(0.015, 0.035);
    for k in 0..90 {
        let a = k as f64 * 2.39996;
        let s = (k as f64 / 90.0).sqrt();
        let (x, y) = (s * (hw - cr) * a.cos(), s * (hd - cr) * a.sin());
        let z = height(x, y) + 0.004;
        coin(
            b,
            [x, y, z],
            cr,
            0.15 + 0.6 * ((k * 7 % 5) as f64 / 5.0),
            a * 1.7,
        );
    }
    // Goblets stuck in the heap, gems red and blue.
    for (fx, fy, s) in [(-0.4, 0.25, 1.0), (0.3, -0.2, 0.85), (0.15, 0.45, 0.7)] {
        let (x, y) = (fx * hw, fy * hd);
        let g = 0.4 * h * s;
        let z = (height(x, y) - 0.25 * g).min(h - g);
        b.revolved(
            Body,
            0,
            [x, y, z],
            IDENTITY,
            1.0,
            vec![
                [0.0, 0.0],
                [0.3 * g, 0.0],
                [0.3 * g, 0.05 * g],
                [0.06 * g, 0.12 * g],
                [0.05 * g, 0.5 * g],
                [0.3 * g, 0.62 * g],
                [0.36 * g, g],
                [0.3 * g, g],
            ],
        );
        b.revolved(
            Interior,
            0,
            [x, y, z + 0.92 * g],
            IDENTITY,
            1.0,
            vec![[0.0, 0.0], [0.33 * g, 0.0], [0.33 * g, 0.004], [0.0, 0.004]],
        );
    }
    for k in 0..8 {
        let a = k as f64 * 2.1 + 0.5;
        let s = 0.25 + 0.6 * ((k * 3 % 7) as f64 / 7.0);
        let (x, y) = (s * hw * a.cos(), s * hd * a.sin());
        let r = (0.06 * h).clamp(0.02, 0.04);
        let z = (height(x, y) + 0.3 * r).min(h - r);
        let role = if k % 2 == 0 { Cushion } else { Glass };
        b.ellipsoid_rot(role, 0, [x, y, z], [r, r, 0.7 * r], rot_z(a));
    }
}
