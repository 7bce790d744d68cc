//! The meaning of relations, anchors and validity (ARCHITECTURE.md), as predicates on placed
//! objects. The layout search filters candidates with them and the tests check layouts with them.
use super::spec::{
    Anchor, Layout, MissedAnchor, Opening, OpeningKind, PlacedObject, Relation, RelationKind,
    SceneSpec, SceneType,
};

pub mod ceiling;
pub mod fronts;
pub mod walk;

/// Footprint of an object: centre, yaw (radians), half extents (width, depth), and z range.
#[derive(Debug, Clone, Copy)]
pub struct Box2 {
    pub c: [f64; 2],
    pub ex: [f64; 2],
    pub ey: [f64; 2],
    pub half: [f64; 2],
    pub z0: f64,
    pub z1: f64,
}

impl Box2 {
    pub fn of(o: &PlacedObject) -> Box2 {
        Box2::new(
            [o.position[0], o.position[1]],
            o.yaw,
            [o.size[0], o.size[1]],
            o.position[2],
            o.position[2] + o.size[2],
        )
    }

    pub fn new(c: [f64; 2], yaw_deg: f64, size: [f64; 2], z0: f64, z1: f64) -> Box2 {
        let (s, co) = yaw_deg.to_radians().sin_cos();
        Box2 {
            c,
            // local +x (the object's right) and local +y (its facing)
            ex: [co, s],
            ey: [-s, co],
            half: [0.5 * size[0], 0.5 * size[1]],
            z0,
            z1,
        }
    }

    /// Point in this box's local frame.
    pub fn local(&self, p: [f64; 2]) -> [f64; 2] {
        let d = [p[0] - self.c[0], p[1] - self.c[1]];
        [
            d[0] * self.ex[0] + d[1] * self.ex[1],
            d[0] * self.ey[0] + d[1] * self.ey[1],
        ]
    }

    pub fn corners(&self) -> [[f64; 2]; 4] {
        let [hx, hy] = self.half;
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(a, b)| {
            [
                self.c[0] + a * hx * self.ex[0] + b * hy * self.ey[0],
                self.c[1] + a * hx * self.ex[1] + b * hy * self.ey[1],
            ]
        })
    }

    /// Interval of `other`'s footprint projected on this box's local axis `axis` (0: x, 1: y).
    pub fn project_other(&self, other: &Box2, axis: usize) -> (f64, f64) {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for p in other.corners() {
            let v = self.local(p)[axis];
            lo = lo.min(v);
            hi = hi.max(v);
        }
        (lo, hi)
    }

    /// World-axis bounding box [xmin, ymin, xmax, ymax].
    pub fn aabb(&self) -> [f64; 4] {
        let c = self.corners();
        let xs = c.map(|p| p[0]);
        let ys = c.map(|p| p[1]);
        [
            xs.iter().copied().fold(f64::INFINITY, f64::min),
            ys.iter().copied().fold(f64::INFINITY, f64::min),
            xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            ys.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        ]
    }

    pub fn contains(&self, p: [f64; 2]) -> bool {
        let l = self.local(p);
        l[0].abs() <= self.half[0] + 1e-9 && l[1].abs() <= self.half[1] + 1e-9
    }
}

fn axes(a: &Box2, b: &Box2) -> [[f64; 2]; 4] {
    [a.ex, a.ey, b.ex, b.ey]
}

fn proj(b: &Box2, axis: [f64; 2]) -> (f64, f64) {
    let c = b.c[0] * axis[0] + b.c[1] * axis[1];
    let r = b.half[0] * (b.ex[0] * axis[0] + b.ex[1] * axis[1]).abs()
        + b.half[1] * (b.ey[0] * axis[0] + b.ey[1] * axis[1]).abs();
    (c - r, c + r)
}

/// Depth of 2D overlap (smallest separating-axis overlap); <= 0 when the footprints are apart.
pub fn overlap_depth(a: &Box2, b: &Box2) -> f64 {
    let mut best = f64::INFINITY;
    for ax in axes(a, b) {
        let (a0, a1) = proj(a, ax);
        let (b0, b1) = proj(b, ax);
        best = best.min(a1.min(b1) - a0.max(b0));
    }
    best
}

