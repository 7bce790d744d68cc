//! What a view shows of a scene's boxes (occlusion ignored): objects in frame, the share of the
//! frame each covers, the view's subject and which side of it the camera sees; and the overview
//! camera of the viewer. The render views are chosen from these figures (`choose.rs`). Host-only.
use super::{camera, valid_viewpoint, ObjectBox, SceneBox, ROOM_MARGIN, SCENE_FOV_X};
use crate::camera::Camera;
use crate::plan::spec::SceneType;

/// The largest share of the frame one object may fill in a well-framed view.
pub const MAX_OBJECT_SHARE: f64 = 0.4;
/// Objects no taller than this (rugs, mats) lie on the floor: they count as in view but never as
/// filling the frame, because from eye height one sees across them.
pub(crate) const FLAT: f64 = 0.05;

/// What one view shows of a scene's boxes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewStats {
    /// Objects whose box centre is in front of the camera and inside the frame.
    pub in_view: usize,
    /// The largest share of the frame one (non-flat) object's projected box covers.
    pub largest: f64,
    /// The summed shares of the frame the objects cover (capped at 1): 0 is bare wall or floor.
    pub covered: f64,
    /// The view's subject: the index of the (non-flat) object filling the most of the frame.
    pub subject: Option<usize>,
    /// Which side of its subject the view sees: the cosine between the subject's facing and the
    /// horizontal direction from it to the camera (1 its front, 0 a side, −1 its back; 0 without
    /// a subject).
    pub facing: f64,
}

impl ViewStats {
    /// At least two objects in view and none over [`MAX_OBJECT_SHARE`] of the frame.
    pub fn framed_well(&self) -> bool {
        self.in_view >= 2 && self.largest <= MAX_OBJECT_SHARE
    }
}

/// Camera-frame coordinates of `p`.
fn to_cam(cam: &Camera, p: [f64; 3]) -> [f64; 3] {
    let (r, t) = cam.world_to_camera();
    [0, 1, 2].map(|i| r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i])
}

/// The eight corners of an object's oriented box in world coordinates.
fn corners(o: &ObjectBox) -> [[f64; 3]; 8] {
    let (s, c) = o.yaw.to_radians().sin_cos();
    let mut out = [[0.0; 3]; 8];
    for (k, q) in out.iter_mut().enumerate() {
        let lx = if k & 1 == 0 { -0.5 } else { 0.5 } * o.size[0];
        let ly = if k & 2 == 0 { -0.5 } else { 0.5 } * o.size[1];
        let lz = if k & 4 == 0 { 0.0 } else { o.size[2] };
        *q = [
            o.position[0] + c * lx - s * ly,
            o.position[1] + s * lx + c * ly,
            o.position[2] + lz,
        ];
    }
    out
}

/// Near plane of the projection (metres), the rasteriser's.
const NEAR: f64 = 0.2;

/// The share of the frame `o`'s box covers from `cam`: its silhouette (the box clipped by the
/// near plane, projected, convex hull) clipped to the image, over the image area.
pub fn frame_share(cam: &Camera, o: &ObjectBox) -> f64 {
    let (w, h) = (cam.width as f64, cam.height as f64);
    polygon_area(&silhouette(cam, o)) / (w * h)
}

/// The share of the frame `o` covers (as [`frame_share`]) and the bounding rectangle of its
/// silhouette in the image, `[x0, y0, x1, y1]` pixels (`None` out of frame).
pub fn screen_box(cam: &Camera, o: &ObjectBox) -> (f64, Option<[f64; 4]>) {
    let (w, h) = (cam.width as f64, cam.height as f64);
    let s = silhouette(cam, o);
    let rect = (s.len() >= 3).then(|| {
        s.iter()
            .fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |r, p| {
                [
                    r[0].min(p[0]),
                    r[1].min(p[1]),
                    r[2].max(p[0]),
                    r[3].max(p[1]),
                ]
            })
    });
    (polygon_area(&s) / (w * h), rect)
}

