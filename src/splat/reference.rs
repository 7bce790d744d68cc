//! The CPU reference rasterizer in plain Rust and f64: the semantics the GPU kernels must match.
//!
//! INRIA 3DGS forward: near plane 0.2, EWA projection with the Jacobian's x/z and y/z clamped to
//! 1.3 x tan(fov/2), +0.3 on the 2D covariance diagonal, 3-sigma tile rectangle narrowed to tiles
//! the splat's alpha cutoff actually reaches, depth order front to back (ties by index),
//! alpha = min(0.99, o * exp(power)), skipped below 1/255, stop before T < 1e-4.

// `!(x > 0.0)` is deliberate throughout: it is also true for NaN, which must cull.
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    reason = "`!(x > 0.0)` is also true for NaN, which must cull"
)]
use super::cloud::{Gaussians, SH_C0};
use crate::camera::Camera;
use crate::gpu::kernels as k;
use rayon::prelude::*;

/// A Gaussian projected to the image.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projected {
    pub index: usize,
    pub xy: [f64; 2],
    pub conic: [f64; 3],
    pub depth: f64,
    pub opacity: f64,
    pub rgb: [f64; 3],
    pub radius: f64,
    /// Tile rectangle `[x0, y0, x1, y1)`.
    pub rect: [u32; 4],
}

/// A rendered image: colour (background included), final transmittance and expected depth
/// `sum z_i alpha_i T_i`, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct RefImage {
    pub width: u32,
    pub height: u32,
    pub color: Vec<[f64; 3]>,
    pub transmittance: Vec<f64>,
    pub depth: Vec<f64>,
}

/// SH basis constants of degrees 1 to 3 (INRIA ordering and signs).
pub const SH_C1: f64 = 0.488_602_511_902_919_9;
pub const SH_C2: [f64; 5] = [
    1.092_548_430_592_079_2,
    -1.092_548_430_592_079_2,
    0.315_391_565_252_520_05,
    -1.092_548_430_592_079_2,
    0.546_274_215_296_039_6,
];
pub const SH_C3: [f64; 7] = [
    -0.590_043_589_926_643_5,
    2.890_611_442_640_554,
    -0.457_045_799_464_465_8,
    0.373_176_332_590_115_4,
    -0.457_045_799_464_465_8,
    1.445_305_721_320_277,
    -0.590_043_589_926_643_5,
];

/// SH basis values for unit direction `d` up to `degree` (INRIA ordering and signs).
pub fn sh_basis(degree: u32, d: [f64; 3]) -> Vec<f64> {
    let [x, y, z] = d;
    let mut b = vec![SH_C0];
    if degree >= 1 {
        b.extend([-SH_C1 * y, SH_C1 * z, -SH_C1 * x]);
    }
    if degree >= 2 {
        let (xx, yy, zz) = (x * x, y * y, z * z);
        b.extend([
            SH_C2[0] * x * y,
            SH_C2[1] * y * z,
            SH_C2[2] * (2.0 * zz - xx - yy),
            SH_C2[3] * x * z,
            SH_C2[4] * (xx - yy),
        ]);
        if degree >= 3 {
            b.extend([
                SH_C3[0] * y * (3.0 * xx - yy),
                SH_C3[1] * x * y * z,
                SH_C3[2] * y * (4.0 * zz - xx - yy),
                SH_C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy),
                SH_C3[4] * x * (4.0 * zz - xx - yy),
                SH_C3[5] * z * (xx - yy),
                SH_C3[6] * x * (xx - 3.0 * yy),
            ]);
        }
    }
    b
}

