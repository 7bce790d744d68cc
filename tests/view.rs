//! `dreamscene view` in a real browser: Debian's headless chromium, driven by playwright-core
//! (viewer/tests/screenshot.mjs), opens the page on a red cluster at +x and a blue one at −x,
//! waits for the page's rendered-frame signal and takes a screenshot, whose left and right
//! halves must be red and blue (the start view looks from +y, so +x is on the left); the same
//! PLY with per-Gaussian labels (`instance_id`, `semantic_id`) gives the same picture. Also: a
//! busy port and a viewer without its npm packages are one-line errors, and SIGINT (Ctrl-C)
//! stops the server with exit status 0. The screenshot script fails if the page asks for any URL
//! outside the server under test.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-view-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Starts `view` on a free port and returns the process and its URL.
fn serve(ply: &Path, port: &str) -> (Child, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(["view", ply.to_str().unwrap(), "--port", port])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    let mut line = String::new();
    BufReader::new(child.stdout.as_mut().unwrap())
        .read_line(&mut line)
        .unwrap();
    let url = line
        .split_whitespace()
        .find(|w| w.starts_with("http://127.0.0.1:"))
        .unwrap_or_else(|| panic!("no URL in {line:?}"))
        .to_string();
    (child, url)
}

fn interrupt(child: &mut Child) -> std::process::ExitStatus {
    // SAFETY: kill(2) on the pid of a child this test started and has not reaped.
    let r = unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGINT) };
    assert_eq!(r, 0, "kill(SIGINT) succeeded");
    child.wait().unwrap()
}

/// Serves `ply` with `view` and takes the page's screenshot (320x240) in headless chromium.
fn screenshot(ply: &Path, shot: &Path) -> image::RgbImage {
    let (mut child, url) = serve(ply, "0");
    let viewer = Path::new(env!("CARGO_MANIFEST_DIR")).join("viewer");
    let o = Command::new("node")
        .current_dir(&viewer)
        .arg("tests/screenshot.mjs")
        .arg(&url)
        .arg(shot)
        .arg("320x240")
        .output()
        .expect("node runs (scripts/setup.sh installs it)");
    let status = interrupt(&mut child);
    assert!(
        o.status.success(),
        "browser: {}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(status.success(), "view exited with {status:?} on SIGINT");
    let img = image::open(shot).unwrap().to_rgb8();
    assert_eq!(
        img.dimensions(),
        (320, 240),
        "the screenshot has the size asked for"
    );
    img
}

#[test]
fn browser_shows_red_on_the_left_and_blue_on_the_right_labelled_or_not() {
    let d = tmp("browser");
    let ply = d.join("clusters.ply");
    common::two_clusters(&ply, 3000, 0.15, 5);
    let img = screenshot(&ply, &d.join("shot.png"));
    // Count strongly red and strongly blue pixels in the left and right halves (rows 40-200,
    // clear of the page's text overlays).
    let (mut red, mut blue) = ([0usize; 2], [0usize; 2]);
    for y in 40..200 {
        for x in 0..320 {
            let p = img.get_pixel(x, y).0.map(|v| v as i32);
            let half = (x >= 160) as usize;
            if p[0] > 150 && p[1] < 80 && p[2] < 80 {
                red[half] += 1;
            }
            if p[2] > 150 && p[0] < 80 && p[1] < 80 {
                blue[half] += 1;
            }
        }
    }
    eprintln!("red left/right {red:?}, blue left/right {blue:?}");
    assert!(red[0] > 2000 && blue[1] > 2000, "red {red:?} blue {blue:?}");
    assert!(
        red[1] < red[0] / 10 && blue[0] < blue[1] / 10,
        "red {red:?} blue {blue:?}"
    );

    // The same Gaussians with per-Gaussian labels (instance_id, semantic_id after the INRIA
    // properties, as scene.ply has them) look the same in the viewer.
    let g = dreamscene::splat::ply::read_ply(&ply).unwrap();
    let n = g.len();
    let labels = dreamscene::splat::ply::Labels {
        instance: (0..n).map(|i| if i < n / 2 { 1 } else { 2 }).collect(),
        semantic: (0..n).map(|i| if i < n / 2 { 1 } else { 2 }).collect(),
    };
    let labelled = d.join("labelled.ply");
    dreamscene::splat::ply::write_ply_labelled(&labelled, &g, Some(&labels)).unwrap();
    assert!(dreamscene::splat::ply::read_ply_labelled(&labelled)
        .unwrap()
        .1
        .is_some());
    let other = screenshot(&labelled, &d.join("labelled.png"));
    let diff: f64 = img
        .as_raw()
        .iter()
        .zip(other.as_raw())
        .map(|(a, b)| (f64::from(*a) - f64::from(*b)).abs())
        .sum::<f64>()
        / img.as_raw().len() as f64;
    eprintln!("labelled vs plain: mean difference {diff:.3}/255");
    assert!(
        diff < 2.0,
        "the labelled PLY looks different: {diff:.3}/255"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn busy_port_and_missing_packages_are_clear_errors() {
    let d = tmp("errors");
    let ply = d.join("clusters.ply");
    common::two_clusters(&ply, 3000, 0.15, 5);
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port().to_string();
    let o = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(["view", ply.to_str().unwrap(), "--port", &port])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        err.contains(&format!("port {port} on 127.0.0.1 is in use")),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");

    let bare = d.join("viewer");
    std::fs::create_dir_all(&bare).unwrap();
    std::fs::write(bare.join("index.html"), "<!doctype html>").unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .env("DREAMSCENE_VIEWER_DIR", &bare)
        .args(["view", ply.to_str().unwrap(), "--port", "0"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(err.contains("run scripts/setup.sh"), "{err}");
    drop(listener);
    std::fs::remove_dir_all(&d).ok();
}
