//! The INRIA 3DGS PLY, as [`crate::splat::ply::write_ply`] writes it, and its "compat" form for
//! viewers that accept only the full layout: SH degree 3 (45 `f_rest`, zero where the cloud has
//! no such band, which leaves every colour unchanged) with normals, 62 floats = 248 bytes a
//! vertex. Both write the cloud in the frame they are given (see [`super`] for frames).
use super::{ExportError, Result};
use crate::scene::compose::pad_sh;
use crate::splat::ply::{write_ply_labelled, Labels};
use crate::splat::Gaussians;
use std::path::Path;

/// Bytes a vertex takes in the compat layout: 3 position + 3 normal + 3 DC + 45 rest + opacity +
/// 3 scales + 4 rotation floats.
pub const COMPAT_VERTEX_BYTES: usize = 62 * 4;

/// Writes `g` as an INRIA PLY at its own SH degree, atomically, with `labels` after the INRIA
/// properties when given.
pub fn write(path: &Path, g: &Gaussians, labels: Option<&Labels>) -> Result<()> {
    write_ply_labelled(path, g, labels).map_err(|source| ExportError::Write {
        path: path.display().to_string(),
        source,
    })
}

/// Writes `g` padded to SH degree 3 (the 248-byte vertex layout), atomically.
pub fn write_compat(path: &Path, g: &Gaussians, labels: Option<&Labels>) -> Result<()> {
    write(path, &pad_sh(g, 3), labels)
}
