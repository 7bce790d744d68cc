//! Composition: exact SH rotation, instance transforms (covariances and renders), scene.json.
mod common;
use dreamscene::camera::Camera;
use dreamscene::scene::compose::{compose, covariance, mat_to_quat, pad_sh, transform, Placement};
use dreamscene::scene::dir::{compose_scene, read_scene, write_scene, SceneFile};
use dreamscene::scene::sh_rotate::{eval, rotate_coeffs, Mat3, ShRotation};
use dreamscene::splat::loss::psnr;
use dreamscene::splat::ply::write_ply;
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::reference::quat_to_mat;
use dreamscene::splat::Gaussians;
use rand::Rng;

fn unit(rng: &mut impl Rng) -> [f64; 3] {
    loop {
        let v: [f64; 3] = [0; 3].map(|_| rng.gen_range(-1.0..1.0));
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if n > 0.1 && n < 1.0 {
            return v.map(|x| x / n);
        }
    }
}

fn random_rotation(rng: &mut impl Rng) -> Mat3 {
    let q = [0; 4].map(|_| rng.gen_range(-1.0..1.0));
    quat_to_mat(q).expect("a random quaternion is non-zero")
}

fn mul(a: &Mat3, b: &Mat3) -> Mat3 {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn tr(a: &Mat3) -> Mat3 {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| a[j][i]))
}

fn apply(r: &Mat3, d: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| r[i][0] * d[0] + r[i][1] * d[1] + r[i][2] * d[2])
}

fn rot_x(deg: f64) -> Mat3 {
    let (s, c) = deg.to_radians().sin_cos();
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
}

