//! A thing hung on a wall above a thing that stands on the floor (a shelf on the wall above the
//! desk, a mirror above the dresser, a clock above the stove) hangs on the wall that thing stands
//! against, over it: its centre within the thing's span along that wall.
use super::{yaw_facing, Pose, Problem, WALL_MARGIN};
use crate::plan::check::{wall_distances, Box2, WALL_NORMALS};

/// How far from the wall the thing below may stand and still have the wall "above" it (m).
const BELOW_REACH: f64 = 0.5;

impl Problem {
    /// The wall (in [`wall_distances`] order) nearest the footprint `below`.
    fn wall_behind(&self, below: &Box2) -> usize {
        let wd = wall_distances(below, self.room);
        (0..4).min_by(|&a, &b| wd[a].total_cmp(&wd[b])).unwrap_or(0)
    }

    /// Poses of wall-hung `i` on the wall behind the thing it hangs above, over it: centred
    /// first, then along its span.
    pub(super) fn above_poses(&self, i: usize, placed: &[Option<Pose>]) -> Vec<Pose> {
        let Some(j) = self.above[i] else {
            return vec![];
        };
        let Some(pj) = placed[j] else {
            return vec![];
        };
        let below = self.boxed(j, &pj);
        let wall = self.wall_behind(&below);
        let [x0, y0, x1, y1] = below.aabb();
        let (lo, hi) = if wall < 2 { (y0, y1) } else { (x0, x1) };
        let s = self.inst[i].size;
        let (hw, hd) = (0.5 * self.room[0], 0.5 * self.room[1]);
        let half_room = if wall < 2 { hd } else { hw };
        let off = WALL_MARGIN + 0.5 * s[1];
        let n = WALL_NORMALS[wall];
        let yaw = yaw_facing(n);
        // (over its top: a tall mirror above a low cabinet hangs higher, if the ceiling lets it)
        let z0 = self.hung[i].unwrap_or(0.0);
        let z = if z0 < below.z1 + 0.05 && below.z1 + 0.05 + s[2] <= self.room[2] - 0.05 {
            below.z1 + 0.05
        } else {
            z0
        };
        let mid = 0.5 * (lo + hi);
        let room_along = (half_room - 0.5 * s[0]).max(0.0);
        [0.0, -0.25, 0.25, -0.45, 0.45]
            .into_iter()
            .map(|t| (mid + t * (hi - lo)).clamp(-room_along, room_along))
            .map(|a| {
                let c = match wall {
                    0 => [-hw + off, a],
                    1 => [hw - off, a],
                    2 => [a, -hd + off],
                    _ => [a, hd - off],
                };
                Pose { c, yaw, z }
            })
            .collect()
    }

    /// For wall-hung `i` (box `b`) above a placed thing: whether it hangs over it (on the wall
    /// the thing stands against, its centre within the thing's span along that wall), and how
    /// far its centre is from the middle of that span (m).
    pub(super) fn above_holds(
        &self,
        i: usize,
        b: &Box2,
        placed: &[Option<Pose>],
    ) -> Option<(bool, f64)> {
        let j = self.above[i]?;
        let below = self.boxed(j, &placed[j]?);
        let wall = self.wall_behind(&below);
        let on_wall = wall_distances(b, self.room)[wall] <= WALL_MARGIN + 0.03;
        let [x0, y0, x1, y1] = below.aabb();
        let (lo, hi, at) = if wall < 2 {
            (y0, y1, b.c[1])
        } else {
            (x0, x1, b.c[0])
        };
        let near = wall_distances(&below, self.room)[wall] <= BELOW_REACH;
        let holds = on_wall && near && (lo..=hi).contains(&at);
        let off = if on_wall {
            (at - 0.5 * (lo + hi)).abs()
        } else {
            crate::plan::check::gap(b, &below) + 0.5 * (hi - lo)
        };
        Some((holds, off))
    }
}
