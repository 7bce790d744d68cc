//! The object edits as changes of `scene.json`: move (with the collision check and the GCP
//! re-run for the partners of broken relations), remove and add (planned from the knowledge
//! base, placed by GCP with every present object pinned, built by the shape prior). Host-only:
//! the local re-optimisation and the renders are the caller's.
use super::commit::Edit;
use super::state::SceneState;
use super::{EditError, Result};
use crate::plan::check::Box2;
use crate::plan::gcp::{layout_pinned, LayoutOptions, Pin};
use crate::plan::spec::{
    Anchor, ObjectSpec, PlacedBy, Relation, RelationKind, SceneSpec, SceneType,
};
use crate::scene::dir::SceneObject;
use serde_json::json;
use std::collections::BTreeMap;

/// An instance's transform.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    pub position: [f64; 3],
    /// Degrees, counter-clockwise about +z.
    pub yaw: f64,
    pub scale: [f64; 3],
}

impl Pose {
    pub fn of(o: &SceneObject) -> Pose {
        Pose {
            position: o.position,
            yaw: o.yaw,
            scale: o.scale,
        }
    }

    /// The facing direction `(−sin yaw, cos yaw)`.
    pub fn forward(&self) -> [f64; 2] {
        let (s, c) = self.yaw.to_radians().sin_cos();
        [-s, c]
    }

    /// The object's left (facing turned +90°).
    pub fn left(&self) -> [f64; 2] {
        let f = self.forward();
        [-f[1], f[0]]
    }
}

/// The yaw (degrees) that faces direction `d`.
pub fn yaw_facing(d: [f64; 2]) -> f64 {
    (-d[0]).atan2(d[1]).to_degrees()
}

/// `yaw` brought into (−180, 180].
pub fn wrap_yaw(yaw: f64) -> f64 {
    let mut y = yaw % 360.0;
    if y > 180.0 {
        y -= 360.0;
    }
    if y <= -180.0 {
        y += 360.0;
    }
    y
}

/// What `move ID` asks with flags.
#[derive(Debug, Clone, Default)]
pub struct MoveFlags {
    /// New centre (x, y), world frame.
    pub to: Option<[f64; 2]>,
    /// Shift (dx, dy), world frame.
    pub by: Option<[f64; 2]>,
    /// Turn by this many degrees (counter-clockwise).
    pub rotate: Option<f64>,
    /// Turn to face this instance.
    pub face: Option<String>,
    /// Multiply the scale by this.
    pub scale: Option<f64>,
}

/// The pose `flags` give instance `id`: position (`--to` then `--by`), then yaw (`--rotate`,
/// or `--face`; a seat of a group moved without either turns to face its partner), then scale.
pub fn pose_from_flags(state: &SceneState, id: &str, flags: &MoveFlags) -> Result<Pose> {
    let o = state.object(id)?;
    let mut p = Pose::of(o);
    if let Some([x, y]) = flags.to {
        p.position[0] = x;
        p.position[1] = y;
    }
    if let Some([dx, dy]) = flags.by {
        p.position[0] += dx;
        p.position[1] += dy;
    }
    if let Some(r) = flags.rotate {
        p.yaw = wrap_yaw(p.yaw + r);
    } else if flags.face.is_none() && (flags.to.is_some() || flags.by.is_some()) {
        // a seat of a group (at a table, a desk, round a fire) turns to face its partner
        let partner = state.relations.iter().find(|r| {
            r.subject == id
                && matches!(
                    r.relation,
                    RelationKind::At
                        | RelationKind::AtBack
                        | RelationKind::Around
                        | RelationKind::Circle
                )
        });
        if let Some(t) = partner.and_then(|r| state.object(&r.object).ok()) {
            let d = [t.position[0] - p.position[0], t.position[1] - p.position[1]];
            if d[0].hypot(d[1]) > 1e-6 {
                p.yaw = wrap_yaw(yaw_facing(d));
            }
        }
    }
    if let Some(other) = &flags.face {
        let t = state.object(other)?;
        if t.id == id {
            return Err(EditError::Bad(format!("{id} cannot face itself")));
        }
        let d = [t.position[0] - p.position[0], t.position[1] - p.position[1]];
        p.yaw = wrap_yaw(yaw_facing(d));
    }
    if let Some(s) = flags.scale {
        if !(s.is_finite() && s > 0.0) {
            return Err(EditError::Bad(format!(
                "--scale {s}: expected a positive factor"
            )));
        }
        p.scale = p.scale.map(|v| v * s);
    }
    let finite = p.position.iter().chain(&p.scale).all(|v| v.is_finite()) && p.yaw.is_finite();
    if !finite {
        return Err(EditError::Bad("the new transform is not finite".into()));
    }
    Ok(p)
}

