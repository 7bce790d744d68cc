//! Furniture for pets, drawn for what the animal does with it: a dog bed (a padded base inside a
//! plump bolster, lower at the front where the dog steps in) and a cat tree (sisal-wrapped posts
//! on a carpeted base, a cubby with a round door, platforms at several heights and a perch with a
//! rim on top, a toy hanging from a string). The front is +y.
use super::archetypes::Builder;
use super::fittings::{disc, Y};
use super::materials::Role::*;
use std::f64::consts::TAU;

/// A dog bed: a flat cushion inside a bolster that runs round its rim, dipping at the front.
pub fn dog_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.5 * h).min(0.3 * hw.min(hd));
    // The base: an oval pad the dog lies on.
    b.revolved(
        Upholstery,
        0,
        [0.0, 0.0, 0.0],
        super::parts::IDENTITY,
        hd / hw,
        vec![
            [0.0, 0.0],
            [hw - 0.3 * r, 0.0],
            [hw - 0.3 * r, 0.35 * h],
            [0.0, 0.35 * h],
        ],
    );
    b.ellipsoid(
        Cushion,
        [0.0, 0.0, 0.35 * h],
        [hw - 1.6 * r, hd - 1.6 * r, 0.12 * h],
    );
    // The bolster: a tube round the rim, its centre high at the back and sides, low at the front.
    let n = 40;
    let pts: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            let (s, c) = a.sin_cos();
            // s = 1 at the front (+y): the bolster sinks there to an entrance.
            let dip = ((s - 0.1) / 0.7).clamp(0.0, 1.0);
            let z = (h - r) * (1.0 - 0.65 * dip) + 0.02 * h;
            [c * (hw - r), s * (hd - r), z.max(r * 0.6)]
        })
        .collect();
    b.polyline(Upholstery, &pts, r);
}

/// A cat tree: a carpeted base, sisal posts carrying a cubby, platforms and a rimmed perch.
pub fn cat_tree(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.03 * h.max(1.0);
    let post = (0.08 * hw.min(hd)).max(0.035);
    b.cuboid(Upholstery, [-hw, -hd, 0.0], [hw, hd, t]);
    // The cubby: a carpeted box on one side, a round door to the front.
    let (cx0, cx1) = (-hw, 0.1 * hw);
    let cz = 0.3 * h;
    b.cuboid(Upholstery, [cx0, -hd, t], [cx1, 0.2 * hd, cz]);
    disc(
        b,
        Interior,
        [0.5 * (cx0 + cx1), 0.2 * hd + 0.004, 0.5 * (t + cz)],
        Y,
        0.32 * (cx1 - cx0).min(cz - t),
        0.006,
    );
    // Sisal posts: one from the floor to the top perch, one to the middle platform, one short
    // scratching post at the front corner.
    let tall = [0.55 * hw, -0.45 * hd];
    b.cylinder(Frame, [tall[0], tall[1], t], post, h - 0.12 * h - t);
    b.cylinder(Frame, [-0.5 * hw, -0.5 * hd, cz], post, 0.58 * h - cz);
    b.cylinder(Frame, [0.6 * hw, 0.55 * hd, t], post, 0.28 * h);
    // Platforms: one over the short post, one mid-height, the perch on top with a raised rim.
    let pad = |b: &mut Builder, x: f64, y: f64, r: f64, z: f64| {
        b.revolved(
            Upholstery,
            0,
            [x, y, z],
            super::parts::IDENTITY,
            1.0,
            vec![[0.0, 0.0], [r, 0.0], [r, t], [0.0, t]],
        );
    };
    pad(b, 0.6 * hw, 0.55 * hd, 0.42 * hw.min(hd), 0.28 * h + t);
    b.cuboid(
        Upholstery,
        [-hw, -hd, 0.58 * h],
        [0.2 * hw, 0.3 * hd, 0.58 * h + t],
    );
    let pr = 0.55 * hw.min(hd);
    let (px, py, pz) = (0.4 * hw, -0.3 * hd, h - 0.12 * h);
    b.revolved(
        Upholstery,
        0,
        [px, py, pz],
        super::parts::IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [pr, 0.0],
            [pr, 0.12 * h],
            [0.82 * pr, 0.12 * h],
            [0.82 * pr, 0.04 * h],
            [0.0, 0.04 * h],
        ],
    );
    // A toy ball on a string under the middle platform's front edge.
    let (tx, ty) = (-0.3 * hw, 0.27 * hd);
    let top = 0.58 * h;
    let ball = 0.035f64.min(0.3 * hd);
    b.rod(Metal, [tx, ty, top], [tx, ty, top - 0.16 * h], 0.003);
    b.ellipsoid(Handle, [tx, ty, top - 0.16 * h - ball], [ball; 3]);
    // Sisal rope bands on the tall post, a little darker than the post.
    let bands = 6;
    for i in 0..bands {
        let z = t + (i as f64 + 0.5) * (h - 0.12 * h - t) / bands as f64;
        b.cylinder(Trunk, [tall[0], tall[1], z], 1.04 * post, 0.01);
    }
}