fn sigmoid(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

/// Rotation matrix of quaternion (w, x, y, z), normalised first; `None` for a zero quaternion.
pub fn quat_to_mat(q: [f64; 4]) -> Option<[[f64; 3]; 3]> {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    if !(n > 0.0) || !n.is_finite() {
        return None;
    }
    let [r, x, y, z] = q.map(|v| v / n);
    Some([
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - r * z),
            2.0 * (x * z + r * y),
        ],
        [
            2.0 * (x * y + r * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - r * x),
        ],
        [
            2.0 * (x * z - r * y),
            2.0 * (y * z + r * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ])
}

/// Projects Gaussian `i`, or `None` when it is culled (behind the near plane, degenerate,
/// non-finite, off-screen, or too transparent to touch any tile).
pub fn project(g: &Gaussians, i: usize, cam: &Camera) -> Option<Projected> {
    let pr = project_raw(g, i, cam)?;
    if pr.rect[2] <= pr.rect[0] || pr.rect[3] <= pr.rect[1] || tile_count(&pr) == 0 {
        return None;
    }
    Some(pr)
}

/// Projection without the screen-space culling (tile rectangle and alpha cutoff): `None` only
/// behind the near plane or for degenerate or non-finite Gaussians. The smooth rendering mode of
/// the gradient checks uses it.
pub fn project_raw(g: &Gaussians, i: usize, cam: &Camera) -> Option<Projected> {
    let (rcw, t) = cam.world_to_camera();
    let m = g.means[i].map(f64::from);
    if !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    let p = [0, 1, 2].map(|r| rcw[r][0] * m[0] + rcw[r][1] * m[1] + rcw[r][2] * m[2] + t[r]);
    if !(p[2] > k::NEAR_PLANE as f64) {
        return None;
    }
    let rot = quat_to_mat(g.rotations[i].map(f64::from))?;
    let s = g.scales[i].map(|v| (v as f64).exp());
    if !s.iter().all(|v| v.is_finite()) {
        return None;
    }
    // Sigma = R diag(s^2) R^T
    let mut sigma = [[0.0; 3]; 3];
    for a in 0..3 {
        for b in 0..3 {
            sigma[a][b] = (0..3).map(|c| rot[a][c] * s[c] * s[c] * rot[b][c]).sum();
        }
    }
    let (w, h) = (cam.width as f64, cam.height as f64);
    let limx = 1.3 * 0.5 * w / cam.fx;
    let limy = 1.3 * 0.5 * h / cam.fy;
    let tx = (p[0] / p[2]).clamp(-limx, limx) * p[2];
    let ty = (p[1] / p[2]).clamp(-limy, limy) * p[2];
    let z = p[2];
    let j = [
        [cam.fx / z, 0.0, -cam.fx * tx / (z * z)],
        [0.0, cam.fy / z, -cam.fy * ty / (z * z)],
    ];
    // T = J * Rcw (2x3), cov2 = T Sigma T^T
    let tm: [[f64; 3]; 2] =
        [0, 1].map(|r| [0, 1, 2].map(|c| (0..3).map(|q| j[r][q] * rcw[q][c]).sum()));
    let mut cov = [[0.0; 2]; 2];
    for a in 0..2 {
        for b in 0..2 {
            cov[a][b] = (0..3)
                .map(|u| {
                    (0..3)
                        .map(|v| tm[a][u] * sigma[u][v] * tm[b][v])
                        .sum::<f64>()
                })
                .sum();
        }
    }
    let (a, b, c) = (
        cov[0][0] + k::COV_BLUR as f64,
        cov[0][1],
        cov[1][1] + k::COV_BLUR as f64,
    );
    let det = a * c - b * b;
    if !(det > 0.0) {
        return None;
    }
    let conic = [c / det, -b / det, a / det];
    let xy = [cam.fx * p[0] / z + 0.5 * w, cam.fy * p[1] / z + 0.5 * h];
    let mid = 0.5 * (a + c);
    let l1 = mid + (mid * mid - det).max(0.1).sqrt();
    let l2 = mid - (mid * mid - det).max(0.1).sqrt();
    let radius = (3.0 * l1.max(l2).sqrt()).ceil();
    let ts = k::TILE as f64;
    let (gx, gy) = (
        cam.width.div_ceil(k::TILE) as f64,
        cam.height.div_ceil(k::TILE) as f64,
    );
    // INRIA's rectangle, in its pixel coordinates (centre of pixel i at i).
    let (px, py) = (xy[0] - 0.5, xy[1] - 0.5);
    let rect = [
        ((px - radius) / ts).floor().clamp(0.0, gx) as u32,
        ((py - radius) / ts).floor().clamp(0.0, gy) as u32,
        ((px + radius + ts - 1.0) / ts).floor().clamp(0.0, gx) as u32,
        ((py + radius + ts - 1.0) / ts).floor().clamp(0.0, gy) as u32,
    ];
    let dir = {
        let d = [
            m[0] - cam.position[0],
            m[1] - cam.position[1],
            m[2] - cam.position[2],
        ];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        d.map(|v| v / l)
    };
    let basis = sh_basis(g.sh_degree, dir);
    let kc = g.coeffs();
    let rgb = [0, 1, 2].map(|ch| {
        let v: f64 = basis
            .iter()
            .enumerate()
            .map(|(ci, bv)| bv * g.sh[(i * kc + ci) * 3 + ch] as f64)
            .sum();
        v + 0.5
    });
    // A non-finite colour culls the splat (checked before the clamp, which would hide -inf).
    if !rgb.iter().all(|v| v.is_finite()) {
        return None;
    }
    let rgb = rgb.map(|v| v.max(0.0));
    let opacity = sigmoid(g.opacities[i] as f64);
    if !(opacity.is_finite()
        && rgb.iter().all(|v| v.is_finite())
        && conic.iter().all(|v| v.is_finite()))
    {
        return None;
    }
    Some(Projected {
        index: i,
        xy,
        conic,
        depth: z,
        opacity,
        rgb,
        radius,
        rect,
    })
}

/// Minimum of `a dx^2 + 2 b dx dy + c dy^2` over the box `[lo, hi]` of offsets (a, c > 0).
pub fn box_min_quadratic(conic: [f64; 3], lo: [f64; 2], hi: [f64; 2]) -> f64 {
    let [a, b, c] = conic;
    if lo[0] <= 0.0 && hi[0] >= 0.0 && lo[1] <= 0.0 && hi[1] >= 0.0 {
        return 0.0;
    }
    let q = |dx: f64, dy: f64| a * dx * dx + 2.0 * b * dx * dy + c * dy * dy;
    let mut best = f64::INFINITY;
    for dx in [lo[0], hi[0]] {
        let dy = (-b * dx / c).clamp(lo[1], hi[1]);
        best = best.min(q(dx, dy));
    }
    for dy in [lo[1], hi[1]] {
        let dx = (-b * dy / a).clamp(lo[0], hi[0]);
        best = best.min(q(dx, dy));
    }
    best
}

/// Whether the splat reaches alpha >= 1/255 (plus margin) at any pixel centre of tile (tx, ty).
pub fn tile_touched(p: &Projected, tx: u32, ty: u32) -> bool {
    let thr = (p.opacity / k::ALPHA_MIN as f64).ln() + k::CULL_MARGIN as f64;
    if thr < 0.0 {
        return false;
    }
    let ts = k::TILE as f64;
    let lo = [
        tx as f64 * ts + 0.5 - p.xy[0],
        ty as f64 * ts + 0.5 - p.xy[1],
    ];
    let hi = [lo[0] + ts - 1.0, lo[1] + ts - 1.0];
    0.5 * box_min_quadratic(p.conic, lo, hi) <= thr
}

/// Tiles the splat is binned to.
pub fn tile_count(p: &Projected) -> u32 {
    let mut n = 0;
    for ty in p.rect[1]..p.rect[3] {
        for tx in p.rect[0]..p.rect[2] {
            n += tile_touched(p, tx, ty) as u32;
        }
    }
    n
}

/// Per-tile lists of projected splats, front to back (ties by index).
pub fn bin(projected: &[Projected], cam: &Camera) -> Vec<Vec<Projected>> {
    let gx = cam.width.div_ceil(k::TILE);
    let gy = cam.height.div_ceil(k::TILE);
    let mut order: Vec<&Projected> = projected.iter().collect();
    order.sort_by(|a, b| a.depth.total_cmp(&b.depth).then(a.index.cmp(&b.index)));
    let mut tiles = vec![Vec::new(); (gx * gy) as usize];
    for p in order {
        for ty in p.rect[1]..p.rect[3] {
            for tx in p.rect[0]..p.rect[2] {
                if tile_touched(p, tx, ty) {
                    tiles[(ty * gx + tx) as usize].push(*p);
                }
            }
        }
    }
    tiles
}

/// Renders `g` from `cam` over background `bg` (multithreaded over tiles).
pub fn render(g: &Gaussians, cam: &Camera, bg: [f64; 3]) -> RefImage {
    render_with(g, cam, bg, Cutoffs::Exact)
}

/// Per-tile splat lists under `cutoffs`: binned and culled (exact), or every projectable splat
/// in depth order for every tile (smooth).
pub fn tile_lists(g: &Gaussians, cam: &Camera, cutoffs: Cutoffs) -> Vec<Vec<Projected>> {
    match cutoffs {
        Cutoffs::Exact => {
            let projected: Vec<Projected> = (0..g.len())
                .into_par_iter()
                .filter_map(|i| project(g, i, cam))
                .collect();
            bin(&projected, cam)
        }
        Cutoffs::Smooth => {
            let mut all: Vec<Projected> = (0..g.len())
                .filter_map(|i| project_raw(g, i, cam))
                .collect();
            all.sort_by(|a, b| a.depth.total_cmp(&b.depth).then(a.index.cmp(&b.index)));
            let n = (cam.width.div_ceil(k::TILE) * cam.height.div_ceil(k::TILE)) as usize;
            vec![all; n]
        }
    }
}

/// [`render`] with a choice of cutoffs.
pub fn render_with(g: &Gaussians, cam: &Camera, bg: [f64; 3], cutoffs: Cutoffs) -> RefImage {
    let tiles = tile_lists(g, cam, cutoffs);
    let (w, h) = (cam.width as usize, cam.height as usize);
    let gx = cam.width.div_ceil(k::TILE) as usize;
    let ts = k::TILE as usize;
    type Row = (Vec<[f64; 3]>, Vec<f64>, Vec<f64>);
    let rows: Vec<Row> = (0..h)
        .into_par_iter()
        .map(|y| {
            let mut row = (vec![[0.0; 3]; w], vec![0.0; w], vec![0.0; w]);
            for x in 0..w {
                let list = &tiles[(y / ts) * gx + x / ts];
                let (c, t, d) = blend_pixel_with(list, x as f64 + 0.5, y as f64 + 0.5, cutoffs);
                row.0[x] = [0, 1, 2].map(|ch| c[ch] + t * bg[ch]);
                row.1[x] = t;
                row.2[x] = d;
            }
            row
        })
        .collect();
    let mut img = RefImage {
        width: cam.width,
        height: cam.height,
        color: vec![],
        transmittance: vec![],
        depth: vec![],
    };
    for (c, t, d) in rows {
        img.color.extend(c);
        img.transmittance.extend(t);
        img.depth.extend(d);
    }
    img
}

/// Walks the splats that contribute to a pixel centre under the blending rules, front to back,
/// calling `f(splat, alpha, T before it)`; returns the final transmittance.
pub fn walk_pixel(
    list: &[Projected],
    px: f64,
    py: f64,
    mut f: impl FnMut(&Projected, f64, f64),
) -> f64 {
    walk_pixel_with(list, px, py, Cutoffs::Exact, |p, alpha, t, _| {
        f(p, alpha, t)
    })
}

/// Which discontinuities blending has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cutoffs {
    /// INRIA semantics: skip alpha < 1/255, stop before T < 1e-4 (and tile culling when binning).
    Exact,
    /// No alpha skip and no early stop, every splat in every tile: a differentiable function of
    /// the parameters for finite-difference checks (the 0.99 clamp stays; keep opacities below it).
    Smooth,
}

