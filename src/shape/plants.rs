//! Layouts of potted plants by kind, each with its own habit: a snake plant (upright sword
//! leaves), a fern (arching fronds of paired leaflets spilling over the pot), lucky bamboo
//! (jointed canes with leaf tufts), an orchid (broad leaves, a staked arching spray of flowers), a bonsai (a
//! twisted trunk with flat pads of leaves in a shallow tray), a hanging plant (a pot on three
//! cords with trailing strands) and a potted palm (slender canes crowned with arching feather
//! fronds). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::{rot_z, V3};
use super::racks::along;
use std::f64::consts::{PI, TAU};

/// Golden angle: successive leaves turn by it, so none stands in front of the last.
const GOLDEN: f64 = 2.399_963;

/// A round pot `ph` high of top radius `r` with its soil, standing on the floor.
fn pot(b: &mut Builder, r: f64, ph: f64) {
    b.frustum(Pot, [0.0, 0.0, 0.0], 0.78 * r, 0.78 * r, 1.0 / 0.78, ph);
    b.revolved(
        Pot,
        0,
        [0.0, 0.0, ph - 0.025],
        super::parts::IDENTITY,
        1.0,
        super::parts::frustum_profile(1.05 * r, 1.05 * r, 0.025),
    );
    b.frustum(Soil, [0.0, 0.0, ph], 0.97 * r, 0.97 * r, 1.0, 0.004);
}

fn unit(v: V3) -> V3 {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|q| q / l)
}

/// A flat leaf blade of length `l` and half width `w` from `base` along `dir`, turned `spin`
/// about it: widest a third of the way up, pointed at the tip.
fn blade(b: &mut Builder, variant: u32, base: V3, dir: V3, spin: f64, l: f64, w: f64) {
    along(
        b,
        Foliage,
        variant,
        base,
        dir,
        spin,
        0.15,
        vec![
            [0.0, 0.0],
            [0.7 * w, 0.04 * l],
            [w, 0.35 * l],
            [0.8 * w, 0.7 * l],
            [0.0, l],
        ],
    );
}

/// A snake plant: a cylinder pot and a fan of stiff upright sword leaves of several heights.
pub fn snake_plant(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.8 * hw.min(hd);
    let ph = (0.25 * h).min(0.3);
    pot(b, r, ph);
    let n = 11;
    for i in 0..n {
        let a = i as f64 * GOLDEN;
        let (s, c) = a.sin_cos();
        let off = 0.45 * r * ((i % 4) as f64 / 3.0);
        let lean = 0.05 + 0.12 * (off / r);
        let dir = unit([lean * c, lean * s, 1.0]);
        let l = (h - ph - 0.01) * (0.62 + 0.38 * ((i * 5 % 7) as f64 / 6.0)) / dir[2];
        let w = (0.09 * hw.min(hd) + 0.012).min(0.04);
        blade(b, i as u32, [off * c, off * s, ph], dir, a, l, w);
    }
}

/// A fern: a low pot and a crown of fronds rising from the middle and arching out and down over
/// the rim, each a row of leaflets narrowing to the tip.
pub fn fern(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = 0.42 * m;
    let ph = (0.3 * h).min(0.25);
    pot(b, r, ph);
    let n = 16;
    let segs = 7;
    for i in 0..n {
        let a = i as f64 * GOLDEN;
        let (s, c) = a.sin_cos();
        // Inner fronds stand taller, outer ones reach further and droop.
        let k = (i % 4) as f64 / 3.0;
        let reach = (0.8 + 0.2 * k) * (m - 0.02);
        let rise = (0.7 - 0.4 * k) * (h - ph - 0.05);
        for j in 0..segs {
            let t0 = j as f64 / segs as f64;
            let t1 = (j + 1) as f64 / segs as f64;
            // Out along the frond; up in a parabola that falls past its peak.
            let at = |t: f64| {
                let out = reach * t;
                let up = rise * (1.4 * t - 1.2 * t * t) / 0.408;
                [out * c, out * s, ph + up.max(0.0)]
            };
            let (q0, q1) = (at(t0), at(t1));
            let d = [q1[0] - q0[0], q1[1] - q0[1], q1[2] - q0[2]];
            let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            // The stalk, and a pair of leaflets either side of it, shorter towards the tip.
            b.rod(Trunk, q0, q1, 0.004);
            let centre = [0, 1, 2].map(|q| 0.5 * (q0[q] + q1[q]));
            let leaflet = (0.22 * reach).min(0.08) * (1.0 - 0.75 * t0);
            let side = [-s, c, 0.0];
            for sign in [-1.0, 1.0] {
                let dir = side.map(|v| sign * v);
                let mid = [
                    centre[0] + dir[0] * 0.5 * leaflet,
                    centre[1] + dir[1] * 0.5 * leaflet,
                    centre[2] - 0.15 * leaflet,
                ];
                b.ellipsoid_rot(
                    Foliage,
                    (i + j) as u32,
                    mid,
                    [(0.45 * len).max(0.01), 0.06 * leaflet, 0.5 * leaflet],
                    frame_along(dir),
                );
            }
        }
    }
}

