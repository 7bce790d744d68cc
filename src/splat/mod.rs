//! Gaussian splats: the differentiable rasterizer's orchestration, its kernels' typed wrappers,
//! the CPU reference, and file formats. Knows nothing of diffusion.
pub mod adam;
pub mod backward;
pub mod cloud;
pub mod guided;
pub mod loss;
pub mod ply;
pub mod raster;
pub mod reference;
pub mod reference_grad;
pub mod scan;
pub mod score;
pub mod sort;
pub mod train;
pub mod view;

pub use cloud::Gaussians;
