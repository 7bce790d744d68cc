//! Placing object clouds in the world: `world = Rz(yaw) · diag(scale) · p + position` (yaw in
//! degrees, counter-clockwise about +z), applied exactly to every Gaussian, and merging instances
//! into one cloud. Host-only, f64 inside.
//!
//! Means map through the affine transform. Covariances map exactly, `Σ' = M Σ Mᵀ` with
//! `M = Rz · S`: for a uniform positive scale this is a quaternion product and a log-scale shift;
//! otherwise `Σ'` is refitted to a rotation and three scales by a symmetric eigendecomposition,
//! which is exact for any scale (non-uniform or mirrored).
//!
//! View-dependent colour: an SH expansion follows the orthogonal part of `M`,
//! `O = Rz · diag(sign(scale))` (for positive scales just `Rz`), rotated exactly by
//! [`super::sh_rotate`]. With a uniform scale that is the exact view-direction map. With a
//! non-uniform scale the object-frame direction of a world direction `d` is `normalize(M⁻¹ d)`,
//! which is not an orthogonal map, and no degree-3 expansion reproduces it in general; `O` is the
//! nearest orthogonal map and leaves view-independent (degree 0) colour exact.
use super::sh_rotate::{Mat3, ShRotation};
use crate::splat::cloud::sh_coeffs;
use crate::splat::reference::quat_to_mat;
use crate::splat::Gaussians;
use rayon::prelude::*;

/// Where an instance goes: `world = Rz(yaw) · diag(scale) · p + position`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Degrees, counter-clockwise about +z.
    pub yaw: f64,
    pub scale: [f64; 3],
    pub position: [f64; 3],
}

impl Placement {
    /// No change.
    pub const IDENTITY: Placement = Placement {
        yaw: 0.0,
        scale: [1.0; 3],
        position: [0.0; 3],
    };

    /// The linear part `M = Rz(yaw) · diag(scale)`.
    pub fn linear(&self) -> Mat3 {
        let r = rz(self.yaw);
        [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[i][j] * self.scale[j]))
    }
}

