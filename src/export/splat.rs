//! antimatter15's `.splat`: no header, 32 little-endian bytes a Gaussian, the count being the
//! file size / 32 (the layout of antimatter15/splat's `convert.py` and `main.js`):
//!
//! | offset | type   | content |
//! |--------|--------|---------|
//! | 0      | f32 x3 | position, as given (those writers copy the PLY's, RDF)  |
//! | 12     | f32 x3 | linear scale `exp(scale_i)` |
//! | 24     | u8 x4  | R, G, B = `(0.5 + SH_C0 · f_dc) · 255`, A = `sigmoid(opacity) · 255` |
//! | 28     | u8 x4  | unit quaternion (w, x, y, z), byte = `q · 128 + 128` |
//!
//! Bytes are rounded and clamped to 0..=255 (main.js stores through a `Uint8ClampedArray`, which
//! rounds). Records are ordered as those writers order them, by descending "importance"
//! `exp(s0 + s1 + s2) · sigmoid(opacity)`, ties in input order, so the large opaque Gaussians
//! arrive first when a viewer streams the file. The format has no view-dependent colour: SH
//! bands above 0 are dropped.
use super::{sigmoid, to_u8, unit_quat};
use crate::splat::cloud::SH_C0;
use crate::splat::Gaussians;

/// Bytes a record takes.
pub const RECORD_BYTES: usize = 32;

/// The order records are written in: indices by descending importance, stable.
pub fn order(g: &Gaussians) -> Vec<usize> {
    let importance: Vec<f64> = (0..g.len())
        .map(|i| {
            let s: f64 = g.scales[i].iter().map(|&v| f64::from(v)).sum();
            s.exp() * f64::from(sigmoid(g.opacities[i]))
        })
        .collect();
    let mut idx: Vec<usize> = (0..g.len()).collect();
    idx.sort_by(|&a, &b| importance[b].total_cmp(&importance[a]));
    idx
}

/// One Gaussian's record.
pub fn record(g: &Gaussians, i: usize) -> [u8; RECORD_BYTES] {
    let mut r = [0u8; RECORD_BYTES];
    let k = g.coeffs() * 3;
    let floats = g.means[i].into_iter().chain(g.scales[i].map(f32::exp));
    for (j, v) in floats.enumerate() {
        r[4 * j..4 * j + 4].copy_from_slice(&v.to_le_bytes());
    }
    for ch in 0..3 {
        let dc = f64::from(g.sh[i * k + ch]);
        r[24 + ch] = to_u8(((0.5 + SH_C0 * dc) * 255.0) as f32);
    }
    r[27] = to_u8(sigmoid(g.opacities[i]) * 255.0);
    for (j, q) in unit_quat(g.rotations[i]).into_iter().enumerate() {
        r[28 + j] = to_u8(q * 128.0 + 128.0);
    }
    r
}

/// The file's bytes.
pub fn encode(g: &Gaussians) -> Vec<u8> {
    let mut out = Vec::with_capacity(g.len() * RECORD_BYTES);
    for i in order(g) {
        out.extend_from_slice(&record(g, i));
    }
    out
}
