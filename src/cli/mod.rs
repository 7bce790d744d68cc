//! The verbs' glue, one file each: a clap `Args` struct and `run`. Shared helpers below.
pub mod batch;
pub mod bench;
pub mod demo;
pub mod doctor;
pub mod edit;
pub mod export;
pub mod fit;
pub mod generate;
pub mod generate_full;
pub mod layout;
pub mod object;
pub mod plan;
pub mod render;
pub mod scene_renders;
pub mod stage;
pub mod stage_prior;
pub mod video;
pub mod view;

use anyhow::{Context as _, Result};
use dreamscene::gpu::Context;
use dreamscene::splat::raster::RenderOutput;
use std::path::{Path, PathBuf};

/// An error and its causes in one line, each thing said once: a cause that repeats a path (or
/// anything else) the line already holds drops the repeat.
pub fn error_line(chain: &[String]) -> String {
    let mut out = String::new();
    for cause in chain {
        let mut rest = cause.trim();
        while let Some((head, tail)) = rest.split_once(": ") {
            if out.contains(head.trim()) {
                rest = tail.trim();
            } else {
                break;
            }
        }
        if rest.is_empty() || out.contains(rest) {
            continue;
        }
        if !out.is_empty() {
            out.push_str(": ");
        }
        out.push_str(rest);
    }
    out
}

pub fn parse_hw(s: &str) -> Result<(usize, usize), String> {
    let (h, w) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("{s:?}: expected HxW, e.g. 64x64"))?;
    let p = |v: &str| {
        v.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=1024).contains(n))
            .ok_or_else(|| format!("{s:?}: sizes must be whole numbers from 1 to 1024"))
    };
    Ok((p(h)?, p(w)?))
}

pub fn parse_rgb(s: &str) -> Result<[f32; 3], String> {
    let v: Vec<f32> = s
        .split(',')
        .map(|x| x.trim().parse::<f32>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("`{s}`: {e}"))?;
    match v.as_slice() {
        [r, g, b] if v.iter().all(|c| (0.0..=1.0).contains(c)) => Ok([*r, *g, *b]),
        _ => Err(format!(
            "`{s}`: expected three numbers in [0, 1] such as 1,1,1"
        )),
    }
}

pub fn open_device() -> Result<Context> {
    Context::new().context("opening the Vulkan device (run `dreamscene doctor`)")
}

pub fn save_png(img: &RenderOutput, path: &Path) -> Result<()> {
    let mut buf = image::RgbImage::new(img.width, img.height);
    for (i, p) in buf.pixels_mut().enumerate() {
        let c = img.color[i];
        *p = image::Rgb(c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8));
    }
    write_png(&buf, path)
}

/// Writes a PNG atomically (temporary file, then rename; see `util::write_atomic`).
pub fn write_png(img: &image::RgbImage, path: &Path) -> Result<()> {
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .with_context(|| format!("encoding {}", path.display()))?;
    Ok(dreamscene::util::write_atomic(path, &bytes)?)
}

/// The scene directory `input` names (a directory, or its scene.json), or None for a PLY.
fn scene_dir_of(input: &Path) -> Option<std::path::PathBuf> {
    if input.is_dir() {
        return Some(input.to_path_buf());
    }
    let json = input
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    json.then(|| match input.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    })
}

/// Runs `read` on `input` while no edit is being put in place when it is a scene, so a reader
/// sees the scene before an edit or after it, never a mix (a PLY is read as it is).
pub fn read_input<T>(input: &Path, read: impl FnOnce() -> Result<T>) -> Result<T> {
    match scene_dir_of(input) {
        Some(dir) if dir.join("scene.json").is_file() => {
            dreamscene::edit::txn::read_consistent(&dir, read)?
        }
        _ => read(),
    }
}

/// Checks, before any long work, that `file` can be written: its directory is created and a
/// probe file is written there and removed. The probe never touches `file` itself, so an existing
/// output stays as it is until the real write replaces it.
pub fn check_writable(file: &Path) -> Result<()> {
    create_parent(file)?;
    let dir = match file.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(d) => d.to_path_buf(),
        None => PathBuf::from("."),
    };
    check_writable_dir(&dir).with_context(|| format!("cannot write {}", file.display()))
}

/// Runs `write`, which writes the output file `file`; when it succeeds over a file that was
/// already there (an export or a video written again over the last one), says so in one line,
/// so nothing is overwritten unsaid (a refused run keeps the old file and says only its error).
pub fn saying_if_replaced(file: &Path, write: impl FnOnce() -> Result<()>) -> Result<()> {
    let existed = file.is_file();
    write()?;
    if existed {
        eprintln!("note: {} existed: it is replaced", file.display());
    }
    Ok(())
}

/// Creates the folder `dir` (and its parents); a path that is a file is refused in one line
/// that says so, not with the system's "File exists".
pub fn create_dir(dir: &Path) -> Result<()> {
    if dir.is_file() {
        anyhow::bail!(
            "{} is a file, not a folder: give a folder for the outputs",
            dir.display()
        );
    }
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))
}

/// Checks that files can be created in `dir` (created if missing), before any long work.
pub fn check_writable_dir(dir: &Path) -> Result<()> {
    create_dir(dir)?;
    let probe = dir.join(format!(".dreamscene-write-check-{}", std::process::id()));
    std::fs::write(&probe, b"").map_err(|e| anyhow::anyhow!("{}: {e}", dir.display()))?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// Creates the directory that will hold `file`.
pub fn create_parent(file: &Path) -> Result<()> {
    match file.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(dir) => create_dir(dir),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn an_error_line_says_each_path_once() {
        let chain = [
            "writing ro/x.spz".to_string(),
            "ro/x.spz: Operation not permitted (os error 1)".to_string(),
            "Operation not permitted (os error 1)".to_string(),
        ];
        assert_eq!(
            super::error_line(&chain),
            "writing ro/x.spz: Operation not permitted (os error 1)"
        );
        let plain = ["a: b".to_string(), "c".to_string()];
        assert_eq!(super::error_line(&plain), "a: b: c", "distinct causes kept");
    }
}
