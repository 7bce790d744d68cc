//! From parsed steps to poses: the final pose of a move in words, and the keyframes of a motion
//! (`animate`), written as the instance's track in `scene.json`'s timeline. A path that runs
//! through a wall or another object is reported with the time it first does. Host-only.
use super::commit::Edit;
use super::ops::{wrap_yaw, yaw_facing, Pose};
use super::parse::{parse, Command, Step};
use super::state::SceneState;
use super::{EditError, Result};
use crate::plan::check::{gap, Box2};
use crate::plan::spec::RelationKind;
use crate::scene::dir::{Key, Timeline, Track};
use crate::scene::timeline::{sample, scene_at};
use serde_json::json;

/// Gap left between footprints when a step places an object beside another (metres).
pub const BESIDE_GAP: f64 = 0.2;
/// Walking pace of the default durations (m/s) and turning pace (degrees/s).
const PACE: f64 = 1.0;
const TURN_PACE: f64 = 180.0;

/// A keyframe relative to the start of its step: (fraction of the step's duration, pose).
type Keys = Vec<(f64, Pose)>;

fn shifted(p: &Pose, d: [f64; 2]) -> Pose {
    Pose {
        position: [p.position[0] + d[0], p.position[1] + d[1], p.position[2]],
        ..*p
    }
}

/// The yaw equivalent to `target` nearest `from` (so a turn takes the short way).
fn nearest_yaw(from: f64, target: f64) -> f64 {
    from + wrap_yaw(target - from)
}

fn centre(state: &SceneState, id: &str) -> Result<[f64; 2]> {
    let o = state.object(id)?;
    Ok([o.position[0], o.position[1]])
}

/// The footprint of `id` at pose `p`.
fn box_at(state: &SceneState, id: &str, p: &Pose) -> Result<Box2> {
    let o = state.object(id)?;
    let s = state.sizes.get(id).copied().unwrap_or([0.0; 3]);
    let k = [0, 1, 2].map(|a| (p.scale[a] / o.scale[a]).abs());
    Ok(Box2::new(
        [p.position[0], p.position[1]],
        p.yaw,
        [s[0] * k[0], s[1] * k[1]],
        p.position[2],
        p.position[2] + s[2] * k[2],
    ))
}

/// The pose of `id` beside `target` in `relation`: on the side the relation names (NEXT: the
/// free side nearest where it is), `BESIDE_GAP` from the target's footprint. Side by side (NEXT,
/// LEFT, RIGHT) it joins the target's group: it faces what stands in FRONT of the target (an
/// armchair beside the sofa turns to the coffee table), else it is turned as the target is;
/// in FRONT or BEHIND its yaw is kept.
fn beside(state: &SceneState, id: &str, p: &Pose, target: &str, rel: RelationKind) -> Result<Pose> {
    let t = state.object(target)?;
    let tb = state.box_of(t);
    // side by side, it joins the target's group: turned as the target is
    let side_by_side = matches!(
        rel,
        RelationKind::Next | RelationKind::Left | RelationKind::Right
    );
    let turned = Pose {
        yaw: if side_by_side { t.yaw } else { p.yaw },
        ..*p
    };
    let p = &turned;
    let me = box_at(state, id, p)?;
    let sides: Vec<[f64; 2]> = match rel {
        RelationKind::Front => vec![tb.ey],
        RelationKind::Behind => vec![tb.ey.map(|v| -v)],
        RelationKind::Left => vec![tb.ex.map(|v| -v)],
        RelationKind::Right => vec![tb.ex],
        _ => vec![tb.ex, tb.ex.map(|v| -v), tb.ey, tb.ey.map(|v| -v)],
    };
    let reach = |b: &Box2, d: [f64; 2]| {
        b.half[0] * (b.ex[0] * d[0] + b.ex[1] * d[1]).abs()
            + b.half[1] * (b.ey[0] * d[0] + b.ey[1] * d[1]).abs()
    };
    let focus = state
        .relations
        .iter()
        .find(|r| r.object == t.id && r.subject != id && r.relation == RelationKind::Front)
        .and_then(|r| state.object(&r.subject).ok())
        .map(|f| [f.position[0], f.position[1]]);
    let mut best: Option<(f64, Pose)> = None;
    for d in sides {
        let r = reach(&tb, d) + BESIDE_GAP + reach(&me, d);
        let c = [tb.c[0] + d[0] * r, tb.c[1] + d[1] * r];
        let cand = Pose {
            position: [c[0], c[1], p.position[2]],
            ..*p
        };
        // ... and toward what stands in front of the target, if anything does (an armchair
        // beside the sofa turns to the coffee table before it)
        let cand = match focus.filter(|_| side_by_side) {
            Some(f) => {
                let d = [f[0] - c[0], f[1] - c[1]];
                Pose {
                    yaw: wrap_yaw(yaw_facing(d)),
                    ..cand
                }
            }
            None => cand,
        };
        let moved = super::ops::with_pose(state, id, cand)?;
        let free = moved.collisions(id, state).is_empty();
        let dist = (c[0] - p.position[0]).hypot(c[1] - p.position[1]);
        let cost = dist + if free { 0.0 } else { 100.0 };
        if best.as_ref().is_none_or(|b| cost < b.0) {
            best = Some((cost, cand));
        }
    }
    Ok(best.expect("at least one side").1)
}

