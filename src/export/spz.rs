//! Niantic's `.spz`, version 2: gzip around a 16-byte header and six attribute streams. Version
//! 2 is the one every SPZ reader accepts (nianticlabs/spz reads 1 to 4; Spark, Babylon.js and
//! PlayCanvas splat-transform read 2 and 3; GaussianSplats3D reads 1 and 2). Layout and
//! quantisation follow nianticlabs/spz `src/cc/load-spz.cc` (`packGaussians`,
//! `serializePackedGaussians`):
//!
//! - header (little-endian): u32 magic `0x5053474e` ("NGSP"), u32 version 2, u32 count, u8 SH
//!   degree, u8 fractional bits (12), u8 flags (0), u8 reserved (0);
//! - positions: 3 x 24-bit signed fixed point a Gaussian, `round(v · 2^12)` (0.24 mm steps,
//!   ±2048 m range);
//! - alphas: `round(sigmoid(opacity) · 255)`;
//! - colours: `round(f_dc · 0.15 · 255 + 127.5)` per channel;
//! - scales: `round((log_scale + 10) · 16)`;
//! - rotations: x, y, z of the unit quaternion with w made non-negative, `round(q · 127.5 + 127.5)`;
//! - SH (degree 1 to 3): coefficient-major, channel-inner (opposite of the PLY's `f_rest`), each
//!   `round(x · 128) + 128` snapped to buckets of 8 (band 1, 5 bits) or 16 (bands 2-3, 4 bits).
//!
//! Every byte is clamped to 0..=255. SPZ stores the RUB frame of three.js/OpenGL, and its writers
//! take a PLY as RDF (the INRIA convention), so the conversion flips y and z: positions
//! `(x, -y, -z)`, quaternions `(w, x, -y, -z)`, and each SH coefficient times the parity of its
//! basis function under that flip (`flipSh` of nianticlabs/spz `splat-types.h`). Niantic's
//! reader undoes it when asked for RDF; three.js viewers draw RUB as it is (y up).
use super::{sigmoid, to_u8, unit_quat, ExportError, Result};
use crate::splat::Gaussians;
use flate2::write::GzEncoder;
use flate2::Compression;
use std::io::Write as _;

/// "NGSP", little-endian.
pub const MAGIC: u32 = 0x5053_474e;
/// The version written.
pub const VERSION: u32 = 2;
/// Fractional bits of the fixed-point positions (nianticlabs/spz's writer default).
pub const FRACTIONAL_BITS: u8 = 12;
/// Scale of the DC colour bytes (`colorScale` of nianticlabs/spz).
pub const COLOR_SCALE: f32 = 0.15;

/// Sign of each SH basis function (bands 1 to 3, 15 of them) when y and z are negated: the
/// function's parity in y and z. Band 1 is (y, z, x); band 2 (xy, yz, z², xz, x²-y²); band 3
/// (y(3x²-y²), xyz, y(5z²-1), z(5z²-3), x(5z²-1), z(x²-y²), x(x²-3y²)).
pub const FLIP_SH: [f32; 15] = [
    -1.0, -1.0, 1.0, // band 1
    -1.0, 1.0, 1.0, -1.0, 1.0, // band 2
    -1.0, 1.0, -1.0, -1.0, 1.0, -1.0, 1.0, // band 3
];

/// One SH value as a byte: 8-bit quantised, then snapped to the centre of its bucket.
fn quantize_sh(x: f32, bucket: i32) -> u8 {
    let q = (x * 128.0).round() as i32 + 128;
    let q = (q + bucket / 2) / bucket * bucket;
    q.clamp(0, 255) as u8
}

/// The uncompressed payload (header and streams).
pub fn payload(g: &Gaussians) -> Result<Vec<u8>> {
    let n = g.len();
    let count = u32::try_from(n).map_err(|_| {
        ExportError::Unrepresentable(format!("{n} Gaussians: SPZ holds at most 2^32 - 1"))
    })?;
    let k = g.coeffs();
    let mut out = Vec::with_capacity(16 + n * (9 + 1 + 3 + 3 + 3 + (k - 1) * 3));
    out.extend(MAGIC.to_le_bytes());
    out.extend(VERSION.to_le_bytes());
    out.extend(count.to_le_bytes());
    out.extend([g.sh_degree as u8, FRACTIONAL_BITS, 0, 0]);

    let one = f32::from(1u16 << FRACTIONAL_BITS);
    let limit = 1i64 << 23;
    for (i, m) in g.means.iter().enumerate() {
        for (axis, v) in [m[0], -m[1], -m[2]].into_iter().enumerate() {
            let fixed = (f64::from(v) * f64::from(one)).round() as i64;
            if fixed < -limit || fixed >= limit {
                return Err(ExportError::Unrepresentable(format!(
                    "Gaussian {i}: coordinate {} = {} m is outside SPZ's ±2048 m",
                    ["x", "y", "z"][axis],
                    m[axis]
                )));
            }
            out.extend(&(fixed as i32).to_le_bytes()[..3]);
        }
    }
    out.extend(g.opacities.iter().map(|&o| to_u8(sigmoid(o) * 255.0)));
    for i in 0..n {
        for ch in 0..3 {
            let dc = g.sh[i * k * 3 + ch];
            out.push(to_u8(dc * (COLOR_SCALE * 255.0) + 127.5));
        }
    }
    for s in &g.scales {
        out.extend(s.map(|v| to_u8((v + 10.0) * 16.0)));
    }
    for q in &g.rotations {
        let [w, x, y, z] = unit_quat(*q);
        let (x, y, z) = (x, -y, -z);
        let sign = if w < 0.0 { -1.0 } else { 1.0 };
        out.extend([x, y, z].map(|v| to_u8(v * sign * 127.5 + 127.5)));
    }
    for i in 0..n {
        for c in 1..k {
            let bucket = if c <= 3 { 8 } else { 16 };
            for ch in 0..3 {
                let v = g.sh[(i * k + c) * 3 + ch] * FLIP_SH[c - 1];
                out.push(quantize_sh(v, bucket));
            }
        }
    }
    Ok(out)
}

/// The file's bytes: the payload, gzip-compressed.
pub fn encode(g: &Gaussians) -> Result<Vec<u8>> {
    let raw = payload(g)?;
    let io = |e: std::io::Error| ExportError::Unrepresentable(format!("gzip: {e}"));
    let mut gz = GzEncoder::new(Vec::with_capacity(raw.len() / 2), Compression::default());
    gz.write_all(&raw).map_err(io)?;
    gz.finish().map_err(io)
}

#[cfg(test)]
mod tests {
    use super::quantize_sh;

    #[test]
    fn sh_bytes_snap_to_bucket_centres_and_keep_zero() {
        assert_eq!(quantize_sh(0.0, 8), 128);
        assert_eq!(quantize_sh(0.0, 16), 128);
        // 0.1 * 128 = 12.8 -> 141 -> bucket of 8 around 144.
        assert_eq!(quantize_sh(0.1, 8), 144);
        assert_eq!(quantize_sh(5.0, 16), 255);
        assert_eq!(quantize_sh(-5.0, 16), 0);
    }
}
