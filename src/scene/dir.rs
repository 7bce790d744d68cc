//! The scene directory's `scene.json` (the contract of ARCHITECTURE.md): typed read with clear
//! one-line errors, atomic write, and composition of the directory's object and environment
//! PLYs into one world-frame cloud. Keys this build does not know are kept through a
//! read-write round trip. Host-only.
use super::compose::{merge, place, Placement};
use crate::plan::spec::SceneType;
use crate::splat::ply::{read_ply, PlyError};
use crate::splat::Gaussians;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// The `scene.json` version this build reads and writes.
pub const VERSION: u32 = 1;

/// Bounds on what `scene.json` may say (metres, degrees, seconds): values outside them are
/// refused in one line before any work, so no loop's cost follows a hand-edited coordinate.
pub const MIN_ROOM: f64 = 0.1;
pub const MAX_ROOM: f64 = 1000.0;
/// How far outside its room (or ground area) an instance may stand.
pub const MAX_OUTSIDE: f64 = 10.0;
pub const MAX_SCALE: f64 = 1000.0;
pub const MAX_YAW: f64 = 1e6;
pub const MAX_SECONDS: f64 = 3600.0;
pub const MAX_FPS: f64 = 240.0;

/// How far `p` lies outside the room of size `room` (centred on the origin, floor at z = 0),
/// metres; 0 inside.
pub fn outside_room(room: [f64; 3], p: [f64; 3]) -> f64 {
    let gap = |v: f64, lo: f64, hi: f64| (lo - v).max(v - hi).max(0.0);
    let g = [
        gap(p[0], -0.5 * room[0], 0.5 * room[0]),
        gap(p[1], -0.5 * room[1], 0.5 * room[1]),
        gap(p[2], 0.0, room[2]),
    ];
    (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt()
}

/// `scene.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneFile {
    pub version: u32,
    pub prompt: String,
    pub seed: u64,
    pub scene_type: SceneType,
    pub room: Room,
    pub prior: Prior,
    pub objects: Vec<SceneObject>,
    /// Absent (null) before an environment exists.
    #[serde(default)]
    pub environment: Option<Environment>,
    #[serde(default)]
    pub stages: Vec<Stage>,
    /// 4D animation; null when static.
    #[serde(default)]
    pub timeline: Option<Timeline>,
    /// Edits applied, oldest first (written by `edit`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub history: Vec<Value>,
    /// Keys this build does not know, kept as they were.
    #[serde(flatten)]
    pub extra: Map<String, Value>,
}

/// Room (indoor) or ground area and sky height (outdoor), `[W, D, H]` metres.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Room {
    pub size: [f64; 3],
}

/// The prior that generated the objects.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Prior {
    /// `sd`, `shape` or `oracle`.
    pub kind: String,
    /// Model directory (sd), or null.
    #[serde(default)]
    pub models: Option<String>,
}

/// One placed instance: world points are `Rz(yaw) · diag(scale) · p + position`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneObject {
    pub id: String,
    pub category: String,
    /// Object-frame PLY, relative to the scene directory.
    pub ply: String,
    pub position: [f64; 3],
    /// Degrees, counter-clockwise about +z.
    pub yaw: f64,
    #[serde(default = "unit_scale")]
    pub scale: [f64; 3],
}

fn unit_scale() -> [f64; 3] {
    [1.0; 3]
}

impl SceneObject {
    /// Its static transform.
    pub fn placement(&self) -> Placement {
        Placement {
            yaw: self.yaw,
            scale: self.scale,
            position: self.position,
        }
    }
}

/// The environment cloud (world frame).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Environment {
    /// `cuboid` or `hemisphere`.
    pub kind: String,
    /// Relative to the scene directory.
    pub ply: String,
}

/// A generation stage and whether it finished.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Stage {
    pub name: String,
    pub done: bool,
}

/// A 4D timeline: instances with a track take their transform from its keys at time t.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Timeline {
    pub duration: f64,
    pub fps: f64,
    pub tracks: Vec<Track>,
}

/// Keyframes of one instance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Track {
    pub id: String,
    #[serde(default = "linear")]
    pub interpolation: String,
    pub keys: Vec<Key>,
}

