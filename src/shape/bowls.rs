//! Open vessels drawn with what is in them: a fruit bowl (apples, an orange, a bunch of bananas
//! and grapes heaped over its rim), a pet bowl (a flared steel bowl on a rubber ring, kibble in
//! it), a laundry basket (a woven tub with hand holes, clothes heaped in it) and a water jug (a
//! big ribbed bottle with a neck, a cap and a grip), and a plain bowl (empty, wide and deep on
//! a foot ring, glazed inside in another colour). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::fittings::{band, disc};
use super::materials::Role::{self, *};
use super::parts::IDENTITY;
use std::f64::consts::TAU;

const Z: [f64; 3] = [0.0, 0.0, 1.0];

/// An open bowl standing at the origin, `[rb, r, h, t]`: foot radius `rb`, rim radius `r` at
/// height `h`, walls `t` thick; its depth scaled by `ay` (an oval basket). The inside is drawn
/// in `inner`.
pub(super) fn open_bowl(
    b: &mut Builder,
    role: Role,
    inner: Role,
    [rb, r, h, t]: [f64; 4],
    ay: f64,
) {
    b.revolved(
        role,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        ay,
        vec![[0.0, 0.0], [rb, 0.0], [r, h], [r - t, h]],
    );
    b.revolved(
        inner,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        ay,
        vec![[r - t, h], [rb - t, t], [0.0, t]],
    );
}

/// A round fruit of radius `r` resting with its bottom at `z`, `variant` its colour.
fn fruit(b: &mut Builder, variant: u32, x: f64, y: f64, z: f64, r: f64) {
    b.push(
        Books,
        variant,
        super::parts::Primitive::Revolved {
            origin: [x, y, z + r],
            rot: IDENTITY,
            ay: 1.0,
            profile: super::parts::ellipsoid_profile(r, 0.92 * r),
        },
    );
    b.rod(
        Trunk,
        [x, y, z + 1.8 * r],
        [x + 0.1 * r, y, z + 2.1 * r],
        0.08 * r,
    );
}

/// A fruit bowl: a shallow ceramic bowl on a foot, with apples, an orange, bananas and grapes
/// heaped in it and over its rim. The fruit colours are the goods palette's (`groceries`).
pub fn fruit_bowl(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let hb = 0.55 * h;
    b.frustum(Body, [0.0, 0.0, 0.0], 0.35 * r, 0.35 * r, 1.1, 0.12 * hb);
    let first = b.parts.len();
    open_bowl(b, Body, Top, [0.4 * r, r, 0.88 * hb, 0.03 * r], 1.0);
    b.translate_from(first, [0.0, 0.0, 0.12 * hb]);
    let zf = 0.4 * hb;
    let rf = 0.3 * r;
    // Apples (red, green), an orange, round in the bowl; the top of the heap under the box.
    let fr = rf.min((h - zf) / 2.3);
    for (k, v) in [0u32, 3, 4, 0].into_iter().enumerate() {
        let a = k as f64 / 4.0 * TAU + 0.4;
        fruit(b, v, 0.45 * r * a.cos(), 0.45 * r * a.sin(), zf, fr);
    }
    // A bunch of bananas lying across the top.
    for k in 0..3 {
        let dz = k as f64 * 0.35 * fr;
        let pts: Vec<[f64; 3]> = (0..=6)
            .map(|i| {
                let f = i as f64 / 6.0 * 2.0 - 1.0;
                [
                    f * 0.75 * r,
                    0.15 * r * (1.0 - f * f) + (k as f64 - 1.0) * 0.25 * fr,
                    (zf + 1.7 * fr - 0.3 * fr * (1.0 - f * f) + dz).min(h - 0.3 * fr),
                ]
            })
            .collect();
        for w in pts.windows(2) {
            b.push(
                Books,
                1,
                super::parts::Primitive::Revolved {
                    origin: w[0],
                    rot: frame_along([w[1][0] - w[0][0], w[1][1] - w[0][1], w[1][2] - w[0][2]]),
                    ay: 1.0,
                    profile: super::parts::frustum_profile(
                        0.28 * fr,
                        0.28 * fr,
                        ((w[1][0] - w[0][0]).powi(2)
                            + (w[1][1] - w[0][1]).powi(2)
                            + (w[1][2] - w[0][2]).powi(2))
                        .sqrt(),
                    ),
                },
            );
        }
    }
    // Grapes over the rim at the front.
    let gr = 0.12 * fr;
    for i in 0..12 {
        let a = i as f64 * 2.4;
        let s = (i as f64 / 12.0).sqrt();
        let (x, y, z) = (
            0.35 * r * s * a.cos(),
            0.8 * r - 0.2 * r * s * a.sin().abs(),
            zf + 0.6 * fr + (1.0 - s) * fr,
        );
        b.push(
            Books,
            6,
            super::parts::Primitive::Revolved {
                origin: [x, y.min(hd - gr), z],
                rot: IDENTITY,
                ay: 1.0,
                profile: super::parts::ellipsoid_profile(2.0 * gr, 2.0 * gr),
            },
        );
    }
}

