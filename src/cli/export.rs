//! `dreamscene export`: a scene directory's merged world-frame cloud, or a splat PLY, written as
//! INRIA PLY, antimatter15 `.splat`, Niantic `.spz` or glTF `.glb` for other tools and viewers.
use anyhow::{bail, Context as _, Result};
use dreamscene::export::{export, load_input, Format, Options};
use std::path::PathBuf;

/// The formats by name, for `--format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FormatArg {
    /// INRIA 3DGS binary PLY (SuperSplat, Spark, GaussianSplats3D, gsplat.js, Babylon.js, ...).
    Ply,
    /// antimatter15 .splat, 32 bytes a Gaussian, no view-dependent colour (antimatter15/splat,
    /// Spark, GaussianSplats3D, gsplat.js, SuperSplat, Babylon.js).
    Splat,
    /// Niantic .spz version 2 with gzip, stored y up as Niantic's convention says (Spark,
    /// Babylon.js, GaussianSplats3D; splat-transform 3.7 skips the frame conversion and shows it
    /// upside down).
    Spz,
    /// glTF 2.0 binary with KHR_gaussian_splatting and a COLOR_0 point fallback, y up
    /// (Babylon.js, CesiumJS; other glTF viewers show coloured points).
    Glb,
}

impl From<FormatArg> for Format {
    fn from(f: FormatArg) -> Format {
        match f {
            FormatArg::Ply => Format::Ply,
            FormatArg::Splat => Format::Splat,
            FormatArg::Spz => Format::Spz,
            FormatArg::Glb => Format::Glb,
        }
    }
}

#[derive(clap::Args)]
pub struct Args {
    /// A scene directory (written by `generate`) or its scene.json, or a splat PLY.
    pub input: PathBuf,
    /// Output format (default: from the extension of --out: .ply, .splat, .spz or .glb).
    #[arg(long, value_enum)]
    pub format: Option<FormatArg>,
    /// Output file (written atomically; its directory is created if missing).
    #[arg(long)]
    pub out: PathBuf,
    /// PLY only: pad to SH degree 3 with normals (248-byte vertices), for viewers that accept
    /// nothing else.
    #[arg(long)]
    pub compat: bool,
    /// PLY, .splat and .spz: keep the scene's z-up world frame (to read the file back into
    /// dreamscene) instead of the viewers' convention (x right, y down, z forward; SPZ y up).
    #[arg(long)]
    pub scene_frame: bool,
    /// Play the scene's timeline (scene.json `timeline`, made by `edit animate`) to this time in
    /// seconds and export the scene as it stands then (glb of a scene: the engine-ready glb,
    /// still, posed at that time).
    #[arg(long)]
    pub time: Option<f64>,
    /// Engine export (a scene directory): keep only these instances, categories or `walls`
    /// (comma separated; ids with spaces or `_`).
    #[arg(long, value_delimiter = ',')]
    pub only: Vec<String>,
    /// Engine export (a scene directory): leave out these instances, categories or `walls`.
    #[arg(long, value_delimiter = ',')]
    pub without: Vec<String>,
    /// glb of a scene: each object's collider, its layout box or the convex hull of its opaque
    /// Gaussians.
    #[arg(long, value_enum, default_value = "box")]
    pub colliders: CollidersArg,
    /// glb of a scene: the splats as one primitive of every Gaussian, or one per instance (a
    /// child `splats_<id>` of its node, in its frame, so moving the node moves them) and
    /// `splats_environment`.
    #[arg(long, value_enum, default_value = "one")]
    pub splats: SplatsArg,
    /// glb of a scene: the navmesh agent's radius in metres (footprints grow by it).
    #[arg(long, default_value_t = 0.25)]
    pub agent_radius: f64,
}

/// `--splats`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SplatsArg {
    One,
    PerObject,
}

/// `--colliders`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum CollidersArg {
    Box,
    Hull,
}

/// The format `--out`'s extension names, if it names one.
fn format_of(out: &std::path::Path) -> Option<FormatArg> {
    let ext = out.extension()?.to_str()?.to_ascii_lowercase();
    <FormatArg as clap::ValueEnum>::from_str(&ext, true).ok()
}

pub fn run(a: Args) -> Result<()> {
    let out = a.out.clone();
    super::saying_if_replaced(&out, || write(a))
}

fn write(a: Args) -> Result<()> {
    let Some(format) = a.format.or_else(|| format_of(&a.out)) else {
        bail!(
            "{}: give --format ply|splat|spz|glb (the extension names none)",
            a.out.display()
        );
    };
    let format = Format::from(format);
    if a.out.is_dir() {
        bail!(
            "{} is a folder: give a file for the export",
            a.out.display()
        );
    }
    if a.compat && format != Format::Ply {
        bail!("--compat applies to --format ply only");
    }
    if a.scene_frame && format == Format::Glb {
        bail!("--scene-frame does not apply to --format glb (glTF is y up by definition)");
    }
    if let (Some(asked), Some(named)) = (a.format, format_of(&a.out)) {
        if asked != named {
            bail!(
                "{}: its extension names {} but --format says {}: give an --out ending .{} or leave --format out",
                a.out.display(),
                Format::from(named).name(),
                Format::from(asked).name(),
                Format::from(asked).name()
            );
        }
    }
    if let Some(done) = engine_export(&a, format)? {
        return Ok(done);
    }
    let g = super::read_input(&a.input, || Ok(load_input(&a.input, a.time)?))
        .map_err(|e| intact_ply_hint(&a.input, e))?;
    if format == Format::Splat && g.sh_degree > 0 {
        eprintln!(
            "note: .splat holds only the diffuse colour; the view-dependent colour (SH degree {}) \
             is left out",
            g.sh_degree
        );
    }
    super::create_parent(&a.out)?;
    let opts = Options {
        compat: a.compat,
        scene_frame: a.scene_frame,
    };
    export(&g, format, opts, &a.out)?;
    let bytes = std::fs::metadata(&a.out)
        .with_context(|| format!("reading back {}", a.out.display()))?
        .len();
    let frame = match format {
        Format::Glb => "y up",
        _ if a.scene_frame => "scene frame, z up",
        Format::Spz => "y up",
        _ => "x right, y down, z forward",
    };
    println!(
        "wrote {} ({} Gaussians, SH degree {}, {}{}, {frame}, {bytes} bytes)",
        a.out.display(),
        g.len(),
        g.sh_degree,
        format.name(),
        if a.compat { " compat" } else { "" },
    );
    Ok(())
}

