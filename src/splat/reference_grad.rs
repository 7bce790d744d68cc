//! The CPU reference of the backward pass in plain Rust and f64: gradients of a loss given
//! dL/d(pixel colour) with respect to every raw Gaussian parameter. The GPU backward must match
//! it; it is itself checked against central finite differences of [`super::reference::render_with`]
//! in smooth mode.
//!
//! Two stages, as on the GPU: the blend backward gives each Gaussian's screen-space gradient
//! ([`Grad2d`]: centre, conic, opacity, colour), summed over pixels; the projection backward
//! carries it to means, log-scales, quaternions, opacity logits and SH coefficients.
// Index loops mirror the maths (and the GLSL) more plainly than iterator chains here.
#![allow(
    clippy::needless_range_loop,
    reason = "index loops mirror the maths and the GLSL"
)]
use super::cloud::Gaussians;
use super::reference::{self as r, Cutoffs, Projected};
use crate::camera::Camera;
use crate::gpu::kernels as k;
use rayon::prelude::*;

/// Screen-space gradient of one Gaussian (with respect to the projected values).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Grad2d {
    /// Pixel-space centre.
    pub xy: [f64; 2],
    /// Conic (a, b, c) of `power = -a dx^2 / 2 - b dx dy - c dy^2 / 2`.
    pub conic: [f64; 3],
    /// Activated opacity.
    pub opacity: f64,
    /// Clamped colour.
    pub rgb: [f64; 3],
}

impl Grad2d {
    fn add(&mut self, o: &Grad2d) {
        for c in 0..2 {
            self.xy[c] += o.xy[c];
        }
        for c in 0..3 {
            self.conic[c] += o.conic[c];
            self.rgb[c] += o.rgb[c];
        }
        self.opacity += o.opacity;
    }

    /// Norm of the centre gradient in normalised device coordinates (x and y in [-1, 1]): the
    /// densification statistic of 3DGS.
    pub fn ndc_norm(&self, cam: &Camera) -> f64 {
        let gx = self.xy[0] * 0.5 * cam.width as f64;
        let gy = self.xy[1] * 0.5 * cam.height as f64;
        (gx * gx + gy * gy).sqrt()
    }
}

/// Gradients with respect to the raw parameters, laid out as [`Gaussians`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Grads {
    pub means: Vec<[f64; 3]>,
    pub scales: Vec<[f64; 3]>,
    pub rotations: Vec<[f64; 4]>,
    pub opacities: Vec<f64>,
    pub sh: Vec<f64>,
}

impl Grads {
    /// Zero gradients for `g`.
    pub fn zeros(g: &Gaussians) -> Grads {
        Grads {
            means: vec![[0.0; 3]; g.len()],
            scales: vec![[0.0; 3]; g.len()],
            rotations: vec![[0.0; 4]; g.len()],
            opacities: vec![0.0; g.len()],
            sh: vec![0.0; g.sh.len()],
        }
    }
}

/// Gradients of `L = sum_pixels dot(dl_dcolor[pixel], colour[pixel])` (colour over `bg`, row
/// major): the per-Gaussian screen-space gradients and the parameter gradients.
pub fn backward(
    g: &Gaussians,
    cam: &Camera,
    bg: [f64; 3],
    dl_dcolor: &[[f64; 3]],
    cutoffs: Cutoffs,
) -> (Vec<Grad2d>, Grads) {
    let tiles = r::tile_lists(g, cam, cutoffs);
    let g2 = blend_backward(&tiles, cam, bg, dl_dcolor, cutoffs, g.len());
    let mut out = Grads::zeros(g);
    let kc = g.coeffs() * 3;
    for (i, gi) in g2.iter().enumerate() {
        if *gi == Grad2d::default() {
            continue;
        }
        let p = project_backward(g, i, cam, gi);
        out.means[i] = p.mean;
        out.scales[i] = p.scale;
        out.rotations[i] = p.rotation;
        out.opacities[i] = p.opacity;
        out.sh[i * kc..(i + 1) * kc].copy_from_slice(&p.sh);
    }
    (g2, out)
}

