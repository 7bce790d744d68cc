//! The diffusion layer's error: what went wrong, sorted by what a user can do about it.
use std::path::PathBuf;

/// Errors of the diffusion prior.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// ONNX Runtime (or an execution provider) could not be loaded or used.
    #[error("ONNX Runtime: {0}")]
    Runtime(String),
    /// A model directory that cannot be used as it is: missing files, ports of another shape.
    #[error("{}: {msg}", path.display())]
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

/// Result alias of the diffusion layer.
pub type Result<T, E = Error> = std::result::Result<T, E>;
