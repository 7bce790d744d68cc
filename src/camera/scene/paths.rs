//! Evaluation paths: the authors' inference circle, an exploring loop through the room and
//! object orbits. Host-only; every path camera of a scene is a valid viewpoint.
use super::{add, camera, len, nearest_valid, valid_viewpoint, SceneBox, ROOM_MARGIN, SCENE_FOV_X};
use crate::camera::Camera;
use crate::plan::spec::SceneType;
use std::f64::consts::PI;

/// The inference circle: `frames` cameras at mid height on the inscribed circle (radius
/// R − 0.01, shrunk by 0.98 until at least half the poses are valid), looking at the centre;
/// only valid poses are kept.
pub fn inference_circle(scene: &SceneBox, frames: usize, width: u32, height: u32) -> Vec<Camera> {
    let z = scene.zmid();
    let mut r = scene.r_in() - 0.01;
    let ring = |r: f64| -> Vec<[f64; 3]> {
        (0..frames)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / frames.max(1) as f64;
                [r * a.sin(), r * a.cos(), z]
            })
            .collect()
    };
    let mut pts = ring(r);
    for _ in 0..200 {
        if 2 * pts.iter().filter(|p| valid_viewpoint(scene, **p)).count() >= frames {
            break;
        }
        r *= 0.98;
        pts = ring(r);
    }
    let cams = pts
        .into_iter()
        .filter(|p| valid_viewpoint(scene, *p))
        .map(|p| {
            camera(
                p,
                [0.0, 0.0, z],
                [0.0, 0.0, 1.0],
                width,
                height,
                SCENE_FOV_X,
            )
        });
    named(cams.collect(), "circle")
}

fn named(mut cams: Vec<Camera>, name: &str) -> Vec<Camera> {
    for (i, c) in cams.iter_mut().enumerate() {
        c.id = i as u32;
        c.img_name = format!("{name}_{i:04}");
    }
    cams
}

/// An evaluation path: a closed loop at eye height (1.5 m, lower in low rooms) through the room,
/// each camera looking a quarter of the loop ahead (along and across the room); points that fall
/// in an object move in or out along their radius, or to the nearest valid point. Outdoors it is
/// a circle at 2/3 of the half-extent looking at the centre. Every camera is a valid viewpoint.
pub fn explore_path(scene: &SceneBox, frames: usize, width: u32, height: u32) -> Vec<Camera> {
    let indoor = scene.scene_type == SceneType::Indoor;
    let eye = 1.5f64.min(0.55 * scene.room[2]).max(ROOM_MARGIN);
    let [hx, hy] = scene.half();
    let k = if indoor { 0.6 } else { 2.0 / 3.0 };
    let at = |a: f64| [k * hx * a.sin(), k * hy * a.cos(), eye];
    let mut cams = vec![];
    for i in 0..frames {
        let a = 2.0 * PI * i as f64 / frames.max(1) as f64;
        let p = at(a);
        let fixed = [1.0, 0.9, 1.1, 0.8, 1.2, 0.7, 1.3, 0.6, 0.5, 0.4, 0.3, 0.2]
            .into_iter()
            .map(|f| [p[0] * f, p[1] * f, eye])
            .find(|q| valid_viewpoint(scene, *q))
            .or_else(|| nearest_valid(scene, p))
            .unwrap_or([0.0, 0.0, 0.5 * scene.room[2]]);
        let target = if indoor {
            let ahead = at(a + 0.5 * PI);
            [ahead[0], ahead[1], 0.8 * eye]
        } else {
            [0.0, 0.0, 0.8 * eye]
        };
        let target = if len(add(target, fixed, -1.0)) > 0.3 {
            target
        } else {
            [0.0, 0.0, 0.8 * eye]
        };
        cams.push(camera(
            fixed,
            target,
            [0.0, 0.0, 1.0],
            width,
            height,
            SCENE_FOV_X,
        ));
    }
    named(cams, "explore")
}

/// `frames` cameras on a horizontal circle of `radius` around `target` at height `height`,
/// looking at it, with horizontal field of view `fov_x` radians.
pub fn orbit(
    target: [f64; 3],
    radius: f64,
    height: f64,
    frames: usize,
    width: u32,
    height_px: u32,
    fov_x: f64,
) -> Vec<Camera> {
    let cams = (0..frames)
        .map(|i| {
            let a = 2.0 * PI * i as f64 / frames.max(1) as f64;
            let eye = [
                target[0] + radius * a.sin(),
                target[1] + radius * a.cos(),
                height,
            ];
            camera(eye, target, [0.0, 0.0, 1.0], width, height_px, fov_x)
        })
        .collect();
    named(cams, "orbit")
}
