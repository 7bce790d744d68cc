pub mod encode;
pub mod trajectory;
pub mod video;
