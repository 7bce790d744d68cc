//! Things that line the walls, counted by the room ("bookcases along every wall", "a corridor
//! lined with lockers on both sides"): a plural the text gives no number for is as many as the
//! runs of the walls it names take once the room is sized, each its width and a hand's gap
//! apart, corners kept clear, and a share of each run left for the door, the windows and what
//! else stands there.
use super::Draft;
use crate::plan::spec::{SceneSpec, SceneType};

/// Share of every wall that a lining takes (a door, windows, a counter and corners besides).
const EVERY_WALL_SHARE: f64 = 0.5;
/// Share of one or two named walls it takes.
const NAMED_WALL_SHARE: f64 = 0.75;
/// Gap between neighbours in a run, metres.
const GAP: f64 = 0.1;
/// Outdoors (planters lining a terrace's edge, lanterns along a path's sides) neighbours stand
/// this many of their own widths apart: an open edge is dotted, not walled with them.
const OPEN_GAP: f64 = 1.0;
/// Most instances a lining adds up to (a long hall's walls are not a warehouse's stock).
const MOST: u32 = 24;

/// How many things `along` wide and `deep` deep line `walls` (1, 2, or 0 for every wall) of a
/// room `w` by `d` metres (the sides of an open ground when `open`).
pub(super) fn lining_count(walls: u32, along: f64, deep: f64, w: f64, d: f64, open: bool) -> u32 {
    let (long, short) = (w.max(d), w.min(d));
    let runs: &[f64] = match walls {
        1 => &[long],
        2 => &[long, long],
        _ => &[long, long, short, short],
    };
    let share = match walls {
        1 | 2 => NAMED_WALL_SHARE,
        _ => EVERY_WALL_SHARE,
    };
    let length: f64 = runs.iter().map(|l| (l - 2.0 * deep).max(0.0)).sum::<f64>() * share;
    let gap = if open { OPEN_GAP * along } else { GAP };
    ((length / (along + gap)).floor() as u32).min(MOST)
}

/// Raises the count of every lining mention of `d` to what the walls of `spec`'s room take;
/// true when a count changed (the spec is then built again for the new counts).
pub(super) fn fill_walls(d: &mut Draft, spec: &SceneSpec) -> bool {
    let Some(room) = spec.room else {
        return false;
    };
    let mut changed = false;
    for &(i, walls) in &d.r.lining {
        let Some(c) = d.cats.get(i) else { continue };
        let (Some(o), Some(&now)) = (spec.objects.get(c), d.counts.get(c)) else {
            continue;
        };
        let open = spec.scene_type == SceneType::Outdoor;
        let n = lining_count(
            walls,
            o.size[0],
            o.size[1],
            room.size[0],
            room.size[1],
            open,
        );
        if n > now {
            d.counts.insert(c.clone(), n);
            changed = true;
        }
    }
    changed
}

#[cfg(test)]
mod tests {
    use super::lining_count;

    #[test]
    fn a_lining_fills_the_runs_it_names() {
        // a 10 x 3 m corridor, lockers 0.9 wide and 0.5 deep down both long walls
        assert_eq!(lining_count(2, 0.9, 0.5, 10.0, 3.0, false), 13);
        // one wall only: half as many
        assert_eq!(lining_count(1, 0.9, 0.5, 10.0, 3.0, false), 6);
        // every wall of a 6 x 5 m shop, bookcases 1 m wide, 0.35 deep
        assert_eq!(lining_count(0, 1.0, 0.35, 6.0, 5.0, false), 8);
        // never more than a run's worth of a hall
        assert_eq!(lining_count(0, 0.5, 0.4, 40.0, 30.0, false), 24);
        // the open edge of a 10 x 8 m terrace, planters 0.6 wide: spaced, not a wall of them
        assert_eq!(lining_count(0, 0.6, 0.6, 10.0, 8.0, true), 13);
    }
}
