//! The score of a candidate pose, and of a finished attempt.
use super::{compose, yaw_facing, Pose, Problem, WALKWAY, WALL_MARGIN};
use crate::plan::check::{
    anchor_holds_in, penetration, relation_holds_alone, wall_distances, Box2, TOLERANCE,
};
use crate::plan::spec::{Anchor, Layout, OpeningKind, PlacedBy, RelationKind};

/// What standing out over the rim of a round support costs (a relation held counts 10): a
/// lake's boat keeps its bow and stern on the water wherever the lake has room for it.
const ELLIPSE_WEIGHT: f64 = 6.0;

/// Weight of a thing turning toward what it relates to, against the search's seeded jitter
/// (at most 3).
const FACING_WEIGHT: f64 = 1.5;
/// Weight of a pose that leaves the thing to be placed in front of it (or behind) its anchor.
const LOOKAHEAD_WEIGHT: f64 = 6.0;

impl Problem {
    /// (hard-valid, constraints satisfied, constraint count, score) of pose `p` for `i`.
    pub(super) fn evaluate(
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
        // (with what will stand on it: a stand whose TV would cover a window). A thing resting
        // on a support placed before it is held to the windows through that support's load,
        // which the support was placed with: on a dresser set under a window (a pinned scene's
        // own) a lamp still stands where it was asked, as on a sill.
        let mut loaded = b;
        loaded.z1 += self.load_height(i);
        let resting = self.rels[i]
            .iter()
            .any(|&(rel, j, subject)| subject && rel == RelationKind::Over && placed[j].is_some());
        let kept = |k: usize| !(resting && self.openings[k].kind == OpeningKind::Window);
        if self
            .zones
            .iter()
            .enumerate()
            .any(|(k, z)| kept(k) && penetration(&loaded, z) > 0.0)
        {
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
                clearance = clearance.min(crate::plan::check::gap(&b, bj));
            }
        }
        let mut total = 1;
        // a desk whose seat faces the door across it: its back to the door
        let (held, anchor) = if self.seat_faces_door(i) {
            let back = Pose {
                yaw: p.yaw + 180.0,
                ..*p
            };
            (self.boxed(i, &back), Anchor::FaceDoor)
        } else {
            (b, self.inst[i].anchor)
        };
        let mut ok = anchor_holds_in(&held, anchor, self.scene, self.room, &self.openings) as usize;
        // A thing that stands with its back to a wall (a window seat, a sideboard) still does
        // at a window: its back to the window's wall, not turned out into the room.
        if self.faced[i] && self.inst[i].anchor == Anchor::Window {
            total += 1;
            ok += anchor_holds_in(&b, Anchor::Side, self.scene, self.room, &self.openings) as usize;
        }
        let mut near = 0.0;
        let mut pose_bonus = 0.0;
        let free_yaw = !matches!(
            self.inst[i].anchor,
            Anchor::Side | Anchor::Corner | Anchor::FaceWindow | Anchor::FaceDoor
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
            // on a support drawn round lying on the ground (a lake, a round rug) a thing keeps
            // off the box's corners where it can; on a round table it may sit out over the rim
            // rather than off its support (two magazines on a small round side table)
            if subject
                && rel == RelationKind::Over
                && self.round[j]
                && bj.z1 < 0.1
                && !super::problem::on_ellipse(&b, &bj)
            {
                pose_bonus -= ELLIPSE_WEIGHT;
            }
            if rel == RelationKind::Opposite {
                // the two ends face each other, in range or not (a wall TV on the wall the
                // sofa faces, not behind it), rather than stand close
                let (sb, ob) = if subject { (&b, &bj) } else { (&bj, &b) };
                pose_bonus += 2.0
                    * FACING_WEIGHT
                    * crate::plan::check::facing_error(sb, ob).to_radians().cos();
            } else {
                near += crate::plan::check::gap(&b, &bj).min(3.0);
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
                    pose_bonus += FACING_WEIGHT
                        * crate::plan::check::facing_error(&b, &bj).to_radians().cos();
                }
            }
        }
        // a thing hung above another hangs over it, centred
        if let Some((holds, off)) = self.above_holds(i, &b, placed) {
            total += 1;
            ok += holds as usize;
            near += off;
        }
        // A thing stands where what is placed in front of or behind it can keep its own
        // anchor (a sofa where its coffee table can stand in the middle of the room), and a
        // thing in front of or behind another placed first stands where that other can keep
        // its own (a coffee table where its sofa can face the window).
        pose_bonus += LOOKAHEAD_WEIGHT * self.lookahead(i, p, &b, placed) as f64;
        // a front kept clear is one more constraint (a seat that can only be drawn up before
        // the stove's front is a relaxed one)
        let front = self.front_cost(i, &b, boxes);
        total += 1;
        ok += (front == 0.0) as usize;
        let comp = self.composition(i, p, &b, placed, boxes)
            + self.gathering(i, p, &b, placed, boxes)
            - front
            - self.staff_cost(i, &b, boxes)
            - self.sliver_cost(i, &b, placed, boxes);
        let score = 10.0 * ok as f64 + 2.0 * clearance - 0.3 * near + pose_bonus + comp + jitter;
        (true, ok, total, score)
    }
}

