//! Carved and standing things of a garden or a park that are more than a post: a sundial (a
//! stone baluster carrying a bronze dial plate with hour marks and a slanted gnomon), a totem
//! pole (carved faces stacked up a pole, each with eyes, a beak or a nose and a mouth, spread
//! wings at the top) and a tree stump (bark, flaring roots, a pale cut top with growth rings).
//! The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::fittings::{band, disc};
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x, IDENTITY};
use std::f64::consts::TAU;

const Z: [f64; 3] = [0.0, 0.0, 1.0];

/// A sundial on a stone baluster: a square plinth, a turned column, a dial plate with twelve
/// hour marks and a triangular gnomon slanting up to the north (-y).
pub fn sundial(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let plinth = 0.08 * h;
    b.cuboid(Stone, [-0.8 * r, -0.8 * r, 0.0], [0.8 * r, 0.8 * r, plinth]);
    let top = 0.88 * h;
    let rc = 0.3 * r;
    // The baluster, turned: a stack of frustums (radius at its foot, radius at its head, the
    // height of its head above the plinth).
    let hc = top - plinth;
    let turned = [
        (0.6 * r, 0.55 * r, 0.06 * h),
        (0.55 * r, rc, 0.12 * h),
        (rc, 1.3 * rc, 0.35 * hc),
        (1.3 * rc, rc, 0.75 * hc),
        (rc, 0.6 * r, hc - 0.03 * h),
        (0.6 * r, 0.8 * r, hc),
    ];
    let mut z = 0.0;
    for (r0, r1, z1) in turned {
        b.frustum(Body, [0.0, 0.0, plinth + z], r0, r0, r1 / r0, z1 - z);
        z = z1;
    }
    disc(b, Metal, [0.0, 0.0, top + 0.005], Z, 0.95 * r, 0.01);
    for k in 0..12 {
        let a = k as f64 / 12.0 * TAU;
        let (c, s) = (a.cos(), a.sin());
        b.rod(
            BlackKeys,
            [0.7 * r * c, 0.7 * r * s, top + 0.011],
            [0.88 * r * c, 0.88 * r * s, top + 0.011],
            0.006,
        );
    }
    // The gnomon: a thin plate on the north-south line, its edge rising to the north.
    let gh = (h - top - 0.012).max(0.02);
    let l = 0.8 * r;
    let ang = (gh / l).atan();
    let hyp = (gh * gh + l * l).sqrt();
    b.slab(
        Metal,
        [0.0, 0.4 * r - l / 2.0, top + 0.01 + gh / 2.0],
        [0.004, hyp / 2.0, 0.01],
        rot_x(ang),
    );
    b.cuboid(
        Metal,
        [-0.004, -0.4 * r, top + 0.01],
        [0.004, 0.4 * r, top + 0.01 + gh * 0.5],
    );
}

/// One carved face of a totem pole on the pole of radius `r` from `z0` to `z1`: big eyes,
/// painted brows, a beak (`beak`) or a broad nose, and a mouth.
fn carved_face(b: &mut Builder, r: f64, z0: f64, z1: f64, beak: bool, variant: u32) {
    let hseg = z1 - z0;
    b.cylinder(Body, [0.0, 0.0, z0], r, hseg);
    band(
        b,
        Handle,
        [0.0, 0.0, z1 - 0.02 * hseg],
        Z,
        1.03 * r,
        0.05 * r,
        0.04 * hseg,
    );
    let y = r;
    for sx in [-1.0, 1.0] {
        let x = sx * 0.42 * r;
        let ze = z0 + 0.68 * hseg;
        b.ellipsoid(Canvas, [x, 0.88 * y, ze], [0.22 * r, 0.12 * r, 0.12 * hseg]);
        b.ellipsoid(
            BlackKeys,
            [x, 0.98 * y, ze],
            [0.09 * r, 0.04 * r, 0.06 * hseg],
        );
        b.cuboid_v(
            Door,
            variant,
            [x - 0.25 * r, 0.8 * y, ze + 0.12 * hseg],
            [x + 0.25 * r, 1.0 * y, ze + 0.2 * hseg],
        );
    }
    let zn = z0 + 0.45 * hseg;
    if beak {
        b.revolved(
            Door,
            variant,
            [0.0, 0.9 * y, zn + 0.05 * hseg],
            rot_x(-std::f64::consts::FRAC_PI_2 - 0.5),
            0.7,
            vec![[0.0, 0.0], [0.2 * r, 0.0], [0.0, 0.35 * r]],
        );
    } else {
        b.ellipsoid(Body, [0.0, 0.95 * y, zn], [0.18 * r, 0.15 * r, 0.12 * hseg]);
    }
    b.cuboid(
        Interior,
        [-0.35 * r, 0.93 * y, z0 + 0.15 * hseg],
        [0.35 * r, 1.0 * y, z0 + 0.25 * hseg],
    );
    b.cuboid_v(
        Door,
        variant,
        [-0.45 * r, 0.9 * y, z0 + 0.12 * hseg],
        [0.45 * r, 0.99 * y, z0 + 0.15 * hseg],
    );
}

