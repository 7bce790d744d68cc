//! 4D timelines (`scene.json`'s `timeline`): an instance with a track takes its transform from
//! the track's keys at time t, the others keep their static transform. Keys are interpolated
//! `linear`ly (position, yaw in degrees as stored, so a spin of 720° stays a spin, and scale),
//! held (`step`) or eased (`smooth`, a smoothstep between keys); before the first key and after
//! the last the nearest key holds. Host-only.
use super::compose::{merge, place, Placement};
use super::dir::{draft_boxes, object_bounds, read_scene, SceneError, SceneFile, Timeline, Track};
use super::env::DraftLight;
use crate::splat::ply::read_ply;
use crate::splat::Gaussians;
use std::path::Path;

/// How a track moves between keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interpolation {
    Linear,
    Step,
    Smooth,
}

impl Interpolation {
    /// The interpolation named `name` (`linear`, `step`, `smooth`); an unknown name is linear.
    pub fn parse(name: &str) -> Interpolation {
        match name {
            "step" | "hold" | "constant" => Interpolation::Step,
            "smooth" | "ease" | "cubic" => Interpolation::Smooth,
            _ => Interpolation::Linear,
        }
    }
}

/// The transform of `track` at time `t` (seconds). A track without keys gives `None`.
pub fn sample(track: &Track, t: f64) -> Option<Placement> {
    let keys = &track.keys;
    let first = keys.first()?;
    let last = keys.last()?;
    let at = |k: &super::dir::Key| Placement {
        yaw: k.yaw,
        scale: k.scale,
        position: k.position,
    };
    // NaN times hold the first key too.
    if t.is_nan() || t <= first.t {
        return Some(at(first));
    }
    if t >= last.t {
        return Some(at(last));
    }
    // The segment [a, b] holding t (keys sorted by time; equal times jump).
    let j = keys.partition_point(|k| k.t <= t).max(1);
    let (a, b) = (&keys[j - 1], &keys[j]);
    let span = b.t - a.t;
    let u = if span > 0.0 { (t - a.t) / span } else { 1.0 };
    let u = match Interpolation::parse(&track.interpolation) {
        Interpolation::Linear => u,
        Interpolation::Step => 0.0,
        Interpolation::Smooth => u * u * (3.0 - 2.0 * u),
    };
    let mix = |x: f64, y: f64| x + (y - x) * u;
    Some(Placement {
        yaw: mix(a.yaw, b.yaw),
        scale: [0, 1, 2].map(|i| mix(a.scale[i], b.scale[i])),
        position: [0, 1, 2].map(|i| mix(a.position[i], b.position[i])),
    })
}

/// The track of instance `id`, if the timeline has one.
pub fn track<'a>(timeline: &'a Timeline, id: &str) -> Option<&'a Track> {
    timeline.tracks.iter().find(|tr| tr.id == id)
}

/// `scene` with every tracked instance moved to its transform at time `t`.
pub fn scene_at(scene: &SceneFile, t: f64) -> SceneFile {
    let mut out = scene.clone();
    if let Some(tl) = &scene.timeline {
        for o in &mut out.objects {
            if let Some(p) = track(tl, &o.id).and_then(|tr| sample(tr, t)) {
                o.position = p.position;
                o.yaw = p.yaw;
                o.scale = p.scale;
            }
        }
    }
    out
}

/// The scene's merged world-frame cloud at time `t` (seconds): every instance under its
/// transform at `t` (its track's, or its static one), then the environment. For a static scene
/// (no timeline) this is `scene.ply`'s content at any `t`. Reads the directory on every call; a
/// frame loop keeps an [`Animated`] instead.
pub fn compose_at(dir: &Path, t: f64) -> Result<Gaussians, SceneError> {
    Ok(Animated::open(dir)?.at(t))
}

/// A scene directory loaded once for playing its timeline: [`Animated::at`] only places and
/// merges. A draft's light is kept between frames: only the contact shadows of objects whose
/// box changed are re-computed.
#[derive(Debug)]
pub struct Animated {
    pub scene: SceneFile,
    /// Each distinct object PLY, by its path in `scene.json`.
    clouds: std::collections::HashMap<String, Gaussians>,
    /// The object-frame bounds of each cloud.
    bounds: std::collections::HashMap<String, super::dir::Bounds>,
    /// The environment, when present and finished.
    environment: Option<Gaussians>,
    /// A draft's light (room part and the shadows last cast), built on the first frame.
    light: std::sync::Mutex<Option<DraftLight>>,
}

impl Clone for Animated {
    fn clone(&self) -> Animated {
        let light = self.light.lock().map(|l| l.clone()).unwrap_or_default();
        Animated {
            scene: self.scene.clone(),
            clouds: self.clouds.clone(),
            bounds: self.bounds.clone(),
            environment: self.environment.clone(),
            light: std::sync::Mutex::new(light),
        }
    }
}

