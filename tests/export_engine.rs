//! The engine-ready export of a scene (`export DIR --format glb|ply`) read by outside clients:
//! three.js GLTFLoader with its splat plugin, the Khronos glTF validator,
//! `@gltf-transform/extensions` (EXT_mesh_features), recast-navigation (Detour paths on the
//! navmesh), PlayCanvas splat-transform (labels kept and filtered) and Debian's Blender 3.4
//! glTF importer (a missing Blender fails the test unless `DREAMSCENE_SKIP_EXTERNAL=blender`).
//! Expected values come from the scene's own `layout.json` and `scene.json` with the frames
//! written out here, not from the exporter.
//!
//! The fixture is a draft of "a small bedroom" (or of `DREAMSCENE_ENGINE_PROMPT`, which
//! `scripts/engine_export_prompts.sh` sets to run these checks over many prompts); an indoor
//! scene keeps the openings its layout placed, or is given a door and a window in scene.json as
//! ARCHITECTURE.md's `openings` say when it has none.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::export::engine::{obstacles, read_input};
use dreamscene::export::navmesh::{Agent, Obstacle};
use dreamscene::splat::ply::read_ply_labelled;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

mod common;
#[allow(dead_code, reason = "this test uses some of the shared export helpers")]
mod export_support;
use export_support::{draft_scene, export_ok, node_dir, require_readers};

/// Agent radius the export uses by default.
const RADIUS: f64 = 0.25;
/// Tolerance of collider boxes against layout.json (the 2 cm).
const BOX_TOL: f64 = 0.02;

struct Fixture {
    scene: PathBuf,
    glb: PathBuf,
    layout: Value,
    scene_json: Value,
}

/// The scene, exported once for every test of this file.
fn fixture() -> &'static Fixture {
    static F: OnceLock<Fixture> = OnceLock::new();
    F.get_or_init(|| {
        // One fixture directory a worktree, replaced by each run: a scene is 0.2-0.7 GB, and a
        // directory per process was never removed (the tests share it, none can tell it is last).
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("export-engine");
        let _ = std::fs::remove_dir_all(&dir);
        let scene = dir.join("bedroom");
        let prompt = std::env::var("DREAMSCENE_ENGINE_PROMPT")
            .ok()
            .filter(|p| !p.trim().is_empty())
            .unwrap_or_else(|| "a small bedroom".to_string());
        draft_scene(&prompt, &scene);
        let layout: Value = read_json(&scene.join("layout.json"));
        let mut scene_json: Value = read_json(&scene.join("scene.json"));
        let [w, d, _] = room(&scene_json);
        let has_openings = scene_json["openings"]
            .as_array()
            .is_some_and(|a| !a.is_empty());
        if indoor(&scene_json) && !has_openings {
            scene_json["openings"] = json!([
            {"kind": "door", "wall": "south", "position": [w / 4.0, -d / 2.0, 0.0],
             "width": 0.9, "height": 2.1},
            {"kind": "window", "wall": "east", "position": [w / 2.0, 0.0, 0.9],
             "width": 1.2, "height": 1.1}
            ]);
        }
        std::fs::write(scene.join("scene.json"), scene_json.to_string()).unwrap();
        let glb = dir.join("bedroom.glb");
        export_ok(&scene, "glb", &glb, &[]);
        Fixture {
            scene,
            glb,
            layout,
            scene_json,
        }
    })
}

