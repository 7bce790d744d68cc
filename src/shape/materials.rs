//! Colours from words: the roles parts play (upholstery, legs, shade, foliage, …) with their
//! default colours, the material and colour-name tables, and the parser that turns a description
//! ("red velvet sofa with oak legs") into per-role colours. Data and string handling only.

pub use crate::plan::colours::{Class, Rgb, COLOURS, MATERIALS};

/// What a part is, for colouring.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Role {
    /// Upholstered body of a seat, a rug's field, a soft object.
    Upholstery,
    /// Loose cushions and a rug's border.
    Cushion,
    /// Seat and back of a chair or stool.
    Seat,
    /// Legs, frames, posts, rails.
    Frame,
    /// Table tops, counter tops, mantels, lids.
    Top,
    /// The carcass of cabinets, appliances, vehicles and most solid objects.
    Body,
    /// Doors and drawer fronts.
    Door,
    /// Handles, knobs, taps, small metal fittings.
    Handle,
    /// Bare metal: poles, bases, stands.
    Metal,
    /// Lamp shades and canopies.
    Shade,
    Foliage,
    Trunk,
    Pot,
    Soil,
    /// Displays and screens (dark).
    Screen,
    Mattress,
    Pillow,
    Duvet,
    Glass,
    /// See-through glass: a faint tint over what stands behind it (a display case's front, an
    /// aquarium's walls, a shower screen); drawn with a low opacity.
    Pane,
    Water,
    /// Books and products on shelves; coloured by variant from a palette.
    Books,
    /// Dark interiors: openings, fireboxes, shelf backs.
    Interior,
    Keys,
    BlackKeys,
    Tyre,
    Skin,
    /// Writing or picture surfaces (whiteboard, canvas).
    Canvas,
    /// Emissive-looking parts: bulbs, flames.
    Light,
    /// Rough natural stone (rocks, boulders): lumps differ in shade and a little in hue by
    /// variant, like weathered rock.
    Stone,
}

impl Role {
    /// The colour of a role when neither the description nor the archetype says otherwise.
    pub fn default_colour(self) -> Rgb {
        use Role::*;
        match self {
            Upholstery => [0.55, 0.55, 0.57],
            Cushion => [0.62, 0.61, 0.62],
            Seat => [0.55, 0.38, 0.22],
            Frame => [0.45, 0.30, 0.18],
            Top => [0.60, 0.43, 0.27],
            Body => [0.58, 0.42, 0.27],
            Door => [0.62, 0.46, 0.30],
            Handle => [0.75, 0.72, 0.66],
            Metal => [0.30, 0.30, 0.32],
            Shade => [0.90, 0.85, 0.74],
            Foliage => [0.20, 0.48, 0.18],
            Trunk => [0.38, 0.27, 0.17],
            Pot => [0.74, 0.42, 0.28],
            Soil => [0.22, 0.15, 0.10],
            Screen => [0.05, 0.06, 0.08],
            Mattress => [0.93, 0.93, 0.91],
            Pillow => [0.96, 0.96, 0.95],
            Duvet => [0.88, 0.88, 0.86],
            Glass => [0.72, 0.84, 0.88],
            Pane => [0.80, 0.90, 0.94],
            Water => [0.20, 0.45, 0.62],
            Books => [0.50, 0.30, 0.20],
            Interior => [0.14, 0.11, 0.09],
            Keys => [0.96, 0.96, 0.94],
            BlackKeys => [0.05, 0.05, 0.05],
            Tyre => [0.08, 0.08, 0.08],
            Skin => [0.85, 0.68, 0.55],
            Canvas => [0.96, 0.96, 0.95],
            Light => [1.00, 0.93, 0.70],
            Stone => [0.55, 0.53, 0.49],
        }
    }

