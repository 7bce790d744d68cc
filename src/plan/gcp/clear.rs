//! Fronts kept clear in the search (kb/placement.txt's front clearances, judged as
//! [`crate::plan::check::fronts`] judges them): a pose that stands before the front of a
//! placed thing that keeps one, or whose own front would take in a placed thing or a wall, costs more
//! than any relation it could satisfy there, unless the two are related or stacked (a stool at
//! its counter, a rug under a table); in a room too tight for anything else it is still taken.
use super::Problem;
use crate::plan::check::fronts::{blocks_front, front_zone};
use crate::plan::check::{wall_distances, Box2, TOLERANCE};

/// What a pose that blocks a front costs: more than two relations it could satisfy.
const FRONT_COST: f64 = 25.0;

impl Problem {
    /// [`FRONT_COST`] for each placed thing whose front instance `i` at box `b` blocks or that
    /// blocks `i`'s front.
    pub(super) fn front_cost(&self, i: usize, b: &Box2, boxes: &[Option<(Box2, [f64; 4])>]) -> f64 {
        // a front against a wall opens nowhere
        let walled = self.fronts[i].is_some_and(|d| {
            wall_distances(&front_zone(b, d), self.room)
                .iter()
                .any(|&v| v < -TOLERANCE)
        });
        FRONT_COST * (self.fronts_blocked_by(i, b, boxes) + walled as usize) as f64
    }

    /// How many placed things instance `i` at box `b` stands before the front of, or has
    /// before its own front (`boxes`: the placed instances' boxes).
    fn fronts_blocked_by(&self, i: usize, b: &Box2, boxes: &[Option<(Box2, [f64; 4])>]) -> usize {
        let own = self.fronts[i].map(|d| front_zone(b, d));
        boxes
            .iter()
            .enumerate()
            .filter(|(j, pb)| {
                let (j, pb) = (*j, *pb);
                let Some((bj, _)) = pb else { return false };
                if j == i || self.is_stacked(i, j) || self.rels[i].iter().any(|r| r.1 == j) {
                    return false;
                }
                let before_it = self.fronts[j].is_some_and(|d| blocks_front(b, &front_zone(bj, d)));
                let before_me = own.as_ref().is_some_and(|z| blocks_front(bj, z));
                before_it || before_me
            })
            .count()
    }
}