/// The share of rectangle `far` that rectangle `near` covers (see [`screen_box`]).
pub fn hidden_share(near: &[f64; 4], far: &[f64; 4]) -> f64 {
    let (a, b) = (near, far);
    let overlap =
        (a[2].min(b[2]) - a[0].max(b[0])).max(0.0) * (a[3].min(b[3]) - a[1].max(b[1])).max(0.0);
    overlap / ((b[2] - b[0]) * (b[3] - b[1])).max(1e-9)
}

/// A convex polygon of image points kept on the stack (a box's silhouette has at most 24
/// corners: 20 after the near plane, one more for each side of the frame).
#[derive(Clone, Copy)]
pub(crate) struct Poly {
    pts: [[f64; 2]; Poly::CAP],
    n: usize,
}

impl Poly {
    const CAP: usize = 32;

    fn new() -> Poly {
        Poly {
            pts: [[0.0; 2]; Poly::CAP],
            n: 0,
        }
    }

    fn push(&mut self, p: [f64; 2]) {
        if self.n < Poly::CAP {
            self.pts[self.n] = p;
            self.n += 1;
        }
    }
}

impl std::ops::Deref for Poly {
    type Target = [[f64; 2]];
    fn deref(&self) -> &[[f64; 2]] {
        &self.pts[..self.n]
    }
}

/// `o`'s box as the image sees it: clipped by the near plane, projected, its convex hull
/// clipped to the image (pixels). A box wholly outside one side of the view is empty at once.
pub(crate) fn silhouette(cam: &Camera, o: &ObjectBox) -> Poly {
    let (r, t) = cam.world_to_camera();
    let pc = corners(o)
        .map(|p| [0, 1, 2].map(|i| r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i]));
    let (w, h) = (cam.width as f64, cam.height as f64);
    // The view's five sides, each `>= 0` inside: the near plane and the frame's four edges.
    let sides = |p: &[f64; 3]| {
        [
            p[2] - NEAR,
            cam.fx * p[0] + 0.5 * w * p[2],
            0.5 * w * p[2] - cam.fx * p[0],
            cam.fy * p[1] + 0.5 * h * p[2],
            0.5 * h * p[2] - cam.fy * p[1],
        ]
    };
    let outside = pc.iter().map(sides).fold([true; 5], |all, d| {
        [0, 1, 2, 3, 4].map(|k| all[k] && d[k] < 0.0)
    });
    if outside.contains(&true) {
        return Poly::new();
    }
    let mut pts = [[0.0f64; 2]; 20];
    let mut n = 0;
    let mut keep = |p: [f64; 3]| {
        pts[n] = [
            cam.fx * p[0] / p[2] + 0.5 * w,
            cam.fy * p[1] / p[2] + 0.5 * h,
        ];
        n += 1;
    };
    for (i, a) in pc.iter().enumerate() {
        if a[2] >= NEAR {
            keep(*a);
        }
        // Edges join corners that differ in one bit.
        for bit in [1, 2, 4] {
            let j = i ^ bit;
            if j > i {
                let b = pc[j];
                if (a[2] - NEAR) * (b[2] - NEAR) < 0.0 {
                    let t = (NEAR - a[2]) / (b[2] - a[2]);
                    keep([0, 1, 2].map(|k| a[k] + t * (b[k] - a[k])));
                }
            }
        }
    }
    clip_to_rect(&hull(&mut pts[..n]), w, h)
}