/// Lucky bamboo: a pot with a handful of straight jointed canes of several heights, a tuft of
/// slender leaves at the top of each.
pub fn bamboo(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = 0.6 * m;
    let ph = (0.22 * h).min(0.3);
    pot(b, r, ph);
    let canes = 6;
    for i in 0..canes {
        let a = i as f64 * TAU / canes as f64 + 0.3;
        let (s, c) = a.sin_cos();
        let base = [0.45 * r * c, 0.45 * r * s, ph];
        let top = (h - ph - 0.16) * (0.55 + 0.45 * ((i * 3 % 5) as f64 / 4.0));
        let rc = (0.035 * m).max(0.01);
        let x = base[0] * (1.0 + 0.4 * top / h);
        let y = base[1] * (1.0 + 0.4 * top / h);
        let tip = [x, y, ph + top];
        b.rod(Trunk, base, tip, rc);
        let joints = (top / 0.2).floor() as usize;
        for j in 1..=joints {
            let f = j as f64 * 0.2 / top;
            let p = [0, 1, 2].map(|q| base[q] + (tip[q] - base[q]) * f);
            b.rod(
                Trunk,
                [p[0], p[1], p[2] - 0.006],
                [p[0], p[1], p[2] + 0.006],
                1.35 * rc,
            );
        }
        for k in 0..4 {
            let t = a + k as f64 * PI / 2.0;
            let (ts, tc) = t.sin_cos();
            let dir = unit([tc, ts, 0.9 - 0.35 * k as f64]);
            let l = (0.75 * m).min(0.18);
            let from = [tip[0], tip[1], tip[2] - 0.03 * k as f64];
            blade(b, (i * 4 + k) as u32, from, dir, 0.0, l, 0.018);
        }
    }
}

/// An orchid: a pot, broad leaves low over its rim, a stake with a stem arching forward over
/// it carrying a row of blooms that face the front.
pub fn orchid(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = 0.8 * m;
    let ph = (0.25 * h).min(0.15);
    pot(b, r, ph);
    for k in 0..4 {
        let a = k as f64 * PI / 2.0 + 0.5;
        let (s, c) = a.sin_cos();
        let l = 0.95 * (hw - 0.01);
        let dir = unit([c, s, 0.35]);
        let centre = [
            0.5 * l * dir[0],
            0.5 * l * dir[1],
            ph + 0.02 + 0.5 * l * dir[2],
        ];
        b.ellipsoid_rot(
            Foliage,
            k,
            centre,
            [0.35 * l, 0.05 * l, 0.5 * l],
            frame_along(dir),
        );
    }
    // The stake and the stem: up, then arching forward and down a little.
    let zs = h - 0.09;
    b.rod(Trunk, [0.0, -0.2 * hd, ph], [0.0, -0.2 * hd, zs], 0.004);
    let pts: Vec<V3> = (0..=8)
        .map(|i| {
            let t = i as f64 / 8.0;
            let y = -0.2 * hd + t * 1.0 * hd;
            let z = zs + 0.05 * (PI * t).sin() - 0.04 * t;
            [0.0, y, z]
        })
        .collect();
    b.polyline(Trunk, &pts, 0.004);
    let blooms = 6;
    for i in 0..blooms {
        let t = (i as f64 + 1.0) / (blooms as f64 + 0.5);
        let y = -0.2 * hd + t * 0.95 * hd;
        let z = zs + 0.05 * (PI * t).sin() - 0.04 * t - 0.03;
        let rb = (0.28 * m).min(0.035) * (1.0 - 0.3 * t);
        let x = if i % 2 == 0 { 0.02 } else { -0.02 };
        b.ellipsoid(Canvas, [x, y, z], [rb, 0.3 * rb, rb]);
        b.ellipsoid(Pillow, [x, y + 0.3 * rb, z], [0.3 * rb, 0.2 * rb, 0.3 * rb]);
    }
}

