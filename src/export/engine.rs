//! The engine-ready `.glb` of a scene directory (ARCHITECTURE.md, "Engine-ready glb"): a root
//! node `dreamscene` (extras: units, room, the id → category table) holding
//!
//! - `splats`: every Gaussian as one `KHR_gaussian_splatting` primitive (world frame), with
//!   `_FEATURE_ID_0` = instance id and `EXT_mesh_features`; or with
//!   [`EngineOptions::per_object_splats`] one primitive per instance (`splats_<id>`, a child of
//!   its node in the node's frame) and `splats_environment`;
//! - one node per instance, named by its id with spaces as `_`, posed by `scene.json`, extras
//!   `{id, category, instance_id, semantic, semantic_id, size_m, style_prompt, gaussians:
//!   [start, count]}`, with a `collider_<id>` child: a box of its layout size (or of its
//!   Gaussians' bounds), or with [`Colliders::Hull`] the 3-D convex hull of its opaque
//!   Gaussians;
//! - `collider_floor` and `collider_wall_<side>` (openings cut out); outdoors only the ground;
//! - `navmesh` ([`super::navmesh`]) and `spawn_<n>` nodes on it.
//!
//! A scene with a timeline (`edit animate`) keeps its motion: every instance's splats are its
//! node's child (as with per-object splats) and each animated node has an animation sampled at
//! the timeline's frame rate; colliders move with their node, the navmesh is the rest pose's.
//! With [`EngineOptions::time`] the scene is exported still, as it stands at that time (nodes,
//! colliders and navmesh posed there; the root's extras give `time_s`).
//!
//! Colliders carry `OMI_physics_body`/`OMI_physics_shape` (Godot 4) and the Khronos draft
//! `KHR_physics_rigid_bodies`/`KHR_implicit_shapes`, all in `extensionsUsed` only.
use super::collider::{self, Mesh};
use super::glb::{to_gltf_frame, GlbBuilder, NodeTransform};
use super::labels::{node_name, SceneLabels};
use super::navmesh::{Agent, NavMesh, Obstacle};
use super::{ExportError, Result};
use crate::scene::compose::merge;
use crate::scene::dir::{compose_parts, read_scene, SceneFile};
use crate::splat::Gaussians;
use serde_json::{json, Value};
use std::path::Path;

/// Which collider each object gets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Colliders {
    /// The oriented box of its layout size.
    #[default]
    Box,
    /// The 3-D convex hull of its opaque Gaussians.
    Hull,
}

/// What the engine export writes.
#[derive(Debug, Clone, Default)]
pub struct EngineOptions {
    pub colliders: Colliders,
    pub agent: Agent,
    /// Navmesh cell side, metres (0 = 0.05: the grid is conservative, so a passage loses up to a
    /// cell on each side, and at 0.1 m a 0.65 m gap between a sofa and an armchair is closed).
    pub cell: f64,
    /// Instances, categories or `walls` to keep (empty = all).
    pub only: Vec<String>,
    /// Instances, categories or `walls` to leave out.
    pub without: Vec<String>,
    /// One splat primitive per instance (a child of its node, in its frame) and one for the
    /// environment, instead of one for the whole scene.
    pub per_object_splats: bool,
    /// Export the scene as it stands at this time of its timeline (seconds), still.
    pub time: Option<f64>,
}

/// A scene read for export: the scene file, its parts and labels, layout sizes and openings.
pub struct SceneInput {
    pub scene: SceneFile,
    pub labels: SceneLabels,
    pub cloud: Gaussians,
    /// World-frame size of each instance (scene order).
    pub sizes: Vec<[f64; 3]>,
    pub openings: Vec<collider::Opening>,
    /// Each instance's style prompt ([`super::instances::style_prompts`]).
    pub styles: Vec<Option<String>>,
}