fn read_json(p: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn indoor(scene: &Value) -> bool {
    scene["scene_type"] == "indoor"
}

fn room(scene: &Value) -> [f64; 3] {
    let s = &scene["room"]["size"];
    [0, 1, 2].map(|i| s[i].as_f64().unwrap())
}

fn f3(v: &Value) -> [f64; 3] {
    [0, 1, 2].map(|i| v[i].as_f64().unwrap())
}

/// A glTF reader's node name for an id (spaces become `_`).
fn name(id: &str) -> String {
    id.replace(' ', "_")
}

/// World-frame (z up) axis-aligned box of a layout object: its footprint rotated by yaw.
fn layout_box(o: &Value) -> ([f64; 3], [f64; 3]) {
    let (s, p, yaw) = (
        f3(&o["size"]),
        f3(&o["position"]),
        o["yaw"].as_f64().unwrap(),
    );
    let (sn, cs) = yaw.to_radians().sin_cos();
    let ex = (s[0] / 2.0 * cs).abs() + (s[1] / 2.0 * sn).abs();
    let ey = (s[0] / 2.0 * sn).abs() + (s[1] / 2.0 * cs).abs();
    (
        [p[0] - ex, p[1] - ey, p[2]],
        [p[0] + ex, p[1] + ey, p[2] + s[2]],
    )
}

/// What each object blocks for the export's agent, by the rule the navmesh itself is cut by
/// (`engine::obstacles`: one helper), checked here against layout.json: an object no taller than
/// the agent blocks with exactly its layout footprint, a taller one with a part of its footprint
/// (what stands below the agent's head), and every object standing on the floor that the agent
/// cannot step over blocks.
fn floor_obstacles(f: &Fixture) -> Vec<(String, Obstacle)> {
    let agent = Agent {
        radius: RADIUS,
        ..Agent::default()
    };
    let input = read_input(&f.scene).unwrap();
    let ids = input.scene.objects.iter().map(|o| o.id.clone());
    let blocks: Vec<(String, Option<Obstacle>)> = ids.zip(obstacles(&input, &agent)).collect();
    for o in f.layout["objects"].as_array().unwrap() {
        let id = o["id"].as_str().unwrap();
        let (s, p, yaw) = (
            f3(&o["size"]),
            f3(&o["position"]),
            o["yaw"].as_f64().unwrap(),
        );
        let block = blocks.iter().find(|b| b.0 == id).unwrap().1;
        if p[2] < 0.01 && s[2] > agent.climb {
            assert!(
                block.is_some(),
                "{id} stands on the floor and blocks nothing"
            );
        }
        let Some(b) = block else { continue };
        let whole = Obstacle {
            centre: [p[0], p[1]],
            half: [s[0] / 2.0, s[1] / 2.0],
            yaw,
            z: [p[2], p[2] + s[2]],
        };
        let (sn, cs) = b.yaw.to_radians().sin_cos();
        let corners = [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)].map(|(u, v)| {
            let (x, y) = (u * b.half[0], v * b.half[1]);
            [b.centre[0] + cs * x - sn * y, b.centre[1] + sn * x + cs * y]
        });
        assert!(
            corners.iter().all(|c| whole.contains(*c, 1e-6)),
            "{id} blocks {b:?}, outside its layout footprint"
        );
        if whole.z[1] <= agent.height {
            let same = (0..2).all(|a| (b.half[a] - whole.half[a]).abs() < 1e-6);
            assert!(same, "{id} blocks {b:?}, not its whole footprint");
        }
    }
    blocks
        .into_iter()
        .filter_map(|(id, b)| Some((id, b?)))
        .collect()
}

/// Seats and beds standing on the floor: the furniture a person must be able to walk up to. The
/// function class is the knowledge base's (`seat`, `bed`), so no category is named here.
fn reachable_furniture(layout: &Value) -> Vec<&Value> {
    layout["objects"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|o| f3(&o["position"])[2] < 0.01)
        .filter(|o| {
            let cat = o["category"].as_str().unwrap_or_default();
            matches!(
                dreamscene::shape::functions::function_of(cat),
                Some("seat" | "bed")
            )
        })
        .collect()
}

/// Candidate spots beside an object, in the scene frame: on each of its four sides, at five
/// places along the side and three distances out (the agent's radius plus 0.15 to 0.45 m).
fn spots_beside(o: &Value) -> Vec<[f64; 2]> {
    let (s, p, yaw) = (
        f3(&o["size"]),
        f3(&o["position"]),
        o["yaw"].as_f64().unwrap(),
    );
    let (sn, cs) = yaw.to_radians().sin_cos();
    let mut spots = vec![];
    // Front (+v), back, right (+u), left: the side's normal and the extents across and along it.
    for (u, v) in [(0.0, 1.0), (0.0, -1.0), (1.0, 0.0), (-1.0, 0.0)] {
        let (across, along) = if u == 0.0 { (s[1], s[0]) } else { (s[0], s[1]) };
        for gap in [0.15, 0.3, 0.45] {
            let out = across / 2.0 + RADIUS + gap;
            for k in [0.0, -0.2, 0.2, -0.4, 0.4] {
                let t = k * along;
                let (lx, ly) = (u * out + v * t, v * out + u * t);
                spots.push([p[0] + cs * lx - sn * ly, p[1] + sn * lx + cs * ly]);
            }
        }
    }
    spots
}

