//! `dreamscene edit DIR <operation>`: change a generated scene in place, atomically, with the
//! edit recorded in `scene.json`'s history and `undo` to take it back.
use anyhow::{bail, Context as _, Result};
use dreamscene::diffusion::runtime::Provider;
use dreamscene::edit::destination;
use dreamscene::edit::ops::{self, MoveFlags, Pose};
use dreamscene::edit::parse;
use dreamscene::edit::reopt::{self, ReoptConfig};
use dreamscene::edit::{animate, apply_edit, txn, Edit, SceneState};
use dreamscene::plan::kb::parse_anchor;
use dreamscene::scene::lock::{SceneLock, Wait};
use serde_json::json;
use std::path::PathBuf;

/// Edit a generated scene in place: move, add, remove, restyle or animate objects, or undo.
///
/// Every edit is atomic (a crash leaves the old scene or the new one), re-composes scene.ply,
/// re-renders the views of renders/cameras.json, and is recorded in scene.json's "history" with
/// what it replaced, so `undo` restores the previous files byte for byte. After moves, adds and
/// removals the environment around the old and new footprints is re-optimised with the scene's
/// prior (oracle or sd; a draft's shape prior has nothing to optimise and says so).
#[derive(clap::Args)]
pub struct Args {
    /// The scene directory `generate` wrote.
    dir: PathBuf,
    #[command(subcommand)]
    op: Op,
}

/// How an edit that re-optimises part of the scene runs (prior oracle or sd).
#[derive(clap::Args, Clone, Copy)]
struct Reopt {
    /// Iterations of the local re-optimisation and of restyling (prior oracle or sd).
    #[arg(long, default_value_t = Reopt::DEFAULT.iterations,
          value_parser = clap::value_parser!(u32).range(1..=100_000))]
    iterations: u32,
    /// Render size of the local re-optimisation and restyling views (a multiple of 8).
    #[arg(long, default_value_t = Reopt::DEFAULT.resolution,
          value_parser = clap::value_parser!(u32).range(16..=2048))]
    resolution: u32,
    /// ONNX Runtime provider of an sd prior's models (auto: a GPU provider on a real GPU, else
    /// the CPU).
    #[arg(long, value_enum, default_value_t = Reopt::DEFAULT.provider)]
    provider: Provider,
}

impl Reopt {
    /// The flags' defaults.
    const DEFAULT: Reopt = Reopt {
        iterations: 150,
        resolution: 128,
        provider: Provider::Auto,
    };
}

/// How an edit is put in place.
#[derive(clap::Args, Clone, Copy)]
struct Write {
    /// Leave renders/ as it is (no Vulkan device needed for moves, adds and removals of a draft).
    #[arg(long)]
    no_render: bool,
    /// When another command is writing the scene, exit at once naming it instead of waiting.
    #[arg(long)]
    no_wait: bool,
}

