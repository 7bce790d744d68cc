//! The engine-ready glb's options, read back by outside clients: `--splats per-object` (one
//! `KHR_gaussian_splatting` primitive per instance, a child of its node in the node's frame),
//! `--colliders hull` (the 3-D convex hull of each object's opaque Gaussians, snapped to a
//! grid of at most 4 cm) and each node's
//! `style_prompt`. The glb is parsed here from the glTF definition (accessors, node transforms)
//! and judged against the scene's own `scene.ply` and `labels.json`; the Khronos validator,
//! `@gltf-transform/extensions` and Debian's Blender importer read the same file (a missing
//! Blender fails the test unless `DREAMSCENE_SKIP_EXTERNAL=blender`).
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::splat::ply::read_ply_labelled;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

mod common;
#[allow(dead_code, reason = "this test uses some of the shared export helpers")]
mod export_support;
use export_support::{export_ok, node_dir, require_readers};

/// A draft of a prompt of this test's own, exported with both options.
fn fixture() -> (PathBuf, PathBuf) {
    // One directory a worktree, replaced by each run (a directory per process was never removed).
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("engine-splats");
    let _ = std::fs::remove_dir_all(&dir);
    let scene = dir.join("study");
    let o = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args([
            "generate",
            "a study with a desk, an office chair and a bookshelf",
        ])
        .args(["--draft", "--renders", "0", "--out"])
        .arg(&scene)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let glb = dir.join("study.glb");
    export_ok(
        &scene,
        "glb",
        &glb,
        &["--splats", "per-object", "--colliders", "hull"],
    );
    (scene, glb)
}

/// A glb's JSON and binary chunks.
struct Glb {
    doc: Value,
    bin: Vec<u8>,
}

impl Glb {
    fn read(path: &Path) -> Glb {
        let bytes = std::fs::read(path).unwrap();
        let len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
        Glb {
            doc: serde_json::from_slice(&bytes[20..20 + len]).unwrap(),
            bin: bytes[20 + len + 8..].to_vec(),
        }
    }

    fn node(&self, name: &str) -> (usize, &Value) {
        let nodes = self.doc["nodes"].as_array().unwrap();
        let k = nodes
            .iter()
            .position(|n| n["name"] == name)
            .unwrap_or_else(|| panic!("no node {name}"));
        (k, &nodes[k])
    }

    fn children(&self, parent: &Value) -> Vec<&Value> {
        parent["children"]
            .as_array()
            .map(|c| {
                c.iter()
                    .map(|k| &self.doc["nodes"][k.as_u64().unwrap() as usize])
                    .collect()
            })
            .unwrap_or_default()
    }

    /// An accessor's elements as f64 (FLOAT, UNSIGNED_INT or UNSIGNED_SHORT components).
    fn accessor(&self, index: &Value) -> Vec<Vec<f64>> {
        let a = &self.doc["accessors"][index.as_u64().unwrap() as usize];
        let v = &self.doc["bufferViews"][a["bufferView"].as_u64().unwrap() as usize];
        let comps = match a["type"].as_str().unwrap() {
            "SCALAR" => 1,
            "VEC3" => 3,
            "VEC4" => 4,
            t => panic!("{t}"),
        };
        let size = match a["componentType"].as_u64().unwrap() {
            5126 | 5125 => 4,
            5123 => 2,
            t => panic!("component type {t}"),
        };
        let stride = v["byteStride"]
            .as_u64()
            .map_or(comps * size, |s| s as usize);
        let start = v["byteOffset"].as_u64().unwrap_or(0) as usize
            + a["byteOffset"].as_u64().unwrap_or(0) as usize;
        (0..a["count"].as_u64().unwrap() as usize)
            .map(|i| {
                (0..comps)
                    .map(|c| {
                        let o = start + i * stride + c * size;
                        let b = &self.bin[o..o + size];
                        match a["componentType"].as_u64().unwrap() {
                            5126 => f64::from(f32::from_le_bytes(b.try_into().unwrap())),
                            5125 => f64::from(u32::from_le_bytes(b.try_into().unwrap())),
                            _ => f64::from(u16::from_le_bytes(b.try_into().unwrap())),
                        }
                    })
                    .collect()
            })
            .collect()
    }

