//! Primitive parts (oriented boxes and surfaces of revolution) and their surface samplers.
//!
//! A part's surface is covered by flat surfels: stratified, jittered samples whose count follows
//! the surface area, each carrying its local frame (two tangents and the outward normal) and the
//! spacing of its neighbours, from which the Gaussian's scales are made. Pure geometry: no colour,
//! no GPU.
use super::materials::Role;
use rand::Rng;

pub use crate::util::convex_hull;

/// A point or vector in the object frame (metres).
pub type V3 = [f64; 3];
/// A rotation: its columns are the part's local axes in the object frame.
pub type M3 = [[f64; 3]; 3];

/// The identity rotation.
pub const IDENTITY: M3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Rotation by `a` radians about the object's x axis.
pub fn rot_x(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
}

/// Rotation by `a` radians about the object's y axis.
pub fn rot_y(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]
}

/// Rotation by `a` radians about the object's z axis.
pub fn rot_z(a: f64) -> M3 {
    let (s, c) = a.sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

/// `m * v`.
pub fn mul(m: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2])
}

/// `a * b`.
pub fn mat_mul(a: &M3, b: &M3) -> M3 {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn col(m: &M3, j: usize) -> V3 {
    [m[0][j], m[1][j], m[2][j]]
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: V3) -> V3 {
    let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt().max(1e-12);
    scale(a, 1.0 / l)
}

/// The shape of one part.
#[derive(Debug, Clone, PartialEq)]
pub enum Primitive {
    /// An oriented box: centre, half extents along its local axes, and its rotation.
    Cuboid { centre: V3, half: V3, rot: M3 },
    /// A surface of revolution about the local z axis through `origin`: the profile is a polyline
    /// of `(ρ, z)` points; the cross-section at a profile point is the ellipse with semi-axes
    /// `(ρ, ay·ρ)`. A closed cylinder, a cone, a disc and an ellipsoid are all profiles.
    Revolved {
        origin: V3,
        rot: M3,
        ay: f64,
        profile: Vec<[f64; 2]>,
    },
}

/// One part of an archetype: a primitive, the role that colours it, and a variant number (books
/// on a shelf take different colours by variant).
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    pub prim: Primitive,
    pub role: Role,
    pub variant: u32,
}

/// One surface sample: position, local frame (columns: tangent u, tangent v, outward normal) and
/// the sample spacing along u and v.
#[derive(Debug, Clone, Copy)]
pub struct Surfel {
    pub pos: V3,
    pub frame: M3,
    pub du: f64,
    pub dv: f64,
}

impl Surfel {
    /// The outward normal.
    pub fn normal(&self) -> V3 {
        col(&self.frame, 2)
    }
}

fn frame_of(tu: V3, tv: V3, n: V3) -> M3 {
    [
        [tu[0], tv[0], n[0]],
        [tu[1], tv[1], n[1]],
        [tu[2], tv[2], n[2]],
    ]
}

/// Jitter of a stratified sample, as a fraction of its cell: small enough that neighbours never
/// drift two cells apart (no holes), large enough to break the grid pattern.
const JITTER: f64 = 0.3;

fn jitter(rng: &mut impl Rng) -> f64 {
    0.5 + rng.gen_range(-JITTER..=JITTER)
}

/// Samples on a flat rectangle `origin + u·e1 + v·e2`, u, v in [0, 1], normal `e1 × e2`.
fn sample_rect(
    origin: V3,
    e1: V3,
    e2: V3,
    spacing: f64,
    rng: &mut impl Rng,
    out: &mut Vec<Surfel>,
) {
    let (l1, l2) = (len(e1), len(e2));
    let nu = ((l1 / spacing).round() as usize).max(1);
    let nv = ((l2 / spacing).round() as usize).max(1);
    let (tu, tv) = (norm(e1), norm(e2));
    let frame = frame_of(tu, tv, norm(cross(tu, tv)));
    for i in 0..nu {
        for j in 0..nv {
            let u = (i as f64 + jitter(rng)) / nu as f64;
            let v = (j as f64 + jitter(rng)) / nv as f64;
            out.push(Surfel {
                pos: add(origin, add(scale(e1, u), scale(e2, v))),
                frame,
                du: l1 / nu as f64,
                dv: l2 / nv as f64,
            });
        }
    }
}

fn len(a: V3) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// Approximate perimeter of the ellipse with semi-axes a, b (Ramanujan).
fn ellipse_perimeter(a: f64, b: f64) -> f64 {
    std::f64::consts::PI * (3.0 * (a + b) - ((3.0 * a + b) * (a + 3.0 * b)).sqrt())
}

impl Primitive {
    /// Surface area (approximate for surfaces of revolution with elliptic sections).
    pub fn area(&self) -> f64 {
        match self {
            Primitive::Cuboid { half: h, .. } => 8.0 * (h[0] * h[1] + h[1] * h[2] + h[0] * h[2]),
            Primitive::Revolved { ay, profile, .. } => profile
                .windows(2)
                .map(|w| {
                    let seg = ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt();
                    let r = 0.5 * (w[0][0] + w[1][0]);
                    seg * ellipse_perimeter(r, ay * r)
                })
                .sum(),
        }
    }

