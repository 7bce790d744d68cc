//! Composition as furnishers do it, as soft terms of the search's score: the two ends of an
//! OPPOSITE pair (a TV and its sofa) on one axis with nothing taller than 0.6 m between them;
//! the face of a thing against a wall (a wardrobe's doors, a bookcase's shelves, a fireplace)
//! kept free 0.6 m deep of things not related to it; a thing NEXT to another at its sides
//! rather than off its back, and not in front of its face; a thing alone on its support centred on it (at its back
//! when the support stands against a wall); a thing by a
//! window or door as close to it as it can stand; a thing in FRONT of or BEHIND another
//! centred on its axis, between [`FRONT_LEGROOM`] and [`FRONT_GAP`] from it and square to
//! it; a thing over another that it is longer than (UNDER) spanning it,
//! past both ends, and centred over what stands under it.
use super::pairs::{VIEW_FAR, VIEW_NEAR};
use super::{Pose, Problem};
use crate::plan::check::{
    blocks_sight, gap, opening_distance, overlap_depth, sight_zone, Box2, SIGHTLINE_HEIGHT,
};
use crate::plan::spec::{Anchor, OpeningKind, RelationKind};

/// Depth kept free in front of a thing against a wall (m).
pub const FACE_CLEARANCE: f64 = 0.6;
/// The gap a thing in FRONT of or BEHIND another keeps at most without cost (m): a coffee
/// table within reach of the sofa's seat (furnishers' 40-50 cm).
pub const FRONT_GAP: f64 = 0.45;
/// The gap below which a thing in FRONT of another leaves no room for legs (m).
pub const FRONT_LEGROOM: f64 = 0.3;

/// The free space in front of `b`'s face.
fn face_zone(b: &Box2) -> Box2 {
    let c = [
        b.c[0] + b.ey[0] * (b.half[1] + 0.5 * FACE_CLEARANCE),
        b.c[1] + b.ey[1] * (b.half[1] + 0.5 * FACE_CLEARANCE),
    ];
    let yaw = (-b.ey[0]).atan2(b.ey[1]).to_degrees();
    Box2::new(c, yaw, [2.0 * b.half[0], FACE_CLEARANCE], 0.0, 2.0)
}

/// How far `over`'s long axis reaches past `under` at each end (m), 0 when it does not
/// reach past them, at most 1.
fn span(over: &Box2, under: &Box2) -> f64 {
    let (ax, half) = if over.half[0] >= over.half[1] {
        (over.ex, over.half[0])
    } else {
        (over.ey, over.half[1])
    };
    let dot = |a: [f64; 2], b: [f64; 2]| (a[0] * b[0] + a[1] * b[1]).abs();
    let extent = dot(ax, under.ex) * under.half[0] + dot(ax, under.ey) * under.half[1];
    (half - extent).clamp(0.0, 1.0)
}

impl Problem {
    /// How many things rest on instance `j`.
    fn load(&self, j: usize) -> usize {
        self.rels[j]
            .iter()
            .filter(|r| r.0 == RelationKind::Over && !r.2)
            .count()
    }

    /// The height of the tallest thing that rests on instance `j` (0 when none does).
    pub(super) fn load_height(&self, j: usize) -> f64 {
        self.rels[j]
            .iter()
            .filter(|r| r.0 == RelationKind::Over && !r.2)
            .map(|r| self.inst[r.1].size[2])
            .fold(0.0, f64::max)
    }

    /// The viewing-distance cost of a thing at `b` whose OPPOSITE partner `j`, not placed yet,
    /// will stand against a wall: that partner before the wall `b` faces, at most [`VIEW_FAR`]
    /// away (0 when it can be).
    fn view_ahead(&self, b: &Box2, j: usize) -> f64 {
        let [hw, hd] = [0.5 * self.room[0], 0.5 * self.room[1]];
        // distance along b's facing to the wall it looks at
        let reach = |c: f64, e: f64, h: f64| {
            if e > 1e-6 {
                (h - c) / e
            } else if e < -1e-6 {
                (-h - c) / e
            } else {
                f64::INFINITY
            }
        };
        let t = reach(b.c[0], b.ey[0], hw).min(reach(b.c[1], b.ey[1], hd));
        let d = t - super::WALL_MARGIN - 0.5 * self.inst[j].size[1];
        4.0 * ((d - VIEW_FAR).max(0.0) + (VIEW_NEAR - d).max(0.0)).min(2.0)
    }

    fn related(&self, i: usize, j: usize) -> bool {
        self.rels[i].iter().any(|r| r.1 == j)
    }

