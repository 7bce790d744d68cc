//! `dreamscene export` checked by independent readers installed by `scripts/setup.sh` from
//! `tests/node/package.json` and its lock file: PlayCanvas `splat-transform` (reads PLY, .splat
//! and .spz and writes CSV), Niantic's SPZ decoder (`@adobe/spz`, the C++ library built to
//! WebAssembly), `@gltf-transform/core` and the Khronos glTF validator. A missing Node.js or
//! package fails these tests with what to run; none is skipped.
//!
//! Tolerances are each format's quantisation, stated where they are used: PLY and the float
//! fields of .splat and .glb are exact; bytes are half a step (+1e-6 for float arithmetic).
use dreamscene::splat::ply::read_ply;
use export_support::*;
use serde_json::Value;
use std::path::Path;
use std::process::Command;

mod common;
#[allow(dead_code, reason = "this test uses some of the shared export helpers")]
mod export_support;

#[test]
fn ply_export_reads_back_exactly_in_splat_transform() {
    require_readers();
    let dir = tempdir("ply");
    let g = cloud(1, 64, 2);
    let input = input_ply(&dir, &g);
    let per = g.coeffs() - 1;
    // f_rest is channel-major: all R coefficients, then G, then B.
    let rest = |c: usize, ch: usize| format!("f_rest_{}", ch * per + c - 1);

    // --scene-frame: the cloud itself, every float exact.
    let out = dir.join("scene-frame.ply");
    export_ok(&input, "ply", &out, &["--scene-frame"]);
    let t = splat_transform_csv(&out);
    assert_eq!(t.rows.len(), g.len());
    for i in 0..g.len() {
        let f = |name: &str| t.get(i, name) as f32;
        assert_eq!([f("x"), f("y"), f("z")], g.means[i], "position {i}");
        assert_eq!([f("scale_0"), f("scale_1"), f("scale_2")], g.scales[i]);
        assert_eq!(
            [f("rot_0"), f("rot_1"), f("rot_2"), f("rot_3")],
            g.rotations[i]
        );
        assert_eq!(f("opacity"), g.opacities[i]);
        for ch in 0..3 {
            assert_eq!(f(&format!("f_dc_{ch}")) as f64, sh(&g, i, 0, ch));
            for c in 1..=per {
                let v = f(&rest(c, ch)) as f64;
                assert_eq!(
                    v,
                    sh(&g, i, c, ch),
                    "Gaussian {i} coefficient {c} channel {ch}"
                );
            }
        }
    }

    // The default: the viewers' frame, x right, y down, z forward. Positions map exactly (a
    // signed axis permutation); rotations compose with the frame's; the view-dependent colour
    // seen from a world direction is the same as seen from that direction in the new frame.
    let out = dir.join("viewer.ply");
    export_ok(&input, "ply", &out, &[]);
    let t = splat_transform_csv(&out);
    let mut rng = common::rng(10);
    let mut worst_sh = 0.0f64;
    for i in 0..g.len() {
        let f = |name: &str| t.get(i, name);
        let want = apply(&RDF, g.means[i].map(f64::from)).map(|v| v as f32);
        assert_eq!(
            [f("x"), f("y"), f("z")].map(|v| v as f32),
            want,
            "position {i}"
        );
        let q = [f("rot_0"), f("rot_1"), f("rot_2"), f("rot_3")];
        let want = mat_mul(&RDF, &rot(g.rotations[i].map(f64::from)));
        assert!(rot_diff(&rot(q), &want) < 1e-6, "rotation {i}");
        assert_eq!(
            [f("scale_0"), f("scale_1"), f("scale_2")].map(|v| v as f32),
            g.scales[i]
        );
        assert_eq!(f("opacity") as f32, g.opacities[i]);
        let framed = |c: usize, ch: usize| {
            if c == 0 {
                f(&format!("f_dc_{ch}"))
            } else if c <= per {
                f(&rest(c, ch))
            } else {
                0.0
            }
        };
        let world = |c: usize, ch: usize| if c <= per { sh(&g, i, c, ch) } else { 0.0 };
        worst_sh = worst_sh.max(sh_frame_diff(&RDF, world, framed, &mut rng));
    }
    println!("ply: worst view-dependent colour difference in the viewer frame {worst_sh:.2e}");
    assert!(worst_sh < 1e-5, "SH rotation off by {worst_sh}");
}

