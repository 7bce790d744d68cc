//! Exact rotation of real spherical-harmonic colour coefficients (bands 1 to 3) in the INRIA
//! 3DGS basis, ordering and signs, as evaluated by [`crate::splat::reference::sh_basis`].
//!
//! For an orthogonal 3x3 matrix `R` (a rotation, or a rotation with reflections) and
//! coefficients `c`, the rotated coefficients `c'` satisfy `eval(c', R d) = eval(c, d)` for every
//! unit direction `d`. Each band `l` spans a space of functions that any orthogonal map of the
//! sphere keeps, so `c'_l = M_l c_l` for one `(2l+1) x (2l+1)` matrix per band. It is built
//! without angle formulas: at a fixed set of well-spread directions `e_k`, `eval(c', e_k)` must
//! equal `eval(c, Rᵀ e_k)`, a linear system in `M_l` solved by least squares in f64 (exact up to
//! rounding: the basis itself is evaluated, so conventions cannot drift from the renderer's).
//! Band 0 is invariant. Host-only: no GPU here.
use crate::splat::reference::sh_basis;

/// A 3x3 matrix, rows first.
pub type Mat3 = [[f64; 3]; 3];

/// Number of sample directions for the least-squares fit: comfortably more than the 7
/// functions of band 3, on a Fibonacci sphere, so the normal equations are well conditioned.
const SAMPLES: usize = 48;

/// The per-band matrices of one orthogonal transform, up to SH degree 3.
#[derive(Debug, Clone, PartialEq)]
pub struct ShRotation {
    /// `bands[l - 1]` is band `l`'s `(2l+1) x (2l+1)` matrix, row-major, mapping original to
    /// rotated coefficients of that band.
    bands: Vec<Vec<f64>>,
}

impl ShRotation {
    /// The matrices of bands 1 to `degree` (at most 3) for orthogonal `r`. A non-orthogonal `r`
    /// gives only the least-squares best fit of the mapped functions.
    pub fn new(r: &Mat3, degree: u32) -> ShRotation {
        let degree = degree.min(3);
        let dirs = fibonacci_sphere(SAMPLES);
        // Rᵀ e_k: the original direction that R maps onto e_k.
        let back: Vec<[f64; 3]> = dirs
            .iter()
            .map(|e| [0, 1, 2].map(|i| r[0][i] * e[0] + r[1][i] * e[1] + r[2][i] * e[2]))
            .collect();
        let a_all: Vec<Vec<f64>> = dirs.iter().map(|&e| sh_basis(degree, e)).collect();
        let b_all: Vec<Vec<f64>> = back.iter().map(|&e| sh_basis(degree, e)).collect();
        let bands = (1..=degree as usize)
            .map(|l| {
                let (lo, n) = (l * l, 2 * l + 1);
                // Normal equations (AᵀA) M = AᵀB, with A_km = Y_m(e_k), B_km = Y_m(Rᵀ e_k).
                let mut ata = vec![0.0; n * n];
                let mut atb = vec![0.0; n * n];
                for (a, b) in a_all.iter().zip(&b_all) {
                    for i in 0..n {
                        for j in 0..n {
                            ata[i * n + j] += a[lo + i] * a[lo + j];
                            atb[i * n + j] += a[lo + i] * b[lo + j];
                        }
                    }
                }
                solve(n, &mut ata, &mut atb);
                atb
            })
            .collect();
        ShRotation { bands }
    }

    /// Highest band held.
    pub fn degree(&self) -> u32 {
        self.bands.len() as u32
    }

    /// Band `l`'s matrix (1 <= l <= degree), `(2l+1) x (2l+1)` row-major.
    pub fn band(&self, l: u32) -> &[f64] {
        &self.bands[l as usize - 1]
    }

    /// Rotates one channel's coefficients (DC first, `(d+1)^2` of them for degree `d`) in place.
    /// Bands above [`Self::degree`] are left alone.
    pub fn apply(&self, coeffs: &mut [f64]) {
        for (li, m) in self.bands.iter().enumerate() {
            let l = li + 1;
            let (lo, n) = (l * l, 2 * l + 1);
            if coeffs.len() < lo + n {
                break;
            }
            let mut src = [0.0; 7];
            src[..n].copy_from_slice(&coeffs[lo..lo + n]);
            for (i, out) in coeffs[lo..lo + n].iter_mut().enumerate() {
                *out = m[i * n..(i + 1) * n]
                    .iter()
                    .zip(&src)
                    .map(|(a, b)| a * b)
                    .sum();
            }
        }
    }

    /// Rotates one Gaussian's coefficient block laid out `[coeff][rgb]` (as in
    /// [`crate::splat::Gaussians::sh`], at most 16 coefficients) in place, in f64.
    pub fn apply_rgb(&self, sh: &mut [f32]) {
        let k = (sh.len() / 3).min(16);
        let mut ch = [0.0; 16];
        for c in 0..3 {
            for (i, v) in ch[..k].iter_mut().enumerate() {
                *v = sh[i * 3 + c] as f64;
            }
            self.apply(&mut ch[..k]);
            for (i, v) in ch[..k].iter().enumerate() {
                sh[i * 3 + c] = *v as f32;
            }
        }
    }
}

/// Rotated copy of one channel's coefficients (DC first; the degree follows from the length,
/// `(d+1)^2` for d = 0..3; extra trailing values are copied unchanged).
pub fn rotate_coeffs(r: &Mat3, coeffs: &[f64]) -> Vec<f64> {
    let degree = (0..=3u32)
        .rev()
        .find(|&d| coeffs.len() >= ((d + 1) * (d + 1)) as usize)
        .unwrap_or(0);
    let mut out = coeffs.to_vec();
    ShRotation::new(r, degree).apply(&mut out);
    out
}

/// Value of one channel's SH expansion in unit direction `d` (DC included, without the +0.5
/// offset the renderer adds).
pub fn eval(coeffs: &[f64], d: [f64; 3]) -> f64 {
    let degree = (0..=3u32)
        .rev()
        .find(|&k| coeffs.len() >= ((k + 1) * (k + 1)) as usize)
        .unwrap_or(0);
    sh_basis(degree, d)
        .iter()
        .zip(coeffs)
        .map(|(b, c)| b * c)
        .sum()
}

/// `n` nearly uniform unit directions (golden-angle spiral).
fn fibonacci_sphere(n: usize) -> Vec<[f64; 3]> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / n as f64;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * i as f64;
            [r * phi.cos(), r * phi.sin(), z]
        })
        .collect()
}

/// Solves `A X = B` in place for symmetric positive definite `a` (n x n) and `b` (n x n),
/// leaving X in `b`; Gaussian elimination with partial pivoting.
fn solve(n: usize, a: &mut [f64], b: &mut [f64]) {
    for col in 0..n {
        let piv = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .expect("a non-empty pivot range");
        if piv != col {
            for j in 0..n {
                a.swap(piv * n + j, col * n + j);
                b.swap(piv * n + j, col * n + j);
            }
        }
        let p = a[col * n + col];
        for row in 0..n {
            if row == col {
                continue;
            }
            let f = a[row * n + col] / p;
            if f == 0.0 {
                continue;
            }
            for j in 0..n {
                a[row * n + j] -= f * a[col * n + j];
                b[row * n + j] -= f * b[col * n + j];
            }
        }
    }
    for row in 0..n {
        let p = a[row * n + row];
        for j in 0..n {
            b[row * n + j] /= p;
        }
    }
}
