//! What an edit reads of a scene directory and the host-side checks it makes: `scene.json`,
//! the instances' sizes and anchors (from `layout.json`, else the object PLY's extent), the
//! relations of `spec.json`, oriented-box collisions against the walls and the other objects,
//! and composition of a scene whose changed PLYs are still in memory. Host-only.
use super::EditError;
use crate::plan::check::{
    anchors_unmet, penetration, relation_unsatisfied, relations_unsatisfied, wall_distances, Box2,
    TOLERANCE,
};
use crate::plan::spec::{Anchor, Layout, PlacedBy, PlacedObject, Relation, SceneSpec, SceneType};
use crate::scene::compose::{merge, place};
use crate::scene::dir::{read_scene, SceneFile, SceneObject};
use crate::shape::Mount;
use crate::splat::ply::read_ply;
use crate::splat::Gaussians;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A scene directory opened for editing.
#[derive(Debug, Clone)]
pub struct SceneState {
    pub dir: PathBuf,
    pub scene: SceneFile,
    /// `layout.json`, kept in step with `scene.json` by the edits (absent in hand-made scenes).
    pub layout: Option<Layout>,
    /// Relations between instances (`spec.json`'s, those naming present instances).
    pub relations: Vec<Relation>,
    /// Size ([w, d, h], metres, scale applied) and anchor of every instance, by id.
    pub sizes: BTreeMap<String, [f64; 3]>,
    pub anchors: BTreeMap<String, Anchor>,
}

impl SceneState {
    /// Opens `dir` (its `scene.json` checked; sizes from `layout.json` or the object PLYs).
    pub fn open(dir: &Path) -> Result<SceneState, EditError> {
        let scene = read_scene(dir)?;
        let layout: Option<Layout> = std::fs::read_to_string(dir.join("layout.json"))
            .ok()
            .and_then(|t| serde_json::from_str(&t).ok());
        let relations: Vec<Relation> = std::fs::read_to_string(dir.join("spec.json"))
            .ok()
            .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
            .and_then(|v| serde_json::from_value(v.get("relations")?.clone()).ok())
            .unwrap_or_default();
        let mut sizes = BTreeMap::new();
        let mut anchors = BTreeMap::new();
        for o in &scene.objects {
            let planned = layout
                .as_ref()
                .and_then(|l| l.objects.iter().find(|p| p.id == o.id));
            let size = match planned {
                Some(p) => p.size,
                None => {
                    let g = read_ply(&dir.join(&o.ply))?;
                    let e = extent(&g);
                    [0, 1, 2].map(|a| e[a] * o.scale[a].abs())
                }
            };
            sizes.insert(o.id.clone(), size);
            anchors.insert(o.id.clone(), planned.map_or(Anchor::Others, |p| p.anchor));
        }
        let ids: Vec<&str> = scene.objects.iter().map(|o| o.id.as_str()).collect();
        let relations = relations
            .into_iter()
            .filter(|r| ids.contains(&r.subject.as_str()) && ids.contains(&r.object.as_str()))
            .collect();
        Ok(SceneState {
            dir: dir.to_path_buf(),
            scene,
            layout,
            relations,
            sizes,
            anchors,
        })
    }

    /// How the things of `category` are held up in this scene, as its draft drew them: the
    /// mount the layout gives the category in the scene's `spec.json` (a TV in a room with no
    /// stand for it hangs on the wall), else the knowledge base's. A redraw of an instance (a
    /// restyle) takes it, so a wall TV gets no foot back and a wall mirror no legs.
    pub fn mount(&self, category: &str) -> Mount {
        std::fs::read_to_string(self.dir.join("spec.json"))
            .ok()
            .and_then(|t| serde_json::from_str::<SceneSpec>(&t).ok())
            .map_or_else(
                || Mount::of_category(category),
                |spec| Mount::in_scene(&spec, category),
            )
    }

    /// Every instance's id and category, in scene order (what names in a sentence resolve to).
    pub fn id_categories(&self) -> Vec<(String, String)> {
        self.scene
            .objects
            .iter()
            .map(|o| (o.id.clone(), o.category.clone()))
            .collect()
    }