    fn primitive(&self, node: &Value) -> &Value {
        &self.doc["meshes"][node["mesh"].as_u64().unwrap() as usize]["primitives"][0]
    }
}

/// A node's local point to the scene frame (z up): glTF's translation and rotation (a turn
/// about +y here), then glTF (x, y, z) is scene (x, -z, y).
fn to_scene(node: &Value, p: &[f64]) -> [f64; 3] {
    let t: Vec<f64> = node["translation"].as_array().map_or(vec![0.0; 3], |a| {
        a.iter().map(|v| v.as_f64().unwrap()).collect()
    });
    let q: Vec<f64> = node["rotation"]
        .as_array()
        .map_or(vec![0.0, 0.0, 0.0, 1.0], |a| {
            a.iter().map(|v| v.as_f64().unwrap()).collect()
        });
    assert!(
        q[0].abs() < 1e-9 && q[2].abs() < 1e-9,
        "a turn about +y only: {q:?}"
    );
    let a = 2.0 * q[1].atan2(q[3]);
    let (s, c) = a.sin_cos();
    // Rotation about +y: x' = c x + s z, z' = -s x + c z.
    let g = [
        c * p[0] + s * p[2] + t[0],
        p[1] + t[1],
        -s * p[0] + c * p[2] + t[2],
    ];
    [g[0], -g[2], g[1]]
}

