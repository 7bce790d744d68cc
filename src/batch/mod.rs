//! Many scenes from a manifest (`dreamscene batch`): manifest reading, sharding by scene id,
//! claiming scenes through their scene lock, resuming, and the shared `index.json` record.
//! There is no scheduler here: Slurm, Kubernetes or a shell loop starts the workers. Host-only.
pub mod index;
pub mod manifest;
pub mod shard;
pub mod worker;

/// Why a batch could not proceed.
#[derive(Debug, thiserror::Error)]
pub enum BatchError {
    #[error("{path}: {msg}")]
    Io { path: String, msg: String },
    #[error("{path}: {msg}")]
    Manifest { path: String, msg: String },
    #[error("{path}: {msg} (fix or remove it; the scene directories are kept)")]
    Index { path: String, msg: String },
}