    /// The instance `id`, or an error listing the ids there are.
    pub fn object(&self, id: &str) -> Result<&SceneObject, EditError> {
        self.scene
            .objects
            .iter()
            .find(|o| o.id == id)
            .ok_or_else(|| {
                let ids: Vec<&str> = self.scene.objects.iter().map(|o| o.id.as_str()).collect();
                EditError::Bad(format!(
                    "no instance `{id}` in the scene (it has {})",
                    if ids.is_empty() {
                        "none".to_string()
                    } else {
                        ids.join(", ")
                    }
                ))
            })
    }

    /// The footprint box of instance `o` at its current transform.
    pub fn box_of(&self, o: &SceneObject) -> Box2 {
        let s = self.sizes.get(&o.id).copied().unwrap_or([0.0; 3]);
        Box2::new(
            [o.position[0], o.position[1]],
            o.yaw,
            [s[0], s[1]],
            o.position[2],
            o.position[2] + s[2],
        )
    }

    /// The instances at their current transforms, as placed objects (anchors kept).
    fn placed_objects(&self) -> Vec<PlacedObject> {
        self.scene
            .objects
            .iter()
            .map(|o| {
                let planned = self
                    .layout
                    .as_ref()
                    .and_then(|l| l.objects.iter().find(|p| p.id == o.id));
                PlacedObject {
                    id: o.id.clone(),
                    category: o.category.clone(),
                    size: self.sizes.get(&o.id).copied().unwrap_or([0.0; 3]),
                    position: o.position,
                    yaw: o.yaw,
                    anchor: self.anchors.get(&o.id).copied().unwrap_or(Anchor::Others),
                    placed_by: planned.map_or(PlacedBy::Constraint, |p| p.placed_by),
                }
            })
            .collect()
    }

    /// The layout of the current scene (positions, yaws and sizes of `scene.json`, anchors kept).
    pub fn current_layout(&self) -> Layout {
        let objects = self.placed_objects();
        let unsatisfied = relations_unsatisfied(&objects, &self.relations);
        let openings = self
            .layout
            .as_ref()
            .map_or_else(Vec::new, |l| l.openings.clone());
        let room = self.scene.room.size;
        let unsatisfied_anchors = anchors_unmet(&objects, self.scene.scene_type, room, &openings);
        Layout {
            scene_type: self.scene.scene_type,
            room: crate::plan::spec::Room {
                size: self.scene.room.size,
            },
            seed: self.layout.as_ref().map_or(self.scene.seed, |l| l.seed),
            objects,
            unsatisfied,
            unsatisfied_anchors,
            openings,
        }
    }

    /// Whether relation `r` holds between the current instances, as the layout judges it
    /// ([`relation_unsatisfied`]: FRONT / BEHIND alone within reach, OPPOSITE's sightline
    /// clear); true when it names an instance the scene does not have.
    pub fn relation_holds(&self, r: &Relation) -> bool {
        !relation_unsatisfied(&self.placed_objects(), &self.relations, r)
    }

    /// The shift (x, y) that brings instance `id` inside the walls (or the ground's edges) where
    /// it passes through them by no more than the collision tolerance: what a move that ends
    /// flush against a wall, a centimetre through it, takes back. Zero where it is inside or
    /// further through (that is a collision).
    pub fn back_inside(&self, id: &str) -> [f64; 2] {
        let Ok(o) = self.object(id) else {
            return [0.0; 2];
        };
        let w = wall_distances(&self.box_of(o), self.scene.room.size);
        if w.iter().any(|&v| v < -TOLERANCE - 1e-9) {
            return [0.0; 2];
        }
        let out = |v: f64| if v < -1e-6 { -v } else { 0.0 };
        [out(w[0]) - out(w[1]), out(w[2]) - out(w[3])]
    }

