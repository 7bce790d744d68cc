//! Turning a prepared edit into one transaction (new PLYs, `scene.ply` re-composed with its
//! per-Gaussian labels and `labels.json` beside it, preview views re-rendered, `layout.json`
//! kept in step, the history entry with its undo record), and undoing the last one byte for
//! byte.
use super::state::SceneState;
use super::txn::{Backup, Txn, HISTORY};
use super::{EditError, Result};
use crate::camera::scene::{render_views, SceneBox};
use crate::camera::{read_cameras, write_cameras};
use crate::export::labels::SceneLabels;
use crate::gpu::Context;
use crate::plan::spec::Layout;
use crate::scene::compose::merge;
use crate::scene::dir::SceneFile;
use crate::splat::ply::{write_ply, write_ply_labelled};
use crate::splat::raster::{GpuGaussians, Rasterizer};
use crate::splat::Gaussians;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::path::Path;

/// An edit ready to be applied: the new `scene.json` (without its history entry) and the files
/// that change.
#[derive(Debug, Clone)]
pub struct Edit {
    /// `move`, `add`, `remove`, `restyle`, `animate`.
    pub op: String,
    /// What was asked, recorded in the history entry.
    pub args: Value,
    pub scene: SceneFile,
    /// New or changed clouds by path relative to the scene directory.
    pub files: BTreeMap<String, Gaussians>,
    /// Other new or changed files (bytes).
    pub raw: BTreeMap<String, Vec<u8>>,
    /// Files the edit removes.
    pub deletes: Vec<String>,
    /// The new `layout.json` (when the scene has one).
    pub layout: Option<Layout>,
    /// What was done, one line each, for the user and the history.
    pub notes: Vec<String>,
}

impl Edit {
    /// An edit of `state` that changes nothing yet.
    pub fn new(state: &SceneState, op: &str, args: Value) -> Edit {
        Edit {
            op: op.to_string(),
            args,
            scene: state.scene.clone(),
            files: BTreeMap::new(),
            raw: BTreeMap::new(),
            deletes: vec![],
            layout: None,
            notes: vec![],
        }
    }
}

/// What an applied edit did.
#[derive(Debug, Clone)]
pub struct Applied {
    pub notes: Vec<String>,
    /// Gaussians of the new `scene.ply`.
    pub gaussians: usize,
    /// Preview views re-rendered.
    pub renders: usize,
    /// The undo record (`history/NNNN`).
    pub record: String,
}

fn io(path: &Path) -> impl Fn(std::io::Error) -> EditError + '_ {
    move |e| EditError::Io(format!("{}: {e}", path.display()))
}

/// The background of the preview views (as `generate` renders them).
const BACKGROUND: [f32; 3] = [0.0; 3];

/// Applies `edit` to the scene `state` was opened from, in one transaction. With `ctx`, the
/// views of `renders/cameras.json` are re-rendered; without, they are left as they were.
pub fn apply_edit(state: &SceneState, edit: Edit, ctx: Option<&Context>) -> Result<Applied> {
    let dir = state.dir.as_path();
    // An edit never writes a scene.json that could not be read back (and so not undone).
    edit.scene
        .validate()
        .map_err(|m| EditError::Bad(format!("refused: {m} (nothing changed)")))?;
    let mut next = state.clone();
    next.scene = edit.scene.clone();
    // scene.ply keeps its per-Gaussian labels and labels.json follows the new instances, so
    // an export by label after the edit cuts exactly the instances scene.json now has.
    let parts = next.compose_parts(&edit.files)?;
    let labels = SceneLabels::of_parts(&next.scene, &parts)
        .map_err(|e| EditError::Bad(format!("refused: {e} (nothing changed)")))?;
    let labels_text = labels
        .to_json_text()
        .map_err(|e| EditError::Io(e.to_string()))?;
    let composed = merge(&parts);
    let mut t = Txn::begin(dir)?;
    let result = (|| {
        for (rel, g) in &edit.files {
            let p = t.stage_path(rel)?;
            write_ply(&p, g).map_err(io(&p))?;
        }
        for (rel, bytes) in &edit.raw {
            t.write(rel, bytes)?;
        }
        for rel in &edit.deletes {
            t.delete(rel)?;
        }
        if let Some(l) = &edit.layout {
            let text = serde_json::to_string_pretty(l).map_err(|e| EditError::Io(e.to_string()))?;
            t.write("layout.json", text.as_bytes())?;
            if dir.join("layout.png").is_file() {
                let p = t.stage_path("layout.png")?;
                crate::plan::draw::draw_layout(l)
                    .save_with_format(&p, image::ImageFormat::Png)
                    .map_err(|e| EditError::Io(format!("{}: {e}", p.display())))?;
            }
        }
        let p = t.stage_path("scene.ply")?;
        write_ply_labelled(&p, &composed, Some(&labels.per_gaussian())).map_err(io(&p))?;
        t.write("labels.json", labels_text.as_bytes())?;
        let (renders, dropped) = match ctx {
            Some(ctx) => render_previews(ctx, &mut t, &composed, edit.layout.as_ref())?,
            None => (0, vec![]),
        };
        let record = format!("{HISTORY}/{:04}", state.scene.history.len() + 1);
        let backup = t.backup(&record)?;
        let mut scene = edit.scene.clone();
        let mut entry = json!({"op": edit.op});
        if let (Some(e), Some(a)) = (entry.as_object_mut(), edit.args.as_object()) {
            for (k, v) in a {
                e.insert(k.clone(), v.clone());
            }
            e.insert("notes".into(), json!(edit.notes));
            e.insert(
                "undo".into(),
                serde_json::to_value(&backup).map_err(|e| EditError::Io(e.to_string()))?,
            );
        }
        scene.history.push(entry);
        let text =
            serde_json::to_string_pretty(&scene).map_err(|e| EditError::Io(e.to_string()))?;
        t.write("scene.json", text.as_bytes())?;
        Ok((renders, dropped, record))
    })();
    match result {
        Ok((renders, dropped, record)) => {
            t.commit()?;
            let mut notes = edit.notes;
            if !dropped.is_empty() {
                notes.push(format!(
                    "renders: {} removed: the new layout gives {renders} distinct good views, not {} (undo restores them)",
                    dropped.join(", "),
                    renders + dropped.len()
                ));
            }
            Ok(Applied {
                notes,
                gaussians: composed.len(),
                renders,
                record,
            })
        }
        Err(e) => {
            t.abort();
            Err(e)
        }
    }
}

