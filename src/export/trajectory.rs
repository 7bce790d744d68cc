//! Camera paths for `video` and `render`: an orbit around a single splat file or the room centre,
//! the exploring loop through a room (circles outdoors), or an INRIA cameras.json. A scene
//! directory's object boxes come from its object PLYs placed by `scene.json`, so the paths stay
//! clear of what is actually drawn after any edit. Host-only: never imports `ash`.
use crate::camera::scene::{
    explore_path, orbit, valid_viewpoint, ObjectBox, SceneBox, ROOM_MARGIN, SCENE_FOV_X,
};
use crate::camera::{read_cameras, Camera, CameraError};
use crate::plan::spec::SceneType;
use crate::scene::dir::{compose_scene, read_scene, SceneError, SceneFile};
use crate::splat::ply::{read_ply, PlyError};
use crate::splat::Gaussians;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// Why a camera path cannot be made.
#[derive(Debug, thiserror::Error)]
pub enum TrajectoryError {
    #[error(transparent)]
    Cameras(#[from] CameraError),
    #[error(transparent)]
    Ply(#[from] PlyError),
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error("{0}")]
    Invalid(String),
}

pub type Result<T> = std::result::Result<T, TrajectoryError>;

/// Which path the camera follows.
#[derive(Debug, Clone, PartialEq)]
pub enum Trajectory {
    /// Around a single splat file, or inside the room around its centre.
    Orbit,
    /// The exploring loop at eye height through the room, outside every object (circles outdoors).
    Explore,
    /// The cameras of an INRIA cameras.json, one frame each.
    Cameras(PathBuf),
}

impl FromStr for Trajectory {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "orbit" => Ok(Trajectory::Orbit),
            "explore" => Ok(Trajectory::Explore),
            _ if s.ends_with(".json") => Ok(Trajectory::Cameras(PathBuf::from(s))),
            _ => Err(format!(
                "`{s}` is not a trajectory: give orbit, explore or a cameras.json file"
            )),
        }
    }
}

/// An image size `WxH` in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Size {
    pub width: u32,
    pub height: u32,
}

impl FromStr for Size {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let bad = || format!("`{s}` is not a size: give WIDTHxHEIGHT, e.g. 640x480");
        let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
        let (width, height) = (
            w.trim().parse::<u32>().map_err(|_| bad())?,
            h.trim().parse::<u32>().map_err(|_| bad())?,
        );
        if !(1..=8192).contains(&width) || !(1..=8192).contains(&height) {
            return Err(format!(
                "size {width}x{height}: each side must be 1 to 8192"
            ));
        }
        Ok(Size { width, height })
    }
}

/// What a path moves around: a room with its object boxes, or the bounds of a single cloud.
#[derive(Debug, Clone)]
pub enum Subject {
    Scene(SceneBox),
    /// Robust bounds (1st to 99th percentile per axis) of a cloud's centres.
    Cloud {
        min: [f64; 3],
        max: [f64; 3],
    },
}

impl Subject {
    /// The box the subject fills: the room (ground area up to the sky) or the cloud's bounds.
    pub fn bounds(&self) -> ([f64; 3], [f64; 3]) {
        match self {
            Subject::Scene(s) => (
                [-0.5 * s.room[0], -0.5 * s.room[1], 0.0],
                [0.5 * s.room[0], 0.5 * s.room[1], s.room[2]],
            ),
            Subject::Cloud { min, max } => (*min, *max),
        }
    }

    /// The bounds of a single splat file.
    pub fn of_cloud(g: &Gaussians) -> Result<Subject> {
        let (min, max) = robust_bounds(g, 0.01)
            .ok_or_else(|| TrajectoryError::Invalid("the splat file has no Gaussians".into()))?;
        Ok(Subject::Cloud { min, max })
    }

    /// The room of a scene directory and the boxes of its instances: each object PLY's extent
    /// (0.5th to 99.5th percentile, so a stray splat does not swell the box; symmetric about the
    /// bottom-face centre, which is the object frame's origin) scaled and placed as `scene.json`
    /// says.
    pub fn of_scene(dir: &Path, scene: &SceneFile) -> Result<Subject> {
        let mut extents: Vec<(String, [f64; 3])> = vec![];
        let mut objects = vec![];
        for o in &scene.objects {
            let ext = match extents.iter().find(|(p, _)| *p == o.ply) {
                Some((_, e)) => *e,
                None => {
                    let g = read_ply(&dir.join(&o.ply))?;
                    let (lo, hi) = robust_bounds(&g, 0.005).unwrap_or(([0.0; 3], [0.0; 3]));
                    let e = [
                        2.0 * lo[0].abs().max(hi[0].abs()),
                        2.0 * lo[1].abs().max(hi[1].abs()),
                        hi[2].max(0.0),
                    ];
                    extents.push((o.ply.clone(), e));
                    e
                }
            };
            objects.push(ObjectBox {
                id: o.id.clone(),
                position: o.position,
                size: [
                    ext[0] * o.scale[0].abs(),
                    ext[1] * o.scale[1].abs(),
                    ext[2] * o.scale[2].abs(),
                ],
                yaw: o.yaw,
            });
        }
        Ok(Subject::Scene(SceneBox {
            scene_type: scene.scene_type,
            room: scene.room.size,
            openings: vec![],
            objects,
        }))
    }
}