/// A pet bowl: a flared steel bowl with a rolled rim on a rubber ring, kibble filling it.
pub fn pet_bowl(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    band(b, Tyre, [0.0, 0.0, 0.0075], Z, 0.98 * r, 0.08 * r, 0.015);
    open_bowl(
        b,
        Metal,
        Metal,
        [0.98 * r, 0.62 * r, h - 0.02, 0.02 * r],
        1.0,
    );
    // The bowl flares outwards at its foot: the wide base is at the floor, the mouth above.
    band(b, Metal, [0.0, 0.0, h - 0.022], Z, 0.64 * r, 0.06 * r, 0.01);
    disc(b, Soil, [0.0, 0.0, 0.6 * h], Z, 0.62 * r, 0.01);
    for k in 0..10 {
        let a = k as f64 * 2.4;
        let s = 0.2 + 0.35 * (k as f64 / 10.0).sqrt();
        b.ellipsoid(
            Soil,
            [s * r * a.cos(), s * r * a.sin(), 0.62 * h],
            [0.08 * r, 0.08 * r, 0.05 * r],
        );
    }
}

/// A laundry basket: an oval woven tub widening a little to its rim, darker weave bands round
/// it, a hand hole at each end, and clothes heaped above the rim (the goods palette's
/// `clothes`).
pub fn laundry_basket(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ay = hd / hw;
    let rim = 0.78 * h;
    open_bowl(b, Body, Interior, [0.88 * hw, hw, rim, 0.03 * hw], ay);
    for k in 1..6 {
        let z = k as f64 / 6.0 * rim;
        let rz = 0.88 * hw + 0.12 * hw * z / rim;
        b.revolved(
            Frame,
            0,
            [0.0, 0.0, z],
            IDENTITY,
            ay,
            vec![[rz + 0.004, -0.01], [rz + 0.004, 0.01]],
        );
    }
    b.revolved(
        Frame,
        0,
        [0.0, 0.0, rim - 0.02],
        IDENTITY,
        ay,
        vec![[hw, 0.0], [hw, 0.03], [hw - 0.03 * hw, 0.03]],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Interior,
            [sx * hw - 0.012, -0.25 * hd, rim - 0.12 * h],
            [sx * hw + 0.0, 0.25 * hd, rim - 0.06 * h],
        );
    }
    // Clothes: soft lumps heaped in the tub, the top ones over the rim.
    for (k, v) in [0u32, 2, 5, 1, 6, 3].into_iter().enumerate() {
        let a = k as f64 * 2.1;
        let s = if k < 3 { 0.45 } else { 0.15 };
        let z = rim - 0.05 * h + if k < 3 { 0.0 } else { 0.08 * h };
        b.push(
            Books,
            v,
            super::parts::Primitive::Revolved {
                origin: [s * hw * a.cos(), s * hd * a.sin(), z],
                rot: super::parts::rot_z(a),
                ay: 0.7,
                profile: super::parts::ellipsoid_profile(0.45 * hw, (h - z).min(0.12 * h)),
            },
        );
    }
}

