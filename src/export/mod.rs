//! Outputs people take into other tools: videos ([`video`], [`encode`], camera paths in
//! [`trajectory`]; rendered on the device) and splat files other viewers open, host-only: the
//! INRIA PLY (plain, or padded for viewers that insist on SH degree 3), antimatter15's `.splat`,
//! Niantic's `.spz` (version 2, gzip) and glTF 2.0 binary with `KHR_gaussian_splatting`, one
//! file per format.
//!
//! Frames. The project's world is z up; splat viewers expect the frame of the captures they were
//! built for. PLY and `.splat` viewers (SuperSplat, antimatter15's viewer) take the
//! COLMAP/INRIA camera convention, x right, y down, z forward ("RDF"), so [`export`] rotates
//! the cloud +90° about x first ([`Z_UP_TO_RDF`]: world `(x, y, z)` is `(x, -z, y)`): up is -y,
//! the room's +y side is forward. SPZ's writer then applies Niantic's RDF-to-RUB conversion, so
//! SPZ holds the scene y up, as three.js viewers (Spark) show it. glTF is y up by definition
//! ([`glb::Z_UP_TO_Y_UP`]). [`Options::scene_frame`] keeps the world frame instead for PLY,
//! `.splat` and SPZ (a file to read back into dreamscene). Every rotation is applied exactly to
//! means, quaternions and SH bands ([`rotate`]).
//!
//! [`load_input`] is the one place that turns a command's input path (a scene directory or a
//! splat PLY) into the cloud to export.
pub mod collider;
pub mod encode;
pub mod engine;
pub mod glb;
pub mod instances;
pub mod labels;
pub mod navmesh;
pub mod ply;
pub mod splat;
pub mod spz;
pub mod trajectory;
pub mod video;

use crate::scene::compose::mat_to_quat;
use crate::scene::sh_rotate::{Mat3, ShRotation};
use crate::splat::Gaussians;
use std::path::Path;

/// The formats `export` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// INRIA 3DGS binary PLY.
    Ply,
    /// antimatter15's 32-byte records.
    Splat,
    /// Niantic SPZ, version 2 (gzip).
    Spz,
    /// glTF 2.0 binary with `KHR_gaussian_splatting`.
    Glb,
}

impl Format {
    /// The name `--format` takes, which is also the usual file extension.
    pub fn name(self) -> &'static str {
        match self {
            Format::Ply => "ply",
            Format::Splat => "splat",
            Format::Spz => "spz",
            Format::Glb => "glb",
        }
    }
}

/// Options that change what a format writes.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Options {
    /// PLY only: pad to SH degree 3 with normals (62 floats, 248 bytes a vertex).
    pub compat: bool,
    /// PLY, `.splat` and SPZ: keep the scene's z-up world frame instead of the viewers' RDF
    /// frame. glTF is always y up.
    pub scene_frame: bool,
}

/// The project's z-up world to the RDF frame of PLY viewers (x right, y down, z forward): +90°
/// about x, world `(x, y, z)` to `(x, -z, y)`.
pub const Z_UP_TO_RDF: Mat3 = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];

/// `g` turned by rotation `r` (a proper rotation matrix) about the origin: means `r · m`,
/// quaternions pre-multiplied by `r`'s (unit length, w >= 0; a zero one is left as it is),
/// SH bands rotated exactly. Scales, opacities and DC colours are unchanged. For the signed axis
/// permutations used here the means map exactly.
pub fn rotate(g: &Gaussians, r: &Mat3) -> Gaussians {
    let mut out = g.clone();
    for m in &mut out.means {
        let v = m.map(f64::from);
        *m = [0, 1, 2].map(|i| (r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2]) as f32);
    }
    let qr = mat_to_quat(r);
    for q in &mut out.rotations {
        let p = quat_mul(qr, q.map(f64::from));
        let n = p.iter().map(|v| v * v).sum::<f64>().sqrt();
        if n > 0.0 && n.is_finite() {
            let s = if p[0] < 0.0 { -1.0 / n } else { 1.0 / n };
            *q = p.map(|v| (v * s) as f32);
        }
    }
    if g.sh_degree > 0 {
        let shr = ShRotation::new(r, g.sh_degree);
        for block in out.sh.chunks_exact_mut(g.coeffs() * 3) {
            shr.apply_rgb(block);
        }
    }
    out
}

/// Hamilton product of quaternions (w, x, y, z).
fn quat_mul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// Why an export failed.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The input is neither a scene directory nor a splat PLY, or cannot be read.
    #[error(transparent)]
    Input(#[from] trajectory::TrajectoryError),
    /// The cloud cannot be written in the format (empty, non-finite, out of the format's range).
    #[error("{0}")]
    Unrepresentable(String),
    #[error("writing {path}: {source}")]
    Write {
        path: String,
        source: std::io::Error,
    },
}

/// Result of this module.
pub type Result<T> = std::result::Result<T, ExportError>;

/// The cloud an input path stands for, through the loader `video`, `render` and `view` use
/// ([`trajectory::open_input`]): a scene directory (or its `scene.json`) composed into its merged
/// world-frame cloud, the cloud `generate` writes as `scene.ply`, or a splat PLY.
/// With `time`, a scene's timeline is played to that time first.
pub fn load_input(path: &Path, time: Option<f64>) -> Result<Gaussians> {
    Ok(trajectory::open_input_at(path, time)?.cloud)
}