/// Renders the preview views into the stage, with their contact sheet `renders/overview.png`.
/// When the edit changed the layout, the views are chosen afresh for it (as many, at the same
/// size, as `renders/cameras.json` had), so no view keeps looking at what was moved or removed;
/// otherwise the views of `renders/cameras.json` are kept. Nothing happens without that file.
/// Returns how many views were rendered and the names of the views removed (the new layout
/// gave fewer distinct good views than there were).
fn render_previews(
    ctx: &Context,
    t: &mut Txn,
    g: &Gaussians,
    layout: Option<&Layout>,
) -> Result<(usize, Vec<String>)> {
    let cams_path = t.dir().join("renders/cameras.json");
    if !cams_path.is_file() {
        return Ok((0, vec![]));
    }
    let mut dropped = vec![];
    let mut cams = read_cameras(&cams_path).map_err(|e| EditError::Io(e.to_string()))?;
    if let (Some(l), Some(first)) = (layout, cams.first()) {
        let mut fresh = render_views(
            &SceneBox::from_layout(l),
            cams.len(),
            first.width,
            first.height,
        );
        // The views keep their names (and ids): scripts and users know them.
        for (c, old) in fresh.iter_mut().zip(&cams) {
            c.id = old.id;
            c.img_name = old.img_name.clone();
        }
        for old in &cams {
            let stale = !fresh.iter().any(|c| c.img_name == old.img_name);
            if stale
                && t.dir()
                    .join(format!("renders/{}.png", old.img_name))
                    .is_file()
            {
                t.delete(&format!("renders/{}.png", old.img_name))?;
                dropped.push(old.img_name.clone());
            }
        }
        let p = t.stage_path("renders/cameras.json")?;
        write_cameras(&p, &fresh).map_err(io(&p))?;
        cams = fresh;
    }
    let r = Rasterizer::new(ctx)?;
    let gg = GpuGaussians::upload(ctx, g)?;
    let mut shots = vec![];
    for cam in &cams {
        let img = r.forward(ctx, &gg, cam, BACKGROUND)?.read()?;
        let p = t.stage_path(&format!("renders/{}.png", cam.img_name))?;
        save_png(&p, img.width, img.height, &img.color)?;
        shots.push(img);
    }
    let tiles: Vec<_> = shots
        .iter()
        .map(|i| (i.width, i.height, i.color.as_slice()))
        .collect();
    let p = t.stage_path("renders/overview.png")?;
    crate::util::contact_sheet(&tiles, 4, 256)
        .save_with_format(&p, image::ImageFormat::Png)
        .map_err(|e| EditError::Io(format!("{}: {e}", p.display())))?;
    Ok((cams.len(), dropped))
}

/// Writes an RGB image in [0, 1] as a PNG.
pub fn save_png(path: &Path, w: u32, h: u32, rgb: &[[f32; 3]]) -> Result<()> {
    let mut buf = image::RgbImage::new(w, h);
    for (p, c) in buf.pixels_mut().zip(rgb) {
        *p = image::Rgb(c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8));
    }
    buf.save_with_format(path, image::ImageFormat::Png)
        .map_err(|e| EditError::Io(format!("{}: {e}", path.display())))
}

/// Undoes the last edit of `dir`: every file it changed comes back from its record byte for
/// byte (`scene.json` and `scene.ply` included), files it created go, and the record is removed.
/// Returns the undone entry's op.
pub fn undo(dir: &Path) -> Result<String> {
    super::txn::recover(dir)?;
    let scene = crate::scene::dir::read_scene(dir)?;
    let Some(last) = scene.history.last() else {
        return Err(EditError::Bad(format!(
            "{}: nothing to undo (scene.json has no edit history)",
            dir.display()
        )));
    };
    let op = last
        .get("op")
        .and_then(|v| v.as_str())
        .unwrap_or("edit")
        .to_string();
    let backup: Backup = last
        .get("undo")
        .cloned()
        .and_then(|v| serde_json::from_value(v).ok())
        .ok_or_else(|| {
            EditError::Bad("the last history entry has no undo record; it cannot be undone".into())
        })?;
    let record = dir.join(&backup.dir);
    for rel in &backup.saved {
        if !record.join(rel).is_file() {
            return Err(EditError::Io(format!(
                "{}: missing from the undo record; it cannot be undone",
                record.join(rel).display()
            )));
        }
    }
    let mut t = Txn::begin(dir)?;
    let staged = (|| {
        for rel in &backup.saved {
            let p = t.stage_path(rel)?;
            let src = record.join(rel);
            if std::fs::hard_link(&src, &p).is_err() {
                std::fs::copy(&src, &p).map_err(io(&src))?;
            }
        }
        for rel in &backup.created {
            t.delete(rel)?;
        }
        t.cleanup_dir(&backup.dir)
    })();
    match staged {
        Ok(()) => {
            t.commit()?;
            Ok(op)
        }
        Err(e) => {
            t.abort();
            Err(e)
        }
    }
}