/// A totem pole: carved faces stacked up a round pole, alternately beaked and broad-nosed, a
/// thunderbird at the top with its wings spread.
pub fn totem_pole(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The pole is as thick as the size box is deep; the wings spread across its width.
    let r = 0.8 * hd.min(0.45 * hw);
    let wings = 0.14 * h;
    let top = h - wings;
    let n = 4;
    for k in 0..n {
        let z0 = k as f64 / n as f64 * top;
        let z1 = (k as f64 + 1.0) / n as f64 * top;
        carved_face(b, r, z0, z1, k % 2 == 1, k as u32);
    }
    // The thunderbird: a head with a beak over spread wings.
    b.cylinder(Body, [0.0, 0.0, top], 0.8 * r, 0.6 * wings);
    b.revolved(
        Door,
        0,
        [0.0, 0.75 * r, top + 0.4 * wings],
        rot_x(-std::f64::consts::FRAC_PI_2 - 0.6),
        0.7,
        vec![
            [0.0, 0.0],
            [0.25 * r, 0.0],
            [0.0, (hd - 0.8 * r).max(0.1 * r)],
        ],
    );
    for sx in [-1.0, 1.0] {
        b.slab_v(
            Door,
            1,
            [sx * 0.5 * (hw + 0.6 * r), 0.0, top + 0.45 * wings],
            [0.5 * (hw - 0.6 * r), 0.04 * hd, 0.4 * wings],
            super::parts::rot_y(sx * 0.35),
        );
        for k in 0..3 {
            let x = sx * (0.8 * r + (k as f64 + 0.5) * 0.3 * (hw - 0.8 * r));
            b.cuboid(
                BlackKeys,
                [x - 0.01, 0.03 * hd, top + 0.15 * wings],
                [x + 0.01, 0.04 * hd + 0.01, top + 0.6 * wings],
            );
        }
    }
    b.ellipsoid(
        Body,
        [0.0, 0.0, h - 0.35 * wings],
        [0.6 * r, 0.6 * r, 0.35 * wings],
    );
}

/// A tree stump: a bark-covered trunk flaring into roots at its foot, a pale cut top with
/// darker growth rings and a split.
pub fn tree_stump(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.6 * hw.min(hd);
    b.revolved(
        Trunk,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        hd.min(hw) / hw.max(hd),
        vec![
            [0.0, 0.0],
            [1.2 * r, 0.0],
            [1.02 * r, 0.2 * h],
            [r, 0.9 * h],
            [0.98 * r, h - 0.02],
            [0.0, h - 0.02],
        ],
    );
    // Roots: flattened cones flaring out of the trunk's foot and running down into the
    // ground, thick where they leave the trunk and thin at their tips.
    let l = hw.min(hd) - r;
    for k in 0..7 {
        let a = k as f64 / 7.0 * TAU + 0.3;
        let (c, s) = (a.cos(), a.sin());
        let from = [0.6 * r * c, 0.6 * r * s, 0.28 * h];
        let to = [(r + 0.95 * l) * c, (r + 0.95 * l) * s, 0.0];
        let d = [0, 1, 2].map(|i| to[i] - from[i]);
        let len = d.iter().map(|v| v * v).sum::<f64>().sqrt();
        b.revolved(
            Trunk,
            0,
            from,
            frame_along(d),
            1.3,
            frustum_profile(0.42 * r, 0.08 * r, len),
        );
    }
    disc(b, Top, [0.0, 0.0, h - 0.01], Z, 0.96 * r, 0.02);
    for k in 1..5 {
        band(
            b,
            Frame,
            [0.0, 0.0, h - 0.0005],
            Z,
            k as f64 / 5.0 * 0.9 * r,
            0.015 * r,
            0.002,
        );
    }
    b.cuboid(
        Interior,
        [-0.02 * r, 0.1 * r, h - 0.0015],
        [0.02 * r, 0.85 * r, h],
    );
    // Moss on one side of the bark.
    b.ellipsoid(
        Foliage,
        [-0.75 * r, -0.6 * r, 0.35 * h],
        [0.3 * r, 0.3 * r, 0.2 * h],
    );
}
