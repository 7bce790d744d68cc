//! Scene planning: the SceneSpec / Layout contracts, their semantics, and the graph-based
//! constraint placement. Pure host code: never imports `ash`.
pub mod capacity;
pub mod check;
pub mod colours;
pub mod conform;
pub mod dialogue;
pub mod draw;
pub mod finish;
pub mod gcp;
pub mod groups;
pub mod kb;
pub mod lang;
pub mod lexicon;
pub mod llm;
pub mod offline;
pub mod roles;
pub mod seating;
pub mod spec;
pub mod understood;
pub mod units;