/// `state` with instance `id` at `pose` (its size follows the scale).
pub fn with_pose(state: &SceneState, id: &str, pose: Pose) -> Result<SceneState> {
    let mut next = state.clone();
    let old = Pose::of(state.object(id)?);
    let o = next
        .scene
        .objects
        .iter_mut()
        .find(|o| o.id == id)
        .ok_or_else(|| EditError::Bad(format!("no instance `{id}`")))?;
    o.position = pose.position;
    o.yaw = pose.yaw;
    o.scale = pose.scale;
    if let Some(s) = next.sizes.get_mut(id) {
        for (a, v) in s.iter_mut().enumerate() {
            *v *= (pose.scale[a] / old.scale[a]).abs();
        }
    }
    Ok(next)
}

/// Moves instance `id` to `pose`. Refused with the reasons when it would pass through a wall or
/// another object (unless `force`). When the move breaks a relation of `spec.json` that held,
/// and `follow` is set, the partners are placed again by GCP with every other object pinned.
/// Returns the edit and the footprints that changed (old and new, for the local
/// re-optimisation).
pub fn move_object(
    state: &SceneState,
    id: &str,
    pose: Pose,
    force: bool,
    follow: bool,
    args: serde_json::Value,
) -> Result<(Edit, Vec<Box2>)> {
    let before = state.object(id)?.clone();
    let mut pose = pose;
    // its seats go with it: what it may not run into is the rest
    let seats = super::riders::seats(state, id);
    let mut alone = state.clone();
    alone.scene.objects.retain(|o| !seats.contains(&o.id));
    let mut notes = vec![];
    // (a move that ends a centimetre through a wall stops at it)
    let shift = with_pose(&alone, id, pose)?.back_inside(id);
    if shift != [0.0; 2] && !force {
        pose.position[0] += shift[0];
        pose.position[1] += shift[1];
        notes.push(format!(
            "{id} stops at the wall, {:.2} m short of the asked pose",
            shift[0].hypot(shift[1])
        ));
    }
    let problems = with_pose(&alone, id, pose)?.collisions(id, &alone);
    if !problems.is_empty() {
        if force {
            notes.push(format!("placed despite: {} (--force)", problems.join("; ")));
        } else if let Some((p, _)) = nearest_free(&alone, id, pose)? {
            notes.push(format!(
                "the asked pose collides ({}); the nearest free pose is {:.2} m from it",
                problems.join("; "),
                dist2(p.position, pose.position)
            ));
            pose = p;
        } else {
            return Err(EditError::Collision(problems.join("; ")));
        }
    }
    if same_pose(Pose::of(&before), pose) {
        return Err(if problems.is_empty() {
            EditError::Bad(format!("{id} already stands there: nothing to move"))
        } else {
            EditError::Collision(format!(
                "{}; no free pose within {NEAREST_REACH} m but where {id} stands",
                problems.join("; ")
            ))
        });
    }
    let next = with_pose(state, id, pose)?;
    let (carried, riding) = super::riders::carry_riders(state, next, id, Pose::of(&before))?;
    let (carried, seats) = super::riders::carry_seats(state, carried, id, Pose::of(&before))?;
    let mut next = carried;
    let mut footprints = vec![state.box_of(&before), next.box_of(next.object(id)?)];
    for r in riding.iter().chain(&seats) {
        footprints.push(state.box_of(state.object(r)?));
        footprints.push(next.box_of(next.object(r)?));
    }
    notes.insert(
        0,
        format!(
            "{id}: position ({:.2}, {:.2}, {:.2}) -> ({:.2}, {:.2}, {:.2}), yaw {:.1} -> {:.1}, scale {:.3} -> {:.3}",
            before.position[0],
            before.position[1],
            before.position[2],
            pose.position[0],
            pose.position[1],
            pose.position[2],
            before.yaw,
            pose.yaw,
            before.scale[0],
            pose.scale[0]
        ),
    );
    let shift = [
        pose.position[0] - before.position[0],
        pose.position[1] - before.position[1],
    ];
    if shift[0].hypot(shift[1]) >= 0.005 {
        notes.insert(1, format!("{id} -> {}", world_words(shift)));
    }
    if !riding.is_empty() {
        notes.push(format!(
            "{} move with {id}: they rest on it",
            riding.join(", ")
        ));
    }
    if !seats.is_empty() {
        notes.push(format!(
            "{} move with {id}: they are its seats",
            seats.join(", ")
        ));
    }
    let broken: Vec<&Relation> = state
        .relations
        .iter()
        .filter(|r| (r.subject == id || r.object == id) && state.relation_holds(r))
        .filter(|r| !next.relation_holds(r))
        .collect();
    if !broken.is_empty() {
        let partners: Vec<String> = broken
            .iter()
            .map(|r| {
                if r.subject == id {
                    r.object.clone()
                } else {
                    r.subject.clone()
                }
            })
            .collect();
        if follow {
            let moved = replace_partners(&next, &partners, &[id])?;
            for (pid, p) in moved {
                let old = next.object(&pid)?.clone();
                let cand = with_pose(&next, &pid, p)?;
                if !cand.collisions(&pid, &next).is_empty() {
                    notes.push(format!("{pid} stays: no free pose keeps its relation"));
                    continue;
                }
                footprints.push(next.box_of(&old));
                next = cand;
                footprints.push(next.box_of(next.object(&pid)?));
                notes.push(format!(
                    "{pid} follows: ({:.2}, {:.2}) -> ({:.2}, {:.2}), yaw {:.1}",
                    old.position[0], old.position[1], p.position[0], p.position[1], p.yaw
                ));
            }
        }
        for r in &broken {
            if !next.relation_holds(r) {
                notes.push(format!(
                    "relation no longer holds: {} {:?} {}",
                    r.subject, r.relation, r.object
                ));
            }
        }
    }
    let mut edit = Edit::new(state, "move", args);
    edit.scene = next.scene.clone();
    edit.layout = state.layout.as_ref().map(|_| next.current_layout());
    edit.notes = notes;
    Ok((edit, footprints))
}