#[test]
fn compat_ply_has_248_byte_vertices_with_degree_3_and_normals() {
    require_readers();
    let dir = tempdir("compat");
    let g = cloud(2, 40, 1);
    let input = input_ply(&dir, &g);
    let out = dir.join("compat.ply");
    export_ok(&input, "ply", &out, &["--compat", "--scene-frame"]);
    let bytes = std::fs::read(&out).unwrap();
    let end = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .unwrap()
        + 11;
    assert_eq!(bytes.len() - end, 248 * g.len(), "248 bytes a vertex");
    let header = String::from_utf8_lossy(&bytes[..end]);
    for p in ["nx", "ny", "nz", "f_rest_44"] {
        assert!(header.contains(&format!("property float {p}\n")), "{p}");
    }
    let t = splat_transform_csv(&out);
    assert_eq!(t.rows.len(), g.len());
    for i in 0..g.len() {
        for n in ["nx", "ny", "nz"] {
            assert_eq!(t.get(i, n), 0.0);
        }
        for ch in 0..3 {
            for c in 1..16 {
                let v = t.get(i, &format!("f_rest_{}", ch * 15 + c - 1));
                let want = if c < 4 { sh(&g, i, c, ch) } else { 0.0 };
                assert_eq!(v, want, "Gaussian {i} coefficient {c} channel {ch}");
            }
        }
        assert_eq!(t.get(i, "opacity") as f32, g.opacities[i]);
    }
    // The padded file is still a cloud of the same Gaussians for the project's own reader.
    let back = read_ply(&out).unwrap();
    assert_eq!(back.sh_degree, 3);
    assert_eq!(back.means, g.means);
}

#[test]
fn splat_export_is_importance_ordered_and_within_byte_quantisation() {
    require_readers();
    let dir = tempdir("splat");
    let g = cloud(3, 200, 1);
    let input = input_ply(&dir, &g);
    let out = dir.join("out.splat");
    export_ok(&input, "splat", &out, &[]);
    assert_eq!(std::fs::metadata(&out).unwrap().len(), 32 * g.len() as u64);
    let t = splat_transform_csv(&out);
    assert_eq!(t.rows.len(), g.len());
    // antimatter15's writers order by descending exp(s0 + s1 + s2) * sigmoid(opacity).
    let importance = |i: usize| {
        let s: f64 = g.scales[i].iter().map(|&v| f64::from(v)).sum();
        s.exp() * sigmoid(f64::from(g.opacities[i]))
    };
    let mut order: Vec<usize> = (0..g.len()).collect();
    order.sort_by(|&a, &b| importance(b).total_cmp(&importance(a)));
    let (mut worst_colour, mut worst_alpha, mut worst_rot) = (0.0f64, 0.0f64, 0.0f64);
    for (row, &i) in order.iter().enumerate() {
        let f = |name: &str| t.get(row, name);
        // Positions (in the viewers' RDF frame) and linear scales are float32 in the file: exact
        // (scale via exp/log in f32).
        let want = apply(&RDF, g.means[i].map(f64::from)).map(|v| v as f32);
        assert_eq!(
            [f("x") as f32, f("y") as f32, f("z") as f32],
            want,
            "row {row} holds Gaussian {i}"
        );
        for a in 0..3 {
            let s = f(&format!("scale_{a}"));
            assert!((s - f64::from(g.scales[i][a])).abs() < 1e-5, "scale {i}");
        }
        // Colours and alpha are bytes: within half a step of 1/255.
        for ch in 0..3 {
            let got = 0.5 + SH_C0 * f(&format!("f_dc_{ch}"));
            let want = 0.5 + SH_C0 * sh(&g, i, 0, ch);
            worst_colour = worst_colour.max((got - want).abs());
        }
        let alpha = sigmoid(f("opacity"));
        worst_alpha = worst_alpha.max((alpha - sigmoid(f64::from(g.opacities[i]))).abs());
        // Quaternion bytes q*128+128; splat-transform decodes b/255*2-1 and renormalises: the
        // two decodings differ by up to 1/128 a component, so the rotation is compared as a
        // rotation within 0.03 (about 1.7 degrees).
        let q = [f("rot_0"), f("rot_1"), f("rot_2"), f("rot_3")];
        let want = mat_mul(&RDF, &rot(g.rotations[i].map(f64::from)));
        worst_rot = worst_rot.max(rot_diff(&rot(q), &want));
    }
    println!(
        "splat: worst colour {worst_colour:.2e}, alpha {worst_alpha:.2e}, rotation {worst_rot:.2e}"
    );
    assert!(worst_colour <= 0.5 / 255.0 + 1e-6, "colour {worst_colour}");
    assert!(worst_alpha <= 0.5 / 255.0 + 1e-6, "alpha {worst_alpha}");
    assert!(worst_rot <= 0.03, "rotation {worst_rot}");
}