/// [`walk_pixel`] with a choice of cutoffs; `f` also gets whether alpha hit its 0.99 clamp.
pub fn walk_pixel_with(
    list: &[Projected],
    px: f64,
    py: f64,
    cutoffs: Cutoffs,
    mut f: impl FnMut(&Projected, f64, f64, bool),
) -> f64 {
    let exact = cutoffs == Cutoffs::Exact;
    let mut t = 1.0;
    for p in list {
        let dx = p.xy[0] - px;
        let dy = p.xy[1] - py;
        let power = -0.5 * (p.conic[0] * dx * dx + p.conic[2] * dy * dy) - p.conic[1] * dx * dy;
        if power > 0.0 {
            continue;
        }
        let raw = p.opacity * power.exp();
        let clamped = raw > k::ALPHA_MAX as f64;
        let alpha = raw.min(k::ALPHA_MAX as f64);
        if exact && alpha < k::ALPHA_MIN as f64 {
            continue;
        }
        let next = t * (1.0 - alpha);
        if exact && next < k::T_MIN as f64 {
            break;
        }
        f(p, alpha, t, clamped);
        t = next;
    }
    t
}

/// Front-to-back blend of one pixel centre: (colour without background, transmittance, depth).
pub fn blend_pixel(list: &[Projected], px: f64, py: f64) -> ([f64; 3], f64, f64) {
    blend_pixel_with(list, px, py, Cutoffs::Exact)
}

