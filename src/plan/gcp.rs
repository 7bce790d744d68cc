//! Graph-based constraint placement (GCP, the paper's Algorithm 1), improved: the most connected
//! object first (larger and wall-anchored ones first on ties), breadth-first over the constraint
//! graph, candidate poses on a grid from the anchor regions plus poses derived from each placed
//! partner, filtered by collision (oriented boxes) and scored by the relations and anchor they
//! satisfy, walkway clearance and a seeded jitter; OVER subjects wait for their support; several
//! seeded restarts keep the best layout. No object is ever dropped: when nothing satisfies its
//! constraints it takes the best pose it can get and is marked `fallback`.
use super::check::{
    anchor_holds_in, opening_zone, penetration, relation_holds_alone, wall_distances, Box2,
    CORNER_DISTANCE, TOLERANCE,
};
use super::spec::{
    Anchor, Instance, Layout, Opening, PlacedBy, PlacedObject, RelationKind, Room, SceneSpec,
    SceneType, SpecError,
};
use rand::{Rng, SeedableRng};

pub mod classes;
mod clear;
mod compose;
mod fit;
mod gather;
pub mod openings;
mod poses;
pub mod rows;
mod spacing;
mod tables;
use fit::join_names;
pub use fit::smallest_room;
use std::collections::{BTreeMap, BTreeSet, VecDeque};

/// Layout search settings.
#[derive(Debug, Clone, Copy)]
pub struct LayoutOptions {
    pub seed: u64,
    /// Independent seeded attempts; the best is kept.
    pub restarts: u32,
}

impl LayoutOptions {
    /// The default search with a given seed.
    pub fn seeded(seed: u64) -> LayoutOptions {
        LayoutOptions {
            seed,
            ..Default::default()
        }
    }
}

impl Default for LayoutOptions {
    fn default() -> Self {
        LayoutOptions {
            seed: 0,
            restarts: 6,
        }
    }
}

/// Occupancy the chosen room size aims at (footprint area / floor area).
pub const INDOOR_OCCUPANCY: f64 = 0.4;
const OUTDOOR_OCCUPANCY: f64 = 0.2;
/// Gap kept from walls when placing against them.
const WALL_MARGIN: f64 = 0.02;
/// Preferred free space around unrelated objects (a walkway).
const WALKWAY: f64 = 0.6;
/// Weight of a thing turning toward what it relates to, against the search's seeded jitter
/// (at most 3).
const FACING_WEIGHT: f64 = 1.5;
/// Weight of a pose that leaves the thing to be placed in front of it (or behind) its anchor.
const LOOKAHEAD_WEIGHT: f64 = 6.0;

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

#[derive(Clone)]
struct Problem {
    scene: SceneType,
    /// Per instance: the height its bottom hangs at (on a wall or from the ceiling).
    hung: Vec<Option<f64>>,
    /// Doors and windows of this attempt, and the zones they keep clear.
    openings: Vec<Opening>,
    zones: Vec<Box2>,
    room: [f64; 3],
    inst: Vec<Instance>,
    index: BTreeMap<String, usize>,
    /// Per instance: (relation, other instance, true when this instance is the subject).
    rels: Vec<Vec<(RelationKind, usize, bool)>>,
    stacked: BTreeSet<(usize, usize)>,
    /// Per instance: against a wall with a face to keep free (a wardrobe, a bookcase).
    faced: Vec<bool>,
    /// Per instance: hung on a wall (touching it).
    wall_hung: Vec<bool>,
    /// Per instance standing on the floor: the depth its front keeps clear (kb/placement.txt).
    fronts: Vec<Option<f64>>,
    /// OPPOSITE pairs (subject, object): sightlines to keep clear.
    sightlines: Vec<(usize, usize)>,
    step: f64,
    /// Place the largest footprints first whatever holds what (the retry of a spec whose
    /// constraint order left no room).
    largest_first: bool,
}

#[derive(Clone, Copy, Debug)]
struct Pose {
    c: [f64; 2],
    yaw: f64,
    z: f64,
}

fn yaw_facing(d: [f64; 2]) -> f64 {
    // facing (-sin yaw, cos yaw) = d / |d|
    (-d[0]).atan2(d[1]).to_degrees()
}

impl Problem {
    fn boxed(&self, i: usize, p: &Pose) -> Box2 {
        let s = self.inst[i].size;
        Box2::new(p.c, p.yaw, [s[0], s[1]], p.z, p.z + s[2])
    }