    /// Stratified surface samples about `spacing` apart.
    pub fn sample(&self, spacing: f64, rng: &mut impl Rng, out: &mut Vec<Surfel>) {
        match self {
            Primitive::Cuboid { centre, half, rot } => {
                let a = [0, 1, 2].map(|i| scale(col(rot, i), half[i]));
                // Each face: (normal axis, tangent u axis, tangent v axis) right-handed.
                for (n, u, v) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
                    for sign in [1.0, -1.0] {
                        let (u, v) = if sign > 0.0 { (u, v) } else { (v, u) };
                        let face = add(*centre, scale(a[n], sign));
                        let origin = add(face, scale(add(a[u], a[v]), -1.0));
                        sample_rect(
                            origin,
                            scale(a[u], 2.0),
                            scale(a[v], 2.0),
                            spacing,
                            rng,
                            out,
                        );
                    }
                }
            }
            Primitive::Revolved {
                origin,
                rot,
                ay,
                profile,
            } => sample_revolved(*origin, rot, *ay, profile, spacing, rng, out),
        }
    }

    /// Whether the primitive is a closed solid whose projection is filled (a box, or a profile
    /// that starts and ends on the axis); a ring such as a wheel's tyre is not.
    pub fn solid(&self) -> bool {
        match self {
            Primitive::Cuboid { .. } => true,
            Primitive::Revolved { profile, .. } => {
                profile.first().is_some_and(|p| p[0].abs() < 1e-9)
                    && profile.last().is_some_and(|p| p[0].abs() < 1e-9)
            }
        }
    }

    /// Corner points whose convex hull is the primitive (coarse for curved surfaces, always
    /// inside the true shape), in the object frame.
    pub fn hull_points(&self) -> Vec<V3> {
        match self {
            Primitive::Cuboid { centre, half, rot } => {
                let mut pts = vec![];
                for sx in [-1.0, 1.0] {
                    for sy in [-1.0, 1.0] {
                        for sz in [-1.0, 1.0] {
                            let l = [sx * half[0], sy * half[1], sz * half[2]];
                            pts.push(add(*centre, mul(rot, l)));
                        }
                    }
                }
                pts
            }
            Primitive::Revolved {
                origin,
                rot,
                ay,
                profile,
            } => {
                let mut pts = vec![];
                for p in profile {
                    for k in 0..32 {
                        let t = k as f64 / 32.0 * std::f64::consts::TAU;
                        let l = [p[0] * t.cos(), ay * p[0] * t.sin(), p[1]];
                        pts.push(add(*origin, mul(rot, l)));
                    }
                }
                pts
            }
        }
    }
}

#[allow(
    clippy::too_many_arguments,
    reason = "the revolved surface is named by its parameters; a struct would only rename them"
)]
fn sample_revolved(
    origin: V3,
    rot: &M3,
    ay: f64,
    profile: &[[f64; 2]],
    spacing: f64,
    rng: &mut impl Rng,
    out: &mut Vec<Surfel>,
) {
    let seg_len: Vec<f64> = profile
        .windows(2)
        .map(|w| ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt())
        .collect();
    let total: f64 = seg_len.iter().sum();
    if total <= 0.0 {
        return;
    }
    let rows = ((total / spacing).round() as usize).max(1);
    let dv = total / rows as f64;
    for k in 0..rows {
        // Arc length along the profile at the row's centre picks the segment and its point.
        let row_centre = (k as f64 + 0.5) * dv;
        let mut s = row_centre;
        let mut seg = 0;
        while seg + 1 < seg_len.len() && s > seg_len[seg] {
            s -= seg_len[seg];
            seg += 1;
        }
        let (a, b) = (profile[seg], profile[seg + 1]);
        let l = seg_len[seg].max(1e-12);
        let rho_mid = a[0] + (b[0] - a[0]) * (s / l).clamp(0.0, 1.0);
        let circ = ellipse_perimeter(rho_mid, ay * rho_mid);
        let count = ((circ / spacing).round() as usize).max(1);
        let offset: f64 = rng.gen_range(0.0..1.0);
        let (dr, dz) = ((b[0] - a[0]) / l, (b[1] - a[1]) / l);
        for j in 0..count {
            let t = ((s + (jitter(rng) - 0.5) * dv) / l).clamp(0.0, 1.0);
            let rho = a[0] + (b[0] - a[0]) * t;
            let z = a[1] + (b[1] - a[1]) * t;
            let th = (j as f64 + offset + jitter(rng) - 0.5) / count as f64 * std::f64::consts::TAU;
            let (sn, cs) = th.sin_cos();
            let local = [rho * cs, ay * rho * sn, z];
            // d/dθ and the outward normal (θ-tangent × profile tangent, divided by ρ).
            let d_th = [-rho * sn, ay * rho * cs, 0.0];
            let n_local = norm([ay * cs * dz, sn * dz, -ay * dr]);
            let tu_local = norm([-sn, ay * cs, 0.0]);
            let tv_local = cross(n_local, tu_local);
            let du = (len(d_th) * std::f64::consts::TAU / count as f64).max(0.3 * spacing);
            out.push(Surfel {
                pos: add(origin, mul(rot, local)),
                frame: frame_of(mul(rot, tu_local), mul(rot, tv_local), mul(rot, n_local)),
                du: du.min(3.0 * spacing),
                dv,
            });
        }
    }
}