    /// Material classes that a material word may give this role.
    pub fn accepts(self, c: Class) -> bool {
        use Class as C;
        let ok: &[Class] = match self {
            Role::Upholstery | Role::Cushion => &[C::Fabric, C::Leather, C::Wicker],
            Role::Seat => &[
                C::Wood,
                C::Fabric,
                C::Leather,
                C::Plastic,
                C::Metal,
                C::Wicker,
            ],
            Role::Frame => &[C::Wood, C::Metal, C::Wicker, C::Plastic],
            Role::Top => &[C::Wood, C::Stone, C::Glass, C::Metal, C::Plastic],
            Role::Body | Role::Door => &[
                C::Wood,
                C::Metal,
                C::Plastic,
                C::Stone,
                C::Ceramic,
                C::Wicker,
                C::Paper,
            ],
            Role::Handle | Role::Metal => &[C::Metal],
            Role::Shade => &[C::Fabric, C::Glass, C::Paper],
            Role::Pot => &[C::Ceramic, C::Stone, C::Metal, C::Plastic, C::Wicker],
            Role::Mattress | Role::Pillow | Role::Duvet => &[C::Fabric],
            Role::Glass | Role::Pane => &[C::Glass],
            Role::Stone => &[C::Stone],
            _ => &[],
        };
        ok.contains(&c)
    }
}

/// Words naming a part: a colour or material word followed within two words by one of these
/// colours that part only ("walnut legs", "marble top", "linen shade").
const PART_WORDS: &[(&str, Role)] = &[
    ("top", Role::Top),
    ("tabletop", Role::Top),
    ("mantel", Role::Top),
    ("lid", Role::Top),
    ("legs", Role::Frame),
    ("leg", Role::Frame),
    ("frame", Role::Frame),
    ("base", Role::Frame),
    ("stand", Role::Frame),
    ("shade", Role::Shade),
    ("lampshade", Role::Shade),
    ("handles", Role::Handle),
    ("handle", Role::Handle),
    ("knobs", Role::Handle),
    ("cushions", Role::Cushion),
    ("cushion", Role::Cushion),
    ("pillows", Role::Pillow),
    ("pot", Role::Pot),
    ("doors", Role::Door),
    ("door", Role::Door),
    ("drawers", Role::Door),
    ("seat", Role::Seat),
    ("duvet", Role::Duvet),
    ("bedding", Role::Duvet),
    ("screen", Role::Screen),
    ("screens", Role::Screen),
    ("awning", Role::Shade),
    ("canopy", Role::Shade),
];

/// Words after a material that make it the material of a thing's fittings or trim
/// ("iron-bound", "brass-studded", "copper-banded"), not of the thing.
const TRIMS: &[&str] = &[
    "bound", "banded", "strapped", "studded", "trimmed", "hinged", "riveted", "edged", "capped",
    "tipped", "handled",
];

/// What a colour word says.
#[derive(Debug, Clone, PartialEq)]
pub enum WordKind {
    /// A colour name.
    Colour,
    /// A material of this class.
    Material(Class),
}

/// One colour or material word found in a description.
#[derive(Debug, Clone, PartialEq)]
pub struct ColourWord {
    /// The phrase as matched, with its modifier (`"dark green"`).
    pub phrase: String,
    pub kind: WordKind,
    /// The colour after light/dark modifiers.
    pub rgb: Rgb,
    /// The part it names, when a part word follows it ("oak legs" → `Frame`).
    pub part: Option<Role>,
}

fn modify(rgb: Rgb, m: &str) -> Rgb {
    match m {
        "light" | "pale" | "soft" => rgb.map(|c| c + (1.0 - c) * 0.4),
        "dark" | "deep" => rgb.map(|c| c * 0.55),
        "bright" | "vivid" => rgb.map(|c| (c * 1.15).min(1.0)),
        _ => rgb,
    }
}

