//! The scene directory (`scene.json`) and composition of objects into the world frame
//! (`Rz(yaw) · diag(scale) · p + position`, with exact covariance and SH rotation). Host-only:
//! never imports `ash` or `crate::gpu`.
pub mod compose;
pub mod dir;
pub mod sh_rotate;