#[derive(clap::Subcommand)]
enum Op {
    /// Move, turn or scale an instance: `move sofa1 --by 0.5,0 --rotate 90`, or in words:
    /// `move "move the sofa back half a metre"`, `move chair1 "turn to face the tv"`.
    ///
    /// Directions in words are in the object's own frame (forward is where it faces); flags are
    /// in the world frame (x east, y north, metres). A pose that passes through a wall or another
    /// object is refused with the reason unless --force. Objects whose relation to the moved one
    /// breaks (a coffee table in front of a sofa) are placed again by the layout, the others
    /// pinned, unless --no-follow.
    Move {
        /// An instance id, then optionally a sentence; or the sentence alone.
        #[arg(required = true, num_args = 1..=2)]
        target: Vec<String>,
        /// New centre X,Y (metres, world frame).
        #[arg(long, value_parser = parse_xy, allow_hyphen_values = true)]
        to: Option<[f64; 2]>,
        /// Shift DX,DY (metres, world frame).
        #[arg(long, value_parser = parse_xy, allow_hyphen_values = true)]
        by: Option<[f64; 2]>,
        /// Turn by DEG degrees (counter-clockwise seen from above).
        #[arg(long, allow_hyphen_values = true)]
        rotate: Option<f64>,
        /// Turn to face another instance.
        #[arg(long)]
        face: Option<String>,
        /// Multiply the size by S.
        #[arg(long)]
        scale: Option<f64>,
        /// Place it even where it collides.
        #[arg(long)]
        force: bool,
        /// Leave related objects where they are.
        #[arg(long)]
        no_follow: bool,
        #[command(flatten)]
        reopt: Reopt,
        #[command(flatten)]
        write: Write,
    },
    /// Add an object: `add "a green armchair" --near sofa1 --anchor SIDE`. Planned from the
    /// knowledge base, placed by the layout around the objects already there, generated with
    /// the scene's prior.
    Add {
        /// What to add, e.g. "a green armchair".
        description: String,
        /// Place it next to this instance.
        #[arg(long)]
        near: Option<String>,
        /// SIDE, CORNER, CENTER or OTHERS (default: the category's).
        #[arg(long)]
        anchor: Option<String>,
        /// Object-formation iterations with the sd or oracle prior.
        #[arg(long, default_value_t = 300,
              value_parser = clap::value_parser!(u32).range(1..=100_000))]
        object_iterations: u32,
        #[command(flatten)]
        reopt: Reopt,
        #[command(flatten)]
        write: Write,
    },
    /// Remove an instance (its object PLY stays while another instance uses it).
    Remove {
        /// The instance to remove, e.g. chair2 (`edit DIR history` and scene.json list them).
        id: String,
        #[command(flatten)]
        reopt: Reopt,
        #[command(flatten)]
        write: Write,
    },
    /// Restyle an instance, the environment or the floor: `restyle sofa1 "a red leather sofa"`.
    ///
    /// With sd or oracle priors: the paper's MTS editing rule on that part's Gaussians only,
    /// the rest frozen bit for bit. With the shape prior: recoloured from the description's
    /// colour and material words, geometry kept.
    Restyle {
        /// An instance id, `environment` (walls and ceiling, or sky) or `floor` (or ground).
        part: String,
        /// The new look, e.g. "a red leather sofa".
        description: String,
        /// Oracle prior: the second reference the edit aims at (object frame for an instance,
        /// world frame for the environment or floor).
        #[arg(long)]
        edit_reference: Option<PathBuf>,
        #[command(flatten)]
        reopt: Reopt,
        #[command(flatten)]
        write: Write,
    },
    /// Animate an instance: `animate car1 "drive forward 3 m then turn left"` writes keyframes
    /// (position, yaw, scale) to scene.json's timeline.
    Animate {
        /// The instance to animate, e.g. car1.
        id: String,
        /// The motion in words, e.g. "drive forward 3 m then turn left".
        motion: String,
        /// Total length; the steps share it (default: from the words, else 1.5 s a step).
        #[arg(long)]
        seconds: Option<f64>,
        /// Frames per second of the timeline.
        #[arg(long, default_value_t = 30.0)]
        fps: f64,
        #[command(flatten)]
        write: Write,
    },
    /// Undo the last edit (scene.json, scene.ply and every other file it changed, byte for byte).
    Undo {
        /// When another command is writing the scene, exit at once naming it instead of waiting.
        #[arg(long)]
        no_wait: bool,
    },
    /// List the edits in the history.
    History,
}

fn parse_xy(s: &str) -> Result<[f64; 2], String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|e| format!("`{s}`: {e}"))?;
    match v.as_slice() {
        [x, y] if x.is_finite() && y.is_finite() => Ok([*x, *y]),
        _ => Err(format!("`{s}`: expected two numbers such as 0.5,-1")),
    }
}

