//! Pinhole cameras in the 3DGS/COLMAP convention (x right, y down, z forward; principal point at
//! the image centre; pixel (i, j) centred at (i + 0.5, j + 0.5)) and the INRIA `cameras.json` format.
//! Never imports `ash`.
pub mod object;
pub mod scene;

use serde::{Deserialize, Serialize};
use std::path::Path;

/// One camera. `rotation` is camera-to-world (rows), `position` the camera centre in world space.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Camera {
    pub id: u32,
    pub img_name: String,
    pub width: u32,
    pub height: u32,
    pub position: [f64; 3],
    pub rotation: [[f64; 3]; 3],
    pub fx: f64,
    pub fy: f64,
}

/// Errors reading or validating cameras.
#[derive(Debug, thiserror::Error)]
pub enum CameraError {
    #[error("{path}: {msg}")]
    Invalid { path: String, msg: String },
}

impl Camera {
    /// A camera at `eye` looking at `target` with world `up`, vertical field of view `fov_y` radians.
    pub fn look_at(
        eye: [f64; 3],
        target: [f64; 3],
        up: [f64; 3],
        width: u32,
        height: u32,
        fov_y: f64,
    ) -> Camera {
        let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let cross = |a: [f64; 3], b: [f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let norm = |a: [f64; 3]| {
            let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
            [a[0] / l, a[1] / l, a[2] / l]
        };
        let z = norm(sub(target, eye));
        let mut x = cross(z, up);
        if x.iter().map(|v| v * v).sum::<f64>() < 1e-12 {
            x = cross(z, [1.0, 0.0, 0.0]);
        }
        let x = norm(x);
        let y = cross(z, x);
        let f = 0.5 * height as f64 / (0.5 * fov_y).tan();
        Camera {
            id: 0,
            img_name: "view".into(),
            width,
            height,
            position: eye,
            // camera-to-world: its columns are the camera axes in world space.
            rotation: [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]],
            fx: f,
            fy: f,
        }
    }

    /// World-to-camera rotation (rows) and translation: `p_cam = R * p_world + t`.
    pub fn world_to_camera(&self) -> ([[f64; 3]; 3], [f64; 3]) {
        let r = &self.rotation;
        let rt = [
            [r[0][0], r[1][0], r[2][0]],
            [r[0][1], r[1][1], r[2][1]],
            [r[0][2], r[1][2], r[2][2]],
        ];
        let p = self.position;
        let t = [
            -(rt[0][0] * p[0] + rt[0][1] * p[1] + rt[0][2] * p[2]),
            -(rt[1][0] * p[0] + rt[1][1] * p[1] + rt[1][2] * p[2]),
            -(rt[2][0] * p[0] + rt[2][1] * p[1] + rt[2][2] * p[2]),
        ];
        (rt, t)
    }

    fn validate(&self) -> Result<(), String> {
        if self.width == 0 || self.height == 0 || self.width > 16384 || self.height > 16384 {
            return Err(format!(
                "camera {} has size {}x{} (1..16384 allowed)",
                self.id, self.width, self.height
            ));
        }
        if !(self.fx.is_finite() && self.fy.is_finite() && self.fx > 0.0 && self.fy > 0.0) {
            return Err(format!(
                "camera {} has focal lengths {} {}",
                self.id, self.fx, self.fy
            ));
        }
        if !self
            .position
            .iter()
            .chain(self.rotation.iter().flatten())
            .all(|v| v.is_finite())
        {
            return Err(format!("camera {} has a non-finite pose", self.id));
        }
        let r = &self.rotation;
        // R·Rᵀ must be the identity and det R = +1; 1e-3 leaves room for values printed with
        // six or seven digits (COLMAP and the INRIA converter write full precision).
        let mut off = 0.0f64;
        for i in 0..3 {
            for j in 0..3 {
                let d: f64 = (0..3).map(|k| r[i][k] * r[j][k]).sum();
                off = off.max((d - if i == j { 1.0 } else { 0.0 }).abs());
            }
        }
        let det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1])
            - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
            + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
        if off > 1e-3 || det <= 0.0 {
            return Err(format!(
                "camera {} (`{}`) has a `rotation` that is not a rotation matrix (R·Rᵀ differs \
                 from the identity by {off:.3}, determinant {det:.3})",
                self.id, self.img_name
            ));
        }
        self.check_img_name()
    }

    /// The file stem this camera's image has: `img_name`, or the id as five digits when empty.
    pub fn output_name(&self) -> String {
        if self.img_name.is_empty() {
            format!("{:05}", self.id)
        } else {
            self.img_name.clone()
        }
    }

    /// `img_name` must stay inside the directory it is joined to: a relative path of plain
    /// components (`sub/dir/view` is fine; `..`, `.`, an absolute path or a NUL are not).
    fn check_img_name(&self) -> Result<(), String> {
        let name = &self.img_name;
        let p = Path::new(name);
        let plain = p
            .components()
            .all(|c| matches!(c, std::path::Component::Normal(_)));
        if !plain || name.contains('\0') || name.ends_with('/') {
            return Err(format!(
                "camera {} has img_name `{name}`, which is not a relative path inside the output \
                 directory (no `..`, no leading `/`)",
                self.id
            ));
        }
        Ok(())
    }
}

/// Reads an INRIA `cameras.json`.
pub fn read_cameras(path: &Path) -> Result<Vec<Camera>, CameraError> {
    let err = |msg: String| CameraError::Invalid {
        path: path.display().to_string(),
        msg,
    };
    if path.is_dir() {
        return Err(err(
            "is a directory; expected an INRIA cameras.json file".into()
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| err(e.to_string()))?;
    let cams = parse_cameras(&bytes).map_err(err)?;
    Ok(cams)
}

/// Parses and validates the text of an INRIA `cameras.json`; errors are one line without the
/// file name.
pub fn parse_cameras(bytes: &[u8]) -> Result<Vec<Camera>, String> {
    let what = crate::util::describe_bytes(bytes);
    let text = std::str::from_utf8(bytes)
        .map_err(|_| format!("this file {what}; expected an INRIA cameras.json"))?;
    let cams: Vec<Camera> = serde_json::from_str(text).map_err(|e| {
        if what.starts_with("looks like a cameras.json") || what.starts_with("is a JSON list") {
            format!("not a cameras.json list: {e}")
        } else {
            format!("this file {what}; expected an INRIA cameras.json (a list of cameras)")
        }
    })?;
    if cams.is_empty() {
        return Err("no cameras in the file".into());
    }
    let mut seen = std::collections::HashMap::new();
    for c in &cams {
        c.validate()?;
        if let Some(other) = seen.insert(c.output_name(), c.id) {
            return Err(format!(
                "cameras {other} and {} have the same img_name `{}`; each image needs its own name",
                c.id,
                c.output_name()
            ));
        }
    }
    Ok(cams)
}

/// Writes an INRIA `cameras.json`.
pub fn write_cameras(path: &Path, cams: &[Camera]) -> std::io::Result<()> {
    let text = serde_json::to_string_pretty(cams).map_err(std::io::Error::other)?;
    crate::util::write_atomic(path, text.as_bytes())
}
