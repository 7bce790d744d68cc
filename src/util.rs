//! Small shared helpers.
use std::io::Write;
use std::path::{Path, PathBuf};

/// Writes `bytes` to `path` so that a crash or a full disk never leaves half a file:
///
/// - a regular file (or a new path) is written through a temporary sibling
///   `<name>.<process>-<n>.tmp` renamed into place, one of its own for each writer, so that two
///   processes writing one file at once (shards of one scene) never rename each other's half
///   file; on failure the temporary file is removed;
/// - a symbolic link is followed, and the file it points to is replaced the same way (the link
///   stays a link);
/// - anything else that exists (a device such as `/dev/stdout` or `/dev/null`, a pipe) is written
///   through directly, never replaced; a directory is refused.
///
/// Errors name the path.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let named = |e: std::io::Error, p: &Path| {
        std::io::Error::new(e.kind(), format!("{}: {e}", p.display()))
    };
    if is_special(path) {
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(|e| named(e, path))?;
        return f
            .write_all(bytes)
            .and_then(|()| f.flush())
            .map_err(|e| named(e, path));
    }
    let target = resolve_links(path).map_err(|e| named(e, path))?;
    if target.is_dir() {
        return Err(named(
            std::io::Error::new(std::io::ErrorKind::IsADirectory, "is a directory"),
            path,
        ));
    }
    static WRITES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let n = WRITES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let mut tmp = target.as_os_str().to_owned();
    tmp.push(format!(".{}-{n}.tmp", std::process::id()));
    let tmp = PathBuf::from(tmp);
    let written = std::fs::write(&tmp, bytes).and_then(|()| std::fs::rename(&tmp, &target));
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(named(e, &target));
    }
    Ok(())
}

/// Checks that [`write_atomic`] can write `path` (following links): its directory takes a new
/// file. Devices and pipes are refused, since a caller that asks is about to write it more than
/// once. Errors name the path.
pub fn check_writable(path: &Path) -> std::io::Result<()> {
    let named =
        |e: std::io::Error| std::io::Error::new(e.kind(), format!("{}: {e}", path.display()));
    if is_special(path) {
        return Err(named(std::io::Error::other(
            "not a regular file (a device or pipe); give a file path",
        )));
    }
    let target = resolve_links(path).map_err(named)?;
    if target.is_dir() {
        return Err(named(std::io::Error::new(
            std::io::ErrorKind::IsADirectory,
            "is a directory; give a file path",
        )));
    }
    let mut probe = target.as_os_str().to_owned();
    probe.push(".tmp");
    let probe = PathBuf::from(probe);
    std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(true)
        .open(&probe)
        .map_err(named)?;
    std::fs::remove_file(&probe).map_err(named)
}

/// True when `path` exists and is not a regular file, directory or link to one: a device, a pipe,
/// a socket, or anything under `/dev` or `/proc` (whose links, such as `/dev/stdout`, name
/// descriptors rather than files).
pub fn is_special(path: &Path) -> bool {
    if path.starts_with("/dev") || path.starts_with("/proc") {
        return path.exists();
    }
    match std::fs::metadata(path) {
        Ok(m) => !m.is_file() && !m.is_dir(),
        Err(_) => false,
    }
}

/// `path` with symbolic links followed (a dangling link gives the path it points to).
fn resolve_links(path: &Path) -> std::io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            _ => return Ok(p),
        }
    }
    Err(std::io::Error::other("too many levels of symbolic links"))
}

/// What a file's first bytes look like, as a phrase for error messages ("is a JSON object with
/// keys objects, room, ..." or "is a PNG image"), so that a file of the wrong kind is named.
pub fn describe_bytes(head: &[u8]) -> String {
    let head = &head[..head.len().min(4096)];
    let text = String::from_utf8_lossy(head);
    let t = text.trim_start_matches('\u{feff}').trim_start();
    if head.is_empty() {
        return "is empty".into();
    }
    if head.starts_with(b"\x89PNG") {
        return "is a PNG image".into();
    }
    if head.starts_with(&[0xff, 0xd8, 0xff]) {
        return "is a JPEG image".into();
    }
    if head.starts_with(b"glTF") {
        return "is a binary glTF (.glb)".into();
    }
    if head.starts_with(&[0x1f, 0x8b]) {
        return "is gzip-compressed (an .spz?)".into();
    }
    if t.starts_with("ply") {
        return "is a PLY file".into();
    }
    if t.starts_with('{') || t.starts_with('[') {
        return describe_json(t);
    }
    if head.iter().take(512).any(|&b| b == 0) {
        return "is binary data".into();
    }
    let first: String = t.lines().next().unwrap_or("").chars().take(40).collect();
    format!("is text starting `{first}`")
}

/// Names a JSON text (possibly cut short) by the keys it holds: which of the project's files it
/// looks like.
fn describe_json(t: &str) -> String {
    let has = |k: &str| t.contains(&format!("\"{k}\""));
    let kind = if has("img_name") && has("rotation") {
        Some("cameras.json")
    } else if has("stages") && has("environment") {
        Some("scene.json")
    } else if has("unsatisfied") || has("placed_by") {
        Some("layout.json")
    } else if has("anchors") || has("relations") {
        Some("spec.json")
    } else if has("gaussians") && has("prompt") {
        Some("object.json")
    } else {
        None
    };
    match (kind, t.starts_with('[')) {
        (Some(k), _) => format!("looks like a {k}"),
        (None, true) => "is a JSON list".into(),
        (None, false) => "is a JSON object".into(),
    }
}