fn node_reader(args: &[&str]) -> Value {
    let o = Command::new("node")
        .current_dir(node_dir())
        .arg("engine.mjs")
        .args(args)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "engine.mjs {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).unwrap()
}

fn require_engine_readers() {
    require_readers();
    for p in [
        "recast-navigation/package.json",
        "@gltf-transform/extensions/package.json",
    ] {
        let path = node_dir().join("node_modules").join(p);
        assert!(
            path.exists(),
            "{} missing: run `bash scripts/setup.sh`",
            path.display()
        );
    }
}

/// glTF (y up) to the scene frame (z up): `(x, y, z)` is scene `(x, -z, y)`.
fn to_scene(v: [f64; 3]) -> [f64; 3] {
    [v[0], -v[2], v[1]]
}

fn close_box(got: ([f64; 3], [f64; 3]), want: ([f64; 3], [f64; 3]), what: &str) {
    for a in 0..3 {
        assert!(
            (got.0[a] - want.0[a]).abs() <= BOX_TOL && (got.1[a] - want.1[a]).abs() <= BOX_TOL,
            "{what}: box {got:?} vs layout {want:?}"
        );
    }
}

#[test]
fn three_reads_instances_extras_physics_and_every_splat() {
    require_engine_readers();
    let f = fixture();
    let r = node_reader(&["three", f.glb.to_str().unwrap()]);
    let nodes = &r["nodes"];
    // The scene as composed now (the fixture added openings after `generate`, and a draft's
    // environment is lit with its openings when composed), not scene.ply as generate wrote it.
    let current = dreamscene::scene::dir::read_scene(&f.scene).unwrap();
    let merged = dreamscene::scene::dir::compose_scene(&f.scene, &current).unwrap();
    assert_eq!(
        r["splats"].as_u64(),
        Some(merged.len() as u64),
        "three.js reads every Gaussian of the composed scene"
    );
    for o in f.layout["objects"].as_array().unwrap() {
        let id = o["id"].as_str().unwrap();
        let n = &nodes[name(id)];
        assert_eq!(n["parent"], "dreamscene", "{id}");
        assert_eq!(n["extras"]["id"], id);
        assert_eq!(n["extras"]["category"], o["category"]);
        let p = to_scene(f3(&n["world_position"]));
        let want = f3(&o["position"]);
        assert!(
            (0..3).all(|a| (p[a] - want[a]).abs() < 1e-3),
            "{id}: {p:?} vs {want:?}"
        );
        let c = &nodes[format!("collider_{}", name(id))];
        assert_eq!(c["parent"], json!(name(id)));
        let ext = &c["extras"]["gltfExtensions"];
        assert!(ext["OMI_physics_body"]["collider"]["shape"].is_u64(), "{c}");
        assert!(ext["KHR_physics_rigid_bodies"]["collider"]["geometry"].is_object());
        let (lo, hi) = (f3(&c["world_box"][0]), f3(&c["world_box"][1]));
        let (a, b) = (to_scene(lo), to_scene(hi));
        let got = (
            [0, 1, 2].map(|k| a[k].min(b[k])),
            [0, 1, 2].map(|k| a[k].max(b[k])),
        );
        close_box(got, layout_box(o), id);
    }
    // Walls only indoors (an outdoor scene has its ground and no walls).
    let walls: &[&str] = if indoor(&f.scene_json) {
        &["collider_wall_north", "collider_wall_south"]
    } else {
        &[]
    };
    for n in ["collider_floor", "navmesh", "spawn_0"].iter().chain(walls) {
        assert_eq!(nodes[n]["parent"], "dreamscene", "{n}");
    }
    let cats = &nodes["dreamscene"]["extras"]["categories"];
    assert_eq!(
        cats.as_object().unwrap().len(),
        f.layout["objects"].as_array().unwrap().len()
    );
}