/// SPZ version 2 quantisation steps (nianticlabs/spz load-spz.cc), as half-step tolerances.
const SPZ_POSITION_TOL: f64 = 0.5 / 4096.0 + 1e-6; // 12 fractional bits
const SPZ_LOG_SCALE_TOL: f64 = 0.5 / 16.0 + 1e-5; // (s + 10) * 16
const SPZ_ALPHA_TOL: f64 = 0.5 / 255.0 + 1e-6; // sigmoid * 255
const SPZ_DC_TOL: f64 = 0.5 / (0.15 * 255.0) + 1e-5; // dc * 0.15 * 255 + 127.5
/// x * 128 + 128 rounded (half a step), then snapped to buckets of 8 (band 1) or 16 (bands 2-3).
const SPZ_SH1_TOL: f64 = 4.5 / 128.0 + 1e-6;
const SPZ_SH_REST_TOL: f64 = 8.5 / 128.0 + 1e-6;
/// Version 2 stores x, y, z of the unit quaternion (w made non-negative) in 1/127.5 steps and
/// rebuilds w from them, so x, y, z are within half a step. (w itself is only as good as
/// sqrt(1 - x² - y² - z²) allows: near w = 0 a small step in x, y, z moves it by up to ~0.12, the
/// reason SPZ version 3 stores the smallest three components instead.)
const SPZ_QUAT_TOL: f64 = 0.5 / 127.5 + 1e-6;

/// Largest difference of the vector parts (x, y, z) of unit quaternions `a` and `b`, both given
/// (w, x, y, z) and taken with w >= 0.
fn quat_xyz_diff(a: [f64; 4], b: [f64; 4]) -> f64 {
    let canon = |q: [f64; 4]| {
        let q = unit(q);
        if q[0] < 0.0 {
            q.map(|v| -v)
        } else {
            q
        }
    };
    let (a, b) = (canon(a), canon(b));
    (1..4).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max)
}

fn spz_sh_tol(c: usize) -> f64 {
    if c <= 3 {
        SPZ_SH1_TOL
    } else {
        SPZ_SH_REST_TOL
    }
}

