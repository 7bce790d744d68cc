//! Counters staff stand behind (kb/placement.txt: staffed; a reception desk, a checkout): one
//! the text does not put at a wall itself stands with its back the staff's depth off a wall,
//! facing the room (its poses are the wall poses moved out by that depth, see
//! `Problem::all_candidates`), and the band behind it stays free of what is not related to it.
use super::Problem;
use crate::plan::check::{overlap_depth, wall_distances, Box2};

/// What a pose that stands in a staff band costs (or whose own band would take in a placed
/// thing): as much as a blocked front (`clear.rs`).
const STAFF_COST: f64 = 25.0;
/// Overlap (m) a band tolerates: a thing beside the counter brushing its corner.
const BRUSH: f64 = 0.05;
/// What a band that closes a corner of the room costs (nearer a second wall than
/// [`CORNER_DISTANCE`] and a thing's width): the corner is lost to a plant or a cabinet.
const CORNER_COST: f64 = 5.0;
/// How far (m) from a second wall a band leaves a corner usable.
const CORNER_DISTANCE: f64 = 0.6;

/// The band behind footprint `b` where its staff stand, `depth` deep.
fn staff_zone(b: &Box2, depth: f64) -> Box2 {
    let c = [
        b.c[0] - b.ey[0] * (b.half[1] + 0.5 * depth),
        b.c[1] - b.ey[1] * (b.half[1] + 0.5 * depth),
    ];
    let yaw = (-b.ey[0]).atan2(b.ey[1]).to_degrees();
    Box2::new(c, yaw, [2.0 * b.half[0], depth], 0.0, 2.0)
}

impl Problem {
    /// [`STAFF_COST`] for each placed thing, not related to instance `i`, that `i` at box `b`
    /// stands in the staff band of, or that stands in `i`'s own band.
    pub(super) fn staff_cost(&self, i: usize, b: &Box2, boxes: &[Option<(Box2, [f64; 4])>]) -> f64 {
        let own = (self.staff[i] > 0.0).then(|| staff_zone(b, self.staff[i]));
        let n = boxes
            .iter()
            .enumerate()
            .filter(|&(j, pb)| {
                let Some((bj, _)) = pb else { return false };
                if j == i
                    || self.is_stacked(i, j)
                    || self.rels[i].iter().any(|r| r.1 == j)
                    || self.hung[j].is_some()
                    || self.hung[i].is_some()
                {
                    return false;
                }
                let in_theirs =
                    self.staff[j] > 0.0 && overlap_depth(b, &staff_zone(bj, self.staff[j])) > BRUSH;
                let in_mine = own.as_ref().is_some_and(|z| overlap_depth(bj, z) > BRUSH);
                in_theirs || in_mine
            })
            .count();
        // (its band against the wall behind it, and near another: a corner closed)
        let corner = own.as_ref().is_some_and(|z| {
            let wd = wall_distances(z, self.room);
            wd.iter().filter(|&&d| d < CORNER_DISTANCE).count() >= 2
        });
        STAFF_COST * n as f64 + if corner { CORNER_COST } else { 0.0 }
    }
}
