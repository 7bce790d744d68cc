//! Outputs people take into other tools: videos ([`video`], [`encode`], camera paths in
//! [`trajectory`]) and splat files other tools open: the INRIA PLY (plain, or padded for viewers that insist on
//! SH degree 3), antimatter15's `.splat`, Niantic's `.spz` (version 2, gzip) and glTF 2.0 binary
//! with `KHR_gaussian_splatting`. One file per format; each encoder takes a [`Gaussians`] cloud
//! in the project's world frame (z up) and returns the file's bytes, applying the frame
//! conversion its format defines. The splat formats are host-only; the video side renders on
//! the device.
//!
//! [`load_input`] is the one place that turns a command's input path (a scene directory or a
//! splat PLY) into the cloud to export.
pub mod encode;
pub mod glb;
pub mod ply;
pub mod splat;
pub mod spz;
pub mod trajectory;
pub mod video;

use crate::scene::dir::{compose_scene, read_scene, SceneError};
use crate::splat::ply::{read_ply, PlyError};
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
}

/// Why an export failed.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error(transparent)]
    Ply(#[from] PlyError),
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The input is neither a scene directory nor a splat PLY.
    #[error("{0}")]
    Input(String),
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

/// The cloud an input path stands for: a scene directory gives its merged world-frame
/// `scene.ply` (composed from `scene.json` when the directory has no `scene.ply` yet); a file is
/// read as a splat PLY.
pub fn load_input(path: &Path) -> Result<Gaussians> {
    if path.is_dir() {
        let merged = path.join("scene.ply");
        if merged.is_file() {
            return Ok(read_ply(&merged)?);
        }
        if path.join("scene.json").is_file() {
            let scene = read_scene(path)?;
            return Ok(compose_scene(path, &scene)?);
        }
        return Err(ExportError::Input(format!(
            "{}: not a scene directory (no scene.ply or scene.json in it)",
            path.display()
        )));
    }
    if !path.exists() {
        return Err(ExportError::Input(format!(
            "{}: no such file or directory",
            path.display()
        )));
    }
    Ok(read_ply(path)?)
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

/// Writes `g` in `format` to `out` atomically (a temporary sibling renamed over it), so a failed
/// export never leaves half a file or spoils an older one. `compat` applies to PLY only.
pub fn export(g: &Gaussians, format: Format, opts: Options, out: &Path) -> Result<()> {
    check_exportable(g)?;
    let bytes = match format {
        Format::Ply if opts.compat => return ply::write_compat(out, g),
        Format::Ply => return ply::write(out, g),
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