/// The colour and material words of `description`, in order: each with its colour (light/pale,
/// dark/deep and bright modifiers applied) and the part word that follows it, if any.
pub fn colour_words(description: &str) -> Vec<ColourWord> {
    let lower = description.to_lowercase();
    let words: Vec<&str> = lower
        .split(|c: char| !c.is_ascii_alphabetic())
        .filter(|w| !w.is_empty())
        .collect();
    let mut out = vec![];
    let mut i = 0;
    while i < words.len() {
        let pair = (i + 1 < words.len()).then(|| format!("{} {}", words[i], words[i + 1]));
        let mut found = None;
        if let Some(p) = &pair {
            if let Some(m) = MATERIALS.iter().find(|m| m.0 == p) {
                found = Some((2, p.clone(), WordKind::Material(m.1), m.2));
            }
        }
        if found.is_none() {
            let w = words[i];
            if let Some(m) = MATERIALS.iter().find(|m| m.0 == w) {
                found = Some((1, w.to_string(), WordKind::Material(m.1), m.2));
            } else if let Some(c) = COLOURS.iter().find(|c| c.0 == w) {
                found = Some((1, w.to_string(), WordKind::Colour, c.1));
            }
        }
        let Some((n, phrase, kind, mut rgb)) = found else {
            i += 1;
            continue;
        };
        let mut phrase = phrase;
        if i > 0 {
            let m = words[i - 1];
            let modified = modify(rgb, m);
            if modified != rgb {
                rgb = modified;
                phrase = format!("{m} {phrase}");
            }
        }
        let mut part = words[i + n..]
            .iter()
            .take(2)
            .find_map(|w| PART_WORDS.iter().find(|p| p.0 == *w).map(|p| p.1));
        // "iron-bound", "brass-studded": the material of the fittings, not of the thing
        if words.get(i + n).is_some_and(|w| TRIMS.contains(w)) {
            if kind != WordKind::Material(Class::Metal) {
                i += n;
                continue;
            }
            part = Some(Role::Metal);
        }
        out.push(ColourWord {
            phrase,
            kind,
            rgb,
            part,
        });
        i += n;
    }
    out
}

/// Per-role colours for one object.
#[derive(Debug, Clone)]
pub struct Palette {
    colours: Vec<(Role, Rgb)>,
    /// Colours of the [`Role::Books`] parts (books and products on shelves), by variant.
    goods: &'static [Rgb],
}

impl Palette {
    /// Colours from `description` over the archetype's `defaults`: the first colour word without
    /// a part word colours the `main` roles; a word followed by a part word colours that part; a
    /// material word without a part word colours every role that accepts its class (a colour word
    /// keeps precedence on the main roles).
    pub fn new(description: &str, main: &[Role], defaults: &[(Role, Rgb)]) -> Palette {
        let mut colours: Vec<(Role, Rgb)> = defaults.to_vec();
        let set = |colours: &mut Vec<(Role, Rgb)>, role: Role, rgb: Rgb| {
            colours.retain(|c| c.0 != role);
            colours.push((role, rgb));
        };
        let words = colour_words(description);
        let mut fixed: Vec<Role> = vec![];
        // Part-named words first, then the first free colour word, then free materials.
        for w in words.iter().filter(|w| w.part.is_some()) {
            if let Some(r) = w.part {
                set(&mut colours, r, w.rgb);
                fixed.push(r);
            }
        }
        let free_colour = words
            .iter()
            .find(|w| w.part.is_none() && w.kind == WordKind::Colour);
        if let Some(w) = free_colour {
            for &r in main {
                if !fixed.contains(&r) {
                    set(&mut colours, r, w.rgb);
                    fixed.push(r);
                }
            }
        }
        for w in words.iter().filter(|w| w.part.is_none()) {
            if let WordKind::Material(class) = w.kind {
                // a material things are built of that none of the object's parts is usually
                // made of ("a stone bench": a bench's seat and frame are wood or metal) is what
                // the object itself is built of: its main structural parts take it (not what a
                // machine works on: a paper shredder's body is no paper)
                let builds = [Class::Stone, Class::Wood, Class::Metal, Class::Wicker];
                let own = builds.contains(&class) && main.iter().all(|r| !r.accepts(class));
                let drawn = colours.iter().any(|(r, _)| r.accepts(class));
                let structural = [Role::Seat, Role::Frame, Role::Body, Role::Top, Role::Door];
                let mains = main
                    .iter()
                    .copied()
                    .filter(|r| own && !drawn && structural.contains(r));
                for r in ALL_ROLES
                    .into_iter()
                    .filter(|r| r.accepts(class))
                    .chain(mains)
                {
                    if !fixed.contains(&r) {
                        set(&mut colours, r, w.rgb);
                        fixed.push(r);
                    }
                }
            }
        }
        Palette {
            colours,
            goods: super::goods::Goods::Books.palette(),
        }
    }

