//! `dreamscene object` through the binary: the shape-prior draft, bad input, the oracle prior
//! killed mid-run and resumed, and the tiny Stable Diffusion model end to end.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use dreamscene::splat::loss::psnr;
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_dreamscene"));
    c.env_remove("DREAMSCENE_MODELS");
    c
}

fn run(args: &[&str]) -> Output {
    bin().args(args).output().expect("runs")
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-object-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn object_without_models_writes_a_shape_prior_draft() {
    let out = tmp("draft");
    let o = run(&[
        "object",
        "a navy leather sofa",
        "--out",
        out.to_str().unwrap(),
        "--resolution",
        "64",
        "--turntable",
        "3",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("draft") && err.contains("DREAMSCENE_MODELS"),
        "{err}"
    );
    let j = json(&out.join("object.json"));
    for k in [
        "prompt",
        "category",
        "size",
        "prior",
        "seed",
        "iterations",
        "resolution",
        "gaussians",
        "seconds",
    ] {
        assert!(j.get(k).is_some(), "object.json lacks {k}: {j}");
    }
    assert_eq!(j["category"], "sofa");
    assert_eq!(j["prior"], "shape");
    let g = read_ply(&out.join("object.ply")).unwrap();
    assert_eq!(j["gaussians"]["final"], g.len());
    assert!(g.len() > 1000);
    for i in 0..3 {
        assert!(out.join(format!("renders/turntable_{i:03}.png")).is_file());
    }
}

#[test]
fn object_bad_input_gets_one_line_errors() {
    let out = tmp("bad");
    let o = out.to_str().unwrap();
    for (args, want) in [
        (
            vec!["object", "a chair", "--out", o, "--size", "1,2"],
            "W,D,H",
        ),
        (
            vec!["object", "a chair", "--out", o, "--size", "1,-2,1"],
            "positive",
        ),
        (
            vec!["object", "a chair", "--out", o, "--prior", "magic"],
            "oracle:REF",
        ),
        (
            vec!["object", "a chair", "--out", o, "--prior", "sd"],
            "model directory",
        ),
        (
            vec![
                "object",
                "a chair",
                "--out",
                o,
                "--prior",
                "oracle:/nonexistent.ply",
            ],
            "nonexistent.ply",
        ),
        (vec!["object", " ", "--out", o], "empty"),
        (
            vec!["object", "a chair", "--out", o, "--filter-fraction", "1.5"],
            "fraction",
        ),
    ] {
        let r = run(&args);
        let err = String::from_utf8_lossy(&r.stderr);
        assert!(!r.status.success(), "{args:?} succeeded");
        assert!(err.contains(want), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    let r = run(&[
        "object",
        "a chair",
        "--out",
        o,
        "--prior",
        "oracle:tests/data/none.ply",
        "--resume",
    ]);
    assert!(!r.status.success());
}

/// Renders a PLY from a few fixed views.
fn renders(ctx: &dreamscene::gpu::Context, ply: &Path) -> Vec<Vec<[f32; 3]>> {
    let g = read_ply(ply).unwrap();
    let r = Rasterizer::new(ctx).unwrap();
    let gg = GpuGaussians::upload(ctx, &g).unwrap();
    let frame = dreamscene::camera::object::ObjectFrame {
        size: [0.85, 0.85, 0.9],
    };
    dreamscene::camera::object::turntable(&frame, 4, 70.0, 64)
        .iter()
        .map(|c| {
            r.forward(ctx, &gg, c, [1.0; 3])
                .unwrap()
                .read()
                .unwrap()
                .color
        })
        .collect()
}

#[test]
fn oracle_object_killed_and_resumed_matches_an_uninterrupted_run() {
    let ctx = common::gpu();
    // The reference: a shape-prior armchair; the start: a sofa's shape prior at the same size.
    let refdir = tmp("ref");
    let r = run(&[
        "object",
        "a red armchair",
        "--out",
        refdir.to_str().unwrap(),
        "--turntable",
        "0",
    ]);
    assert!(r.status.success());
    let init = tmp("init");
    let r = run(&[
        "object",
        "a sofa",
        "--size",
        "0.85,0.85,0.9",
        "--out",
        init.to_str().unwrap(),
        "--turntable",
        "0",
    ]);
    assert!(r.status.success());
    // Every fourth Gaussian of each: the mechanics under test need no dense clouds, and the
    // oracle renders its reference for every view of every step.
    let sparse = |from: &Path, to: &Path| {
        let g = read_ply(from).unwrap();
        let keep: Vec<bool> = (0..g.len()).map(|i| i % 4 == 0).collect();
        write_ply(to, &dreamscene::generate::object::subset(&g, &keep)).unwrap();
    };
    let (ref_ply, init_ply) = (refdir.join("sparse.ply"), init.join("sparse.ply"));
    sparse(&refdir.join("object.ply"), &ref_ply);
    sparse(&init.join("object.ply"), &init_ply);
    let oracle = format!("oracle:{}", ref_ply.display());
    let args = |out: &Path| -> Vec<String> {
        [
            "object",
            "a red armchair",
            "--out",
            out.to_str().unwrap(),
            "--prior",
            &oracle,
            "--init",
            init_ply.to_str().unwrap(),
            "--iterations",
            "30",
            "--resolution",
            "64",
            "--sh-degree",
            "0",
            "--recon-views",
            "4",
            "--recon-passes",
            "3",
            "--checkpoint-every",
            "5",
            "--turntable",
            "0",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect()
    };
    let whole = tmp("whole");
    let o = bin().args(args(&whole)).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let cut = tmp("cut");
    common::kill_when(
        bin().args(args(&cut)),
        &cut.join("checkpoints/run.json"),
        |j| j["iteration"].as_u64().unwrap_or(0) >= 15,
        600,
    );
    assert!(!cut.join("object.ply").exists());
    let mut a = args(&cut);
    a.push("--resume".into());
    let o = bin().args(&a).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("resuming"), "{err}");
    let (x, y) = (
        renders(&ctx, &whole.join("object.ply")),
        renders(&ctx, &cut.join("object.ply")),
    );
    let p: f64 = x.iter().zip(&y).map(|(a, b)| psnr(a, b)).sum::<f64>() / x.len() as f64;
    println!("resumed vs uninterrupted: {p:.1} dB");
    assert!(p > 30.0, "resumed run differs: {p:.1} dB");
    // Resuming with another seed is refused with the reason.
    let mut a = args(&cut);
    a.extend(["--resume".into(), "--seed".into(), "5".into()]);
    let o = bin().args(&a).output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("another run"));
}

#[test]
fn tiny_sd_model_runs_the_sd_prior_end_to_end() {
    let out = tmp("sd");
    let o = run(&[
        "object",
        "a wooden chair",
        "--out",
        out.to_str().unwrap(),
        "--models",
        "tests/data/tiny-sd",
        "--iterations",
        "4",
        "--batch",
        "2",
        "--resolution",
        "64",
        "--recon-views",
        "2",
        "--recon-passes",
        "1",
        "--turntable",
        "1",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let j = json(&out.join("object.json"));
    assert_eq!(j["prior"], "sd");
    assert_eq!(j["iterations"], 4);
    let g = read_ply(&out.join("object.ply")).unwrap();
    assert!(g.len() > 100 && g.means.iter().flatten().all(|v| v.is_finite()));
}
