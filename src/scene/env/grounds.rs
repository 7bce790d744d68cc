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
