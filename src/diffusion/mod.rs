//! The diffusion prior: noise-schedule maths and the guidance rules of the method (MTS, pseudo
//! ground truth, editing, and the ablations' SDS / ISM / DreamTime), the CLIP tokenizer, and the
//! Stable Diffusion models run in ONNX Runtime. Knows nothing of splats or Vulkan.
pub mod convert;
pub mod error;
pub mod guidance;
pub mod model;
pub mod probe;
pub mod runtime;
pub mod schedule;
pub mod target;
pub mod tokenizer;
pub mod webgpu;

pub use error::Error;
