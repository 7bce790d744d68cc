//! Scenes: the scene directory (`scene.json`), composition of objects into the world frame
//! (`Rz(yaw) · diag(scale) · p + position`, with exact covariance and SH rotation) and the
//! environment. Host-only: never imports `ash` or `crate::gpu`.
pub mod compose;
pub mod dir;
pub mod env;
pub mod lock;
pub mod sh_rotate;
pub mod timeline;
