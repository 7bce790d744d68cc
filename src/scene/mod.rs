//! Scenes: the scene directory, composition of objects into the world, and the environment.
pub mod env;