    /// Whether exactly one instance is `rel` of instance `o` (a coffee table alone in front of
    /// its sofa).
    fn alone(&self, rel: RelationKind, o: usize) -> bool {
        self.rels[o].iter().filter(|r| r.0 == rel && !r.2).count() == 1
    }

    fn is_stacked(&self, a: usize, b: usize) -> bool {
        self.stacked.contains(&(a.min(b), a.max(b)))
    }

    /// Candidate poses for instance `i` given the placed ones: the poses its functional groups
    /// suggest (tried first: a seat's slots at its table, a desk's place in its row), then all.
    fn candidates(&self, i: usize, placed: &[Option<Pose>]) -> (Vec<Pose>, Vec<Pose>) {
        let mut group = vec![];
        for &(rel, j, subject) in &self.rels[i] {
            let Some(pj) = placed[j] else { continue };
            if subject {
                if let Some(poses) = self.group_poses(i, rel, (j, &pj), &self.boxed(j, &pj), placed)
                {
                    group.extend(poses);
                }
            }
        }
        (group, self.all_candidates(i, placed))
    }

    /// Every candidate pose for instance `i`: anchor regions and around placed partners.
    fn all_candidates(&self, i: usize, placed: &[Option<Pose>]) -> Vec<Pose> {
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
        // Yaws suggested by placed partners.
        let mut yaws: Vec<f64> = vec![0.0, 90.0, 180.0, -90.0];
        for &(_, j, _) in &self.rels[i] {
            if let Some(pj) = placed[j] {
                yaws.push(pj.yaw);
                yaws.push(pj.yaw + 180.0);
            }
        }
        match self.inst[i].anchor {
            Anchor::Side => {
                // Back to each wall, facing into the room, anywhere along it.
                for (wall, yaw) in [(0usize, -90.0), (1, 90.0), (2, 0.0), (3, 180.0)] {
                    let depth_half = 0.5 * s[1];
                    let off = WALL_MARGIN + depth_half;
                    let along_half = 0.5 * s[0];
                    match wall {
                        0 | 1 => {
                            let x = if wall == 0 { -hw + off } else { hw - off };
                            for y in grid(-hd + along_half, hd - along_half) {
                                out.push(Pose {
                                    c: [x, y],
                                    yaw,
                                    z: z0,
                                });
                            }
                        }
                        _ => {
                            let y = if wall == 2 { -hd + off } else { hd - off };
                            for x in grid(-hw + along_half, hw - along_half) {
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
                // Facing diagonally out of each corner, its box against both walls.
                for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    let yaw = yaw_facing([-sx, -sy]);
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
            anchor => {
                let r = 0.25 * w.min(d);
                for x in grid(-hw, hw) {
                    for y in grid(-hd, hd) {
                        if anchor == Anchor::Center && (x * x + y * y).sqrt() > r {
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
                        let face = yaw_facing(to);
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

    /// (hard-valid, constraints satisfied, constraint count, score) of pose `p` for `i`.
    fn evaluate(
        &self,
        i: usize,
        p: &Pose,
        placed: &[Option<Pose>],
        boxes: &[Option<(Box2, [f64; 4])>],
        jitter: f64,
    ) -> (bool, usize, usize, f64) {
        let b = self.boxed(i, p);
        let wd = wall_distances(&b, self.room);
        if wd.iter().any(|&v| v < -1e-9) || b.z1 > self.room[2] + 1e-9 {
            return (false, 0, 0, f64::NEG_INFINITY);
        }
        if self.zones.iter().any(|z| penetration(&b, z) > 0.0) {
            return (false, 0, 0, f64::NEG_INFINITY);
        }
        // A thing hung on a wall touches it, facing into the room.
        if self.wall_hung[i]
            && !(wd.iter().any(|&v| v <= WALL_MARGIN + 0.03)
                && anchor_holds_in(&b, Anchor::Side, self.scene, self.room, &[]))
        {
            return (false, 0, 0, f64::NEG_INFINITY);
        }
        let ab = b.aabb();
        let mut clearance = WALKWAY;
        for (j, pb) in boxes.iter().enumerate() {
            let Some((bj, aj)) = pb else { continue };
            // Boxes whose bounding boxes are a walkway apart neither collide nor crowd.
            let apart = (aj[0] - ab[2])
                .max(ab[0] - aj[2])
                .max(aj[1] - ab[3])
                .max(ab[1] - aj[3]);
            if apart >= WALKWAY || self.is_stacked(i, j) {
                continue;
            }
            // Within half the validity tolerance: flat things (rugs, mats) may lie under others.
            if apart < 0.0 && penetration(&b, bj) > 0.5 * TOLERANCE {
                return (false, 0, 0, f64::NEG_INFINITY);
            }
            if !self.rels[i].iter().any(|r| r.1 == j) {
                clearance = clearance.min(super::check::gap(&b, bj));
            }
        }
        let mut total = 1;
        let mut ok = anchor_holds_in(
            &b,
            self.inst[i].anchor,
            self.scene,
            self.room,
            &self.openings,
        ) as usize;
        let mut near = 0.0;
        let mut pose_bonus = 0.0;
        let free_yaw = !matches!(
            self.inst[i].anchor,
            Anchor::Side | Anchor::Corner | Anchor::FaceWindow
        );
        for &(rel, j, subject) in &self.rels[i] {
            let Some(pj) = placed[j] else { continue };
            let bj = self.boxed(j, &pj);
            total += 1;
            let holds = if subject {
                relation_holds_alone(&b, rel, &bj, self.alone(rel, j))
            } else {
                relation_holds_alone(&bj, rel, &b, self.alone(rel, i))
            };
            ok += holds as usize;
            if rel == RelationKind::Opposite {
                // the two ends face each other, in range or not (a wall TV on the wall the
                // sofa faces, not behind it), rather than stand close
                let (sb, ob) = if subject { (&b, &bj) } else { (&bj, &b) };
                pose_bonus +=
                    2.0 * FACING_WEIGHT * super::check::facing_error(sb, ob).to_radians().cos();
            } else {
                near += super::check::gap(&b, &bj).min(3.0);
            }
            if free_yaw {
                if matches!(rel, RelationKind::Over | RelationKind::Under) {
                    // stacked things line up with their partner
                    let dy = (p.yaw - pj.yaw).to_radians();
                    pose_bonus += dy.cos().abs();
                } else if (subject || rel == RelationKind::Opposite) && !is_group(rel) {
                    // chairs, tables, lamps turn toward what they relate to; OPPOSITE pairs
                    // face each other
                    // (as much as the search's jitter, so a seat does not end turned away)
                    pose_bonus +=
                        FACING_WEIGHT * super::check::facing_error(&b, &bj).to_radians().cos();
                }
            }
        }
        // A thing stands where what is placed in front of or behind it can keep its own
        // anchor (a sofa where its coffee table can stand in the middle of the room).
        for &(rel, j, subject) in &self.rels[i] {
            let dir = match rel {
                RelationKind::Front => 1.0,
                RelationKind::Behind => -1.0,
                _ => continue,
            };
            if subject || placed[j].is_some() || self.inst[j].anchor == Anchor::Others {
                continue;
            }
            let sj = self.inst[j].size;
            let off = dir * (b.half[1] + compose::FRONT_GAP + 0.5 * sj[1]);
            let c = [b.c[0] + off * b.ey[0], b.c[1] + off * b.ey[1]];
            let bj = Box2::new(c, p.yaw, [sj[0], sj[1]], 0.0, sj[2]);
            let anchor = self.inst[j].anchor;
            if anchor_holds_in(&bj, anchor, self.scene, self.room, &self.openings) {
                pose_bonus += LOOKAHEAD_WEIGHT;
            }
        }
        // a front kept clear is one more constraint (a seat that can only be drawn up before
        // the stove's front is a relaxed one)
        let front = self.front_cost(i, &b, boxes);
        total += 1;
        ok += (front == 0.0) as usize;
        let comp = self.composition(i, p, &b, placed, boxes)
            + self.gathering(i, p, &b, placed, boxes)
            - front;
        let score = 10.0 * ok as f64 + 2.0 * clearance - 0.3 * near + pose_bonus + comp + jitter;
        (true, ok, total, score)
    }
}

/// The functional-group relations, which fix their subject's turn themselves.
fn is_group(rel: RelationKind) -> bool {
    matches!(
        rel,
        RelationKind::Around
            | RelationKind::At
            | RelationKind::AtBack
            | RelationKind::Flank
            | RelationKind::Circle
            | RelationKind::Row
            | RelationKind::Before
    )
}

/// Lays out `spec` (validated first). Deterministic for a given seed. A spec with an object
/// larger than its room, or whose objects cannot all be placed without interpenetrating, is
/// refused with [`SpecError::DoesNotFit`] naming what does not fit and the smallest room (same
/// proportions) that takes everything.
pub fn layout(spec: &SceneSpec, opts: LayoutOptions) -> Result<Layout, SpecError> {
    spec.validate()?;
    let inst = spec.instances();
    let room = spec.room.unwrap_or_else(|| {
        let mut r = choose_room(&inst, spec.scene_type);
        // rows asked: wide and deep enough for the block, its walkways and its front
        let need = rows::room_for_rows(spec);
        for (v, n) in r.size.iter_mut().zip(need) {
            *v = v.max((n * 10.0).ceil() / 10.0);
        }
        r
    });
    let big: Vec<String> = spec
        .objects
        .iter()
        .filter(|(_, o)| !super::capacity::fits(o.size, room.size))
        .map(|(c, o)| format!("{c} ({} x {} x {} m)", o.size[0], o.size[1], o.size[2]))
        .collect();
    if !big.is_empty() {
        let need = smallest_room(spec);
        return Err(SpecError::DoesNotFit(format!(
            "{} larger than the {} x {} x {} m room; the smallest room that takes everything is {} x {} x {} m",
            join_names(&big, if big.len() == 1 { "is" } else { "are" }),
            room.size[0], room.size[1], room.size[2], need.size[0], need.size[1], need.size[2]
        )));
    }
    let mut l = layout_in(spec, room, opts);
    let mut problems = super::check::validity_problems(&l, spec);
    if !problems.is_empty() {
        // one greedy order can paint itself into a corner: the largest first before refusing
        let more = LayoutOptions {
            restarts: 4 * opts.restarts.max(1),
            ..opts
        };
        let l2 = layout_in_pinned(spec, room, more, &BTreeMap::new(), None, true);
        let p2 = super::check::validity_problems(&l2, spec);
        if p2.len() < problems.len() {
            (l, problems) = (l2, p2);
        }
    }
    if !problems.is_empty() {
        let mut ids: Vec<String> = vec![];
        for o in &l.objects {
            if o.placed_by == PlacedBy::Fallback
                && problems.iter().any(|p| p.split(' ').any(|w| w == o.id))
            {
                ids.push(o.id.clone());
            }
        }
        if ids.is_empty() {
            ids = l.objects.iter().map(|o| o.id.clone()).take(3).collect();
        }
        let need = smallest_room(spec);
        return Err(SpecError::DoesNotFit(format!(
            "{} not fit in the {} x {} m room ({} overlapping or outside); the smallest room that takes everything is {} x {} x {} m",
            join_names(&ids, if ids.len() == 1 { "does" } else { "do" }),
            room.size[0], room.size[1], problems.len(), need.size[0], need.size[1], need.size[2]
        )));
    }
    Ok(l)
}

/// A fixed pose for an instance in [`layout_pinned`]: bottom-face centre and yaw (degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pin {
    pub position: [f64; 3],
    pub yaw: f64,
}

/// [`layout`] with the instances named in `pins` kept at their given poses: they are placed
/// first, as they are, and the others are placed around them (an edit moves or adds objects in a
/// scene whose other objects stay), in a room with the given `openings` (the scene's; `None`:
/// new ones). Pins naming no instance are ignored.
pub fn layout_pinned(
    spec: &SceneSpec,
    opts: LayoutOptions,
    pins: &BTreeMap<String, Pin>,
    openings: Option<&[Opening]>,
) -> Result<Layout, SpecError> {
    spec.validate()?;
    let room = spec
        .room
        .unwrap_or_else(|| choose_room(&spec.instances(), spec.scene_type));
    Ok(layout_in_pinned(spec, room, opts, pins, openings, false))
}

/// The GCP search in `room`, without the fit checks.
pub(crate) fn layout_in(spec: &SceneSpec, room: Room, opts: LayoutOptions) -> Layout {
    layout_in_pinned(spec, room, opts, &BTreeMap::new(), None, false)
}

/// [`layout_in`] with pinned instances placed first, as they are. The placement classes
/// (kb/placement.txt) become anchors and OVER relations of a working copy of the spec first.
fn layout_in_pinned(
    spec: &SceneSpec,
    room: Room,
    opts: LayoutOptions,
    pins: &BTreeMap<String, Pin>,
    openings: Option<&[Opening]>,
    largest_first: bool,
) -> Layout {
    let mut work = spec.clone();
    let mounts = classes::apply(&mut work);
    let spec = &work;
    let inst = spec.instances();
    let hung: Vec<Option<f64>> = inst
        .iter()
        .map(|i| {
            let h = room.size[2];
            if mounts.ceiling.contains(&i.id) {
                Some((h - i.size[2]).max(0.0))
            } else {
                mounts
                    .wall
                    .get(&i.id)
                    .map(|&z| z.min(h - i.size[2] - 0.05).max(0.0))
            }
        })
        .collect();
    let mut index = BTreeMap::new();
    for (k, i) in inst.iter().enumerate() {
        index.insert(i.id.clone(), k);
    }
    let mut rels = vec![vec![]; inst.len()];
    let mut stacked = BTreeSet::new();
    for r in &spec.relations {
        let (s, o) = (index[&r.subject], index[&r.object]);
        rels[s].push((r.relation, o, true));
        rels[o].push((r.relation, s, false));
        if matches!(r.relation, RelationKind::Over | RelationKind::Under) {
            stacked.insert((s.min(o), s.max(o)));
        }
    }
    let [w, d, _] = room.size;
    let step = (w.min(d) / 30.0).clamp(0.1, 0.5);
    let faced: Vec<bool> = inst
        .iter()
        .map(|i| {
            spec.scene_type == SceneType::Indoor
                && classes::effective_class(spec, &i.category) == classes::Class::AgainstWall
        })
        .collect();
    let sightlines: Vec<(usize, usize)> = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Opposite)
        .map(|r| (index[&r.subject], index[&r.object]))
        .collect();
    let wall_hung: Vec<bool> = inst
        .iter()
        .map(|i| spec.scene_type == SceneType::Indoor && mounts.wall.contains_key(&i.id))
        .collect();
    // (the retry of a room the first search could not pack gives its fronts up)
    let fronts: Vec<Option<f64>> = inst
        .iter()
        .zip(&hung)
        .map(|(i, h)| {
            (h.is_none() && !largest_first)
                .then(|| classes::Placements::builtin().front_clearance(&i.category))
                .flatten()
        })
        .collect();
    let mut prob = Problem {
        fronts,
        faced,
        wall_hung,
        sightlines,
        hung,
        openings: vec![],
        zones: vec![],
        scene: spec.scene_type,
        room: room.size,
        inst,
        index,
        rels,
        stacked,
        step,
        largest_first,
    };
    let pinned: Vec<Option<Pose>> = prob
        .inst
        .iter()
        .map(|i| {
            pins.get(&i.id).map(|p| Pose {
                c: [p.position[0], p.position[1]],
                yaw: p.yaw,
                z: p.position[2],
            })
        })
        .collect();
    let mut best: Option<(f64, Layout)> = None;
    for attempt in 0..opts.restarts.max(1) {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(
            opts.seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ attempt as u64,
        );
        prob.openings = match (openings, spec.scene_type) {
            (Some(o), _) => o.to_vec(),
            (None, SceneType::Indoor) => openings::generate(
                room.size,
                openings::asked_windows(&spec.scene_text),
                &mut rng,
            ),
            (None, SceneType::Outdoor) => vec![],
        };
        prob.zones = prob.openings.iter().map(opening_zone).collect();
        let mut fixed = pinned.clone();
        prob.place_rows(spec, &mut fixed);
        let mut l = attempt_layout(&prob, spec, room, opts.seed, &mut rng, &fixed);
        l.openings = prob.openings.clone();
        let q =
            quality(&prob, &l) - 3.0 * super::check::fronts::fronts_blocked(&l, spec).len() as f64;
        if best.as_ref().is_none_or(|b| q > b.0) {
            best = Some((q, l));
        }
    }
    best.expect("at least one attempt").1
}

/// Satisfied constraints minus a large penalty per fallback.
fn quality(prob: &Problem, l: &Layout) -> f64 {
    let mut q = 0.0;
    for o in &l.objects {
        let b = super::check::Box2::of(o);
        if anchor_holds_in(&b, o.anchor, prob.scene, prob.room, &prob.openings) {
            q += 1.0;
        }
        if o.placed_by == PlacedBy::Fallback {
            q -= 5.0;
        }
    }
    // everything a person can walk up to from the door
    q -= 2.0 * super::check::walk::unreachable(l).len() as f64;
    q - l.unsatisfied.len() as f64
}

/// Placement order: a CENTER thing that nothing relates to first (a dance floor keeps the
/// middle), then breadth-first from the most connected instance of each component (ties:
/// wall-anchored, then larger), OVER subjects after their support.
fn order(prob: &Problem, rng: &mut impl Rng) -> Vec<usize> {
    let n = prob.inst.len();
    // How much an instance holds others in place: being placed by a partner (a nightstand at
    // its bed, a coffee table in front of its sofa) and a support's load (a lamp on that
    // nightstand) do not count, so a partner is placed before what is placed by it; on ties,
    // what no partner places goes first.
    let placed_by = |rel: RelationKind| {
        is_group(rel)
            || matches!(
                rel,
                RelationKind::Front
                    | RelationKind::Behind
                    | RelationKind::Left
                    | RelationKind::Right
                    | RelationKind::Next
            )
    };
    let key = |i: usize| {
        let a = &prob.inst[i];
        let wall = matches!(a.anchor, Anchor::Side | Anchor::Corner) as u32;
        let area = a.size[0] * a.size[1];
        let holds = prob.rels[i]
            .iter()
            .filter(|&&(rel, _, subject)| {
                if subject {
                    !placed_by(rel)
                } else {
                    rel != RelationKind::Over
                }
            })
            .count();
        let free = !prob.rels[i]
            .iter()
            .any(|&(rel, _, subject)| subject && placed_by(rel));
        if prob.largest_first {
            return (false, 0, false, 0, (area * 1000.0) as u64);
        }
        // a thing the middle is kept for and nothing else places (a dance floor) takes it first
        let middle = a.anchor == Anchor::Center && prob.rels[i].is_empty();
        (middle, holds, free, wall, (area * 1000.0) as u64)
    };
    let mut done = vec![false; n];
    let mut out = vec![];
    loop {
        let start = (0..n)
            .filter(|&i| !done[i])
            .max_by_key(|&i| (key(i), std::cmp::Reverse(i)));
        let Some(start) = start else { break };
        let mut q = VecDeque::from([start]);
        done[start] = true;
        while let Some(i) = q.pop_front() {
            out.push(i);
            let mut next: Vec<usize> = prob.rels[i]
                .iter()
                .map(|r| r.1)
                .filter(|&j| !done[j])
                .collect();
            next.sort();
            next.dedup();
            // Ties broken by the key, then at random (restarts see different orders).
            // (One random draw per entry: a key drawn afresh at each comparison is no order.)
            let mut keyed: Vec<_> = next
                .into_iter()
                .map(|j| (std::cmp::Reverse(key(j)), rng.gen::<u32>(), j))
                .collect();
            keyed.sort();
            for (_, _, j) in keyed {
                done[j] = true;
                q.push_back(j);
            }
        }
    }
    // OVER subjects after their supports.
    let mut fixed: Vec<usize> = vec![];
    let mut waiting: Vec<usize> = out;
    for _ in 0..n + 1 {
        let mut rest = vec![];
        for &i in &waiting {
            let ready = prob.rels[i].iter().all(|&(rel, j, subject)| {
                !(subject && rel == RelationKind::Over) || fixed.contains(&j)
            });
            if ready {
                fixed.push(i);
            } else {
                rest.push(i);
            }
        }
        if rest.is_empty() || rest.len() == waiting.len() {
            fixed.extend(rest);
            break;
        }
        waiting = rest;
    }
    fixed
}

fn attempt_layout(
    prob: &Problem,
    spec: &SceneSpec,
    room: Room,
    seed: u64,
    rng: &mut rand_chacha::ChaCha8Rng,
    pinned: &[Option<Pose>],
) -> Layout {
    let n = prob.inst.len();
    let mut placed: Vec<Option<Pose>> = pinned.to_vec();
    let mut by: Vec<PlacedBy> = vec![PlacedBy::Constraint; n];
    for i in order(prob, rng) {
        if placed[i].is_some() {
            continue;
        }
        let (group, cands) = prob.candidates(i, &placed);
        let boxes: Vec<Option<(Box2, [f64; 4])>> = placed
            .iter()
            .enumerate()
            .map(|(j, p)| {
                p.map(|p| {
                    let b = prob.boxed(j, &p);
                    (b, b.aabb())
                })
            })
            .collect();
        let mut best: Option<(f64, Pose, bool)> = None;
        let mut search = |poses: &[Pose], best: &mut Option<(f64, Pose, bool)>| {
            for p in poses {
                let (valid, ok, total, score) =
                    prob.evaluate(i, p, &placed, &boxes, rng.gen::<f64>() * 3.0);
                if valid && best.as_ref().is_none_or(|b| score > b.0) {
                    *best = Some((score, *p, ok == total));
                }
            }
        };
        search(&group, &mut best);
        if !best.as_ref().is_some_and(|b| b.2) {
            search(&cands, &mut best);
        }
        let (pose, all_ok) = match best {
            Some((_, p, ok)) => (p, ok),
            None => (fallback_pose(prob, i, &placed, rng), false),
        };
        placed[i] = Some(pose);
        if !all_ok {
            by[i] = PlacedBy::Fallback;
        }
    }
    let objects: Vec<PlacedObject> = prob
        .inst
        .iter()
        .enumerate()
        .map(|(i, inst)| {
            let p = placed[i].expect("every instance placed");
            let mut yaw = p.yaw % 360.0;
            if yaw > 180.0 {
                yaw -= 360.0;
            }
            if yaw <= -180.0 {
                yaw += 360.0;
            }
            PlacedObject {
                id: inst.id.clone(),
                category: inst.category.clone(),
                size: inst.size,
                position: [p.c[0], p.c[1], p.z],
                yaw,
                anchor: inst.anchor,
                placed_by: by[i],
            }
        })
        .collect();
    let unsatisfied = super::check::relations_unsatisfied(&objects, &spec.relations);
    Layout {
        scene_type: spec.scene_type,
        room,
        seed,
        objects,
        unsatisfied,
        openings: vec![],
    }
}

/// The least-colliding pose inside the room when nothing is free (the room is overfull).
fn fallback_pose(
    prob: &Problem,
    i: usize,
    placed: &[Option<Pose>],
    rng: &mut rand_chacha::ChaCha8Rng,
) -> Pose {
    let [w, d, _] = prob.room;
    let s = prob.inst[i].size;
    let mut best = (
        f64::INFINITY,
        Pose {
            c: [0.0, 0.0],
            yaw: 0.0,
            z: 0.0,
        },
    );
    // a thing hung on a wall stays on a wall, at its height
    let z = prob.hung[i].unwrap_or(0.0);
    let on_wall: Vec<Pose> = if prob.wall_hung[i] {
        prob.all_candidates(i, placed)
            .into_iter()
            .filter(|p| {
                let wd = wall_distances(&prob.boxed(i, p), prob.room);
                wd.iter().all(|&v| v >= -1e-9) && wd.iter().any(|&v| v <= WALL_MARGIN + 0.03)
            })
            .collect()
    } else {
        vec![]
    };
    let random = (0..2000).map(|_| {
        let yaw = [0.0, 90.0][rng.gen_range(0..2)];
        let (ex, ey) = if yaw == 0.0 {
            (s[0], s[1])
        } else {
            (s[1], s[0])
        };
        let x = rng.gen_range(-0.5 * (w - ex).max(0.0)..=0.5 * (w - ex).max(0.0));
        let y = rng.gen_range(-0.5 * (d - ey).max(0.0)..=0.5 * (d - ey).max(0.0));
        Pose { c: [x, y], yaw, z }
    });
    let poses: Vec<Pose> = if on_wall.is_empty() {
        random.collect()
    } else {
        on_wall
    };
    for p in poses {
        let b = prob.boxed(i, &p);
        let cost: f64 = placed
            .iter()
            .enumerate()
            .filter_map(|(j, q)| q.map(|q| (j, q)))
            .filter(|(j, _)| !prob.is_stacked(i, *j))
            .map(|(j, q)| penetration(&b, &prob.boxed(j, &q)).max(0.0))
            .sum::<f64>()
            + prob
                .zones
                .iter()
                .map(|z| penetration(&b, z).max(0.0))
                .sum::<f64>();
        if cost < best.0 {
            best = (cost, p);
        }
    }
    best.1
}
