//! PLY and cameras.json round trips and clear errors on malformed files.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::{read_cameras, write_cameras, Camera};
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::Gaussians;

#[test]
fn ply_round_trips_every_sh_degree() {
    let dir = tempdir("ply");
    let mut rng = common::rng(20);
    for deg in 0..=3 {
        let g = Gaussians::random(&mut rng, 37, [-1.0; 3], [1.0; 3], 0.1, deg);
        let p = dir.join(format!("d{deg}.ply"));
        write_ply(&p, &g).unwrap();
        assert_eq!(read_ply(&p).unwrap(), g, "degree {deg}");
    }
}

#[test]
fn ply_f_rest_is_channel_major() {
    let dir = tempdir("plyorder");
    let mut g = Gaussians {
        sh_degree: 1,
        ..Default::default()
    };
    g.means.push([0.0; 3]);
    g.scales.push([0.0; 3]);
    g.rotations.push([1.0, 0.0, 0.0, 0.0]);
    g.opacities.push(0.0);
    // [coeff][rgb]: value = 10 * coeff + channel
    for c in 0..4 {
        for ch in 0..3 {
            g.sh.push((10 * c + ch) as f32);
        }
    }
    let p = dir.join("o.ply");
    write_ply(&p, &g).unwrap();
    let bytes = std::fs::read(&p).unwrap();
    let body = &bytes[bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .unwrap()
        + 11..];
    let f = |i: usize| f32::from_le_bytes(body[4 * i..4 * i + 4].try_into().unwrap());
    // x y z nx ny nz f_dc_0..2 then f_rest_0.. = red coefficients 1..3, then green, then blue.
    assert_eq!([f(6), f(7), f(8)], [0.0, 1.0, 2.0]);
    assert_eq!(
        (9..18).map(f).collect::<Vec<_>>(),
        vec![10.0, 20.0, 30.0, 11.0, 21.0, 31.0, 12.0, 22.0, 32.0]
    );
}

#[test]
fn malformed_ply_gets_a_one_line_error_naming_the_file() {
    let dir = tempdir("plybad");
    let mut rng = common::rng(21);
    let g = Gaussians::random(&mut rng, 10, [-1.0; 3], [1.0; 3], 0.1, 0);
    let good = dir.join("good.ply");
    write_ply(&good, &g).unwrap();
    let bytes = std::fs::read(&good).unwrap();
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("truncated.ply", bytes[..bytes.len() - 10].to_vec(), "truncated"),
        ("notply.ply", b"hello\n".to_vec(), "not a PLY"),
        ("cut_header.ply", String::from_utf8_lossy(&bytes[..40]).replace("binary_little_endian", "ascii").into_bytes(), "before `end_header`"),
        ("noheader.ply", b"ply\nformat binary_little_endian 1.0\n".to_vec(), "end_header"),
        (
            "noopacity.ply",
            b"ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n".to_vec(),
            "missing property",
        ),
    ];
    for (name, data, want) in cases {
        let p = dir.join(name);
        std::fs::write(&p, data).unwrap();
        let e = read_ply(&p).unwrap_err().to_string();
        assert!(e.contains(name) && e.contains(want), "{name}: `{e}`");
        assert!(!e.contains('\n'), "{name}: error spans lines: `{e}`");
    }
}

#[test]
fn cameras_json_round_trips_and_rejects_bad_files() {
    let dir = tempdir("cams");
    let mut c = Camera::look_at([1.0, 2.0, 3.0], [0.0; 3], [0.0, 0.0, 1.0], 64, 48, 0.8);
    c.img_name = "a".into();
    let p = dir.join("cameras.json");
    write_cameras(&p, &[c.clone()]).unwrap();
    assert_eq!(read_cameras(&p).unwrap(), vec![c]);
    for (name, text) in [
        ("empty.json", "[]"),
        ("junk.json", "{not json"),
        (
            "zero.json",
            r#"[{"id":0,"img_name":"a","width":0,"height":4,"position":[0,0,0],"rotation":[[1,0,0],[0,1,0],[0,0,1]],"fx":1,"fy":1}]"#,
        ),
    ] {
        let q = dir.join(name);
        std::fs::write(&q, text).unwrap();
        let e = read_cameras(&q).unwrap_err().to_string();
        assert!(e.contains(name), "{name}: `{e}`");
    }
}

