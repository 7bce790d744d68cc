//! How the members of a functional group stand among themselves, as soft terms of the search's
//! score: the members of a ring (tents or chairs round a fire) spread evenly round its centre,
//! the big ones (tents) beyond the small ones (seats); and a seat pulled up to its table, desk or
//! counter keeps a spot free beside or behind it where a person stands to sit down, which nothing
//! placed later takes away (a chair wedged between a wall and a planter is no seat).
use super::spacing::{HEAD_HEIGHT, SEAT_GAP, SPOT, TABLE_ROOM};
use super::{yaw_facing, Pose, Problem};
use crate::plan::check::{gap, overlap_depth, penetration, Box2, CIRCLE_GAP};
use crate::plan::spec::RelationKind;
use std::f64::consts::TAU;

/// Footprint area (m²) from which a ring member is big (a tent, not a seat): it stands in the
/// outer ring.
const BIG_MEMBER: f64 = 1.5;
/// Weight of a ring member standing closer to its neighbours than an even spread would.
const SPREAD_WEIGHT: f64 = 6.0;
/// Gap (m) between a flanker and the side of what it flanks, as its poses keep it.
const FLANK_SIDE_GAP: f64 = 0.02;
/// Weight of a thing taking the spot a flanker still to come needs: more than a relation of its
/// own, since the flanker then loses its relation and its place.
const FLANK_WEIGHT: f64 = 12.0;
/// Weight (per metre) of the gap between what stands in front of a thing on a support and the
/// support: more than the walkway the search keeps from unrelated things (2 per metre) and,
/// 0.2 m past a seat's gap, than the search's seeded jitter (at most 3).
const DRAWN_UP_WEIGHT: f64 = 20.0;
/// Weight of a seat at a table standing off the spots the table plans for its seats: more than
/// the search's seeded jitter (at most 3), less than a relation.
const SPREAD_SEAT_WEIGHT: f64 = 4.0;
/// Weight of a seat left with no standing spot.
const ACCESS_WEIGHT: f64 = 8.0;

impl Problem {
    /// Gaps (m) of the ring round a centre for a member of footprint `s`: seats close in, big
    /// things (tents) at the far edge of the ring's range, beyond the seats.
    pub(super) fn ring_gaps(s: [f64; 3]) -> [f64; 2] {
        if s[0] * s[1] >= BIG_MEMBER {
            [CIRCLE_GAP.1 - 0.3, CIRCLE_GAP.1 - 0.1]
        } else {
            [CIRCLE_GAP.0 + 0.2, CIRCLE_GAP.0 + 0.5]
        }
    }

    /// The other members of instance `i`'s ring round `j` (same category), placed or not.
    fn ring_mates(&self, i: usize, j: usize) -> Vec<usize> {
        self.rels[j]
            .iter()
            .filter(|&&(rel, k, subject)| {
                rel == RelationKind::Circle
                    && !subject
                    && k != i
                    && self.inst[k].category == self.inst[i].category
            })
            .map(|r| r.1)
            .collect()
    }

    /// Ring poses for `i` round placed `j` evenly spread from the members already placed (a
    /// third tent a third of a turn from the others), at the ring's gaps for its size.
    pub(super) fn ring_poses(
        &self,
        i: usize,
        j: usize,
        pj: &Pose,
        placed: &[Option<Pose>],
    ) -> Vec<Pose> {
        let s = self.inst[i].size;
        let mates = self.ring_mates(i, j);
        let n = mates.len() + 1;
        let ext = 0.5 * s[0].max(s[1]);
        let half = 0.5 * self.inst[j].size[0].max(self.inst[j].size[1]);
        let mut out = vec![];
        for q in mates.iter().filter_map(|&k| placed[k]) {
            let a0 = (q.c[1] - pj.c[1]).atan2(q.c[0] - pj.c[0]);
            for m in 1..n {
                let a = a0 + m as f64 * TAU / n as f64;
                for g in Self::ring_gaps(s) {
                    let r = half + g + ext;
                    let c = [pj.c[0] + r * a.cos(), pj.c[1] + r * a.sin()];
                    let yaw = yaw_facing([pj.c[0] - c[0], pj.c[1] - c[1]]);
                    out.push(Pose { c, yaw, z: 0.0 });
                }
            }
        }
        out
    }