/// A closed frustum about local z: bottom radius `r0`, top radius `r1`, height `h`.
pub fn frustum_profile(r0: f64, r1: f64, h: f64) -> Vec<[f64; 2]> {
    let mut p = vec![[0.0, 0.0], [r0, 0.0], [r1, h]];
    if r1 > 0.0 {
        p.push([0.0, h]);
    }
    p
}

/// A full ellipsoid profile with equatorial radius `r` and half height `rz`, centred at z = 0.
pub fn ellipsoid_profile(r: f64, rz: f64) -> Vec<[f64; 2]> {
    let n = 24;
    (0..=n)
        .map(|i| {
            let phi = i as f64 / n as f64 * std::f64::consts::PI;
            [r * phi.sin(), -rz * phi.cos()]
        })
        .collect()
}

/// Whether `p` lies inside the counter-clockwise convex polygon `hull`.
pub fn hull_contains(hull: &[[f64; 2]], p: [f64; 2]) -> bool {
    if hull.len() < 3 {
        return false;
    }
    (0..hull.len()).all(|i| {
        let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
        (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0.0
    })
}

/// Quaternion (w, x, y, z) of a rotation matrix.
pub fn quaternion(m: &M3) -> [f64; 4] {
    let tr = m[0][0] + m[1][1] + m[2][2];
    let q = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        [
            0.25 * s,
            (m[2][1] - m[1][2]) / s,
            (m[0][2] - m[2][0]) / s,
            (m[1][0] - m[0][1]) / s,
        ]
    } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
        let s = (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt() * 2.0;
        [
            (m[2][1] - m[1][2]) / s,
            0.25 * s,
            (m[0][1] + m[1][0]) / s,
            (m[0][2] + m[2][0]) / s,
        ]
    } else if m[1][1] > m[2][2] {
        let s = (1.0 + m[1][1] - m[0][0] - m[2][2]).sqrt() * 2.0;
        [
            (m[0][2] - m[2][0]) / s,
            (m[0][1] + m[1][0]) / s,
            0.25 * s,
            (m[1][2] + m[2][1]) / s,
        ]
    } else {
        let s = (1.0 + m[2][2] - m[0][0] - m[1][1]).sqrt() * 2.0;
        [
            (m[1][0] - m[0][1]) / s,
            (m[0][2] + m[2][0]) / s,
            (m[1][2] + m[2][1]) / s,
            0.25 * s,
        ]
    };
    let l = q.iter().map(|v| v * v).sum::<f64>().sqrt().max(1e-12);
    q.map(|v| v / l)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn quaternion_round_trips_rotations() {
        let m = mat_mul(&rot_z(0.7), &rot_x(-1.2));
        let [w, x, y, z] = quaternion(&m);
        // Rotation matrix of the quaternion.
        let r = [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ];
        for i in 0..3 {
            for j in 0..3 {
                assert!((r[i][j] - m[i][j]).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn samples_follow_area_and_point_outward() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let prims = [
            Primitive::Cuboid {
                centre: [0.0, 0.0, 1.0],
                half: [0.5, 0.3, 0.2],
                rot: rot_z(0.4),
            },
            Primitive::Revolved {
                origin: [0.0, 0.0, 1.0],
                rot: IDENTITY,
                ay: 0.6,
                profile: ellipsoid_profile(0.5, 0.3),
            },
            Primitive::Revolved {
                origin: [0.0, 0.0, 0.8],
                rot: IDENTITY,
                ay: 1.0,
                profile: frustum_profile(0.4, 0.2, 0.4),
            },
        ];
        for p in prims {
            let mut s = vec![];
            let spacing = 0.01;
            p.sample(spacing, &mut rng, &mut s);
            let expect = p.area() / (spacing * spacing);
            let n = s.len() as f64;
            assert!(
                (n / expect - 1.0).abs() < 0.1,
                "{n} samples, {expect} expected"
            );
            for x in &s {
                let c = [0.0, 0.0, 1.0];
                let out = [x.pos[0] - c[0], x.pos[1] - c[1], x.pos[2] - c[2]];
                let nn = x.normal();
                assert!(out[0] * nn[0] + out[1] * nn[1] + out[2] * nn[2] > -1e-9);
            }
        }
    }

    #[test]
    fn hull_contains_its_interior_only() {
        let h = convex_hull(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]]);
        assert_eq!(h.len(), 4);
        assert!(hull_contains(&h, [0.2, 0.7]));
        assert!(!hull_contains(&h, [1.2, 0.7]));
    }
}
