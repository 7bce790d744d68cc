//! Turning on the spot: candidate views from each standing spot of a room in evenly spaced
//! directions, each looking at the wall (or ground edge) ahead. Aimed only at objects, the views
//! of a room with one or two spots to stand on look the same few ways and copy one another; a
//! person there turns round instead, and each turn shows another part of the room. Host-only.
use super::super::{SceneBox, ROOM_MARGIN};
use super::Shot;
use crate::plan::spec::SceneType;

/// Directions a spot turns to (every 30°).
const TURNS: usize = 12;
/// A spot looks at least this far ahead (metres; the pick skips targets nearer than 0.8 m).
const AHEAD: f64 = 1.0;

/// Horizontal distance from `p` along `dir` to the room's (ground's) edge.
fn to_edge(scene: &SceneBox, p: [f64; 3], dir: [f64; 2]) -> f64 {
    let [hx, hy] = scene.half();
    let reach = |x: f64, f: f64, h: f64| {
        if f.abs() < 1e-9 {
            f64::INFINITY
        } else {
            ((f.signum() * h - x) / f).max(0.0)
        }
    };
    reach(p[0], dir[0], hx).min(reach(p[1], dir[1], hy))
}

/// The shots of every spot of `positions` turned to [`TURNS`] directions, indoors: (eye, spot
/// looked at on the floor under the wall ahead, target 0 (the room, no object aimed at), lens,
/// a turn).
pub(super) fn turns(scene: &SceneBox, positions: &[[f64; 3]], fov: f64) -> Vec<Shot> {
    if scene.scene_type != SceneType::Indoor {
        return vec![];
    }
    let mut out = vec![];
    for p in positions {
        for k in 0..TURNS {
            let a = std::f64::consts::TAU * k as f64 / TURNS as f64;
            let dir = [a.cos(), a.sin()];
            let d = (to_edge(scene, *p, dir) - ROOM_MARGIN).max(AHEAD);
            out.push((
                *p,
                [p[0] + d * dir[0], p[1] + d * dir[1], 0.0],
                0,
                fov,
                true,
            ));
        }
    }
    out
}
