//! Camera paths of `video` and `render` (host only, no GPU): in a scene directory built here,
//! the orbit and the exploring loop stay inside the room and clear of every object (checked
//! against the objects' own points, placed by an independent transform), the orbit looks at
//! the room centre, a single PLY's orbit frames the cloud, a cameras.json is resized with its
//! focal lengths, and an outdoor loop is a circle.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::camera::{write_cameras, Camera};
use dreamscene::export::trajectory::{cameras, open_input, Size, Subject, Trajectory};
use dreamscene::splat::ply::write_ply;
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-trajectory-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("objects")).unwrap();
    d
}

/// A box of `size` [w, d, h] filled with Gaussians on a 5 cm grid, in the object frame
/// (bottom-face centre at the origin).
fn box_cloud(size: [f32; 3]) -> Gaussians {
    let mut g = Gaussians::default();
    let steps = size.map(|s| (s / 0.05).ceil().max(1.0) as usize);
    for i in 0..=steps[0] {
        for j in 0..=steps[1] {
            for k in 0..=steps[2] {
                g.means.push([
                    -0.5 * size[0] + size[0] * i as f32 / steps[0] as f32,
                    -0.5 * size[1] + size[1] * j as f32 / steps[1] as f32,
                    size[2] * k as f32 / steps[2] as f32,
                ]);
                g.scales.push([-4.0; 3]);
                g.rotations.push([1.0, 0.0, 0.0, 0.0]);
                g.opacities.push(2.0);
                g.sh.extend([0.5, 0.5, 0.5]);
            }
        }
    }
    g
}

struct Placed {
    size: [f32; 3],
    position: [f64; 3],
    yaw: f64,
    scale: [f64; 3],
}

/// A scene directory with the given objects (one PLY each) and no environment.
fn scene_dir(name: &str, scene_type: &str, room: [f64; 3], objects: &[Placed]) -> PathBuf {
    let d = tmp(name);
    let mut objs = vec![];
    for (i, o) in objects.iter().enumerate() {
        let ply = format!("objects/thing{i}.ply");
        write_ply(&d.join(&ply), &box_cloud(o.size)).unwrap();
        objs.push(
            serde_json::json!({"id": format!("thing{}", i + 1), "category": "thing",
            "ply": ply, "position": o.position, "yaw": o.yaw, "scale": o.scale}),
        );
    }
    let scene = serde_json::json!({"version": 1, "prompt": "test", "seed": 0,
        "scene_type": scene_type, "room": {"size": room}, "prior": {"kind": "shape", "models": null},
        "objects": objs, "environment": null, "stages": [], "timeline": null});
    std::fs::write(d.join("scene.json"), scene.to_string()).unwrap();
    d
}