fn linear() -> String {
    "linear".into()
}

/// One keyframe.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Key {
    pub t: f64,
    pub position: [f64; 3],
    pub yaw: f64,
    #[serde(default = "unit_scale")]
    pub scale: [f64; 3],
}

/// Why a scene directory cannot be read, written or composed.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// A file that is missing, unreadable or not what it should be.
    #[error("{path}: {msg}")]
    File { path: String, msg: String },
    #[error(transparent)]
    Ply(#[from] PlyError),
}

fn file_err(path: &Path, msg: impl Into<String>) -> SceneError {
    SceneError::File {
        path: path.display().to_string(),
        msg: msg.into(),
    }
}

impl SceneFile {
    /// Checks what the renderer and composition rely on: the version, unique instance ids, and
    /// finite transforms with non-zero scales.
    pub fn validate(&self) -> Result<(), String> {
        if self.version != VERSION {
            return Err(format!(
                "version {} (this build reads version {VERSION})",
                self.version
            ));
        }
        let room = self.room.size;
        if !room
            .iter()
            .all(|v| v.is_finite() && (MIN_ROOM..=MAX_ROOM).contains(v))
        {
            return Err(format!(
                "room size {room:?} is outside {MIN_ROOM} to {MAX_ROOM} m a side"
            ));
        }
        let mut ids = std::collections::HashSet::new();
        for o in &self.objects {
            if !ids.insert(o.id.as_str()) {
                return Err(format!("instance id `{}` appears twice", o.id));
            }
            let finite = o.position.iter().chain(&o.scale).all(|v| v.is_finite());
            if !finite || !o.yaw.is_finite() {
                return Err(format!("instance `{}` has a non-finite transform", o.id));
            }
            if o.scale.contains(&0.0) {
                return Err(format!("instance `{}` has a zero scale", o.id));
            }
            if !o
                .scale
                .iter()
                .all(|s| (1.0 / MAX_SCALE..=MAX_SCALE).contains(&s.abs()))
            {
                return Err(format!(
                    "instance `{}` has scale {:?}, outside 1/{MAX_SCALE} to {MAX_SCALE}",
                    o.id, o.scale
                ));
            }
            if o.yaw.abs() > MAX_YAW {
                return Err(format!(
                    "instance `{}` has yaw {} degrees (at most {MAX_YAW} either way)",
                    o.id, o.yaw
                ));
            }
            let out = outside_room(room, o.position);
            if out > MAX_OUTSIDE {
                return Err(format!(
                    "instance `{}` at ({:.1}, {:.1}, {:.1}) is {out:.1} m outside the {:.1} x \
                     {:.1} x {:.1} m room (at most {MAX_OUTSIDE} m); move it back in scene.json",
                    o.id, o.position[0], o.position[1], o.position[2], room[0], room[1], room[2]
                ));
            }
        }
        if let Some(t) = &self.timeline {
            if !(t.duration.is_finite() && (0.0..=MAX_SECONDS).contains(&t.duration)) {
                return Err(format!(
                    "timeline duration {} s is outside 0 to {MAX_SECONDS} s",
                    t.duration
                ));
            }
            if !(t.fps.is_finite() && (1.0..=MAX_FPS).contains(&t.fps)) {
                return Err(format!("timeline fps {} is outside 1 to {MAX_FPS}", t.fps));
            }
            for track in &t.tracks {
                for k in &track.keys {
                    let finite = k.position.iter().chain(&k.scale).all(|v| v.is_finite())
                        && k.yaw.is_finite()
                        && k.t.is_finite();
                    if !finite
                        || !(0.0..=MAX_SECONDS).contains(&k.t)
                        || outside_room(room, k.position) > MAX_OUTSIDE
                    {
                        return Err(format!(
                            "timeline key of `{}` at t = {} is not finite, or outside the \
                             timeline or the room",
                            track.id, k.t
                        ));
                    }
                }
            }
        }
        Ok(())
    }

    /// Whether stage `name` is listed as not done (an unlisted stage is not "not done").
    pub fn stage_pending(&self, name: &str) -> bool {
        self.stages.iter().any(|s| s.name == name && !s.done)
    }
}

