//! Scene cameras for the three environment stages (official code facts §9, "Scene cameras"),
//! the inference circle, an evaluation path and object orbits. Host-only.
//!
//! Frame: the room is centred at the origin, z up, floor at 0 (ARCHITECTURE.md). The authors'
//! constants were set for their scene scale; here they are scaled to the room:
//! * Indoor, their inward radius 2.4 (= 0.8 x 3, with the inscribed half-extent R ≈ 3 of their
//!   rooms) becomes 0.8 *half-extents*: horizontal offsets are measured per axis in units of
//!   (W/2, D/2) (so a long room is covered end to end) and vertical ones in units of
//!   R = min(W, D)/2. Stage 1's `[max(3, .75R), max(3, 1.1R)]·0.8` becomes `[0.8, 0.88]`.
//! * Outdoor, their example ground of 15 x 15 m (half-extent 7.5) puts 2.4 at 0.32 half-extents
//!   and the outward-looking radii 0.13–0.65 at 0.017–0.087. Their box top of 4 m gives the
//!   camera heights: mid height min(H, 4)/2, stage 2 at 2/3 of min(H, 4) (our sky is taller).
//! * Object-centric orbits stay in metres: r ∈ [0.8R, 0.8·max(R, distance to the nearest wall)]
//!   times clip(largest object side in metres, 0.75, 1.5) (their affine scale S).
//!
//! A viewpoint is valid when inside the room box shrunk by [`ROOM_MARGIN`] and outside every
//! object's oriented box grown by [`OBJECT_MARGIN`] (both above the rasteriser's 0.2 m near
//! plane, so no camera sees through a wall or an object). An invalid pose is resampled with its
//! offset scaled by 0.98 (1.02 when it fell inside the object it orbits), as the authors do, for
//! at most [`MAX_TRIES`] tries; then the nearest valid point of a 0.2 m grid takes its place.
mod choose;
mod faults;
mod paths;
mod repeat;
mod views;
mod wall;

pub use choose::{eye_height, foot_mass_share, render_views, view_fov, MASS_SHARE};
pub use faults::{
    alike, blocker_of, blocker_share, grazing_share, is_panel, looks_at_wall, view_faults,
    ViewFaults, BARE_COVER, BARE_WALL, CLOSE_DEPTH, CLOSE_WALL, COPY,
};
pub use paths::{explore_path, inference_circle, orbit};
pub use repeat::{
    backdrop, heading, new_share, repeats, Look, BACKDROP_COS, BACKDROP_FAR, REPEAT_COS,
    REPEAT_NEW, REPEAT_SEEN,
};
pub use views::{
    facing, frame_share, framing_score, in_frame, overview_camera, screen_box, view_stats,
    ViewStats, MAX_OBJECT_SHARE,
};
pub use wall::{bare_wall_share, opening_box};

use super::Camera;
use crate::plan::spec::{Layout, SceneType};
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};

/// Horizontal field of view of the scene cameras (the authors' 0.96 rad FoVx).
pub const SCENE_FOV_X: f64 = 0.96;
/// Distance kept from walls, floor, ceiling and the ground boundary (metres).
pub const ROOM_MARGIN: f64 = 0.3;
/// How much object boxes grow for the collision test (metres).
pub const OBJECT_MARGIN: f64 = 0.25;
/// Resampling tries before the grid fallback.
pub const MAX_TRIES: usize = 100;

/// An object's oriented box: `position` the bottom-face centre, `size` [w, d, h], `yaw` degrees.
#[derive(Debug, Clone, PartialEq)]
pub struct ObjectBox {
    pub id: String,
    pub position: [f64; 3],
    pub size: [f64; 3],
    pub yaw: f64,
}

/// What the cameras need of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneBox {
    pub scene_type: SceneType,
    pub room: [f64; 3],
    pub objects: Vec<ObjectBox>,
    /// The room's doors and windows as thin boxes on their walls ([`opening_box`]): something a
    /// view sees, never something it stands in or is about.
    pub openings: Vec<ObjectBox>,
}

