//! Wall spans: a thing against a wall stands where it leaves the wall things still to be
//! placed spans they fit in, as a furnisher runs cabinets from a corner or on from the last
//! one, not a sliver of wall away from them (a counter in the middle of a wall leaves half a
//! metre at each end, where the fridge no longer fits).
use super::{Pose, Problem, WALL_MARGIN};
use crate::plan::check::{wall_distances, Box2};
use crate::plan::spec::{Anchor, OpeningKind, SceneType};

/// Cost of a metre of wall left too narrow for any wall thing still to be placed, against the
/// search's other soft terms (a free walkway around a thing is worth at most 1.2).
const SLIVER_WEIGHT: f64 = 6.0;
/// Gaps this small are a thing standing beside another, not a wasted span (m).
const TOUCH: f64 = 0.05;

impl Problem {
    /// Whether instance `j` stands on the floor with its back to a wall.
    fn walled(&self, j: usize) -> bool {
        self.hung[j].is_none() && (self.faced[j] || self.inst[j].anchor == Anchor::Side)
    }

    /// The cost of the wall spans that instance `i` at box `b` leaves beside it, on the wall
    /// its back is against, too narrow for the narrowest wall thing not placed yet (0 when it
    /// is not against a wall or none is left to place).
    pub(super) fn sliver_cost(
        &self,
        i: usize,
        b: &Box2,
        placed: &[Option<Pose>],
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> f64 {
        if self.scene != SceneType::Indoor || !self.walled(i) {
            return 0.0;
        }
        let need = (0..self.inst.len())
            .filter(|&j| j != i && placed[j].is_none() && self.walled(j))
            .map(|j| self.inst[j].size[0].min(self.inst[j].size[1]))
            .fold(f64::INFINITY, f64::min);
        if !need.is_finite() {
            return 0.0;
        }
        let wd = wall_distances(b, self.room);
        let Some(k) = (0..4).min_by(|&a, &c| wd[a].total_cmp(&wd[c])) else {
            return 0.0;
        };
        if wd[k] > WALL_MARGIN + TOUCH {
            return 0.0;
        }
        // (walls -x, +x run along y; walls -y, +y along x)
        let (ax, across) = if k < 2 { (1, 0) } else { (0, 1) };
        let own = b.aabb();
        let (lo, hi) = (own[ax], own[ax + 2]);
        let depth = (own[across + 2] - own[across]).max(0.6);
        let half = 0.5 * self.room[ax];
        let wall_at = if k % 2 == 0 {
            -0.5 * self.room[across]
        } else {
            0.5 * self.room[across]
        };
        // what stands in the strip of wall this thing backs onto: placed floor things and
        // the doors' clear zones
        let in_strip = |a: &[f64; 4]| {
            let near = (a[across] - wall_at)
                .abs()
                .min((a[across + 2] - wall_at).abs());
            let spans = a[across] <= wall_at && a[across + 2] >= wall_at;
            near < depth || spans
        };
        let doors = self
            .openings
            .iter()
            .zip(&self.zones)
            .filter(|(o, _)| o.kind == OpeningKind::Door)
            .map(|(_, z)| z.aabb());
        let things = boxes
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i && self.hung[j].is_none())
            .filter_map(|(_, x)| x.as_ref().map(|x| x.1));
        let (mut left, mut right) = (-half, half);
        for a in things.chain(doors).filter(|a| in_strip(a)) {
            if a[ax + 2] <= lo + TOUCH {
                left = left.max(a[ax + 2]);
            } else if a[ax] >= hi - TOUCH {
                right = right.min(a[ax]);
            }
        }
        let wasted = |g: f64| if g > TOUCH && g < need { g } else { 0.0 };
        SLIVER_WEIGHT * (wasted(lo - left) + wasted(right - hi))
    }
}