#[test]
fn validator_finds_only_the_known_splat_attribute_errors() {
    require_engine_readers();
    let f = fixture();
    let report = export_support::reader_json("validate", &f.glb);
    for m in report["issues"]["messages"].as_array().unwrap() {
        let code = m["code"].as_str().unwrap();
        let pointer = m["pointer"].as_str().unwrap_or("");
        let known = code == "MESH_PRIMITIVE_INVALID_ATTRIBUTE"
            && pointer.contains("/attributes/KHR_gaussian_splatting:");
        assert!(known || m["severity"].as_u64() >= Some(2), "validator: {m}");
    }
}

#[test]
fn splats_are_optional_and_the_navmesh_obj_is_the_navmesh_node() {
    let f = fixture();
    let bytes = std::fs::read(&f.glb).unwrap();
    let doc = glb_json(&bytes);
    // Blender refuses a file whose splat extension is required.
    let required = doc["extensionsRequired"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    assert!(
        !required.iter().any(|e| e == "KHR_gaussian_splatting"),
        "extensionsRequired: {required:?}"
    );
    assert!(doc["extensionsUsed"]
        .as_array()
        .unwrap()
        .iter()
        .any(|e| e == "KHR_gaussian_splatting"));
    // `<stem>.navmesh.obj` beside the glb holds the navmesh node's vertices (both y up).
    let obj = std::fs::read_to_string(f.glb.with_extension("navmesh.obj")).unwrap();
    let vs: Vec<[f64; 3]> = obj
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    let faces = obj.lines().filter(|l| l.starts_with("f ")).count();
    let mesh = mesh_positions(&bytes, "navmesh");
    assert_eq!(vs.len(), mesh.len(), "navmesh.obj vertices");
    let node = doc["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|n| n["name"] == "navmesh")
        .unwrap();
    let prim = &doc["meshes"][node["mesh"].as_u64().unwrap() as usize]["primitives"][0];
    let indices = &doc["accessors"][prim["indices"].as_u64().unwrap() as usize]["count"];
    assert_eq!(
        Some(faces as u64 * 3),
        indices.as_u64(),
        "navmesh.obj faces"
    );
    for (a, b) in vs.iter().zip(&mesh) {
        assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-3), "{a:?} vs {b:?}");
    }
}