impl SceneBox {
    /// The boxes of a layout.
    pub fn from_layout(layout: &Layout) -> SceneBox {
        SceneBox {
            scene_type: layout.scene_type,
            room: layout.room.size,
            objects: layout
                .objects
                .iter()
                .map(|o| ObjectBox {
                    id: o.id.clone(),
                    position: o.position,
                    size: o.size,
                    yaw: o.yaw,
                })
                .collect(),
            openings: layout
                .openings
                .iter()
                .enumerate()
                .map(|(n, o)| opening_box(o, n + 1))
                .collect(),
        }
    }

    pub(crate) fn half(&self) -> [f64; 2] {
        [0.5 * self.room[0], 0.5 * self.room[1]]
    }

    /// Inscribed horizontal half-extent (the authors' `radius_trans_max`).
    pub(crate) fn r_in(&self) -> f64 {
        self.half()[0].min(self.half()[1])
    }

    /// Top of the camera region: the room height indoors, at most 4 m outdoors.
    fn top(&self) -> f64 {
        match self.scene_type {
            SceneType::Indoor => self.room[2],
            SceneType::Outdoor => self.room[2].min(4.0),
        }
    }

    pub(crate) fn zmid(&self) -> f64 {
        0.5 * self.top()
    }
}

/// An object's kind from its id: the id without its trailing count (`tree3` → `tree`), which
/// is its category.
pub(crate) fn kind(o: &ObjectBox) -> &str {
    o.id.trim_end_matches(|c: char| c.is_ascii_digit())
}

impl ObjectBox {
    /// True when `p` is inside the box grown by `grow` on every side.
    pub fn contains(&self, p: [f64; 3], grow: f64) -> bool {
        let (s, c) = self.yaw.to_radians().sin_cos();
        let (dx, dy) = (p[0] - self.position[0], p[1] - self.position[1]);
        let (lx, ly) = (c * dx + s * dy, -s * dx + c * dy);
        let dz = p[2] - self.position[2];
        lx.abs() <= 0.5 * self.size[0] + grow
            && ly.abs() <= 0.5 * self.size[1] + grow
            && dz >= -grow
            && dz <= self.size[2] + grow
    }

    fn centre(&self) -> [f64; 3] {
        let p = self.position;
        [p[0], p[1], p[2] + 0.5 * self.size[2]]
    }
}

/// The three environment stages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// Walls / sky, from near the centre.
    One,
    /// Floor / ground: regions and objects (indoor), concentric circles (outdoor).
    Two,
    /// Reconstructive refinement over all kinds of poses.
    Three,
}

/// True when a camera may stand at `p`: inside the shrunk room box, outside every grown object box.
pub fn valid_viewpoint(scene: &SceneBox, p: [f64; 3]) -> bool {
    let [hx, hy] = scene.half();
    let m = ROOM_MARGIN;
    let inside = p[0].abs() <= hx - m
        && p[1].abs() <= hy - m
        && p[2] >= m
        && p[2] <= scene.room[2] - m
        && p.iter().all(|v| v.is_finite());
    inside && !scene.objects.iter().any(|o| o.contains(p, OBJECT_MARGIN))
}

/// One camera request: a look-at anchor and how the offset from it is sampled, in the authors'
/// spherical form `r·(sinθ sinφ, sinθ cosφ, cosθ)` with each axis scaled by `unit`.
#[derive(Clone, Copy)]
struct Request {
    anchor: [f64; 3],
    unit: [f64; 3],
    r: [f64; 2],
    theta: [f64; 2],
    phi: [f64; 2],
    /// Mirror the offset through the anchor and look away from it (the authors' scale −1).
    outward: bool,
    /// The orbited object, whose box makes the offset grow instead of shrink.
    orbits: Option<usize>,
    fov_x: [f64; 2],
}

struct Sampler<'a> {
    scene: &'a SceneBox,
    rng: ChaCha8Rng,
    width: u32,
    height: u32,
    cams: Vec<Camera>,
    name: &'static str,
}