/// Interpenetration of two boxes: the smaller of footprint overlap depth and z overlap.
pub fn penetration(a: &Box2, b: &Box2) -> f64 {
    let z = a.z1.min(b.z1) - a.z0.max(b.z0);
    overlap_depth(a, b).min(z)
}

fn seg_point_dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let ap = [p[0] - a[0], p[1] - a[1]];
    let l2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t = if l2 > 0.0 {
        ((ap[0] * ab[0] + ap[1] * ab[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let d = [ap[0] - t * ab[0], ap[1] - t * ab[1]];
    (d[0] * d[0] + d[1] * d[1]).sqrt()
}

/// Gap between two footprints (0 when they touch or overlap).
pub fn gap(a: &Box2, b: &Box2) -> f64 {
    if overlap_depth(a, b) >= 0.0 {
        return 0.0;
    }
    let (ca, cb) = (a.corners(), b.corners());
    let mut best = f64::INFINITY;
    for i in 0..4 {
        for p in cb {
            best = best.min(seg_point_dist(p, ca[i], ca[(i + 1) % 4]));
        }
        for p in ca {
            best = best.min(seg_point_dist(p, cb[i], cb[(i + 1) % 4]));
        }
    }
    best
}

/// Largest footprint gap of FRONT / BEHIND / LEFT / RIGHT.
pub const DIRECTIONAL_GAP: f64 = 3.0;
/// Largest footprint gap of NEXT.
pub const NEXT_GAP: f64 = 0.5;
/// Largest footprint gap of FRONT / BEHIND when the subject is the only thing on that side of
/// its object (a coffee table before its sofa, a rug at the foot of a bed): within reach.
pub const FRONT_REACH: f64 = 0.6;
/// How far off its object's axis the only thing in FRONT of / BEHIND it may stand, as a
/// fraction of the object's half width.
pub const FRONT_CENTRING: f64 = 0.5;
/// Height above which a thing blocks a sightline (m).
pub const SIGHTLINE_HEIGHT: f64 = 0.6;
/// Height from which a thing hangs clear of a sightline (m): a seated eye is below it.
pub const SIGHTLINE_CLEAR_ABOVE: f64 = 1.2;

/// Angle in degrees between the facing of `s` and the direction from `s` to `o`.
pub fn facing_error(s: &Box2, o: &Box2) -> f64 {
    let d = [o.c[0] - s.c[0], o.c[1] - s.c[1]];
    let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
    if l == 0.0 {
        return 180.0;
    }
    let c = (d[0] * s.ey[0] + d[1] * s.ey[1]) / l;
    c.clamp(-1.0, 1.0).acos().to_degrees()
}

/// Largest footprint gap of AROUND and AT (a seat pulled up to its table, desk or counter).
pub const SEAT_GAP: f64 = 0.3;
/// Largest footprint gap of FLANK (flush beside).
pub const FLANK_GAP: f64 = 0.15;
/// Largest distance between the backs of a FLANK pair.
pub const FLANK_BACK: f64 = 0.25;
/// Footprint gap range of CIRCLE (seats round a fire).
pub const CIRCLE_GAP: (f64, f64) = (0.6, 1.5);
/// Footprint gap range of BEFORE: a seat's room between the subject and its object (a
/// teacher's chair between the desk and the board), and no farther than the front of a room.
pub const BEFORE_GAP: (f64, f64) = (0.7, 2.5);
/// Largest angle of "facing" in AROUND, AT, AT_BACK, FLANK, CIRCLE, ROW and BEFORE.
pub const FACING_TOLERANCE: f64 = 30.0;

/// The point of `o`'s footprint nearest to `p`.
pub fn nearest_point(o: &Box2, p: [f64; 2]) -> [f64; 2] {
    let l = o.local(p);
    let x = l[0].clamp(-o.half[0], o.half[0]);
    let y = l[1].clamp(-o.half[1], o.half[1]);
    [
        o.c[0] + x * o.ex[0] + y * o.ey[0],
        o.c[1] + x * o.ex[1] + y * o.ey[1],
    ]
}

/// Angle in degrees between the facing of `s` and the direction from its centre to the nearest
/// point of `o`'s footprint (180 when the centre is inside it).
pub fn facing_footprint_error(s: &Box2, o: &Box2) -> f64 {
    let q = nearest_point(o, s.c);
    let d = [q[0] - s.c[0], q[1] - s.c[1]];
    let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
    if l < 1e-9 {
        return 180.0;
    }
    let c = (d[0] * s.ey[0] + d[1] * s.ey[1]) / l;
    c.clamp(-1.0, 1.0).acos().to_degrees()
}

/// Angle in degrees between the facings of two boxes.
pub fn yaw_difference(a: &Box2, b: &Box2) -> f64 {
    let c = a.ey[0] * b.ey[0] + a.ey[1] * b.ey[1];
    c.clamp(-1.0, 1.0).acos().to_degrees()
}

/// Whether "s is `rel` of o" holds.
pub fn relation_holds(s: &PlacedObject, rel: RelationKind, o: &PlacedObject) -> bool {
    relation_holds_box(&Box2::of(s), rel, &Box2::of(o))
}

/// [`relation_holds`] on boxes.
pub fn relation_holds_box(sb: &Box2, rel: RelationKind, ob: &Box2) -> bool {
    let l = ob.local(sb.c);
    let [hw, hd] = ob.half;
    let band = |axis: usize, h: f64| {
        let (lo, hi) = ob.project_other(sb, axis);
        hi >= -h - 1e-9 && lo <= h + 1e-9
    };
    let top = ob.z1;
    match rel {
        RelationKind::Front => l[1] > hd && band(0, hw) && gap(sb, ob) <= DIRECTIONAL_GAP,
        RelationKind::Behind => l[1] < -hd && band(0, hw) && gap(sb, ob) <= DIRECTIONAL_GAP,
        RelationKind::Left => l[0] < -hw && band(1, hd) && gap(sb, ob) <= DIRECTIONAL_GAP,
        RelationKind::Right => l[0] > hw && band(1, hd) && gap(sb, ob) <= DIRECTIONAL_GAP,
        RelationKind::Next => gap(sb, ob) <= NEXT_GAP,
        RelationKind::Opposite => {
            let d = ((sb.c[0] - ob.c[0]).powi(2) + (sb.c[1] - ob.c[1]).powi(2)).sqrt();
            // facing it: its centre, and the nearest point of its footprint (a sofa beside a
            // screen's end, turned to its centre, sees the screen's edge)
            l[1] > hd
                && band(0, hw)
                && (1.0..=5.0).contains(&d)
                && facing_error(sb, ob) <= 30.0
                && facing_footprint_error(sb, ob) <= 30.0
        }
        RelationKind::Over => ob.contains(sb.c) && (sb.z0 - top).abs() <= 0.05,
        // below it, one over the other: a thing on a wall (a mirror, 4 cm deep) is over a sink
        // whose footprint holds its centre, though the sink's centre is not in the mirror's
        RelationKind::Under => (ob.contains(sb.c) || sb.contains(ob.c)) && sb.z1 <= top + 1e-6,
        RelationKind::Around => {
            let beside = (l[0].abs() <= hw + 1e-9) != (l[1].abs() <= hd + 1e-9);
            beside
                && overlap_depth(sb, ob) <= TOLERANCE
                && gap(sb, ob) <= SEAT_GAP
                && facing_footprint_error(sb, ob) <= FACING_TOLERANCE
        }
        RelationKind::At => {
            l[1] > hd
                && band(0, hw)
                && overlap_depth(sb, ob) <= TOLERANCE
                && gap(sb, ob) <= SEAT_GAP
                && facing_footprint_error(sb, ob) <= FACING_TOLERANCE
        }
        RelationKind::Flank => {
            // the subject's back: its local -y face, in the object's frame
            let back = ob.local([
                sb.c[0] - sb.ey[0] * sb.half[1],
                sb.c[1] - sb.ey[1] * sb.half[1],
            ]);
            l[0].abs() > hw
                && band(1, hd)
                && gap(sb, ob) <= FLANK_GAP
                && (back[1] + hd).abs() <= FLANK_BACK
                && yaw_difference(sb, ob) <= FACING_TOLERANCE
        }
        RelationKind::Circle => {
            let g = gap(sb, ob);
            (CIRCLE_GAP.0..=CIRCLE_GAP.1).contains(&g)
                && facing_footprint_error(sb, ob) <= FACING_TOLERANCE
        }
        RelationKind::Row => l[1] > hd && yaw_difference(sb, ob) >= 180.0 - FACING_TOLERANCE,
        RelationKind::AtBack => {
            l[1] < -hd
                && band(0, hw)
                && overlap_depth(sb, ob) <= TOLERANCE
                && gap(sb, ob) <= SEAT_GAP
                && facing_footprint_error(sb, ob) <= FACING_TOLERANCE
        }
        RelationKind::Before => {
            let g = gap(sb, ob);
            l[1] > hd
                && band(0, hw)
                && (BEFORE_GAP.0 - 1e-9..=BEFORE_GAP.1 + 1e-9).contains(&g)
                && yaw_difference(sb, ob) <= FACING_TOLERANCE
        }
    }
}

/// [`relation_holds_box`], and when `alone` (the subject is the only one in that relation to
/// its object) a FRONT / BEHIND subject also stands within [`FRONT_REACH`] of the object and
/// its centre within [`FRONT_CENTRING`] of the object's half width from its axis.
pub fn relation_holds_alone(sb: &Box2, rel: RelationKind, ob: &Box2, alone: bool) -> bool {
    if !relation_holds_box(sb, rel, ob) {
        return false;
    }
    if !alone || !matches!(rel, RelationKind::Front | RelationKind::Behind) {
        return true;
    }
    gap(sb, ob) <= FRONT_REACH + 1e-9
        && ob.local(sb.c)[0].abs() <= FRONT_CENTRING * ob.half[0] + 1e-9
}

/// The sight zone of an OPPOSITE pair (a TV stand and its sofa): the band from one centre to the
/// other, half as wide as the narrower of the two, floor to [`SIGHTLINE_CLEAR_ABOVE`].
pub fn sight_zone(a: &Box2, b: &Box2) -> Box2 {
    let d = [b.c[0] - a.c[0], b.c[1] - a.c[1]];
    let len = d[0].hypot(d[1]);
    let yaw = (-d[0]).atan2(d[1]).to_degrees();
    let width = a.half[0].min(b.half[0]);
    Box2::new(
        [0.5 * (a.c[0] + b.c[0]), 0.5 * (a.c[1] + b.c[1])],
        yaw,
        [width, len],
        0.0,
        SIGHTLINE_CLEAR_ABOVE,
    )
}

/// Whether `k` stands in a sight zone: taller than [`SIGHTLINE_HEIGHT`], hanging below
/// [`SIGHTLINE_CLEAR_ABOVE`], its footprint in the zone by more than 2 cm.
pub fn blocks_sight(k: &Box2, zone: &Box2) -> bool {
    k.z1 > SIGHTLINE_HEIGHT && k.z0 < SIGHTLINE_CLEAR_ABOVE && overlap_depth(k, zone) > 0.02
}

/// The relations of `relations` that `objects` do not satisfy, each as
/// [`relation_unsatisfied`] judges it. Relations naming no object are left out.
pub fn relations_unsatisfied(objects: &[PlacedObject], relations: &[Relation]) -> Vec<Relation> {
    relations
        .iter()
        .filter(|r| relation_unsatisfied(objects, relations, r))
        .cloned()
        .collect()
}

/// Whether `objects` do not satisfy relation `r` of the set `relations`: as [`relation_holds`]
/// says (FRONT / BEHIND as [`relation_holds_alone`] when the subject is the only one in that
/// relation to its object in `relations`), and an OPPOSITE pair also with nothing but what
/// stands on its ends or is a seat of one (two desks facing each other across their chairs)
/// blocking its [`sight_zone`]. False when `r` names no object of `objects`.
/// The layout's report and the edits judge relations with it alike.
pub fn relation_unsatisfied(
    objects: &[PlacedObject],
    relations: &[Relation],
    r: &Relation,
) -> bool {
    let find = |id: &str| objects.iter().find(|o| o.id == id);
    // what stands on an end (over or under it) or is a seat of it (a desk's chair)
    let stacked = |a: &str, b: &str| {
        relations.iter().any(|r| {
            let pair = (r.subject == a && r.object == b) || (r.subject == b && r.object == a);
            (pair && matches!(r.relation, RelationKind::Over | RelationKind::Under))
                || (r.subject == a && r.object == b && r.relation.is_seat())
        })
    };
    let (Some(s), Some(o)) = (find(&r.subject), find(&r.object)) else {
        return false;
    };
    let alone = relations
        .iter()
        .filter(|q| q.object == r.object && q.relation == r.relation)
        .count()
        == 1;
    let (sb, ob) = (Box2::of(s), Box2::of(o));
    if !relation_holds_alone(&sb, r.relation, &ob, alone) {
        return true;
    }
    if r.relation != RelationKind::Opposite {
        return false;
    }
    let zone = sight_zone(&sb, &ob);
    objects.iter().any(|k| {
        k.id != s.id
            && k.id != o.id
            && !stacked(&k.id, &s.id)
            && !stacked(&k.id, &o.id)
            && blocks_sight(&Box2::of(k), &zone)
    })
}

/// Distances from a footprint to the room's walls: [-x, +x, -y, +y] (negative: outside).
pub fn wall_distances(b: &Box2, room: [f64; 3]) -> [f64; 4] {
    let [x0, y0, x1, y1] = b.aabb();
    let (hw, hd) = (0.5 * room[0], 0.5 * room[1]);
    [x0 + hw, hw - x1, y0 + hd, hd - y1]
}

/// Inward normals of the walls in [`wall_distances`] order.
pub const WALL_NORMALS: [[f64; 2]; 4] = [[1.0, 0.0], [-1.0, 0.0], [0.0, 1.0], [0.0, -1.0]];

/// How close to a wall (or the outdoor ground boundary) a SIDE object must be.
pub fn side_distance(scene: SceneType, room: [f64; 3]) -> f64 {
    match scene {
        SceneType::Indoor => 0.3,
        SceneType::Outdoor => (0.05 * room[0].min(room[1])).max(0.3),
    }
}

/// Largest distance to two walls of a CORNER object.
pub const CORNER_DISTANCE: f64 = 0.5;

/// Whether an object's anchor holds.
pub fn anchor_holds(o: &PlacedObject, anchor: Anchor, scene: SceneType, room: [f64; 3]) -> bool {
    anchor_holds_box(&Box2::of(o), anchor, scene, room)
}

/// Largest distance (m) from a WINDOW thing's footprint to its window's wall.
pub const WINDOW_DISTANCE: f64 = 1.0;
/// How far beyond the ends of a window's span (m) the centre of a thing at the window may
/// stand: beside its frame, not along the wall past it.
pub const WINDOW_SIDE: f64 = 0.3;
/// Largest footprint distance to the window's span of FACE_WINDOW.
pub const FACE_WINDOW_DISTANCE: f64 = 2.0;
/// Largest footprint distance to a door's span of DOOR.
pub const DOOR_DISTANCE: f64 = 1.0;
/// Depth of a door's clear zone inside the room.
pub const DOOR_CLEAR_DEPTH: f64 = 0.8;
/// Facing tolerance of FACE_WINDOW and FACE_DOOR (degrees).
pub const FACE_WINDOW_TOLERANCE: f64 = 30.0;
/// Largest footprint distance to the door's span of FACE_DOOR: across a small room, beyond the
/// door's clear zone.
pub const FACE_DOOR_DISTANCE: f64 = 4.0;

/// Distance from a footprint to an opening's span on the floor.
pub fn opening_distance(b: &Box2, o: &Opening) -> f64 {
    let (a, e) = o.span();
    b.corners()
        .iter()
        .map(|&p| seg_point_dist(p, a, e))
        .fold(f64::INFINITY, f64::min)
}

/// Whether footprint `b` stands at window `w` (WINDOW: "a desk under the window", "a plant by
/// the window"): its centre before the window's span or within [`WINDOW_SIDE`] beyond its
/// ends, and the footprint within [`WINDOW_DISTANCE`] of the window's wall. A thing along the
/// same wall past the window, however near its frame, is not at it.
pub fn at_window(b: &Box2, w: &Opening) -> bool {
    let (a, n) = (w.wall.along(), w.wall.inward());
    let [x, y, _] = w.position;
    let along = ((b.c[0] - x) * a[0] + (b.c[1] - y) * a[1]).abs();
    let off = b
        .corners()
        .iter()
        .map(|p| (p[0] - x) * n[0] + (p[1] - y) * n[1])
        .fold(f64::INFINITY, f64::min);
    along <= 0.5 * w.width + WINDOW_SIDE + 1e-9 && off <= WINDOW_DISTANCE + 1e-9
}

/// A door's clear zone: its width (plus 5 cm a side) by [`DOOR_CLEAR_DEPTH`] (plus 10 cm)
/// inside the room, floor to the top of the door.
pub fn door_zone(o: &Opening) -> Box2 {
    let n = o.wall.inward();
    let depth = DOOR_CLEAR_DEPTH + 0.1;
    let c = [
        o.position[0] + n[0] * 0.5 * depth,
        o.position[1] + n[1] * 0.5 * depth,
    ];
    let yaw = if o.wall.along()[0] != 0.0 { 0.0 } else { 90.0 };
    Box2::new(c, yaw, [o.width + 0.1, depth], 0.0, o.height.max(1.9))
}

/// The space a window keeps free of tall furniture: its width, 0.45 m deep, from 10 cm above
/// the sill to its top (a desk or sink under the sill may stand there; a wardrobe may not).
pub fn window_zone(o: &Opening) -> Box2 {
    let n = o.wall.inward();
    let depth = 0.45;
    let c = [
        o.position[0] + n[0] * 0.5 * depth,
        o.position[1] + n[1] * 0.5 * depth,
    ];
    let yaw = if o.wall.along()[0] != 0.0 { 0.0 } else { 90.0 };
    Box2::new(
        c,
        yaw,
        [o.width, depth],
        o.position[2] + 0.1,
        o.position[2] + o.height,
    )
}

/// The zone an opening keeps clear (door) or uncovered (window).
pub fn opening_zone(o: &Opening) -> Box2 {
    match o.kind {
        OpeningKind::Door => door_zone(o),
        OpeningKind::Window => window_zone(o),
    }
}

/// [`anchor_holds_box`] in a room with `openings`. WINDOW: the footprint stands at a window
/// ([`at_window`]). FACE_WINDOW: the window nearest the footprint is
/// within [`FACE_WINDOW_DISTANCE`] of it, and the object faces that window's centre within
/// [`FACE_WINDOW_TOLERANCE`]. DOOR: the footprint is within [`DOOR_DISTANCE`] of a door's span
/// and outside its clear zone. FACE_DOOR: the door nearest the footprint is within
/// [`FACE_DOOR_DISTANCE`] of it, the footprint is outside its clear zone, and the object faces
/// the door's centre within [`FACE_WINDOW_TOLERANCE`]. Without openings none of them holds.
pub fn anchor_holds_in(
    b: &Box2,
    anchor: Anchor,
    scene: SceneType,
    room: [f64; 3],
    openings: &[Opening],
) -> bool {
    let of = |k: OpeningKind| openings.iter().filter(move |o| o.kind == k);
    match anchor {
        Anchor::Window => of(OpeningKind::Window).any(|w| at_window(b, w)),
        Anchor::FaceWindow => faces_nearest(b, of(OpeningKind::Window), FACE_WINDOW_DISTANCE),
        Anchor::FaceDoor => {
            of(OpeningKind::Door).all(|d| overlap_depth(b, &door_zone(d)) <= 0.0)
                && faces_nearest(b, of(OpeningKind::Door), FACE_DOOR_DISTANCE)
        }
        Anchor::Door => of(OpeningKind::Door).any(|d| {
            opening_distance(b, d) <= DOOR_DISTANCE && overlap_depth(b, &door_zone(d)) <= 0.0
        }),
        a => anchor_holds_box(b, a, scene, room),
    }
}

/// Whether the opening of `openings` nearest the footprint `b` is within `distance` of it and
/// `b` faces its centre within [`FACE_WINDOW_TOLERANCE`].
fn faces_nearest<'a>(b: &Box2, openings: impl Iterator<Item = &'a Opening>, distance: f64) -> bool {
    let nearest = openings
        .map(|o| (opening_distance(b, o), o))
        .min_by(|a, c| a.0.total_cmp(&c.0));
    nearest.is_some_and(|(d, o)| {
        let to = [o.position[0] - b.c[0], o.position[1] - b.c[1]];
        let l = (to[0] * to[0] + to[1] * to[1]).sqrt().max(1e-9);
        let c = (to[0] * b.ey[0] + to[1] * b.ey[1]) / l;
        d <= distance && c.clamp(-1.0, 1.0).acos().to_degrees() <= FACE_WINDOW_TOLERANCE
    })
}

/// [`anchor_holds`] on a box (the opening anchors need [`anchor_holds_in`]).
pub fn anchor_holds_box(b: &Box2, anchor: Anchor, scene: SceneType, room: [f64; 3]) -> bool {
    let d = wall_distances(b, room);
    let facing_dot = |w: usize| b.ey[0] * WALL_NORMALS[w][0] + b.ey[1] * WALL_NORMALS[w][1];
    match anchor {
        Anchor::Others => true,
        Anchor::Center => {
            (b.c[0].powi(2) + b.c[1].powi(2)).sqrt() <= 0.25 * room[0].min(room[1]) + 1e-9
        }
        Anchor::Side => {
            let near: Vec<usize> = (0..4)
                .filter(|&w| d[w] <= side_distance(scene, room) + 1e-9)
                .collect();
            let backs: Vec<usize> = near
                .iter()
                .copied()
                .filter(|&w| facing_dot(w) >= 30f64.to_radians().cos() - 1e-9)
                .collect();
            // outdoors a thing as long as its side (the sea along a beach) also reaches the
            // sides at its ends (indoors a piece in a corner is still at two walls)
            let [x0, y0, x1, y1] = b.aabb();
            let spans = |w: usize| {
                let (along, len) = if w < 2 {
                    (y1 - y0, room[1])
                } else {
                    (x1 - x0, room[0])
                };
                along >= len - 2.0 * side_distance(scene, room)
            };
            backs.len() == 1 && (near.len() == 1 || scene == SceneType::Outdoor && spans(backs[0]))
        }
        Anchor::Corner => {
            if scene == SceneType::Outdoor {
                return false;
            }
            let near: Vec<usize> = (0..4).filter(|&w| d[w] <= CORNER_DISTANCE + 1e-9).collect();
            near.len() == 2 && near.iter().all(|&w| facing_dot(w) > 0.0)
        }
        Anchor::Window | Anchor::FaceWindow | Anchor::Door | Anchor::FaceDoor => false,
    }
}

/// The instances of `objects` whose anchor does not hold where they stand, in a room with
/// `openings` ([`anchor_holds_in`]).
pub fn anchors_unmet(
    objects: &[PlacedObject],
    scene: SceneType,
    room: [f64; 3],
    openings: &[Opening],
) -> Vec<MissedAnchor> {
    objects
        .iter()
        .filter(|o| !anchor_holds_in(&Box2::of(o), o.anchor, scene, room, openings))
        .map(|o| MissedAnchor {
            id: o.id.clone(),
            anchor: o.anchor,
        })
        .collect()
}

/// Tolerance of the validity rules (metres).
pub const TOLERANCE: f64 = 0.01;

/// Validity problems of a layout of `spec`: outside the room, above the ceiling,
/// interpenetrating (an OVER/UNDER pair of the spec excepted). Empty when valid.
pub fn validity_problems(layout: &Layout, spec: &SceneSpec) -> Vec<String> {
    let room = layout.room.size;
    let mut out = vec![];
    let boxes: Vec<Box2> = layout.objects.iter().map(Box2::of).collect();
    for (o, b) in layout.objects.iter().zip(&boxes) {
        if wall_distances(b, room).iter().any(|&d| d < -TOLERANCE) {
            out.push(format!("{} is outside the room", o.id));
        }
        if b.z1 > room[2] + TOLERANCE || b.z0 < -TOLERANCE {
            out.push(format!("{} is above the ceiling or below the floor", o.id));
        }
    }
    for i in 0..boxes.len() {
        for j in i + 1..boxes.len() {
            let (a, b) = (&layout.objects[i], &layout.objects[j]);
            if spec.is_stacked(&a.id, &b.id) {
                continue;
            }
            let p = penetration(&boxes[i], &boxes[j]);
            if p > TOLERANCE {
                out.push(format!("{} and {} interpenetrate by {p:.3} m", a.id, b.id));
            }
        }
    }
    out
}