#[test]
fn feature_ids_and_labelled_ply_agree_with_labels_json() {
    require_engine_readers();
    let f = fixture();
    let dir = f.glb.parent().unwrap();
    let ply = dir.join("labelled.ply");
    export_ok(&f.scene, "ply", &ply, &["--scene-frame"]);
    let (g, labels) = read_ply_labelled(&ply).unwrap();
    let labels = labels.expect("instance_id and semantic_id in the PLY");
    assert_eq!(labels.instance.len(), g.len());
    let mut counts = std::collections::BTreeMap::<u16, u64>::new();
    for &i in &labels.instance {
        *counts.entry(i).or_default() += 1;
    }
    // The scene's composition holds the same Gaussians in the same order. It is composed again
    // here rather than read from scene.ply: the fixture added openings to scene.json after
    // `generate`, and a draft's environment is lit with its openings when composed.
    let current = dreamscene::scene::dir::read_scene(&f.scene).unwrap();
    let merged = dreamscene::scene::dir::compose_scene(&f.scene, &current).unwrap();
    assert_eq!(g, merged);
    // instance k is scene.json's k-th object: its block is that object's PLY's size.
    for (k, o) in f.scene_json["objects"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
    {
        let own = dreamscene::splat::ply::read_ply(&f.scene.join(o["ply"].as_str().unwrap()))
            .unwrap()
            .len() as u64;
        assert_eq!(counts.get(&(k as u16 + 1)), Some(&own), "{}", o["id"]);
    }
    let feats = node_reader(&["features", f.glb.to_str().unwrap()]);
    let fid = &feats[0]["featureIds"][0];
    assert_eq!(fid["featureCount"].as_u64(), Some(counts.len() as u64));
    assert_eq!(fid["label"], "instance");
    for (k, n) in &counts {
        assert_eq!(
            feats[0]["histogram"][k.to_string()].as_u64(),
            Some(*n),
            "instance {k}"
        );
    }

    // splat-transform keeps instance_id through PLY -> PLY and filters by it.
    let k = 1u16;
    let one = dir.join("one.ply");
    let o = Command::new(node_dir().join("node_modules/.bin/splat-transform"))
        .args(["-q", "-w"])
        .arg(&ply)
        .args(["-V", &format!("instance_id,eq,{k}")])
        .arg(&one)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (g1, l1) = read_ply_labelled(&one).unwrap();
    let l1 = l1.expect("labels kept");
    assert_eq!(g1.len() as u64, counts[&k]);
    assert!(l1.instance.iter().all(|&i| i == k));
    // Re-exporting the labelled PLY keeps the labels; --only keeps one instance.
    let again = dir.join("again.ply");
    export_ok(&one, "ply", &again, &["--scene-frame"]);
    assert_eq!(read_ply_labelled(&again).unwrap().1, Some(l1));
    let only = dir.join("only.ply");
    let first = f.scene_json["objects"][0]["id"]
        .as_str()
        .unwrap()
        .replace(' ', "_");
    export_ok(&f.scene, "ply", &only, &["--only", &first]);
    assert_eq!(read_ply_labelled(&only).unwrap().0.len() as u64, counts[&1]);
}

/// The glb's JSON chunk.
fn glb_json(bytes: &[u8]) -> Value {
    let len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    serde_json::from_slice(&bytes[20..20 + len]).unwrap()
}

/// Whether a value Blender reports equals the glb's: numbers within float precision (Blender
/// keeps custom properties as 32-bit floats in arrays), lists and tables element by element.
fn same_value(got: &Value, want: &Value) -> bool {
    match (got, want) {
        (Value::Number(a), Value::Number(b)) => {
            let (a, b) = (a.as_f64().unwrap(), b.as_f64().unwrap());
            (a - b).abs() <= 1e-5 * b.abs().max(1.0)
        }
        (Value::Array(a), Value::Array(b)) => {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same_value(x, y))
        }
        (Value::Object(a), Value::Object(b)) => {
            a.len() == b.len()
                && b.iter()
                    .all(|(k, y)| a.get(k).is_some_and(|x| same_value(x, y)))
        }
        _ => got == want,
    }
}

