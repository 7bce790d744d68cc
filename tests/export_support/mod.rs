//! The export tests' harness: the binary, the independent readers (failing, never skipping,
//! when one is missing), a test cloud in every format's range, and the maths the checks need,
//! written from the formats' definitions rather than taken from the code under test.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::splat::Gaussians;
use rand::Rng;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

pub const SH_C0: f64 = 0.282_094_791_773_878_14;

// ---------------------------------------------------------------------------------------------
// Harness: the binary, the readers, a scratch directory.

/// A scratch directory, removed when the test passes and kept for a look when it fails.
pub struct Scratch(PathBuf);

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

pub fn tempdir(tag: &str) -> Scratch {
    let d = std::env::temp_dir().join(format!("dreamscene-export-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    Scratch(d)
}

pub fn node_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node")
}

/// Whether Blender's glTF importer can be run: Blender itself and the numpy its add-on needs.
/// Missing, the test fails saying how to install them, unless `DREAMSCENE_SKIP_EXTERNAL` names
/// `blender` (see `common::external_tool`).
pub fn blender_ready() -> bool {
    let runs = |cmd: &str, args: &[&str]| {
        Command::new(cmd)
            .args(args)
            .output()
            .is_ok_and(|o| o.status.success())
    };
    let problem = if !runs("blender", &["--version"]) {
        Some("Blender is missing: apt-get install blender python3-numpy".to_string())
    } else if !runs(
        "blender",
        &[
            "-b",
            "--factory-startup",
            "--python-exit-code",
            "1",
            "--python-expr",
            "import numpy",
        ],
    ) {
        Some(
            "numpy (Blender's glTF importer needs it) is missing: apt-get install python3-numpy"
                .to_string(),
        )
    } else {
        None
    };
    crate::common::external_tool("blender", problem)
}

/// Fails (never skips) when Node.js or a reader package is missing.
pub fn require_readers() {
    let node = Command::new("node").arg("--version").output();
    assert!(
        node.as_ref().is_ok_and(|o| o.status.success()),
        "Node.js is missing: run `bash scripts/setup.sh` (installs nodejs and the readers in tests/node)"
    );
    for p in [
        ".bin/splat-transform",
        "@adobe/spz/package.json",
        "@gltf-transform/core/package.json",
        "gltf-validator/package.json",
    ] {
        let path = node_dir().join("node_modules").join(p);
        assert!(
            path.exists(),
            "{} is missing: run `bash scripts/setup.sh` (runs `npm ci` in tests/node)",
            path.display()
        );
    }
}

/// A draft scene of `prompt` (shape prior, no renders) generated into `scene`.
pub fn draft_scene(prompt: &str, scene: &Path) {
    let o = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(["generate", prompt, "--draft", "--renders", "0", "--out"])
        .arg(scene)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "generate \"{prompt}\": {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

pub fn export(input: &Path, format: &str, out: &Path, extra: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .arg("export")
        .arg(input)
        .args(["--format", format, "--out"])
        .arg(out)
        .args(extra)
        .output()
        .unwrap()
}

pub fn export_ok(input: &Path, format: &str, out: &Path, extra: &[&str]) {
    let o = export(input, format, out, extra);
    assert!(
        o.status.success(),
        "export {format} failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// A table read back by splat-transform: column names and rows, in file order.
pub struct Table {
    pub columns: Vec<String>,
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    pub fn col(&self, name: &str) -> usize {
        self.columns
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("splat-transform gave no column {name}: {:?}", self.columns))
    }
    pub fn get(&self, row: usize, name: &str) -> f64 {
        self.rows[row][self.col(name)]
    }
}

/// `splat-transform FILE out.csv`: what PlayCanvas's readers decode, as PLY-convention columns.
pub fn splat_transform_csv(file: &Path) -> Table {
    let csv = file.with_extension("readback.csv");
    let o = Command::new(node_dir().join("node_modules/.bin/splat-transform"))
        .args(["-q", "-w"])
        .arg(file)
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "splat-transform could not read {}: {}{}",
        file.display(),
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    let columns = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').map(|v| v.parse::<f64>().unwrap()).collect())
        .collect();
    Table { columns, rows }
}

/// `node readers.mjs KIND FILE` as JSON.
pub fn reader_json(kind: &str, file: &Path) -> Value {
    let o = Command::new("node")
        .current_dir(node_dir())
        .arg("readers.mjs")
        .arg(kind)
        .arg(file)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "reader {kind} failed on {}: {}",
        file.display(),
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).unwrap_or_else(|e| {
        panic!(
            "reader {kind} printed no JSON ({e}): {:.500}",
            String::from_utf8_lossy(&o.stdout)
        )
    })
}

pub fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

// ---------------------------------------------------------------------------------------------
// The test cloud and the maths the checks need, written from the formats' definitions.

/// Gaussians in the ranges every format holds without clamping: positions within ±4 m, log
/// scales in [-6, 0.5], opacity logits in [-4, 4], DC colours in [-1.5, 1.5] (colour 0.08 to
/// 0.92), higher SH in [-0.9, 0.9] (SPZ's byte range is ±1), raw quaternions of length 0.5 to 2.
pub fn cloud(seed: u64, n: usize, sh_degree: u32) -> Gaussians {
    let mut rng = crate::common::rng(seed);
    let k = ((sh_degree + 1) * (sh_degree + 1)) as usize;
    let mut g = Gaussians {
        sh_degree,
        ..Default::default()
    };
    for _ in 0..n {
        g.means.push([0; 3].map(|_| rng.gen_range(-4.0..4.0)));
        g.scales.push([0; 3].map(|_| rng.gen_range(-6.0..0.5)));
        let q: [f32; 4] = [0; 4].map(|_| rng.gen_range(-1.0..1.0));
        let norm = q.iter().map(|v| v * v).sum::<f32>().sqrt().max(0.1);
        let len = rng.gen_range(0.5..2.0);
        g.rotations.push(q.map(|v| v / norm * len));
        g.opacities.push(rng.gen_range(-4.0..4.0));
        for c in 0..k {
            for _ in 0..3 {
                let r = if c == 0 { 1.5 } else { 0.9 };
                g.sh.push(rng.gen_range(-r..r));
            }
        }
    }
    g
}

pub fn sigmoid(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

pub fn unit(q: [f64; 4]) -> [f64; 4] {
    let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    q.map(|v| v / n)
}

/// Rotation matrix of a unit quaternion (w, x, y, z).
pub fn rot(q: [f64; 4]) -> [[f64; 3]; 3] {
    let [w, x, y, z] = unit(q);
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

pub fn mat_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// Largest entry difference of the rotation matrices: 0 for the same rotation (either sign of
/// the quaternion), about the angle between them in radians otherwise.
pub fn rot_diff(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> f64 {
    (0..9)
        .map(|i| (a[i / 3][i % 3] - b[i / 3][i % 3]).abs())
        .fold(0.0, f64::max)
}

/// The real SH basis with the constants of the KHR_gaussian_splatting specification (its
/// Appendix A), in its coefficient order (l = 0..3, m = -l..l), at unit direction `d`.
pub fn basis(d: [f64; 3]) -> [f64; 16] {
    let [x, y, z] = d;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    [
        0.282_094_791_773_878_1,
        -0.488_602_511_902_919_9 * y,
        0.488_602_511_902_919_9 * z,
        -0.488_602_511_902_919_9 * x,
        1.092_548_430_592_079 * x * y,
        -1.092_548_430_592_079 * y * z,
        0.315_391_565_252_52 * (2.0 * zz - xx - yy),
        -1.092_548_430_592_079 * x * z,
        0.546_274_215_296_039_5 * (xx - yy),
        -0.590_043_589_926_643_5 * y * (3.0 * xx - yy),
        2.890_611_442_640_554 * x * y * z,
        -0.457_045_799_464_465_7 * y * (4.0 * zz - xx - yy),
        0.373_176_332_590_115_4 * z * (2.0 * zz - 3.0 * xx - 3.0 * yy),
        -0.457_045_799_464_465_7 * x * (4.0 * zz - xx - yy),
        1.445_305_721_320_277 * z * (xx - yy),
        -0.590_043_589_926_643_5 * x * (xx - 3.0 * yy),
    ]
}

/// Coefficient `c` (0..16) of Gaussian `i`, channel `ch`, from the `[gaussian][coeff][rgb]` layout.
pub fn sh(g: &Gaussians, i: usize, c: usize, ch: usize) -> f64 {
    f64::from(g.sh[(i * g.coeffs() + c) * 3 + ch])
}

/// Writes `g` as the input PLY of an export.
pub fn input_ply(dir: &Path, g: &Gaussians) -> PathBuf {
    let p = dir.join("in.ply");
    dreamscene::splat::ply::write_ply(&p, g).unwrap();
    p
}

// ---------------------------------------------------------------------------------------------

/// The frame PLY and .splat viewers expect (x right, y down, z forward) of the z-up world.
pub const RDF: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
/// glTF's y-up frame of the z-up world (also SPZ's stored RUB frame).
pub const Y_UP: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]];

pub fn apply(f: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|r| (0..3).map(|c| f[r][c] * v[c]).sum::<f64>())
}

/// Largest colour difference between SH coefficients `a` (world frame) seen from direction d and
/// `b` (frame `f`) seen from `f · d`, over a few random directions, for every channel: zero when
/// `b` is `a` rotated into the frame (the specification's basis, evaluated here).
pub fn sh_frame_diff(
    f: &[[f64; 3]; 3],
    a: impl Fn(usize, usize) -> f64,
    b: impl Fn(usize, usize) -> f64,
    rng: &mut impl Rng,
) -> f64 {
    let mut worst = 0.0f64;
    for _ in 0..4 {
        let d: [f64; 3] = [0; 3].map(|_| rng.gen_range(-1.0..1.0));
        let n = d.iter().map(|v| v * v).sum::<f64>().sqrt();
        let d = d.map(|v| v / n);
        let (bw, bf) = (basis(d), basis(apply(f, d)));
        for ch in 0..3 {
            let world: f64 = (0..16).map(|c| bw[c] * a(c, ch)).sum();
            let framed: f64 = (0..16).map(|c| bf[c] * b(c, ch)).sum();
            worst = worst.max((world - framed).abs());
        }
    }
    worst
}

/// Writes `glb` to `renamed` with its extension attributes renamed to application-specific
/// semantics ([`rename_extension_attributes`], which the core specification allows) and checks
/// that the reference validator finds no error and no warning in it: accessors, bounds, views,
/// alignment and the GLB container are all valid glTF 2.0.
pub fn assert_renamed_validates_clean(glb: &[u8], renamed: &Path) {
    std::fs::write(renamed, rename_extension_attributes(glb)).unwrap();
    let report = reader_json("validate", renamed);
    assert_eq!(report["issues"]["numErrors"].as_u64(), Some(0), "{report}");
    assert_eq!(
        report["issues"]["numWarnings"].as_u64(),
        Some(0),
        "{report}"
    );
}

/// The GLB with every `KHR_gaussian_splatting:NAME` attribute renamed `_KHR_gaussian_splatting_NAME`
/// (JSON chunk re-padded, lengths rewritten).
pub fn rename_extension_attributes(glb: &[u8]) -> Vec<u8> {
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let json = std::str::from_utf8(&glb[20..20 + json_len]).unwrap();
    let mut json = json
        .replace("\"KHR_gaussian_splatting:", "\"_KHR_gaussian_splatting_")
        .into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let bin = &glb[20 + json_len..];
    let mut out = Vec::new();
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend(((12 + 8 + json.len() + bin.len()) as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(json);
    out.extend(bin);
    out
}