#[test]
fn per_object_splats_sit_under_their_nodes_and_hulls_hold_the_opaque_gaussians() {
    require_readers();
    let (scene, glb_path) = fixture();
    let glb = Glb::read(&glb_path);
    let (cloud, labels) = read_ply_labelled(&scene.join("scene.ply")).unwrap();
    let labels = labels.expect("labelled scene.ply");
    let lj: Value =
        serde_json::from_str(&std::fs::read_to_string(scene.join("labels.json")).unwrap()).unwrap();
    let spec: Value =
        serde_json::from_str(&std::fs::read_to_string(scene.join("spec.json")).unwrap()).unwrap();
    assert!(glb.doc["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .all(|n| n["name"] != "splats"));
    let mut decoded = 0;
    let mut curved = 0;
    let instances = lj["instances"].as_array().unwrap();
    for inst in &instances[1..] {
        let id = inst["id"].as_str().unwrap().replace(' ', "_");
        let k = inst["instance_id"].as_u64().unwrap() as u16;
        let (_, node) = glb.node(&id);
        let desc = &spec["objects"][inst["category"].as_str().unwrap()]["description"];
        assert_eq!(node["extras"]["style_prompt"], *desc, "{id}");
        // Its splats: a child primitive whose points, through the node's transform, are its
        // Gaussians of scene.ply (glTF frame and node frame undone here).
        let kids = glb.children(node);
        let splat = kids
            .iter()
            .find(|c| c["name"] == format!("splats_{id}"))
            .unwrap_or_else(|| panic!("{id} has no splats child"));
        let prim = glb.primitive(splat);
        assert!(prim["extensions"]["KHR_gaussian_splatting"].is_object());
        let pos = glb.accessor(&prim["attributes"]["POSITION"]);
        let mine: Vec<usize> = (0..cloud.len())
            .filter(|&i| labels.instance[i] == k)
            .collect();
        assert_eq!(pos.len(), mine.len(), "{id}");
        for (p, &i) in pos.iter().zip(&mine) {
            let w = to_scene(node, p);
            let m = cloud.means[i];
            assert!(
                (0..3).all(|a| (w[a] - f64::from(m[a])).abs() < 1e-4),
                "{id}: {w:?} vs {m:?}"
            );
        }
        let fid = glb.accessor(&prim["attributes"]["_FEATURE_ID_0"]);
        assert!(fid.iter().all(|f| f[0] == f64::from(k)));
        decoded += pos.len();
        // Its collider: a closed convex mesh holding every opaque Gaussian centre, made of them.
        let col = kids
            .iter()
            .find(|c| c["name"] == format!("collider_{id}"))
            .unwrap_or_else(|| panic!("{id} has no collider"));
        let cprim = glb.primitive(col);
        let verts: Vec<[f64; 3]> = glb
            .accessor(&cprim["attributes"]["POSITION"])
            .iter()
            .map(|p| to_scene(node, p))
            .collect();
        let tris = glb.accessor(&cprim["indices"]);
        // Its points are snapped to a grid (extras say which) before the hull is taken: every
        // Gaussian centre within half a cell's diagonal (and 1 mm) of its inside, every vertex
        // within half a cell's diagonal of a centre.
        assert_eq!(col["extras"]["shape"], "hull", "{id}");
        let step = col["extras"]["hull_grid_m"].as_f64().unwrap();
        assert!(step <= 0.04, "{id}: grid {step}");
        let opaque: Vec<[f64; 3]> = mine
            .iter()
            .filter(|&&i| cloud.opacities[i] >= 0.0)
            .map(|&i| cloud.means[i].map(f64::from))
            .collect();
        let opaque = if opaque.is_empty() {
            mine.iter()
                .map(|&i| cloud.means[i].map(f64::from))
                .collect()
        } else {
            opaque
        };
        for t in tris.chunks(3) {
            let [a, b, c] = [0, 1, 2].map(|j| verts[t[j][0] as usize]);
            let u = [0, 1, 2].map(|x| b[x] - a[x]);
            let v = [0, 1, 2].map(|x| c[x] - a[x]);
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            if l < dreamscene::export::collider::SLIVER {
                continue; // a sliver's plane is not defined by its f32 vertices
            }
            for p in &opaque {
                let d = (0..3).map(|x| n[x] * (p[x] - a[x])).sum::<f64>() / l;
                // The hull holds the grid points within 1 mm (quickhull works in f32).
                assert!(
                    d <= step * 0.87 + 1.5e-3,
                    "{id}: a Gaussian {d:.4} m outside its hull"
                );
            }
        }
        for v in &verts {
            assert!(
                opaque.iter().any(
                    |p| (0..3).map(|x| (p[x] - v[x]).powi(2)).sum::<f64>().sqrt()
                        <= step * 0.87 + 1e-4
                ),
                "{id}: hull vertex {v:?} is no Gaussian centre"
            );
        }
        // A prism has two heights of vertices; a 3-D hull of furniture has more.
        let mut zs: Vec<i64> = verts
            .iter()
            .map(|v| (v[2] * 1000.0).round() as i64)
            .collect();
        zs.sort();
        zs.dedup();
        curved += usize::from(zs.len() > 2);
        let ext = &col["extensions"];
        assert_eq!(
            ext["KHR_physics_rigid_bodies"]["collider"]["geometry"]["convexHull"],
            true
        );
        let shape = ext["OMI_physics_body"]["collider"]["shape"]
            .as_u64()
            .unwrap() as usize;
        assert_eq!(
            glb.doc["extensions"]["OMI_physics_shape"]["shapes"][shape]["type"],
            "convex"
        );
    }
    assert!(curved * 2 > instances.len() - 1, "hulls look like prisms");
    // The environment's splats at the root, in the world frame.
    let (_, env) = glb.node("splats_environment");
    let env_n = instances[0]["gaussians"][1].as_u64().unwrap() as usize;
    let pos = glb.accessor(&glb.primitive(env)["attributes"]["POSITION"]);
    assert_eq!(pos.len(), env_n);
    decoded += env_n;
    assert_eq!(decoded, cloud.len());

    // Outside readers: the validator finds only the splat attribute names it always flags, and
    // gltf-transform reads one feature id per primitive with the PLY's counts.
    let report = export_support::reader_json("validate", &glb_path);
    for m in report["issues"]["messages"].as_array().unwrap() {
        let known = m["code"] == "MESH_PRIMITIVE_INVALID_ATTRIBUTE"
            && m["pointer"]
                .as_str()
                .unwrap_or("")
                .contains("/attributes/KHR_gaussian_splatting:");
        assert!(known || m["severity"].as_u64() >= Some(2), "validator: {m}");
    }
    let o = Command::new("node")
        .current_dir(node_dir())
        .args(["engine.mjs", "features"])
        .arg(&glb_path)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let feats: Value = serde_json::from_slice(&o.stdout).unwrap();
    let mut total = 0;
    for f in feats.as_array().unwrap() {
        let h = f["histogram"].as_object().unwrap();
        assert_eq!(h.len(), 1, "{f}");
        let (k, n) = h.iter().next().unwrap();
        let k: u16 = k.parse().unwrap();
        let want = labels.instance.iter().filter(|&&i| i == k).count();
        assert_eq!(n.as_u64(), Some(want as u64), "instance {k}");
        total += want;
    }
    assert_eq!(total, cloud.len());
    blender_reads_hulls_and_style_prompts(&glb_path, &glb);
}

/// Blender's importer: every object node with its style prompt as a custom
/// property, each hull collider imported whole (all its vertices) and placed where the glb
/// says (its box as the one computed here).
fn blender_reads_hulls_and_style_prompts(path: &Path, glb: &Glb) {
    if !export_support::blender_ready() {
        return;
    }
    let o = Command::new("blender")
        .args(["-b", "--factory-startup", "--python"])
        .arg(node_dir().join("blender_import.py"))
        .arg("--")
        .arg(path)
        .output()
        .unwrap();
    let log = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.success() && !log.contains("Traceback") && !log.contains("Error"),
        "{log}"
    );
    let objs: Value = serde_json::from_str(
        log.lines()
            .find_map(|l| l.strip_prefix("RESULT "))
            .expect(&log),
    )
    .unwrap();
    for n in glb.doc["nodes"].as_array().unwrap() {
        let Some(cat) = n["extras"]["category"].as_str() else {
            continue;
        };
        let name = n["name"].as_str().unwrap();
        let b = &objs[name];
        assert_eq!(b["props"]["category"], cat, "{name}");
        assert_eq!(
            b["props"]["style_prompt"], n["extras"]["style_prompt"],
            "{name}"
        );
        let cname = format!("collider_{name}");
        let col = glb
            .children(n)
            .into_iter()
            .find(|c| c["name"] == cname.as_str())
            .unwrap();
        // Blender's box is its object's local box placed in the world: the corners of the
        // mesh's local bounds through the node's transform.
        let local = glb.accessor(&glb.primitive(col)["attributes"]["POSITION"]);
        let lo = [0, 1, 2].map(|a| local.iter().map(|v| v[a]).fold(f64::MAX, f64::min));
        let hi = [0, 1, 2].map(|a| local.iter().map(|v| v[a]).fold(f64::MIN, f64::max));
        let verts: Vec<[f64; 3]> = (0..8)
            .map(|k| {
                let c = [0, 1, 2].map(|a| if k >> a & 1 == 0 { lo[a] } else { hi[a] });
                to_scene(n, &c)
            })
            .collect();
        let bb = &objs[&cname]["world_box"];
        for a in 0..3 {
            let lo = verts.iter().map(|v| v[a]).fold(f64::MAX, f64::min);
            let hi = verts.iter().map(|v| v[a]).fold(f64::MIN, f64::max);
            assert!(
                (bb[0][a].as_f64().unwrap() - lo).abs() < 1e-3,
                "{cname}: {bb}"
            );
            assert!(
                (bb[1][a].as_f64().unwrap() - hi).abs() < 1e-3,
                "{cname}: {bb}"
            );
        }
        assert_eq!(
            objs[&cname]["vertices"].as_u64(),
            Some(local.len() as u64),
            "{cname}: Blender keeps every hull vertex"
        );
    }
}
