//! The scene camera schedule on planned and hand-made layouts, indoor and outdoor: every camera
//! stands inside the room and outside every object, looks into the scene, every object is seen in
//! stage 2, the union of the stages sees the floor, the evaluation paths are valid.
use dreamscene::camera::scene::{
    explore_path, inference_circle, orbit, stage_cameras, valid_viewpoint, ObjectBox, SceneBox,
    Stage, SCENE_FOV_X,
};
use dreamscene::camera::Camera;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_offline;
use dreamscene::plan::spec::SceneType;

const W: u32 = 256;
const COUNTS: [(Stage, usize); 3] = [(Stage::One, 400), (Stage::Two, 400), (Stage::Three, 80)];

fn planned(prompt: &str) -> SceneBox {
    let spec = plan_offline(prompt);
    let l = layout(&spec, LayoutOptions::seeded(3)).expect("layout");
    SceneBox::from_layout(&l)
}

fn obj(id: &str, position: [f64; 3], size: [f64; 3], yaw: f64) -> ObjectBox {
    ObjectBox {
        id: id.into(),
        position,
        size,
        yaw,
    }
}

/// Planned layouts and hand-made ones (a cramped bedroom, a long hall with a rotated piece, an
/// empty field).
fn scenes() -> Vec<(String, SceneBox)> {
    let mut v: Vec<(String, SceneBox)> = [
        "a cozy living room",
        "a bedroom",
        "a kitchen",
        "a classroom",
        "a garden",
        "a beach",
        "a city street",
    ]
    .iter()
    .map(|p| (p.to_string(), planned(p)))
    .collect();
    v.push((
        "cramped bedroom".into(),
        SceneBox {
            scene_type: SceneType::Indoor,
            room: [3.0, 3.2, 2.4],
            openings: vec![],
            objects: vec![
                obj("bed1", [0.0, -0.4, 0.0], [1.6, 2.0, 0.6], 0.0),
                obj("wardrobe1", [1.0, 1.25, 0.0], [1.0, 0.6, 2.1], 180.0),
            ],
        },
    ));
    v.push((
        "long hall".into(),
        SceneBox {
            scene_type: SceneType::Indoor,
            room: [10.0, 4.0, 3.0],
            openings: vec![],
            objects: vec![
                obj("table1", [2.0, 0.0, 0.0], [2.0, 1.0, 0.75], 35.0),
                obj("shelf1", [-4.6, 0.0, 0.0], [0.4, 2.0, 2.0], 90.0),
            ],
        },
    ));
    v.push((
        "empty field".into(),
        SceneBox {
            scene_type: SceneType::Outdoor,
            room: [20.0, 20.0, 10.0],
            openings: vec![],
            objects: vec![],
        },
    ));
    v
}

/// Pixel coordinates and depth of `p`, when it is in front of the camera (beyond the rasteriser's
/// 0.2 m near plane) and inside the image.
fn project(c: &Camera, p: [f64; 3]) -> Option<(f64, f64, f64)> {
    let (r, t) = c.world_to_camera();
    let q: Vec<f64> = (0..3)
        .map(|i| r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i])
        .collect();
    if q[2] <= 0.2 {
        return None;
    }
    let u = c.fx * q[0] / q[2] + 0.5 * c.width as f64;
    let v = c.fy * q[1] / q[2] + 0.5 * c.height as f64;
    (u >= 0.0 && v >= 0.0 && u < c.width as f64 && v < c.height as f64).then_some((u, v, q[2]))
}

fn inside_room(s: &SceneBox, p: [f64; 3]) -> bool {
    p[0].abs() < 0.5 * s.room[0] && p[1].abs() < 0.5 * s.room[1] && p[2] > 0.0 && p[2] < s.room[2]
}

fn forward(c: &Camera) -> [f64; 3] {
    [c.rotation[0][2], c.rotation[1][2], c.rotation[2][2]]
}

#[test]
fn every_stage_camera_stands_inside_the_room_and_outside_every_object() {
    for (name, s) in scenes() {
        for (stage, n) in COUNTS {
            let cams = stage_cameras(stage, &s, n, W, W, 11);
            assert_eq!(cams.len(), n, "{name} {stage:?}");
            for c in &cams {
                let p = c.position;
                assert!(
                    valid_viewpoint(&s, p),
                    "{name} {stage:?} {}: {p:?}",
                    c.img_name
                );
                assert!(
                    inside_room(&s, p),
                    "{name} {stage:?}: {p:?} outside the room"
                );
                for o in &s.objects {
                    assert!(!o.contains(p, 0.2), "{name} {stage:?}: {p:?} in {}", o.id);
                }
            }
        }
    }
}