/// Gaussians that sit within relative distance `rel` of a blending cutoff (alpha = 1/255,
/// alpha = 0.99, T = 1e-4) at some pixel. Whether such a splat counts there depends on rounding,
/// so f32 and f64 may legitimately disagree about its gradient; tests leave these out.
pub fn near_cutoffs(g: &Gaussians, cam: &Camera, rel: f64) -> Vec<bool> {
    let mut out = vec![false; g.len()];
    cutoff_walk(g, cam, rel, |_, i| out[i] = true);
    out
}

/// Pixels where some Gaussian sits within relative distance `rel` of a blending cutoff: where
/// f32 and f64 may round to opposite sides and legitimately render different values.
pub fn near_cutoff_pixels(g: &Gaussians, cam: &Camera, rel: f64) -> Vec<bool> {
    let mut out = vec![false; (cam.width * cam.height) as usize];
    cutoff_walk(g, cam, rel, |px, _| out[px] = true);
    out
}

/// Walks every pixel's blend in the reference and calls `near(pixel, gaussian)` for each
/// Gaussian within relative distance `rel` of a cutoff there.
fn cutoff_walk(g: &Gaussians, cam: &Camera, rel: f64, mut near_at: impl FnMut(usize, usize)) {
    let tiles = r::tile_lists(g, cam, Cutoffs::Exact);
    let gx = cam.width.div_ceil(k::TILE) as usize;
    let ts = k::TILE as usize;
    let near = |v: f64, at: f64| (v / at - 1.0).abs() < rel;
    for y in 0..cam.height as usize {
        for x in 0..cam.width as usize {
            let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
            let mut t = 1.0;
            for p in &tiles[(y / ts) * gx + x / ts] {
                let dx = p.xy[0] - px;
                let dy = p.xy[1] - py;
                let power =
                    -0.5 * (p.conic[0] * dx * dx + p.conic[2] * dy * dy) - p.conic[1] * dx * dy;
                let raw = p.opacity * power.exp();
                let alpha = raw.min(k::ALPHA_MAX as f64);
                let next = t * (1.0 - alpha);
                if near(raw, k::ALPHA_MIN as f64)
                    || near(raw, k::ALPHA_MAX as f64)
                    || (alpha >= k::ALPHA_MIN as f64 && near(next, k::T_MIN as f64))
                {
                    near_at(y * cam.width as usize + x, p.index);
                }
                if power > 0.0 || alpha < k::ALPHA_MIN as f64 {
                    continue;
                }
                if next < k::T_MIN as f64 {
                    break;
                }
                t = next;
            }
        }
    }
}

/// The blend backward: per-Gaussian screen-space gradients summed over all pixels.
pub fn blend_backward(
    tiles: &[Vec<Projected>],
    cam: &Camera,
    bg: [f64; 3],
    dl_dcolor: &[[f64; 3]],
    cutoffs: Cutoffs,
    n: usize,
) -> Vec<Grad2d> {
    let (w, h) = (cam.width as usize, cam.height as usize);
    assert_eq!(dl_dcolor.len(), w * h, "one colour gradient per pixel");
    let gx = cam.width.div_ceil(k::TILE) as usize;
    let ts = k::TILE as usize;
    (0..h)
        .into_par_iter()
        .fold(
            || vec![Grad2d::default(); n],
            |mut acc, y| {
                for x in 0..w {
                    let list = &tiles[(y / ts) * gx + x / ts];
                    let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                    pixel_backward(list, px, py, bg, dl_dcolor[y * w + x], cutoffs, &mut acc);
                }
                acc
            },
        )
        .reduce(
            || vec![Grad2d::default(); n],
            |mut a, b| {
                for (x, y) in a.iter_mut().zip(&b) {
                    x.add(y);
                }
                a
            },
        )
}

