//! Where a person hangs things from the ceiling. One said to hang over a thing (a chandelier
//! over the table) hangs centred over it, several in a row along its long side (pendant lights
//! above the island). Those said to hang nowhere: a lone one over the room's main piece (the
//! thing the most others gather at: a dining table, an island, a bed, a coffee table) or the
//! room's middle; several of a kind in a row over that piece when they fit along it, else
//! spread evenly over the room in a grid, clear of the walls.
use super::{Pose, Problem};
use crate::plan::check::ceiling::CEILING_WALL_GAP;
use crate::plan::spec::{Anchor, RelationKind};

/// Free length (m) between neighbours in a row over a piece that makes several lights no one
/// placed hang there: pendants over an island are not hung shade to shade.
const ROW_GAP: f64 = 0.3;
/// Least free length (m) between neighbours in a row said to hang over a piece (four pendants
/// over a short island hang closer rather than past its ends).
const ROW_GAP_ASKED: f64 = 0.05;
/// Steps (m) of the nudges tried around a hung thing's own spot when something tall stands
/// there.
const NUDGES: [f64; 3] = [0.15, 0.3, 0.5];

/// Whether a relation of a subject to a thing gathers the subject at it (seats round a table,
/// stools at an island, nightstands by a bed, a rug under it).
fn gathers(rel: RelationKind) -> bool {
    !matches!(
        rel,
        RelationKind::Over | RelationKind::Opposite | RelationKind::Row | RelationKind::Before
    )
}

impl Problem {
    /// The room's main piece among the placed things with a floor footprint of their own: the
    /// one kept for the middle, then the one the most others gather at (at least two), then
    /// the larger; none when nothing is gathered at.
    fn main_piece(&self, placed: &[Option<Pose>]) -> Option<usize> {
        (0..self.inst.len())
            .filter(|&j| {
                placed[j].is_some()
                    && self.hung[j].is_none()
                    && !self.rels[j].iter().any(|&(rel, _, subject)| {
                        subject && matches!(rel, RelationKind::Over | RelationKind::Under)
                    })
            })
            .map(|j| {
                let gathered = self.rels[j]
                    .iter()
                    .filter(|&&(rel, _, subject)| !subject && gathers(rel))
                    .count();
                let middle = self.inst[j].anchor == Anchor::Center;
                let s = self.inst[j].size;
                (j, middle, gathered, s[0] * s[1])
            })
            .filter(|&(_, middle, gathered, _)| middle || gathered >= 2)
            .max_by(|a, b| {
                (a.1, a.2)
                    .cmp(&(b.1, b.2))
                    .then(a.3.total_cmp(&b.3))
                    .then(b.0.cmp(&a.0))
            })
            .map(|t| t.0)
    }

    /// The ceiling things hung as one with `i` (same kind, hung over the same thing), in
    /// instance order.
    fn ceiling_group(&self, i: usize) -> Vec<usize> {
        (0..self.inst.len())
            .filter(|&k| {
                self.ceiling[k]
                    && self.inst[k].category == self.inst[i].category
                    && self.hang_over[k] == self.hang_over[i]
            })
            .collect()
    }

    /// Spots of `n` things of width `w` in a row along the long side of placed `j`'s
    /// footprint, centred over it: evenly over its length, at least `w` + [`ROW_GAP_ASKED`]
    /// apart.
    fn row_over(&self, j: usize, pj: &Pose, n: usize, w: f64) -> Vec<Pose> {
        let b = self.boxed(j, pj);
        let long = if b.half[0] >= b.half[1] { 0 } else { 1 };
        let axis = if long == 0 { b.ex } else { b.ey };
        let step = (2.0 * b.half[long] / n as f64).max(w + ROW_GAP_ASKED);
        (0..n)
            .map(|k| {
                let t = (k as f64 - 0.5 * (n as f64 - 1.0)) * step;
                Pose {
                    c: [b.c[0] + t * axis[0], b.c[1] + t * axis[1]],
                    yaw: pj.yaw,
                    z: 0.0,
                }
            })
            .collect()
    }

    /// Whether `n` things of width `w` fit in a row along placed `j`'s long side.
    fn row_fits(&self, j: usize, n: usize, w: f64) -> bool {
        let s = self.inst[j].size;
        s[0].max(s[1]) >= n as f64 * (w + ROW_GAP)
    }

