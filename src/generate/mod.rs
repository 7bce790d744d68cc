//! The generators: object generation by Formation Pattern Sampling with any prior (`sd`,
//! `oracle`; `shape` needs no optimisation), its checkpoints, 3D Gaussian filtering and progress.
//! The only layer besides `edit` that combines the splat engine with the diffusion prior.
pub mod checkpoint;
pub mod filter;
pub mod object;
pub mod object_shard;
pub mod prior;
pub mod prior_spec;
pub mod progress;
pub mod scene;
pub mod scene_objects;
pub mod scene_stages;
pub mod sd_pool;
pub mod stage;
pub mod variants;
