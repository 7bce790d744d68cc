//! The diffusion prior: noise-schedule maths and the guidance rules of the method (MTS, pseudo
//! ground truth, editing, and the ablations' SDS / ISM / DreamTime), written against a noise
//! predictor trait that the ONNX Runtime UNet implements. Knows nothing of splats or Vulkan.
pub mod guidance;
pub mod schedule;
pub mod tokenizer;