    /// This palette with `rgb` on `role`.
    pub fn with(mut self, role: Role, rgb: Rgb) -> Palette {
        self.colours.retain(|c| c.0 != role);
        self.colours.push((role, rgb));
        self
    }

    /// This palette with `goods` as the colours of its [`Role::Books`] parts (what a shelf
    /// holds: loaves, packs, toys…), chosen by variant.
    pub fn holding(self, goods: &'static [Rgb]) -> Palette {
        Palette { goods, ..self }
    }

    /// The colour of a part with this role and variant.
    pub fn colour(&self, role: Role, variant: u32) -> Rgb {
        if role == Role::Books {
            return self.goods[variant as usize % self.goods.len()];
        }
        let c = self
            .colours
            .iter()
            .find(|c| c.0 == role)
            .map_or(role.default_colour(), |c| c.1);
        // Leaf clusters and a rock's lumps differ in shade and a little in hue, like real
        // foliage and weathered stone.
        let shades: &[[f32; 3]] = match role {
            Role::Foliage => &[
                [1.0, 1.0, 1.0],
                [0.82, 0.88, 0.80],
                [1.1, 1.12, 0.95],
                [0.9, 0.95, 1.05],
                [1.15, 1.05, 0.85],
            ],
            // open water, the deep (darker, greener), the shallows (lighter, turquoise)
            Role::Water => &[[1.0, 1.0, 1.0], [0.7, 0.85, 0.85], [1.4, 1.3, 1.05]],
            Role::Stone => &[
                [1.0, 1.0, 1.0],
                [0.84, 0.83, 0.81],
                [1.08, 1.03, 0.94],
                [0.93, 0.88, 0.80],
                [1.14, 1.13, 1.11],
                [0.76, 0.76, 0.77],
            ],
            // glass and its sheen (a mirror's light streaks)
            Role::Canvas => &[[1.0, 1.0, 1.0], [1.22, 1.18, 1.14]],
            _ => return c,
        };
        let k = shades[variant as usize % shades.len()];
        [0, 1, 2].map(|i| (c[i] * k[i]).min(1.0))
    }
}

const ALL_ROLES: [Role; 13] = [
    Role::Upholstery,
    Role::Cushion,
    Role::Seat,
    Role::Frame,
    Role::Top,
    Role::Body,
    Role::Door,
    Role::Handle,
    Role::Metal,
    Role::Shade,
    Role::Pot,
    Role::Glass,
    Role::Stone,
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_carry_modifiers_and_parts() {
        let w =
            colour_words("A dark green velvet sofa with walnut legs and a stainless steel frame");
        let p: Vec<&str> = w.iter().map(|w| w.phrase.as_str()).collect();
        assert_eq!(p, ["dark green", "velvet", "walnut", "stainless steel"]);
        assert_eq!(w[2].part, Some(Role::Frame));
        assert!(w[0].rgb[1] < 0.55 * 0.56);
    }

    #[test]
    fn palette_puts_colour_on_main_and_material_on_parts() {
        let p = Palette::new("red velvet sofa with oak legs", &[Role::Upholstery], &[]);
        assert_eq!(p.colour(Role::Upholstery, 0), [0.78, 0.12, 0.10]);
        assert_eq!(p.colour(Role::Frame, 0), [0.64, 0.47, 0.29]);
        let p = Palette::new("kitchen island with a marble top", &[Role::Body], &[]);
        assert_eq!(p.colour(Role::Top, 0), [0.90, 0.89, 0.87]);
        assert_eq!(p.colour(Role::Body, 0), Role::Body.default_colour());
    }
}
