//! The `dreamscene` command line: a thin layer over the library; each verb's glue is in
//! `cli/<verb>.rs`.
use anyhow::Result;
use clap::{Parser, Subcommand};
mod cli;

/// Text to editable 3D Gaussian-splat scenes on any Vulkan GPU (DreamScene method).
///
/// The Vulkan device is chosen automatically (discrete GPU, then integrated, then a CPU device
/// such as Mesa lavapipe); set DREAMSCENE_DEVICE to a name fragment or index to choose.
#[derive(Parser)]
#[command(name = "dreamscene", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a splat PLY (or a scene directory) from every camera of an INRIA cameras.json,
    /// or along a path (--trajectory orbit|explore), into <out>/<img_name>.png.
    Render(cli::render::Args),
    /// Write a random demo scene (scene.ply, cameras.json on an orbit) and render it.
    Demo(cli::demo::Args),
    /// Render a scene directory or splat PLY along a camera path (orbit, explore or a
    /// cameras.json) into an H.264 MP4 or an animated GIF; --depth adds a depth video beside it.
    Video(cli::video::Args),
    /// Serve the scene (directory or splat PLY) in an interactive browser viewer on 127.0.0.1:
    /// orbit with the mouse, fly with W A S D Q E. Needs the viewer's npm packages
    /// (scripts/setup.sh); nothing is fetched from the network. Ctrl-C stops it.
    View(cli::view::Args),
    /// Fit Gaussians to posed images (3DGS optimisation: Adam, densify and prune) and write a PLY.
    ///
    /// Images are found as <images>/<img_name>[.png|.jpg|.jpeg] for each camera. The model is
    /// checkpointed to --out every --checkpoint-every iterations, with the optimiser state
    /// (iteration, Adam moments) in <out>.state, so an interrupted fit continues with --resume.
    Fit(cli::fit::Args),
    /// Generate one object from a prompt: writes <out>/object.ply (object frame: bottom-face
    /// centre at the origin, front +y, z up), object.json, renders/ (a turntable) and
    /// checkpoints/.
    ///
    /// With Stable Diffusion (--models DIR or DREAMSCENE_MODELS) it runs Formation Pattern
    /// Sampling: MTS from the shape prior, 3D Gaussian filtering, reconstructive generation.
    /// Without models the object is its procedural shape prior (a draft in seconds).
    /// --prior oracle:REF.ply verifies the generator against a known answer.
    Object(cli::object::Args),
    /// Plan a scene from a sentence (or a dialogue) and lay it out: writes <out>/spec.json,
    /// <out>/layout.json and a top-down picture <out>/layout.png.
    ///
    /// Planning is offline, from the built-in knowledge base: the scene type, the objects the
    /// prompt names with their counts and adjectives ("no tv", "0 chairs" mean none), sizes
    /// ("4m x 5m", "15 ft x 12 ft", "400cm by 300cm", "20 square meters"), placement phrases
    /// ("faces", "around", "on either side of", "in the corner") and style words; rooms are
    /// furnished in functional groups. A prompt it cannot read, or named objects that cannot
    /// fit the stated room, is an error that says why.
    Plan(cli::plan::Args),
    /// Generate a scene from a sentence (or a dialogue): plan, lay out, make the objects and the
    /// environment, compose them. Writes the scene directory: scene.json, spec.json,
    /// layout.json, layout.png, objects/<category>.ply, environment.ply, scene.ply, renders/
    /// (views chosen by what they show, with cameras.json and overview.png) and checkpoints/.
    ///
    /// Without diffusion models (or with --draft or --prior shape) the scene is a draft in
    /// seconds: each object is its procedural shape prior and the environment its initial
    /// surfaces, with no optimisation.
    Generate(cli::generate::Args),
    /// Generate many scenes from a manifest (one prompt a line, or JSONL of {"id", "prompt",
    /// "seed", ...generate flags}) into DIR/<id>/, each exactly as `generate` writes it.
    ///
    /// Each scene is claimed through its scene lock, so workers started on the same manifest
    /// never do a scene twice; finished scenes are skipped and unfinished ones resume. The
    /// worker's shard comes from --shard I/N, a Slurm job array or a Kubernetes Indexed Job
    /// (JOB_COMPLETION_INDEX with --shards). SIGTERM stops it after the current scene.
    /// DIR/index.json records every scene, DIR/index.html is a contact sheet; --status DIR counts.
    Batch(cli::batch::Args),
    /// Edit a generated scene in place: move, add, remove, restyle or animate objects, or undo.
    Edit(cli::edit::Args),
    /// Place the objects of a scene spec (spec.json) with graph-based constraint placement.
    ///
    /// Writes layout.json: every instance placed exactly once, collision-free, with the relations
    /// it could not satisfy listed under `unsatisfied` and relaxed placements marked `fallback`.
    Layout(cli::layout::Args),
    /// Export a scene directory's merged world-frame cloud (scene.ply), or a splat PLY, as INRIA
    /// PLY, antimatter15 .splat, Niantic .spz (version 2) or glTF .glb (KHR_gaussian_splatting).
    ///
    /// The scene (z up) is turned into each format's viewer convention, SH included: PLY and
    /// .splat x right, y down, z forward (as INRIA captures); .spz y up (Niantic's RUB); .glb y up
    /// (glTF). --scene-frame keeps the scene's own frame for PLY, .splat and .spz.
    Export(cli::export::Args),
    /// Check the Vulkan device, ONNX Runtime, and (with --models) a diffusion model directory.
    Doctor(cli::doctor::Args),
    /// Measure kernel throughput at fixed sizes on the selected device; with --unet, the latency
    /// of the diffusion models instead.
    Bench(cli::bench::Args),
}

fn main() {
    // Output piped into `head` and the like ends quietly, as for other command-line tools,
    // instead of panicking on a closed stdout.
    // SAFETY: restoring the default disposition of SIGPIPE before any thread starts.
    #[cfg(unix)]
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    // An empty variable means unset, as scripts write `NAME=` to unset one; clap's `env` would
    // take the empty value as given. Done before any thread starts.
    for (name, value) in std::env::vars_os() {
        let n = name.to_string_lossy();
        let ours = n.starts_with("DREAMSCENE_") || n == "OPENAI_API_KEY";
        if ours && value.to_string_lossy().trim().is_empty() {
            std::env::remove_var(&name);
        }
    }
    let cli = Cli::parse();
    if let Err(e) = run(cli) {
        let chain: Vec<String> = e
            .chain()
            .map(|c| c.to_string().replace('\n', " "))
            .collect();
        eprintln!("error: {}", cli::error_line(&chain));
        std::process::exit(1);
    }
}

fn run(cli: Cli) -> Result<()> {
    match cli.command {
        Command::Render(a) => cli::render::run(a),
        Command::Demo(a) => cli::demo::run(a),
        Command::Video(a) => cli::video::run(a),
        Command::View(a) => cli::view::run(a),
        Command::Fit(a) => cli::fit::run(a),
        Command::Object(a) => cli::object::run(a),
        Command::Plan(a) => cli::plan::run(a),
        Command::Generate(a) => cli::generate::run(a),
        Command::Batch(a) => cli::batch::run(a),
        Command::Edit(a) => cli::edit::run(a),
        Command::Layout(a) => cli::layout::run(a),
        Command::Export(a) => cli::export::run(a),
        Command::Doctor(a) => cli::doctor::run(a),
        Command::Bench(a) => cli::bench::run(a),
    }
}
