//! Editing a generated scene in place (paper §III-E): move, add, remove, restyle and animate
//! instances, and undo. Every edit is one transaction ([`txn`]): the changed files are staged,
//! the ones they replace kept in `history/NNNN/` for undo, `scene.ply` re-composed, the preview
//! views in `renders/` re-rendered, and the edit recorded in `scene.json`'s `history`; then
//! everything is put in place at once. The language of plain commands is [`parse`]; the
//! timeline maths live in [`crate::scene::timeline`].
pub mod animate;
pub mod commit;
pub mod destination;
pub mod ops;
pub mod parse;
pub mod reopt;
pub mod restyle;
pub mod riders;
pub mod state;
pub mod txn;
pub mod wanted;

pub use commit::{apply_edit, undo, Applied, Edit};
pub use state::SceneState;

/// Why an edit cannot be made. Every message is one line naming what is wrong.
#[derive(Debug, thiserror::Error)]
pub enum EditError {
    /// The request itself: an unknown id, a sentence that says nothing, a bad value.
    #[error("{0}")]
    Bad(String),
    /// A move that would collide, with the reasons (`--force` overrides).
    #[error("refused: {0} (nothing changed; --force places it anyway)")]
    Collision(String),
    /// An edit with no place free of collisions and no `--force` to override it (`add`).
    #[error("refused: {0} (nothing changed)")]
    NoRoom(String),
    #[error("{0}")]
    Io(String),
    #[error(transparent)]
    Scene(#[from] crate::scene::dir::SceneError),
    #[error(transparent)]
    Lock(#[from] crate::scene::lock::LockError),
    #[error(transparent)]
    Ply(#[from] crate::splat::ply::PlyError),
    #[error("GPU: {0}")]
    Gpu(String),
    /// The generator (its prior, its GPU work or its checkpoints) failed.
    #[error(transparent)]
    Gen(#[from] crate::generate::object::GenError),
}

impl From<crate::gpu::GpuError> for EditError {
    fn from(e: crate::gpu::GpuError) -> Self {
        EditError::Gpu(e.to_string())
    }
}

/// Result alias of the edit layer.
pub type Result<T, E = EditError> = std::result::Result<T, E>;