#[test]
fn spz_v2_decodes_in_niantics_reader_and_splat_transform() {
    require_readers();
    let dir = tempdir("spz");
    let g = cloud(4, 150, 3);
    let input = input_ply(&dir, &g);
    // In the scene frame the writer's input is the cloud itself, so Niantic's frame conversion
    // and quantisation are checked coefficient by coefficient; the default frame is checked last.
    let out = dir.join("out.spz");
    export_ok(&input, "spz", &out, &["--scene-frame"]);

    // The container: gzip around the 16-byte legacy header, version 2, 12 fractional bits.
    let mut raw = Vec::new();
    std::io::Read::read_to_end(
        &mut flate2::read::GzDecoder::new(std::fs::File::open(&out).unwrap()),
        &mut raw,
    )
    .unwrap();
    assert_eq!(&raw[0..4], b"NGSP");
    assert_eq!(u32::from_le_bytes(raw[4..8].try_into().unwrap()), 2);
    assert_eq!(
        u32::from_le_bytes(raw[8..12].try_into().unwrap()),
        g.len() as u32
    );
    assert_eq!(&raw[12..16], &[3, 12, 0, 0]);

    // 1. Niantic's decoder converting back to the PLY (RDF) frame gives the cloud itself.
    let c = reader_json("spz", &out);
    assert_eq!(c["numPoints"].as_u64(), Some(g.len() as u64));
    assert_eq!(c["shDegree"].as_u64(), Some(3));
    let (pos, scales, rots) = (
        floats(&c["positions"]),
        floats(&c["scales"]),
        floats(&c["rotations"]),
    );
    let (alphas, colors, shs) = (floats(&c["alphas"]), floats(&c["colors"]), floats(&c["sh"]));
    for i in 0..g.len() {
        for a in 0..3 {
            let d = (pos[3 * i + a] - f64::from(g.means[i][a])).abs();
            assert!(d <= SPZ_POSITION_TOL, "position {i}.{a} off by {d}");
            let d = (scales[3 * i + a] - f64::from(g.scales[i][a])).abs();
            assert!(d <= SPZ_LOG_SCALE_TOL, "log scale {i}.{a} off by {d}");
            let d = (colors[3 * i + a] - sh(&g, i, 0, a)).abs();
            assert!(d <= SPZ_DC_TOL, "colour {i}.{a} off by {d}");
        }
        let d = (sigmoid(alphas[i]) - sigmoid(f64::from(g.opacities[i]))).abs();
        assert!(d <= SPZ_ALPHA_TOL, "alpha {i} off by {d}");
        // The library's quaternions are (x, y, z, w).
        let q = [
            rots[4 * i + 3],
            rots[4 * i],
            rots[4 * i + 1],
            rots[4 * i + 2],
        ];
        let d = quat_xyz_diff(q, g.rotations[i].map(f64::from));
        assert!(d <= SPZ_QUAT_TOL, "rotation {i} off by {d}");
        // The library's SH are coefficient-major, channel-inner.
        for c in 1..16 {
            for ch in 0..3 {
                let got = shs[(i * 15 + c - 1) * 3 + ch];
                let d = (got - sh(&g, i, c, ch)).abs();
                assert!(
                    d <= spz_sh_tol(c),
                    "SH {i} coefficient {c} channel {ch} off by {d}"
                );
            }
        }
    }

    // 2. splat-transform decodes SPZ without a frame conversion: it must see the stored RUB
    // frame, y and z negated. Quaternions follow the reflection (x, -y, -z of the vector part)
    // and each SH coefficient takes the parity of its basis function, computed here from the
    // basis itself.
    let flip = |v: [f64; 3]| [v[0], -v[1], -v[2]];
    let probe = unit([0.3, -0.5, 0.7, 0.0]);
    let probe = [probe[0], probe[1], probe[2]];
    let (b, bf) = (basis(probe), basis(flip(probe)));
    let parity: Vec<f64> = (0..16).map(|c| (bf[c] / b[c]).round()).collect();
    let t = splat_transform_csv(&out);
    assert_eq!(t.rows.len(), g.len());
    for i in 0..g.len() {
        let m = flip(g.means[i].map(f64::from));
        for (a, name) in ["x", "y", "z"].into_iter().enumerate() {
            let d = (t.get(i, name) - m[a]).abs();
            assert!(
                d <= SPZ_POSITION_TOL,
                "splat-transform position {i}.{a} off by {d}"
            );
        }
        let [w, x, y, z] = g.rotations[i].map(f64::from);
        let q = [0, 1, 2, 3].map(|k| t.get(i, &format!("rot_{k}")));
        let d = quat_xyz_diff(q, [w, x, -y, -z]);
        assert!(d <= SPZ_QUAT_TOL, "splat-transform rotation {i} off by {d}");
        for ch in 0..3 {
            for (c, sign) in parity.iter().enumerate().skip(1) {
                let got = t.get(i, &format!("f_rest_{}", ch * 15 + c - 1));
                let d = (got - sign * sh(&g, i, c, ch)).abs();
                assert!(
                    d <= spz_sh_tol(c),
                    "splat-transform SH {i}.{c}.{ch} off by {d}"
                );
            }
        }
    }

    // The default frame: the scene turned into RDF (x right, y down, z forward), which Niantic's
    // reader gives back when asked for RDF; splat-transform sees the stored RUB frame, y up.
    let out = dir.join("viewer.spz");
    export_ok(&input, "spz", &out, &[]);
    let c = reader_json("spz", &out);
    let pos = floats(&c["positions"]);
    let t = splat_transform_csv(&out);
    for i in 0..g.len() {
        let m = g.means[i].map(f64::from);
        let (rdf, rub) = (apply(&RDF, m), apply(&Y_UP, m));
        for (a, name) in ["x", "y", "z"].into_iter().enumerate() {
            let d = (pos[3 * i + a] - rdf[a]).abs();
            assert!(d <= SPZ_POSITION_TOL, "RDF position {i}.{a} off by {d}");
            let d = (t.get(i, name) - rub[a]).abs();
            assert!(d <= SPZ_POSITION_TOL, "RUB position {i}.{a} off by {d}");
        }
    }
}