pub(crate) fn add(a: [f64; 3], b: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

pub(crate) fn len(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// A camera at `eye` looking at `target` with horizontal field of view `fov_x`.
pub(crate) fn camera(
    eye: [f64; 3],
    target: [f64; 3],
    up: [f64; 3],
    w: u32,
    h: u32,
    fov_x: f64,
) -> Camera {
    let f = 0.5 * w as f64 / (0.5 * fov_x).tan();
    let fov_y = 2.0 * (0.5 * h as f64 / f).atan();
    Camera::look_at(eye, target, up, w, h, fov_y)
}

impl Sampler<'_> {
    fn uni(&mut self, r: [f64; 2]) -> f64 {
        if r[1] > r[0] {
            self.rng.gen_range(r[0]..r[1])
        } else {
            r[0]
        }
    }

    fn gauss(&mut self, sd: f64) -> f64 {
        Normal::new(0.0, sd).map_or(0.0, |n| n.sample(&mut self.rng))
    }

    /// Samples the request until valid (see the module doc) and appends the camera.
    fn place(&mut self, q: Request) {
        let mut scale = 1.0;
        let mut pose = None;
        let mut first = None;
        for _ in 0..MAX_TRIES {
            let (r, th, ph) = (
                self.uni(q.r),
                self.uni(q.theta).to_radians(),
                self.uni(q.phi).to_radians(),
            );
            let d = [th.sin() * ph.sin(), th.sin() * ph.cos(), th.cos()];
            let off = [0, 1, 2].map(|k| scale * r * d[k] * q.unit[k]);
            let jit = [0, 1, 2].map(|_| self.rng.gen_range(-0.025..0.025));
            let (eye, target) = if q.outward {
                let eye = add(add(q.anchor, off, -1.0), jit, 1.0);
                (eye, add(eye, off, -1.0 / len(off).max(1e-9)))
            } else {
                (add(add(q.anchor, off, 1.0), jit, 1.0), q.anchor)
            };
            first.get_or_insert((eye, target));
            if valid_viewpoint(self.scene, eye) && len(add(target, eye, -1.0)) > 0.3 {
                pose = Some((eye, target));
                break;
            }
            let in_orbited = q
                .orbits
                .is_some_and(|i| self.scene.objects[i].contains(eye, OBJECT_MARGIN));
            scale = (scale * if in_orbited { 1.02 } else { 0.98 }).clamp(0.3, 3.0);
        }
        let (eye, target) = pose.unwrap_or_else(|| {
            let (want, target) = first.unwrap_or((q.anchor, [0.0, 0.0, self.scene.zmid()]));
            let eye = nearest_valid(self.scene, want).unwrap_or([0.0, 0.0, self.scene.zmid()]);
            // moved to the nearest valid spot, it keeps its direction unless that stares out of
            // the room (or into an object) from point-blank range: then it looks at the centre
            let to = add(target, eye, -1.0);
            let ahead = add(eye, to, 0.5 / len(to).max(1e-9));
            let target = if len(to) > 0.3 && valid_viewpoint(self.scene, ahead) {
                target
            } else {
                add(eye, [-eye[0], -eye[1] + 1e-3, 0.0], 1.0)
            };
            (eye, target)
        });
        let t = [0, 1, 2].map(|k| target[k] + self.gauss(0.05));
        let up = [self.gauss(0.01), self.gauss(0.01), 1.0 + self.gauss(0.01)];
        let fov = self.uni(q.fov_x);
        let mut cam = camera(eye, t, up, self.width, self.height, fov);
        cam.id = self.cams.len() as u32;
        cam.img_name = format!("{}_{:05}", self.name, cam.id);
        self.cams.push(cam);
    }

    fn room_unit(&self) -> [f64; 3] {
        let [hx, hy] = self.scene.half();
        [hx, hy, self.scene.r_in()]
    }

    /// Stage1_Indoor: `size` sectors around the centre, looking at it.
    fn stage1_indoor(&mut self, size: usize, view_floor: bool) {
        let z = self.scene.zmid() + self.uni([-0.5, 0.5]) * (self.scene.room[2] / 5.6).min(1.0);
        for k in 0..size {
            let sector = 360.0 / size as f64;
            let phi0 = k as f64 * sector - 180.0;
            self.place(Request {
                anchor: [0.0, 0.0, z],
                unit: self.room_unit(),
                r: [0.8, 0.88],
                theta: if view_floor {
                    [45.0, 90.0]
                } else {
                    [75.0, 115.0]
                },
                phi: [phi0, phi0 + sector],
                outward: false,
                orbits: None,
                fov_x: [SCENE_FOV_X; 2],
            });
        }
    }

    /// Stage2_Indoor(affine): eight cameras orbiting object `i`.
    fn stage2_object(&mut self, i: usize) {
        let o = &self.scene.objects[i];
        let (c, ext) = (o.centre(), o.size.iter().fold(0.0f64, |a, &b| a.max(b)));
        let zj = 0.5f64.min(0.5 * o.size[2]);
        let [hx, hy] = self.scene.half();
        let wall = (hx - c[0].abs()).min(hy - c[1].abs()).max(0.0);
        let r_in = self.scene.r_in();
        let s = ext.clamp(0.75, 1.5);
        let r = [0.8 * r_in * s, 0.8 * r_in.max(wall) * s];
        let anchor = [c[0], c[1], c[2] + self.uni([-zj, zj])];
        for _ in 0..8 {
            self.place(Request {
                anchor,
                unit: [1.0; 3],
                r,
                theta: [60.0, 110.0],
                phi: [-180.0, 180.0],
                outward: false,
                orbits: Some(i),
                fov_x: [SCENE_FOV_X; 2],
            });
        }
    }

    /// Stage2_Indoor(idx): eight cameras across the room looking at a point a third of the way
    /// out in sector `idx` of `size`.
    fn stage2_region(&mut self, idx: usize, size: usize) {
        let sector = 360.0 / size as f64;
        let psi = idx as f64 * sector - 180.0 + self.uni([0.0, sector]);
        let u = self.room_unit();
        let (s, c) = psi.to_radians().sin_cos();
        let dz = self.uni([-1.0, 1.0]) * (self.scene.room[2] / 2.8).min(1.0);
        let anchor = [u[0] * s / 3.0, u[1] * c / 3.0, self.scene.zmid() + 0.5 * dz];
        for _ in 0..8 {
            self.place(Request {
                anchor,
                unit: u,
                r: [0.8, 0.8],
                theta: [60.0, 110.0],
                phi: [psi + 120.0, psi + 240.0],
                outward: false,
                orbits: None,
                fov_x: [SCENE_FOV_X; 2],
            });
        }
    }

    /// Stage1_Outdoor: twelve sectors around the centre, half looking in from 0.32 half-extents,
    /// half standing near the centre looking out.
    fn stage1_outdoor(&mut self) {
        let z = self.scene.zmid() + self.uni([-0.5, 0.5]);
        for k in 0..12 {
            let phi0 = k as f64 * 30.0 - 180.0;
            let outward = self.rng.gen_bool(0.5);
            self.place(Request {
                anchor: [0.0, 0.0, z],
                unit: self.room_unit(),
                r: if outward {
                    [0.017, 0.087]
                } else {
                    [0.32, 0.32]
                },
                theta: [80.0, 110.0],
                phi: [phi0, phi0 + 30.0],
                outward,
                orbits: None,
                fov_x: [SCENE_FOV_X; 2],
            });
        }
    }

    /// Stage1_Outdoor2 / Stage2_Outdoor: four cameras on a diameter at offsets −1/2, −1/4, 1/4,
    /// 1/2 (± 1/20) of the half-extent, all looking the same way (concentric circles).
    fn diameter(&mut self, stage2: bool, psi: Option<f64>) {
        let psi = psi.unwrap_or_else(|| self.uni([-180.0, 180.0]));
        let u = self.room_unit();
        let (s, c) = psi.to_radians().sin_cos();
        for (i, f) in [-0.5, -0.25, 0.25, 0.5].into_iter().enumerate() {
            let f = f + self.uni([-0.05, 0.05]);
            let z = if stage2 {
                self.scene.top() * 2.0 / 3.0
            } else {
                self.scene.zmid() + self.uni([-0.5, 0.5])
            };
            let outward = i <= 1;
            let theta = match (stage2, outward) {
                (true, false) => [90.0, 90.0],
                (true, true) => [85.0, 95.0],
                (false, _) => [70.0, 100.0],
            };
            self.place(Request {
                anchor: [u[0] * f * s, u[1] * f * c, z],
                unit: u,
                r: [0.32, 0.32],
                theta,
                phi: [psi, psi],
                outward,
                orbits: None,
                fov_x: if stage2 {
                    [0.96, 1.44]
                } else {
                    [SCENE_FOV_X; 2]
                },
            });
        }
    }

    /// Stage3_Outdoor("env"): 16 azimuths, from a quarter of the way out, looking outward at
    /// polar 95° and 110°.
    fn stage3_outdoor(&mut self) {
        let u = self.room_unit();
        for k in 0..16 {
            let psi = k as f64 * 22.5 - 180.0;
            let (s, c) = psi.to_radians().sin_cos();
            for theta in [95.0, 110.0] {
                self.place(Request {
                    anchor: [-0.25 * u[0] * s, -0.25 * u[1] * c, self.scene.zmid()],
                    unit: u,
                    r: [0.32, 0.32],
                    theta: [theta; 2],
                    phi: [psi, psi],
                    outward: true,
                    orbits: None,
                    fov_x: [SCENE_FOV_X; 2],
                });
            }
        }
    }
}

/// The nearest valid point to `p` on a 0.2 m grid (at heights from p's down to the margin).
pub(crate) fn nearest_valid(scene: &SceneBox, p: [f64; 3]) -> Option<[f64; 3]> {
    let [hx, hy] = scene.half();
    let step = 0.2;
    let (nx, ny) = ((hx / step) as i64, (hy / step) as i64);
    let zs = [
        p[2].clamp(ROOM_MARGIN, scene.room[2] - ROOM_MARGIN),
        1.5,
        0.5 * scene.room[2],
    ];
    let mut best: Option<([f64; 3], f64)> = None;
    for z in zs {
        for i in -nx..=nx {
            for j in -ny..=ny {
                let q = [i as f64 * step, j as f64 * step, z];
                let d = len(add(q, p, -1.0));
                if best.is_none_or(|b| d < b.1) && valid_viewpoint(scene, q) {
                    best = Some((q, d));
                }
            }
        }
    }
    best.map(|b| b.0)
}

/// The camera list of a stage as the authors build it (§9 "Camera lists per stage"), `count`
/// cameras of `width` x `height`, deterministic for a seed. Stage 3 is shuffled.
pub fn stage_cameras(
    stage: Stage,
    scene: &SceneBox,
    count: usize,
    width: u32,
    height: u32,
    seed: u64,
) -> Vec<Camera> {
    let name = match stage {
        Stage::One => "stage1",
        Stage::Two => "stage2",
        Stage::Three => "stage3",
    };
    let mut s = Sampler {
        scene,
        rng: ChaCha8Rng::seed_from_u64(seed),
        width,
        height,
        cams: Vec::with_capacity(count + 32),
        name,
    };
    let n_obj = scene.objects.len();
    let (mut next_obj, mut next_idx) = (0, 0);
    let indoor = scene.scene_type == SceneType::Indoor;
    while s.cams.len() < count {
        let late = s.cams.len() as f64 >= 0.7 * count as f64;
        match (stage, indoor) {
            (Stage::One, true) => {
                if late && n_obj > 0 && s.rng.gen_bool(0.3) {
                    s.stage2_object(next_obj % n_obj);
                    next_obj += 1;
                }
                s.stage1_indoor(8, false);
            }
            (Stage::One, false) => {
                s.stage1_outdoor();
                if late {
                    s.diameter(false, None);
                }
            }
            (Stage::Two, true) => {
                let p: f64 = s.rng.gen();
                if p < 0.25 && n_obj > 0 {
                    s.stage2_object(next_obj % n_obj);
                    next_obj += 1;
                } else if p < 0.75 {
                    s.stage2_region(next_idx % 8, 8);
                    next_idx += 1;
                } else {
                    s.stage1_indoor(8, true);
                }
            }
            (Stage::Two, false) => s.diameter(true, None),
            (Stage::Three, true) => {
                if s.rng.gen_bool(0.5) {
                    s.stage1_indoor(12, true);
                } else {
                    s.stage2_region(next_idx % 12, 12);
                    next_idx += 1;
                }
            }
            (Stage::Three, false) => {
                if s.cams.is_empty() {
                    s.stage3_outdoor();
                } else {
                    s.diameter(true, None);
                }
            }
        }
    }
    if stage == Stage::Three {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
        s.cams.shuffle(&mut rng);
    }
    s.cams.truncate(count);
    for (i, c) in s.cams.iter_mut().enumerate() {
        c.id = i as u32;
        c.img_name = format!("{name}_{i:05}");
    }
    s.cams
}