    /// The composition term of pose `p` (box `b`) for instance `i` (0 at best, negative).
    pub(super) fn composition(
        &self,
        i: usize,
        p: &Pose,
        b: &Box2,
        placed: &[Option<Pose>],
        boxes: &[Option<(Box2, [f64; 4])>],
    ) -> f64 {
        let mut score = 0.0;
        let boxed = |j: usize| boxes[j].as_ref().map(|x| x.0);
        // Sightlines of the placed OPPOSITE pairs that this pose would cross, with what will
        // stand on it (a low stand under its TV).
        let mut loaded = *b;
        loaded.z1 += self.load_height(i);
        if loaded.z1 > SIGHTLINE_HEIGHT {
            for &(a, c) in &self.sightlines {
                if a == i || c == i || self.belongs_to(i, a) || self.belongs_to(i, c) {
                    continue;
                }
                if let (Some(ba), Some(bc)) = (boxed(a), boxed(c)) {
                    if blocks_sight(&loaded, &sight_zone(&ba, &bc)) {
                        score -= 12.0;
                    }
                }
            }
        }
        // The view from a block of rows to its front is kept clear of what belongs to neither
        // (a default table squeezed before the first row).
        if b.z1 > SIGHTLINE_HEIGHT && b.z0 < super::spacing::HEAD_HEIGHT {
            for (band, members) in &self.bands {
                let belongs =
                    members.contains(&i) || self.rels[i].iter().any(|r| members.contains(&r.1));
                // (more than an anchor is worth: a table kept mid-room gives the middle up)
                if !belongs && overlap_depth(b, band) > 0.0 {
                    score -= 25.0;
                }
            }
        }
        for &(rel, j, subject) in &self.rels[i] {
            let Some(bj) = boxed(j) else {
                if rel == RelationKind::Opposite && self.inst[j].anchor == Anchor::Side {
                    score -= self.view_ahead(b, j);
                }
                continue;
            };
            match rel {
                RelationKind::Opposite => {
                    // on the partner's axis (the object's frame), and nothing tall between
                    let lateral = if subject {
                        bj.local(p.c)[0]
                    } else {
                        b.local(bj.c)[0]
                    };
                    score -= 5.0 * lateral.abs().min(2.0);
                    // at a viewing distance (a sofa 2-3 m from its TV)
                    let d = ((p.c[0] - bj.c[0]).powi(2) + (p.c[1] - bj.c[1]).powi(2)).sqrt();
                    score -= 4.0 * ((d - VIEW_FAR).max(0.0) + (VIEW_NEAR - d).max(0.0)).min(2.0);
                    let zone = sight_zone(b, &bj);
                    for (k, bk) in boxes.iter().enumerate() {
                        let Some((bk, _)) = bk else { continue };
                        if k == j || bk.z1 <= SIGHTLINE_HEIGHT {
                            continue;
                        }
                        if self.belongs_to(k, i) || self.belongs_to(k, j) {
                            continue;
                        }
                        if blocks_sight(bk, &zone) {
                            score -= 12.0;
                        }
                    }
                }
                RelationKind::Over if subject && self.load(j) == 1 => {
                    // alone on its support: centred on it, at its back when the support
                    // stands against a wall (a TV on its stand, a monitor on a desk)
                    let back = if self.faced[j] {
                        (bj.half[1] - 0.5 * self.inst[i].size[1]).max(0.0)
                    } else {
                        0.0
                    };
                    let t = [bj.c[0] - bj.ey[0] * back, bj.c[1] - bj.ey[1] * back];
                    let d = ((p.c[0] - t[0]).powi(2) + (p.c[1] - t[1]).powi(2)).sqrt();
                    score -= 8.0 * d;
                }
                RelationKind::Front | RelationKind::Behind => {
                    // in front of or behind a thing is centred on its axis (a coffee table
                    // before the middle of its sofa)
                    let lateral = if subject {
                        bj.local(p.c)[0]
                    } else {
                        b.local(bj.c)[0]
                    };
                    score -= 3.0 * lateral.abs().min(2.0);
                    // and within reach of it (a coffee table about 0.45 m from its sofa)
                    let g = gap(b, &bj);
                    score -= 4.0 * (g - FRONT_GAP).clamp(0.0, 2.5);
                    // with room for legs between them
                    score -= 30.0 * (FRONT_LEGROOM - g).max(0.0);
                    // and square to it (a coffee table parallel to its sofa)
                    let turn = (p.yaw - placed[j].map_or(p.yaw, |q| q.yaw)).to_radians();
                    score -= 4.0 * turn.sin().abs();
                }
                RelationKind::Under => {
                    // a thing over another that it is longer than spans it with its length,
                    // reaching past both ends (a bridge across its pond); 0 when it is not
                    let (over, under) = if subject { (&bj, b) } else { (b, &bj) };
                    score += 4.0 * span(over, under);
                    if !subject {
                        // a roof centred over what stands under it (a gazebo over its table)
                        let d = ((p.c[0] - bj.c[0]).powi(2) + (p.c[1] - bj.c[1]).powi(2)).sqrt();
                        score -= 3.0 * d.min(3.0);
                    }
                }
                RelationKind::Next if subject => {
                    // at its ends: not before its face, nor off its back (an armchair at the
                    // end of a coffee table, not between it and the TV)
                    let ly = bj.local(p.c)[1];
                    if ly > bj.half[1] {
                        score -= 3.0;
                    } else if ly < -bj.half[1] {
                        score -= 2.0;
                    }
                }
                _ => {}
            }
        }
        // Things by a window or door stand as close to it as they can.
        let kind = match self.inst[i].anchor {
            Anchor::Window => Some(OpeningKind::Window),
            Anchor::Door => Some(OpeningKind::Door),
            _ => None,
        };
        if let Some(kind) = kind {
            let d = self
                .openings
                .iter()
                .filter(|o| o.kind == kind)
                .map(|o| opening_distance(b, o))
                .fold(f64::INFINITY, f64::min);
            if d.is_finite() {
                score -= 4.0 * d.min(2.0);
            }
        }
        // Faces of things against walls.
        if b.z0 < 1.0 {
            for (j, bj) in boxes.iter().enumerate() {
                let Some((bj, _)) = bj else { continue };
                if self.faced[j]
                    && !self.related(i, j)
                    && !self.is_stacked(i, j)
                    && overlap_depth(b, &face_zone(bj)) > 0.05
                {
                    score -= 4.0;
                }
            }
        }
        if self.faced[i] {
            let zone = face_zone(b);
            for (j, bj) in boxes.iter().enumerate() {
                let Some((bj, _)) = bj else { continue };
                if bj.z0 < 1.0
                    && !self.related(i, j)
                    && !self.is_stacked(i, j)
                    && overlap_depth(bj, &zone) > 0.05
                {
                    score -= 4.0;
                }
            }
        }
        score
    }
}