/// Reads a scene directory: composes it and finds each instance's size (layout.json, scaled by
/// the instance's scale; else its Gaussians' bounds) and the openings (scene.json, else
/// layout.json).
pub fn read_input(dir: &Path) -> Result<SceneInput> {
    read_input_at(dir, None)
}

/// [`read_input`] with every animated instance posed at `time` (seconds) of the scene's
/// timeline, which is then dropped: the scene as it stands at that time, still.
pub fn read_input_at(dir: &Path, time: Option<f64>) -> Result<SceneInput> {
    let dir = if dir.is_file() {
        dir.parent().unwrap_or(Path::new("."))
    } else {
        dir
    };
    let bad = |e: crate::scene::dir::SceneError| ExportError::Unrepresentable(e.to_string());
    let mut scene = read_scene(dir).map_err(bad)?;
    if let Some(t) = time {
        if !t.is_finite() || t < 0.0 {
            return Err(ExportError::Unrepresentable(format!(
                "--time {t}: give a time in seconds, 0 or more"
            )));
        }
        scene = crate::scene::timeline::scene_at(&scene, t);
        scene.timeline = None;
    }
    let parts = compose_parts(dir, &scene).map_err(bad)?;
    let labels = SceneLabels::of_parts(&scene, &parts)?;
    let layout: Value = std::fs::read_to_string(dir.join("layout.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or(Value::Null);
    let scene_value = serde_json::to_value(&scene).unwrap_or(Value::Null);
    let mut openings = collider::openings(&scene_value);
    if openings.is_empty() {
        openings = collider::openings(&layout);
    }
    let sizes = scene
        .objects
        .iter()
        .zip(&parts)
        .map(|(o, g)| {
            let planned = layout["objects"].as_array().and_then(|a| {
                let e = a.iter().find(|e| e["id"].as_str() == Some(o.id.as_str()))?;
                let s = e["size"].as_array()?;
                Some([
                    s.first()?.as_f64()?,
                    s.get(1)?.as_f64()?,
                    s.get(2)?.as_f64()?,
                ])
            });
            match planned {
                Some(s) => [0, 1, 2].map(|a| s[a] * o.scale[a].abs()),
                None => local_bounds(g, &o.placement())
                    .map_or([0.0; 3], |(lo, hi)| [0, 1, 2].map(|a| hi[a] - lo[a])),
            }
        })
        .collect();
    let styles = super::instances::style_prompts(dir, &scene);
    Ok(SceneInput {
        scene,
        labels,
        cloud: merge(&parts),
        sizes,
        openings,
        styles,
    })
}

/// Object-frame centres (after yaw is undone, relative to the instance position) of a placed
/// cloud's opaque Gaussians (sigmoid(opacity) >= 0.5; all when none is), each with its largest
/// scale.
fn local_gaussians(g: &Gaussians, p: &crate::scene::compose::Placement) -> Vec<([f64; 3], f64)> {
    let (s, c) = p.yaw.to_radians().sin_cos();
    let opaque = g.opacities.iter().any(|&o| o >= 0.0);
    g.means
        .iter()
        .zip(&g.scales)
        .zip(&g.opacities)
        .filter(|(_, &o)| !opaque || o >= 0.0)
        .map(|((m, sc), _)| {
            let d = [0, 1, 2].map(|a| f64::from(m[a]) - p.position[a]);
            let r = f64::from(sc[0].max(sc[1]).max(sc[2])).exp();
            ([c * d[0] + s * d[1], -s * d[0] + c * d[1], d[2]], r)
        })
        .collect()
}

/// [`local_gaussians`]' centres.
fn local_points(g: &Gaussians, p: &crate::scene::compose::Placement) -> Vec<[f64; 3]> {
    local_gaussians(g, p).into_iter().map(|(m, _)| m).collect()
}

/// What each instance (scene order) blocks for `agent` walking on the floor: its layout box's
/// footprint, or for one taller than the agent the part below its head
/// ([`Obstacle::walked_into`], measured on its Gaussians); `None` when it blocks nothing. The
/// navmesh is cut by exactly these, and the export tests check paths against them.
pub fn obstacles(input: &SceneInput, agent: &Agent) -> Vec<Option<Obstacle>> {
    let labels = &input.labels.instances;
    input
        .scene
        .objects
        .iter()
        .zip(labels)
        .zip(&input.sizes)
        .map(|((o, inst), size)| {
            let p = o.placement();
            let whole = Obstacle {
                centre: [p.position[0], p.position[1]],
                half: [size[0] / 2.0, size[1] / 2.0],
                yaw: p.yaw,
                z: [p.position[2], p.position[2] + size[2]],
            };
            let own = select_range(&input.cloud, inst.start, inst.count);
            whole.walked_into(agent, &local_gaussians(&own, &p))
        })
        .collect()
}

fn local_bounds(
    g: &Gaussians,
    p: &crate::scene::compose::Placement,
) -> Option<([f64; 3], [f64; 3])> {
    let pts = local_points(g, p);
    if pts.is_empty() {
        return None;
    }
    let m = Mesh {
        vertices: pts,
        triangles: vec![],
    };
    Some(m.bounds())
}

/// Scene frame (z up) to glTF (y up): `(x, y, z)` to `(x, z, -y)`.
fn y_up(v: [f64; 3]) -> [f32; 3] {
    [v[0] as f32, v[2] as f32, -v[1] as f32]
}

fn add_mesh(b: &mut GlbBuilder, name: &str, m: &Mesh, offset: [f64; 3]) -> usize {
    let pos: Vec<[f32; 3]> = m
        .vertices
        .iter()
        .map(|v| y_up([v[0] - offset[0], v[1] - offset[1], v[2] - offset[2]]))
        .collect();
    let idx: Vec<u32> = m.triangles.iter().flatten().copied().collect();
    b.add_triangles(name, &pos, &idx, Value::Null)
}

/// The physics blocks of a static collider node: OMI body + shape, KHR rigid body + shape.
struct Physics {
    omi: Vec<Value>,
    khr: Vec<Value>,
}

impl Physics {
    /// `shape` is an OMI shape; a box also becomes a KHR implicit shape, a mesh a KHR node
    /// geometry.
    fn attach(&mut self, b: &mut GlbBuilder, node: usize, shape: Value, convex: bool) {
        self.omi.push(shape.clone());
        let omi = self.omi.len() - 1;
        let khr_geometry = if shape["type"] == "box" {
            self.khr.push(shape);
            json!({ "shape": self.khr.len() - 1 })
        } else {
            json!({ "node": node, "convexHull": convex })
        };
        b.set_node_field(
            node,
            "extensions",
            json!({
                "OMI_physics_body": { "collider": { "shape": omi } },
                "KHR_physics_rigid_bodies": { "collider": { "geometry": khr_geometry } }
            }),
        );
    }
}

/// Writes the engine-ready `.glb` of the scene in `dir` and returns its bytes and the navmesh.
pub fn encode(input: &SceneInput, opts: &EngineOptions) -> Result<(Vec<u8>, NavMesh)> {
    let (scene, labels) = (&input.scene, &input.labels);
    let keep = labels.select(&opts.only, &opts.without)?;
    let all = labels.per_gaussian();
    let kept: Vec<bool> = all.instance.iter().map(|&i| keep[usize::from(i)]).collect();
    let cloud = select(&input.cloud, &kept);
    if cloud.is_empty() {
        return Err(ExportError::Unrepresentable(
            "the selection (--only/--without) keeps no Gaussian".into(),
        ));
    }
    let ids = all.filter(&kept).instance;
    // A timeline moves instances: each keeps its own splats under its node, so they move with it.
    let timeline = scene.timeline.as_ref().filter(|t| !t.tracks.is_empty());
    let per_object = opts.per_object_splats || timeline.is_some();
    let mut b = GlbBuilder::new();
    let room = scene.room.size;
    let indoor = scene
        .environment
        .as_ref()
        .is_none_or(|e| e.kind != "hemisphere");
    let categories: serde_json::Map<String, Value> = labels
        .instances
        .iter()
        .filter(|i| keep[usize::from(i.instance_id)])
        .map(|i| (node_name(&i.id), json!(i.category)))
        .collect();
    let mut root_node = json!({
        "name": "dreamscene",
        "extras": {
            "units": "metres", "up": "+y", "prompt": scene.prompt,
            "scene_type": if indoor { "indoor" } else { "outdoor" },
            "room_size_m": room, "categories": categories,
            "labels": labels.to_json()["semantic"].clone(),
        }
    });
    if timeline.is_some() {
        // only when animated: a still scene's extras stay as they were
        root_node["extras"]["animated"] = json!(true);
    }
    if let Some(t) = opts.time {
        root_node["extras"]["time_s"] = json!(t);
    }
    let root = b.push_node(root_node);
    if per_object {
        if keep[0] && labels.environment.1 > 0 {
            let (start, count) = labels.environment;
            let env = select_range(&input.cloud, start, count);
            let mesh = b.add_splats("splats_environment", &to_gltf_frame(&env))?;
            b.add_feature_ids(mesh, &vec![0; env.len()], "instance");
            let n = b.push_node(json!({ "name": "splats_environment", "mesh": mesh }));
            b.add_child(root, n);
        }
    } else {
        let mesh = b.add_splats("splats", &to_gltf_frame(&cloud))?;
        b.add_feature_ids(mesh, &ids, "instance");
        let splats = b.push_node(json!({ "name": "splats", "mesh": mesh }));
        b.add_child(root, splats);
    }

    let mut phys = Physics {
        omi: vec![],
        khr: vec![],
    };
    for (((o, inst), size), style) in scene
        .objects
        .iter()
        .zip(&labels.instances)
        .zip(&input.sizes)
        .zip(&input.styles)
    {
        let p = o.placement();
        if !keep[usize::from(inst.instance_id)] {
            continue;
        }
        let name = node_name(&o.id);
        let half = (p.yaw.to_radians() / 2.0).sin_cos();
        let node = b.push_node(json!({
            "name": name,
            "translation": y_up(p.position),
            "rotation": [0.0, half.0, 0.0, half.1],
            "extras": {
                "id": o.id, "category": o.category, "instance_id": inst.instance_id,
                "semantic": o.category, "semantic_id": inst.semantic_id, "size_m": size,
                "yaw_deg": o.yaw, "style_prompt": style, "gaussians": [inst.start, inst.count],
            }
        }));
        b.add_child(root, node);
        if let Some(t) = timeline {
            if let Some(track) = crate::scene::timeline::track(t, &o.id) {
                animate(&mut b, &name, node, t, track, &p);
            }
        }
        let own = select_range(&input.cloud, inst.start, inst.count);
        if per_object && !own.is_empty() {
            let local = super::instances::node_local(&own, p.yaw, p.position);
            let sname = format!("splats_{name}");
            let mesh = b.add_splats(&sname, &to_gltf_frame(&local))?;
            b.add_feature_ids(mesh, &vec![inst.instance_id; own.len()], "instance");
            let n = b.push_node(json!({ "name": sname, "mesh": mesh }));
            b.add_child(node, n);
        }
        let hull = (opts.colliders == Colliders::Hull)
            .then(|| collider::convex_hull(&local_points(&own, &p)))
            .flatten();
        let cname = format!("collider_{name}");
        let extras = json!({ "collider_of": o.id });
        let col = match hull {
            Some((m, step)) => {
                let mesh = add_mesh(&mut b, &cname, &m, [0.0; 3]);
                let extras = json!({ "collider_of": o.id, "shape": "hull", "hull_grid_m": step });
                let n = b.push_node(json!({ "name": cname, "mesh": mesh, "extras": extras }));
                phys.attach(
                    &mut b,
                    n,
                    json!({"type": "convex", "convex": {"mesh": mesh}}),
                    true,
                );
                n
            }
            None => {
                let mut m = Mesh::default();
                let h = [size[0] / 2.0, size[1] / 2.0, size[2] / 2.0];
                m.add_box([-h[0], -h[1], -h[2]], h);
                let mesh = add_mesh(&mut b, &cname, &m, [0.0; 3]);
                let n = b.push_node(json!({
                    "name": cname, "mesh": mesh, "extras": extras,
                    "translation": [0.0, h[2], 0.0]
                }));
                let gl = [size[0], size[2], size[1]];
                phys.attach(&mut b, n, json!({"type": "box", "box": {"size": gl}}), true);
                n
            }
        };
        b.add_child(node, col);
    }

    // The floor (or ground) and the walls.
    if keep[0] {
        let t = collider::WALL;
        let mut floor = Mesh::default();
        floor.add_box(
            [-room[0] / 2.0, -room[1] / 2.0, -t],
            [room[0] / 2.0, room[1] / 2.0, 0.0],
        );
        let mesh = add_mesh(&mut b, "collider_floor", &floor, [0.0, 0.0, -t / 2.0]);
        let n = b.push_node(json!({
            "name": "collider_floor", "mesh": mesh, "translation": [0.0, -t / 2.0, 0.0],
            "extras": { "collider_of": "floor" }
        }));
        let size = [room[0], t, room[1]];
        phys.attach(
            &mut b,
            n,
            json!({"type": "box", "box": {"size": size}}),
            true,
        );
        b.add_child(root, n);
        if indoor {
            for (side, m) in collider::walls(room, &input.openings) {
                let name = format!("collider_wall_{side}");
                let mesh = add_mesh(&mut b, &name, &m, [0.0; 3]);
                let cut: Vec<&str> = input
                    .openings
                    .iter()
                    .filter(|o| o.wall == side)
                    .map(|o| o.kind.as_str())
                    .collect();
                let n = b.push_node(json!({
                    "name": name, "mesh": mesh,
                    "extras": { "collider_of": format!("wall {side}"), "openings": cut }
                }));
                phys.attach(
                    &mut b,
                    n,
                    json!({"type": "trimesh", "trimesh": {"mesh": mesh}}),
                    false,
                );
                b.add_child(root, n);
            }
        }
    }

    // The navmesh and spawn points (every obstacle counts, kept or not: it is the scene's floor).
    let cell = if opts.cell > 0.0 { opts.cell } else { 0.05 };
    let blocks: Vec<Obstacle> = obstacles(input, &opts.agent)
        .into_iter()
        .flatten()
        .collect();
    let nav = NavMesh::build([room[0], room[1]], &blocks, opts.agent, cell);
    if !nav.triangles.is_empty() {
        let m = Mesh {
            vertices: nav.vertices.clone(),
            triangles: nav.triangles.clone(),
        };
        let mesh = add_mesh(&mut b, "navmesh", &m, [0.0; 3]);
        let n = b.push_node(json!({
            "name": "navmesh", "mesh": mesh,
            "extras": {
                "agent_radius": opts.agent.radius, "agent_height": opts.agent.height,
                "max_climb": opts.agent.climb, "cell": cell, "walkable_m2": nav.area(),
            }
        }));
        b.add_child(root, n);
    }
    for (k, (p, near)) in nav
        .spawn_points(&door_points(input), 2)
        .into_iter()
        .enumerate()
    {
        let n = b.push_node(json!({
            "name": format!("spawn_{k}"), "translation": y_up(p),
            "extras": { "spawn": k, "near": near }
        }));
        b.add_child(root, n);
    }
    if !phys.omi.is_empty() {
        b.set_root_extension("OMI_physics_shape", json!({ "shapes": phys.omi }));
        b.use_extension("OMI_physics_body");
        b.set_root_extension("KHR_implicit_shapes", json!({ "shapes": phys.khr }));
        b.use_extension("KHR_physics_rigid_bodies");
    }
    Ok((b.finish()?, nav))
}

/// Adds the animation of instance node `node` (posed at `rest`, its splats baked at that pose's
/// scale) over the timeline's frames: translation and yaw as the track says, and its scale
/// relative to the rest scale.
fn animate(
    b: &mut GlbBuilder,
    name: &str,
    node: usize,
    timeline: &crate::scene::dir::Timeline,
    track: &crate::scene::dir::Track,
    rest: &crate::scene::compose::Placement,
) {
    use crate::scene::timeline::{frame_times, sample};
    let ratio = |k: f64, r: f64| if r.abs() > 1e-9 { k / r } else { 1.0 };
    let keys: Vec<(f64, NodeTransform)> = frame_times(timeline)
        .into_iter()
        .filter_map(|t| {
            let p = sample(track, t)?;
            let half = (p.yaw.to_radians() / 2.0).sin_cos();
            let s = [0, 1, 2].map(|a| ratio(p.scale[a], rest.scale[a]));
            Some((
                t,
                NodeTransform {
                    translation: Some(y_up(p.position).map(f64::from)),
                    rotation: Some([0.0, half.0, 0.0, half.1]),
                    scale: Some([s[0], s[2], s[1]]),
                },
            ))
        })
        .collect();
    if !keys.is_empty() {
        b.add_node_animation(name, node, &keys);
    }
}

/// The points 0.6 m inside the room in front of each door, where spawn points go first.
pub fn door_points(input: &SceneInput) -> Vec<[f64; 2]> {
    input
        .openings
        .iter()
        .filter(|o| o.kind == "door")
        .map(|o| inside_point(o, 0.6))
        .collect()
}

/// The point `d` metres inside the room in front of an opening.
fn inside_point(o: &collider::Opening, d: f64) -> [f64; 2] {
    let [x, y, _] = o.position;
    match o.wall.as_str() {
        "north" => [x, y - d],
        "south" => [x, y + d],
        "east" => [x - d, y],
        _ => [x + d, y],
    }
}

/// Reads the scene in `dir` and writes the engine glb to `out` and the navmesh as OBJ beside
/// it (`<stem>.navmesh.obj`), atomically; returns the glb's size and the navmesh.
pub fn export_scene(dir: &Path, opts: &EngineOptions, out: &Path) -> Result<(usize, NavMesh)> {
    let input = read_input_at(dir, opts.time)?;
    let (bytes, nav) = encode(&input, opts)?;
    let write = |p: &Path, b: &[u8]| {
        crate::util::write_atomic(p, b).map_err(|source| ExportError::Write {
            path: p.display().to_string(),
            source,
        })
    };
    write(out, &bytes)?;
    write(&navmesh_path(out), nav.to_obj().as_bytes())?;
    Ok((bytes.len(), nav))
}

/// Where [`export_scene`] writes the navmesh OBJ for a glb at `out`.
pub fn navmesh_path(out: &Path) -> std::path::PathBuf {
    let stem = out
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy());
    out.with_file_name(format!("{stem}.navmesh.obj"))
}

/// The Gaussians of `g` that `keep` marks, in order.
pub fn select(g: &Gaussians, keep: &[bool]) -> Gaussians {
    let on = |i: &usize| keep.get(*i).copied().unwrap_or(false);
    let idx: Vec<usize> = (0..g.len()).filter(on).collect();
    crate::splat::view::select(g, &idx)
}

/// Gaussians `start..start + count` of `g` (clamped to its length).
fn select_range(g: &Gaussians, start: usize, count: usize) -> Gaussians {
    let end = (start + count).min(g.len());
    let idx: Vec<usize> = (start.min(end)..end).collect();
    crate::splat::view::select(g, &idx)
}
