//! glTF 2.0 binary (`.glb`) with `KHR_gaussian_splatting` (Khronos release candidate,
//! `extensions/2.0/Khronos/KHR_gaussian_splatting/README.md`): each cloud is a mesh primitive in
//! `POINTS` mode whose attributes are
//!
//! - `POSITION` (float VEC3, with min/max), the Gaussian means;
//! - `KHR_gaussian_splatting:ROTATION` (float VEC4), unit quaternions in glTF's (x, y, z, w) order;
//! - `KHR_gaussian_splatting:SCALE` (float VEC3), linear scales `exp(scale_i)`;
//! - `KHR_gaussian_splatting:OPACITY` (float SCALAR), `sigmoid(opacity)` in 0..1;
//! - `KHR_gaussian_splatting:SH_DEGREE_0_COEF_0` and `SH_DEGREE_l_COEF_n` (float VEC3, r g b) for
//!   every band the cloud has, `n` running over m = -l..l as in the INRIA basis;
//! - `COLOR_0` (normalised u8 VEC4), the fallback for viewers without the extension: the diffuse
//!   colour `clamp(0.5 + SH_C0 · f_dc)` decoded from sRGB to linear (glTF vertex colours are
//!   linear), alpha the opacity; such viewers draw a coloured point cloud.
//!
//! The extension object says `kernel: "ellipse"`, `colorSpace: "srgb_rec709_display"` (3DGS
//! colours are display sRGB), the default projection and sorting. glTF is y-up, the project's
//! world z-up, so [`to_gltf_frame`] rotates the cloud -90° about x (`(x, y, z) -> (x, z, -y)`),
//! quaternions and SH included, before writing (baked into the data rather than put in a node
//! rotation, so viewers that do not rotate SH by the node still light it right). [`GlbBuilder`] can hold several meshes and nodes (one per object instance,
//! with node translations and rotations); [`encode`] writes one node for the whole cloud.
mod graph;

use super::{sigmoid, ExportError, Result};
use crate::scene::sh_rotate::Mat3;
use crate::splat::cloud::SH_C0;
use crate::splat::Gaussians;
use serde_json::{json, Value};

/// The extension's name, also the prefix of its attribute semantics.
pub const EXTENSION: &str = "KHR_gaussian_splatting";
/// `ARRAY_BUFFER`, the target of vertex attribute buffer views.
const ARRAY_BUFFER: u32 = 34962;
/// Component types.
const FLOAT: u32 = 5126;
const UNSIGNED_BYTE: u32 = 5121;

/// The project's world frame (z up) to glTF's (y up): -90° about x.
pub const Z_UP_TO_Y_UP: Mat3 = [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]];

/// `g` rotated from the project's z-up world into glTF's y-up frame: means `(x, z, -y)`,
/// quaternions and SH bands rotated with them ([`super::rotate`]).
pub fn to_gltf_frame(g: &Gaussians) -> Gaussians {
    super::rotate(g, &Z_UP_TO_Y_UP)
}

/// sRGB transfer function decoded to linear (IEC 61966-2-1).
fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// A glTF asset under construction: one binary buffer, its views and accessors, meshes of splat
/// primitives and the nodes that place them.
#[derive(Debug, Default)]
pub struct GlbBuilder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
    meshes: Vec<Value>,
    nodes: Vec<Value>,
    animations: Vec<Value>,
    /// Extensions used besides [`EXTENSION`], in first-use order.
    used: Vec<String>,
    /// Document-level extension objects.
    root_extensions: serde_json::Map<String, Value>,
}

/// A node's placement: glTF translation and rotation (x, y, z, w), in the parent's frame.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct NodeTransform {
    pub translation: Option<[f64; 3]>,
    pub rotation: Option<[f64; 4]>,
    pub scale: Option<[f64; 3]>,
}

/// The smallest and largest value of each of the `comps` components (an accessor's min/max).
fn bounds(data: &[f32], comps: usize) -> (Vec<f32>, Vec<f32>) {
    let mut lo = vec![f32::INFINITY; comps];
    let mut hi = vec![f32::NEG_INFINITY; comps];
    for row in data.chunks_exact(comps) {
        for (j, &v) in row.iter().enumerate() {
            lo[j] = lo[j].min(v);
            hi[j] = hi[j].max(v);
        }
    }
    (lo, hi)
}

impl GlbBuilder {
    /// An empty asset.
    pub fn new() -> GlbBuilder {
        GlbBuilder::default()
    }

    /// Appends `bytes` as a vertex-attribute buffer view (4-byte aligned) and returns its index.
    fn view(&mut self, bytes: &[u8]) -> usize {
        let v = self.plain_view(bytes);
        self.views[v]["target"] = json!(ARRAY_BUFFER);
        v
    }

