//! Glue of the larger verbs, one file each.
pub mod generate;
pub mod object;
