//! Where things hung from the ceiling hang (a chandelier, pendant lights, a ceiling fan): from
//! the ceiling, clear of the walls, and over what they are said to hang over.
use super::{wall_distances, Box2, TOLERANCE};

/// Least gap between a ceiling thing's footprint and any wall (m): a person hangs a light or a
/// fan out in the room, not against a wall.
pub const CEILING_WALL_GAP: f64 = 0.5;

/// Whether `b` hangs from the ceiling of `room`: its top at the ceiling (within
/// [`TOLERANCE`]) and its footprint at least [`CEILING_WALL_GAP`] from every wall.
pub fn hangs_from_ceiling(b: &Box2, room: [f64; 3]) -> bool {
    (b.z1 - room[2]).abs() <= TOLERANCE
        && wall_distances(b, room)
            .iter()
            .all(|&d| d >= CEILING_WALL_GAP - TOLERANCE)
}

/// Whether `s` hangs over `o` in `room`: from the ceiling, its centre inside `o`'s footprint
/// and its bottom above `o`'s top.
pub fn hangs_over(s: &Box2, o: &Box2, room: [f64; 3]) -> bool {
    (s.z1 - room[2]).abs() <= TOLERANCE && o.contains(s.c) && s.z0 >= o.z1 - TOLERANCE
}