fn rot_z(deg: f64) -> Mat3 {
    dreamscene::scene::compose::rz(deg)
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn rotated_sh_evaluates_equal_at_rotated_directions() {
    let mut rng = common::rng(1);
    for degree in 1..=3u32 {
        let k = ((degree + 1) * (degree + 1)) as usize;
        let mut worst: f64 = 0.0;
        for trial in 0..40 {
            // Every other one a reflection (a rotation times a mirror), which the bands also keep.
            let mut r = random_rotation(&mut rng);
            if trial % 2 == 1 {
                r[0] = r[0].map(|v| -v);
            }
            let c: Vec<f64> = (0..k).map(|_| rng.gen_range(-1.0..1.0)).collect();
            let c2 = rotate_coeffs(&r, &c);
            let scale = c.iter().map(|v| v.abs()).sum::<f64>();
            for _ in 0..20 {
                let d = unit(&mut rng);
                let err = (eval(&c2, apply(&r, d)) - eval(&c, d)).abs() / scale;
                worst = worst.max(err);
            }
        }
        println!("degree {degree}: max relative SH error {worst:.2e}");
        assert!(worst < 1e-5, "degree {degree}: error {worst}");
    }
}

/// One-hot coefficients of degree 3 with `v` at index `i`.
fn one_hot(i: usize, v: f64) -> Vec<f64> {
    let mut c = vec![0.0; 16];
    c[i] = v;
    c
}

#[test]
fn quarter_and_half_turns_move_basis_functions_as_derived() {
    // Basis (INRIA): 1: -C1 y, 2: C1 z, 3: -C1 x; 4: xy, 5: -yz, 6: 2zz-xx-yy, 7: -xz, 8: xx-yy
    // (up to constants, C2[1] = C2[3]); 9: y(3xx-yy), ..., 15: x(xx-3yy) with C3[0] = C3[6].
    // The rotated function at e is the original at Rᵀe.
    let cases: [(Mat3, usize, Vec<f64>); 14] = [
        // Rz(90): Rᵀe = (y, -x, z). -C1 y -> C1 x = -(-C1 x).
        (rot_z(90.0), 1, one_hot(3, -1.0)),
        (rot_z(90.0), 3, one_hot(1, 1.0)),
        (rot_z(90.0), 2, one_hot(2, 1.0)),
        (rot_z(90.0), 4, one_hot(4, -1.0)),
        (rot_z(90.0), 5, one_hot(7, -1.0)),
        (rot_z(90.0), 7, one_hot(5, 1.0)),
        (rot_z(90.0), 8, one_hot(8, -1.0)),
        (rot_z(90.0), 9, one_hot(15, 1.0)),
        // Rz(180): Rᵀe = (-x, -y, z).
        (rot_z(180.0), 1, one_hot(1, -1.0)),
        (rot_z(180.0), 13, one_hot(13, -1.0)),
        // Rx(90): Rᵀe = (x, z, -y). C1 z -> -C1 y; -C1 y -> -C1 z.
        (rot_x(90.0), 2, one_hot(1, 1.0)),
        (rot_x(90.0), 1, one_hot(2, -1.0)),
        // Rx(180): Rᵀe = (x, -y, -z). xy -> -xy, yz -> yz.
        (rot_x(180.0), 4, one_hot(4, -1.0)),
        (rot_x(180.0), 5, one_hot(5, 1.0)),
    ];
    for (r, from, want) in cases {
        let got = rotate_coeffs(&r, &one_hot(from, 1.0));
        let e = max_diff(&got, &want);
        assert!(e < 1e-12, "coefficient {from}: got {got:?}, want {want:?}");
    }
}

#[test]
fn rotation_then_inverse_is_identity_and_rotations_compose() {
    let mut rng = common::rng(2);
    let (mut round, mut comp): (f64, f64) = (0.0, 0.0);
    for _ in 0..20 {
        let (r1, r2) = (random_rotation(&mut rng), random_rotation(&mut rng));
        let c: Vec<f64> = (0..16).map(|_| rng.gen_range(-1.0..1.0)).collect();
        let back = rotate_coeffs(&tr(&r1), &rotate_coeffs(&r1, &c));
        round = round.max(max_diff(&back, &c));
        let twice = rotate_coeffs(&r2, &rotate_coeffs(&r1, &c));
        let once = rotate_coeffs(&mul(&r2, &r1), &c);
        comp = comp.max(max_diff(&twice, &once));
    }
    println!("round trip {round:.2e}, composition {comp:.2e}");
    assert!(round < 1e-10 && comp < 1e-10, "{round} {comp}");
    // The matrices of a rotation are orthogonal (the basis is orthonormal).
    let m = ShRotation::new(&random_rotation(&mut rng), 3);
    for l in 1..=3usize {
        let (b, n) = (m.band(l as u32), 2 * l + 1);
        for i in 0..n {
            for j in 0..n {
                let dot: f64 = (0..n).map(|k| b[i * n + k] * b[j * n + k]).sum();
                assert!((dot - (i == j) as u8 as f64).abs() < 1e-10);
            }
        }
    }
}

fn cloud(seed: u64, n: usize, degree: u32) -> Gaussians {
    let mut rng = common::rng(seed);
    Gaussians::random(
        &mut rng,
        n,
        [-0.5, -0.5, 0.0],
        [0.5, 0.5, 1.0],
        0.04,
        degree,
    )
}

#[test]
fn transformed_covariance_is_m_sigma_mt() {
    let g = cloud(3, 500, 1);
    let placements = [
        ([1.7, 0.6, 1.2], 33.0),
        ([2.0, 2.0, 2.0], -120.0),
        ([-1.0, 0.8, 0.5], 75.0),
        ([1.0, 1.0, 1.0], 0.0),
    ];
    for (scale, yaw) in placements {
        let out = transform(&g, yaw, scale, [0.3, -2.0, 0.1]);
        let m: Mat3 = [0, 1, 2].map(|i| [0, 1, 2].map(|j| rot_z(yaw)[i][j] * scale[j]));
        let mut worst: f64 = 0.0;
        for i in 0..g.len() {
            let want = mul(&mul(&m, &covariance(&g, i).expect("valid")), &tr(&m));
            let got = covariance(&out, i).expect("valid");
            let norm = want.iter().flatten().map(|v| v * v).sum::<f64>().sqrt();
            let e = (0..9)
                .map(|k| (got[k / 3][k % 3] - want[k / 3][k % 3]).abs())
                .fold(0.0, f64::max);
            worst = worst.max(e / norm);
            let x = g.means[i].map(f64::from);
            let mx = apply(&m, x);
            for a in 0..3 {
                let p = mx[a] + [0.3, -2.0, 0.1][a];
                assert!((out.means[i][a] as f64 - p).abs() < 1e-5);
            }
        }
        println!("scale {scale:?} yaw {yaw}: max relative covariance error {worst:.2e}");
        assert!(worst < 1e-5, "{worst}");
    }
}

#[test]
fn pad_and_compose_merge_degrees() {
    let a = cloud(4, 10, 1);
    let b = cloud(5, 7, 3);
    let p = pad_sh(&a, 3);
    assert_eq!(p.sh.len(), 10 * 16 * 3);
    assert_eq!(&p.sh[..12], &a.sh[..12]);
    assert!(p.sh[12..48].iter().all(|&v| v == 0.0));
    let c = compose(&[(&a, Placement::IDENTITY), (&b, Placement::IDENTITY)]);
    c.check().expect("consistent");
    assert_eq!((c.len(), c.sh_degree), (17, 3));
    assert_eq!(&c.sh[10 * 48..], &b.sh[..]);
}

/// Largest-to-smallest eigenpairs of a symmetric matrix in closed form (trigonometric
/// eigenvalues, eigenvectors from cross products): independent of the library's Jacobi refit.
fn closed_form_eigen(a: &Mat3) -> ([f64; 3], Mat3) {
    let cross = |u: [f64; 3], v: [f64; 3]| {
        [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ]
    };
    let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let normed = |u: [f64; 3]| u.map(|x| x / dot(u, u).sqrt());
    let q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    let p1 = a[0][1].powi(2) + a[0][2].powi(2) + a[1][2].powi(2);
    let p2 = (0..3).map(|i| (a[i][i] - q).powi(2)).sum::<f64>() + 2.0 * p1;
    let p = (p2 / 6.0).sqrt();
    let b: Mat3 = [0, 1, 2].map(|i| [0, 1, 2].map(|j| (a[i][j] - q * (i == j) as u8 as f64) / p));
    let det = dot(b[0], cross(b[1], b[2]));
    let phi = (det / 2.0).clamp(-1.0, 1.0).acos() / 3.0;
    let l1 = q + 2.0 * p * phi.cos();
    let l3 = q + 2.0 * p * (phi + 2.0 * std::f64::consts::PI / 3.0).cos();
    let l2 = 3.0 * q - l1 - l3;
    let vec_of = |l: f64| {
        let r: Mat3 = [0, 1, 2].map(|i| [0, 1, 2].map(|j| a[i][j] - l * (i == j) as u8 as f64));
        let cands = [cross(r[0], r[1]), cross(r[0], r[2]), cross(r[1], r[2])];
        let best = cands
            .into_iter()
            .max_by(|u, v| dot(*u, *u).total_cmp(&dot(*v, *v)))
            .expect("three candidates");
        normed(best)
    };
    let v1 = vec_of(l1);
    let v2 = vec_of(l2);
    let v2 = normed([0, 1, 2].map(|i| v2[i] - dot(v1, v2) * v1[i]));
    let v3 = cross(v1, v2);
    ([l1, l2, l3], [0, 1, 2].map(|i| [v1[i], v2[i], v3[i]]))
}

/// `g` under `world = M p + t`, with each covariance `M Σ Mᵀ` factored by [`closed_form_eigen`].
fn explicitly_transformed(g: &Gaussians, m: &Mat3, t: [f64; 3]) -> Gaussians {
    let mut out = g.clone();
    for i in 0..g.len() {
        let x = apply(m, g.means[i].map(f64::from));
        out.means[i] = [0, 1, 2].map(|a| (x[a] + t[a]) as f32);
        let sigma = mul(&mul(m, &covariance(g, i).expect("valid")), &tr(m));
        let (l, v) = closed_form_eigen(&sigma);
        out.rotations[i] = mat_to_quat(&v).map(|v| v as f32);
        out.scales[i] = l.map(|l| (0.5 * l.ln()) as f32);
    }
    out
}

/// `cam` as seen from the object frame of `world = s O p + t` (O orthogonal): position
/// `Oᵀ (c - t) / s`, axes `Oᵀ` times the world axes (left-handed when O mirrors; the renderer only
/// needs an orthogonal camera matrix).
fn camera_in_object_frame(cam: &Camera, o: &Mat3, s: f64, t: [f64; 3]) -> Camera {
    let ot = tr(o);
    let c = [0, 1, 2].map(|i| cam.position[i] - t[i]);
    Camera {
        position: apply(&ot, c).map(|v| v / s),
        rotation: mul(&ot, &cam.rotation),
        ..cam.clone()
    }
}

fn world_camera(t: [f64; 3]) -> Camera {
    let target = [t[0], t[1], t[2] + 0.5];
    let eye = [t[0] + 1.6, t[1] - 1.9, t[2] + 1.3];
    Camera::look_at(eye, target, [0.0, 0.0, 1.0], 128, 128, 50f64.to_radians())
}

#[test]
fn transformed_instances_render_as_the_equivalent_views() {
    let ctx = common::gpu();
    let raster = Rasterizer::new(&ctx).expect("rasterizer");
    let bg = [0.1, 0.2, 0.3];
    let render = |g: &Gaussians, cam: &Camera| {
        let gg = GpuGaussians::upload(&ctx, g).expect("upload");
        let out = raster.forward(&ctx, &gg, cam, bg).expect("forward");
        out.read().expect("read").color
    };
    let t = [1.2, -0.7, 0.3];
    let cam = world_camera(t);
    let g3 = cloud(6, 3000, 3);

    // (a) rigid, SH degree 3: the moved object from the camera = the object from the camera
    // moved by the inverse transform.
    let yaw = 37.0;
    let moved = render(&transform(&g3, yaw, [1.0; 3], t), &cam);
    let original = render(&g3, &camera_in_object_frame(&cam, &rot_z(yaw), 1.0, t));
    let rigid = psnr(&moved, &original);
    // Leaving the SH unrotated is visible: the test sees view-dependent colour.
    let mut unrotated = transform(&g3, yaw, [1.0; 3], t);
    unrotated.sh = g3.sh.clone();
    let without_sh = psnr(&render(&unrotated, &cam), &original);

    // (b) non-uniform scale, SH degree 0: the refit against explicit covariances.
    let g0 = cloud(7, 3000, 0);
    let (yaw_b, scale_b) = (-25.0, [1.6, 0.7, 1.2]);
    let m: Mat3 = [0, 1, 2].map(|i| [0, 1, 2].map(|j| rot_z(yaw_b)[i][j] * scale_b[j]));
    let refit = render(&transform(&g0, yaw_b, scale_b, t), &cam);
    let explicit = render(&explicitly_transformed(&g0, &m, t), &cam);
    let nonuniform = psnr(&refit, &explicit);
    // Adding log(scale) to the object-frame log-scales (exact only for uniform scale) is visible.
    let mut naive = transform(&g0, yaw_b, [1.0; 3], t);
    naive.means = explicitly_transformed(&g0, &m, t).means;
    for (s, g) in naive.scales.iter_mut().zip(&g0.scales) {
        *s = [0, 1, 2].map(|a| g[a] + scale_b[a].ln() as f32);
    }
    let naive_scale = psnr(&render(&naive, &cam), &explicit);

    // (c) uniform scale s, SH degree 3: the inverse similarity moves the camera to (c - t)/s.
    let (yaw_c, s) = (140.0, 1.8);
    let scaled = render(&transform(&g3, yaw_c, [s; 3], t), &cam);
    let original_c = render(&g3, &camera_in_object_frame(&cam, &rot_z(yaw_c), s, t));
    let similar = psnr(&scaled, &original_c);

    // (d) mirrored (scale -1 along x), SH degree 3: an orthogonal map, so also exact.
    let yaw_d = 60.0;
    let mirror = mul(
        &rot_z(yaw_d),
        &[[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    );
    let mirrored = render(&transform(&g3, yaw_d, [-1.0, 1.0, 1.0], t), &cam);
    let original_d = render(&g3, &camera_in_object_frame(&cam, &mirror, 1.0, t));
    let mirrored_psnr = psnr(&mirrored, &original_d);

    // The views are not trivially equal: the untransformed object differs.
    let unmoved = psnr(&render(&g3, &cam), &moved);
    println!(
        "PSNR rigid {rigid:.1} dB, non-uniform {nonuniform:.1} dB, uniform scale {similar:.1} dB, \
         mirrored {mirrored_psnr:.1} dB (untransformed {unmoved:.1} dB, SH unrotated {without_sh:.1} dB, log-scale shift \
         {naive_scale:.1} dB)"
    );
    assert!(rigid >= 50.0 && nonuniform >= 50.0 && similar >= 50.0 && mirrored_psnr >= 50.0);
    assert!(unmoved < 30.0 && without_sh < 45.0 && naive_scale < 45.0);
}

fn sample_scene() -> SceneFile {
    serde_json::from_str(
        r#"{"version": 1, "prompt": "a cozy living room", "seed": 0, "scene_type": "indoor",
   "room": {"size": [5.0, 4.0, 2.8]}, "prior": {"kind": "shape", "models": null},
   "objects": [{"id": "sofa1", "category": "sofa", "ply": "objects/sofa.ply",
                "position": [0.0, -1.5, 0.0], "yaw": 0.0, "scale": [1.0, 1.0, 1.0]},
               {"id": "sofa2", "category": "sofa", "ply": "objects/sofa.ply",
                "position": [1.0, 1.5, 0.0], "yaw": 180.0, "scale": [2.0, 2.0, 2.0]}],
   "environment": {"kind": "cuboid", "ply": "environment.ply"},
   "stages": [{"name": "objects", "done": true}, {"name": "environment", "done": true}],
   "timeline": null, "future_key": {"kept": [1, 2]}}"#,
    )
    .expect("the contract's example parses")
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("dreamscene-compose-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

#[test]
fn scene_json_round_trips_atomically_and_keeps_unknown_keys() {
    let dir = temp_dir("roundtrip");
    let mut scene = sample_scene();
    scene.timeline = serde_json::from_str(
        r#"{"duration": 3.0, "fps": 30, "tracks": [{"id": "sofa2", "interpolation": "linear",
            "keys": [{"t": 0.0, "position": [1, 1.5, 0], "yaw": 0.0, "scale": [1, 1, 1]},
                     {"t": 3.0, "position": [2, 1.5, 0], "yaw": 90.0, "scale": [1, 1, 1]}]}]}"#,
    )
    .expect("the contract's timeline parses");
    write_scene(&dir, &scene).expect("write");
    let names: Vec<String> = std::fs::read_dir(&dir)
        .expect("list")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["scene.json"], "no temporary file left behind");
    let back = read_scene(&dir).expect("read");
    assert_eq!(back, scene);
    assert_eq!(back.extra["future_key"]["kept"][1], 2);
    let mut still = back.clone();
    still.timeline = None;
    write_scene(&dir, &still).expect("write");
    let text = std::fs::read_to_string(dir.join("scene.json")).expect("text");
    assert!(text.contains("\"timeline\": null"), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn wrong_or_missing_scene_json_gets_a_one_line_reason() {
    let dir = temp_dir("wrong");
    let e = read_scene(&dir).expect_err("missing").to_string();
    assert!(
        e.contains("scene.json") && e.contains("not a scene directory"),
        "{e}"
    );
    let layout = r#"{"scene_type": "indoor", "room": {"size": [5.0, 4.0, 2.8]}, "seed": 7,
        "objects": [{"id": "sofa1", "category": "sofa", "size": [2.0, 1.0, 0.8],
        "position": [0.0, -1.5, 0.0], "yaw": 0.0, "anchor": "SIDE", "placed_by": "constraint"}],
        "unsatisfied": []}"#;
    std::fs::write(dir.join("layout.json"), layout).expect("write");
    std::fs::write(dir.join("scene.json"), layout).expect("write");
    for path in [dir.join("layout.json"), dir.clone()] {
        let e = read_scene(&path).expect_err("a layout").to_string();
        assert!(e.contains("layout.json") && !e.contains('\n'), "{e}");
    }
    std::fs::write(dir.join("scene.json"), "{\"version\": 2}").expect("write");
    let e = read_scene(&dir).expect_err("bad").to_string();
    assert!(e.contains("not a valid scene.json"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn compose_scene_places_instances_and_appends_the_environment() {
    let dir = temp_dir("compose");
    std::fs::create_dir_all(dir.join("objects")).expect("mkdir");
    let mut sofa = cloud(8, 20, 1);
    sofa.means[0] = [0.5, 0.25, 0.0];
    write_ply(&dir.join("objects/sofa.ply"), &sofa).expect("sofa");
    let env = cloud(9, 30, 0);
    write_ply(&dir.join("environment.ply"), &env).expect("env");
    let mut scene = sample_scene();
    let g = compose_scene(&dir, &scene).expect("compose");
    assert_eq!((g.len(), g.sh_degree), (20 + 20 + 30, 1));
    // sofa1 at yaw 0: (0.5, 0.25, 0) + (0, -1.5, 0); sofa2 at yaw 180, scale 2: (-1, -0.5, 0) + (1, 1.5, 0).
    let close = |a: [f32; 3], b: [f32; 3]| (0..3).all(|i| (a[i] - b[i]).abs() < 1e-5);
    assert!(close(g.means[0], [0.5, -1.25, 0.0]), "{:?}", g.means[0]);
    assert!(close(g.means[20], [0.0, 1.0, 0.0]), "{:?}", g.means[20]);
    assert_eq!(&g.means[40..], &env.means[..]);
    assert!(g.sh[40 * 12..]
        .chunks(12)
        .all(|c| c[3..].iter().all(|&v| v == 0.0)));
    // A pending environment stage leaves the environment out; a missing PLY is named.
    scene.stages[1].done = false;
    assert_eq!(compose_scene(&dir, &scene).expect("compose").len(), 40);
    scene.objects[1].ply = "objects/chair.ply".into();
    let e = compose_scene(&dir, &scene)
        .expect_err("missing")
        .to_string();
    assert!(e.contains("chair.ply") && e.contains("not found"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}
