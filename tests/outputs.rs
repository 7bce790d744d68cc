//! Output paths: devices are written through and never replaced, links are followed, a full
//! disk leaves no temporary file and names the path; `render` creates img_name sub-directories,
//! refuses bad input before writing and says what it wrote; `fit` checks it can write before it
//! starts, prints progress off a terminal and a summary; `doctor` gives a verdict per component.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::camera::{write_cameras, Camera};
use dreamscene::splat::ply::write_ply;
use dreamscene::splat::Gaussians;
use dreamscene::util::write_atomic;
use std::os::unix::fs::FileTypeExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn tempdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("dreamscene-outputs-{tag}-{}", std::process::id()));
    std::fs::remove_dir_all(&d).ok();
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_dreamscene"))
}

fn text(o: &Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn tmp_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = vec![];
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(tmp_files(&p));
        } else if p.to_string_lossy().ends_with(".tmp") {
            out.push(p);
        }
    }
    out
}

#[test]
fn devices_are_written_through_and_links_followed() {
    let dir = tempdir("devices");
    // /dev/full: the error names the path and the device stays a device.
    let e = write_atomic(Path::new("/dev/full"), b"data").unwrap_err();
    assert!(e.to_string().contains("/dev/full"), "{e}");
    assert_eq!(e.kind(), std::io::ErrorKind::StorageFull, "{e}");
    let meta = std::fs::metadata("/dev/full").unwrap();
    assert!(meta.file_type().is_char_device());
    write_atomic(Path::new("/dev/null"), b"data").unwrap();
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // A link is followed: the target changes, the link stays a link.
    let target = dir.join("target.json");
    std::fs::write(&target, "old").unwrap();
    let link = dir.join("link.json");
    std::os::unix::fs::symlink("target.json", &link).unwrap();
    write_atomic(&link, b"new").unwrap();
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "new");
    // A dangling link creates the file it names.
    let dangling = dir.join("dangling.json");
    std::os::unix::fs::symlink("made.json", &dangling).unwrap();
    write_atomic(&dangling, b"made").unwrap();
    assert_eq!(
        std::fs::read_to_string(dir.join("made.json")).unwrap(),
        "made"
    );
    // A directory is refused, not replaced.
    let e = write_atomic(&dir, b"x").unwrap_err();
    assert!(e.to_string().contains("directory"), "{e}");
    assert!(dir.is_dir());
    assert!(tmp_files(&dir).is_empty());
    std::fs::remove_dir_all(&dir).ok();
}

/// A full disk (here a file-size limit, which fails the write the same way) leaves no `*.tmp`
/// and names the file.
#[test]
fn a_failed_write_leaves_no_temporary_file_and_names_the_path() {
    let dir = tempdir("full");
    let out = Command::new("sh")
        .arg("-c")
        // Ignore SIGXFSZ so the write fails with EFBIG instead of killing the process.
        .arg(format!(
            "trap '' XFSZ; ulimit -f 4; exec \"{}\" demo --gaussians 100 --out \"{}\"",
            env!("CARGO_BIN_EXE_dreamscene"),
            dir.display()
        ))
        .output()
        .unwrap();
    let (_, err) = text(&out);
    assert!(!out.status.success(), "{err}");
    assert!(
        err.contains("scene.ply") && err.starts_with("error:"),
        "{err}"
    );
    assert!(tmp_files(&dir).is_empty(), "{:?}", tmp_files(&dir));
    assert!(!dir.join("scene.ply").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn layout_writes_to_stdout() {
    let spec = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/living_room.json");
    let out = bin()
        .args(["layout", "--out", "/dev/stdout", "--spec"])
        .arg(&spec)
        .output()
        .unwrap();
    let (stdout, err) = text(&out);
    assert!(out.status.success(), "{err}");
    let l = dreamscene::plan::spec::Layout::parse(stdout.as_bytes()).unwrap();
    assert!(!l.objects.is_empty());
}

/// A few Gaussians in front of three 16x16 cameras, one of them in a sub-directory.
fn scene(dir: &Path) -> (PathBuf, PathBuf) {
    let g = Gaussians::random(&mut common::rng(60), 50, [-0.5; 3], [0.5; 3], 0.1, 0);
    let ply = dir.join("s.ply");
    write_ply(&ply, &g).unwrap();
    let cams: Vec<Camera> = ["front", "sub/dir/side", "top"]
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let a = i as f64 * 0.7;
            let mut c = Camera::look_at(
                [3.0 * a.sin(), -3.0 * a.cos(), 1.0],
                [0.0; 3],
                [0.0, 0.0, 1.0],
                16,
                16,
                0.8,
            );
            c.id = i as u32;
            c.img_name = name.to_string();
            c
        })
        .collect();
    let cameras = dir.join("cameras.json");
    write_cameras(&cameras, &cams).unwrap();
    (ply, cameras)
}

