//! Runs along a wall ("six chairs along the wall", a laundromat's washers): the instances of a
//! category that stand against a wall (SIDE), each beside the one before (`k NEXT k-1`), stand
//! in one straight run along one wall, evenly spaced, facing the room; on two walls meeting at
//! a corner only when no wall is long enough. Placed before the search (as the rows are), so
//! nothing else takes the wall first; a run no wall takes is left to the search.
use super::{yaw_facing, Pose, Problem, WALL_MARGIN};
use crate::plan::check::{penetration, WALL_NORMALS};
use crate::plan::spec::{Anchor, RelationKind, SceneSpec, SceneType};

/// The gap between neighbours of a run (m): side by side, a hand apart.
const RUN_GAP: f64 = 0.1;
/// The least distance (m) from a run's ends to the walls at its ends: a SIDE thing stands near
/// one wall only (`check::side_distance`, 0.3 m indoors), with 5 cm to spare.
const END: f64 = 0.35;
/// The step (m) by which a run's start is moved from the middle of its wall when the middle is
/// taken.
const SLIDE: f64 = 0.1;

impl Problem {
    /// The instances of `cat` in index order when they form a run: at least two, every one
    /// standing against a wall (SIDE, on the floor) and each NEXT the one before.
    fn run(&self, spec: &SceneSpec, cat: &str) -> Option<Vec<usize>> {
        let n = spec.objects.get(cat)?.number as usize;
        if n < 2 || self.scene != SceneType::Indoor {
            return None;
        }
        let ids: Vec<usize> = (1..=n)
            .map(|k| self.index.get(&format!("{cat}{k}")).copied())
            .collect::<Option<_>>()?;
        let walled = ids
            .iter()
            .all(|&i| self.inst[i].anchor == Anchor::Side && self.hung[i].is_none());
        let chained = ids.windows(2).all(|w| {
            self.rels[w[1]]
                .iter()
                .any(|&(rel, j, subject)| rel == RelationKind::Next && j == w[0] && subject)
        });
        (walled && chained).then_some(ids)
    }

    /// Poses for the runs of `spec` that `placed` leaves free, written into `placed` (a run
    /// with an instance placed already is left alone).
    pub(super) fn place_runs(&self, spec: &SceneSpec, placed: &mut [Option<Pose>]) {
        for cat in spec.objects.keys() {
            let Some(ids) = self.run(spec, cat) else {
                continue;
            };
            if ids.iter().any(|&i| placed[i].is_some()) {
                continue;
            }
            if let Some(poses) = self.run_poses(&ids, placed) {
                for (&i, p) in ids.iter().zip(poses) {
                    placed[i] = Some(p);
                }
            }
        }
    }

    /// The run's poses: along one wall, the longest first (on ties one without a door), from
    /// one end of it (the rest of the wall left in one span, a corner free beyond it), else as
    /// near its middle as is free; else split over two walls at a corner, as many on the first
    /// as it takes.
    fn run_poses(&self, ids: &[usize], placed: &[Option<Pose>]) -> Option<Vec<Pose>> {
        let mut walls: Vec<usize> = (0..4).collect();
        let has_door = |k: usize| {
            self.openings.iter().any(|o| {
                o.kind == crate::plan::spec::OpeningKind::Door && o.wall.inward() == WALL_NORMALS[k]
            })
        };
        walls.sort_by(|&a, &b| {
            self.wall_length(b)
                .total_cmp(&self.wall_length(a))
                .then(has_door(a).cmp(&has_door(b)))
        });
        let length = self.run_length(ids);
        for &k in &walls {
            let half = 0.5 * self.wall_length(k);
            let (lo, hi) = (-half + END, half - END - length);
            if hi < lo {
                continue;
            }
            let middle = (-0.5 * length).clamp(lo, hi);
            let steps = ((hi - lo) / SLIDE).ceil() as usize;
            let starts = [lo, hi].into_iter().chain((0..=steps).flat_map(|m| {
                let d = m as f64 * SLIDE;
                [middle - d, middle + d]
            }));
            for s in starts.filter(|s| (lo - 1e-9..=hi + 1e-9).contains(s)) {
                let poses = self.segment(ids, k, s, 1.0);
                if self.run_is_free(ids, &poses, placed) {
                    return Some(poses);
                }
            }
        }
        // two walls meeting at a corner: `m` on wall `a` from the corner, the rest on wall `b`
        for m in (1..ids.len()).rev() {
            for a in 0..4 {
                for b in if a < 2 { [2, 3] } else { [0, 1] } {
                    let (first, rest) = ids.split_at(m);
                    let (da, db) = (self.toward(a, b), self.toward(b, a));
                    let (ha, hb) = (0.5 * self.wall_length(a), 0.5 * self.wall_length(b));
                    let depth_a = first
                        .iter()
                        .map(|&i| self.inst[i].size[1])
                        .fold(0.0, f64::max);
                    let off_b = END.max(WALL_MARGIN + depth_a + RUN_GAP);
                    let la = self.run_length(first);
                    let lb = self.run_length(rest);
                    if END + la > 2.0 * ha - END || off_b + lb > 2.0 * hb - END {
                        continue;
                    }
                    // (a segment's start is its corner end; it runs away from the corner, the
                    // first segment's last instance at the corner, next to the rest's first)
                    let back: Vec<usize> = first.iter().rev().copied().collect();
                    let mut poses = self.segment(&back, a, da * (ha - END), -da);
                    poses.reverse();
                    poses.extend(self.segment(rest, b, db * (hb - off_b), -db));
                    if self.run_is_free(ids, &poses, placed) {
                        return Some(poses);
                    }
                }
            }
        }
        None
    }

