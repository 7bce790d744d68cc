//! The room a layout is given when the spec names none.
use super::WALKWAY;
use crate::plan::spec::{Instance, Room, SceneType};

/// Occupancy the chosen room size aims at (footprint area / floor area).
pub const INDOOR_OCCUPANCY: f64 = 0.4;
const OUTDOOR_OCCUPANCY: f64 = 0.2;

/// A room that fits the instances: floor area = footprints / occupancy (aspect 5:4), never
/// narrower than the largest object plus a walkway, height above the tallest object.
pub fn choose_room(instances: &[Instance], scene: SceneType) -> Room {
    let occ = match scene {
        SceneType::Indoor => INDOOR_OCCUPANCY,
        SceneType::Outdoor => OUTDOOR_OCCUPANCY,
    };
    // Stacked things (a TV on a stand) still count: a slight overestimate is harmless.
    let area: f64 = instances.iter().map(|i| i.size[0] * i.size[1]).sum::<f64>() / occ;
    let min_side = match scene {
        SceneType::Indoor => 3.0,
        SceneType::Outdoor => 8.0,
    };
    let longest = instances
        .iter()
        .map(|i| i.size[0].max(i.size[1]))
        .fold(0.0, f64::max);
    let w = (area * 1.25)
        .sqrt()
        .max(min_side)
        .max(longest + 2.0 * WALKWAY);
    let d = (area / w).max(min_side).max(longest + 2.0 * WALKWAY);
    let tallest = instances.iter().map(|i| i.size[2]).fold(0.0, f64::max);
    let h = match scene {
        SceneType::Indoor => (tallest + 0.3).max(2.8),
        SceneType::Outdoor => (tallest + 2.0).max(10.0),
    };
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    Room {
        size: [r(w), r(d), r(h)],
    }
}