/// Whether two poses are the same (a tenth of a millimetre, a thousandth of a degree: a move
/// by 1 mm is a move), the same scale.
fn same_pose(a: Pose, b: Pose) -> bool {
    dist2(a.position, b.position) < 1e-4
        && (a.position[2] - b.position[2]).abs() < 1e-4
        && wrap_yaw(a.yaw - b.yaw).abs() < 1e-3
        && (0..3).all(|k| (a.scale[k] - b.scale[k]).abs() < 1e-6)
}

/// Most a colliding move is shifted to find a free pose (metres).
const NEAREST_REACH: f64 = 0.5;

/// The free pose nearest `pose` for `id` (same yaw and height; rings 5 cm apart, 16 directions
/// each), with the state it gives; `None` when nothing within [`NEAREST_REACH`] is free.
fn nearest_free(state: &SceneState, id: &str, pose: Pose) -> Result<Option<(Pose, SceneState)>> {
    let steps = (NEAREST_REACH / 0.05).round() as usize;
    for ring in 1..=steps {
        let r = ring as f64 * 0.05;
        for k in 0..16 {
            let a = k as f64 * std::f64::consts::TAU / 16.0;
            let mut p = pose;
            p.position[0] += r * a.cos();
            p.position[1] += r * a.sin();
            let cand = with_pose(state, id, p)?;
            if cand.collisions(id, state).is_empty() {
                return Ok(Some((p, cand)));
            }
        }
    }
    Ok(None)
}

