//! Layouts of lumps on the ground outdoors: a rock or boulder (irregular lumps of weathered
//! stone, each of its own shade by [`Role::Stone`](super::materials::Role::Stone) variant, with
//! faceted flanks and a broad foot) and a snowman (three balls of snow, a carrot nose, coal eyes
//! and buttons, stick arms, a scarf and a hat). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_z;

/// A lump's profile from its foot to its top, (radius, height) as fractions of the lump's
/// radius and height: a broad foot, facets narrowing to a flattish crown.
const PROFILE: [[f64; 2]; 7] = [
    [0.0, 0.0],
    [1.0, 0.0],
    [1.0, 0.16],
    [0.86, 0.52],
    [0.58, 0.84],
    [0.22, 1.0],
    [0.0, 1.0],
];

/// Lumps as (centre x, y as fractions of the half width and depth, size as a fraction of the
/// room left to the box's side, height as a fraction of the box's, cross-section aspect, turn
/// about z in radians). A lump's radius fits the box at its centre, so no lump is cut open.
const LUMPS: [[f64; 6]; 7] = [
    [0.0, 0.0, 1.0, 0.86, 0.82, 0.3],
    [0.25, 0.15, 1.0, 1.0, 0.85, 0.9],
    [0.45, 0.1, 0.95, 0.72, 0.8, 1.2],
    [-0.45, -0.1, 0.95, 0.62, 0.74, -0.7],
    [0.1, 0.45, 0.9, 0.48, 0.9, 0.5],
    [-0.2, -0.45, 0.9, 0.55, 0.8, 2.0],
    [0.55, -0.5, 0.9, 0.32, 0.9, 0.0],
];

/// A boulder: overlapping faceted lumps of stone of different shades, a crown off the middle,
/// lower ones leaning against the main mass.
pub fn rock(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    for (k, l) in LUMPS.iter().enumerate() {
        let r = l[2] * (hw * (1.0 - l[0].abs())).min(hd * (1.0 - l[1].abs()));
        let lh = l[3] * h;
        let profile = PROFILE.iter().map(|p| [p[0] * r, p[1] * lh]).collect();
        b.revolved(
            Stone,
            k as u32,
            [l[0] * hw, l[1] * hd, 0.0],
            rot_z(l[5]),
            l[4],
            profile,
        );
    }
}

/// A snowman: three balls of snow stacked, smaller upwards; coal eyes and buttons, a carrot
/// nose pointing forward, stick arms out to the sides, a scarf round the neck and a hat.
pub fn snowman(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    // Ball radii in proportion 1 : 0.72 : 0.5, overlapping a little, the hat on top.
    let hat = 0.14 * h;
    let r0 = ((h - hat) / (2.0 * (1.0 + 0.72 + 0.5) - 0.3)).min(0.95 * m);
    let (r1, r2) = (0.72 * r0, 0.5 * r0);
    let z0 = r0;
    let z1 = z0 + r0 + r1 - 0.15 * r0;
    let z2 = z1 + r1 + r2 - 0.15 * r0;
    for (z, r) in [(z0, r0), (z1, r1), (z2, r2)] {
        b.ellipsoid(Body, [0.0, 0.0, z], [r, r, r]);
    }
    // Coal: two eyes, three buttons down the middle ball.
    let coal = 0.08 * r2;
    for sx in [-1.0, 1.0] {
        let (a, e): (f64, f64) = (0.35 * sx, 0.3);
        let p = [
            r2 * a.sin() * e.cos(),
            r2 * a.cos() * e.cos(),
            z2 + r2 * e.sin(),
        ];
        b.ellipsoid(BlackKeys, p, [coal, coal, coal]);
    }
    for k in 0..3 {
        let e = 0.45 - 0.4 * k as f64;
        b.ellipsoid(
            BlackKeys,
            [0.0, r1 * e.cos(), z1 + r1 * e.sin()],
            [1.2 * coal, 1.2 * coal, 1.2 * coal],
        );
    }
    // The carrot nose: a cone forward from the face.
    let nose = (0.9 * r2).min(hd - r2);
    b.revolved(
        Pot,
        0,
        [0.0, 0.9 * r2, z2],
        super::parts::rot_x(-std::f64::consts::FRAC_PI_2),
        1.0,
        super::parts::frustum_profile(0.16 * r2, 0.01, nose),
    );
    // Stick arms out and up from the middle ball, each with a twig.
    for sx in [-1.0, 1.0] {
        let a = [sx * 0.85 * r1, 0.0, z1 + 0.2 * r1];
        let c = [sx * (hw - 0.02), 0.0, z1 + 0.75 * r1];
        b.rod(Trunk, a, c, 0.012);
        let mid = [0.5 * (a[0] + c[0]), 0.0, 0.5 * (a[2] + c[2])];
        b.rod(Trunk, mid, [mid[0] + sx * 0.05, 0.0, mid[2] + 0.12], 0.008);
    }
    // A scarf round the neck and a top hat.
    let zn = z2 - 0.8 * r2;
    b.frustum(
        Upholstery,
        [0.0, 0.0, zn - 0.06 * r0],
        0.8 * r2,
        0.8 * r2,
        1.0,
        0.25 * r2,
    );
    let zh = z2 + 0.85 * r2;
    b.cylinder(Metal, [0.0, 0.0, zh], 0.9 * r2, 0.02);
    b.cylinder(Metal, [0.0, 0.0, zh], 0.6 * r2, (h - zh).max(0.02));
}
