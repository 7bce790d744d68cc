//! The scene-graph side of [`GlbBuilder`]: nodes with children, extras and extensions, plain
//! triangle meshes (colliders, the navmesh), `EXT_mesh_features` feature ids on a splat
//! primitive, and document-level extension objects.
use super::{GlbBuilder, ARRAY_BUFFER};
use serde_json::{json, Value};

/// `ELEMENT_ARRAY_BUFFER`, the target of index buffer views.
const ELEMENT_ARRAY_BUFFER: u32 = 34963;
const UNSIGNED_SHORT: u32 = 5123;
const UNSIGNED_INT: u32 = 5125;
/// The glTF extension of per-vertex feature ids.
pub const MESH_FEATURES: &str = "EXT_mesh_features";

impl GlbBuilder {
    /// Records `name` in `extensionsUsed` (never in `extensionsRequired`).
    pub fn use_extension(&mut self, name: &str) {
        if name != super::EXTENSION && !self.used.iter().any(|u| u == name) {
            self.used.push(name.to_string());
        }
    }

    /// Sets a document-level extension object (and marks the extension used).
    pub fn set_root_extension(&mut self, name: &str, value: Value) {
        self.use_extension(name);
        self.root_extensions.insert(name.to_string(), value);
    }

    /// Adds a node given as its JSON (name, mesh, transform, extras, extensions) and returns
    /// its index; it is a root until [`GlbBuilder::add_child`] hangs it under another.
    pub fn push_node(&mut self, node: Value) -> usize {
        self.nodes.push(node);
        self.nodes.len() - 1
    }

    /// Makes `child` a child of `parent`.
    pub fn add_child(&mut self, parent: usize, child: usize) {
        let node = &mut self.nodes[parent];
        if !node["children"].is_array() {
            node["children"] = json!([]);
        }
        if let Some(c) = node["children"].as_array_mut() {
            c.push(json!(child));
        }
    }

    /// Sets `key` of node `node`'s JSON (e.g. `extensions`).
    pub fn set_node_field(&mut self, node: usize, key: &str, value: Value) {
        self.nodes[node][key] = value;
    }

    /// Adds a mesh of one `TRIANGLES` primitive (positions in the glTF frame, 32-bit indices,
    /// counter-clockwise faces seen from outside) and returns the mesh's index.
    pub fn add_triangles(
        &mut self,
        name: &str,
        positions: &[[f32; 3]],
        indices: &[u32],
        extras: Value,
    ) -> usize {
        let flat: Vec<f32> = positions.iter().flatten().copied().collect();
        let pos = self.floats(&flat, 3, "VEC3", true);
        let bytes: Vec<u8> = indices.iter().flat_map(|i| i.to_le_bytes()).collect();
        let view = self.plain_view(&bytes);
        self.views[view]["target"] = json!(ELEMENT_ARRAY_BUFFER);
        self.accessors.push(json!({
            "bufferView": view, "componentType": UNSIGNED_INT, "count": indices.len(),
            "type": "SCALAR"
        }));
        let idx = self.accessors.len() - 1;
        let mut mesh = json!({
            "name": name,
            "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx, "mode": 4 }]
        });
        if !extras.is_null() {
            mesh["extras"] = extras;
        }
        self.meshes.push(mesh);
        self.meshes.len() - 1
    }

    /// Adds `_FEATURE_ID_0` (one unsigned short per vertex) to the first primitive of `mesh`
    /// with its `EXT_mesh_features` entry; the feature count is the number of distinct ids.
    pub fn add_feature_ids(&mut self, mesh: usize, ids: &[u16], label: &str) {
        // Each vertex attribute element starts on a 4-byte boundary: a stride of 4.
        let bytes: Vec<u8> = ids
            .iter()
            .flat_map(|i| {
                let b = i.to_le_bytes();
                [b[0], b[1], 0, 0]
            })
            .collect();
        let view = self.plain_view(&bytes);
        self.views[view]["target"] = json!(ARRAY_BUFFER);
        self.views[view]["byteStride"] = json!(4);
        self.accessors.push(json!({
            "bufferView": view, "componentType": UNSIGNED_SHORT, "count": ids.len(),
            "type": "SCALAR"
        }));
        let acc = self.accessors.len() - 1;
        let mut seen = vec![false; usize::from(u16::MAX) + 1];
        let mut count = 0;
        for &i in ids {
            if !seen[usize::from(i)] {
                seen[usize::from(i)] = true;
                count += 1;
            }
        }
        let prim = &mut self.meshes[mesh]["primitives"][0];
        prim["attributes"]["_FEATURE_ID_0"] = json!(acc);
        prim["extensions"][MESH_FEATURES] = json!({
            "featureIds": [{ "featureCount": count, "attribute": 0, "label": label }]
        });
        self.use_extension(MESH_FEATURES);
    }
}
