//! `dreamscene video` and `render --trajectory` through the binary, checked by an outside
//! decoder (Debian's ffprobe/ffmpeg, installed by scripts/setup.sh): frame count, size, frames
//! that differ along the path, the decoded first frame against the engine's own PNG of the same
//! camera, the depth video beside, the GIF, and one-line errors on bad input. The frame loop's
//! time-indexed source (the hook for 4D timelines) is driven directly.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;

use dreamscene::camera::Camera;
use dreamscene::export::video::{render_video, FrameSource, VideoOptions};
use dreamscene::splat::cloud::SH_C0;
use dreamscene::splat::Gaussians;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(args)
        .output()
        .expect("runs")
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-video-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// One cluster of `colour` around the origin.
fn cluster(colour: [f32; 3]) -> Gaussians {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
    let n = Normal::new(0.0f32, 0.2).unwrap();
    let mut g = Gaussians::default();
    for _ in 0..2000 {
        g.means
            .push([n.sample(&mut rng), n.sample(&mut rng), n.sample(&mut rng)]);
        g.scales.push([-3.0; 3]);
        g.rotations.push([1.0, 0.0, 0.0, 0.0]);
        g.opacities.push(4.0);
        g.sh.extend(colour.map(|c| ((c as f64 - 0.5) / SH_C0) as f32));
    }
    g
}

/// Red before `switch` seconds, blue from then on; records the times it was asked about.
struct Switching {
    red: Gaussians,
    blue: Gaussians,
    switch: f64,
    last: Option<bool>,
    asked: Vec<f64>,
}

impl FrameSource for Switching {
    fn gaussians_at(&mut self, t: f64) -> Option<&Gaussians> {
        self.asked.push(t);
        let blue = t >= self.switch;
        if self.last == Some(blue) {
            return None;
        }
        self.last = Some(blue);
        Some(if blue { &self.blue } else { &self.red })
    }
}

#[test]
fn frame_loop_asks_the_source_for_each_frame_time_and_draws_what_it_gives() {
    let ctx = common::gpu();
    let d = tmp("source");
    let out = d.join("switch.mp4");
    let cam = Camera::look_at([0.0, -3.0, 0.0], [0.0; 3], [0.0, 0.0, 1.0], 64, 48, 0.8);
    let cams = vec![cam; 6];
    let mut source = Switching {
        red: cluster([1.0, 0.0, 0.0]),
        blue: cluster([0.0, 0.0, 1.0]),
        switch: 0.25,
        last: None,
        asked: vec![],
    };
    let opts = VideoOptions {
        fps: 10.0,
        background: [0.0; 3],
        depth_far: 5.0,
    };
    let mut calls = 0;
    let report = render_video(
        &ctx,
        &mut source,
        &cams,
        &opts,
        &out,
        None,
        &mut |done, total| {
            calls += 1;
            assert_eq!((done, total), (calls, 6));
        },
    )
    .unwrap();
    assert_eq!((report.frames, report.width, report.height), (6, 64, 48));
    assert_eq!(source.asked, [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]);
    let frames = decode(&out, 64, 48);
    assert_eq!(frames.len(), 6);
    // The centre 8x8 pixels: red for t < 0.25, blue after.
    for (i, f) in frames.iter().enumerate() {
        let (mut r, mut b) = (0.0, 0.0);
        for y in 20..28 {
            for x in 28..36 {
                let p = &f[(y * 64 + x) * 3..][..3];
                r += p[0] as f64 / 64.0;
                b += p[2] as f64 / 64.0;
            }
        }
        let red = i < 3;
        assert!(
            if red {
                r > 150.0 && b < 60.0
            } else {
                b > 150.0 && r < 60.0
            },
            "frame {i}: mean red {r:.0}, blue {b:.0}"
        );
    }
    std::fs::remove_dir_all(&d).ok();
}

/// ffprobe's frame count and size of the first video stream.
fn probe(path: &Path) -> (usize, u32, u32) {
    let o = Command::new("ffprobe")
        .args(["-v", "error", "-count_frames", "-select_streams", "v:0"])
        .args(["-show_entries", "stream=nb_read_frames,width,height"])
        .args(["-of", "csv=p=0:nk=1"])
        .arg(path)
        .output()
        .expect("ffprobe runs (scripts/setup.sh installs ffmpeg)");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    let v: Vec<&str> = text.trim().split(',').collect();
    assert_eq!(v.len(), 3, "ffprobe said {text:?}");
    (
        v[2].parse().unwrap(),
        v[0].parse().unwrap(),
        v[1].parse().unwrap(),
    )
}

