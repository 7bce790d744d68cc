//! Outdoor grounds of the draft: the scene area's own surface (paving on a patio, decking on a
//! ship, sand on a beach) and what lies around it (a lawn round a patio, the sea round a ship,
//! the roofs round a rooftop), plus a parapet round a rooftop or a bulwark round a ship's
//! deck. Host-only and deterministic.
use super::colours::Pattern::{self, *};

const GRASS: [f32; 3] = [0.30, 0.50, 0.20];
const SAND: [f32; 3] = [0.86, 0.76, 0.55];
const PAVING: [f32; 3] = [0.66, 0.63, 0.58];
const LIGHT_PAVING: [f32; 3] = [0.80, 0.78, 0.73];
const COBBLES: [f32; 3] = [0.50, 0.48, 0.45];
const ASPHALT: [f32; 3] = [0.25, 0.25, 0.26];
const CONCRETE: [f32; 3] = [0.62, 0.62, 0.60];
const GRAVEL: [f32; 3] = [0.62, 0.60, 0.55];
const SNOW: [f32; 3] = [0.93, 0.95, 0.98];
const FOREST_FLOOR: [f32; 3] = [0.40, 0.38, 0.22];
const EARTH: [f32; 3] = [0.45, 0.40, 0.25];
const DECK: [f32; 3] = [0.55, 0.40, 0.26];
const SEA: [f32; 3] = [0.12, 0.32, 0.45];
const MOSS: [f32; 3] = [0.28, 0.42, 0.20];
/// Roofing felt and gravel seen over a rooftop's parapet.
const ROOFS: [f32; 3] = [0.36, 0.36, 0.38];
/// A rendered parapet wall.
const PARAPET: [f32; 3] = [0.80, 0.78, 0.74];

/// Ground of an outdoor scene kind: (kind, area colour, area pattern, surround colour, surround
/// pattern).
type KindGround = (&'static str, [f32; 3], Pattern, [f32; 3], Pattern);

/// The grounds of outdoor scene kinds; kinds not listed stand on grass all round.
#[rustfmt::skip]
const GROUNDS: &[KindGround] = &[
    ("patio", PAVING, Slabs, GRASS, Mottled),
    ("cafe terrace", PAVING, Slabs, COBBLES, Cobbles),
    ("pool area", LIGHT_PAVING, Slabs, GRASS, Mottled),
    ("beach", SAND, Speckled, SAND, Speckled),
    ("desert oasis", SAND, Speckled, SAND, Speckled),
    ("street", ASPHALT, Speckled, ASPHALT, Speckled),
    ("market", COBBLES, Cobbles, COBBLES, Cobbles),
    ("winter village", SNOW, Mottled, SNOW, Mottled),
    ("campsite", FOREST_FLOOR, Mottled, FOREST_FLOOR, Mottled),
    ("forest clearing", FOREST_FLOOR, Mottled, FOREST_FLOOR, Mottled),
    ("farm", EARTH, Mottled, GRASS, Mottled),
    ("zen garden", GRAVEL, Speckled, MOSS, Mottled),
    ("beer garden", GRAVEL, Speckled, GRASS, Mottled),
    ("basketball court", ASPHALT, Speckled, GRASS, Mottled),
    ("skate park", CONCRETE, Mottled, GRASS, Mottled),
    ("pirate ship deck", DECK, Planks, SEA, Mottled),
];

/// A ship's bulwark: the tarred timber wall round its deck.
const BULWARK: [f32; 3] = [0.30, 0.20, 0.12];

/// Outdoor scene kinds walled round at rail height (a ship's deck inside its bulwark): (kind,
/// the wall's colour).
const WALLED: &[(&str, [f32; 3])] = &[("pirate ship deck", BULWARK)];

/// Words that put a scene up on a building, on a roof or a balcony: paving inside a parapet,
/// roofs around.
const ROOF_WORDS: &[&str] = &[
    "rooftop",
    "roof",
    "roof-top",
    "roofs",
    "rooftops",
    "balcony",
    "balconies",
];

/// Height of a rooftop's parapet (metres): a guard-rail height.
pub const PARAPET_HEIGHT: f64 = 1.05;

/// The outdoor ground of a scene: its area, what surrounds it, and a rooftop's parapet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutdoorGround {
    pub area: ([f32; 3], Pattern),
    pub surround: ([f32; 3], Pattern),
    /// A parapet's colour round the area (rooftops; a ship's bulwark).
    pub parapet: Option<[f32; 3]>,
    /// Whether what the text says of the ground covers the surround too (one ground all round).
    pub one_ground: bool,
}

