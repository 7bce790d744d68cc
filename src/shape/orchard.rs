//! Layouts of trees that bear fruit or blossom: a fruit tree (a short trunk forking into a
//! rounded crown of leaf clumps, hung all over with fruit: red apples unless the description
//! names another colour) and a blossom tree (a dark crooked trunk with spreading limbs under a
//! wide, flattish crown of pink blossom clumps flecked with paler flowers). Round about +z.
use super::archetypes::Builder;
use super::materials::Role::{self, *};
use super::parts::rot_z;

/// One clump of a crown: its centre and radii.
struct Clump {
    c: [f64; 3],
    r: [f64; 3],
}

/// `n` clumps spread over a crown of half extents `hw`, `hd` between `z0` and `z1`, each of
/// horizontal radius `r` and vertical `rz`, drawn in `role` (the golden angle spreads them).
fn crown(b: &mut Builder, role: Role, n: usize, r: f64, rz: f64, z0: f64, z1: f64) -> Vec<Clump> {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (r, rz) = (r.min(hw.min(hd)), rz.min(h / 2.0));
    let mut out = vec![];
    for i in 0..n {
        let t = i as f64 / (n - 1).max(1) as f64;
        let a = i as f64 * 2.399_963;
        // Outer clumps low, inner ones high: a dome.
        let rho = 0.35 + 0.65 * (1.0 - t).sqrt();
        let x = (rho * a.cos() * (hw - r)).clamp(-(hw - r), hw - r);
        let y = (rho * a.sin() * (hd - r)).clamp(-(hd - r), hd - r);
        let z = (z0 + (z1 - z0) * t).clamp(rz, h - rz);
        let k = 0.85 + 0.15 * ((i * 7) % 5) as f64 / 4.0;
        let radii = [r * k, r * k * 0.95, rz * k];
        b.ellipsoid_rot(role, i as u32, [x, y, z], radii, rot_z(a));
        out.push(Clump {
            c: [x, y, z],
            r: radii,
        });
    }
    out
}

/// Small balls of `role` set into the outward faces of `clumps`, `per` on each.
fn dots(b: &mut Builder, clumps: &[Clump], role: Role, per: usize, size: f64, centre_z: f64) {
    for (i, cl) in clumps.iter().enumerate() {
        for j in 0..per {
            let a = (i * per + j) as f64 * 2.399_963 + 0.7;
            // Directions over the clump's outward half: away from the trunk, level or below.
            let out = cl.c[1].atan2(cl.c[0]);
            let phi = out + 1.3 * a.sin();
            let el = -0.4
                + 0.9
                    * ((j as f64 + 0.5) / per as f64)
                    * if cl.c[2] > centre_z { 1.0 } else { 0.6 };
            let d = [phi.cos() * el.cos(), phi.sin() * el.cos(), el.sin()];
            let p = [0, 1, 2].map(|k| cl.c[k] + 0.97 * cl.r[k] * d[k]);
            b.ellipsoid(role, p, [size, size, size]);
        }
    }
}

/// A fruit tree.
pub fn fruit_tree(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let rt = (0.07 * m).min(0.2);
    b.frustum(Trunk, [0.0, 0.0, 0.0], rt, rt, 0.8, 0.45 * h);
    for a in [0.3f64, 2.4, 4.5] {
        b.rod(
            Trunk,
            [0.0, 0.0, 0.4 * h],
            [0.4 * m * a.cos(), 0.4 * m * a.sin(), 0.62 * h],
            0.6 * rt,
        );
    }
    b.ellipsoid(
        Foliage,
        [0.0, 0.0, 0.68 * h],
        [0.7 * hw, 0.7 * hd, 0.25 * h],
    );
    let clumps = crown(b, Foliage, 14, 0.42 * m, 0.16 * h, 0.5 * h, 0.92 * h);
    dots(b, &clumps, Skin, 4, (0.045 * m).clamp(0.03, 0.09), 0.7 * h);
}

/// A blossom tree.
pub fn blossom_tree(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let rt = (0.06 * m).min(0.2);
    b.frustum(Trunk, [0.0, 0.0, 0.0], rt, rt, 0.8, 0.4 * h);
    for (k, a) in [0.2f64, 1.5, 2.8, 4.0, 5.3].into_iter().enumerate() {
        let reach = if k % 2 == 0 { 0.7 } else { 0.55 };
        let z = if k % 2 == 0 { 0.6 } else { 0.68 };
        b.polyline(
            Trunk,
            &[
                [0.0, 0.0, 0.36 * h],
                [
                    0.3 * reach * m * a.cos(),
                    0.3 * reach * m * a.sin(),
                    0.5 * h,
                ],
                [reach * m * a.cos(), reach * m * a.sin(), z * h],
            ],
            0.5 * rt,
        );
    }
    b.ellipsoid(
        Foliage,
        [0.0, 0.0, 0.72 * h],
        [0.78 * hw, 0.78 * hd, 0.18 * h],
    );
    let clumps = crown(b, Foliage, 16, 0.4 * m, 0.13 * h, 0.58 * h, 0.9 * h);
    dots(
        b,
        &clumps,
        Cushion,
        5,
        (0.05 * m).clamp(0.03, 0.1),
        0.74 * h,
    );
}