/// The keys of one step from pose `p`, and its default duration (seconds).
fn step_keys(state: &SceneState, id: &str, p: &Pose, step: &Step) -> Result<(Keys, f64)> {
    let line = |to: Pose| {
        let d = (to.position[0] - p.position[0]).hypot(to.position[1] - p.position[1]);
        (vec![(1.0, to)], (d / PACE).max(0.5))
    };
    Ok(match step {
        Step::Shift { forward, left } => {
            let (f, l) = (p.forward(), p.left());
            line(shifted(
                p,
                [f[0] * forward + l[0] * left, f[1] * forward + l[1] * left],
            ))
        }
        Step::Approach { target, distance } => {
            let c = centre(state, target)?;
            let v = [c[0] - p.position[0], c[1] - p.position[1]];
            let len = v[0].hypot(v[1]).max(1e-9);
            let u = [v[0] / len, v[1] / len];
            // How far it may go before its footprint comes within BESIDE_GAP of the target's.
            let tb = state.box_of(state.object(target)?);
            let room_at = |s: f64| -> Result<f64> {
                Ok(gap(
                    &box_at(state, id, &shifted(p, [u[0] * s, u[1] * s]))?,
                    &tb,
                ))
            };
            let (mut lo, mut hi) = (0.0, len);
            if room_at(0.0)? <= BESIDE_GAP {
                hi = 0.0;
            }
            for _ in 0..50 {
                let mid = 0.5 * (lo + hi);
                if room_at(mid)? > BESIDE_GAP {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let s = distance.map_or(lo, |d| d.min(lo));
            line(shifted(p, [u[0] * s, u[1] * s]))
        }
        Step::Retreat { target, distance } => {
            let c = centre(state, target)?;
            let v = [p.position[0] - c[0], p.position[1] - c[1]];
            let len = v[0].hypot(v[1]).max(1e-9);
            line(shifted(p, [v[0] / len * distance, v[1] / len * distance]))
        }
        Step::Place { target, relation } => line(beside(state, id, p, target, *relation)?),
        Step::Centre => line(Pose {
            position: [0.0, 0.0, p.position[2]],
            ..*p
        }),
        Step::Turn { degrees } => (
            vec![(
                1.0,
                Pose {
                    yaw: p.yaw + degrees,
                    ..*p
                },
            )],
            (degrees.abs() / TURN_PACE).max(0.5),
        ),
        Step::Face { target, away } => {
            let c = centre(state, target)?;
            let d = [c[0] - p.position[0], c[1] - p.position[1]];
            let mut y = yaw_facing(d);
            if *away {
                y += 180.0;
            }
            let to = nearest_yaw(p.yaw, y);
            (
                vec![(1.0, Pose { yaw: to, ..*p })],
                ((to - p.yaw).abs() / TURN_PACE).max(0.5),
            )
        }
        Step::Scale { factor } => (
            vec![(
                1.0,
                Pose {
                    scale: p.scale.map(|s| s * factor),
                    ..*p
                },
            )],
            1.0,
        ),
        Step::Circle { target, turns } => {
            let c = centre(state, target)?;
            let v = [p.position[0] - c[0], p.position[1] - c[1]];
            let r = v[0].hypot(v[1]);
            if r < 1e-6 {
                return Err(EditError::Bad(format!(
                    "{id} stands on {target}'s centre; it cannot circle it"
                )));
            }
            let a0 = v[1].atan2(v[0]);
            let n = ((turns.abs() * 12.0).ceil() as usize).max(2);
            let sign = turns.signum();
            // Facing along the way round: the tangent, counter-clockwise or clockwise.
            let yaw_at = |a: f64| yaw_facing([-a.sin() * sign, a.cos() * sign]);
            let start_yaw = nearest_yaw(p.yaw, yaw_at(a0));
            let keys = (1..=n)
                .map(|k| {
                    let u = k as f64 / n as f64;
                    let a = a0 + std::f64::consts::TAU * turns * u;
                    let pose = Pose {
                        position: [c[0] + r * a.cos(), c[1] + r * a.sin(), p.position[2]],
                        yaw: start_yaw + 360.0 * turns * u,
                        scale: p.scale,
                    };
                    (u, pose)
                })
                .collect();
            let mut keys: Keys = keys;
            keys.insert(
                0,
                (
                    0.0,
                    Pose {
                        yaw: start_yaw,
                        ..*p
                    },
                ),
            );
            (
                keys,
                (std::f64::consts::TAU * r * turns.abs() / PACE).max(1.0),
            )
        }
        Step::Bounce { height, times } => {
            let n = *times as usize;
            let mut keys = vec![];
            for hop in 0..n {
                for q in 1..=4 {
                    let u = q as f64 / 4.0;
                    let z = 4.0 * height * u * (1.0 - u);
                    keys.push((
                        (hop as f64 + u) / n as f64,
                        Pose {
                            position: [p.position[0], p.position[1], p.position[2] + z],
                            ..*p
                        },
                    ));
                }
            }
            (keys, 0.6 * n as f64)
        }
        Step::Sway {
            forward,
            left,
            times,
            across,
        } => {
            let (f, l) = (p.forward(), p.left());
            let d = [f[0] * forward + l[0] * left, f[1] * forward + l[1] * left];
            // out and back, or out, across and back: the start between
            let legs: &[f64] = if *across {
                &[1.0, 0.0, -1.0, 0.0]
            } else {
                &[1.0, 0.0]
            };
            let n = (*times as usize * legs.len()) as f64;
            let keys = (0..*times as usize)
                .flat_map(|_| legs.iter())
                .enumerate()
                .map(|(k, &s)| ((k + 1) as f64 / n, shifted(p, [s * d[0], s * d[1]])))
                .collect();
            let reach = forward.hypot(*left);
            (keys, (n * reach / PACE).max(0.5 * *times as f64))
        }
        Step::Pause => (vec![(1.0, *p)], 1.0),
    })
}

/// Keyframes of a command for instance `id` from its current pose: `(t, pose)`, the first at
/// t = 0. `seconds` stretches the steps without their own duration to that total.
pub fn keyframes(
    state: &SceneState,
    id: &str,
    cmd: &Command,
    seconds: Option<f64>,
) -> Result<Vec<(f64, Pose)>> {
    let start = Pose::of(state.object(id)?);
    let mut pose = start;
    let mut steps = vec![];
    for (step, given) in &cmd.steps {
        let (keys, default) = step_keys(state, id, &pose, step)?;
        if let Some(last) = keys.last() {
            pose = last.1;
        }
        steps.push((keys, *given, default));
    }
    let fixed: f64 = steps.iter().filter_map(|s| s.1).sum();
    let free: f64 = steps.iter().filter(|s| s.1.is_none()).map(|s| s.2).sum();
    let stretch = match seconds {
        Some(total) if free > 0.0 => ((total - fixed) / free).max(0.05),
        _ => 1.0,
    };
    let mut out = vec![(0.0, start)];
    let mut t = 0.0;
    for (keys, given, default) in steps {
        let dur = given.unwrap_or(default * stretch).max(1e-3);
        for (u, p) in keys {
            out.push((t + u * dur, p));
        }
        t += dur;
    }
    Ok(out)
}

/// The pose a command leaves instance `id` in (yaw brought into (−180, 180]).
pub fn final_pose(state: &SceneState, id: &str, cmd: &Command) -> Result<Pose> {
    let keys = keyframes(state, id, cmd, None)?;
    let mut p = keys
        .last()
        .map(|k| k.1)
        .unwrap_or(Pose::of(state.object(id)?));
    p.yaw = wrap_yaw(p.yaw);
    Ok(p)
}

/// Animates instance `id` from a motion sentence: its track in the timeline (replacing an
/// earlier one), keys of position, yaw and scale; the timeline lasts as long as its longest
/// track. Warnings name the times the path runs through a wall or another object.
pub fn animate(
    state: &SceneState,
    id: &str,
    motion: &str,
    seconds: Option<f64>,
    fps: f64,
) -> Result<Edit> {
    state.object(id)?;
    if let Some(s) = seconds {
        if !(s.is_finite() && s > 0.0) {
            return Err(EditError::Bad(format!(
                "--seconds {s}: expected a positive number"
            )));
        }
    }
    if !(fps.is_finite() && fps > 0.0 && fps <= 240.0) {
        return Err(EditError::Bad(format!("--fps {fps}: expected 1 to 240")));
    }
    let objects = state.id_categories();
    let cmd = parse(motion, &objects, Some(id)).map_err(EditError::Bad)?;
    let keys = keyframes(state, id, &cmd, seconds)?;
    let track = Track {
        id: id.to_string(),
        interpolation: "linear".into(),
        keys: keys
            .iter()
            .map(|(t, p)| Key {
                t: (t * 1e6).round() / 1e6,
                position: p.position,
                yaw: p.yaw,
                scale: p.scale,
            })
            .collect(),
    };
    let end = track.keys.last().map_or(0.0, |k| k.t);
    let mut edit = Edit::new(
        state,
        "animate",
        json!({"id": id, "motion": motion, "seconds": seconds}),
    );
    let mut tl = edit.scene.timeline.clone().unwrap_or(Timeline {
        duration: 0.0,
        fps,
        tracks: vec![],
    });
    tl.tracks.retain(|t| t.id != id);
    tl.tracks.push(track);
    tl.fps = fps;
    tl.duration = tl
        .tracks
        .iter()
        .filter_map(|t| t.keys.last().map(|k| k.t))
        .fold(0.0, f64::max);
    edit.scene.timeline = Some(tl.clone());
    edit.notes.push(format!(
        "{id}: {} steps, {} keys over {end:.2} s (timeline {:.2} s at {fps} fps)",
        cmd.steps.len(),
        keys.len(),
        tl.duration
    ));
    if !cmd.unread.is_empty() {
        edit.notes.push(format!(
            "not understood, so left out: \"{}\"",
            cmd.unread.join("\", \"")
        ));
    }
    edit.notes.extend(path_warnings(state, &edit.scene, id)?);
    Ok(edit)
}

/// Where the animated instance `id` runs through walls or other objects: one warning per
/// obstacle, at the first frame it does.
pub fn path_warnings(
    state: &SceneState,
    scene: &crate::scene::dir::SceneFile,
    id: &str,
) -> Result<Vec<String>> {
    let Some(tl) = &scene.timeline else {
        return Ok(vec![]);
    };
    let Some(track) = tl.tracks.iter().find(|t| t.id == id) else {
        return Ok(vec![]);
    };
    let mut seen: Vec<String> = vec![];
    let mut out = vec![];
    let mut start = state.clone();
    start.scene = scene_at(scene, 0.0);
    for t in crate::scene::timeline::frame_times(tl) {
        let Some(p) = sample(track, t) else { break };
        let mut at = state.clone();
        at.scene = scene_at(scene, t);
        let pose = Pose {
            position: p.position,
            yaw: p.yaw,
            scale: p.scale,
        };
        let at = super::ops::with_pose(&at, id, pose)?;
        let at = SceneState {
            sizes: {
                let mut s = at.sizes.clone();
                let b = box_at(state, id, &pose)?;
                s.insert(
                    id.to_string(),
                    [2.0 * b.half[0], 2.0 * b.half[1], b.z1 - b.z0],
                );
                s
            },
            ..at
        };
        for problem in at.collisions(id, &start) {
            let what = problem
                .split(" would ")
                .nth(1)
                .unwrap_or(&problem)
                .to_string();
            let key = what.split(" by ").next().unwrap_or(&what).to_string();
            let key = key.split(" m through ").last().unwrap_or(&key).to_string();
            if !seen.contains(&key) {
                seen.push(key);
                out.push(format!("warning: at t = {t:.2} s {id}'s path would {what}"));
            }
        }
    }
    Ok(out)
}