/// Checks what every format needs: consistent arrays, at least one Gaussian, finite numbers.
pub fn check_exportable(g: &Gaussians) -> Result<()> {
    g.check().map_err(ExportError::Unrepresentable)?;
    if g.is_empty() {
        return Err(ExportError::Unrepresentable(
            "the cloud has no Gaussians to export".into(),
        ));
    }
    let k = g.coeffs() * 3;
    for i in 0..g.len() {
        let finite = g.means[i].iter().all(|v| v.is_finite())
            && g.scales[i].iter().all(|v| v.is_finite())
            && g.rotations[i].iter().all(|v| v.is_finite())
            && g.opacities[i].is_finite()
            && g.sh[i * k..(i + 1) * k].iter().all(|v| v.is_finite());
        if !finite {
            return Err(ExportError::Unrepresentable(format!(
                "Gaussian {i} has a non-finite parameter (NaN or infinity)"
            )));
        }
    }
    Ok(())
}

/// Writes `g` (world frame) in `format` to `out` atomically (a temporary sibling renamed over
/// it), so a failed export never leaves half a file or spoils an older one. The cloud is first
/// turned into the format's frame (see the module notes).
pub fn export(g: &Gaussians, format: Format, opts: Options, out: &Path) -> Result<()> {
    export_labelled(g, None, format, opts, out)
}

/// [`export`] with per-Gaussian labels, which the PLY formats write as `instance_id` and
/// `semantic_id` (the other formats have no place for them).
pub fn export_labelled(
    g: &Gaussians,
    labels: Option<&crate::splat::ply::Labels>,
    format: Format,
    opts: Options,
    out: &Path,
) -> Result<()> {
    check_exportable(g)?;
    if opts.compat && format != Format::Ply {
        return Err(ExportError::Unrepresentable(
            "the compat layout is a PLY layout (--format ply)".into(),
        ));
    }
    if opts.scene_frame && format == Format::Glb {
        return Err(ExportError::Unrepresentable(
            "glTF is y up by definition: a .glb cannot keep the scene's z-up frame".into(),
        ));
    }
    let viewer;
    let g = if opts.scene_frame || format == Format::Glb {
        g
    } else {
        viewer = rotate(g, &Z_UP_TO_RDF);
        &viewer
    };
    let bytes = match format {
        Format::Ply if opts.compat => return ply::write_compat(out, g, labels),
        Format::Ply => return ply::write(out, g, labels),
        Format::Splat => splat::encode(g),
        Format::Spz => spz::encode(g)?,
        Format::Glb => glb::encode(g)?,
    };
    crate::util::write_atomic(out, &bytes).map_err(|source| ExportError::Write {
        path: out.display().to_string(),
        source,
    })
}

/// Logistic sigmoid, the activation of the stored opacity logits.
pub(crate) fn sigmoid(x: f32) -> f32 {
    1.0 / (1.0 + (-x).exp())
}

/// The unit quaternion (w, x, y, z) of a raw rotation; a zero-length one becomes the identity.
pub(crate) fn unit_quat(q: [f32; 4]) -> [f32; 4] {
    let n = q.iter().map(|v| v * v).sum::<f32>().sqrt();
    if n > 0.0 && n.is_finite() {
        q.map(|v| v / n)
    } else {
        [1.0, 0.0, 0.0, 0.0]
    }
}

/// Rounds to the nearest byte, clamped to 0..=255.
pub(crate) fn to_u8(x: f32) -> u8 {
    x.round().clamp(0.0, 255.0) as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(mean: [f32; 3]) -> Gaussians {
        Gaussians {
            means: vec![mean],
            scales: vec![[0.0; 3]],
            rotations: vec![[1.0, 0.0, 0.0, 0.0]],
            opacities: vec![0.0],
            sh: vec![0.0; 3],
            sh_degree: 0,
        }
    }

    #[test]
    fn frames_put_world_up_where_viewers_expect_it() {
        // RDF: up is -y, the room's +y side is forward (+z), x stays right.
        assert_eq!(
            rotate(&one([0.0, 0.0, 1.0]), &Z_UP_TO_RDF).means[0],
            [0.0, -1.0, 0.0]
        );
        assert_eq!(
            rotate(&one([0.0, 1.0, 0.0]), &Z_UP_TO_RDF).means[0],
            [0.0, 0.0, 1.0]
        );
        assert_eq!(
            rotate(&one([1.0, 0.0, 0.0]), &Z_UP_TO_RDF).means[0],
            [1.0, 0.0, 0.0]
        );
        // glTF: up is +y.
        let up = glb::Z_UP_TO_Y_UP;
        assert_eq!(rotate(&one([0.0, 0.0, 1.0]), &up).means[0], [0.0, 1.0, 0.0]);
        // The identity rotation of a Gaussian becomes the frame's rotation.
        let q = rotate(&one([0.0; 3]), &Z_UP_TO_RDF).rotations[0];
        let h = std::f32::consts::FRAC_1_SQRT_2;
        assert!((q[0] - h).abs() < 1e-6 && (q[1] - h).abs() < 1e-6, "{q:?}");
    }
}
