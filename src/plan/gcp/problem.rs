//! The search's problem (instances, their relations, the room's openings and zones) and the
//! candidate poses of an instance.
use super::WALL_MARGIN;
use crate::plan::check::{Box2, CORNER_DISTANCE};
use crate::plan::spec::{Anchor, Instance, Opening, RelationKind, SceneType};
use std::collections::{BTreeMap, BTreeSet};

#[derive(Clone)]
pub(super) struct Problem {
    pub(super) scene: SceneType,
    /// Per instance: the height its bottom hangs at (on a wall or from the ceiling).
    pub(super) hung: Vec<Option<f64>>,
    /// Doors and windows of this attempt, and the zones they keep clear.
    pub(super) openings: Vec<Opening>,
    pub(super) zones: Vec<Box2>,
    pub(super) room: [f64; 3],
    pub(super) inst: Vec<Instance>,
    pub(super) index: BTreeMap<String, usize>,
    /// Per instance: (relation, other instance, true when this instance is the subject).
    pub(super) rels: Vec<Vec<(RelationKind, usize, bool)>>,
    pub(super) stacked: BTreeSet<(usize, usize)>,
    /// Per instance: against a wall with a face to keep free (a wardrobe, a bookcase).
    pub(super) faced: Vec<bool>,
    /// Per instance: hung on a wall (touching it).
    pub(super) wall_hung: Vec<bool>,
    /// Per instance hung on a wall: the instance with a floor footprint it hangs above.
    pub(super) above: Vec<Option<usize>>,
    /// Per instance: hung from the ceiling.
    pub(super) ceiling: Vec<bool>,
    /// Per instance hung from the ceiling: the instance with a floor footprint it hangs over.
    pub(super) hang_over: Vec<Option<usize>>,
    /// Per instance: its top is drawn round or oval (a lake, a round table), so what stands on
    /// it keeps its whole footprint on that ellipse, not out at the box's corners.
    pub(super) round: Vec<bool>,
    /// Per instance standing on the floor: the depth its front keeps clear (kb/placement.txt).
    pub(super) fronts: Vec<Option<f64>>,
    /// Per instance: the depth kept behind it for its staff (a reception desk; `staff.rs`),
    /// 0 when none.
    pub(super) staff: Vec<f64>,
    /// Front bands of the blocks of rows of this attempt (the view from the rows to what they
    /// face), each with the instances that belong there.
    pub(super) bands: Vec<(Box2, Vec<usize>)>,
    /// OPPOSITE pairs (subject, object): sightlines to keep clear.
    pub(super) sightlines: Vec<(usize, usize)>,
    pub(super) step: f64,
    /// Place the largest footprints first whatever holds what (the retry of a spec whose
    /// constraint order left no room).
    pub(super) largest_first: bool,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct Pose {
    pub(super) c: [f64; 2],
    pub(super) yaw: f64,
    pub(super) z: f64,
}

/// Whether `category`'s top is drawn round or oval (its knowledge-base drawing is a lake, a
/// round or an oval one).
pub(super) fn round_top(category: &str) -> bool {
    crate::plan::kb::KnowledgeBase::builtin()
        .object(category)
        .is_some_and(|o| {
            o.archetype == "lake"
                || o.archetype.starts_with("round_")
                || o.archetype.starts_with("oval_")
        })
}

/// Whether footprint `b` lies on the ellipse inscribed in `support`'s footprint, where a
/// footprint of its size centred on it would (a boat on its lake, off the box's corners).
pub(super) fn on_ellipse(b: &Box2, support: &Box2) -> bool {
    let [a, e] = support.half;
    let inside = |p: [f64; 2]| (p[0] / a).powi(2) + (p[1] / e).powi(2) <= 1.0;
    let centred = Box2 { c: support.c, ..*b };
    let fits = centred.corners().iter().all(|q| inside(support.local(*q)));
    !fits || b.corners().iter().all(|q| inside(support.local(*q)))
}

/// The widest gap between a desk's back and its seat there (m): the seats' poses
/// (`poses.rs`, AT_BACK) try 0.05 and this.
pub(super) const AT_BACK_GAP: f64 = 0.12;

/// How near one wall a SIDE thing stands (m), ARCHITECTURE.md "Relation and anchor meaning":
/// a thing with little more slack than twice this along its wall keeps clear of both end walls
/// only near the wall's middle.
const SIDE_DISTANCE: f64 = 0.3;

/// A corner thing at least this wide on both sides (metres) stands square in its corner.
const FLUSH_CORNER_SIDE: f64 = 0.8;

impl Problem {
    /// Whether instance `i` has a seat AT it (a desk with its chair): it is used from its front.
    pub(super) fn seated_at(&self, i: usize) -> bool {
        self.rels[i]
            .iter()
            .any(|&(k, _, subject)| k == RelationKind::At && !subject)
    }