#[test]
fn scene_cameras_look_into_the_scene() {
    for (name, s) in scenes() {
        for (stage, n) in COUNTS {
            for (i, c) in stage_cameras(stage, &s, n, W, W, 5).into_iter().enumerate() {
                let f = forward(&c);
                // Not staring into a wall, the floor or the sky from point-blank range (an object
                // orbit may look steeply down at a low object nearby).
                let ahead = [0, 1, 2].map(|k| c.position[k] + 0.5 * f[k]);
                assert!(
                    inside_room(&s, ahead),
                    "{name} {stage:?} {}: looks out of the room from {:?} along {f:?}",
                    c.img_name,
                    c.position
                );
                // The first 70% of stage 1 are centre-looking (object orbits join later).
                if stage == Stage::One && s.scene_type == SceneType::Indoor && i * 10 < n * 7 {
                    let seen = (1..10)
                        .map(|k| [0.0, 0.0, s.room[2] * k as f64 / 10.0])
                        .any(|p| project(&c, p).is_some());
                    assert!(
                        seen,
                        "{name} {}: the room centre is not in view",
                        c.img_name
                    );
                }
            }
        }
    }
}

#[test]
fn every_object_is_seen_by_a_stage_two_camera() {
    for (name, s) in scenes() {
        let cams = stage_cameras(Stage::Two, &s, 2800, W, W, 2);
        for o in &s.objects {
            let centre = [
                o.position[0],
                o.position[1],
                o.position[2] + 0.5 * o.size[2],
            ];
            let seen = cams.iter().filter(|c| project(c, centre).is_some()).count();
            assert!(seen > 0, "{name}: {} never seen in stage 2", o.id);
        }
    }
}

#[test]
fn the_stages_together_see_the_whole_floor() {
    for (name, s) in scenes() {
        let cams: Vec<Camera> = COUNTS
            .iter()
            .flat_map(|&(stage, n)| stage_cameras(stage, &s, n, W, W, 8))
            .collect();
        let (hx, hy) = (0.5 * s.room[0], 0.5 * s.room[1]);
        let (mut total, mut seen) = (0, 0);
        let step = 0.25;
        let mut x = -hx + 0.5 * step;
        while x < hx {
            let mut y = -hy + 0.5 * step;
            while y < hy {
                total += 1;
                if cams.iter().any(|c| project(c, [x, y, 0.0]).is_some()) {
                    seen += 1;
                }
                y += step;
            }
            x += step;
        }
        let frac = seen as f64 / total as f64;
        assert!(frac >= 0.95, "{name}: floor seen {frac:.3}");
    }
}

#[test]
fn explore_path_and_circle_stay_valid() {
    for (name, s) in scenes() {
        let path = explore_path(&s, 120, W, W);
        assert_eq!(path.len(), 120);
        for c in &path {
            assert!(valid_viewpoint(&s, c.position), "{name} {}", c.img_name);
            let f = forward(c);
            let ahead = [0, 1, 2].map(|k| c.position[k] + f[k]);
            assert!(inside_room(&s, ahead), "{name} {}", c.img_name);
        }
        let circle = inference_circle(&s, 120, W, W);
        assert!(circle.len() >= 60, "{name}: {} circle views", circle.len());
        assert!(circle.iter().all(|c| valid_viewpoint(&s, c.position)));
    }
}

#[test]
fn orbit_looks_at_its_target() {
    let t = [1.0, -0.5, 0.4];
    let cams = orbit(t, 2.0, 1.2, 36, W, W, 0.8);
    assert_eq!(cams.len(), 36);
    for (i, c) in cams.iter().enumerate() {
        assert_eq!(c.id, i as u32);
        let (u, v, _) = project(c, t).expect("target in view");
        assert!((u - 128.0).abs() < 1e-6 && (v - 128.0).abs() < 1e-6);
        assert!((c.position[2] - 1.2).abs() < 1e-12);
    }
}

#[test]
fn stage_cameras_are_deterministic_with_scene_fov() {
    let s = planned("a cozy living room");
    let a = stage_cameras(Stage::Two, &s, 100, 512, 384, 9);
    assert_eq!(a, stage_cameras(Stage::Two, &s, 100, 512, 384, 9));
    assert_ne!(a, stage_cameras(Stage::Two, &s, 100, 512, 384, 10));
    let one = stage_cameras(Stage::One, &s, 16, 512, 384, 9);
    for (i, c) in one.iter().enumerate() {
        assert_eq!(c.id, i as u32);
        assert_eq!(c.img_name, format!("stage1_{i:05}"));
        let fov_x = 2.0 * (256.0 / c.fx).atan();
        assert!((fov_x - SCENE_FOV_X).abs() < 1e-9, "{fov_x}");
        assert!((c.fx - c.fy).abs() < 1e-9);
    }
    assert!(stage_cameras(Stage::Three, &s, 0, 64, 64, 0).is_empty());
}