/// The convex hull of `p` (reordered), counter-clockwise from its lowest-leftmost point (the
/// monotone chain of [`crate::util::convex_hull`], on the stack).
fn hull(p: &mut [[f64; 2]]) -> Poly {
    let mut q = Poly::new();
    for &v in p.iter().filter(|v| v[0].is_finite() && v[1].is_finite()) {
        q.push(v);
    }
    let pts = &mut q.pts[..q.n];
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    let mut m = 0;
    for k in 0..pts.len() {
        if m == 0 || pts[k] != pts[m - 1] {
            pts[m] = pts[k];
            m += 1;
        }
    }
    q.n = m;
    if m < 3 {
        return q;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut out = [[0.0f64; 2]; 2 * Poly::CAP];
    let mut len = 0;
    // The lower chain left to right, then the upper one right to left.
    for upper in [false, true] {
        let start = len;
        for k in 0..m {
            let v = q.pts[if upper { m - 1 - k } else { k }];
            while len >= start + 2 && cross(out[len - 2], out[len - 1], v) <= 0.0 {
                len -= 1;
            }
            out[len] = v;
            len += 1;
        }
        len -= 1;
    }
    let mut res = Poly::new();
    for &v in &out[..len] {
        res.push(v);
    }
    res
}

/// True when `o`'s box centre is in front of `cam` and inside its frame.
pub fn in_frame(cam: &Camera, o: &ObjectBox) -> bool {
    in_frame_within(cam, o, 0.0)
}

/// True when `o`'s box centre is in front of `cam` and inside its frame narrowed by `inset`
/// of its width at each side.
pub(crate) fn in_frame_within(cam: &Camera, o: &ObjectBox, inset: f64) -> bool {
    let c = to_cam(
        cam,
        [
            o.position[0],
            o.position[1],
            o.position[2] + 0.5 * o.size[2],
        ],
    );
    if c[2] <= NEAR {
        return false;
    }
    let (w, h) = (cam.width as f64, cam.height as f64);
    let (u, v) = (
        cam.fx * c[0] / c[2] + 0.5 * w,
        cam.fy * c[1] / c[2] + 0.5 * h,
    );
    (inset * w..=(1.0 - inset) * w).contains(&u) && (0.0..=h).contains(&v)
}

/// Statistics of one view of `scene` (see [`ViewStats`]).
pub fn view_stats(scene: &SceneBox, cam: &Camera) -> ViewStats {
    let mut s = ViewStats {
        in_view: 0,
        largest: 0.0,
        covered: 0.0,
        subject: None,
        facing: 0.0,
    };
    for (k, o) in scene.objects.iter().enumerate() {
        if in_frame(cam, o) {
            s.in_view += 1;
        }
        let share = frame_share(cam, o);
        s.covered += share;
        if o.size[2] > FLAT && share > s.largest {
            s.largest = share;
            s.subject = Some(k);
            s.facing = facing(o, cam.position);
        }
    }
    s.covered = s.covered.min(1.0);
    s
}

/// The cosine between `o`'s facing and the horizontal direction from its centre to `p` (0 when
/// `p` stands above its centre).
pub fn facing(o: &ObjectBox, p: [f64; 3]) -> f64 {
    let (s, c) = o.yaw.to_radians().sin_cos();
    let (dx, dy) = (p[0] - o.position[0], p[1] - o.position[1]);
    let d = dx.hypot(dy);
    if d < 1e-9 {
        return 0.0;
    }
    (-s * dx + c * dy) / d
}

/// The share of `cams` that frame `scene` well ([`ViewStats::framed_well`]); 0 for no cameras.
pub fn framing_score(scene: &SceneBox, cams: &[Camera]) -> f64 {
    if cams.is_empty() {
        return 0.0;
    }
    let good = cams
        .iter()
        .filter(|c| view_stats(scene, c).framed_well())
        .count();
    good as f64 / cams.len() as f64
}

/// Sutherland–Hodgman clipping of a convex polygon to `[0, w] x [0, h]`.
fn clip_to_rect(poly: &Poly, w: f64, h: f64) -> Poly {
    let mut out = *poly;
    // (axis, bound, keep below)
    for (axis, bound, below) in [(0, 0.0, false), (0, w, true), (1, 0.0, false), (1, h, true)] {
        let inside = |p: &[f64; 2]| {
            if below {
                p[axis] <= bound
            } else {
                p[axis] >= bound
            }
        };
        let input = std::mem::replace(&mut out, Poly::new());
        for (i, a) in input.iter().enumerate() {
            let b = &input[(i + 1) % input.len()];
            let (ia, ib) = (inside(a), inside(b));
            if ia {
                out.push(*a);
            }
            if ia != ib {
                let t = (bound - a[axis]) / (b[axis] - a[axis]);
                out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
            }
        }
    }
    out
}

fn polygon_area(p: &[[f64; 2]]) -> f64 {
    if p.len() < 3 {
        return 0.0;
    }
    let s: f64 = (0..p.len())
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            a[0] * b[1] - a[1] * b[0]
        })
        .sum();
    0.5 * s.abs()
}

