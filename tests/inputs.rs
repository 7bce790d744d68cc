//! Input files as common tools write them, and malformed ones: PLY encodings and property types,
//! non-finite values, hostile headers, cameras.json names and rotations, files of the wrong kind.
//! No device needed.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
#[path = "inputs/props.rs"]
mod props;
use dreamscene::camera::{parse_cameras, read_cameras, write_cameras, Camera};
use dreamscene::plan::spec::{Layout, SceneSpec};
use dreamscene::splat::ply::{parse_ply, read_ply, read_ply_with, write_ply, Invalid};
use dreamscene::splat::Gaussians;
use std::path::{Path, PathBuf};

fn tempdir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("dreamscene-inputs-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[derive(Clone, Copy, PartialEq)]
enum Enc {
    Ascii,
    Little,
    Big,
}

/// A splat PLY written independently of the project's writer: the splat properties as `ty`
/// (`float` or `double`), with `uchar red green blue` after the positions, an `element camera`
/// before `vertex` and a `face` list element after it, in encoding `enc`.
fn foreign_ply(g: &Gaussians, enc: Enc, ty: &str) -> Vec<u8> {
    let k = g.coeffs();
    let mut names: Vec<String> = ["x", "y", "z"].map(String::from).to_vec();
    let colour = ["red", "green", "blue"];
    let mut tail: Vec<String> = ["nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"]
        .map(String::from)
        .to_vec();
    tail.extend((0..3 * (k - 1)).map(|i| format!("f_rest_{i}")));
    tail.push("opacity".into());
    tail.extend((0..3).map(|i| format!("scale_{i}")));
    tail.extend((0..4).map(|i| format!("rot_{i}")));
    let format = match enc {
        Enc::Ascii => "ascii",
        Enc::Little => "binary_little_endian",
        Enc::Big => "binary_big_endian",
    };
    let mut h = format!("ply\nformat {format} 1.0\ncomment made by a test\n");
    h += "element camera 2\nproperty float view_px\nproperty uchar flag\nproperty list uchar int ids\n";
    h += &format!("element vertex {}\n", g.len());
    for n in &names {
        h += &format!("property {ty} {n}\n");
    }
    for c in colour {
        h += &format!("property uchar {c}\n");
    }
    for n in &tail {
        h += &format!("property {ty} {n}\n");
    }
    h += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    names.extend(tail);
    let mut out = h.into_bytes();
    let num = |out: &mut Vec<u8>, v: f64, ty: &str| match (enc, ty) {
        (Enc::Ascii, _) => out.extend(format!("{v:?} ").bytes()),
        (Enc::Little, "float") => out.extend((v as f32).to_le_bytes()),
        (Enc::Big, "float") => out.extend((v as f32).to_be_bytes()),
        (Enc::Little, "double") => out.extend(v.to_le_bytes()),
        (Enc::Big, "double") => out.extend(v.to_be_bytes()),
        (Enc::Little | Enc::Big, "uchar") => out.push(v as u8),
        (Enc::Little, "int") => out.extend((v as i32).to_le_bytes()),
        (Enc::Big, "int") => out.extend((v as i32).to_be_bytes()),
        _ => unreachable!(),
    };
    let nl = |out: &mut Vec<u8>| {
        if enc == Enc::Ascii {
            out.push(b'\n')
        }
    };
    for cam in 0..2 {
        num(&mut out, 0.5, "float");
        num(&mut out, 1.0, "uchar");
        num(&mut out, 2.0, "uchar");
        num(&mut out, cam as f64, "int");
        num(&mut out, 7.0, "int");
        nl(&mut out);
    }
    for i in 0..g.len() {
        let mut row: Vec<f64> = g.means[i].iter().map(|&v| v as f64).collect();
        row.extend([0.0; 3]);
        row.extend((0..3).map(|ch| g.sh[i * k * 3 + ch] as f64));
        for ch in 0..3 {
            for c in 1..k {
                row.push(g.sh[(i * k + c) * 3 + ch] as f64);
            }
        }
        row.push(g.opacities[i] as f64);
        row.extend(g.scales[i].map(|v| v as f64));
        row.extend(g.rotations[i].map(|v| v as f64));
        for (j, v) in row.iter().enumerate() {
            num(&mut out, *v, ty);
            if j == 2 {
                for c in [200.0, 100.0, 50.0] {
                    num(&mut out, c, "uchar");
                }
            }
        }
        nl(&mut out);
    }
    num(&mut out, 3.0, "uchar");
    for v in [0.0, 1.0, 2.0] {
        num(&mut out, v, "int");
    }
    nl(&mut out);
    out
}

#[test]
fn ply_reads_ascii_big_endian_double_and_extra_properties() {
    let mut rng = common::rng(40);
    for deg in [0, 3] {
        let g = Gaussians::random(&mut rng, 23, [-2.0; 3], [2.0; 3], 0.1, deg);
        for enc in [Enc::Ascii, Enc::Little, Enc::Big] {
            for ty in ["float", "double"] {
                let bytes = foreign_ply(&g, enc, ty);
                let r = parse_ply(&mut bytes.as_slice(), Invalid::Refuse)
                    .unwrap_or_else(|e| panic!("degree {deg} {ty}: {e}"));
                assert_eq!(r.gaussians, g, "degree {deg} {ty}");
                assert_eq!(r.dropped, 0);
            }
        }
    }
}

#[test]
fn ply_integer_splat_properties_are_refused_by_name() {
    let g = Gaussians::random(&mut common::rng(41), 2, [-1.0; 3], [1.0; 3], 0.1, 0);
    let text = String::from_utf8_lossy(&foreign_ply(&g, Enc::Ascii, "float"))
        .replace("property float opacity", "property uchar opacity");
    let e = parse_ply(&mut text.as_bytes(), Invalid::Refuse).unwrap_err();
    assert!(e.contains("`opacity`") && e.contains("float"), "{e}");
}

/// NaN, ±Inf, a double beyond f32 and a zero quaternion: refused with the count and the first
/// vertex, or dropped on request.
#[test]
fn ply_non_finite_or_degenerate_gaussians_are_refused_or_dropped() {
    let mut g = Gaussians::random(&mut common::rng(42), 12, [-1.0; 3], [1.0; 3], 0.1, 1);
    let keep = g.clone();
    g.means[3][1] = f32::NAN;
    g.scales[5][0] = f32::INFINITY;
    g.rotations[9] = [0.0; 4];
    let dir = tempdir("nan");
    let p = dir.join("nan.ply");
    write_ply(&p, &g).unwrap();
    let e = read_ply(&p).unwrap_err().to_string();
    assert!(
        e.contains("nan.ply")
            && e.contains("3 of 12")
            && e.contains("vertex 3")
            && e.contains("`y`"),
        "{e}"
    );
    let r = read_ply_with(&p, Invalid::Drop).unwrap();
    assert_eq!(r.dropped, 3);
    let mut want = keep.clone();
    for i in [9, 5, 3] {
        want.means.remove(i);
        want.scales.remove(i);
        want.rotations.remove(i);
        want.opacities.remove(i);
        want.sh.drain(i * 12..(i + 1) * 12);
    }
    assert_eq!(r.gaussians, want);
    // A double too large for a 32-bit float is not finite once read.
    let mut big = foreign_ply(&keep, Enc::Ascii, "double");
    let text = String::from_utf8(big.clone()).unwrap();
    let at = text.find("end_header\n").unwrap() + 11;
    let body_start = text[at..].find('\n').unwrap() + at + 1; // after the first camera row
    let body_start = text[body_start..].find('\n').unwrap() + body_start + 1;
    let first_value_end = text[body_start..].find(' ').unwrap() + body_start;
    big.splice(body_start..first_value_end, b"1e300".iter().copied());
    let e = parse_ply(&mut big.as_slice(), Invalid::Refuse).unwrap_err();
    assert!(
        e.contains("vertex 0") && e.contains("`x`") && e.contains("1e300"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A header that claims 10^12 vertices (or a 10^12-row element before them) on a short file is a
/// quick "truncated" error: nothing is allocated or looped by the claimed count.
#[test]
fn ply_huge_counts_in_the_header_neither_allocate_nor_hang() {
    let g = Gaussians::random(&mut common::rng(43), 3, [-1.0; 3], [1.0; 3], 0.1, 0);
    let started = std::time::Instant::now();
    for enc in [Enc::Ascii, Enc::Little] {
        let text = foreign_ply(&g, enc, "float");
        let huge = |from: &str, to: &str| {
            let at = text
                .windows(from.len())
                .position(|w| w == from.as_bytes())
                .unwrap();
            [&text[..at], to.as_bytes(), &text[at + from.len()..]].concat()
        };
        for (from, to) in [
            ("element vertex 3", "element vertex 1000000000000"),
            ("element camera 2", "element camera 1000000000000"),
            ("element vertex 3", "element vertex 18446744073709551615"),
        ] {
            let bytes = huge(from, to);
            let e = parse_ply(&mut bytes.as_slice(), Invalid::Refuse).unwrap_err();
            // The camera rows run into the vertex data, which fails to read as cameras.
            assert!(
                e.contains("truncated") || from.contains("camera"),
                "{to}: {e}"
            );
        }
    }
    // An element of no properties and 10^12 rows reads nothing.
    let empty = b"ply\nformat binary_little_endian 1.0\nelement nothing 1000000000000\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nproperty float f_dc_0\nproperty float f_dc_1\nproperty float f_dc_2\nproperty float opacity\nproperty float scale_0\nproperty float scale_1\nproperty float scale_2\nproperty float rot_0\nproperty float rot_1\nproperty float rot_2\nproperty float rot_3\nend_header\n";
    let r = parse_ply(&mut empty.as_slice(), Invalid::Refuse).unwrap();
    assert!(r.gaussians.is_empty());
    assert!(started.elapsed().as_secs() < 5, "{:?}", started.elapsed());
}

fn cam(id: u32, name: &str) -> Camera {
    let mut c = Camera::look_at([1.0, 2.0, 3.0], [0.0; 3], [0.0, 0.0, 1.0], 16, 16, 0.8);
    c.id = id;
    c.img_name = name.into();
    c
}

fn cams_json(cams: &[Camera]) -> Vec<u8> {
    serde_json::to_vec(cams).unwrap()
}

#[test]
fn cameras_img_names_stay_inside_the_output_and_are_unique() {
    for bad in ["../../escape", "/tmp/abs", "a/../../b", "./x", "sub/"] {
        let e = parse_cameras(&cams_json(&[cam(0, "ok"), cam(1, bad)])).unwrap_err();
        assert!(e.contains("camera 1") && e.contains(bad), "{bad}: {e}");
    }
    assert!(parse_cameras(&cams_json(&[cam(0, "sub/dir/view"), cam(1, "top")])).is_ok());
    let e = parse_cameras(&cams_json(&[cam(0, "same"), cam(4, "same")])).unwrap_err();
    assert!(e.contains("cameras 0 and 4") && e.contains("`same`"), "{e}");
    // An empty name stands for the id as five digits, which another camera may not take.
    let e = parse_cameras(&cams_json(&[cam(7, ""), cam(8, "00007")])).unwrap_err();
    assert!(e.contains("00007"), "{e}");
}

#[test]
fn cameras_whose_rotation_is_not_a_rotation_are_refused_by_name() {
    let good = cam(0, "fine");
    let twice = |c: &Camera| {
        let mut c = c.clone();
        c.rotation = c.rotation.map(|r| r.map(|v| 2.0 * v));
        c
    };
    let zero = |c: &Camera| {
        let mut c = c.clone();
        c.rotation = [[0.0; 3]; 3];
        c
    };
    let mirror = |c: &Camera| {
        let mut c = c.clone();
        c.rotation[0] = c.rotation[0].map(|v| -v);
        c
    };
    for (i, f) in [twice, zero, mirror].iter().enumerate() {
        let mut bad = f(&good);
        bad.id = 3;
        bad.img_name = format!("bad{i}");
        let e = parse_cameras(&cams_json(&[good.clone(), bad])).unwrap_err();
        assert!(
            e.contains("camera 3") && e.contains(&format!("bad{i}")) && e.contains("rotation"),
            "{e}"
        );
    }
    // Rounding as written with six digits is accepted.
    let mut rounded = good.clone();
    rounded.rotation = rounded.rotation.map(|r| r.map(|v| (v * 1e6).round() / 1e6));
    assert!(parse_cameras(&cams_json(&[rounded])).is_ok());
}

/// Each reader says what a file of the wrong kind looks like and what it expected.
#[test]
fn wrong_kind_files_are_named() {
    let dir = tempdir("kinds");
    let g = Gaussians::random(&mut common::rng(44), 3, [-1.0; 3], [1.0; 3], 0.1, 0);
    let ply = dir.join("s.ply");
    write_ply(&ply, &g).unwrap();
    let cameras = dir.join("cameras.json");
    write_cameras(&cameras, &[cam(0, "a")]).unwrap();
    let spec_text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/living_room.json"),
    )
    .unwrap();
    let spec_path = dir.join("spec.json");
    std::fs::write(&spec_path, &spec_text).unwrap();
    let spec = SceneSpec::read(&spec_path).unwrap();
    let layout =
        dreamscene::plan::gcp::layout(&spec, dreamscene::plan::gcp::LayoutOptions::seeded(1))
            .unwrap();
    let layout_path = dir.join("layout.json");
    layout.write(&layout_path).unwrap();
    let png = dir.join("p.png");
    image::RgbImage::new(2, 2).save(&png).unwrap();
    assert_eq!(Layout::read(&layout_path).unwrap(), layout);

    let e = read_cameras(&ply).unwrap_err().to_string();
    assert!(
        e.contains("is a PLY file") && e.contains("expected an INRIA cameras.json"),
        "{e}"
    );
    let e = read_cameras(&layout_path).unwrap_err().to_string();
    assert!(
        e.contains("looks like a layout.json") && e.contains("cameras.json"),
        "{e}"
    );
    let e = SceneSpec::read(&layout_path).unwrap_err().to_string();
    assert!(
        e.contains("looks like a layout.json") && e.contains("expected a spec.json"),
        "{e}"
    );
    let e = Layout::read(&spec_path).unwrap_err().to_string();
    assert!(
        e.contains("looks like a spec.json") && e.contains("expected a layout.json"),
        "{e}"
    );
    let e = Layout::read(&cameras).unwrap_err().to_string();
    assert!(e.contains("looks like a cameras.json"), "{e}");
    let e = read_ply(&cameras).unwrap_err().to_string();
    assert!(
        e.contains("looks like a cameras.json") && e.contains("expected a splat PLY"),
        "{e}"
    );
    let e = read_ply(&png).unwrap_err().to_string();
    assert!(e.contains("is a PNG image"), "{e}");
    let e = read_ply(&dir).unwrap_err().to_string();
    assert!(e.contains("is a directory"), "{e}");
    assert!(!e.contains('\n'));
    std::fs::remove_dir_all(&dir).ok();
}