/// Rotation by `yaw_deg` degrees counter-clockwise about +z.
pub fn rz(yaw_deg: f64) -> Mat3 {
    let (s, c) = yaw_deg.to_radians().sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

/// Applies `world = Rz(yaw_deg) · diag(scale) · p + position` to every Gaussian of `g` (see the
/// module notes for covariances and SH). Gaussians with a zero or non-finite quaternion (which
/// the renderer culls) keep their rotation and scales; their means still move. Output
/// quaternions are unit length with w >= 0. A zero scale component gives degenerate Gaussians
/// (log-scale about -345). `g` must pass [`Gaussians::check`] (array lengths agree); the work is
/// spread over threads.
pub fn transform(g: &Gaussians, yaw_deg: f64, scale: [f64; 3], position: [f64; 3]) -> Gaussians {
    let p = Placement {
        yaw: yaw_deg,
        scale,
        position,
    };
    let m = p.linear();
    let r = rz(yaw_deg);
    let uniform = scale[0] > 0.0 && scale[0] == scale[1] && scale[1] == scale[2];
    let orth: Mat3 = [0, 1, 2].map(|i| [0, 1, 2].map(|j| r[i][j] * sign(scale[j])));
    let shr = (g.sh_degree > 0).then(|| ShRotation::new(&orth, g.sh_degree));
    let half = 0.5 * yaw_deg.to_radians();
    let qz = [half.cos(), 0.0, 0.0, half.sin()];
    let k = g.coeffs() * 3;

    let one = |i: usize| {
        let x = g.means[i].map(f64::from);
        let mean = [0, 1, 2]
            .map(|a| (m[a][0] * x[0] + m[a][1] * x[1] + m[a][2] * x[2] + position[a]) as f32);
        let q = g.rotations[i].map(f64::from);
        let Some(rot) = quat_to_mat(q) else {
            return (mean, g.rotations[i], g.scales[i]);
        };
        let s = g.scales[i].map(f64::from);
        if uniform {
            let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
            let q = canonical(quat_mul(qz, q.map(|v| v / n)));
            (
                mean,
                q.map(|v| v as f32),
                s.map(|v| (v + scale[0].ln()) as f32),
            )
        } else {
            let sigma = covariance_of(&rot, s.map(f64::exp));
            let (lam, vecs) = sym_eigen(&mul(&mul(&m, &sigma), &transpose(&m)));
            // Clamp: a zero scale component leaves a zero eigenvalue (or a rounding-negative one).
            let scales = lam.map(|l| (0.5 * l.max(1e-300).ln()) as f32);
            (mean, mat_to_quat(&vecs).map(|v| v as f32), scales)
        }
    };
    let placed: Vec<([f32; 3], [f32; 4], [f32; 3])> =
        (0..g.len()).into_par_iter().map(one).collect();
    let mut out = g.clone();
    for (i, (mean, rot, s)) in placed.into_iter().enumerate() {
        out.means[i] = mean;
        out.rotations[i] = rot;
        out.scales[i] = s;
    }
    if let Some(shr) = &shr {
        out.sh.par_chunks_mut(k).for_each(|c| shr.apply_rgb(c));
    }
    out
}

/// [`transform`] with a [`Placement`].
pub fn place(g: &Gaussians, p: &Placement) -> Gaussians {
    transform(g, p.yaw, p.scale, p.position)
}

/// Merges instances into one cloud, in order; all are padded to the highest SH degree among them.
pub fn compose(parts: &[(&Gaussians, Placement)]) -> Gaussians {
    let placed: Vec<Gaussians> = parts.iter().map(|(g, p)| place(g, p)).collect();
    merge(&placed)
}

/// Concatenates clouds, padding SH to the highest degree among them.
pub fn merge(clouds: &[Gaussians]) -> Gaussians {
    let degree = clouds.iter().map(|g| g.sh_degree).max().unwrap_or(0);
    let mut out = Gaussians {
        sh_degree: degree,
        ..Default::default()
    };
    for g in clouds {
        let g = pad_sh(g, degree);
        out.means.extend(&g.means);
        out.scales.extend(&g.scales);
        out.rotations.extend(&g.rotations);
        out.opacities.extend(&g.opacities);
        out.sh.extend(&g.sh);
    }
    out
}

/// `g` at SH degree `degree` (at most 3): higher bands added as zeros, which leaves colours
/// unchanged; a degree below the cloud's drops its higher bands.
pub fn pad_sh(g: &Gaussians, degree: u32) -> Gaussians {
    let degree = degree.min(3);
    if degree == g.sh_degree {
        return g.clone();
    }
    let (from, to) = (g.coeffs() * 3, sh_coeffs(degree) * 3);
    let mut sh = Vec::with_capacity(g.len() * to);
    for block in g.sh.chunks_exact(from) {
        sh.extend(block.iter().take(to));
        sh.extend(std::iter::repeat_n(0.0, to.saturating_sub(from)));
    }
    Gaussians {
        sh,
        sh_degree: degree,
        ..g.clone()
    }
}

/// Covariance `Σ = R diag(s²) Rᵀ` of Gaussian `i` (scales activated), or `None` for a zero or
/// non-finite quaternion.
pub fn covariance(g: &Gaussians, i: usize) -> Option<Mat3> {
    let rot = quat_to_mat(g.rotations[i].map(f64::from))?;
    Some(covariance_of(&rot, g.scales[i].map(|v| (v as f64).exp())))
}

fn covariance_of(rot: &Mat3, s: [f64; 3]) -> Mat3 {
    [0, 1, 2].map(|a| [0, 1, 2].map(|b| (0..3).map(|c| rot[a][c] * s[c] * s[c] * rot[b][c]).sum()))
}

/// Eigenvalues and eigenvectors (the columns of a proper rotation) of symmetric `a`, by cyclic
/// Jacobi rotations in f64.
pub fn sym_eigen(a: &Mat3) -> ([f64; 3], Mat3) {
    let mut a = *a;
    let mut v: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let scale = a.iter().flatten().map(|x| x.abs()).fold(0.0, f64::max);
    for _sweep in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        // NaN input stops at once (and comes out NaN).
        if off.is_nan() || off <= 1e-22 * scale {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            // The rotation that zeroes a[p][q] (Golub & Van Loan's symmetric Schur step).
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for row in a.iter_mut() {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (rp, rq) = (a[p], a[q]);
            a[p] = [0, 1, 2].map(|k| c * rp[k] - s * rq[k]);
            a[q] = [0, 1, 2].map(|k| s * rp[k] + c * rq[k]);
            for row in v.iter_mut() {
                let (vp, vq) = (row[p], row[q]);
                row[p] = c * vp - s * vq;
                row[q] = s * vp + c * vq;
            }
            // Zero by construction; rounding would otherwise leave ~1e-16 behind.
            a[p][q] = 0.0;
            a[q][p] = 0.0;
        }
    }
    if det(&v) < 0.0 {
        for row in v.iter_mut() {
            row[2] = -row[2];
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

/// Unit quaternion (w, x, y, z), w >= 0, of proper rotation matrix `r` (Shepperd's method).
pub fn mat_to_quat(r: &Mat3) -> [f64; 4] {
    let tr = r[0][0] + r[1][1] + r[2][2];
    let q = if tr > 0.0 {
        let s = 2.0 * (tr + 1.0).sqrt();
        [
            0.25 * s,
            (r[2][1] - r[1][2]) / s,
            (r[0][2] - r[2][0]) / s,
            (r[1][0] - r[0][1]) / s,
        ]
    } else if r[0][0] > r[1][1] && r[0][0] > r[2][2] {
        let s = 2.0 * (1.0 + r[0][0] - r[1][1] - r[2][2]).sqrt();
        [
            (r[2][1] - r[1][2]) / s,
            0.25 * s,
            (r[0][1] + r[1][0]) / s,
            (r[0][2] + r[2][0]) / s,
        ]
    } else if r[1][1] > r[2][2] {
        let s = 2.0 * (1.0 + r[1][1] - r[0][0] - r[2][2]).sqrt();
        [
            (r[0][2] - r[2][0]) / s,
            (r[0][1] + r[1][0]) / s,
            0.25 * s,
            (r[1][2] + r[2][1]) / s,
        ]
    } else {
        let s = 2.0 * (1.0 + r[2][2] - r[0][0] - r[1][1]).sqrt();
        [
            (r[1][0] - r[0][1]) / s,
            (r[0][2] + r[2][0]) / s,
            (r[1][2] + r[2][1]) / s,
            0.25 * s,
        ]
    };
    let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    canonical(q.map(|v| v / n))
}

/// Hamilton product `a ⊗ b` of (w, x, y, z) quaternions: rotate by `b`, then by `a`.
fn quat_mul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

fn canonical(q: [f64; 4]) -> [f64; 4] {
    if q[0] < 0.0 {
        q.map(|v| -v)
    } else {
        q
    }
}

fn sign(x: f64) -> f64 {
    if x < 0.0 {
        -1.0
    } else {
        1.0
    }
}

fn mul(a: &Mat3, b: &Mat3) -> Mat3 {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn transpose(a: &Mat3) -> Mat3 {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| a[j][i]))
}

fn det(a: &Mat3) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_refit_reproduces_the_matrix() {
        let a: Mat3 = [[4.0, 1.0, -2.0], [1.0, 3.0, 0.5], [-2.0, 0.5, 1.0]];
        let (l, v) = sym_eigen(&a);
        assert!((det(&v) - 1.0).abs() < 1e-12);
        let back = mul(
            &mul(
                &v,
                &[0, 1, 2].map(|i| [0, 1, 2].map(|j| if i == j { l[i] } else { 0.0 })),
            ),
            &transpose(&v),
        );
        for i in 0..3 {
            for j in 0..3 {
                assert!((back[i][j] - a[i][j]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn quaternion_round_trips_through_every_branch() {
        // Identity, and half turns about x, y, z (trace -1: the three non-trace branches).
        for q in [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
            [0.3, -0.5, 0.7, 0.2],
        ] {
            let r = quat_to_mat(q).expect("non-zero");
            let back = quat_to_mat(mat_to_quat(&r)).expect("unit");
            for i in 0..3 {
                for j in 0..3 {
                    assert!((back[i][j] - r[i][j]).abs() < 1e-12);
                }
            }
        }
    }
}