/// Colour channel value of the glTF fallback: sRGB decoded to linear.
fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[test]
fn glb_validates_and_reads_back_in_gltf_transform() {
    require_readers();
    let dir = tempdir("glb");
    let g = cloud(5, 120, 3);
    let input = input_ply(&dir, &g);
    let out = dir.join("out.glb");
    export_ok(&input, "glb", &out, &[]);

    // The Khronos validator (2.0.0-dev.3.10, the newest on npm) predates KHR_gaussian_splatting:
    // it says so (UNSUPPORTED_EXTENSION, an info) and flags the extension's attribute names,
    // and must find nothing else.
    let report = reader_json("validate", &out);
    let ext_attr = "/meshes/0/primitives/0/attributes/KHR_gaussian_splatting:";
    let mut unknown_attrs = 0;
    for m in report["issues"]["messages"].as_array().unwrap() {
        let (code, pointer) = (
            m["code"].as_str().unwrap(),
            m["pointer"].as_str().unwrap_or(""),
        );
        if code == "MESH_PRIMITIVE_INVALID_ATTRIBUTE" && pointer.starts_with(ext_attr) {
            unknown_attrs += 1;
        } else {
            assert!(
                code == "UNSUPPORTED_EXTENSION" && m["severity"].as_u64() == Some(2),
                "validator: {m}"
            );
        }
    }
    // ROTATION, SCALE, OPACITY and 16 SH coefficients.
    assert_eq!(unknown_attrs, 3 + 16, "{report}");
    // The same file with those attributes renamed to application-specific semantics ("_" + name,
    // which the core specification allows) validates with no error and no warning: accessors,
    // bounds, views, alignment and the GLB container are all valid glTF 2.0.
    assert_renamed_validates_clean(&std::fs::read(&out).unwrap(), &dir.join("renamed.glb"));

    // An independent glTF reader gives back the attributes, in glTF's y-up frame: the project's
    // world (x, y, z) is (x, z, -y) there.
    let doc = reader_json("gltf", &out);
    assert_eq!(doc["mode"].as_u64(), Some(0), "POINTS");
    assert_eq!(
        doc["extensionsUsed"],
        serde_json::json!(["KHR_gaussian_splatting"])
    );
    let ext = &doc["primitiveExtensions"]["KHR_gaussian_splatting"];
    assert_eq!(ext["kernel"], "ellipse");
    assert_eq!(ext["colorSpace"], "srgb_rec709_display");
    let attr = |name: &str| {
        let a = &doc["attributes"][name];
        assert!(a.is_object(), "no attribute {name}: {}", doc["attributes"]);
        floats(&a["values"])
    };
    let k = "KHR_gaussian_splatting:";
    let (pos, rots, scales, op, colour) = (
        attr("POSITION"),
        attr(&format!("{k}ROTATION")),
        attr(&format!("{k}SCALE")),
        attr(&format!("{k}OPACITY")),
        attr("COLOR_0"),
    );
    let coeffs: Vec<Vec<f64>> = (0..=3)
        .flat_map(|l| (0..2 * l + 1).map(move |m| (l, m)))
        .map(|(l, m)| attr(&format!("{k}SH_DEGREE_{l}_COEF_{m}")))
        .collect();
    assert_eq!(coeffs.len(), 16);
    let mut rng = common::rng(50);
    let mut worst_sh = 0.0f64;
    for i in 0..g.len() {
        let [x, y, z] = g.means[i];
        assert_eq!(
            [pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]].map(|v| v as f32),
            [x, z, -y]
        );
        // glTF quaternions are (x, y, z, w) and unit length; the rotation is the frame change
        // applied after the Gaussian's own.
        let q = [
            rots[4 * i + 3],
            rots[4 * i],
            rots[4 * i + 1],
            rots[4 * i + 2],
        ];
        let norm = q.iter().map(|v| v * v).sum::<f64>().sqrt();
        assert!((norm - 1.0).abs() < 1e-6, "unit quaternion {i}: {norm}");
        let want = mat_mul(&Y_UP, &rot(g.rotations[i].map(f64::from)));
        assert!(rot_diff(&rot(q), &want) < 1e-6, "rotation {i}");
        for a in 0..3 {
            let s = f64::from(g.scales[i][a]).exp();
            assert!(
                (scales[3 * i + a] - s).abs() <= 1e-6 * s,
                "linear scale {i}.{a}"
            );
        }
        let alpha = sigmoid(f64::from(g.opacities[i]));
        assert!((op[i] - alpha).abs() < 1e-6, "opacity {i}");
        for ch in 0..3 {
            assert_eq!(
                coeffs[0][3 * i + ch] as f32 as f64,
                sh(&g, i, 0, ch),
                "DC {i}"
            );
            // COLOR_0: the diffuse colour decoded to linear, in normalised bytes (half a step).
            let c = srgb_to_linear((0.5 + SH_C0 * sh(&g, i, 0, ch)).clamp(0.0, 1.0));
            assert!(
                (colour[4 * i + ch] - c).abs() <= 0.5 / 255.0 + 1e-6,
                "COLOR_0 {i}"
            );
        }
        assert!(
            (colour[4 * i + 3] - alpha).abs() <= 0.5 / 255.0 + 1e-6,
            "COLOR_0 alpha {i}"
        );
        // View-dependent colour: seen from a world direction, the glTF coefficients evaluated at
        // the same direction in glTF's frame give the same colour.
        let world = |c: usize, ch: usize| sh(&g, i, c, ch);
        let gltf = |c: usize, ch: usize| coeffs[c][3 * i + ch];
        worst_sh = worst_sh.max(sh_frame_diff(&Y_UP, world, gltf, &mut rng));
    }
    println!("glb: worst view-dependent colour difference {worst_sh:.2e}");
    assert!(worst_sh < 1e-5, "SH rotation off by {worst_sh}");
}