    /// Whether a seat at instance `i` is to face the door (a desk "facing the door": the one
    /// at it faces the door across it).
    pub(super) fn seat_faces_door(&self, i: usize) -> bool {
        self.rels[i].iter().any(|&(k, j, subject)| {
            k == RelationKind::At && !subject && self.inst[j].anchor == Anchor::FaceDoor
        })
    }
}

pub(super) fn yaw_facing(d: [f64; 2]) -> f64 {
    // facing (-sin yaw, cos yaw) = d / |d|
    (-d[0]).atan2(d[1]).to_degrees()
}

impl Problem {
    pub(super) fn boxed(&self, i: usize, p: &Pose) -> Box2 {
        let s = self.inst[i].size;
        Box2::new(p.c, p.yaw, [s[0], s[1]], p.z, p.z + s[2])
    }

    /// Whether exactly one instance is `rel` of instance `o` (a coffee table alone in front of
    /// its sofa).
    pub(super) fn alone(&self, rel: RelationKind, o: usize) -> bool {
        self.rels[o].iter().filter(|r| r.0 == rel && !r.2).count() == 1
    }

    pub(super) fn is_stacked(&self, a: usize, b: usize) -> bool {
        self.stacked.contains(&(a.min(b), a.max(b)))
    }

    /// Whether instance `a` is stacked with `b` or is a seat of it (a desk's chair): it
    /// belongs to `b`, so it blocks no sightline from `b`.
    pub(super) fn belongs_to(&self, a: usize, b: usize) -> bool {
        self.is_stacked(a, b)
            || self.rels[a]
                .iter()
                .any(|&(rel, j, subject)| subject && j == b && rel.is_seat())
    }

    /// Candidate poses for instance `i` given the placed ones: the poses its functional groups
    /// suggest (tried first: a seat's slots at its table, a desk's place in its row), then all.
    pub(super) fn candidates(&self, i: usize, placed: &[Option<Pose>]) -> (Vec<Pose>, Vec<Pose>) {
        let mut group = vec![];
        for &(rel, j, subject) in &self.rels[i] {
            let Some(pj) = placed[j] else { continue };
            if subject {
                if let Some(poses) = self.group_poses(i, rel, (j, &pj), &self.boxed(j, &pj), placed)
                {
                    group.extend(poses);
                }
            } else if rel == RelationKind::Flank {
                group.extend(self.flanked_poses(i, (j, &pj), placed));
            }
        }
        (group, self.all_candidates(i, placed))
    }

    /// Poses of `i` with its placed FLANK subject `j` at its left or right, backs in line,
    /// turned as `j`, when `j` already flanks another placed thing: the second of two beds with
    /// one nightstand between them stands on the nightstand's free side.
    fn flanked_poses(
        &self,
        i: usize,
        (j, pj): (usize, &Pose),
        placed: &[Option<Pose>],
    ) -> Vec<Pose> {
        let shared = self.rels[j].iter().any(|&(rel, k, subject)| {
            subject && rel == RelationKind::Flank && k != i && placed[k].is_some()
        });
        if !shared {
            return vec![];
        }
        let (s, sj) = (self.inst[i].size, self.inst[j].size);
        let b = Box2::new([0.0, 0.0], pj.yaw, [s[0], s[1]], 0.0, 0.0);
        let mut out = vec![];
        for side in [-1.0, 1.0] {
            for g in [0.02, 0.08] {
                let (lx, ly) = (
                    side * (0.5 * s[0] + g + 0.5 * sj[0]),
                    -0.5 * s[1] + 0.5 * sj[1],
                );
                out.push(Pose {
                    c: [
                        pj.c[0] - lx * b.ex[0] - ly * b.ey[0],
                        pj.c[1] - lx * b.ex[1] - ly * b.ey[1],
                    ],
                    yaw: pj.yaw,
                    z: 0.0,
                });
            }
        }
        out
    }

    /// The room instance `i` keeps between its back and the wall for the seats at its back
    /// that stand against the wall (a head table's party): the deepest seat and its gap; 0
    /// when none.
    pub(super) fn wall_seats_depth(&self, i: usize) -> f64 {
        self.rels[i]
            .iter()
            .filter(|&&(rel, k, subject)| {
                rel == RelationKind::AtBack && !subject && self.inst[k].anchor == Anchor::Side
            })
            .map(|&(_, k, _)| self.inst[k].size[1] + AT_BACK_GAP)
            .fold(0.0, f64::max)
    }

