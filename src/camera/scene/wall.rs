//! Bare wall: the share of a view's frame that is wall with nothing before it, from the
//! cameras, the layout boxes and the room's doors and windows (occlusion among them ignored).
//! The objects' summed cover counts a plant and an armchair against an empty wall as well
//! filled; what a person sees there is mostly wall. Indoors only: open ground has no walls.
//! Host-only.
use super::views::silhouette;
use super::{ObjectBox, SceneBox};
use crate::camera::Camera;
use crate::plan::spec::{Opening, SceneType, Wall};

/// How deep an opening's box stands into the room (metres): a panel on the wall's face.
const OPENING_DEPTH: f64 = 0.02;
/// Samples across (and down) the frame: 24² rays, enough for a share judged in tenths.
const SAMPLES: usize = 24;

/// A door or window as a thin box on its wall, facing into the room (yaw 0 faces +y).
pub fn opening_box(o: &Opening, n: usize) -> ObjectBox {
    let inward = o.wall.inward();
    let yaw = match o.wall {
        Wall::South => 0.0,
        Wall::North => 180.0,
        Wall::East => 90.0,
        Wall::West => -90.0,
    };
    let half = 0.5 * OPENING_DEPTH;
    ObjectBox {
        id: format!("{:?}{n}", o.kind).to_lowercase(),
        position: [
            o.position[0] + half * inward[0],
            o.position[1] + half * inward[1],
            o.position[2],
        ],
        size: [o.width, OPENING_DEPTH, o.height],
        yaw,
    }
}

/// True when the convex polygon `poly` (either winding) holds `p`.
fn inside(poly: &[[f64; 2]], p: [f64; 2]) -> bool {
    if poly.len() < 3 {
        return false;
    }
    let mut sign = 0.0f64;
    for (i, a) in poly.iter().enumerate() {
        let b = poly[(i + 1) % poly.len()];
        let cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        if cross.abs() < 1e-12 {
            continue;
        }
        if sign == 0.0 {
            sign = cross.signum();
        } else if sign != cross.signum() {
            return false;
        }
    }
    true
}

/// True when the ray from `cam` through pixel (u, v) leaves the room through a wall (not the
/// floor or the ceiling).
fn hits_wall(scene: &SceneBox, cam: &Camera, u: f64, v: f64) -> bool {
    let (w, h) = (cam.width as f64, cam.height as f64);
    let c = [(u - 0.5 * w) / cam.fx, (v - 0.5 * h) / cam.fy, 1.0];
    let r = &cam.rotation;
    let d = [0, 1, 2].map(|i| r[i][0] * c[0] + r[i][1] * c[1] + r[i][2] * c[2]);
    let p = cam.position;
    let [hx, hy] = scene.half();
    let exit = |p: f64, d: f64, lo: f64, hi: f64| {
        if d > 1e-12 {
            (hi - p) / d
        } else if d < -1e-12 {
            (lo - p) / d
        } else {
            f64::INFINITY
        }
    };
    let wall = exit(p[0], d[0], -hx, hx).min(exit(p[1], d[1], -hy, hy));
    let flat = exit(p[2], d[2], 0.0, scene.room[2]);
    wall < flat
}

/// The share of `cam`'s frame that is wall with no object and no door or window before it
/// (0 outdoors).
pub fn bare_wall_share(scene: &SceneBox, cam: &Camera) -> f64 {
    if scene.scene_type == SceneType::Outdoor {
        return 0.0;
    }
    let hulls: Vec<super::views::Poly> = scene
        .objects
        .iter()
        .chain(&scene.openings)
        .map(|o| silhouette(cam, o))
        .filter(|s| s.len() >= 3)
        .collect();
    let (w, h) = (cam.width as f64, cam.height as f64);
    let mut bare = 0usize;
    for i in 0..SAMPLES {
        for j in 0..SAMPLES {
            let (u, v) = (
                (i as f64 + 0.5) / SAMPLES as f64 * w,
                (j as f64 + 0.5) / SAMPLES as f64 * h,
            );
            if hits_wall(scene, cam, u, v) && !hulls.iter().any(|s| inside(s, [u, v])) {
                bare += 1;
            }
        }
    }
    bare as f64 / (SAMPLES * SAMPLES) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::scene::camera;
    use crate::plan::spec::OpeningKind;

    #[test]
    fn a_window_covers_the_bare_wall_it_stands_in() {
        // From the room's centre, level, at the north wall 2 m away through a 55° lens: the
        // wall fills the frame's middle band; a window as wide as the view covers much of it.
        let mut scene = SceneBox {
            scene_type: SceneType::Indoor,
            room: [8.0, 4.0, 3.0],
            objects: vec![],
            openings: vec![],
        };
        let cam = camera(
            [0.0, 0.0, 1.5],
            [0.0, 1.0, 1.5],
            [0.0, 0.0, 1.0],
            64,
            64,
            0.96,
        );
        let bare = bare_wall_share(&scene, &cam);
        // Wall from z = 0 to 3 at 2 m: ±37° vertically, beyond the lens's ±27.5°: all wall.
        assert!(bare > 0.99, "bare wall {bare}");
        let window = Opening {
            kind: OpeningKind::Window,
            wall: Wall::North,
            position: [0.0, 2.0, 1.0],
            width: 4.0,
            height: 1.0,
        };
        scene.openings.push(opening_box(&window, 1));
        // The window spans z 1..2 of the wall: 2·atan(0.5/2) of the ±27.5° frame, ~0.5.
        let covered = bare_wall_share(&scene, &cam);
        assert!((covered - 0.5).abs() < 0.1, "bare wall {covered}");
        let outdoor = SceneBox {
            scene_type: SceneType::Outdoor,
            ..scene
        };
        assert_eq!(
            bare_wall_share(&outdoor, &cam),
            0.0,
            "open ground has no wall"
        );
    }
}
