//! Gaussian splats: the differentiable rasterizer's orchestration, its kernels' typed wrappers,
//! the CPU reference, and file formats. Knows nothing of diffusion.
pub mod scan;
pub mod sort;