/// Every frame decoded by ffmpeg as RGB bytes.
fn decode(path: &Path, w: u32, h: u32) -> Vec<Vec<u8>> {
    let o = Command::new("ffmpeg")
        .args(["-v", "error", "-i"])
        .arg(path)
        .args(["-f", "rawvideo", "-pix_fmt", "rgb24", "-"])
        .output()
        .expect("ffmpeg runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let frame = (w * h * 3) as usize;
    assert_eq!(o.stdout.len() % frame, 0, "stdout holds whole frames");
    o.stdout.chunks(frame).map(|c| c.to_vec()).collect()
}

fn mean_abs_diff(a: &[u8], b: &[u8]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (*x as f64 - *y as f64).abs())
        .sum::<f64>()
        / a.len() as f64
}

/// A fresh temporary directory `name` holding the two clusters' PLY and its orbit video `file`
/// made with the options `extra`: the directory, the PLY and the video.
fn orbit_video(name: &str, file: &str, extra: &[&str]) -> (PathBuf, PathBuf, PathBuf) {
    let d = tmp(name);
    let ply = d.join("clusters.ply");
    common::two_clusters(&ply, 2000, 0.12, 3);
    let out = d.join(file);
    let mut args = vec![
        "video",
        ply.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = run(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (d, ply, out)
}

#[test]
fn mp4_decodes_to_the_frames_rendered_along_the_orbit() {
    let (d, ply, out) = orbit_video(
        "mp4",
        "orbit.mp4",
        &["--seconds", "1", "--fps", "8", "--size", "96x64", "--depth"],
    );
    assert_eq!(probe(&out), (8, 96, 64));
    let depth = d.join("orbit.depth.mp4");
    assert_eq!(probe(&depth), (8, 96, 64));
    let frames = decode(&out, 96, 64);
    assert_eq!(frames.len(), 8);
    // The camera goes round: consecutive frames differ, and a quarter turn differs a lot.
    for (i, w) in frames.windows(2).enumerate() {
        let diff = mean_abs_diff(&w[0], &w[1]);
        assert!(diff > 1.0, "frames {i} and {} differ by only {diff}", i + 1);
    }
    assert!(mean_abs_diff(&frames[0], &frames[2]) > 5.0);
    // The same cameras through `render --trajectory`: the decoded video matches the PNGs to
    // within H.264's loss (mean error under 6 of 255 on these flat-coloured clusters).
    let renders = d.join("renders");
    let o = run(&[
        "render",
        "--ply",
        ply.to_str().unwrap(),
        "--trajectory",
        "orbit",
        "--frames",
        "8",
        "--size",
        "96x64",
        "--out",
        renders.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for (i, f) in frames.iter().enumerate() {
        let png = image::open(renders.join(format!("orbit_{i:04}.png")))
            .unwrap()
            .to_rgb8();
        assert_eq!(png.dimensions(), (96, 64));
        let err = mean_abs_diff(f, png.as_raw());
        assert!(
            err < 6.0,
            "frame {i}: decoded video differs from the render by {err}"
        );
    }
    // The depth video is not the colour one and shows the clusters (bright) over empty black.
    let depth_frames = decode(&depth, 96, 64);
    let grey = &depth_frames[0];
    let lit = grey.chunks(3).filter(|p| p[0] > 40).count();
    let dark = grey.chunks(3).filter(|p| p[0] < 10).count();
    assert!(
        lit > 200 && dark > 1000,
        "depth frame: {lit} lit, {dark} dark pixels"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn gif_holds_every_frame_and_bad_requests_fail_in_one_line() {
    let (d, ply, out) = orbit_video(
        "gif",
        "orbit.gif",
        &[
            "--seconds",
            "0.5",
            "--fps",
            "10",
            "--size",
            "64x48",
            "--background",
            "1,1,1",
        ],
    );
    assert_eq!(probe(&out), (5, 64, 48));
    let frames = decode(&out, 64, 48);
    assert_eq!(frames.len(), 5);
    assert!(mean_abs_diff(&frames[0], &frames[1]) > 1.0);
    // White background: the corners are white.
    assert!(
        frames[0][..3].iter().all(|v| *v > 240),
        "{:?}",
        &frames[0][..3]
    );

    let p = ply.to_str().unwrap();
    let bad: [(&[&str], &str); 5] = [
        (&["video", p, "--out", "x.avi"], ".mp4 or .gif"),
        (
            &["video", p, "--out", "x.mp4", "--size", "65x48"],
            "even sides",
        ),
        (
            &["video", p, "--out", "x.mp4", "--size", "big"],
            "WIDTHxHEIGHT",
        ),
        (
            &["video", p, "--out", "x.mp4", "--trajectory", "explore"],
            "scene directory",
        ),
        (
            &["video", "/nonexistent.ply", "--out", "x.mp4"],
            "not found",
        ),
    ];
    for (args, says) in bad {
        let o = run(args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{args:?} succeeded");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!Path::new("x.mp4").exists() && !Path::new("x.mp4.tmp").exists());
    }
    std::fs::remove_dir_all(&d).ok();
}