    /// The centre of `i`'s ring (the object of its CIRCLE relation), if it has one.
    fn centre_of(&self, i: usize) -> Option<usize> {
        self.rels[i]
            .iter()
            .find(|r| r.0 == RelationKind::Circle && r.2)
            .map(|r| r.1)
    }

    /// The group term of pose `p` (box `b`) for instance `i` (0 at best, negative).
    pub(super) fn gathering(
        &self,
        i: usize,
        p: &Pose,
        b: &Box2,
        placed: &[Option<Pose>],
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> f64 {
        let mut score = 0.0;
        // A ring's members spread evenly round its centre.
        if let Some(j) = self.centre_of(i) {
            if let Some(pj) = placed[j] {
                let mates = self.ring_mates(i, j);
                let ideal = TAU / (mates.len() + 1) as f64;
                let angle = |c: [f64; 2]| (c[1] - pj.c[1]).atan2(c[0] - pj.c[0]);
                let a = angle(p.c);
                let sep = mates
                    .iter()
                    .filter_map(|&k| placed[k])
                    .map(|q| {
                        let d = (angle(q.c) - a).rem_euclid(TAU);
                        d.min(TAU - d)
                    })
                    .fold(f64::INFINITY, f64::min);
                if sep.is_finite() && mates.len() < 12 {
                    score -= SPREAD_WEIGHT * ((ideal - sep) / ideal).max(0.0);
                }
            }
        }
        // A seat keeps a standing spot; nothing takes the last one of a placed seat.
        if b.z0 < HEAD_HEIGHT && b.z1 > 0.05 {
            if let Some(t) = self.seat_table(i) {
                // and sits where its table spreads its seats, where it can
                let around = self.rels[i]
                    .iter()
                    .any(|r| r.0 == RelationKind::Around && r.1 == t && r.2);
                if let Some(pt) = placed[t].filter(|_| around) {
                    if self.off_planned_spot(i, b, t, &self.boxed(t, &pt)) {
                        score -= SPREAD_SEAT_WEIGHT;
                    }
                }
                if !self.has_spot(b, t, None, boxes) {
                    score -= ACCESS_WEIGHT;
                }
            }
            let ab = b.aabb();
            for (k, bk) in boxes.iter().enumerate() {
                let Some((bk, ak)) = bk else { continue };
                let near = aabb_gap(ak, &ab);
                if near > SPOT || k == i {
                    continue;
                }
                let Some(t) = self.seat_table(k) else {
                    continue;
                };
                // (a shelter over the seat's table, a parasol, keeps no one from sitting down)
                if t == i || self.is_stacked(i, t) || self.is_stacked(i, k) {
                    continue;
                }
                if self.has_spot(bk, t, None, boxes) && !self.has_spot(bk, t, Some(b), boxes) {
                    score -= ACCESS_WEIGHT;
                }
            }
        }
        // A table keeps room on two of its sides for its seats and the people who sit down;
        // nothing placed later takes it away.
        if b.z0 < HEAD_HEIGHT && b.z1 > 0.05 {
            let want = self.sides_wanted(i);
            if want > 0 && self.free_sides(b, i, None, boxes) < want {
                score -= ACCESS_WEIGHT;
            }
            let ab = b.aabb();
            for (k, bk) in boxes.iter().enumerate() {
                let Some((bk, ak)) = bk else { continue };
                let near = aabb_gap(ak, &ab);
                let want = self.sides_wanted(k);
                if near > TABLE_ROOM || k == i || want == 0 || self.linked(i, k) {
                    continue;
                }
                let before = self.free_sides(bk, k, None, boxes);
                if before >= want && self.free_sides(bk, k, Some(b), boxes) < want {
                    score -= ACCESS_WEIGHT;
                }
            }
        }
        score - self.flank_cost(i, b, placed, boxes) - self.drawn_up_cost(i, b, placed)
    }

    /// What stands in front of a thing on a support (a chair before a computer on a bench)
    /// is drawn up to the support, where a person uses it: the cost of its gap to it.
    fn drawn_up_cost(&self, i: usize, b: &Box2, placed: &[Option<Pose>]) -> f64 {
        let mut cost = 0.0;
        for &(rel, j, subject) in &self.rels[i] {
            if !subject || rel != RelationKind::Front || placed[j].is_none() {
                continue;
            }
            for &(rel, k, on) in &self.rels[j] {
                let Some(pk) = placed[k].filter(|_| on && rel == RelationKind::Over) else {
                    continue;
                };
                cost += DRAWN_UP_WEIGHT * (gap(b, &self.boxed(k, &pk)) - SEAT_GAP).max(0.0);
            }
        }
        cost
    }

    /// The FLANK subjects of `k` not placed yet (the armchairs either side of a fireplace).
    fn flankers_left(&self, k: usize, placed: &[Option<Pose>]) -> Vec<usize> {
        self.rels[k]
            .iter()
            .filter(|&&(rel, _, subject)| rel == RelationKind::Flank && !subject)
            .map(|r| r.1)
            .filter(|&s| placed[s].is_none())
            .collect()
    }

    /// How many of the two spots beside box `bk` (instance `k`) are free for its flankers
    /// `left` (the widest of them, backs in line with `k`'s): inside the room, clear of what
    /// is placed but the flankers' own partners (and of `extra`).
    fn free_flanks(
        &self,
        bk: &Box2,
        left: &[usize],
        extra: Option<&Box2>,
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> usize {
        let s = left
            .iter()
            .map(|&f| self.inst[f].size)
            .fold([0.0f64; 3], |a, s| {
                [a[0].max(s[0]), a[1].max(s[1]), a[2].max(s[2])]
            });
        self.free_beside(bk, s, left, extra, boxes, false)
    }

    /// How many of the two spots of size `s` beside box `bk` (backs in line with its back)
    /// are inside the room and clear of what is placed but what is linked to `left` (and of
    /// `extra`; of the doors' and windows' zones too when `zones`).
    fn free_beside(
        &self,
        bk: &Box2,
        s: [f64; 3],
        left: &[usize],
        extra: Option<&Box2>,
        boxes: &[Option<(Box2, [f64; 4])>],
        zones: bool,
    ) -> usize {
        let [w, d, _] = self.room;
        let yaw = (-bk.ey[0]).atan2(bk.ey[1]).to_degrees();
        let [hw, hd] = bk.half;
        let clear = |spot: &Box2, o: &Box2| penetration(spot, o) <= 0.02;
        [-1.0, 1.0]
            .into_iter()
            .filter(|side| {
                let (lx, ly) = (side * (hw + FLANK_SIDE_GAP + 0.5 * s[0]), -hd + 0.5 * s[1]);
                let c = [
                    bk.c[0] + lx * bk.ex[0] + ly * bk.ey[0],
                    bk.c[1] + lx * bk.ex[1] + ly * bk.ey[1],
                ];
                let spot = Box2::new(c, yaw, [s[0], s[1]], 0.0, s[2]);
                let [x0, y0, x1, y1] = spot.aabb();
                x0 >= -0.5 * w
                    && x1 <= 0.5 * w
                    && y0 >= -0.5 * d
                    && y1 <= 0.5 * d
                    && extra.is_none_or(|e| clear(&spot, e))
                    && (!zones || self.zones.iter().all(|z| penetration(&spot, z) <= 0.0))
                    && boxes.iter().enumerate().all(|(j, bj)| {
                        let Some((bj, _)) = bj else { return true };
                        left.iter().any(|&f| self.linked(f, j)) || clear(&spot, bj)
                    })
            })
            .count()
    }

    /// Whether pose box `b` of `i`, set beside a placed thing it flanks, leaves its other
    /// side free for a thing it flanks that is still to come (one nightstand between two beds:
    /// the second bed's spot inside the room and clear of what is placed); true when `i`
    /// flanks no such pair.
    fn shared_flank_free(
        &self,
        i: usize,
        b: &Box2,
        placed: &[Option<Pose>],
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> bool {
        let flanked = |on: bool| {
            self.rels[i]
                .iter()
                .filter(move |&&(rel, k, subject)| {
                    subject && rel == RelationKind::Flank && placed[k].is_some() == on
                })
                .map(|r| r.1)
        };
        let (Some(p), Some(k)) = (flanked(true).next(), flanked(false).next()) else {
            return true;
        };
        let Some((bp, _)) = boxes[p] else {
            return true;
        };
        let rel = [bp.c[0] - b.c[0], bp.c[1] - b.c[1]];
        let side = if rel[0] * b.ex[0] + rel[1] * b.ex[1] >= 0.0 {
            -1.0
        } else {
            1.0
        };
        let s = self.inst[k].size;
        let [hw, hd] = b.half;
        let (lx, ly) = (side * (hw + FLANK_SIDE_GAP + 0.5 * s[0]), -hd + 0.5 * s[1]);
        let c = [
            b.c[0] + lx * b.ex[0] + ly * b.ey[0],
            b.c[1] + lx * b.ex[1] + ly * b.ey[1],
        ];
        let yaw = (-b.ey[0]).atan2(b.ey[1]).to_degrees();
        let spot = Box2::new(c, yaw, [s[0], s[1]], 0.0, s[2]);
        let [x0, y0, x1, y1] = spot.aabb();
        let [w, d, _] = self.room;
        x0 >= -0.5 * w
            && x1 <= 0.5 * w
            && y0 >= -0.5 * d
            && y1 <= 0.5 * d
            && self.zones.iter().all(|z| penetration(&spot, z) <= 0.0)
            && boxes.iter().enumerate().all(|(j, bj)| {
                let Some((bj, _)) = bj else { return true };
                j == i || self.linked(k, j) && j != p || penetration(&spot, bj) <= 0.02
            })
    }

    /// The cost of pose box `b` for `i` keeping flank spots: a thing with flankers to come
    /// stands where both sides of it are free, and nothing placed before them takes the spot
    /// one of them needs (a TV stand beside the fireplace whose armchairs are still to come).
    fn flank_cost(
        &self,
        i: usize,
        b: &Box2,
        placed: &[Option<Pose>],
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> f64 {
        if b.z0 >= HEAD_HEIGHT {
            return 0.0;
        }
        let mut cost = 0.0;
        if !self.shared_flank_free(i, b, placed, boxes) {
            cost += FLANK_WEIGHT;
        }
        let own = self.flankers_left(i, placed);
        if !own.is_empty() && self.free_flanks(b, &own, None, boxes) < own.len().min(2) {
            cost += ACCESS_WEIGHT;
        }
        // a flanker shared with a thing still to come (one nightstand between two beds) needs
        // a side with room for both, the other thing beyond it
        for &f in &own {
            let (sf, gap) = (self.inst[f].size, FLANK_SIDE_GAP);
            let beyond = self.rels[f].iter().find(|&&(rel, k, subject)| {
                subject && rel == RelationKind::Flank && k != i && placed[k].is_none()
            });
            if let Some(&(_, k, _)) = beyond {
                let sk = self.inst[k].size;
                // (with what stands on the flanker: a lamp on the nightstand before a window)
                let high = (sf[2] + self.load_height(f)).max(sk[2] + self.load_height(k));
                let both = [sf[0] + gap + sk[0], sf[1].max(sk[1]), high];
                if self.free_beside(b, both, &[f, k], None, boxes, true) == 0 {
                    cost += FLANK_WEIGHT;
                }
            }
        }
        let ab = b.aabb();
        for (k, bk) in boxes.iter().enumerate() {
            let Some((bk, ak)) = bk else { continue };
            if k == i || aabb_gap(ak, &ab) > 2.0 {
                continue;
            }
            let left: Vec<usize> = self
                .flankers_left(k, placed)
                .into_iter()
                .filter(|&f| f != i)
                .collect();
            if left.is_empty() || self.flankers_left(k, placed).contains(&i) {
                continue;
            }
            let need = left.len().min(2);
            if self.free_flanks(bk, &left, None, boxes) >= need
                && self.free_flanks(bk, &left, Some(b), boxes) < need
            {
                cost += FLANK_WEIGHT;
            }
        }
        cost
    }

    /// Whether `i` and `j` are related in the spec.
    fn linked(&self, i: usize, j: usize) -> bool {
        self.rels[i].iter().any(|r| r.1 == j)
    }

    /// How many sides of table `t` keep room for its seats: those its AROUND seats take (four
    /// at a small table for four, the long pair at a long one), 0 when none.
    fn sides_wanted(&self, t: usize) -> usize {
        match self.sides_of(t) {
            (_, Some((count, _))) => count.iter().filter(|&&c| c > 0).count(),
            (seats, _) => seats.len().min(2),
        }
    }

    /// How many sides of table box `b` (instance `t`) have [`TABLE_ROOM`] free beyond them:
    /// inside the room, clear of what is placed (and of `extra`) but `t`'s own partners.
    fn free_sides(
        &self,
        b: &Box2,
        t: usize,
        extra: Option<&Box2>,
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> usize {
        let [w, d, _] = self.room;
        let yaw = (-b.ey[0]).atan2(b.ey[1]).to_degrees();
        let [hx, hy] = b.half;
        let at = |lx: f64, ly: f64| {
            [
                b.c[0] + lx * b.ex[0] + ly * b.ey[0],
                b.c[1] + lx * b.ex[1] + ly * b.ey[1],
            ]
        };
        let r = 0.5 * TABLE_ROOM;
        let bands = [
            Box2::new(at(0.0, hy + r), yaw, [2.0 * hx, TABLE_ROOM], 0.0, 1.8),
            Box2::new(at(0.0, -hy - r), yaw, [2.0 * hx, TABLE_ROOM], 0.0, 1.8),
            Box2::new(at(hx + r, 0.0), yaw, [TABLE_ROOM, 2.0 * hy], 0.0, 1.8),
            Box2::new(at(-hx - r, 0.0), yaw, [TABLE_ROOM, 2.0 * hy], 0.0, 1.8),
        ];
        let clear =
            |s: &Box2, o: &Box2| o.z0 >= HEAD_HEIGHT || o.z1 <= 0.05 || overlap_depth(s, o) <= 0.02;
        bands
            .iter()
            .filter(|s| {
                let [x0, y0, x1, y1] = s.aabb();
                x0 >= -0.5 * w
                    && x1 <= 0.5 * w
                    && y0 >= -0.5 * d
                    && y1 <= 0.5 * d
                    && extra.is_none_or(|e| clear(s, e))
                    && boxes.iter().enumerate().all(|(k, bk)| {
                        let Some((bk, _)) = bk else { return true };
                        k == t || self.linked(t, k) || clear(s, bk)
                    })
            })
            .count()
    }

    /// The table, desk or counter instance `i` is a seat at (AROUND or AT), if any.
    fn seat_table(&self, i: usize) -> Option<usize> {
        self.rels[i]
            .iter()
            .find(|r| r.2 && matches!(r.0, RelationKind::Around | RelationKind::At))
            .map(|r| r.1)
    }

    /// Whether seat box `b` at table `t` has a standing spot behind it or at either side:
    /// inside the room and clear of every placed box below head height (and of `extra`).
    fn has_spot(
        &self,
        b: &Box2,
        t: usize,
        extra: Option<&Box2>,
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> bool {
        let [w, d, _] = self.room;
        let yaw = (-b.ey[0]).atan2(b.ey[1]).to_degrees();
        let at = |lx: f64, ly: f64| {
            [
                b.c[0] + lx * b.ex[0] + ly * b.ey[0],
                b.c[1] + lx * b.ex[1] + ly * b.ey[1],
            ]
        };
        let [hx, hy] = b.half;
        let spots = [
            Box2::new(at(0.0, -hy - 0.5 * SPOT), yaw, [2.0 * hx, SPOT], 0.0, 1.8),
            Box2::new(at(-hx - 0.5 * SPOT, 0.0), yaw, [SPOT, 2.0 * hy], 0.0, 1.8),
            Box2::new(at(hx + 0.5 * SPOT, 0.0), yaw, [SPOT, 2.0 * hy], 0.0, 1.8),
        ];
        spots.iter().any(|s| {
            let [x0, y0, x1, y1] = s.aabb();
            let inside = x0 >= -0.5 * w && x1 <= 0.5 * w && y0 >= -0.5 * d && y1 <= 0.5 * d;
            inside
                && extra.is_none_or(|e| e.z0 >= HEAD_HEIGHT || overlap_depth(s, e) <= 0.02)
                && boxes.iter().enumerate().all(|(k, bk)| {
                    let Some((bk, _)) = bk else { return true };
                    k == t
                        || self.is_stacked(k, t)
                        || bk.z0 >= HEAD_HEIGHT
                        || bk.z1 <= 0.05
                        || overlap_depth(s, bk) <= 0.02
                })
        })
    }
}

/// How far apart two axis-aligned boxes `[x0, y0, x1, y1]` are along the axis that separates
/// them most (negative when they overlap).
fn aabb_gap(a: &[f64; 4], b: &[f64; 4]) -> f64 {
    (a[0] - b[2])
        .max(b[0] - a[2])
        .max(a[1] - b[3])
        .max(b[1] - a[3])
}

#[cfg(test)]
mod tests {
    use crate::plan::check::{facing_footprint_error, gap, Box2};
    use crate::plan::gcp::{layout, LayoutOptions};
    use crate::plan::spec::SceneSpec;

    #[test]
    fn tents_round_a_fire_stand_beyond_the_seats_and_face_it() {
        let text = r#"{"scene_type":"outdoor","scene_text":"t","objects":{
            "tent":{"number":3,"size":[2.5,2.5,1.5],"description":"d"},
            "camp chair":{"number":4,"size":[0.6,0.6,0.9],"description":"d"},
            "fire pit":{"number":1,"size":[1.0,1.0,0.4],"description":"d"}},
            "relations":[
            {"subject":"tent1","relation":"CIRCLE","object":"fire pit1"},
            {"subject":"tent2","relation":"CIRCLE","object":"fire pit1"},
            {"subject":"tent3","relation":"CIRCLE","object":"fire pit1"},
            {"subject":"camp chair1","relation":"CIRCLE","object":"fire pit1"},
            {"subject":"camp chair2","relation":"CIRCLE","object":"fire pit1"},
            {"subject":"camp chair3","relation":"CIRCLE","object":"fire pit1"},
            {"subject":"camp chair4","relation":"CIRCLE","object":"fire pit1"}]}"#;
        let spec: SceneSpec = serde_json::from_str(text).expect("spec");
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).expect("laid out");
            assert!(l.unsatisfied.is_empty(), "seed {seed}: {:?}", l.unsatisfied);
            let get = |id: &str| l.objects.iter().find(|o| o.id == id).expect("placed");
            let fire = Box2::of(get("fire pit1"));
            let tents = ["tent1", "tent2", "tent3"];
            for a in tents {
                let t = Box2::of(get(a));
                assert!(
                    facing_footprint_error(&t, &fire) <= 30.0,
                    "seed {seed}: {a} turned away"
                );
                let seat = Box2::of(get("camp chair1"));
                assert!(
                    gap(&t, &fire) > gap(&seat, &fire),
                    "seed {seed}: {a} inside the seats"
                );
            }
        }
    }
}