    /// Why instance `id` at its current transform collides, compared with `before` (its state
    /// before the edit: a collision already there and not made deeper is not the edit's doing).
    /// Empty when it is free.
    pub fn collisions(&self, id: &str, before: &SceneState) -> Vec<String> {
        let Ok(o) = self.object(id) else {
            return vec![];
        };
        let b = self.box_of(o);
        let old = before.object(id).ok().map(|p| before.box_of(p));
        let mut out = vec![];
        let room = self.scene.room.size;
        let walls = wall_distances(&b, room);
        let old_walls = old.map(|ob| wall_distances(&ob, room));
        let names = match self.scene.scene_type {
            SceneType::Indoor => [
                "west wall (x = -W/2)",
                "east wall (x = +W/2)",
                "south wall (y = -D/2)",
                "north wall (y = +D/2)",
            ],
            SceneType::Outdoor => [
                "ground's west edge",
                "ground's east edge",
                "ground's south edge",
                "ground's north edge",
            ],
        };
        for k in 0..4 {
            let was = old_walls.map_or(0.0, |w| w[k].min(0.0));
            if walls[k] < -TOLERANCE && walls[k] < was - 1e-6 {
                out.push(format!(
                    "{id} would pass {:.2} m through the {}",
                    -walls[k], names[k]
                ));
            }
        }
        if b.z1 > room[2] + TOLERANCE {
            out.push(format!(
                "{id} would reach {:.2} m, above the {} at {:.2} m",
                b.z1,
                if self.scene.scene_type == SceneType::Indoor {
                    "ceiling"
                } else {
                    "sky"
                },
                room[2]
            ));
        }
        for other in &self.scene.objects {
            if other.id == id {
                continue;
            }
            let p = penetration(&b, &self.box_of(other));
            let was = old
                .zip(before.object(&other.id).ok())
                .map_or(0.0, |(ob, op)| {
                    penetration(&ob, &before.box_of(op)).max(0.0)
                });
            if p > TOLERANCE && p > was + 1e-6 {
                out.push(format!("{id} would overlap {} by {p:.2} m", other.id));
            }
        }
        out
    }

    /// The merged world-frame cloud of the scene with `overlay`'s clouds (by relative path) in
    /// place of the files: what `scene.ply` becomes once the overlay is written.
    pub fn compose(&self, overlay: &BTreeMap<String, Gaussians>) -> Result<Gaussians, EditError> {
        Ok(merge(&self.compose_parts(overlay)?))
    }

    /// The parts [`SceneState::compose`] merges, in its order: one placed cloud per instance of
    /// `scene.json`, then the environment (when its stage is done); the per-Gaussian labels of
    /// `scene.ply` follow from their sizes.
    pub fn compose_parts(
        &self,
        overlay: &BTreeMap<String, Gaussians>,
    ) -> Result<Vec<Gaussians>, EditError> {
        let mut loaded: BTreeMap<&str, Gaussians> = BTreeMap::new();
        for o in &self.scene.objects {
            if !loaded.contains_key(o.ply.as_str()) {
                loaded.insert(&o.ply, self.load(&o.ply, overlay)?);
            }
        }
        let mut parts: Vec<Gaussians> = self
            .scene
            .objects
            .iter()
            .map(|o| place(&loaded[o.ply.as_str()], &o.placement()))
            .collect();
        if let Some(env) = &self.scene.environment {
            if !self.scene.stage_pending("environment") {
                let mut e = self.load(&env.ply, overlay)?;
                crate::scene::dir::light_draft(&self.scene, &|rel| loaded.get(rel), &mut e);
                parts.push(e);
            }
        }
        Ok(parts)
    }

    /// The cloud at `rel`: from `overlay` when it holds it, else read from the directory.
    pub fn load(
        &self,
        rel: &str,
        overlay: &BTreeMap<String, Gaussians>,
    ) -> Result<Gaussians, EditError> {
        if let Some(g) = overlay.get(rel) {
            return Ok(g.clone());
        }
        let path = self.dir.join(rel);
        if !path.is_file() {
            return Err(EditError::Bad(format!(
                "{}: not found (named in scene.json)",
                path.display()
            )));
        }
        Ok(read_ply(&path)?)
    }
}

