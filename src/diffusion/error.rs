//! The diffusion layer's error: what went wrong, sorted by what a user can do about it.
use std::path::{Path, PathBuf};

/// Errors of the diffusion prior.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// ONNX Runtime (or an execution provider) could not be loaded or used.
    #[error("ONNX Runtime: {0}")]
    Runtime(String),
    /// A model directory that cannot be used as it is: missing files, ports of another shape.
    /// Shown as `msg` alone where it already begins with the path (the loader's messages name
    /// the directory or the file in it).
    #[error("{}", named(path, msg))]
    Model { path: PathBuf, msg: String },
    /// A model run or the guidance maths failed.
    #[error("diffusion: {0}")]
    Run(String),
    /// Inputs of sizes the models cannot take (renders not a multiple of 8, wrong lengths).
    #[error("diffusion input: {0}")]
    Input(String),
    /// The chosen prior cannot run as asked (no model directory, an unknown kind in scene.json).
    #[error("{0}")]
    Unavailable(String),
    /// The oracle was asked for something it has no reference for.
    #[error("oracle: {0}")]
    Oracle(String),
}

/// `msg`, prefixed with `path` unless it already begins with it: each path said once.
fn named(path: &Path, msg: &str) -> String {
    let shown = path.display().to_string();
    let rest = msg.strip_prefix(&shown).unwrap_or("");
    if rest.starts_with(':') || rest.starts_with('/') {
        msg.to_string()
    } else {
        format!("{shown}: {msg}")
    }
}

/// Result alias of the diffusion layer.
pub type Result<T, E = Error> = std::result::Result<T, E>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_model_error_says_its_path_once() {
        let e = |msg: &str| {
            Error::Model {
                path: PathBuf::from("/m"),
                msg: msg.into(),
            }
            .to_string()
        };
        assert_eq!(
            e("/m: model directory not found"),
            "/m: model directory not found"
        );
        assert_eq!(
            e("/m/unet/model.onnx: model file missing"),
            "/m/unet/model.onnx: model file missing"
        );
        assert_eq!(e("no UNet"), "/m: no UNet");
        assert_eq!(e("/mx: gone"), "/m: /mx: gone", "another path is no prefix");
    }
}