fn render(ply: &Path, cameras: &Path, out: &Path, extra: &[&str]) -> Output {
    bin()
        .arg("render")
        .arg("--ply")
        .arg(ply)
        .arg("--cameras")
        .arg(cameras)
        .arg("--out")
        .arg(out)
        .args(extra)
        .output()
        .unwrap()
}

#[test]
fn render_creates_sub_directories_reports_progress_and_what_it_wrote() {
    let _gpu = common::gpu();
    let dir = tempdir("render");
    let (ply, cameras) = scene(&dir);
    let out = dir.join("renders");
    let o = render(&ply, &cameras, &out, &[]);
    let (stdout, err) = text(&o);
    assert!(o.status.success(), "{err}");
    for name in ["front.png", "sub/dir/side.png", "top.png"] {
        let img = image::open(out.join(name)).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), (16, 16));
        assert!(img.pixels().any(|p| p.0 != [0, 0, 0]), "{name} is black");
    }
    assert!(
        stdout.contains("wrote 3 images") && stdout.contains("front.png"),
        "{stdout}"
    );
    // Off a terminal: one progress line per few percent, here per view.
    let lines: Vec<&str> = err.lines().filter(|l| l.contains("render ")).collect();
    assert_eq!(lines.len(), 3, "{err}");
    assert!(
        lines[2].contains("100%") && lines[2].contains("top.png"),
        "{err}"
    );
    assert!(tmp_files(&dir).is_empty());

    // NaN in the PLY: refused with the count and the first index; dropped on request.
    let mut g = dreamscene::splat::ply::read_ply(&ply).unwrap();
    g.opacities[7] = f32::NAN;
    let bad = dir.join("nan.ply");
    write_ply(&bad, &g).unwrap();
    let o = render(&bad, &cameras, &dir.join("nan"), &[]);
    let (_, err) = text(&o);
    assert!(
        !o.status.success() && err.contains("1 of 50") && err.contains("vertex 7"),
        "{err}"
    );
    assert!(!dir.join("nan").exists(), "nothing written on bad input");
    let o = render(&bad, &cameras, &dir.join("nan"), &["--drop-invalid"]);
    let (_, err) = text(&o);
    assert!(o.status.success() && err.contains("dropped 1"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

fn fit(dir: &Path, out: &Path, extra: &[&str]) -> Output {
    bin()
        .args(["fit", "--init-gaussians", "100", "--images"])
        .arg(dir.join("images"))
        .arg("--cameras")
        .arg(dir.join("cameras.json"))
        .arg("--out")
        .arg(out)
        .args(extra)
        .output()
        .unwrap()
}

/// Two 16x16 views whose images are stored as `.PNG` and `.JpG`.
fn fit_data(dir: &Path) {
    let images = dir.join("images");
    std::fs::create_dir_all(&images).unwrap();
    let mut cams = vec![];
    for (i, ext) in ["PNG", "JpG"].iter().enumerate() {
        let mut c = Camera::look_at(
            [i as f64, -3.0, 0.5],
            [0.0; 3],
            [0.0, 0.0, 1.0],
            16,
            16,
            0.8,
        );
        c.id = i as u32;
        c.img_name = format!("v{i}");
        let img = image::RgbImage::from_fn(16, 16, |x, y| {
            image::Rgb([(x * 16) as u8, (y * 16) as u8, 80])
        });
        let format = if i == 0 {
            image::ImageFormat::Png
        } else {
            image::ImageFormat::Jpeg
        };
        img.save_with_format(images.join(format!("v{i}.{ext}")), format)
            .unwrap();
        cams.push(c);
    }
    write_cameras(&dir.join("cameras.json"), &cams).unwrap();
}

#[test]
fn fit_checks_its_outputs_first_finds_upper_case_extensions_and_reports_progress() {
    let _gpu = common::gpu();
    let dir = tempdir("fit");
    fit_data(&dir);
    // The state file cannot be written (a directory holds its name): refused before any
    // iteration runs.
    let out = dir.join("model.ply");
    std::fs::create_dir_all(dir.join("model.ply.state")).unwrap();
    let o = fit(&dir, &out, &["--iterations", "20"]);
    let (_, err) = text(&o);
    assert!(
        !o.status.success() && err.contains("model.ply.state") && err.contains("cannot write"),
        "{err}"
    );
    assert!(!err.contains("fit iteration"), "it started: {err}");
    let o = fit(&dir, Path::new("/dev/full"), &["--iterations", "20"]);
    let (_, err) = text(&o);
    assert!(
        !o.status.success() && err.contains("/dev/full") && !err.contains("fit iteration"),
        "{err}"
    );
    std::fs::remove_dir(dir.join("model.ply.state")).unwrap();

    let o = fit(&dir, &out, &["--iterations", "20"]);
    let (stdout, err) = text(&o);
    assert!(o.status.success(), "{err}");
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.contains("fit iteration"))
        .collect();
    // A line every 5% of 20 iterations; each with the step, loss, PSNR, Gaussians and time left.
    assert_eq!(lines.len(), 20, "{err}");
    assert!(
        lines[19].contains("100%")
            && lines[19].contains("loss")
            && lines[19].contains("PSNR")
            && lines[19].contains("Gaussians")
            && lines[19].contains("left"),
        "{err}"
    );
    assert!(
        stdout.contains("wrote") && stdout.contains("PSNR") && stdout.contains(" dB"),
        "{stdout}"
    );
    assert!(out.is_file() && tmp_files(&dir).is_empty());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn doctor_checks_the_provider_without_models_and_judges_each_component() {
    let _gpu = common::gpu();
    // No ONNX Runtime: rendering is still ready and the command succeeds.
    let o = bin()
        .arg("doctor")
        .env("DREAMSCENE_ORT_LIB", "/nonexistent/libonnxruntime.so")
        .env_remove("DREAMSCENE_MODELS")
        .output()
        .unwrap();
    let (stdout, err) = text(&o);
    assert!(o.status.success(), "{stdout}{err}");
    assert!(stdout.contains("ready: rendering"), "{stdout}");
    assert!(stdout.contains("not ready: Stable Diffusion"), "{stdout}");
    // Asking for a provider checks it without models (CUDA: available where the library has
    // it; this machine's CPU-only library does not, which fails the command).
    let o = bin()
        .args(["doctor", "--provider", "cuda"])
        .env_remove("DREAMSCENE_MODELS")
        .output()
        .unwrap();
    let (stdout, err) = text(&o);
    let line = stdout
        .lines()
        .find(|l| l.contains("provider cuda:"))
        .unwrap_or_else(|| panic!("provider not checked: {stdout}"));
    assert_eq!(
        o.status.success(),
        line.ends_with("available"),
        "{stdout}{err}"
    );
    assert!(stdout.contains("ready: rendering"), "{stdout}");
}
