//! Fronts kept clear: a thing with a front clearance in kb/placement.txt (a stove, a fridge,
//! a wardrobe) keeps that depth before its front free, its width wide, of every thing that
//! stands on the floor there and is not related to it (a table does not stand against the
//! stove's front; a stool at its counter, a rug under it may).
use super::{overlap_depth, Box2};
use crate::plan::gcp::classes::Placements;
use crate::plan::spec::{Layout, SceneSpec};

/// Things lower than this are walked and stood on (a rug, a mat) and block no front (m).
pub const FLAT: f64 = 0.05;
/// Things whose bottom hangs higher than this leave a front free (a range hood) (m).
pub const HANGS_CLEAR: f64 = 1.0;
/// How far a thing may reach into a front zone unnoticed (m).
pub const FRONT_TOLERANCE: f64 = 0.02;

/// The zone `depth` deep before `b`'s front, its width wide, floor to 2 m.
pub fn front_zone(b: &Box2, depth: f64) -> Box2 {
    let c = [
        b.c[0] + b.ey[0] * (b.half[1] + 0.5 * depth),
        b.c[1] + b.ey[1] * (b.half[1] + 0.5 * depth),
    ];
    let yaw = (-b.ey[0]).atan2(b.ey[1]).to_degrees();
    Box2::new(c, yaw, [2.0 * b.half[0], depth], 0.0, 2.0)
}

/// Whether `k` stands in `zone`: neither flat nor hung clear, reaching in by more than
/// [`FRONT_TOLERANCE`].
pub fn blocks_front(k: &Box2, zone: &Box2) -> bool {
    k.z1 - k.z0 > FLAT && k.z0 < HANGS_CLEAR && overlap_depth(k, zone) > FRONT_TOLERANCE
}

/// The (blocker, thing) pairs of `layout` where a thing stands before another's front
/// clearance without a relation of `spec` between them.
pub fn fronts_blocked(layout: &Layout, spec: &SceneSpec) -> Vec<(String, String)> {
    let table = Placements::builtin();
    let related = |a: &str, b: &str| {
        spec.relations
            .iter()
            .any(|r| (r.subject == a && r.object == b) || (r.subject == b && r.object == a))
    };
    let mut out = vec![];
    for o in &layout.objects {
        let Some(depth) = table.front_clearance(&o.category) else {
            continue;
        };
        let zone = front_zone(&Box2::of(o), depth);
        for k in &layout.objects {
            if k.id != o.id && !related(&k.id, &o.id) && blocks_front(&Box2::of(k), &zone) {
                out.push((k.id.clone(), o.id.clone()));
            }
        }
    }
    out
}