/// [`blend_pixel`] with a choice of cutoffs.
pub fn blend_pixel_with(
    list: &[Projected],
    px: f64,
    py: f64,
    cutoffs: Cutoffs,
) -> ([f64; 3], f64, f64) {
    let mut c = [0.0; 3];
    let mut d = 0.0;
    let t = walk_pixel_with(list, px, py, cutoffs, |p, alpha, t, _| {
        for (cc, rgb) in c.iter_mut().zip(p.rgb) {
            *cc += rgb * alpha * t;
        }
        d += p.depth * alpha * t;
    });
    (c, t, d)
}

/// The filtering score of one view (see `splat::score`): `paper` selects
/// sum V / (z^2 maxV(ray)), otherwise the code's sum 1 / z^2, over contributing (pixel, Gaussian) pairs.
pub fn score(g: &Gaussians, cam: &Camera, paper: bool) -> Vec<f64> {
    let projected: Vec<Projected> = (0..g.len()).filter_map(|i| project(g, i, cam)).collect();
    let tiles = bin(&projected, cam);
    let gx = cam.width.div_ceil(k::TILE) as usize;
    let ts = k::TILE as usize;
    let volume = |i: usize| g.scales[i].iter().map(|&s| s as f64).sum::<f64>().exp();
    let mut out = vec![0.0; g.len()];
    for y in 0..cam.height as usize {
        for x in 0..cam.width as usize {
            let list = &tiles[(y / ts) * gx + x / ts];
            let contrib = contributors(list, x as f64 + 0.5, y as f64 + 0.5);
            let maxv = contrib.iter().map(|p| volume(p.index)).fold(0.0, f64::max);
            for p in contrib {
                let w = 1.0 / (p.depth * p.depth);
                out[p.index] += if paper { volume(p.index) * w / maxv } else { w };
            }
        }
    }
    out
}

/// The splats that contribute to a pixel under the blending rules, front to back.
pub fn contributors(list: &[Projected], px: f64, py: f64) -> Vec<Projected> {
    let mut out = Vec::new();
    walk_pixel(list, px, py, |p, _, _| out.push(*p));
    out
}