/// The `scene.json` of `path`: the file inside a directory, or `path` itself when it is a file.
pub fn scene_json_path(path: &Path) -> PathBuf {
    if path.is_dir() {
        path.join("scene.json")
    } else {
        path.to_path_buf()
    }
}

/// Reads and validates `scene.json` from a scene directory (or the file itself).
pub fn read_scene(dir: &Path) -> Result<SceneFile, SceneError> {
    let path = scene_json_path(dir);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let planned = path.with_file_name("layout.json").is_file();
            return Err(file_err(
                &path,
                if planned {
                    "not found; this directory holds a plan, not a scene (`dreamscene generate` \
                     makes one)"
                } else {
                    "not found; not a scene directory (`dreamscene generate --out DIR` makes one)"
                },
            ));
        }
        Err(e) => return Err(file_err(&path, e.to_string())),
    };
    let value: Value =
        serde_json::from_str(&text).map_err(|e| file_err(&path, format!("not valid JSON: {e}")))?;
    if let Some(kind) = looks_like(&value) {
        return Err(file_err(
            &path,
            format!("this is {kind}, not a scene.json; give the scene directory `generate` wrote"),
        ));
    }
    let scene: SceneFile = serde_json::from_value(value)
        .map_err(|e| file_err(&path, format!("not a valid scene.json: {e}")))?;
    scene.validate().map_err(|m| file_err(&path, m))?;
    Ok(scene)
}

/// What another of the project's JSON files looks like, when `v` is one and not a scene.json.
fn looks_like(v: &Value) -> Option<&'static str> {
    let Some(o) = v.as_object() else {
        return Some(if v.is_array() {
            "a JSON list (a cameras.json?)"
        } else {
            "a JSON value that is not an object"
        });
    };
    if o.contains_key("version") && o.contains_key("stages") {
        return None;
    }
    let first_object = o
        .get("objects")
        .and_then(|x| x.as_array())
        .and_then(|a| a.first())
        .and_then(|x| x.as_object());
    if o.contains_key("unsatisfied") || first_object.is_some_and(|f| f.contains_key("anchor")) {
        Some("a layout.json (the layout's output)")
    } else if o.contains_key("scene_text") || o.contains_key("relations") {
        Some("a spec.json (the planner's output)")
    } else if o.contains_key("gaussians") && o.contains_key("iterations") {
        Some("an object.json (the `object` verb's report)")
    } else {
        None
    }
}

/// The files `scene.json` promises that are not in `dir`: every instance's object PLY, the
/// environment PLY (once its stage is done) and `scene.ply`, each named once, relative to `dir`.
pub fn missing_files(dir: &Path, scene: &SceneFile) -> Vec<String> {
    let mut promised: Vec<&str> = scene.objects.iter().map(|o| o.ply.as_str()).collect();
    if let Some(env) = &scene.environment {
        if !scene.stage_pending("environment") {
            promised.push(&env.ply);
        }
    }
    promised.push("scene.ply");
    let mut missing: Vec<String> = vec![];
    for rel in promised {
        if !dir.join(rel).is_file() && !missing.iter().any(|m| m == rel) {
            missing.push(rel.to_string());
        }
    }
    missing
}

/// Writes `dir/scene.json` atomically (a temporary sibling renamed over it).
pub fn write_scene(dir: &Path, scene: &SceneFile) -> Result<(), SceneError> {
    let path = dir.join("scene.json");
    let text = serde_json::to_string_pretty(scene)
        .map_err(|e| file_err(&path, format!("cannot serialise: {e}")))?;
    crate::util::write_atomic(&path, text.as_bytes()).map_err(|e| file_err(&path, e.to_string()))
}

/// Composes the scene's static state into one world-frame cloud: every instance's object PLY
/// (each distinct file read once) placed by its transform, then `environment.ply` as it is.
/// The environment is left out while a stage named `environment` is listed as not done. All
/// parts are padded to the highest SH degree among them. The caller writes `scene.ply`.
pub fn compose_scene(dir: &Path, scene: &SceneFile) -> Result<Gaussians, SceneError> {
    Ok(merge(&compose_parts(dir, scene)?))
}