/// One pixel's contribution to the screen-space gradients.
fn pixel_backward(
    list: &[Projected],
    px: f64,
    py: f64,
    bg: [f64; 3],
    gc: [f64; 3],
    cutoffs: Cutoffs,
    acc: &mut [Grad2d],
) {
    // The pixel's full colour, then a second walk with the running colour: the colour behind
    // splat j is (full - colour up to and including j) / (1 - alpha_j) (see glsl/blend_backward.comp).
    let (c, t, _) = r::blend_pixel_with(list, px, py, cutoffs);
    let full = [0, 1, 2].map(|ch| c[ch] + t * bg[ch]);
    let mut run = [0.0; 3];
    r::walk_pixel_with(list, px, py, cutoffs, |p, alpha, t, clamped| {
        let mut dalpha = 0.0;
        for ch in 0..3 {
            run[ch] += p.rgb[ch] * alpha * t;
            dalpha += gc[ch] * (p.rgb[ch] * t - (full[ch] - run[ch]) / (1.0 - alpha));
        }
        let a = &mut acc[p.index];
        for ch in 0..3 {
            a.rgb[ch] += gc[ch] * alpha * t;
        }
        if clamped {
            return;
        }
        let dx = p.xy[0] - px;
        let dy = p.xy[1] - py;
        let gauss = alpha / p.opacity;
        a.opacity += dalpha * gauss;
        let dpower = dalpha * alpha;
        a.conic[0] += -0.5 * dx * dx * dpower;
        a.conic[1] += -dx * dy * dpower;
        a.conic[2] += -0.5 * dy * dy * dpower;
        a.xy[0] += -(p.conic[0] * dx + p.conic[1] * dy) * dpower;
        a.xy[1] += -(p.conic[2] * dy + p.conic[1] * dx) * dpower;
    });
}

/// Parameter gradients of one Gaussian.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamGrad {
    pub mean: [f64; 3],
    pub scale: [f64; 3],
    pub rotation: [f64; 4],
    pub opacity: f64,
    pub sh: Vec<f64>,
}

type M3 = [[f64; 3]; 3];

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn mat_vec(m: &M3, v: [f64; 3]) -> [f64; 3] {
    [dot3(m[0], v), dot3(m[1], v), dot3(m[2], v)]
}

/// Derivatives of the SH basis functions with respect to the (unit) direction, INRIA ordering.
pub fn sh_basis_grad(degree: u32, d: [f64; 3]) -> Vec<[f64; 3]> {
    use r::{SH_C1 as C1, SH_C2 as C2, SH_C3 as C3};
    let [x, y, z] = d;
    let s = |c: f64, v: [f64; 3]| v.map(|e| c * e);
    let mut b = vec![[0.0; 3]];
    if degree >= 1 {
        b.extend([[0.0, -C1, 0.0], [0.0, 0.0, C1], [-C1, 0.0, 0.0]]);
    }
    if degree >= 2 {
        let (xx, yy, zz) = (x * x, y * y, z * z);
        b.extend([
            s(C2[0], [y, x, 0.0]),
            s(C2[1], [0.0, z, y]),
            s(C2[2], [-2.0 * x, -2.0 * y, 4.0 * z]),
            s(C2[3], [z, 0.0, x]),
            s(C2[4], [2.0 * x, -2.0 * y, 0.0]),
        ]);
        if degree >= 3 {
            b.extend([
                s(C3[0], [6.0 * x * y, 3.0 * xx - 3.0 * yy, 0.0]),
                s(C3[1], [y * z, x * z, x * y]),
                s(C3[2], [-2.0 * x * y, 4.0 * zz - xx - 3.0 * yy, 8.0 * y * z]),
                s(
                    C3[3],
                    [-6.0 * x * z, -6.0 * y * z, 6.0 * zz - 3.0 * xx - 3.0 * yy],
                ),
                s(C3[4], [4.0 * zz - 3.0 * xx - yy, -2.0 * x * y, 8.0 * x * z]),
                s(C3[5], [2.0 * x * z, -2.0 * y * z, xx - yy]),
                s(C3[6], [3.0 * xx - 3.0 * yy, -6.0 * x * y, 0.0]),
            ]);
        }
    }
    b
}