/// An overview of the whole scene for the viewer's first frame: from high in the corner (or, for
/// open ground, above the edge) whose view shows the most objects, looking at the floor's centre.
pub fn overview_camera(scene: &SceneBox, width: u32, height: u32) -> Camera {
    let [hx, hy] = scene.half();
    let (m, z) = match scene.scene_type {
        SceneType::Indoor => (ROOM_MARGIN + 0.05, scene.room[2] - ROOM_MARGIN - 0.05),
        SceneType::Outdoor => (ROOM_MARGIN + 0.05, (0.35 * hx.max(hy)).clamp(2.0, 12.0)),
    };
    let target = [0.0, 0.0, 0.15 * scene.room[2].min(4.0)];
    let fov_x = 2.0 * ((0.5 * SCENE_FOV_X).tan() * 1.2).atan();
    let mut best: Option<(Camera, usize)> = None;
    for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        for shrink in [0.0, 0.4, 0.8, 1.2] {
            let p = [sx * (hx - m - shrink), sy * (hy - m - shrink), z];
            let free = match scene.scene_type {
                SceneType::Indoor => valid_viewpoint(scene, p),
                SceneType::Outdoor => !scene.objects.iter().any(|o| o.contains(p, 0.25)),
            };
            if !free {
                continue;
            }
            let cam = camera(p, target, [0.0, 0.0, 1.0], width, height, fov_x);
            let n = view_stats(scene, &cam).in_view;
            if best.as_ref().is_none_or(|(_, b)| n > *b) {
                best = Some((cam, n));
            }
            break;
        }
    }
    best.map(|(c, _)| c).unwrap_or_else(|| {
        camera(
            [0.0, -hy.max(1.0), z],
            target,
            [0.0, 0.0, 1.0],
            width,
            height,
            fov_x,
        )
    })
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// An unturned box standing on the floor at (x, y) (also the view choice's tests' helper).
    pub(in crate::camera::scene) fn boxed(id: &str, x: f64, y: f64, size: [f64; 3]) -> ObjectBox {
        ObjectBox {
            id: id.into(),
            position: [x, y, 0.0],
            size,
            yaw: 0.0,
        }
    }

    #[test]
    fn a_box_filling_the_view_has_share_one_and_one_behind_zero() {
        let cam = camera(
            [0.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
            [0.0, 0.0, 1.0],
            64,
            64,
            SCENE_FOV_X,
        );
        let wall = boxed("w", 0.0, 1.0, [20.0, 0.1, 5.0]);
        assert!((frame_share(&cam, &wall) - 1.0).abs() < 1e-9);
        let behind = boxed("b", 0.0, -2.0, [1.0, 1.0, 1.0]);
        assert_eq!(frame_share(&cam, &behind), 0.0);
        // A unit square face-on at distance d covers (f / d)² pixels.
        let sq = boxed("s", 0.0, 3.0 + 0.0005, [0.2, 0.001, 0.2]);
        let sq = ObjectBox {
            position: [0.0, sq.position[1], 0.9],
            ..sq
        };
        let f = cam.fx;
        let want = (f * 0.2 / 3.0).powi(2) / (64.0 * 64.0);
        let got = frame_share(&cam, &sq);
        assert!((got - want).abs() < 0.02 * want, "{got} vs {want}");
    }

    #[test]
    fn facing_is_one_in_front_zero_beside_and_minus_one_behind() {
        let o = ObjectBox {
            yaw: 90.0,
            ..boxed("tv", 1.0, 1.0, [1.0, 0.1, 0.6])
        };
        // At yaw 90° an object faces −x.
        assert!((facing(&o, [-2.0, 1.0, 1.5]) - 1.0).abs() < 1e-9);
        assert!(facing(&o, [1.0, 4.0, 1.5]).abs() < 1e-9);
        assert!((facing(&o, [3.0, 1.0, 0.0]) + 1.0).abs() < 1e-9);
    }
}