pub fn run(a: Args) -> Result<()> {
    let dir = &a.dir;
    // What applies to this operation (history only reads; undo restores renders as they were).
    let (no_wait, reopt, no_render) = match &a.op {
        Op::History => return history(dir),
        Op::Undo { no_wait } => (*no_wait, Reopt::DEFAULT, true),
        Op::Move { reopt, write, .. }
        | Op::Add { reopt, write, .. }
        | Op::Remove { reopt, write, .. }
        | Op::Restyle { reopt, write, .. } => (write.no_wait, *reopt, write.no_render),
        Op::Animate { write, .. } => (write.no_wait, Reopt::DEFAULT, write.no_render),
    };
    if !reopt.resolution.is_multiple_of(8) {
        bail!(
            "--resolution {}: expected a multiple of 8, at least 16",
            reopt.resolution
        );
    }
    // The scene is checked before anything is created in it.
    let scene = dreamscene::scene::dir::read_scene(dir)?;
    // A provider asked for by name is checked before any work, even when this edit turns out
    // to need no re-optimisation.
    if scene.prior.kind == "sd" && reopt.provider != Provider::Auto {
        dreamscene::diffusion::runtime::check_provider(reopt.provider)
            .map_err(anyhow::Error::msg)?;
    }
    let wait = if no_wait { Wait::NoWait } else { Wait::Block };
    let command = std::env::args().collect::<Vec<_>>().join(" ");
    let _lock = SceneLock::acquire(dir, wait, &command)?;
    if let Some(what) = txn::recover(dir)? {
        eprintln!("{}: {what}", dir.display());
    }
    if let Op::Undo { .. } = a.op {
        let op = dreamscene::edit::undo(dir)?;
        println!("undid the last edit ({op}) of {}", dir.display());
        return Ok(());
    }
    let mut state = SceneState::open(dir)?;
    let cfg = ReoptConfig {
        iterations: reopt.iterations,
        resolution: reopt.resolution,
        seed: state.scene.seed,
        provider: reopt.provider,
    };
    let mut ctx = None;
    let mut device = || -> Result<dreamscene::gpu::Context> {
        if ctx.is_none() {
            ctx = Some(super::open_device()?);
        }
        Ok(ctx.clone().expect("just set"))
    };
    let (mut edit, footprints): (Edit, Vec<_>) = match a.op {
        Op::Move {
            target,
            to,
            by,
            rotate,
            face,
            scale,
            force,
            no_follow,
            ..
        } => {
            let flags = MoveFlags {
                to,
                by,
                rotate,
                face,
                scale,
            };
            let flags = MoveFlags {
                face: match flags.face {
                    Some(f) => Some(resolve_id(&state, &f)?),
                    None => None,
                },
                ..flags
            };
            let any_flag = flags.to.is_some()
                || flags.by.is_some()
                || flags.rotate.is_some()
                || flags.face.is_some()
                || flags.scale.is_some();
            // A name for the instance ("sofa", "the reading lamp") is read as its id.
            let target: Vec<String> = match target.as_slice() {
                [name] if any_flag && state.object(name).is_err() => {
                    vec![resolve_id(&state, name)?]
                }
                [a, b] if state.object(a).is_err() && state.object(b).is_err() => {
                    match resolve_id(&state, a) {
                        Ok(id) => vec![id, b.clone()],
                        Err(_) => vec![a.clone(), b.clone()],
                    }
                }
                _ => target,
            };
            let (id, pose, args) = match target.as_slice() {
                [id] if state.object(id).is_ok() => {
                    if !any_flag {
                        bail!("move {id}: say how (--to, --by, --rotate, --face, --scale, or a sentence)");
                    }
                    let p = ops::pose_from_flags(&state, id, &flags)?;
                    (
                        id.clone(),
                        p,
                        json!({"id": id, "flags": flags_text(&flags)}),
                    )
                }
                [id, text] | [text, id] if state.object(id).is_ok() => {
                    let (sid, p) = sentence_pose(&state, text, Some(id))?;
                    let p = if any_flag {
                        let mut s2 = state.clone();
                        s2 = ops::with_pose(&s2, &sid, p)?;
                        ops::pose_from_flags(&s2, &sid, &flags)?
                    } else {
                        p
                    };
                    (sid, p, json!({"id": id, "text": text}))
                }
                [text] => {
                    let (sid, p) = sentence_pose(&state, text, None)?;
                    (sid, p, json!({"text": text}))
                }
                _ => bail!(
                    "move {}: expected an instance id and/or a sentence",
                    target.join(" ")
                ),
            };
            let (e, fp) = ops::move_object(&state, &id, pose, force, !no_follow, args)?;
            (e, fp)
        }
        Op::Remove { id, .. } => {
            let id = resolve_id(&state, &id)?;
            let (e, fp) = ops::remove_object(&state, &id)?;
            (e, vec![fp])
        }
        Op::Add {
            description,
            near,
            anchor,
            object_iterations,
            ..
        } => {
            let anchor = match anchor {
                Some(s) => Some(parse_anchor(&s.to_uppercase()).with_context(|| {
                    format!("--anchor {s}: expected SIDE, CORNER, CENTER or OTHERS")
                })?),
                None => None,
            };
            let near = match near {
                Some(n) => Some(resolve_id(&state, &n)?),
                None => None,
            };
            // "two cafe chairs": that many, one edit each (undo takes back one).
            let (n, what) = parse::count_of(&description);
            if n > MAX_ADD {
                bail!("add \"{description}\": at most {MAX_ADD} objects at once");
            }
            // "a green armchair next to the bookshelf": an armchair, next to the scene's one
            let wanted = dreamscene::edit::wanted::read(&what, &state.id_categories());
            let anchor = anchor.or(wanted.anchor);
            let near: Option<(String, Option<dreamscene::plan::spec::RelationKind>)> =
                match (near, &wanted.partner) {
                    (Some(id), said) => Some((id, said.as_ref().map(|p| p.1))),
                    (None, Some((said, kind))) => Some((
                        resolve_id(&state, said)
                            .with_context(|| format!("add \"{description}\": where it goes"))?,
                        Some(*kind),
                    )),
                    // "a desk lamp": on the scene's desk
                    (None, None) => dreamscene::edit::wanted::plan_object(&wanted.what)
                        .ok()
                        .and_then(|p| {
                            dreamscene::edit::wanted::support_named(
                                &wanted.what,
                                &p.category,
                                &state.id_categories(),
                            )
                        })
                        .map(|id| (id, Some(dreamscene::plan::spec::RelationKind::Over))),
                };
            let what = wanted.what;
            let needs_gpu = state.scene.prior.kind != "shape";
            let c = if needs_gpu { Some(device()?) } else { None };
            let mut k = 1;
            loop {
                let (mut e, fp) = reopt::add_object(
                    c.as_ref(),
                    &state,
                    &what,
                    near.as_ref().map(|(id, said)| (id.as_str(), *said)),
                    anchor,
                    object_iterations,
                    &cfg,
                )?;
                if k >= n {
                    // The last one goes through the common path below (re-optimised, rendered).
                    break (e, vec![fp]);
                }
                let note = reopt::local_environment(c.as_ref(), &state, &mut e, &[fp], &cfg)?;
                e.notes.push(note);
                let op = e.op.clone();
                let applied = apply_edit(&state, e, None)?;
                for n in &applied.notes {
                    eprintln!("{n}");
                }
                println!("{op}: done ({k} of {n})");
                state = SceneState::open(dir)?;
                k += 1;
            }
        }
        Op::Restyle {
            part,
            description,
            edit_reference,
            ..
        } => {
            let part = match part.as_str() {
                "environment" | "walls" | "sky" | "floor" | "ground" => part,
                _ if state.object(&part).is_ok() => part,
                _ => resolve_id(&state, &part)?,
            };
            let needs_gpu = state.scene.prior.kind != "shape";
            let c = if needs_gpu { Some(device()?) } else { None };
            let e = dreamscene::edit::restyle::restyle(
                c.as_ref(),
                &state,
                &part,
                &description,
                edit_reference.as_deref(),
                &cfg,
            )?;
            (e, vec![])
        }
        Op::Animate {
            id,
            motion,
            seconds,
            fps,
            ..
        } => {
            let id = resolve_id(&state, &id)?;
            let e = animate::animate(&state, &id, &motion, seconds, fps)?;
            (e, vec![])
        }
        Op::Undo { .. } | Op::History => bail!("handled above"),
    };
    if !footprints.is_empty() {
        let c = if state.scene.prior.kind != "shape" {
            Some(device()?)
        } else {
            None
        };
        let note = reopt::local_environment(c.as_ref(), &state, &mut edit, &footprints, &cfg)?;
        edit.notes.push(note);
    }
    let ctx = if no_render { None } else { Some(device()?) };
    let op = edit.op.clone();
    let applied = apply_edit(&state, edit, ctx.as_ref())?;
    for n in &applied.notes {
        eprintln!("{n}");
    }
    println!(
        "{op}: done; scene.ply {} Gaussians, {} views re-rendered; `dreamscene edit {} undo` takes it back",
        applied.gaussians,
        applied.renders,
        dir.display()
    );
    Ok(())
}