/// The parts [`compose_scene`] merges, in its order: one placed cloud per instance of
/// `scene.objects`, then the environment when it is included.
pub fn compose_parts(dir: &Path, scene: &SceneFile) -> Result<Vec<Gaussians>, SceneError> {
    scene
        .validate()
        .map_err(|m| file_err(&dir.join("scene.json"), m))?;
    let mut loaded: HashMap<&str, Gaussians> = HashMap::new();
    for o in &scene.objects {
        if !loaded.contains_key(o.ply.as_str()) {
            loaded.insert(&o.ply, load(dir, &o.ply)?);
        }
    }
    let mut parts: Vec<Gaussians> = scene
        .objects
        .iter()
        .map(|o| place(&loaded[o.ply.as_str()], &o.placement()))
        .collect();
    if let Some(env) = &scene.environment {
        if !scene.stage_pending("environment") {
            let mut e = load(dir, &env.ply)?;
            light_draft(scene, &|rel| loaded.get(rel), &mut e);
            parts.push(e);
        }
    }
    Ok(parts)
}

/// For a draft (`prior.kind` "shape"), bakes light, contact shadows and the openings into the
/// environment cloud from the current object boxes (`scene::env::bake_light`); trained
/// environments have learnt their own light and are left alone. `cloud` gives an instance's
/// object cloud by its PLY path; the box of an instance is its cloud's bounds, scaled and placed.
pub fn light_draft<'a>(
    scene: &SceneFile,
    cloud: &dyn Fn(&str) -> Option<&'a Gaussians>,
    env: &mut Gaussians,
) {
    if scene.prior.kind != "shape" {
        return;
    }
    let boxes = draft_boxes(scene, &|rel| cloud(rel).and_then(object_bounds));
    let openings = crate::scene::env::styled_openings(
        scene.extra.get("openings"),
        scene.scene_type,
        &scene.prompt,
    );
    // Contact shadows follow the current boxes: every composition (and so every edit) re-lights
    // the unlit `environment.ply` for the layout it composes.
    crate::scene::env::bake_light(env, scene.scene_type, scene.room.size, &boxes, &openings);
}

/// An axis-aligned box as its corners `(lo, hi)`.
pub type Bounds = ([f64; 3], [f64; 3]);

/// The bounds `(lo, hi)` of an object-frame cloud; `None` when it is empty.
pub fn object_bounds(g: &Gaussians) -> Option<Bounds> {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for m in &g.means {
        for k in 0..3 {
            lo[k] = lo[k].min(m[k] as f64);
            hi[k] = hi[k].max(m[k] as f64);
        }
    }
    lo[0].is_finite().then_some((lo, hi))
}

/// The world box of every instance whose object cloud has `bounds` (by its PLY path), scaled and
/// placed, in the scene's object order (the boxes a draft's light casts shadows from).
pub fn draft_boxes(
    scene: &SceneFile,
    bounds: &dyn Fn(&str) -> Option<Bounds>,
) -> Vec<crate::scene::env::LitBox> {
    scene
        .objects
        .iter()
        .filter_map(|o| {
            let (lo, hi) = bounds(&o.ply)?;
            let c = [
                0.5 * (lo[0] + hi[0]) * o.scale[0],
                0.5 * (lo[1] + hi[1]) * o.scale[1],
            ];
            let (s, co) = o.yaw.to_radians().sin_cos();
            Some(crate::scene::env::LitBox {
                position: [
                    o.position[0] + co * c[0] - s * c[1],
                    o.position[1] + s * c[0] + co * c[1],
                    o.position[2] + lo[2] * o.scale[2],
                ],
                size: [0, 1, 2].map(|k| (hi[k] - lo[k]) * o.scale[k]),
                yaw: o.yaw,
            })
        })
        .collect()
}

fn load(dir: &Path, rel: &str) -> Result<Gaussians, SceneError> {
    let path = dir.join(rel);
    if !path.is_file() {
        return Err(file_err(&path, "not found (named in scene.json)"));
    }
    let g = read_ply(&path)?;
    g.check().map_err(|m| file_err(&path, m))?;
    Ok(g)
}