/// What `video`, `render` and `view` were given: a scene directory (or its scene.json), composed
/// into one world-frame cloud, or a single splat PLY.
pub struct Input {
    pub cloud: Gaussians,
    pub subject: Subject,
    /// The scene directory and its scene.json, when one was given.
    pub scene: Option<(PathBuf, SceneFile)>,
}

/// Opens `path`: a scene directory, a `scene.json`, or a splat PLY.
pub fn open_input(path: &Path) -> Result<Input> {
    open_input_at(path, None)
}

/// As [`open_input`], with a scene's timeline played to `time` seconds when one is given (the
/// instances with a track take their transform at that time; a static scene is the same at any
/// time). A splat PLY has no timeline, so a time is refused for one.
pub fn open_input_at(path: &Path, time: Option<f64>) -> Result<Input> {
    if let Some(t) = time {
        if !t.is_finite() || t < 0.0 {
            return Err(TrajectoryError::Invalid(format!(
                "--time {t}: give a time in seconds, 0 or more"
            )));
        }
    }
    let is_json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    if path.is_dir() || is_json {
        let dir = if path.is_dir() {
            path.to_path_buf()
        } else {
            path.parent().unwrap_or(Path::new(".")).to_path_buf()
        };
        let scene = read_scene(path)?;
        let cloud = match time {
            Some(t) => crate::scene::timeline::Animated::open(&dir)?.at(t),
            None => compose_scene(&dir, &scene)?,
        };
        if cloud.is_empty() {
            return Err(TrajectoryError::Invalid(format!(
                "{}: the scene has no Gaussians yet",
                dir.display()
            )));
        }
        let subject = Subject::of_scene(&dir, &scene)?;
        return Ok(Input {
            cloud,
            subject,
            scene: Some((dir, scene)),
        });
    }
    if !path.exists() {
        return Err(TrajectoryError::Invalid(format!(
            "{}: not found (give a scene directory or a splat PLY)",
            path.display()
        )));
    }
    if time.is_some() {
        return Err(TrajectoryError::Invalid(format!(
            "{}: --time plays a scene's timeline; give the scene directory, not a PLY",
            path.display()
        )));
    }
    let cloud = read_ply(path)?;
    cloud
        .check()
        .map_err(|m| TrajectoryError::Invalid(format!("{}: {m}", path.display())))?;
    let subject = Subject::of_cloud(&cloud)?;
    Ok(Input {
        cloud,
        subject,
        scene: None,
    })
}

/// Per-axis `q` and `1 − q` quantiles of the centres, or `None` for an empty cloud.
fn robust_bounds(g: &Gaussians, q: f64) -> Option<([f64; 3], [f64; 3])> {
    if g.is_empty() {
        return None;
    }
    let mut min = [0.0; 3];
    let mut max = [0.0; 3];
    for k in 0..3 {
        let mut v: Vec<f32> = g
            .means
            .iter()
            .map(|m| m[k])
            .filter(|x| x.is_finite())
            .collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f32::total_cmp);
        let at = |f: f64| v[((v.len() - 1) as f64 * f).round() as usize] as f64;
        min[k] = at(q);
        max[k] = at(1.0 - q);
    }
    Some((min, max))
}

/// The cameras of `trajectory` around `subject`: `frames` of them for orbit and explore; a
/// cameras.json gives its own, resized to `size` (focal lengths scaled with the image) when one
/// is given. Orbit and explore use `size`, 640x480 when none is given.
pub fn cameras(
    trajectory: &Trajectory,
    subject: &Subject,
    frames: usize,
    size: Option<Size>,
) -> Result<Vec<Camera>> {
    let Size { width, height } = size.unwrap_or(Size {
        width: 640,
        height: 480,
    });
    if frames == 0 && !matches!(trajectory, Trajectory::Cameras(_)) {
        return Err(TrajectoryError::Invalid(
            "the path needs at least one frame".into(),
        ));
    }
    match (trajectory, subject) {
        (Trajectory::Cameras(path), _) => {
            let mut cams = read_cameras(path)?;
            if let Some(s) = size {
                for c in &mut cams {
                    c.fx *= s.width as f64 / c.width as f64;
                    c.fy *= s.height as f64 / c.height as f64;
                    c.width = s.width;
                    c.height = s.height;
                }
            }
            Ok(cams)
        }
        (Trajectory::Explore, Subject::Scene(scene)) => {
            Ok(explore_path(scene, frames, width, height))
        }
        (Trajectory::Explore, Subject::Cloud { .. }) => Err(TrajectoryError::Invalid(
            "explore walks through a room: give a scene directory, or use --trajectory orbit \
             for a single splat file"
                .into(),
        )),
        (Trajectory::Orbit, Subject::Scene(scene)) => Ok(room_orbit(scene, frames, width, height)),
        (Trajectory::Orbit, Subject::Cloud { min, max }) => {
            Ok(cloud_orbit(*min, *max, frames, width, height))
        }
    }
}