    /// Spots of `n` things of footprint `s` spread evenly over the room: the centres of a grid
    /// of cells shaped like the room (a short last row centred), kept [`CEILING_WALL_GAP`]
    /// from the walls.
    fn grid_over_room(&self, n: usize, s: [f64; 3]) -> Vec<Pose> {
        let [w, d, _] = self.room;
        let cols = ((n as f64 * w / d).sqrt().round() as usize).clamp(1, n);
        let rows = n.div_ceil(cols);
        let cols = n.div_ceil(rows);
        let lim = |room: f64, half: f64| (0.5 * room - CEILING_WALL_GAP - half).max(0.0);
        let (lx, ly) = (lim(w, 0.5 * s[0]), lim(d, 0.5 * s[1]));
        let mut out = vec![];
        for r in 0..rows {
            let in_row = (n - r * cols).min(cols);
            let y = -0.5 * d + (r as f64 + 0.5) * d / rows as f64;
            for c in 0..in_row {
                let x = (c as f64 - 0.5 * (in_row as f64 - 1.0)) * w / cols as f64;
                out.push(Pose {
                    c: [x.clamp(-lx, lx), y.clamp(-ly, ly)],
                    yaw: 0.0,
                    z: 0.0,
                });
            }
        }
        out
    }

    /// `spot` moved the least to keep the footprint of ceiling thing `i` [`CEILING_WALL_GAP`]
    /// from the walls (to the room's middle line where the room is too narrow for that).
    fn clear_of_walls(&self, i: usize, spot: Pose) -> Pose {
        let [x0, y0, x1, y1] = self.boxed(i, &spot).aabb();
        let lim = |room: f64, half: f64| (0.5 * room - CEILING_WALL_GAP - half).max(0.0);
        let (lx, ly) = (
            lim(self.room[0], 0.5 * (x1 - x0)),
            lim(self.room[1], 0.5 * (y1 - y0)),
        );
        Pose {
            c: [spot.c[0].clamp(-lx, lx), spot.c[1].clamp(-ly, ly)],
            ..spot
        }
    }

    /// The spots of ceiling thing `i`'s group over placed `j`, kept clear of the walls where
    /// they stay over it; `None` when one does not and `strict` (a piece by a wall that no one
    /// asked to hang over: the room's middle or a grid is better). When `strict`, a spot kept
    /// clear of the walls must also stay over the middle half of the piece's depth (a light
    /// over a desk's front edge is no light over the desk).
    fn spots_over(
        &self,
        i: usize,
        j: usize,
        n: usize,
        strict: bool,
        placed: &[Option<Pose>],
    ) -> Option<Vec<Pose>> {
        let pj = placed[j]?;
        let below = self.boxed(j, &pj);
        let s = self.inst[i].size;
        let mut out = vec![];
        for spot in self.row_over(j, &pj, n, s[0].max(s[1])) {
            let clear = self.clear_of_walls(i, spot);
            let l = below.local(clear.c);
            let short = if below.half[0] >= below.half[1] { 1 } else { 0 };
            let centred = l[short].abs() <= 0.5 * below.half[short] + 1e-9;
            if below.contains(clear.c) && (centred || !strict) {
                out.push(clear);
            } else if strict {
                return None;
            } else {
                out.push(spot);
            }
        }
        Some(out)
    }

    /// Poses of ceiling thing `i`, the one it is given first: its own spot in its group's
    /// arrangement, the group's other spots, then nudges around its own. Empty when `i` does
    /// not hang from the ceiling or the thing it hangs over is not placed yet.
    pub(super) fn ceiling_poses(&self, i: usize, placed: &[Option<Pose>]) -> Vec<Pose> {
        if !self.ceiling[i] {
            return vec![];
        }
        let group = self.ceiling_group(i);
        let n = group.len();
        let k = group.iter().position(|&g| g == i).unwrap_or(0);
        let s = self.inst[i].size;
        let spots = match self.hang_over[i] {
            Some(j) => match self.spots_over(i, j, n, false, placed) {
                Some(spots) => spots,
                None => return vec![],
            },
            None => {
                let main = self
                    .main_piece(placed)
                    .filter(|&j| n == 1 || self.row_fits(j, n, s[0].max(s[1])))
                    .and_then(|j| self.spots_over(i, j, n, true, placed));
                match main {
                    Some(spots) => spots,
                    None if n == 1 => vec![Pose {
                        c: [0.0, 0.0],
                        yaw: 0.0,
                        z: 0.0,
                    }],
                    None => self.grid_over_room(n, s),
                }
            }
        };
        let z = self.hung[i].unwrap_or(0.0);
        let own = spots[k.min(spots.len() - 1)];
        let mut out = vec![own];
        out.extend(spots.iter().enumerate().filter(|e| e.0 != k).map(|e| *e.1));
        for r in NUDGES {
            for a in 0..8 {
                let (sn, cs) = (a as f64 * std::f64::consts::FRAC_PI_4).sin_cos();
                out.push(self.clear_of_walls(
                    i,
                    Pose {
                        c: [own.c[0] + r * cs, own.c[1] + r * sn],
                        ..own
                    },
                ));
            }
        }
        for p in &mut out {
            p.z = z;
        }
        out
    }
}