/// The move flags as they would be typed (`--by 0.5,0 --rotate 90`).
fn flags_text(f: &MoveFlags) -> String {
    let mut out = vec![];
    if let Some([x, y]) = f.to {
        out.push(format!("--to {x},{y}"));
    }
    if let Some([x, y]) = f.by {
        out.push(format!("--by {x},{y}"));
    }
    if let Some(r) = f.rotate {
        out.push(format!("--rotate {r}"));
    }
    if let Some(id) = &f.face {
        out.push(format!("--face {id}"));
    }
    if let Some(s) = f.scale {
        out.push(format!("--scale {s}"));
    }
    out.join(" ")
}

/// `edit DIR history`: one short line an edit (what was asked), read while no edit is being put
/// in place.
fn history(dir: &std::path::Path) -> Result<()> {
    let s = txn::read_consistent(dir, || dreamscene::scene::dir::read_scene(dir))??;
    if s.history.is_empty() {
        println!("no edits");
    }
    for (i, e) in s.history.iter().enumerate() {
        println!("{:>3} {}", i + 1, history_line(e));
    }
    Ok(())
}

/// What an edit asked, in one short line: its op, the instance and the words or flags given.
fn history_line(e: &serde_json::Value) -> String {
    let mut parts = vec![e["op"].as_str().unwrap_or("edit").to_string()];
    for key in ["id", "part", "text", "description", "motion", "flags"] {
        if let Some(v) = e.get(key).and_then(|v| v.as_str()) {
            parts.push(match key {
                "text" | "description" | "motion" => format!("\"{v}\""),
                _ => v.to_string(),
            });
        }
    }
    let line = parts.join(" ");
    if line.chars().count() > 100 {
        format!("{}...", line.chars().take(97).collect::<String>())
    } else {
        line
    }
}