/// Extent `[w, d, h]` of an object-frame cloud (means): twice the largest |x| and |y|, top z.
pub fn extent(g: &Gaussians) -> [f64; 3] {
    let mut e = [0.0f64; 3];
    for m in &g.means {
        e[0] = e[0].max(2.0 * (m[0] as f64).abs());
        e[1] = e[1].max(2.0 * (m[1] as f64).abs());
        e[2] = e[2].max(m[2] as f64);
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene directory of a sofa, its coffee table (FRONT, alone) and a TV stand OPPOSITE it,
    /// with sizes from layout.json (no PLYs needed).
    fn scene(dir: &Path, table_y: f64, blocker: bool) {
        std::fs::create_dir_all(dir).expect("dir");
        let mut objects = vec![
            ("sofa1", "sofa", [2.0, 0.9, 0.8], [0.0, -1.5, 0.0], 0.0),
            (
                "coffee table1",
                "coffee table",
                [1.0, 0.5, 0.45],
                [0.0, table_y, 0.0],
                0.0,
            ),
            (
                "tv stand1",
                "tv stand",
                [1.4, 0.4, 0.5],
                [0.0, 1.6, 0.0],
                180.0,
            ),
        ];
        if blocker {
            objects.push((
                "bookshelf1",
                "bookshelf",
                [1.0, 0.35, 1.9],
                [0.0, 1.0, 0.0],
                0.0,
            ));
        }
        let scene_objects: Vec<serde_json::Value> = objects
            .iter()
            .map(|(id, c, _, p, y)| {
                serde_json::json!({"id": id, "category": c, "ply": format!("objects/{c}.ply"),
                    "position": p, "yaw": y, "scale": [1.0, 1.0, 1.0]})
            })
            .collect();
        let placed: Vec<serde_json::Value> = objects
            .iter()
            .map(|(id, c, s, p, y)| {
                serde_json::json!({"id": id, "category": c, "size": s, "position": p, "yaw": y,
                    "anchor": "OTHERS", "placed_by": "constraint"})
            })
            .collect();
        let room = serde_json::json!({"size": [5.0, 4.4, 2.8]});
        let write = |name: &str, v: serde_json::Value| {
            std::fs::write(dir.join(name), v.to_string()).expect("write");
        };
        write(
            "scene.json",
            serde_json::json!({"version": 1, "prompt": "a living room", "seed": 0,
                "scene_type": "indoor", "room": room, "prior": {"kind": "shape", "models": null},
                "objects": scene_objects, "environment": null, "stages": [], "timeline": null}),
        );
        write(
            "layout.json",
            serde_json::json!({"scene_type": "indoor", "room": room, "seed": 0,
                "objects": placed, "unsatisfied": []}),
        );
        write(
            "spec.json",
            serde_json::json!({"scene_type": "indoor", "scene_text": "a living room",
                "objects": {}, "relations": [
                {"subject": "coffee table1", "relation": "FRONT", "object": "sofa1"},
                {"subject": "tv stand1", "relation": "OPPOSITE", "object": "sofa1"}]}),
        );
    }

    #[test]
    fn edits_judge_relations_as_the_layout_does() {
        let dir = std::env::temp_dir().join(format!("dreamscene-state-{}", std::process::id()));
        let holds = |table_y: f64, blocker: bool| {
            let _ = std::fs::remove_dir_all(&dir);
            scene(&dir, table_y, blocker);
            let s = SceneState::open(&dir).expect("open");
            let r = s.relations.clone();
            assert_eq!(r.len(), 2, "relations read");
            let got = (s.relation_holds(&r[0]), s.relation_holds(&r[1]));
            assert_eq!(
                s.current_layout().unsatisfied.len(),
                [got.0, got.1].iter().filter(|h| !**h).count(),
                "the layout's report agrees"
            );
            got
        };
        // within reach of the sofa, sightline clear
        assert_eq!(holds(-0.75, false), (true, true));
        // 1.4 m off the sofa: FRONT by the plain reading (gap <= 3 m), not within reach
        assert_eq!(holds(0.45, false), (false, true));
        // a bookcase between the sofa and the TV stand blocks the sightline
        assert_eq!(holds(-0.75, true), (true, false));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
