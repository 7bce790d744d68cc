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

#[cfg(test)]
mod tests {
    use super::*;

    const ROOM: [f64; 3] = [5.0, 4.0, 2.8];

    fn table() -> Box2 {
        Box2::new([1.0, 0.5], 90.0, [1.8, 0.9], 0.0, 0.75)
    }

    #[test]
    fn a_light_at_the_ceiling_over_the_table_hangs_over_it() {
        let light = Box2::new([1.2, 0.6], 0.0, [0.8, 0.8], 2.05, 2.8);
        assert!(
            hangs_over(&light, &table(), ROOM),
            "centred, at the ceiling"
        );
        assert!(hangs_from_ceiling(&light, ROOM), "clear of the walls");
    }

    #[test]
    fn a_light_on_the_table_or_beside_it_does_not_hang_over_it() {
        let on = Box2::new([1.0, 0.5], 0.0, [0.8, 0.8], 0.75, 1.5);
        assert!(!hangs_over(&on, &table(), ROOM), "resting on the top");
        // the table is turned: 0.9 m wide along x, so x = 1.6 is beside it
        let beside = Box2::new([1.6, 0.5], 0.0, [0.8, 0.8], 2.05, 2.8);
        assert!(!hangs_over(&beside, &table(), ROOM), "beside it");
    }

    #[test]
    fn a_light_by_a_wall_or_below_the_ceiling_is_not_hung_from_it() {
        let by_wall = Box2::new([2.0, 0.0], 0.0, [0.8, 0.8], 2.05, 2.8);
        assert!(
            !hangs_from_ceiling(&by_wall, ROOM),
            "0.1 m from the east wall"
        );
        let low = Box2::new([0.0, 0.0], 0.0, [0.8, 0.8], 1.0, 1.75);
        assert!(!hangs_from_ceiling(&low, ROOM), "top below the ceiling");
    }
}