/// A water jug: a big ribbed bottle of tinted plastic with a shoulder, a neck and a cap, and a
/// moulded grip on one side.
pub fn water_jug(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let cap = 0.08 * h;
    b.revolved(
        Glass,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [0.9 * r, 0.0],
            [r, 0.04 * h],
            [r, 0.62 * h],
            [0.75 * r, 0.76 * h],
            [0.25 * r, 0.84 * h],
            [0.22 * r, h - cap],
            [0.0, h - cap],
        ],
    );
    for z in [0.2, 0.32, 0.44] {
        band(b, Glass, [0.0, 0.0, z * h], Z, r, 0.03 * r, 0.02 * h);
    }
    b.cylinder(Handle, [0.0, 0.0, h - cap], 0.26 * r, cap);
    // A moulded grip in the shoulder.
    b.cuboid(
        Interior,
        [0.45 * r, -0.15 * r, 0.66 * h],
        [0.7 * r, 0.15 * r, 0.72 * h],
    );
}

/// A pail: a galvanised body widening to a rolled rim, open at the top with its inside and a
/// little water showing, two ears at the rim and a wire bail arching over the mouth (the
/// bail's top is the object's top).
pub fn pail(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let rim = 0.7 * h;
    open_bowl(
        b,
        Metal,
        Interior,
        [0.74 * r, 0.96 * r, rim, 0.03 * r],
        hd.min(hw) / r,
    );
    band(b, Metal, [0.0, 0.0, rim], Z, r, 0.06 * r, 0.03 * h);
    // Ridges pressed round the body.
    for f in [0.25, 0.5] {
        let rz = (0.74 + 0.22 * f) * r;
        band(
            b,
            Metal,
            [0.0, 0.0, f * rim],
            Z,
            rz + 0.015 * r,
            0.03 * r,
            0.02 * h,
        );
    }
    disc(b, Glass, [0.0, 0.0, 0.55 * rim], Z, 0.84 * r, 0.01);
    // The bail: ears on either side, a wire arching over the mouth, a wooden grip at its top.
    let n = 10;
    let arc = |k: usize| {
        let a = std::f64::consts::PI * k as f64 / n as f64;
        [
            -0.98 * r * a.cos(),
            0.0,
            rim + (h - rim - 0.02 * h) * a.sin(),
        ]
    };
    for k in 0..n {
        b.rod(Handle, arc(k), arc(k + 1), 0.012 * r);
    }
    for s in [-1.0, 1.0] {
        b.ellipsoid(
            Metal,
            [s * 0.97 * r, 0.0, rim - 0.02 * h],
            [0.04 * r, 0.03 * r, 0.05 * h],
        );
    }
    b.rod(
        Trunk,
        [-0.25 * r, 0.0, h - 0.03 * h],
        [0.25 * r, 0.0, h - 0.03 * h],
        0.04 * r,
    );
}

/// A plain bowl: a deep round ceramic bowl on a low foot ring, its inside glazed in a second
/// colour, a thin band of that colour round the outside under the rim. Empty.
pub fn bowl(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let foot = 0.1 * h;
    b.frustum(Body, [0.0, 0.0, 0.0], 0.42 * r, 0.42 * r, 1.05, foot);
    let first = b.parts.len();
    open_bowl(b, Body, Top, [0.45 * r, r, h - foot, 0.05 * r], 1.0);
    b.translate_from(first, [0.0, 0.0, foot]);
    band(
        b,
        Top,
        [0.0, 0.0, h - 0.12 * h],
        Z,
        0.97 * r,
        0.01 * r,
        0.05 * h,
    );
}