/// A bonsai: a shallow tray on little feet, a thick twisting trunk and pads of foliage on
/// branches reaching out to the sides.
pub fn bonsai(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let th = (0.16 * h).min(0.08);
    b.cuboid(
        Pot,
        [-0.85 * hw, -0.8 * hd, 0.0],
        [0.85 * hw, 0.8 * hd, 0.015],
    );
    b.cuboid(
        Pot,
        [-0.9 * hw, -0.85 * hd, 0.015],
        [0.9 * hw, 0.85 * hd, th],
    );
    b.cuboid(
        Soil,
        [-0.85 * hw, -0.8 * hd, th],
        [0.85 * hw, 0.8 * hd, th + 0.004],
    );
    let trunk: [V3; 5] = [
        [-0.1 * hw, 0.0, th],
        [0.2 * hw, 0.05 * hd, th + 0.2 * (h - th)],
        [-0.15 * hw, 0.0, th + 0.42 * (h - th)],
        [0.1 * hw, -0.05 * hd, th + 0.62 * (h - th)],
        [0.0, 0.0, th + 0.78 * (h - th)],
    ];
    let r0 = (0.09 * hw).min(0.03);
    for (k, w) in trunk.windows(2).enumerate() {
        let rr = r0 * (1.0 - 0.2 * k as f64);
        b.rod(Trunk, w[0], w[1], rr);
        b.ellipsoid(Trunk, w[1], [rr, rr, rr]);
    }
    let pad = |b: &mut Builder, v: u32, from: V3, to: V3, rx: f64| {
        b.rod(Trunk, from, to, 0.4 * r0);
        b.ellipsoid_rot(
            Foliage,
            v,
            to,
            [rx, 0.8 * rx, 0.35 * rx],
            rot_z(0.4 * v as f64),
        );
    };
    let rx = 0.36 * hw;
    pad(
        b,
        1,
        trunk[1],
        [-0.55 * hw, 0.1 * hd, trunk[1][2] + 0.08 * h],
        rx,
    );
    pad(
        b,
        2,
        trunk[2],
        [0.55 * hw, -0.1 * hd, trunk[2][2] + 0.08 * h],
        rx,
    );
    pad(
        b,
        3,
        trunk[3],
        [-0.3 * hw, -0.2 * hd, trunk[3][2] + 0.06 * h],
        0.8 * rx,
    );
    pad(
        b,
        4,
        trunk[4],
        [0.05 * hw, 0.0, h - 0.35 * rx - 0.01],
        0.9 * rx,
    );
}

/// A hanging plant: a hook, three cords to the rim of a pot, a mound of leaves in it and
/// strands trailing down from its rim, leaves along them.
pub fn hanging_plant(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = 0.55 * m;
    let ph = 0.22 * h;
    let z0 = 0.42 * h;
    b.frustum(Pot, [0.0, 0.0, z0], 0.75 * r, 0.75 * r, 1.0 / 0.75, ph);
    b.frustum(Soil, [0.0, 0.0, z0 + ph], 0.97 * r, 0.97 * r, 1.0, 0.004);
    let hook = [0.0, 0.0, h - 0.01];
    for k in 0..3 {
        let a = k as f64 * TAU / 3.0;
        let (s, c) = a.sin_cos();
        b.rod(Frame, hook, [r * c, r * s, z0 + ph], 0.003);
    }
    b.ellipsoid(Metal, hook, [0.012, 0.012, 0.01]);
    for i in 0..6 {
        let a = i as f64 * GOLDEN;
        let (s, c) = a.sin_cos();
        let rr = 0.3 * r;
        b.ellipsoid_rot(
            Foliage,
            i,
            [0.55 * r * c, 0.55 * r * s, z0 + ph + 0.6 * rr],
            [rr, 0.8 * rr, 0.6 * rr],
            rot_z(a),
        );
    }
    // Trailing strands, each a row of small leaves falling over the rim.
    let strands = 9;
    for i in 0..strands {
        let a = i as f64 * TAU / strands as f64 + 0.2;
        let (s, c) = a.sin_cos();
        let reach = (m - 0.03 - r).max(0.02);
        let bottom = z0 * (0.05 + 0.6 * ((i * 3 % 5) as f64 / 4.0));
        let top = z0 + ph;
        let n = ((top - bottom) / 0.035).ceil().max(2.0) as usize;
        for j in 0..n {
            let t = j as f64 / (n - 1) as f64;
            let out = r + reach * (1.0 - (1.0 - t).powi(2)).sqrt();
            let z = top - (top - bottom) * t;
            let leaf = 0.022;
            b.ellipsoid_rot(
                Foliage,
                (i + j) as u32,
                [out * c, out * s, z],
                [leaf, 0.4 * leaf, 0.7 * leaf],
                rot_z(a + j as f64),
            );
        }
    }
}

