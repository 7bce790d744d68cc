//! How a drawn thing is held up: standing (on the floor or on a support), hung on a wall, or
//! hung from the ceiling. The layout decides it (`plan::gcp::classes`); the drawing follows it,
//! so a thing hung on a wall has no legs dangling below it and a thing hung from the ceiling
//! hangs on a cord rather than standing on a foot in the air.
use crate::plan::gcp::classes::{effective_class, Class, Placements};
use crate::plan::spec::{SceneSpec, SceneType};

/// How a drawn thing is held up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mount {
    /// On the floor or on a support: its standing drawing (legs, a foot, a stand).
    #[default]
    Stand,
    /// Hung on a wall at a height: flat against it, nothing reaching down.
    Wall,
    /// Hung from the ceiling, the top of its box there: on a cord, chain or rod.
    Ceiling,
    /// Outdoors, where there is no wall to hang it on: drawn as hung on a wall, held up from
    /// the ground behind it by a post (two at the ends of a wide thing); the drop from the
    /// ground to its foot in centimetres.
    Post(u16),
}

impl Mount {
    /// The mount of a placement class.
    pub fn of_class(class: Class) -> Mount {
        match class {
            Class::OnWall(_) => Mount::Wall,
            Class::Ceiling => Mount::Ceiling,
            Class::Floor | Class::AgainstWall | Class::OnSurface(_) => Mount::Stand,
        }
    }

    /// The table's (`kb/placement.txt`) mount of `category`, when no scene says otherwise.
    pub fn of_category(category: &str) -> Mount {
        let c = category.trim().to_lowercase();
        let c = crate::plan::kb::KnowledgeBase::builtin()
            .object(&c)
            .map_or(c, |o| o.category.clone());
        Mount::of_class(Placements::builtin().class(&c))
    }

    /// The mount of `category` in `spec`, as the layout places it: a TV hangs on the wall of a
    /// room with no stand for it; outdoors there is no wall, so a wall thing stands where it is
    /// put, at its height, on posts from the ground (never floating in the air).
    pub fn in_scene(spec: &SceneSpec, category: &str) -> Mount {
        let outdoor = spec.scene_type == SceneType::Outdoor;
        match effective_class(spec, category) {
            Class::Ceiling if outdoor => Mount::Stand,
            Class::OnWall(h) if outdoor && h > 0.05 => Mount::Post((100.0 * h).round() as u16),
            class => Mount::of_class(class),
        }
    }

    /// How its own drawing is held up: a thing on posts is drawn as a wall thing (the posts
    /// are drawn below it, [`super::build`]).
    pub fn drawn(self) -> Mount {
        match self {
            Mount::Post(_) => Mount::Wall,
            m => m,
        }
    }
}
