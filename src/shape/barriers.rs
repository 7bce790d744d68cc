//! Layouts of barriers and heaps that are not fences: a dry stone wall, rope stanchions and a
//! round haystack. The front faces +y, z up, the bottom face's centre at the origin.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A dry stone wall: courses of stones of two tones in staggered joints over a dark core, under
/// a row of cap stones.
pub fn stone_wall(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let gap = (0.02 * h).clamp(0.01, 0.02);
    b.cuboid(
        Interior,
        [-hw + gap, -hd + gap, 0.0],
        [hw - gap, hd - gap, h - gap],
    );
    let courses = ((h / 0.22).round() as usize).max(2);
    let ch = h / courses as f64;
    let stone = (2.0 * ch).max(0.2);
    for k in 0..courses {
        let (z0, z1) = (k as f64 * ch, (k + 1) as f64 * ch - gap);
        let cap = k + 1 == courses;
        // Stagger the joints by half a stone on every other course.
        let mut x = -hw - if k % 2 == 1 { 0.5 * stone } else { 0.0 };
        let mut i = k;
        while x < hw {
            let (x0, x1) = (x.max(-hw), (x + stone - gap).min(hw));
            let role = if cap || i % 3 == 0 { Top } else { Body };
            if x1 > x0 + gap {
                b.cuboid(role, [x0, -hd, z0], [x1, hd, z1]);
            }
            x += stone;
            i += 1;
        }
    }
}

/// Rope stanchions: posts on round bases along the width, a sagging rope between each pair.
pub fn stanchions(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let base = (0.8 * hd).min(0.16);
    let n = ((b.w / 1.5).round() as usize).max(1) + 1;
    let w = b.w;
    let x = |i: usize| -hw + base + i as f64 * (w - 2.0 * base) / (n - 1) as f64;
    let top = h - 0.04;
    for i in 0..n {
        b.frustum(Metal, [x(i), 0.0, 0.0], base, base, 0.7, 0.03);
        b.cylinder(Metal, [x(i), 0.0, 0.03], 0.025, top - 0.03);
        b.ellipsoid(Metal, [x(i), 0.0, top + 0.02], [0.04, 0.04, 0.02]);
    }
    let sag = 0.15 * h;
    let r = 0.02;
    for i in 0..n - 1 {
        let (a, c) = (x(i), x(i + 1));
        let pt = |t: f64| [a + t * (c - a), 0.0, top - 0.05 - sag * 4.0 * t * (1.0 - t)];
        let m = 8;
        for k in 0..m {
            let (t0, t1) = (k as f64 / m as f64, (k + 1) as f64 / m as f64);
            b.rod(Upholstery, pt(t0), pt(t1), r);
        }
    }
}

/// A round haystack: a dome of hay, fuller than a cone, on a slightly wider foot.
pub fn haystack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let profile: Vec<[f64; 2]> = (0..=16)
        .map(|k| {
            let t = k as f64 / 16.0;
            // Radius falls from the foot to the crown like a dome drawn up to a point.
            [hw * (1.0 - t.powf(1.6)).max(0.0).sqrt(), t * h]
        })
        .chain(std::iter::once([0.0, h]))
        .collect();
    let mut p = vec![[0.0, 0.0]];
    p.extend(profile);
    b.revolved(Body, 0, [0.0, 0.0, 0.0], super::parts::IDENTITY, hd / hw, p);
    b.frustum(Top, [0.0, 0.0, 0.0], hw, hd, 0.92, 0.12 * h);
}