/// A potted palm (an areca or kentia palm): a tall pot, a clump of slender canes rising from
/// it at slight leans, and at the top of each a spray of long arching fronds, each a stalk with
/// narrow leaflets in pairs hanging from it, drooping towards the tip.
pub fn potted_palm(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = 0.5 * m;
    let ph = (0.25 * h).min(0.4);
    pot(b, r, ph);
    let canes = 5;
    for i in 0..canes {
        let a = i as f64 * GOLDEN;
        let (s, c) = a.sin_cos();
        let off = if i == 0 { 0.0 } else { 0.4 * r };
        let base = [off * c, off * s, ph];
        // Taller canes in the middle, shorter round it.
        let top_z = ph
            + (h - ph)
                * if i == 0 {
                    0.7
                } else {
                    0.5 + 0.05 * (i % 3) as f64
                };
        let lean = 0.15 * (top_z - ph);
        let top = [base[0] + lean * c, base[1] + lean * s, top_z];
        b.rod(Trunk, base, top, (0.006 * h).clamp(0.006, 0.012));
        let fronds = 4;
        for f in 0..fronds {
            let fa = a + f as f64 / fronds as f64 * TAU + 0.4 * i as f64;
            palm_frond(b, (i * fronds + f) as u32, top, fa, m - 0.03, h);
        }
    }
}

/// One feather-palm frond from `base` out along the bearing `a`: a stalk rising then arching
/// down to a tip `reach` out (within the size box of height `h`), narrow leaflets in pairs
/// along it, shorter towards the tip.
fn palm_frond(b: &mut Builder, variant: u32, base: V3, a: f64, reach: f64, h: f64) {
    let (s, c) = a.sin_cos();
    // Out from the cane to the box's edge; up a little, then down past the base.
    let out = (reach - (base[0] * c + base[1] * s)).max(0.3 * reach);
    let rise = (0.45 * out).min(h - base[2] - 0.02);
    let at = |t: f64| {
        let up = rise * (2.4 * t - 3.4 * t * t);
        [
            base[0] + out * t * c,
            base[1] + out * t * s,
            (base[2] + up).min(h - 0.01),
        ]
    };
    let segs = 12;
    for j in 0..segs {
        let (t0, t1) = (j as f64 / segs as f64, (j + 1) as f64 / segs as f64);
        let (q0, q1) = (at(t0), at(t1));
        b.rod(Trunk, q0, q1, 0.004);
        let centre = [0, 1, 2].map(|q| 0.5 * (q0[q] + q1[q]));
        let leaflet = (0.35 * out).min(0.22) * (1.0 - 0.6 * t0);
        let side = [-s, c, 0.0];
        for sign in [-1.0, 1.0] {
            // Each leaflet hangs out and down from the stalk.
            let dir = unit([sign * side[0], sign * side[1], -0.7]);
            let mid = [0, 1, 2].map(|q| centre[q] + dir[q] * 0.5 * leaflet);
            b.ellipsoid_rot(
                Foliage,
                variant,
                mid,
                [0.012, 0.003, 0.5 * leaflet],
                frame_along(dir),
            );
        }
    }
}