/// Most objects one `add` creates.
const MAX_ADD: u32 = 20;

/// The id an instance id or name means ("sofa1", "sofa", "the chalkboard menu"); an ambiguous
/// or unknown name is one line that lists the ids to choose from.
fn resolve_id(state: &SceneState, name: &str) -> Result<String> {
    if state.object(name).is_ok() {
        return Ok(name.to_string());
    }
    let objects = state.id_categories();
    parse::resolve(name, &objects).map_err(anyhow::Error::msg)
}

/// The instance and pose a sentence asks for (`default` is "it").
fn sentence_pose(state: &SceneState, text: &str, default: Option<&str>) -> Result<(String, Pose)> {
    let objects = state.id_categories();
    let cmd = match parse::parse(text, &objects, default) {
        Ok(cmd) => cmd,
        Err(e) => {
            // not a motion: a place ("under the window", "into the corner")
            let id = match default {
                Some(id) => id.to_string(),
                None => parse::subject(text, &objects).context(e.clone())?,
            };
            let Some(to) = destination::destination(state, &id, text) else {
                bail!(e);
            };
            return Ok((id.clone(), destination::place_at(state, &id, &to)?));
        }
    };
    let Some(id) = cmd.subject.clone() else {
        // "the sofa" in a room of two sofas: say which ones it could be
        bail!(parse::ambiguous(text, &objects).unwrap_or_else(|| {
            "say which object (an id such as sofa1, or \"the sofa\")".to_string()
        }));
    };
    let pose = animate::final_pose(state, &id, &cmd)?;
    Ok((id, pose))
}
