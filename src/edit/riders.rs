//! What rests on an instance moves with it: the computer and printer on a desk, the lamp on a
//! nightstand, the vase on a shelf's top. A rider stands on its carrier's top (its foot within
//! 5 cm of the top) with its centre over the carrier's footprint; things on riders ride
//! too. A carrier is at least 20 cm tall (a rug carries nothing: a sofa standing on
//! it stays when the rug moves). The seats of a desk or a table (its chair) go with it too,
//! keeping their place at it, where they land free.
use super::ops::{with_pose, Pose};
use super::state::SceneState;
use super::Result;
use crate::plan::spec::RelationKind;

/// Most a rider's foot may stand above or below its carrier's top (metres).
const TOP_GAP: f64 = 0.05;
/// Least height of a carrier (metres).
const CARRIER_HEIGHT: f64 = 0.2;
/// Slack of the footprint test (metres).
const EDGE: f64 = 0.02;

/// The instances resting on `id`, directly or on one another, in a stable order (never `id`).
pub fn riders(state: &SceneState, id: &str) -> Vec<String> {
    let mut out: Vec<String> = vec![];
    let mut carriers = vec![id.to_string()];
    while let Some(c) = carriers.pop() {
        let Ok(carrier) = state.object(&c) else {
            continue;
        };
        let b = state.box_of(carrier);
        if b.z1 - b.z0 < CARRIER_HEIGHT {
            continue;
        }
        for o in &state.scene.objects {
            if o.id == id || o.id == c || out.contains(&o.id) {
                continue;
            }
            let l = b.local([o.position[0], o.position[1]]);
            let over = l[0].abs() <= b.half[0] + EDGE && l[1].abs() <= b.half[1] + EDGE;
            if over && (o.position[2] - b.z1).abs() <= TOP_GAP {
                out.push(o.id.clone());
                carriers.push(o.id.clone());
            }
        }
    }
    out.sort();
    out
}

/// Where rider `r` goes when its carrier goes from `from` to `to`: turned with it about the
/// carrier's centre, lifted with its top (a carrier scaled in height lifts what rests on it).
pub fn carried(r: Pose, from: Pose, to: Pose, carrier_height: f64) -> Pose {
    let turn = (to.yaw - from.yaw).to_radians();
    let (s, c) = turn.sin_cos();
    let d = [
        r.position[0] - from.position[0],
        r.position[1] - from.position[1],
    ];
    let lift = (to.scale[2] / from.scale[2] - 1.0) * carrier_height;
    Pose {
        position: [
            to.position[0] + c * d[0] - s * d[1],
            to.position[1] + s * d[0] + c * d[1],
            r.position[2] + (to.position[2] - from.position[2]) + lift,
        ],
        yaw: super::ops::wrap_yaw(r.yaw + to.yaw - from.yaw),
        scale: r.scale,
    }
}

/// `next` (the state with the carrier `id` moved from `from` to its pose there) with every
/// rider of `id` in `before` carried along; the riders' ids.
pub fn carry_riders(
    before: &SceneState,
    next: SceneState,
    id: &str,
    from: Pose,
) -> Result<(SceneState, Vec<String>)> {
    let ids = riders(before, id);
    if ids.is_empty() {
        return Ok((next, ids));
    }
    let to = Pose::of(next.object(id)?);
    let height = before.sizes.get(id).map_or(0.0, |s| s[2]);
    let mut next = next;
    for r in &ids {
        let p = carried(Pose::of(before.object(r)?), from, to, height);
        next = with_pose(&next, r, p)?;
    }
    Ok((next, ids))
}

/// `next` with every seat of `id` in `before` (a chair AT a desk, AROUND a table) carried with
/// it as a rider is, each only where it lands free; the seats' ids. A seat that would collide
/// stays for the layout to place again.
pub fn carry_seats(
    before: &SceneState,
    next: SceneState,
    id: &str,
    from: Pose,
) -> Result<(SceneState, Vec<String>)> {
    let to = Pose::of(next.object(id)?);
    let mut next = next;
    let mut out: Vec<String> = vec![];
    for s in seats(before, id) {
        let cand = with_pose(
            &next,
            &s,
            carried(Pose::of(before.object(&s)?), from, to, 0.0),
        )?;
        if cand.collisions(&s, before).is_empty() {
            next = cand;
            out.push(s);
        }
    }
    Ok((next, out))
}

/// The seats of `id`: the instances AT, AT_BACK or AROUND it (never `id`), in a stable order.
pub fn seats(state: &SceneState, id: &str) -> Vec<String> {
    let mut out: Vec<String> = state
        .relations
        .iter()
        .filter(|r| {
            r.object == id
                && r.subject != id
                && matches!(
                    r.relation,
                    RelationKind::At | RelationKind::AtBack | RelationKind::Around
                )
                && state.object(&r.subject).is_ok()
        })
        .map(|r| r.subject.clone())
        .collect();
    out.sort();
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(x: f64, y: f64, z: f64, yaw: f64) -> Pose {
        Pose {
            position: [x, y, z],
            yaw,
            scale: [1.0; 3],
        }
    }

    #[test]
    fn a_rider_turns_and_shifts_with_its_carrier() {
        let from = pose(1.0, 0.0, 0.0, 0.0);
        let to = pose(2.0, 1.0, 0.0, 90.0);
        let r = carried(pose(1.5, 0.0, 0.75, 10.0), from, to, 0.75);
        assert!((r.position[0] - 2.0).abs() < 1e-9, "{r:?}");
        assert!((r.position[1] - 1.5).abs() < 1e-9, "{r:?}");
        assert!((r.position[2] - 0.75).abs() < 1e-9, "{r:?}");
        assert!((r.yaw - 100.0).abs() < 1e-9, "{r:?}");
        // a carrier scaled to twice its height lifts its rider by its own height
        let mut tall = from;
        tall.scale = [1.0, 1.0, 2.0];
        let r = carried(pose(1.0, 0.0, 0.75, 0.0), from, tall, 0.75);
        assert!((r.position[2] - 1.5).abs() < 1e-9, "{r:?}");
    }
}
