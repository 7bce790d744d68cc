//! dreamscene: text to editable 3D Gaussian-splat scenes on any Vulkan GPU.
#![deny(unsafe_op_in_unsafe_fn)]

pub mod batch;
pub mod bench;
pub mod bench_sd;
pub mod camera;
pub mod diffusion;
pub mod edit;
pub mod export;
pub mod generate;
pub mod gpu;
pub mod plan;
pub mod scene;
pub mod shape;
pub mod splat;
pub mod util;
