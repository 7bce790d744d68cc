//! A florist's flower bucket stand: three tiers stepping up to the back on two side frames, each
//! tier holding a row of zinc buckets with a bunch of stems and blooms in every one (the bloom
//! colours are the goods palette's), and a single flower bucket: a zinc pail, wider at its rim,
//! with green stems fanning out of it under a mound of blooms. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A flower bucket stand (see the module docs).
pub fn flower_bucket_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tiers = 3;
    let bucket = (0.2 * h).min(0.25);
    let bloom = (0.12 * h).min(0.15);
    let depth = b.d / tiers as f64;
    let rb = (0.35 * depth).min(0.12);
    let n = ((b.w / (2.6 * rb)) as usize).max(2);
    let s = 0.03;
    // The side frames: a sloped rail from the front foot up to the back post.
    let top = h - bucket - bloom;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - s / 2.0);
        b.rod(Frame, [x, hd - s, 0.0], [x, -hd + s, top], s / 2.0);
        b.cuboid(Frame, [x - s / 2.0, -hd, 0.0], [x + s / 2.0, -hd + s, top]);
        b.cuboid(Frame, [x - s / 2.0, -hd, 0.0], [x + s / 2.0, hd, s]);
    }
    for k in 0..tiers {
        let yc = hd - (k as f64 + 0.5) * depth;
        let z = top * (k as f64 + 1.0) / tiers as f64;
        b.cuboid(
            Top,
            [-hw, yc - 0.45 * depth, z - 0.02],
            [hw, yc + 0.45 * depth, z],
        );
        b.cuboid(
            Frame,
            [-hw + s, yc - 0.02, 0.0],
            [-hw + s + 0.02, yc, z - 0.02],
        );
        b.cuboid(
            Frame,
            [hw - s - 0.02, yc - 0.02, 0.0],
            [hw - s, yc, z - 0.02],
        );
        for i in 0..n {
            let x = -hw + (i as f64 + 0.5) / n as f64 * b.w;
            b.frustum(Metal, [x, yc, z], rb, rb, 1.25, bucket);
            let v = BLOOMS[(i + 2 * k) % BLOOMS.len()];
            bunch(
                b,
                [x, yc, z + bucket],
                rb,
                bloom,
                (i + 2 * k) as f64,
                &[v; 5],
            );
        }
    }
}

/// A flower bucket: a zinc pail filling the lower half, a bunch of stems fanning out of it to
/// a mound of leaves and blooms as wide as the box.
pub fn flower_bucket(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let zb = 0.5 * h;
    b.frustum(
        Metal,
        [0.0, 0.0, 0.0],
        0.75 * m,
        0.75 * m * hd / hw,
        1.0 / 0.75,
        zb,
    );
    b.cylinder(Interior, [0.0, 0.0, zb], 0.93 * m, 0.01);
    // Stems from inside the rim out to the bunch's edge.
    let zt = h - 0.6 * m;
    for j in 0..9 {
        let a = j as f64 * std::f64::consts::TAU / 9.0;
        let (c, s) = (a.cos(), a.sin());
        b.rod(
            Foliage,
            [0.3 * m * c, 0.3 * m * s, zb - 0.05],
            [0.85 * m * c, 0.85 * m * s, zt],
            (0.012 * h).clamp(0.004, 0.01),
        );
    }
    bunch(b, [0.0, 0.0, zt], 0.85 * m, 2.0 * (h - zt), 0.0, &BLOOMS);
}

/// Bloom colours (variants of the goods palette) a bunch takes them from.
const BLOOMS: [u32; 6] = [0, 1, 5, 6, 8, 4];

/// A bunch of blooms over a mound of leaves, its base at `at`, `rb` across and `bloom` high:
/// one bloom of each of `colours` in a ring turned by `turn`.
fn bunch(b: &mut Builder, at: [f64; 3], rb: f64, bloom: f64, turn: f64, colours: &[u32]) {
    let [x, yc, zt] = at;
    b.ellipsoid(Foliage, [x, yc, zt], [1.1 * rb, 1.1 * rb, 0.5 * bloom]);
    let n = colours.len();
    for (j, v) in colours.iter().enumerate() {
        let a = j as f64 * std::f64::consts::TAU / n as f64 + turn;
        let (dx, dy) = (0.6 * rb * a.cos(), 0.6 * rb * a.sin());
        let r = 0.45 * bloom.min(rb) * (5.0 / n.max(5) as f64).sqrt();
        b.push(
            Books,
            *v,
            super::parts::Primitive::Revolved {
                origin: [x + dx, yc + dy, zt + 0.5 * bloom - r],
                rot: super::parts::IDENTITY,
                ay: 1.0,
                profile: super::parts::ellipsoid_profile(r, r),
            },
        );
    }
}
