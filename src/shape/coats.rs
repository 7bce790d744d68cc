//! An animal's coat pattern in the `marks` colour ([`Role::Top`]) over the body `beasts.rs`
//! drew: a zebra's stripes (bands round body, neck and legs), a cow's patches, a giraffe's
//! spots (thin plates lying on the surface). Deterministic; it draws nothing for plain coats.
use super::animals::{Animal, Pattern};
use super::archetypes::{frame_along, Builder};
use super::beasts::Plan;
use super::goods::Draws;
use super::materials::Role::Top;
use super::parts::V3;

/// Draws `a`'s pattern over the body laid out by `plan`.
pub fn pattern(b: &mut Builder, a: &Animal, plan: &Plan) {
    let Some(p) = a.pattern else { return };
    let (yc, zc, [ra, ry, rz]) = plan.body;
    match p {
        Pattern::Stripes => {
            let n = 11;
            for k in 0..n {
                let t = -0.9 + 1.8 * (k as f64 + 0.5) / n as f64;
                let s = (1.0 - t * t).sqrt();
                let c = [0.0, yc + ry * t, zc];
                b.ellipsoid(Top, c, [1.02 * ra * s, 0.06 * ry, 1.02 * rz * s]);
            }
            if let Some((p0, p1, r0, r1)) = plan.neck {
                for k in 1..6 {
                    let t = k as f64 / 6.0;
                    let r = 1.06 * (r0 + t * (r1 - r0));
                    let c = lerp(p0, p1, t);
                    let rot = frame_along(sub(p1, p0));
                    b.ellipsoid_rot(Top, 0, c, [r, r, 0.03 * len(sub(p1, p0))], rot);
                }
            }
            let (feet, lr) = &plan.legs;
            for f in feet {
                for k in 1..5 {
                    let z = plan.leg_top * (0.15 + 0.2 * k as f64);
                    let r = 0.85 * lr * (1.0 + 0.35 * z / plan.leg_top) * 1.08;
                    b.ellipsoid(Top, [f[0], f[1], z], [r, r, 0.04 * plan.leg_top]);
                }
            }
        }
        Pattern::Patches | Pattern::Spots => {
            let (n, size) = if p == Pattern::Patches {
                (12, 0.38)
            } else {
                (46, 0.13)
            };
            let mut dr = Draws::new(0x9e37_79b9_7f4a_7c15);
            for _ in 0..n {
                let t = -0.85 + 1.7 * dr.next();
                let u = std::f64::consts::PI * (-0.15 + 1.3 * dr.next());
                let s = (1.0 - t * t).sqrt();
                let dir = [s * u.cos(), t, s * u.sin()];
                let pos = [ra * dir[0], yc + ry * dir[1], zc + rz * dir[2]];
                let normal = [dir[0] / ra, dir[1] / ry, dir[2] / rz];
                let pr = size * rz.min(ra) * (0.7 + 0.6 * dr.next());
                let rot = frame_along(normal);
                b.ellipsoid_rot(Top, 0, pos, [pr, 1.3 * pr, 0.12 * pr], rot);
            }
            if let (Some((p0, p1, r0, r1)), Pattern::Spots) = (plan.neck, p) {
                let axis = frame_along(sub(p1, p0));
                for _ in 0..26 {
                    let t = 0.05 + 0.85 * dr.next();
                    let u = std::f64::consts::TAU * dr.next();
                    let r = r0 + t * (r1 - r0);
                    let n = [0, 1, 2].map(|i| axis[i][0] * u.cos() + axis[i][1] * u.sin());
                    let pos = [0, 1, 2].map(|i| p0[i] + t * (p1[i] - p0[i]) + r * n[i]);
                    let pr = 0.45 * r * (0.7 + 0.5 * dr.next());
                    b.ellipsoid_rot(Top, 0, pos, [pr, 1.2 * pr, 0.12 * pr], frame_along(n));
                }
            }
        }
    }
}

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn lerp(a: V3, b: V3, t: f64) -> V3 {
    [0, 1, 2].map(|i| a[i] + t * (b[i] - a[i]))
}

fn len(a: V3) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}