/// Height of the room orbit's look-at point as a fraction of the eye height.
const ORBIT_TARGET: f64 = 0.75;

/// Elevation of the orbit around a single cloud (degrees above its centre).
const CLOUD_ELEVATION_DEG: f64 = 20.0;

/// One circle around a cloud at [`CLOUD_ELEVATION_DEG`], far enough that its bounding sphere
/// fills about 80% of the narrower field of view.
fn cloud_orbit(min: [f64; 3], max: [f64; 3], frames: usize, w: u32, h: u32) -> Vec<Camera> {
    let c = [
        0.5 * (min[0] + max[0]),
        0.5 * (min[1] + max[1]),
        0.5 * (min[2] + max[2]),
    ];
    let r = 0.5
        * ((max[0] - min[0]).powi(2) + (max[1] - min[1]).powi(2) + (max[2] - min[2]).powi(2))
            .sqrt()
            .max(1e-3);
    let fov = SCENE_FOV_X.min(fov_y_of(w, h));
    let dist = r / (0.8 * 0.5 * fov).sin();
    let el = CLOUD_ELEVATION_DEG.to_radians();
    orbit(
        c,
        dist * el.cos(),
        c[2] + dist * el.sin(),
        frames,
        w,
        h,
        SCENE_FOV_X,
    )
}

/// A loop inside the room around its centre: an ellipse at eye height with semi-axes a fraction
/// k of the free half-extents, looking at the room centre at [`ORBIT_TARGET`] of eye height (a
/// gentle pitch, ~10° from a wall-side point of a 5 x 4 m room: the frame shows furniture and walls,
/// not mostly floor). k is the largest of
/// 0.9, 0.85, … 0.3 whose whole loop (sampled every 2°) is a valid viewpoint; when none is, the
/// exploring loop's per-point repair takes over, which keeps every camera valid.
fn room_orbit(scene: &SceneBox, frames: usize, w: u32, h: u32) -> Vec<Camera> {
    let eye = eye_height(scene);
    let [hx, hy] = [
        0.5 * scene.room[0] - ROOM_MARGIN,
        0.5 * scene.room[1] - ROOM_MARGIN,
    ];
    let target = [0.0, 0.0, ORBIT_TARGET * eye];
    let at = |k: f64, a: f64| [k * hx * a.sin(), k * hy * a.cos(), eye];
    let clear =
        |k: f64| (0..180).all(|i| valid_viewpoint(scene, at(k, 2.0 * PI * i as f64 / 180.0)));
    let ks = (0..13).map(|i| 0.9 - 0.05 * i as f64);
    let Some(k) = ks.into_iter().find(|k| clear(*k)) else {
        let mut cams = explore_path(scene, frames, w, h);
        for c in &mut cams {
            c.img_name = c.img_name.replace("explore", "orbit");
        }
        return cams;
    };
    let mut cams: Vec<Camera> = (0..frames)
        .map(|i| {
            let p = at(k, 2.0 * PI * i as f64 / frames as f64);
            Camera::look_at(p, target, [0.0, 0.0, 1.0], w, h, fov_y_of(w, h))
        })
        .collect();
    for (i, c) in cams.iter_mut().enumerate() {
        c.id = i as u32;
        c.img_name = format!("orbit_{i:04}");
    }
    cams
}

/// The vertical field of view matching the scene cameras' horizontal one at this aspect.
fn fov_y_of(w: u32, h: u32) -> f64 {
    2.0 * ((0.5 * SCENE_FOV_X).tan() * h as f64 / w as f64).atan()
}

/// Eye height as the exploring loop takes it: 1.5 m, lower in low rooms, above the margin.
fn eye_height(scene: &SceneBox) -> f64 {
    let top = match scene.scene_type {
        SceneType::Indoor => scene.room[2],
        SceneType::Outdoor => scene.room[2].min(4.0),
    };
    1.5f64.min(0.55 * top).max(ROOM_MARGIN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_trajectories_parse() {
        assert_eq!(
            "320x240".parse::<Size>(),
            Ok(Size {
                width: 320,
                height: 240
            })
        );
        assert!("320".parse::<Size>().is_err());
        assert!("0x10".parse::<Size>().is_err());
        assert_eq!("orbit".parse::<Trajectory>(), Ok(Trajectory::Orbit));
        assert_eq!(
            "a/cams.json".parse::<Trajectory>(),
            Ok(Trajectory::Cameras("a/cams.json".into()))
        );
        assert!("spiral".parse::<Trajectory>().is_err());
    }
}