impl Animated {
    /// Reads `scene.json`, every object PLY it names and the environment.
    pub fn open(dir: &Path) -> Result<Animated, SceneError> {
        let scene = read_scene(dir)?;
        let mut clouds = std::collections::HashMap::new();
        for o in &scene.objects {
            if !clouds.contains_key(&o.ply) {
                clouds.insert(o.ply.clone(), load(dir, &o.ply)?);
            }
        }
        let environment = match &scene.environment {
            Some(env) if !scene.stage_pending("environment") => Some(load(dir, &env.ply)?),
            _ => None,
        };
        let bounds = clouds
            .iter()
            .filter_map(|(k, g)| Some((k.clone(), object_bounds(g)?)))
            .collect();
        Ok(Animated {
            scene,
            clouds,
            bounds,
            environment,
            light: std::sync::Mutex::new(None),
        })
    }

    /// Whether the scene has a timeline with at least one track.
    pub fn is_animated(&self) -> bool {
        self.scene
            .timeline
            .as_ref()
            .is_some_and(|t| !t.tracks.is_empty())
    }

    /// The object-frame cloud of an object PLY named in `scene.json`.
    pub fn object_cloud(&self, ply: &str) -> Option<&Gaussians> {
        self.clouds.get(ply)
    }

    /// The environment's world-frame cloud, when the scene has a finished one.
    pub fn environment(&self) -> Option<&Gaussians> {
        self.environment.as_ref()
    }

    /// The merged world-frame cloud at time `t`, as [`compose_at`].
    pub fn at(&self, t: f64) -> Gaussians {
        let at = scene_at(&self.scene, t);
        let mut parts: Vec<Gaussians> = at
            .objects
            .iter()
            .map(|o| place(&self.clouds[&o.ply], &o.placement()))
            .collect();
        if let Some(env) = &self.environment {
            parts.push(self.environment_at(&at, env));
        }
        merge(&parts)
    }

    /// The environment for the layout `at`: a draft's light follows it (contact shadows move
    /// with the objects) as composing the static scene does, from the kept [`DraftLight`].
    fn environment_at(&self, at: &SceneFile, env: &Gaussians) -> Gaussians {
        if at.prior.kind != "shape" {
            return env.clone();
        }
        let boxes = draft_boxes(at, &|rel| self.bounds.get(rel).copied());
        // A poisoned lock only means another frame panicked: its cache is rebuilt.
        let mut guard = match self.light.lock() {
            Ok(g) => g,
            Err(p) => {
                let mut g = p.into_inner();
                *g = None;
                g
            }
        };
        let light = guard.get_or_insert_with(|| {
            let openings = crate::scene::env::styled_openings(
                at.extra.get("openings"),
                at.scene_type,
                &at.prompt,
            );
            DraftLight::new(env.clone(), at.scene_type, at.room.size, &openings)
        });
        light.lit(&boxes)
    }
}

fn load(dir: &Path, rel: &str) -> Result<Gaussians, SceneError> {
    let path = dir.join(rel);
    if !path.is_file() {
        return Err(SceneError::File {
            path: path.display().to_string(),
            msg: "not found (named in scene.json)".into(),
        });
    }
    let g = read_ply(&path)?;
    g.check().map_err(|m| SceneError::File {
        path: path.display().to_string(),
        msg: m,
    })?;
    Ok(g)
}

/// The times of the frames of a timeline: `0, 1/fps, …` up to and including its duration.
pub fn frame_times(timeline: &Timeline) -> Vec<f64> {
    let fps = if timeline.fps > 0.0 {
        timeline.fps
    } else {
        30.0
    };
    let n = (timeline.duration.max(0.0) * fps).round() as usize;
    (0..=n).map(|i| i as f64 / fps).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::dir::Key;

    fn key(t: f64, x: f64, yaw: f64, s: f64) -> Key {
        Key {
            t,
            position: [x, 0.0, 0.0],
            yaw,
            scale: [s; 3],
        }
    }

    fn tr(interp: &str) -> Track {
        Track {
            id: "car1".into(),
            interpolation: interp.into(),
            keys: vec![
                key(0.0, 0.0, 0.0, 1.0),
                key(2.0, 4.0, 720.0, 2.0),
                key(3.0, 4.0, 720.0, 1.0),
            ],
        }
    }

    #[test]
    fn linear_keys_interpolate_and_hold_outside() {
        let t = tr("linear");
        let p = sample(&t, 0.5).unwrap();
        assert!((p.position[0] - 1.0).abs() < 1e-12);
        assert!((p.yaw - 180.0).abs() < 1e-12, "spins are not wrapped");
        assert!((p.scale[0] - 1.25).abs() < 1e-12);
        assert_eq!(sample(&t, -1.0).unwrap().position[0], 0.0);
        assert_eq!(sample(&t, 9.0).unwrap().scale[0], 1.0);
        assert!((sample(&t, 2.5).unwrap().scale[2] - 1.5).abs() < 1e-12);
    }

    #[test]
    fn step_holds_and_smooth_eases() {
        assert_eq!(sample(&tr("step"), 1.9).unwrap().position[0], 0.0);
        let s = sample(&tr("smooth"), 0.5).unwrap().position[0];
        // smoothstep(0.25) = 0.15625 of the way
        assert!((s - 4.0 * 0.15625).abs() < 1e-12);
        assert!((sample(&tr("smooth"), 1.0).unwrap().position[0] - 2.0).abs() < 1e-12);
    }

    #[test]
    fn frame_times_cover_the_duration() {
        let tl = Timeline {
            duration: 1.0,
            fps: 4.0,
            tracks: vec![],
        };
        assert_eq!(frame_times(&tl), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    }
}