/// Derivative of a loss through the rotation matrix of a normalised quaternion (w, x, y, z):
/// `gr = dL/dR` (rows as in [`super::reference::quat_to_mat`]), returns dL/d(normalised quaternion).
pub fn quat_mat_backward(q: [f64; 4], gr: &M3) -> [f64; 4] {
    let [r, x, y, z] = q;
    let g = gr;
    [
        2.0 * (-z * g[0][1] + y * g[0][2] + z * g[1][0] - x * g[1][2] - y * g[2][0] + x * g[2][1]),
        2.0 * (y * g[0][1] + z * g[0][2] + y * g[1][0] - 2.0 * x * g[1][1] - r * g[1][2]
            + z * g[2][0]
            + r * g[2][1]
            - 2.0 * x * g[2][2]),
        2.0 * (-2.0 * y * g[0][0] + x * g[0][1] + r * g[0][2] + x * g[1][0] + z * g[1][2]
            - r * g[2][0]
            + z * g[2][1]
            - 2.0 * y * g[2][2]),
        2.0 * (-2.0 * z * g[0][0] - r * g[0][1] + x * g[0][2] + r * g[1][0] - 2.0 * z * g[1][1]
            + y * g[1][2]
            + x * g[2][0]
            + y * g[2][1]),
    ]
}