impl Problem {
    /// How many partners of instance `i` in FRONT or BEHIND, not placed yet, can keep their
    /// anchors at the distance the relation keeps from `i` at pose `p` (box `b`).
    fn lookahead(&self, i: usize, p: &Pose, b: &Box2, placed: &[Option<Pose>]) -> usize {
        let mut n = 0;
        for &(rel, j, subject) in &self.rels[i] {
            if rel == RelationKind::Opposite && subject && placed[j].is_none() {
                if let Some(z) = self.hung[j].filter(|_| self.wall_hung[j]) {
                    n += self.wall_spot_ahead(b, self.inst[j].size, z) as usize;
                }
                continue;
            }
            let dir = match rel {
                RelationKind::Front => 1.0,
                RelationKind::Behind => -1.0,
                _ => continue,
            };
            if placed[j].is_some() || self.inst[j].anchor == Anchor::Others {
                continue;
            }
            let sj = self.inst[j].size;
            let anchor = self.inst[j].anchor;
            let holds = |c: [f64; 2], yaw: f64| {
                let bj = Box2::new(c, yaw, [sj[0], sj[1]], 0.0, sj[2]);
                wall_distances(&bj, self.room).iter().all(|&v| v >= 0.0)
                    && anchor_holds_in(&bj, anchor, self.scene, self.room, &self.openings)
            };
            if !subject {
                // `j` stands before (behind) `i`'s face, turned as `i`
                let off = dir * (b.half[1] + compose::FRONT_GAP + 0.5 * sj[1]);
                n += holds([b.c[0] + off * b.ey[0], b.c[1] + off * b.ey[1]], p.yaw) as usize;
                continue;
            }
            // `i` stands before (behind) `j`: `j` on either side of it along its depth, facing
            // it (turned away from it)
            let off = b.half[1] + compose::FRONT_GAP + 0.5 * sj[1];
            n += [1.0, -1.0].into_iter().any(|side| {
                let c = [b.c[0] + side * off * b.ey[0], b.c[1] + side * off * b.ey[1]];
                let to = [dir * (b.c[0] - c[0]), dir * (b.c[1] - c[1])];
                holds(c, yaw_facing(to))
            }) as usize;
        }
        n
    }
}

impl Problem {
    /// Whether a thing of size `s` hung at height `z` finds a spot on the wall that a seat at
    /// box `b` faces, across from it (OPPOSITE) and clear of the doors and windows (a small
    /// lounge's sofa not set where its wall TV could only hang over a window).
    fn wall_spot_ahead(&self, b: &Box2, s: [f64; 3], z: f64) -> bool {
        let [hw, hd] = [0.5 * self.room[0], 0.5 * self.room[1]];
        // the wall ahead: its inward direction against the seat's facing
        let walls = [
            ([1.0, 0.0], -hw),
            ([-1.0, 0.0], hw),
            ([0.0, 1.0], -hd),
            ([0.0, -1.0], hd),
        ];
        let Some((inward, at)) = walls
            .into_iter()
            .find(|(n, _)| n[0] * b.ey[0] + n[1] * b.ey[1] < -0.9)
        else {
            return false;
        };
        let yaw = yaw_facing(inward);
        let off = at + (WALL_MARGIN + 0.5 * s[1]) * (inward[0] + inward[1]);
        [0.0, -0.25, 0.25, -0.5, 0.5, -0.75, 0.75].iter().any(|&t| {
            let p = [
                b.c[0] + t * b.half[0] * b.ex[0],
                b.c[1] + t * b.half[0] * b.ex[1],
            ];
            let c = if inward[0] != 0.0 {
                [off, p[1]]
            } else {
                [p[0], off]
            };
            let spot = Box2::new(c, yaw, [s[0], s[1]], z, z + s[2]);
            wall_distances(&spot, self.room).iter().all(|&v| v >= -1e-9)
                && !self.zones.iter().any(|zone| penetration(&spot, zone) > 0.0)
                && crate::plan::check::relation_holds_box(b, RelationKind::Opposite, &spot)
        })
    }
}

/// The functional-group relations, which fix their subject's turn themselves.
pub(super) fn is_group(rel: RelationKind) -> bool {
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

/// Satisfied constraints minus a large penalty per fallback.
pub(super) fn quality(prob: &Problem, l: &Layout) -> f64 {
    let mut q = 0.0;
    for o in &l.objects {
        let b = crate::plan::check::Box2::of(o);
        if anchor_holds_in(&b, o.anchor, prob.scene, prob.room, &prob.openings) {
            q += 1.0;
        }
        if o.placed_by == PlacedBy::Fallback {
            q -= 5.0;
        }
    }
    // everything a person can walk up to from the door
    q -= 2.0 * crate::plan::check::walk::unreachable(l).len() as f64;
    q - l.unsatisfied.len() as f64
}