/// The exports of a scene directory that know its instances: the engine-ready glb (nodes,
/// colliders, navmesh, labels) and the labelled PLY; a labelled PLY re-exported as PLY keeps its
/// labels. `None` when the plain path applies.
fn engine_export(a: &Args, format: Format) -> Result<Option<()>> {
    use dreamscene::export::engine;
    // A time poses the engine-ready glb; the other formats take the merged cloud at that time.
    let scene_dir = a.input.is_dir() && (a.time.is_none() || format == Format::Glb);
    let selecting = !a.only.is_empty() || !a.without.is_empty();
    if selecting && !scene_dir {
        bail!("--only/--without need a scene directory (they name its instances)");
    }
    if !(a.agent_radius.is_finite() && (0.0..2.0).contains(&a.agent_radius)) {
        bail!("--agent-radius must be between 0 and 2 metres");
    }
    if !scene_dir {
        let is_ply = a
            .input
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("ply"));
        if format == Format::Ply && is_ply && a.time.is_none() {
            let (g, labels) = dreamscene::splat::ply::read_ply_labelled(&a.input)?;
            if labels.is_some() {
                super::create_parent(&a.out)?;
                let opts = Options {
                    compat: a.compat,
                    scene_frame: a.scene_frame,
                };
                dreamscene::export::export_labelled(&g, labels.as_ref(), format, opts, &a.out)?;
                println!(
                    "wrote {} ({} Gaussians, labels kept)",
                    a.out.display(),
                    g.len()
                );
                return Ok(Some(()));
            }
        }
        return Ok(None);
    }
    let start = std::time::Instant::now();
    let opts = engine::EngineOptions {
        colliders: match a.colliders {
            CollidersArg::Box => engine::Colliders::Box,
            CollidersArg::Hull => engine::Colliders::Hull,
        },
        agent: dreamscene::export::navmesh::Agent {
            radius: a.agent_radius,
            ..Default::default()
        },
        only: a.only.clone(),
        without: a.without.clone(),
        per_object_splats: a.splats == SplatsArg::PerObject,
        time: a.time,
        ..Default::default()
    };
    match format {
        Format::Glb => {
            super::create_parent(&a.out)?;
            let (bytes, nav) = engine::export_scene(&a.input, &opts, &a.out)?;
            let tracks = dreamscene::scene::dir::read_scene(&a.input)
                .ok()
                .and_then(|s| s.timeline)
                .map_or(0, |t| t.tracks.len());
            let moving = match a.time {
                Some(t) => format!(" posed at {t} s"),
                None if tracks > 0 => format!(", {tracks} animated over the timeline"),
                None => String::new(),
            };
            println!(
                "wrote {} (glb, y up: nodes{moving}, colliders, navmesh of {:.1} m², {} bytes) and {} in {:.2} s",
                a.out.display(),
                nav.area(),
                bytes,
                engine::navmesh_path(&a.out).display(),
                start.elapsed().as_secs_f64()
            );
            Ok(Some(()))
        }
        Format::Ply => {
            let input = engine::read_input(&a.input)?;
            let keep = input.labels.select(&a.only, &a.without)?;
            let all = input.labels.per_gaussian();
            let kept: Vec<bool> = all.instance.iter().map(|&i| keep[usize::from(i)]).collect();
            let g = engine::select(&input.cloud, &kept);
            let labels = all.filter(&kept);
            super::create_parent(&a.out)?;
            let o = Options {
                compat: a.compat,
                scene_frame: a.scene_frame,
            };
            dreamscene::export::export_labelled(&g, Some(&labels), format, o, &a.out)?;
            println!(
                "wrote {} ({} Gaussians with instance_id and semantic_id, ply)",
                a.out.display(),
                g.len()
            );
            Ok(Some(()))
        }
        _ if selecting => bail!("--only/--without apply to --format glb and ply"),
        _ if a.splats == SplatsArg::PerObject => {
            bail!("--splats per-object applies to --format glb")
        }
        _ => Ok(None),
    }
}

/// A scene whose scene.json cannot be read may still have an intact scene.ply: say so.
fn intact_ply_hint(input: &std::path::Path, e: anyhow::Error) -> anyhow::Error {
    let ply = input.join("scene.ply");
    if input.is_dir() && ply.is_file() {
        anyhow::anyhow!(
            "{e}; its merged cloud {} is there: `dreamscene export {}` exports that",
            ply.display(),
            ply.display()
        )
    } else {
        e
    }
}
