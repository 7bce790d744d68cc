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

/// Adds to `g` (a thing drawn as hung on a wall, its foot `drop` metres above the ground) the
/// posts that hold it up outdoors: one behind the middle of a narrow thing, one behind each end
/// of a wide one (string lights, a long sign), from a foot plate on the ground to two thirds up
/// its back; below and just behind its own box.
pub(super) fn posts(
    g: &mut crate::splat::Gaussians,
    size: [f64; 3],
    drop: f64,
    palette: &super::materials::Palette,
    spacing: f64,
    seed: u64,
) {
    let [w, d, h] = size;
    let r = (0.02 * (drop + h)).clamp(0.03, 0.06);
    let top = drop + 0.67 * h;
    // a box deep enough for the posts behind the thing's back
    let box_d = d + 4.0 * r + 0.02;
    let y = -d / 2.0 - r - 0.005;
    let xs: Vec<f64> = if w > 1.2 {
        vec![-(w / 2.0 - r), w / 2.0 - r]
    } else {
        vec![0.0]
    };
    let mut b = super::builder::Builder {
        parts: vec![],
        w,
        d: box_d,
        h: top,
        goods: None,
        animal: None,
        bird: None,
        variant: 0,
        mount: Mount::Stand,
    };
    for x in xs {
        b.cylinder(super::Role::Metal, [x, y, 0.0], r, top);
        b.cuboid(
            super::Role::Metal,
            [x - 2.5 * r, y - 2.5 * r, 0.0],
            [x + 2.5 * r, y + 2.5 * r, 0.02],
        );
    }
    let p = super::sample(
        &b.parts,
        palette,
        [w, box_d, top],
        spacing.min(0.03),
        seed ^ 0x9057,
    );
    g.means
        .extend(p.means.iter().map(|m| [m[0], m[1], m[2] - drop as f32]));
    g.scales.extend(p.scales);
    g.rotations.extend(p.rotations);
    g.opacities.extend(p.opacities);
    g.sh.extend(p.sh);
}