/// Distance from `p` to the nearest placed point of `o` (world = Rz(yaw)·diag(scale)·p + t),
/// computed here without the library's transform.
fn clearance(p: [f64; 3], o: &Placed) -> f64 {
    let (s, c) = o.yaw.to_radians().sin_cos();
    let g = box_cloud(o.size);
    g.means
        .iter()
        .map(|m| {
            let q = [
                m[0] as f64 * o.scale[0],
                m[1] as f64 * o.scale[1],
                m[2] as f64 * o.scale[2],
            ];
            let w = [
                c * q[0] - s * q[1] + o.position[0],
                s * q[0] + c * q[1] + o.position[1],
                q[2] + o.position[2],
            ];
            ((w[0] - p[0]).powi(2) + (w[1] - p[1]).powi(2) + (w[2] - p[2]).powi(2)).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

fn forward(c: &Camera) -> [f64; 3] {
    [c.rotation[0][2], c.rotation[1][2], c.rotation[2][2]]
}

fn living_room() -> Vec<Placed> {
    vec![
        // A coffee table in the middle, a sofa against a wall, a tall shelf in a corner and a
        // rotated, scaled armchair.
        Placed {
            size: [1.1, 0.6, 0.45],
            position: [0.0, 0.0, 0.0],
            yaw: 0.0,
            scale: [1.0; 3],
        },
        Placed {
            size: [2.2, 0.95, 0.85],
            position: [0.0, -1.5, 0.0],
            yaw: 0.0,
            scale: [1.0; 3],
        },
        Placed {
            size: [1.0, 0.35, 1.9],
            position: [2.0, 1.7, 0.0],
            yaw: 180.0,
            scale: [1.0; 3],
        },
        Placed {
            size: [0.85, 0.85, 0.9],
            position: [-1.4, 0.6, 0.0],
            yaw: 30.0,
            scale: [1.2, 1.2, 1.0],
        },
    ]
}

#[test]
fn room_paths_stay_inside_the_room_and_clear_of_every_object() {
    let room = [5.0, 4.0, 2.8];
    let objects = living_room();
    let d = scene_dir("room", "indoor", room, &objects);
    let input = open_input(&d).unwrap();
    assert!(matches!(input.subject, Subject::Scene(_)));
    let size = Some(Size {
        width: 64,
        height: 48,
    });
    for traj in [Trajectory::Orbit, Trajectory::Explore] {
        let cams = cameras(&traj, &input.subject, 90, size).unwrap();
        assert_eq!(cams.len(), 90, "{traj:?}");
        for c in &cams {
            assert_eq!((c.width, c.height), (64, 48));
            let p = c.position;
            assert!(
                p[0].abs() < 0.5 * room[0] - 0.2
                    && p[1].abs() < 0.5 * room[1] - 0.2
                    && p[2] > 0.2
                    && p[2] < room[2] - 0.2,
                "{traj:?} {}: {p:?} outside the room",
                c.img_name
            );
            for (k, o) in objects.iter().enumerate() {
                let gap = clearance(p, o);
                assert!(
                    gap > 0.2,
                    "{traj:?} {} is {gap:.2} m from object {k}",
                    c.img_name
                );
            }
        }
        // A path, not a scatter: neighbouring cameras are close (a 90-frame loop in a 5x4 m
        // room moves well under 1 m a frame).
        for w in cams.windows(2) {
            let step = (0..3)
                .map(|k| (w[0].position[k] - w[1].position[k]).powi(2))
                .sum::<f64>()
                .sqrt();
            assert!(step < 1.0, "{traj:?}: a jump of {step:.2} m");
        }
    }
    // The orbit looks at the room centre from every camera.
    for c in cameras(&Trajectory::Orbit, &input.subject, 36, size).unwrap() {
        let f = forward(&c);
        let to = [-c.position[0], -c.position[1], 0.0];
        let n = (to[0] * to[0] + to[1] * to[1]).sqrt();
        let cos = (f[0] * to[0] + f[1] * to[1]) / n / (f[0] * f[0] + f[1] * f[1]).sqrt();
        assert!(cos > 0.99, "{}: looks {cos:.3} off the centre", c.img_name);
    }
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn outdoor_explore_is_a_circle_and_a_single_cloud_is_framed() {
    let bench = Placed {
        size: [1.5, 0.5, 0.5],
        position: [8.5, 8.5, 0.0],
        yaw: 45.0,
        scale: [1.0; 3],
    };
    let d = scene_dir("outdoor", "outdoor", [20.0, 20.0, 10.0], &[bench]);
    let input = open_input(&d).unwrap();
    let cams = cameras(&Trajectory::Explore, &input.subject, 24, None).unwrap();
    assert_eq!((cams[0].width, cams[0].height), (640, 480));
    let r0 = cams[0].position[0].hypot(cams[0].position[1]);
    for c in &cams {
        let r = c.position[0].hypot(c.position[1]);
        assert!((r - r0).abs() < 1e-6 && r > 1.0, "radius {r} vs {r0}");
    }
    std::fs::remove_dir_all(&d).ok();

    // A single PLY: every orbit camera sees the whole box inside its image.
    let d = tmp("cloud");
    let ply = d.join("box.ply");
    let mut g = box_cloud([0.6, 0.4, 0.8]);
    for m in &mut g.means {
        m[0] += 3.0;
    }
    write_ply(&ply, &g).unwrap();
    let input = open_input(&ply).unwrap();
    let size = Some(Size {
        width: 80,
        height: 60,
    });
    assert!(cameras(&Trajectory::Explore, &input.subject, 8, size).is_err());
    let cams = cameras(&Trajectory::Orbit, &input.subject, 8, size).unwrap();
    for c in &cams {
        let (r, t) = c.world_to_camera();
        for m in &g.means {
            let m = m.map(|v| v as f64);
            let q: Vec<f64> = (0..3)
                .map(|i| r[i][0] * m[0] + r[i][1] * m[1] + r[i][2] * m[2] + t[i])
                .collect();
            assert!(q[2] > 0.2, "{}: a point behind the camera", c.img_name);
            let (u, v) = (c.fx * q[0] / q[2] + 40.0, c.fy * q[1] / q[2] + 30.0);
            assert!(
                (0.0..80.0).contains(&u) && (0.0..60.0).contains(&v),
                "{}: point at pixel ({u:.1}, {v:.1})",
                c.img_name
            );
        }
    }

    // A cameras.json keeps its cameras and is resized with its focal lengths.
    let json = d.join("cams.json");
    write_cameras(&json, &cams).unwrap();
    let traj: Trajectory = json.to_str().unwrap().parse().unwrap();
    let resized = cameras(
        &traj,
        &input.subject,
        0,
        Some(Size {
            width: 160,
            height: 90,
        }),
    )
    .unwrap();
    assert_eq!(resized.len(), cams.len());
    for (a, b) in cams.iter().zip(&resized) {
        assert_eq!((b.width, b.height), (160, 90));
        assert!((b.fx - 2.0 * a.fx).abs() < 1e-9 && (b.fy - 1.5 * a.fy).abs() < 1e-9);
        assert!((0..3).all(|k| (a.position[k] - b.position[k]).abs() < 1e-9));
    }
    std::fs::remove_dir_all(Path::new(&d)).ok();
}