fn dist2(a: [f64; 3], b: [f64; 3]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// A world-frame shift in words: "0.30 m east", "0.20 m north and 0.10 m west" (north is +y,
/// east +x; a component under 5 mm is left out).
pub fn world_words(d: [f64; 2]) -> String {
    let mut parts = vec![];
    if d[1].abs() >= 0.005 {
        let w = if d[1] > 0.0 { "north" } else { "south" };
        parts.push(format!("{:.2} m {w}", d[1].abs()));
    }
    if d[0].abs() >= 0.005 {
        let w = if d[0] > 0.0 { "east" } else { "west" };
        parts.push(format!("{:.2} m {w}", d[0].abs()));
    }
    if parts.is_empty() {
        "in place".into()
    } else {
        parts.join(" and ")
    }
}

/// New poses for `free` by GCP with every other instance pinned where it is (`extra` pinned
/// too, even when listed in `free`). Instances GCP could only place by fallback are left out.
pub fn replace_partners(
    state: &SceneState,
    free: &[String],
    extra: &[&str],
) -> Result<Vec<(String, Pose)>> {
    let (spec, key) = gcp_spec(state, None)?;
    let mut pins = BTreeMap::new();
    for o in &state.scene.objects {
        if !free.contains(&o.id) || extra.contains(&o.id.as_str()) {
            pins.insert(
                key[&o.id].clone(),
                Pin {
                    position: o.position,
                    yaw: o.yaw,
                },
            );
        }
    }
    let l = layout_pinned(
        &spec,
        LayoutOptions::seeded(state.scene.seed),
        &pins,
        state.layout.as_ref().map(|l| l.openings.as_slice()),
    )
    .map_err(|e| EditError::Bad(format!("re-running the layout: {e}")))?;
    let mut out = vec![];
    for o in &state.scene.objects {
        if pins.contains_key(&key[&o.id]) {
            continue;
        }
        if let Some(p) = l.objects.iter().find(|p| p.id == key[&o.id]) {
            if p.placed_by == PlacedBy::Constraint {
                out.push((
                    o.id.clone(),
                    Pose {
                        position: p.position,
                        yaw: p.yaw,
                        scale: o.scale,
                    },
                ));
            }
        }
    }
    Ok(out)
}

/// One more instance for [`gcp_spec`]: id, category, size, anchor and its relations.
type Added<'a> = (&'a str, &'a str, [f64; 3], Anchor, Vec<Relation>);

/// A SceneSpec of the present instances for GCP under their own categories (each instance
/// with its own size and anchor), so the placement classes hold for them as in the plan: a
/// mirror added or placed again hangs on a wall at its height, a lamp goes on a support. The
/// instances are renumbered per category; instance `id` is called `key[id]`. `add` appends one
/// more instance (`id`, category, size, anchor, its relations).
fn gcp_spec(
    state: &SceneState,
    add: Option<Added>,
) -> Result<(SceneSpec, BTreeMap<String, String>)> {
    let mut entries: Vec<(String, String, [f64; 3], Anchor)> = state
        .scene
        .objects
        .iter()
        .map(|o| {
            let size = state.sizes.get(&o.id).copied().unwrap_or([0.0; 3]);
            let anchor = state.anchors.get(&o.id).copied().unwrap_or(Anchor::Others);
            (o.id.clone(), o.category.clone(), size, anchor)
        })
        .collect();
    let mut relations = state.relations.clone();
    if let Some((id, category, size, anchor, rels)) = add {
        entries.push((id.to_string(), category.to_string(), size, anchor));
        relations.extend(rels);
    }
    let mut objects: BTreeMap<String, ObjectSpec> = BTreeMap::new();
    let mut anchors = BTreeMap::new();
    let mut key = BTreeMap::new();
    // what the plan hung on a wall that its kind stands on the floor stays hung
    let planned: Option<SceneSpec> = std::fs::read_to_string(state.dir.join("spec.json"))
        .ok()
        .and_then(|t| serde_json::from_str(&t).ok());
    let hung = |cat: &str| planned.as_ref()?.objects.get(cat)?.on_wall;
    for (id, cat, size, anchor) in entries {
        let size = size.map(|v| v.max(1e-3));
        let o = objects.entry(cat.clone()).or_insert_with(|| ObjectSpec {
            number: 0,
            size,
            description: cat.clone(),
            rows: 0,
            sizes: vec![],
            on_wall: hung(&cat),
        });
        o.number += 1;
        o.sizes.push(size);
        // (`size` is the largest instance's, as the spec has it where instances differ)
        if size[0] * size[1] > o.size[0] * o.size[1] {
            o.size = size;
        }
        let inst = format!("{cat}{}", o.number);
        if anchor != Anchor::Others {
            let anchor = if anchor == Anchor::Corner && state.scene.scene_type == SceneType::Outdoor
            {
                Anchor::Side
            } else {
                anchor
            };
            anchors.insert(inst.clone(), anchor);
        }
        key.insert(id, inst);
    }
    // one size for all: no per-instance list
    for o in objects.values_mut() {
        if o.sizes.iter().all(|s| *s == o.size) {
            o.sizes.clear();
        }
    }
    let relations = relations
        .iter()
        .filter_map(|r| {
            Some(Relation {
                subject: key.get(&r.subject)?.clone(),
                relation: r.relation,
                object: key.get(&r.object)?.clone(),
            })
        })
        .collect();
    let spec = SceneSpec {
        scene_type: state.scene.scene_type,
        scene_text: state.scene.prompt.clone(),
        room: Some(crate::plan::spec::Room {
            size: state.scene.room.size,
        }),
        objects,
        anchors,
        relations,
    };
    Ok((spec, key))
}

/// Removes instance `id`. Its object PLY goes too unless another instance uses it.
pub fn remove_object(state: &SceneState, id: &str) -> Result<(Edit, Box2)> {
    let o = state.object(id)?.clone();
    let mut edit = Edit::new(state, "remove", json!({"id": id}));
    edit.scene.objects.retain(|x| x.id != id);
    let shared = edit.scene.objects.iter().any(|x| x.ply == o.ply);
    if !shared {
        edit.deletes.push(o.ply.clone());
    }
    if let Some(tl) = &mut edit.scene.timeline {
        tl.tracks.retain(|t| t.id != id);
        if tl.tracks.is_empty() {
            edit.scene.timeline = None;
        }
    }
    let mut next = state.clone();
    next.scene = edit.scene.clone();
    next.relations.retain(|r| r.subject != id && r.object != id);
    edit.layout = state.layout.as_ref().map(|_| next.current_layout());
    edit.notes.push(format!(
        "{id} removed ({}{})",
        o.ply,
        if shared {
            " kept: another instance uses it"
        } else {
            " removed"
        }
    ));
    Ok((edit, state.box_of(&o)))
}

/// What `add` plans for a description: category, size, anchor and the description itself.
#[derive(Debug, Clone, PartialEq)]
pub struct Planned {
    pub category: String,
    pub size: [f64; 3],
    pub anchor: Anchor,
    pub description: String,
}

/// How a thing of `category` is held up in the scene `state` holds (its instances as they
/// are, the new one among them): the mount the layout gives it there (a mirror or a TV with no
/// stand hangs on a wall), else the knowledge base's.
pub fn mount_in(state: &SceneState, category: &str) -> crate::shape::Mount {
    gcp_spec(state, None).map_or_else(
        |_| crate::shape::Mount::of_category(category),
        |(spec, _)| crate::shape::Mount::in_scene(&spec, category),
    )
}

/// The next free instance id of `category` (`chair3` after `chair1`, `chair2`).
pub fn next_id(state: &SceneState, category: &str) -> String {
    (1..)
        .map(|k| format!("{category}{k}"))
        .find(|id| !state.scene.objects.iter().any(|o| &o.id == id))
        .expect("unbounded")
}

/// Places a planned object with GCP against the present ones (all pinned), `near` giving the
/// group relation the two categories form (AROUND, AT, ...; NEXT when none) and `anchor` overriding the knowledge base's. Returns the new instance's id and
/// pose, and whether every constraint held.
pub fn place_new(
    state: &SceneState,
    planned: &Planned,
    near: Option<&str>,
    said: Option<RelationKind>,
    anchor: Option<Anchor>,
) -> Result<(String, Pose, bool)> {
    // near a partner it forms a group with: the group's relation (a chair at a table faces it),
    // unless the request said another ("on the desk")
    let mut relation = RelationKind::Next;
    if let Some(n) = near {
        let partner = state.object(n)?;
        if let Some(r) = crate::plan::groups::relation_between(&planned.category, &partner.category)
        {
            relation = r;
        }
    }
    if let Some(r) = said.filter(|&r| r != RelationKind::Next || relation == RelationKind::Next) {
        relation = r;
    }
    let id = next_id(state, &planned.category);
    let rels: Vec<Relation> = near
        .map(|n| Relation {
            subject: id.clone(),
            relation,
            object: n.to_string(),
        })
        .into_iter()
        .collect();
    let anchor = anchor.unwrap_or(planned.anchor);
    let (spec, key) = gcp_spec(
        state,
        Some((&id, &planned.category, planned.size, anchor, rels)),
    )?;
    let pins: BTreeMap<String, Pin> = state
        .scene
        .objects
        .iter()
        .map(|o| {
            (
                key[&o.id].clone(),
                Pin {
                    position: o.position,
                    yaw: o.yaw,
                },
            )
        })
        .collect();
    let l = layout_pinned(
        &spec,
        LayoutOptions::seeded(state.scene.seed),
        &pins,
        state.layout.as_ref().map(|l| l.openings.as_slice()),
    )
    .map_err(|e| EditError::Bad(format!("placing the new object: {e}")))?;
    let p = l
        .objects
        .iter()
        .find(|p| p.id == key[&id])
        .ok_or_else(|| EditError::Bad("the layout dropped the new object".into()))?;
    Ok((
        id,
        Pose {
            position: p.position,
            yaw: p.yaw,
            scale: [1.0; 3],
        },
        p.placed_by == PlacedBy::Constraint,
    ))
}