/// The ground of an outdoor scene of kind `kind` (a knowledge-base scene name) whose text has
/// the lower-case `words`.
pub fn outdoor_ground(kind: Option<&str>, words: &[String]) -> OutdoorGround {
    let roof = words.iter().any(|w| ROOF_WORDS.contains(&w.as_str()));
    if roof {
        return OutdoorGround {
            area: (PAVING, Slabs),
            surround: (ROOFS, Speckled),
            parapet: Some(PARAPET),
            one_ground: false,
        };
    }
    let found = kind.and_then(|k| GROUNDS.iter().find(|g| g.0 == k));
    let (area, surround) = match found {
        Some(&(_, ac, ap, sc, sp)) => ((ac, ap), (sc, sp)),
        None => ((GRASS, Mottled), (GRASS, Mottled)),
    };
    let walled = kind.and_then(|k| WALLED.iter().find(|g| g.0 == k));
    OutdoorGround {
        area,
        surround,
        parapet: walled.map(|g| g.1),
        one_ground: area == surround,
    }
}

/// Open water past one side of an outdoor ground (the sea along a beach, kb/placement.txt
/// `spans`): the ground where `sign * p[axis] > edge` is sea out to the horizon, `edge` its
/// water line (where the drawn sea's foam runs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shore {
    pub axis: usize,
    pub sign: f64,
    pub edge: f64,
}

impl Shore {
    /// How far the point (x, y) lies past the water line (negative: on land), and where it
    /// lies along the shore.
    pub fn beyond(&self, x: f64, y: f64) -> (f64, f64) {
        let p = [x, y];
        (self.sign * p[self.axis] - self.edge, p[1 - self.axis])
    }
}

/// The shore of a laid-out outdoor scene: the water line of a thing that spans a side (the
/// sea), turned with it; `None` indoors or with none.
pub fn shore_of(layout: &crate::plan::spec::Layout) -> Option<Shore> {
    if layout.scene_type != crate::plan::spec::SceneType::Outdoor {
        return None;
    }
    let table = crate::plan::gcp::classes::Placements::builtin();
    let o = layout
        .objects
        .iter()
        .find(|o| table.spans_side(&o.category))?;
    let (s, c) = o.yaw.to_radians().sin_cos();
    let front = [-s, c];
    let axis = usize::from(front[1].abs() > front[0].abs());
    // the land lies before its front: the water behind its water line, out past its back
    let sign = -front[axis].signum();
    let line = 0.5 * o.size[1] - crate::shape::shore_band(o.size[1]);
    Some(Shore {
        axis,
        sign,
        edge: sign * o.position[axis] - line,
    })
}

/// Sea foam and the breaking crests.
const FOAM: [f32; 3] = [0.92, 0.95, 0.97];
/// The sea by the shore, further out, and far out.
const SHALLOWS: [f32; 3] = [0.18, 0.50, 0.62];
const OPEN_SEA: [f32; 3] = [0.12, 0.40, 0.60];
const DEEP_SEA: [f32; 3] = [0.07, 0.25, 0.42];

/// The colour of the sea `beyond` metres past its water line, `along` the shore: a ragged
/// line of foam at the edge, water deepening away from it, and broken crests in rows roughly
/// parallel to the shore, wavering and sparser further out.
pub fn sea_colour(beyond: f64, along: f64) -> [f32; 3] {
    let mix = |a: [f32; 3], b: [f32; 3], t: f64| {
        let t = t.clamp(0.0, 1.0) as f32;
        [0, 1, 2].map(|k| a[k] + (b[k] - a[k]) * t)
    };
    let foam = 0.3 + 0.2 * (along * 1.3).sin() + 0.15 * (along * 0.37 + 1.0).sin();
    if beyond < foam.max(0.05) {
        return FOAM;
    }
    let water = if beyond < 4.0 {
        mix(SHALLOWS, OPEN_SEA, beyond / 4.0)
    } else {
        mix(OPEN_SEA, DEEP_SEA, (beyond - 4.0) / 20.0)
    };
    // crests: rows 3 m apart that waver along the shore, each broken into pieces
    let wavy = beyond + 0.5 * (along * 0.23 + 0.7 * beyond).sin() + 0.3 * (along * 0.61).sin();
    let row = (wavy / 3.0).floor();
    let f = wavy / 3.0 - row;
    let piece = (along / (1.5 + 0.5 * (row.rem_euclid(3.0)))).floor();
    let h = ((row * 12.9898 + piece * 78.233).sin() * 43_758.547).rem_euclid(1.0);
    let thin = 0.09 / (1.0 + 0.08 * beyond);
    if f < thin && h > 0.45 {
        mix(water, FOAM, 0.75)
    } else {
        water
    }
}