/// Environment variable `name`, with an empty or blank value meaning unset (scripts unset a
/// variable by writing `NAME=`). Every variable the program reads goes through here.
pub fn env_var(name: &str) -> Option<String> {
    std::env::var(name).ok().filter(|v| !v.trim().is_empty())
}

/// [`env_var`] as a path (non-UTF-8 values kept), empty meaning unset.
pub fn env_path(name: &str) -> Option<std::path::PathBuf> {
    std::env::var_os(name)
        .filter(|v| !v.to_string_lossy().trim().is_empty())
        .map(std::path::PathBuf::from)
}

/// The value of environment variable `name` among `choices` (name, value); unset gives `None`,
/// and a value that is none of the names gives `None` with a warning naming the choices.
pub fn env_choice<T: Copy>(name: &str, choices: &[(&str, T)]) -> Option<T> {
    let v = env_var(name)?;
    let found = choices.iter().find(|c| c.0 == v).map(|c| c.1);
    if found.is_none() {
        let names: Vec<&str> = choices.iter().map(|c| c.0).collect();
        eprintln!(
            "warning: {name}={v} is not one of {}; using the device's default",
            names.join("|")
        );
    }
    found
}

/// A contact sheet: `images` (RGB in [0, 1], each `width x height` row-major) scaled to tiles
/// `tile` pixels wide, `cols` to a row, on white with a 4-pixel gap (`renders/overview.png`).
pub fn contact_sheet(images: &[(u32, u32, &[[f32; 3]])], cols: u32, tile: u32) -> image::RgbImage {
    let gap = 4u32;
    let cols = cols.clamp(1, images.len().max(1) as u32);
    let rows = (images.len() as u32).div_ceil(cols).max(1);
    let th = images
        .first()
        .map_or(tile, |(w, h, _)| {
            (tile as u64 * *h as u64 / (*w).max(1) as u64) as u32
        })
        .max(1);
    let mut sheet = image::RgbImage::from_pixel(
        cols * (tile + gap) + gap,
        rows * (th + gap) + gap,
        image::Rgb([255, 255, 255]),
    );
    for (k, (w, h, px)) in images.iter().enumerate() {
        let mut img = image::RgbImage::new(*w, *h);
        for (p, c) in img.pixels_mut().zip(px.iter()) {
            *p = image::Rgb(c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8));
        }
        let small = image::imageops::resize(&img, tile, th, image::imageops::FilterType::Triangle);
        let (x, y) = (k as u32 % cols, k as u32 / cols);
        image::imageops::replace(
            &mut sheet,
            &small,
            (gap + x * (tile + gap)) as i64,
            (gap + y * (th + gap)) as i64,
        );
    }
    sheet
}

/// The 2D convex hull of `points` (Andrew's monotone chain): counter-clockwise, without
/// collinear or repeated points; points that are not finite are left out.
pub fn convex_hull(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut p: Vec<[f64; 2]> = points
        .iter()
        .copied()
        .filter(|q| q[0].is_finite() && q[1].is_finite())
        .collect();
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut hull: Vec<[f64; 2]> = Vec::with_capacity(2 * p.len());
    // The lower chain left to right, then the upper one right to left.
    for chain in [p.clone(), p.into_iter().rev().collect()] {
        let start = hull.len();
        for q in chain {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::{convex_hull, env_choice, write_atomic};

    #[test]
    fn writers_at_once_never_leave_a_reader_half_a_file() {
        // Two writers replace one file over and over (two shards writing the same plan) while
        // a reader reads it: every read is one whole version, never empty or cut.
        let dir = std::env::temp_dir().join(format!("ds-atomic-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("spec.json");
        let (a, b) = (vec![b'a'; 200_000], vec![b'b'; 200_000]);
        write_atomic(&path, &a).unwrap();
        std::thread::scope(|s| {
            for v in [&a, &b] {
                let path = &path;
                s.spawn(move || {
                    for _ in 0..40 {
                        write_atomic(path, v).unwrap();
                    }
                });
            }
            for _ in 0..200 {
                let got = std::fs::read(&path).unwrap();
                assert!(
                    got == a || got == b,
                    "a read of {} bytes is no whole version",
                    got.len()
                );
            }
        });
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left.len(), 1, "no temporary file is left: {left:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn convex_hull_keeps_corners_counter_clockwise_only() {
        let pts = [
            [2.0, 0.0],
            [0.0, 0.0],
            [1.0, 0.0], // on an edge
            [2.0, 1.0],
            [0.0, 1.0],
            [0.0, 1.0], // twice
            [1.0, 0.5], // inside
            [f64::NAN, 5.0],
            [f64::INFINITY, 0.0],
        ];
        let h = convex_hull(&pts);
        assert_eq!(
            h,
            vec![[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]],
            "the four corners from the lowest-left, counter-clockwise"
        );
        assert_eq!(
            convex_hull(&pts[..2]).len(),
            2,
            "two points are their own hull"
        );
    }

    #[test]
    fn env_choice_reads_known_values_and_ignores_others() {
        let var = "DREAMSCENE_TEST_ENV_CHOICE";
        let choices = [("a", 1), ("b", 2)];
        std::env::remove_var(var);
        assert_eq!(env_choice(var, &choices), None);
        std::env::set_var(var, "b");
        assert_eq!(env_choice(var, &choices), Some(2));
        std::env::set_var(var, "c");
        assert_eq!(env_choice(var, &choices), None);
        std::env::remove_var(var);
    }
}