fn tempdir(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("dreamscene-test-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `dreamscene fit` on `<dir>/images` and `<dir>/cameras.json`, writing `<dir>/model.ply`.
fn fit_cli(dir: &std::path::Path, extra: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(["fit", "--images"])
        .arg(dir.join("images"))
        .arg("--cameras")
        .arg(dir.join("cameras.json"))
        .arg("--out")
        .arg(dir.join("model.ply"))
        .args(extra)
        .output()
        .unwrap()
}

/// `fit` refuses bad training data before touching the device: a missing image or one whose
/// size differs from its camera gets one line naming the file.
#[test]
fn fit_names_missing_or_mis_sized_images() {
    let dir = std::env::temp_dir().join(format!("dreamscene-fit-{}", std::process::id()));
    let images = dir.join("images");
    std::fs::create_dir_all(&images).unwrap();
    let mut cam = Camera::look_at([0.0, 0.0, -3.0], [0.0; 3], [0.0, -1.0, 0.0], 32, 24, 0.8);
    cam.img_name = "view0".into();
    write_cameras(&dir.join("cameras.json"), &[cam]).unwrap();
    let run = || {
        let out = fit_cli(&dir, &["--iterations", "1"]);
        assert!(!out.status.success());
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        err
    };
    let err = run();
    assert!(
        err.contains("no image for camera 0") && err.contains("view0"),
        "{err}"
    );
    image::RgbImage::new(30, 24)
        .save(images.join("view0.png"))
        .unwrap();
    let err = run();
    assert!(
        err.contains("view0.png") && err.contains("30x24") && err.contains("32x24"),
        "{err}"
    );
    assert!(
        !dir.join("model.ply").exists(),
        "nothing written on bad input"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `fit --resume` continues from the PLY and its optimiser state, and says what is missing.
#[test]
fn fit_resumes_from_its_checkpoint() {
    let dir = tempdir("resume");
    let images = dir.join("images");
    std::fs::create_dir_all(&images).unwrap();
    let mut cams = vec![];
    for i in 0..3 {
        let a = i as f64 * 0.4;
        let mut cam = Camera::look_at(
            [3.0 * a.sin(), 0.0, -3.0 * a.cos()],
            [0.0; 3],
            [0.0, -1.0, 0.0],
            32,
            24,
            0.8,
        );
        cam.id = i;
        cam.img_name = format!("v{i}");
        image::RgbImage::from_fn(32, 24, |x, y| {
            image::Rgb([(x * 8) as u8, (y * 10) as u8, 90])
        })
        .save(images.join(format!("v{i}.png")))
        .unwrap();
        cams.push(cam);
    }
    write_cameras(&dir.join("cameras.json"), &cams).unwrap();
    let run = |extra: &[&str]| {
        let args = [
            &["--init-gaussians", "200", "--checkpoint-every", "2"],
            extra,
        ]
        .concat();
        let out = fit_cli(&dir, &args);
        (
            out.status.success(),
            format!(
                "{}{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            ),
        )
    };
    let (ok, out) = run(&["--iterations", "4", "--resume"]);
    assert!(!ok && out.contains("--resume needs"), "{out}");
    let (ok, out) = run(&["--iterations", "4"]);
    assert!(ok, "{out}");
    assert!(dir.join("model.ply.state").is_file());
    let (ok, out) = run(&["--iterations", "4", "--resume"]);
    assert!(ok && out.contains("already at iteration 4"), "{out}");
    // A different --iterations is refused: the schedules are fractions of the run.
    let (ok, out) = run(&["--iterations", "6", "--resume"]);
    assert!(
        !ok && out.contains("for 4 iterations")
            && out.contains("asks for 6")
            && out.contains("--init"),
        "{out}"
    );
    // A fit stopped half-way (its state and PLY at iteration 2 of 4) continues to the end.
    {
        use dreamscene::splat::train::{load_views, random_init, FitConfig, Trainer};
        let ctx = common::gpu();
        let views = load_views(&images, &cams, [0.0; 3]).unwrap();
        let config = FitConfig {
            iterations: 4,
            ..Default::default()
        };
        let mut t = Trainer::new(&ctx, &random_init(&cams, 200, 3, 0), views, config).unwrap();
        t.step().unwrap();
        t.step().unwrap();
        write_ply(&dir.join("model.ply"), &t.gaussians().unwrap()).unwrap();
        t.save_state(&dir.join("model.ply.state")).unwrap();
    }
    let (ok, out) = run(&["--iterations", "4", "--resume"]);
    assert!(ok && out.contains("resuming at iteration 2"), "{out}");
    // A state that belongs to another PLY is refused with the reason.
    std::fs::copy(dir.join("model.ply.state"), dir.join("keep.state")).unwrap();
    let (ok, out) = run(&["--iterations", "2"]);
    assert!(ok, "{out}");
    std::fs::copy(dir.join("keep.state"), dir.join("model.ply.state")).unwrap();
    let (ok, out) = run(&["--iterations", "4", "--resume"]);
    assert!(!ok && out.contains("model.ply.state"), "{out}");
    std::fs::remove_dir_all(&dir).ok();
}