#[test]
fn glb_builder_writes_one_node_per_instance() {
    require_readers();
    use dreamscene::export::glb::{to_gltf_frame, GlbBuilder, NodeTransform};
    let dir = tempdir("glb-nodes");
    let mut b = GlbBuilder::new();
    let chair = b
        .add_splats("chair", &to_gltf_frame(&cloud(8, 30, 1)))
        .unwrap();
    let lamp = b
        .add_splats("lamp", &to_gltf_frame(&cloud(9, 20, 1)))
        .unwrap();
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let placed = |x: f64| NodeTransform {
        translation: Some([x, 0.0, 0.0]),
        rotation: Some([0.0, h, 0.0, h]),
        scale: None,
    };
    b.add_node("chair1", chair, placed(1.0));
    b.add_node("chair2", chair, placed(-1.0));
    b.add_node("lamp1", lamp, NodeTransform::default());
    let out = dir.join("instances.glb");
    std::fs::write(&out, b.finish().unwrap()).unwrap();
    assert_renamed_validates_clean(&std::fs::read(&out).unwrap(), &dir.join("renamed.glb"));
    let doc = reader_json("gltf", &out);
    assert_eq!(doc["meshes"].as_u64(), Some(2));
    assert_eq!(doc["nodes"].as_u64(), Some(3));
}

