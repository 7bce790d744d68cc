//! INRIA 3DGS splat PLY: binary little-endian, one `vertex` element of float properties
//! `x y z nx ny nz f_dc_0..2 f_rest_* opacity scale_0..2 rot_0..3`; `f_rest` is channel-major.
//! Reads SH degree 0 to 3 in any property order, in any PLY encoding (see `read`); writes the
//! standard order.
mod header;
mod read;

use super::cloud::Gaussians;
pub use read::{parse_ply, Invalid, Labels, PlyRead};
use std::io::BufReader;
use std::path::Path;

/// A PLY that cannot be read, with the file and what is wrong.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {msg}")]
pub struct PlyError {
    pub path: String,
    pub msg: String,
}

/// Reads a splat PLY, refusing Gaussians with non-finite values or a zero rotation.
pub fn read_ply(path: &Path) -> Result<Gaussians, PlyError> {
    read_ply_with(path, Invalid::Refuse).map(|r| r.gaussians)
}

/// Reads a splat PLY (any encoding and property types; see [`parse_ply`]), refusing or dropping
/// invalid Gaussians as `invalid` says.
pub fn read_ply_with(path: &Path, invalid: Invalid) -> Result<PlyRead, PlyError> {
    let err = |msg: String| PlyError {
        path: path.display().to_string(),
        msg,
    };
    if path.is_dir() {
        return Err(err("is a directory; expected a splat PLY file".into()));
    }
    let file = std::fs::File::open(path).map_err(|e| err(e.to_string()))?;
    parse_ply(&mut BufReader::new(file), invalid).map_err(err)
}

/// Reads a splat PLY and its per-Gaussian labels, if it has them.
pub fn read_ply_labelled(path: &Path) -> Result<(Gaussians, Option<Labels>), PlyError> {
    read_ply_with(path, Invalid::Refuse).map(|r| (r.gaussians, r.labels))
}

/// Writes a splat PLY (through a temporary file, so a crash never leaves half a file).
pub fn write_ply(path: &Path, g: &Gaussians) -> std::io::Result<()> {
    write_ply_labelled(path, g, None)
}

/// Writes a splat PLY with `instance_id` (ushort) and `semantic_id` (uchar) after the INRIA
/// properties when `labels` is given (one of each per Gaussian).
pub fn write_ply_labelled(
    path: &Path,
    g: &Gaussians,
    labels: Option<&Labels>,
) -> std::io::Result<()> {
    g.check().map_err(std::io::Error::other)?;
    if let Some(l) = labels {
        if l.instance.len() != g.len() || l.semantic.len() != g.len() {
            return Err(std::io::Error::other(format!(
                "{} Gaussians but {} instance and {} semantic labels",
                g.len(),
                l.instance.len(),
                l.semantic.len()
            )));
        }
    }
    let k = g.coeffs();
    let per = k - 1;
    let mut header = String::from("ply\nformat binary_little_endian 1.0\n");
    header += &format!("element vertex {}\n", g.len());
    let mut names: Vec<String> = [
        "x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    names.extend((0..3 * per).map(|i| format!("f_rest_{i}")));
    names.push("opacity".into());
    names.extend((0..3).map(|i| format!("scale_{i}")));
    names.extend((0..4).map(|i| format!("rot_{i}")));
    for n in &names {
        header += &format!("property float {n}\n");
    }
    if labels.is_some() {
        header += "property ushort instance_id\nproperty uchar semantic_id\n";
    }
    header += "end_header\n";
    let mut out = header.into_bytes();
    out.reserve(g.len() * names.len() * 4);
    for i in 0..g.len() {
        let mut row: Vec<f32> = Vec::with_capacity(names.len());
        row.extend(g.means[i]);
        row.extend([0.0; 3]);
        row.extend((0..3).map(|ch| g.sh[i * k * 3 + ch]));
        for ch in 0..3 {
            for c in 1..k {
                row.push(g.sh[(i * k + c) * 3 + ch]);
            }
        }
        row.push(g.opacities[i]);
        row.extend(g.scales[i]);
        row.extend(g.rotations[i]);
        for v in row {
            out.extend(v.to_le_bytes());
        }
        if let Some(l) = labels {
            out.extend(l.instance[i].to_le_bytes());
            out.push(l.semantic[i]);
        }
    }
    crate::util::write_atomic(path, &out)
}