    /// Appends `bytes` as a buffer view without a target (animation data).
    fn plain_view(&mut self, bytes: &[u8]) -> usize {
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.bin.resize(self.bin.len().next_multiple_of(4), 0);
        self.views.push(json!({
            "buffer": 0, "byteOffset": offset, "byteLength": bytes.len()
        }));
        self.views.len() - 1
    }

    /// A float accessor of animation data (`comps` components a key), with min/max.
    fn animation_floats(&mut self, data: &[f32], comps: usize, ty: &str) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|v| v.to_le_bytes()).collect();
        let view = self.plain_view(&bytes);
        let (lo, hi) = bounds(data, comps);
        self.accessors.push(json!({
            "bufferView": view, "componentType": FLOAT, "count": data.len() / comps,
            "type": ty, "min": lo, "max": hi
        }));
        self.accessors.len() - 1
    }

    /// A float accessor of `comps` components a Gaussian (`ty` SCALAR, VEC3 or VEC4).
    fn floats(&mut self, data: &[f32], comps: usize, ty: &str, with_bounds: bool) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|v| v.to_le_bytes()).collect();
        let view = self.view(&bytes);
        let mut acc = json!({
            "bufferView": view, "componentType": FLOAT, "count": data.len() / comps, "type": ty
        });
        if with_bounds {
            let (lo, hi) = bounds(data, comps);
            acc["min"] = json!(lo);
            acc["max"] = json!(hi);
        }
        self.accessors.push(acc);
        self.accessors.len() - 1
    }

    /// Adds `g` (already in the glTF frame) as a mesh of one splat primitive and returns the
    /// mesh's index.
    pub fn add_splats(&mut self, name: &str, g: &Gaussians) -> Result<usize> {
        super::check_exportable(g)?;
        let n = g.len();
        let k = g.coeffs();
        let means: Vec<f32> = g.means.iter().flatten().copied().collect();
        let rot: Vec<f32> = g
            .rotations
            .iter()
            .flat_map(|q| {
                let q = super::unit_quat(*q);
                [q[1], q[2], q[3], q[0]]
            })
            .collect();
        let scale: Vec<f32> = g.scales.iter().flatten().map(|v| v.exp()).collect();
        let opacity: Vec<f32> = g.opacities.iter().map(|&o| sigmoid(o)).collect();
        let mut colour = Vec::with_capacity(n * 4);
        for (block, alpha) in g.sh.chunks_exact(k * 3).zip(&opacity) {
            for &dc in &block[..3] {
                let c = (0.5 + SH_C0 * f64::from(dc)).clamp(0.0, 1.0);
                colour.push(super::to_u8((srgb_to_linear(c) * 255.0) as f32));
            }
            colour.push(super::to_u8(alpha * 255.0));
        }

        let mut attrs = serde_json::Map::new();
        attrs.insert(
            "POSITION".into(),
            json!(self.floats(&means, 3, "VEC3", true)),
        );
        let view = self.view(&colour);
        self.accessors.push(json!({
            "bufferView": view, "componentType": UNSIGNED_BYTE, "normalized": true,
            "count": n, "type": "VEC4"
        }));
        attrs.insert("COLOR_0".into(), json!(self.accessors.len() - 1));
        let ext = |s: &str| format!("{EXTENSION}:{s}");
        attrs.insert(ext("ROTATION"), json!(self.floats(&rot, 4, "VEC4", false)));
        attrs.insert(ext("SCALE"), json!(self.floats(&scale, 3, "VEC3", false)));
        attrs.insert(
            ext("OPACITY"),
            json!(self.floats(&opacity, 1, "SCALAR", false)),
        );
        for l in 0..=g.sh_degree as usize {
            for m in 0..2 * l + 1 {
                let c = l * l + m;
                let vals: Vec<f32> = (0..n)
                    .flat_map(|i| {
                        let at = (i * k + c) * 3;
                        [g.sh[at], g.sh[at + 1], g.sh[at + 2]]
                    })
                    .collect();
                let acc = self.floats(&vals, 3, "VEC3", false);
                attrs.insert(ext(&format!("SH_DEGREE_{l}_COEF_{m}")), json!(acc));
            }
        }
        self.meshes.push(json!({
            "name": name,
            "primitives": [{
                "attributes": attrs,
                "mode": 0,
                "extensions": { EXTENSION: {
                    "kernel": "ellipse",
                    "colorSpace": "srgb_rec709_display",
                    "projection": "perspective",
                    "sortingMethod": "cameraDistance"
                }}
            }]
        }));
        Ok(self.meshes.len() - 1)
    }

    /// Adds a root node showing mesh `mesh`, placed by `t`, and returns its index.
    pub fn add_node(&mut self, name: &str, mesh: usize, t: NodeTransform) -> usize {
        let mut node = json!({ "name": name, "mesh": mesh });
        if let Some(tr) = t.translation {
            node["translation"] = json!(tr);
        }
        if let Some(r) = t.rotation {
            node["rotation"] = json!(r);
        }
        if let Some(sc) = t.scale {
            node["scale"] = json!(sc);
        }
        self.nodes.push(node);
        self.nodes.len() - 1
    }

    /// The `.glb` bytes: the 12-byte header, the JSON chunk (space-padded) and the BIN chunk.
    /// Adds an animation moving `node` through `keys` (time in seconds, transform), sampled
    /// linearly between keys.
    pub fn add_node_animation(&mut self, name: &str, node: usize, keys: &[(f64, NodeTransform)]) {
        let times: Vec<f32> = keys.iter().map(|k| k.0 as f32).collect();
        let input = self.animation_floats(&times, 1, "SCALAR");
        let mut samplers = vec![];
        let mut channels = vec![];
        let t: Vec<f32> = keys
            .iter()
            .flat_map(|k| k.1.translation.unwrap_or([0.0; 3]).map(|v| v as f32))
            .collect();
        let r: Vec<f32> = keys
            .iter()
            .flat_map(|k| {
                k.1.rotation
                    .unwrap_or([0.0, 0.0, 0.0, 1.0])
                    .map(|v| v as f32)
            })
            .collect();
        let s: Vec<f32> = keys
            .iter()
            .flat_map(|k| k.1.scale.unwrap_or([1.0; 3]).map(|v| v as f32))
            .collect();
        for (path, data, comps, ty) in [
            ("translation", t, 3, "VEC3"),
            ("rotation", r, 4, "VEC4"),
            ("scale", s, 3, "VEC3"),
        ] {
            let output = self.animation_floats(&data, comps, ty);
            samplers.push(json!({ "input": input, "output": output, "interpolation": "LINEAR" }));
            channels.push(json!({
                "sampler": samplers.len() - 1, "target": { "node": node, "path": path }
            }));
        }
        self.animations
            .push(json!({ "name": name, "samplers": samplers, "channels": channels }));
    }

    pub fn finish(self) -> Result<Vec<u8>> {
        let child: std::collections::HashSet<u64> = self
            .nodes
            .iter()
            .filter_map(|n| n["children"].as_array())
            .flatten()
            .filter_map(Value::as_u64)
            .collect();
        let roots: Vec<usize> = (0..self.nodes.len())
            .filter(|i| !child.contains(&(*i as u64)))
            .collect();
        let mut used = vec![EXTENSION.to_string()];
        used.extend(self.used.iter().cloned());
        let doc = json!({
            "asset": { "version": "2.0",
                       "generator": concat!("dreamscene ", env!("CARGO_PKG_VERSION")) },
            "extensionsUsed": used,
            "scene": 0,
            "scenes": [{ "nodes": roots }],
            "nodes": self.nodes,
            "meshes": self.meshes,
            "accessors": self.accessors,
            "bufferViews": self.views,
            "buffers": [{ "byteLength": self.bin.len() }],
        });
        let mut doc = doc;
        if !self.animations.is_empty() {
            doc["animations"] = json!(self.animations);
        }
        if !self.root_extensions.is_empty() {
            doc["extensions"] = Value::Object(self.root_extensions);
        }
        let mut text = serde_json::to_vec(&doc)
            .map_err(|e| ExportError::Unrepresentable(format!("glTF JSON: {e}")))?;
        text.resize(text.len().next_multiple_of(4), b' ');
        let total = 12 + 8 + text.len() + 8 + self.bin.len();
        let total = u32::try_from(total).map_err(|_| {
            ExportError::Unrepresentable(format!("{total} bytes: a .glb holds at most 4 GiB"))
        })?;
        let mut out = Vec::with_capacity(total as usize);
        out.extend(b"glTF");
        out.extend(2u32.to_le_bytes());
        out.extend(total.to_le_bytes());
        out.extend((text.len() as u32).to_le_bytes());
        out.extend(b"JSON");
        out.extend(text);
        out.extend((self.bin.len() as u32).to_le_bytes());
        out.extend(b"BIN\0");
        out.extend(self.bin);
        Ok(out)
    }
}

/// The `.glb` of `g` (project world frame): one mesh, one node, in glTF's y-up frame.
pub fn encode(g: &Gaussians) -> Result<Vec<u8>> {
    let mut b = GlbBuilder::new();
    let mesh = b.add_splats("scene", &to_gltf_frame(g))?;
    b.add_node("scene", mesh, NodeTransform::default());
    b.finish()
}