#[test]
fn a_generated_draft_scene_directory_exports_its_merged_cloud() {
    require_readers();
    let dir = tempdir("draft");
    let scene = dir.join("bedroom");
    draft_scene("a small bedroom", &scene);
    let merged = read_ply(&scene.join("scene.ply")).unwrap();
    assert!(merged.len() > 10_000, "{} Gaussians", merged.len());
    let out = dir.join("bedroom.spz");
    export_ok(&scene, "spz", &out, &[]);
    // splat-transform's statistics of what it decodes: the stored RUB frame, the scene y up.
    let o = Command::new(node_dir().join("node_modules/.bin/splat-transform"))
        .args(["-q"])
        .arg(&out)
        .args(["--stats", "json", "null"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stats: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(stats["numGaussians"].as_u64(), Some(merged.len() as u64));
    let s = &stats["stats"][0];
    let cols: Vec<&str> = s["columns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    let (lo, hi) = (floats(&s["data"]["min"]), floats(&s["data"]["max"]));
    for (a, name) in ["x", "y", "z"].into_iter().enumerate() {
        let j = cols.iter().position(|c| *c == name).unwrap();
        let vals = merged
            .means
            .iter()
            .map(|m| apply(&Y_UP, m.map(f64::from))[a]);
        let (want_lo, want_hi) = vals.fold((f64::MAX, f64::MIN), |(l, h), v| (l.min(v), h.max(v)));
        // splat-transform prints statistics to 7 significant digits.
        let tol = SPZ_POSITION_TOL + 1e-5;
        assert!(
            (lo[j] - want_lo).abs() <= tol,
            "{name} min {} vs {want_lo}",
            lo[j]
        );
        assert!(
            (hi[j] - want_hi).abs() <= tol,
            "{name} max {} vs {want_hi}",
            hi[j]
        );
    }

    // The directory's cloud is composed from scene.json, objects/ and environment.ply: without
    // scene.ply it is still exactly the cloud generate wrote there.
    std::fs::remove_file(scene.join("scene.ply")).unwrap();
    let again = dir.join("composed.ply");
    export_ok(&scene, "ply", &again, &["--scene-frame"]);
    let composed = read_ply(&again).unwrap();
    assert_eq!(composed.len(), merged.len());
    assert_eq!(composed, merged);
}

#[test]
fn bad_input_fails_with_one_line_and_keeps_the_old_output() {
    let dir = tempdir("bad");
    let out = dir.join("keep.spz");
    std::fs::write(&out, b"old").unwrap();
    let not_scene = dir.join("empty-dir");
    std::fs::create_dir_all(&not_scene).unwrap();
    let mut nan = cloud(6, 3, 0);
    nan.means[1][2] = f32::NAN;
    let nan_ply = dir.join("nan.ply");
    dreamscene::splat::ply::write_ply(&nan_ply, &nan).unwrap();
    let far = {
        let mut g = cloud(7, 2, 0);
        g.means[0][0] = 3000.0;
        let p = dir.join("far.ply");
        dreamscene::splat::ply::write_ply(&p, &g).unwrap();
        p
    };
    let garbage = dir.join("garbage.ply");
    std::fs::write(&garbage, b"not a ply").unwrap();
    let cases: [(&Path, &str, &[&str], &str); 7] = [
        (&dir.join("missing.ply"), "spz", &[], "not found"),
        (&not_scene, "spz", &[], "not a scene directory"),
        (&garbage, "spz", &[], "PLY"),
        (&nan_ply, "spz", &[], "not finite"),
        (&far, "spz", &[], "2048"),
        (&far, "spz", &["--compat"], "--compat"),
        (&far, "glb", &["--scene-frame"], "y up"),
    ];
    for (input, format, extra, expect) in cases {
        let o = export(input, format, &out, extra);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{} was accepted", input.display());
        assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
        assert!(err.starts_with("error: ") && err.contains(expect), "{err}");
        assert_eq!(std::fs::read(&out).unwrap(), b"old", "output kept");
    }
}