    /// The length of wall `k` ([-x, +x, -y, +y], `check::wall_distances` order).
    fn wall_length(&self, k: usize) -> f64 {
        if k < 2 {
            self.room[1]
        } else {
            self.room[0]
        }
    }

    /// The way (+1 or -1) along wall `k` toward the wall `other` across its end.
    fn toward(&self, k: usize, other: usize) -> f64 {
        let n = WALL_NORMALS[other];
        if k < 2 {
            -n[1]
        } else {
            -n[0]
        }
    }

    /// The run's length along its wall: widths and the gaps between them.
    fn run_length(&self, ids: &[usize]) -> f64 {
        ids.iter().map(|&i| self.inst[i].size[0]).sum::<f64>()
            + RUN_GAP * ids.len().saturating_sub(1) as f64
    }

    /// Poses of `ids` side by side along wall `k`, backs to it, facing the room: the first's
    /// outer edge at `start` along the wall, going the way `dir` (+1: toward +x or +y).
    fn segment(&self, ids: &[usize], k: usize, start: f64, dir: f64) -> Vec<Pose> {
        let n = WALL_NORMALS[k];
        let e = if k < 2 { [0.0, 1.0] } else { [1.0, 0.0] };
        let half_across = 0.5 * if k < 2 { self.room[0] } else { self.room[1] };
        let mut at = start;
        ids.iter()
            .map(|&i| {
                let s = self.inst[i].size;
                let t = at + dir * 0.5 * s[0];
                at += dir * (s[0] + RUN_GAP);
                let off = -half_across + WALL_MARGIN + 0.5 * s[1];
                Pose {
                    c: [n[0] * off + e[0] * t, n[1] * off + e[1] * t],
                    yaw: yaw_facing(n),
                    z: 0.0,
                }
            })
            .collect()
    }

    /// Inside the room, clear of the doors' zones, of the windows' (a tall thing never covers
    /// one), of the rows' front bands and of what is placed already.
    fn run_is_free(&self, ids: &[usize], poses: &[Pose], placed: &[Option<Pose>]) -> bool {
        let [w, d, _] = self.room;
        let others: Vec<_> = placed
            .iter()
            .enumerate()
            .filter_map(|(j, p)| p.map(|p| self.boxed(j, &p)))
            .collect();
        ids.iter().zip(poses).all(|(&i, p)| {
            let b = self.boxed(i, p);
            let [x0, y0, x1, y1] = b.aabb();
            let inside = x0 >= -0.5 * w - 1e-9
                && x1 <= 0.5 * w + 1e-9
                && y0 >= -0.5 * d - 1e-9
                && y1 <= 0.5 * d + 1e-9;
            inside
                && self.zones.iter().all(|z| penetration(&b, z) <= 0.0)
                && self.bands.iter().all(|(z, _)| penetration(&b, z) <= 0.0)
                && others.iter().all(|o| penetration(&b, o) <= 0.0)
        })
    }
}

/// The length (m) of the longest run `spec` asks along one wall (its widths, the gaps between
/// them and the room kept at its ends), 0 when none: a room chosen by floor area alone can have
/// no wall that takes eight washers, and the run would turn the corner.
pub fn longest_run(spec: &SceneSpec) -> f64 {
    if spec.scene_type != SceneType::Indoor {
        return 0.0;
    }
    let inst = spec.instances();
    let anchor = |id: &str| inst.iter().find(|i| i.id == id).map(|i| i.anchor);
    let next = |a: &str, b: &str| {
        spec.relations
            .iter()
            .any(|r| r.relation == RelationKind::Next && r.subject == a && r.object == b)
    };
    spec.objects
        .iter()
        .filter(|(_, o)| o.number >= 2 && o.on_wall.is_none())
        .filter(|(c, o)| {
            (1..=o.number).all(|k| anchor(&format!("{c}{k}")) == Some(Anchor::Side))
                && (2..=o.number).all(|k| next(&format!("{c}{k}"), &format!("{c}{}", k - 1)))
        })
        .map(|(_, o)| {
            let n = o.number as f64;
            n * o.size[0] + (n - 1.0) * RUN_GAP + 2.0 * END
        })
        .fold(0.0, f64::max)
}