/// The projection backward of Gaussian `i`: from its screen-space gradient to its raw parameters.
/// The Gaussian must be projectable ([`super::reference::project_raw`] not `None`).
pub fn project_backward(g: &Gaussians, i: usize, cam: &Camera, g2: &Grad2d) -> ParamGrad {
    let (rcw, t) = cam.world_to_camera();
    let m = g.means[i].map(f64::from);
    let p = [0, 1, 2].map(|row| dot3(rcw[row], m) + t[row]);
    let z = p[2];
    let q = g.rotations[i].map(f64::from);
    let qn_len = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    let qn = q.map(|v| v / qn_len);
    let rot = r::quat_to_mat(q).expect("projectable Gaussian");
    let s = g.scales[i].map(|v| (v as f64).exp());
    // M = R diag(s), Sigma = M M^T
    let mm: M3 = [0, 1, 2].map(|a| [0, 1, 2].map(|c| rot[a][c] * s[c]));
    let sigma: M3 = [0, 1, 2].map(|a| [0, 1, 2].map(|b| (0..3).map(|c| mm[a][c] * mm[b][c]).sum()));
    let (w, h) = (cam.width as f64, cam.height as f64);
    let lim = [1.3 * 0.5 * w / cam.fx, 1.3 * 0.5 * h / cam.fy];
    let f = [cam.fx, cam.fy];
    let u = [p[0] / z, p[1] / z];
    let clamped = [0, 1].map(|a| u[a] < -lim[a] || u[a] > lim[a]);
    let tt = [0, 1].map(|a| u[a].clamp(-lim[a], lim[a]) * z);
    // J rows: (f/z, 0, -f tx / z^2), (0, f/z, -f ty / z^2); T = J Rcw.
    let j = [
        [f[0] / z, 0.0, -f[0] * tt[0] / (z * z)],
        [0.0, f[1] / z, -f[1] * tt[1] / (z * z)],
    ];
    let tm: [[f64; 3]; 2] =
        [0, 1].map(|row| [0, 1, 2].map(|c| (0..3).map(|qq| j[row][qq] * rcw[qq][c]).sum()));
    let st = [mat_vec(&sigma, tm[0]), mat_vec(&sigma, tm[1])];
    let a = dot3(tm[0], st[0]) + k::COV_BLUR as f64;
    let b = dot3(tm[0], st[1]);
    let c = dot3(tm[1], st[1]) + k::COV_BLUR as f64;
    let det = a * c - b * b;
    let det2 = det * det;

    // conic -> covariance
    let [ga, gb, gc] = g2.conic;
    let da = (-c * c * ga + b * c * gb - b * b * gc) / det2;
    let db = (2.0 * b * c * ga - (a * c + b * b) * gb + 2.0 * a * b * gc) / det2;
    let dc = (-b * b * ga + a * b * gb - a * a * gc) / det2;
    // covariance -> Sigma (entries as independent variables) and T rows
    let mut gsig = [[0.0; 3]; 3];
    for (uu, row) in gsig.iter_mut().enumerate() {
        for (vv, e) in row.iter_mut().enumerate() {
            *e = da * tm[0][uu] * tm[0][vv]
                + db * tm[0][uu] * tm[1][vv]
                + dc * tm[1][uu] * tm[1][vv];
        }
    }
    let st0 = st[0];
    let st1 = st[1];
    let gt0 = [0, 1, 2].map(|e| 2.0 * da * st0[e] + db * st1[e]);
    let gt1 = [0, 1, 2].map(|e| 2.0 * dc * st1[e] + db * st0[e]);
    // T -> J
    let gj = [
        [0, 1, 2].map(|qq| dot3(gt0, rcw[qq])),
        [0, 1, 2].map(|qq| dot3(gt1, rcw[qq])),
    ];
    let mut gp = [0.0; 3];
    gp[2] += -gj[0][0] * f[0] / (z * z) - gj[1][1] * f[1] / (z * z);
    for (a_, gjr) in [gj[0][2], gj[1][2]].into_iter().enumerate() {
        if clamped[a_] {
            // J_a2 = -f L / z with L the clamp limit
            gp[2] += gjr * f[a_] * tt[a_] / (z * z * z);
        } else {
            gp[a_] += -gjr * f[a_] / (z * z);
            gp[2] += gjr * 2.0 * f[a_] * p[a_] / (z * z * z);
        }
    }
    // centre
    for a_ in 0..2 {
        gp[a_] += g2.xy[a_] * f[a_] / z;
        gp[2] += -g2.xy[a_] * f[a_] * p[a_] / (z * z);
    }
    // p = Rcw m + t
    let mut gm = [0, 1, 2].map(|c_| (0..3).map(|row| rcw[row][c_] * gp[row]).sum::<f64>());
    // Sigma = M M^T -> M = R diag(s)
    let gmm: M3 = [0, 1, 2].map(|a_| {
        [0, 1, 2].map(|c_| {
            (0..3)
                .map(|b_| (gsig[a_][b_] + gsig[b_][a_]) * mm[b_][c_])
                .sum()
        })
    });
    let scale = [0, 1, 2].map(|c_| (0..3).map(|a_| gmm[a_][c_] * rot[a_][c_]).sum::<f64>() * s[c_]);
    let grot: M3 = [0, 1, 2].map(|a_| [0, 1, 2].map(|c_| gmm[a_][c_] * s[c_]));
    let gqn = quat_mat_backward(qn, &grot);
    let proj_q = (0..4).map(|e| qn[e] * gqn[e]).sum::<f64>();
    let rotation = [0, 1, 2, 3].map(|e| (gqn[e] - qn[e] * proj_q) / qn_len);
    // opacity
    let o = 1.0 / (1.0 + (-(g.opacities[i] as f64)).exp());
    let opacity = g2.opacity * o * (1.0 - o);
    // colour
    let d = [0, 1, 2].map(|e| m[e] - cam.position[e]);
    let dl = dot3(d, d).sqrt();
    let dir = d.map(|v| v / dl);
    let basis = r::sh_basis(g.sh_degree, dir);
    let kc = g.coeffs();
    let mut grgb = g2.rgb;
    for (ch, gch) in grgb.iter_mut().enumerate() {
        let raw: f64 = basis
            .iter()
            .enumerate()
            .map(|(ci, bv)| bv * g.sh[(i * kc + ci) * 3 + ch] as f64)
            .sum::<f64>()
            + 0.5;
        if raw < 0.0 {
            *gch = 0.0;
        }
    }
    let mut sh = vec![0.0; kc * 3];
    let mut gdir = [0.0; 3];
    let bgrad = sh_basis_grad(g.sh_degree, dir);
    for ci in 0..kc {
        let mut gb_ = 0.0;
        for ch in 0..3 {
            sh[ci * 3 + ch] = basis[ci] * grgb[ch];
            gb_ += g.sh[(i * kc + ci) * 3 + ch] as f64 * grgb[ch];
        }
        for e in 0..3 {
            gdir[e] += gb_ * bgrad[ci][e];
        }
    }
    let pd = dot3(dir, gdir);
    for e in 0..3 {
        gm[e] += (gdir[e] - dir[e] * pd) / dl;
    }
    ParamGrad {
        mean: gm,
        scale,
        rotation,
        opacity,
        sh,
    }
}
