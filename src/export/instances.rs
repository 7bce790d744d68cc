//! What the engine-ready glb says of each instance beyond its pose: the style prompt it was
//! made from, and, behind `--splats per-object`, its Gaussians in its own node's frame so that
//! an engine moving the node moves the splats with it. Host-only.
use crate::scene::compose::transform;
use crate::scene::dir::SceneFile;
use crate::splat::Gaussians;
use serde_json::Value;
use std::path::Path;

/// The style prompt of every instance of `scene` (scene order): the description its last
/// `edit restyle` gave it (scene.json's history), else its category's description in
/// `spec.json`; `None` when neither says.
pub fn style_prompts(dir: &Path, scene: &SceneFile) -> Vec<Option<String>> {
    let spec: Value = std::fs::read_to_string(dir.join("spec.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok())
        .unwrap_or(Value::Null);
    scene
        .objects
        .iter()
        .map(|o| {
            let restyled = scene.history.iter().rev().find_map(|h| {
                (h["op"] == "restyle" && h["part"].as_str() == Some(o.id.as_str()))
                    .then(|| h["description"].as_str().map(str::to_string))
                    .flatten()
            });
            restyled.or_else(|| {
                spec["objects"][o.category.as_str()]["description"]
                    .as_str()
                    .map(str::to_string)
            })
        })
        .collect()
}

/// An instance's world-frame Gaussians in the frame of its glb node (translated to its
/// position and turned by its yaw about z; its scale stays in the Gaussians, as the node
/// carries none): the inverse of the node's transform.
pub fn node_local(world: &Gaussians, yaw_deg: f64, position: [f64; 3]) -> Gaussians {
    let centred = transform(world, 0.0, [1.0; 3], position.map(|v| -v));
    transform(&centred, -yaw_deg, [1.0; 3], [0.0; 3])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn node_local_undoes_the_node_transform() {
        let g = Gaussians {
            means: vec![[1.0, 2.0, 0.5], [1.5, 2.0, 0.0]],
            scales: vec![[0.0; 3]; 2],
            rotations: vec![[1.0, 0.0, 0.0, 0.0]; 2],
            opacities: vec![0.0; 2],
            sh: vec![0.0; 6],
            sh_degree: 0,
        };
        // The node stands at (1, 2, 0) turned 90°: world +x is its local -y.
        let l = node_local(&g, 90.0, [1.0, 2.0, 0.0]);
        let want = [[0.0, 0.0, 0.5], [0.0, -0.5, 0.0]];
        for (a, b) in l.means.iter().zip(want) {
            assert!(
                (0..3).all(|k| (f64::from(a[k]) - b[k]).abs() < 1e-6),
                "{a:?}"
            );
        }
        // Placing it back by the node's transform gives the world cloud.
        let back = transform(&l, 90.0, [1.0; 3], [1.0, 2.0, 0.0]);
        for (a, b) in back.means.iter().zip(&g.means) {
            assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-6));
        }
    }
}