/// Reads the positions of node `n`'s mesh from the glb.
fn mesh_positions(bytes: &[u8], n: &str) -> Vec<[f64; 3]> {
    let len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    let doc = glb_json(bytes);
    let bin = &bytes[20 + len + 8..];
    let node = doc["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|x| x["name"] == n)
        .unwrap();
    let prim = &doc["meshes"][node["mesh"].as_u64().unwrap() as usize]["primitives"][0];
    let acc = &doc["accessors"][prim["attributes"]["POSITION"].as_u64().unwrap() as usize];
    let view = &doc["bufferViews"][acc["bufferView"].as_u64().unwrap() as usize];
    let start = view["byteOffset"].as_u64().unwrap_or(0) as usize;
    (0..acc["count"].as_u64().unwrap() as usize)
        .map(|i| {
            [0, 1, 2].map(|a| {
                let o = start + (i * 3 + a) * 4;
                f64::from(f32::from_le_bytes(bin[o..o + 4].try_into().unwrap()))
            })
        })
        .collect()
}

#[test]
fn openings_are_cut_from_the_walls_and_paths_on_the_navmesh_avoid_furniture() {
    require_engine_readers();
    let f = fixture();
    let bytes = std::fs::read(&f.glb).unwrap();
    let [w, d, _] = room(&f.scene_json);
    // The middle of each opening just outside its wall, in the scene frame.
    let walls: Vec<(String, [f64; 2], f64)> = if indoor(&f.scene_json) {
        let openings = f.scene_json["openings"].as_array().unwrap();
        assert!(!openings.is_empty(), "an indoor scene has openings");
        openings
            .iter()
            .map(|o| {
                let side = o["wall"].as_str().unwrap().to_string();
                let p = f3(&o["position"]);
                let out = match side.as_str() {
                    "north" => [p[0], d / 2.0 + 0.05],
                    "south" => [p[0], -d / 2.0 - 0.05],
                    "east" => [w / 2.0 + 0.05, p[1]],
                    _ => [-w / 2.0 - 0.05, p[1]],
                };
                (side, out, p[2] + o["height"].as_f64().unwrap() / 2.0)
            })
            .collect()
    } else {
        let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
        let text = String::from_utf8_lossy(&bytes[20..20 + json_len]);
        assert!(
            !text.contains("collider_wall_"),
            "an outdoor scene has no walls"
        );
        vec![]
    };
    // Wall colliders are boxes of 8 vertices: none covers the door's or the window's middle.
    for (wall, at, z) in walls {
        let pts = mesh_positions(&bytes, &format!("collider_wall_{wall}"));
        assert!(pts.len() >= 3 * 8, "{wall}: {} vertices", pts.len());
        for b in pts.chunks(8) {
            let s: Vec<[f64; 3]> = b.iter().map(|p| to_scene(*p)).collect();
            let lo = [0, 1, 2].map(|a| s.iter().map(|p| p[a]).fold(f64::MAX, f64::min));
            let hi = [0, 1, 2].map(|a| s.iter().map(|p| p[a]).fold(f64::MIN, f64::max));
            let covers =
                (0..2).all(|a| lo[a] <= at[a] && at[a] <= hi[a]) && lo[2] <= z && z <= hi[2];
            assert!(!covers, "{wall} wall box {lo:?}..{hi:?} covers its opening");
        }
    }
    // Spawn points and free spots beside every floor object, in glTF's frame.
    let doc_nodes = node_reader(&["three", f.glb.to_str().unwrap()])["nodes"].clone();
    let spawn = f3(&doc_nodes["spawn_0"]["world_position"]);
    let obstacles = floor_obstacles(f);
    for k in ["spawn_0", "spawn_1"] {
        let s = to_scene(f3(&doc_nodes[k]["world_position"]));
        for (id, o) in &obstacles {
            assert!(!o.contains([s[0], s[1]], 0.0), "{k} on {id}");
        }
    }
    // A free spot keeps the agent's radius from every footprint plus a navmesh cell's diagonal:
    // the mesh is rasterised conservatively, so it may lose that much beside an obstacle.
    let cell = doc_nodes["navmesh"]["extras"]["cell"].as_f64().unwrap();
    let margin = RADIUS + cell * std::f64::consts::SQRT_2 + 0.01;
    let free = |x: f64, y: f64| {
        x.abs() < w / 2.0 - margin
            && y.abs() < d / 2.0 - margin
            && obstacles.iter().all(|(_, o)| !o.contains([x, y], margin))
    };
    // Every seat and bed standing on the floor (its function class from the knowledge base) must
    // have a free spot beside it, where a person stands to sit or lie down, and be reachable.
    let mut targets = vec![];
    for o in reachable_furniture(&f.layout) {
        let id = o["id"].as_str().unwrap().to_string();
        let spot = spots_beside(o).into_iter().find(|t| free(t[0], t[1]));
        let t = spot.unwrap_or_else(|| panic!("no free spot beside {id}: {o}"));
        targets.push((id, t));
    }
    let queries: Vec<Value> = targets
        .iter()
        .map(|(_, t)| json!({"from": spawn, "to": [t[0], 0.0, -t[1]]}))
        .collect();
    let q = f.glb.with_file_name("queries.json");
    std::fs::write(&q, serde_json::to_string(&queries).unwrap()).unwrap();
    let r = node_reader(&["recast", f.glb.to_str().unwrap(), q.to_str().unwrap()]);
    assert_eq!(r["success"], true);
    for ((id, t), p) in targets.iter().zip(r["paths"].as_array().unwrap()) {
        assert_eq!(p["success"], true, "{id}");
        let path: Vec<[f64; 3]> = p["path"].as_array().unwrap().iter().map(f3).collect();
        let end = to_scene(*path.last().expect("a path"));
        let miss = ((end[0] - t[0]).powi(2) + (end[1] - t[1]).powi(2)).sqrt();
        assert!(
            miss < 0.15,
            "{id}: path ends {miss:.2} m from the spot beside it"
        );
        for seg in path.windows(2) {
            let (a, b) = (to_scene(seg[0]), to_scene(seg[1]));
            for k in 0..=50 {
                let s = k as f64 / 50.0;
                let (x, y) = (a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s);
                for (other, o) in &obstacles {
                    assert!(!o.contains([x, y], 0.0), "path to {id} crosses {other}");
                }
            }
        }
    }
}

#[test]
fn blender_imports_objects_with_extras_and_collider_boxes() {
    if !export_support::blender_ready() {
        return;
    }
    let f = fixture();
    let script = node_dir().join("blender_import.py");
    let o = Command::new("blender")
        .args(["-b", "--factory-startup", "--python"])
        .arg(&script)
        .arg("--")
        .arg(&f.glb)
        .output()
        .unwrap();
    let log = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{log}");
    assert!(
        !log.contains("Traceback") && !log.contains("Error"),
        "{log}"
    );
    let line = log
        .lines()
        .find_map(|l| l.strip_prefix("RESULT "))
        .expect(&log);
    let objs: Value = serde_json::from_str(line).unwrap();
    // Every node's extras, as the glb's own JSON chunk holds them, are that object's custom
    // properties in Blender: the root's tables and each instance's id, category, labels, size.
    let doc = glb_json(&std::fs::read(&f.glb).unwrap());
    let extras_of = |n: &str| {
        doc["nodes"]
            .as_array()
            .unwrap()
            .iter()
            .find(|x| x["name"] == n)
            .unwrap_or_else(|| panic!("node {n} in the glb"))["extras"]
            .clone()
    };
    for n in ["dreamscene".to_string()].into_iter().chain(
        f.layout["objects"]
            .as_array()
            .unwrap()
            .iter()
            .map(|o| name(o["id"].as_str().unwrap())),
    ) {
        let extras = extras_of(&n);
        let extras = extras.as_object().unwrap();
        assert!(!extras.is_empty(), "{n} has extras");
        for (k, v) in extras {
            let got = &objs[&n]["props"][k];
            assert!(same_value(got, v), "{n}.{k}: Blender {got}, glb {v}");
        }
    }
    for o in f.layout["objects"].as_array().unwrap() {
        let id = o["id"].as_str().unwrap();
        let n = &objs[name(id)];
        assert_eq!(n["type"], "EMPTY", "{id}");
        assert_eq!(n["props"]["category"], o["category"], "{id}");
        assert_eq!(n["props"]["id"], id);
        let c = &objs[format!("collider_{}", name(id))];
        assert_eq!(c["parent"], json!(name(id)));
        // Blender's frame is the scene's (z up).
        close_box(
            (f3(&c["world_box"][0]), f3(&c["world_box"][1])),
            layout_box(o),
            id,
        );
    }
    // The floor's and the walls' colliders bound layout.json's room: the floor's top face is
    // the room's footprint at z = 0, each wall's inner face stands on the room's side over its
    // whole length and height (the thickness, outside the room, is the exporter's own).
    let [w, d, h] = f3(&f.layout["room"]["size"]).map(|v| v / 2.0);
    let near = |a: f64, b: f64| (a - b).abs() <= BOX_TOL;
    let wbox = |n: &str| {
        let b = &objs[n]["world_box"];
        (f3(&b[0]), f3(&b[1]))
    };
    let (lo, hi) = wbox("collider_floor");
    assert!(
        near(lo[0], -w) && near(hi[0], w) && near(lo[1], -d) && near(hi[1], d) && near(hi[2], 0.0),
        "collider_floor {lo:?}..{hi:?} vs the room {w} x {d} (half sizes)"
    );
    if indoor(&f.scene_json) {
        for side in ["north", "south", "east", "west"] {
            let n = format!("collider_wall_{side}");
            let (lo, hi) = wbox(&n);
            let (face, along) = match side {
                "north" => (
                    near(lo[1], d),
                    lo[0] <= -w + BOX_TOL && hi[0] >= w - BOX_TOL,
                ),
                "south" => (
                    near(hi[1], -d),
                    lo[0] <= -w + BOX_TOL && hi[0] >= w - BOX_TOL,
                ),
                "east" => (near(lo[0], w), near(lo[1], -d) && near(hi[1], d)),
                _ => (near(hi[0], -w), near(lo[1], -d) && near(hi[1], d)),
            };
            let up = near(lo[2], 0.0) && near(hi[2], 2.0 * h);
            assert!(face && along && up, "{n} {lo:?}..{hi:?} vs the room");
        }
    }
}