    /// Every candidate pose for instance `i`: anchor regions and around placed partners.
    pub(super) fn all_candidates(&self, i: usize, placed: &[Option<Pose>]) -> Vec<Pose> {
        let [w, d, _] = self.room;
        let (hw, hd) = (0.5 * w, 0.5 * d);
        let s = self.inst[i].size;
        let z0 = self.hung[i].unwrap_or(0.0);
        let mut out = vec![];
        let grid = |lo: f64, hi: f64| -> Vec<f64> {
            if hi < lo {
                return vec![0.5 * (lo + hi)];
            }
            let n = ((hi - lo) / self.step).floor() as usize;
            (0..=n)
                .map(|k| lo + k as f64 * self.step)
                .chain([hi])
                .collect()
        };
        // Spots along a wall `2 * half` long for a thing `2 * own` wide: the grid, and the
        // wall's middle where it has little slack (there alone a thing on a short wall keeps
        // clear of both end walls, and the grid may step over it).
        let along = |half: f64, own: f64| -> Vec<f64> {
            let mut v = grid(-half + own, half - own);
            if 2.0 * (half - own) <= 2.0 * (SIDE_DISTANCE + self.step) {
                v.push(0.0);
            }
            v
        };
        // Yaws suggested by placed partners.
        let mut yaws: Vec<f64> = vec![0.0, 90.0, 180.0, -90.0];
        for &(_, j, _) in &self.rels[i] {
            if let Some(pj) = placed[j] {
                yaws.push(pj.yaw);
                yaws.push(pj.yaw + 180.0);
            }
        }
        // (a thing whose seats at its back stand against the wall stands before them, a
        // counter before its staff)
        let back = self.wall_seats_depth(i).max(self.staff[i]);
        let anchor = if back > 0.0 {
            Anchor::Side
        } else {
            self.inst[i].anchor
        };
        match anchor {
            // a desk or table at a window with a seat at it: only the poses before the window
            // with its back to it (`opening_candidates`)
            Anchor::Window if self.seated_at(i) => {}
            Anchor::Side => {
                // Back to each wall, facing into the room, anywhere along it.
                for (wall, yaw) in [(0usize, -90.0), (1, 90.0), (2, 0.0), (3, 180.0)] {
                    let depth_half = 0.5 * s[1];
                    let off = WALL_MARGIN + depth_half + back;
                    let along_half = 0.5 * s[0];
                    match wall {
                        0 | 1 => {
                            let x = if wall == 0 { -hw + off } else { hw - off };
                            for y in along(hd, along_half) {
                                out.push(Pose {
                                    c: [x, y],
                                    yaw,
                                    z: z0,
                                });
                            }
                        }
                        _ => {
                            let y = if wall == 2 { -hd + off } else { hd - off };
                            for x in along(hw, along_half) {
                                out.push(Pose {
                                    c: [x, y],
                                    yaw,
                                    z: z0,
                                });
                            }
                        }
                    }
                }
            }
            Anchor::Corner => {
                // Its box against both walls of each corner: a small thing (a plant, a coat
                // rack, a corner shelf) faces diagonally out of it; a big one (a shower cabin,
                // an L-shaped desk) stands square in it, facing along either wall, since a
                // footprint turned 45 degrees takes twice its floor.
                let square = s[0].min(s[1]) >= FLUSH_CORNER_SIDE;
                for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    let yaws = if square {
                        vec![yaw_facing([-sx, 0.0]), yaw_facing([0.0, -sy])]
                    } else {
                        vec![yaw_facing([-sx, -sy])]
                    };
                    for yaw in yaws {
                        let probe = Box2::new([0.0, 0.0], yaw, [s[0], s[1]], 0.0, s[2]);
                        let [x0, y0, x1, y1] = probe.aabb();
                        for inset in [WALL_MARGIN, 0.5 * CORNER_DISTANCE] {
                            let cx = if sx < 0.0 {
                                -hw + inset - x0
                            } else {
                                hw - inset - x1
                            };
                            let cy = if sy < 0.0 {
                                -hd + inset - y0
                            } else {
                                hd - inset - y1
                            };
                            out.push(Pose {
                                c: [cx, cy],
                                yaw,
                                z: 0.0,
                            });
                        }
                    }
                }
            }
            anchor => {
                let r = 0.25 * w.min(d);
                for x in grid(-hw, hw) {
                    for y in grid(-hd, hd) {
                        // (beside a block of rows, whose front band may hold the middle, the
                        // whole floor)
                        if anchor == Anchor::Center
                            && self.bands.is_empty()
                            && (x * x + y * y).sqrt() > r
                        {
                            continue;
                        }
                        for &yaw in &yaws[..4] {
                            out.push(Pose {
                                c: [x, y],
                                yaw,
                                z: z0,
                            });
                        }
                    }
                }
            }
        }
        out.extend(self.opening_candidates(i));
        out.extend(self.above_poses(i, placed));
        // Poses derived from each placed partner.
        for &(rel, j, subject) in &self.rels[i] {
            let Some(pj) = placed[j] else { continue };
            let bj = self.boxed(j, &pj);
            let sj = self.inst[j].size;
            if subject && rel == RelationKind::Over {
                // spots over the support's top, centre first
                let free = |k: usize| (0.5 * (sj[k] - s[k])).max(0.0);
                let (fx, fy) = (free(0), free(1));
                for (lx, ly) in [
                    (0.0, 0.0),
                    (-fx, 0.0),
                    (fx, 0.0),
                    (-0.5 * fx, 0.0),
                    (0.5 * fx, 0.0),
                    (0.0, -fy),
                    (-fx, -fy),
                    (fx, -fy),
                    (-0.5 * fx, -fy),
                    (0.5 * fx, -fy),
                    (0.0, fy),
                    (-fx, fy),
                    (fx, fy),
                ] {
                    out.push(Pose {
                        c: [
                            pj.c[0] + lx * bj.ex[0] + ly * bj.ey[0],
                            pj.c[1] + lx * bj.ex[1] + ly * bj.ey[1],
                        ],
                        yaw: pj.yaw,
                        z: bj.z1,
                    });
                }
                continue;
            }
            if (subject && rel == RelationKind::Under) || (!subject && rel == RelationKind::Over) {
                // under the partner, or the support below a placed subject
                // turned as the partner, or across it (a bridge over its pond); a thing under
                // it may also stand off its centre, as long as its own centre stays beneath
                // (a rug kept out of a doorway)
                let z = if subject { 0.0 } else { (pj.z - s[2]).max(0.0) };
                let shifts: &[f64] = if subject { &[0.0, -0.9, 0.9] } else { &[0.0] };
                for &fx in shifts {
                    for &fy in shifts {
                        let c = [
                            pj.c[0] + fx * bj.half[0] * bj.ex[0] + fy * bj.half[1] * bj.ey[0],
                            pj.c[1] + fx * bj.half[0] * bj.ex[1] + fy * bj.half[1] * bj.ey[1],
                        ];
                        for yaw in [pj.yaw, pj.yaw + 90.0] {
                            out.push(Pose { c, yaw, z });
                        }
                    }
                }
                continue;
            }
            if !subject && rel == RelationKind::Under {
                for yaw in [pj.yaw, pj.yaw + 90.0] {
                    out.push(Pose {
                        c: pj.c,
                        yaw,
                        z: 0.0,
                    });
                }
                continue;
            }
            // Around the partner in its frame: front, behind, left, right at several gaps.
            let ext = 0.5 * s[0].max(s[1]);
            let square = self.scene == SceneType::Indoor
                && (self.faced[i] || self.inst[i].anchor == Anchor::Side);
            for (dir, half) in [
                (bj.ey, 0.5 * sj[1]),
                ([-bj.ey[0], -bj.ey[1]], 0.5 * sj[1]),
                (bj.ex, 0.5 * sj[0]),
                ([-bj.ex[0], -bj.ex[1]], 0.5 * sj[0]),
            ] {
                let lateral = [-dir[1], dir[0]];
                for g in [0.05, 0.25, 0.5, 0.9, 1.5, 2.2] {
                    let base = half + g + ext;
                    for t in [-0.3, 0.0, 0.3] {
                        let c = [
                            pj.c[0] + dir[0] * base + lateral[0] * t * ext,
                            pj.c[1] + dir[1] * base + lateral[1] * t * ext,
                        ];
                        let to = [pj.c[0] - c[0], pj.c[1] - c[1]];
                        // (a thing against a wall stays square to it: a dishwasher beside
                        // its sink is not turned toward the sink's centre)
                        let face = if square {
                            (yaw_facing(to) / 90.0).round() * 90.0
                        } else {
                            yaw_facing(to)
                        };
                        for yaw in [
                            face,
                            face + 180.0,
                            face + 90.0,
                            face - 90.0,
                            pj.yaw,
                            pj.yaw + 180.0,
                        ] {
                            out.push(Pose { c, yaw, z: z0 });
                        }
                    }
                }
            }
        }
        out
    }
}
