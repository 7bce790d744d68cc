//! `dreamscene view`: serves the scene and the browser viewer (viewer/: our page, and the npm
//! splat renderer scripts/setup.sh installed there) on 127.0.0.1. Nothing is fetched from the
//! network: every file the page loads comes from this server. Ctrl-C stops it.
use anyhow::{anyhow, bail, Context as _, Result};
use dreamscene::camera::scene::overview_camera;
use dreamscene::camera::Camera;
use dreamscene::export::trajectory::{cameras, open_input, Size, Subject, Trajectory};
use dreamscene::splat::ply::write_ply;
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;
use tiny_http::{Header, Request, Response, Server};

#[derive(clap::Args)]
pub struct Args {
    /// A scene directory (what `generate` writes) or a splat PLY.
    pub input: PathBuf,
    /// Port on 127.0.0.1 (0 picks a free one).
    #[arg(long, default_value_t = 8080)]
    pub port: u16,
    /// Background colour as R,G,B in [0, 1].
    #[arg(long, default_value = "0,0,0", value_parser = super::parse_rgb)]
    pub background: [f32; 3],
}

/// Files the page needs from the npm packages: their absence means setup has not run.
const REQUIRED: [&str; 3] = [
    "node_modules/three/build/three.module.js",
    "node_modules/three/examples/jsm/controls/OrbitControls.js",
    "node_modules/@sparkjsdev/spark/dist/spark.module.js",
];

/// The viewer directory: `DREAMSCENE_VIEWER_DIR`, else the source tree's `viewer/`.
pub fn viewer_dir() -> Result<PathBuf> {
    let dir = dreamscene::util::env_path("DREAMSCENE_VIEWER_DIR")
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("viewer"));
    if !dir.join("index.html").is_file() {
        bail!(
            "{}: no viewer page here (set DREAMSCENE_VIEWER_DIR to the repository's viewer/)",
            dir.display()
        );
    }
    if let Some(missing) = REQUIRED.iter().find(|f| !dir.join(f).is_file()) {
        bail!(
            "{}: the viewer's npm packages are not installed ({missing} missing); run \
             scripts/setup.sh (it runs `npm ci` in viewer/)",
            dir.display()
        );
    }
    Ok(dir)
}

pub fn run(a: Args) -> Result<()> {
    let viewer = viewer_dir()?;
    let input = super::read_input(&a.input, || Ok(open_input(&a.input)?))?;
    let name = a
        .input
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "scene".into());
    // A PLY file is served as it is; a scene directory as its composed world-frame cloud.
    let ply = if input.scene.is_none() {
        std::fs::read(&a.input).with_context(|| format!("reading {}", a.input.display()))?
    } else {
        let tmp = std::env::temp_dir().join(format!("dreamscene-view-{}.ply", std::process::id()));
        write_ply(&tmp, &input.cloud).context("writing the composed scene")?;
        let bytes = std::fs::read(&tmp);
        let _ = std::fs::remove_file(&tmp);
        bytes.context("reading the composed scene")?
    };
    let info = scene_info(&name, &input.subject, input.cloud.len(), a.background)?;

    let server = Server::http(("127.0.0.1", a.port)).map_err(|e| {
        let in_use = e
            .downcast_ref::<std::io::Error>()
            .is_some_and(|e| e.kind() == std::io::ErrorKind::AddrInUse);
        if in_use {
            anyhow!(
                "port {} on 127.0.0.1 is in use: give another with --port (0 picks a free one)",
                a.port
            )
        } else {
            anyhow!("cannot listen on 127.0.0.1:{}: {e}", a.port)
        }
    })?;
    let port = server
        .server_addr()
        .to_ip()
        .map(|s| s.port())
        .unwrap_or(a.port);
    let stop = Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    ctrlc::set_handler(move || flag.store(true, Ordering::SeqCst))
        .context("installing the Ctrl-C handler")?;
    println!(
        "viewing {} at http://127.0.0.1:{port}/ (Ctrl-C stops)",
        a.input.display()
    );
    while !stop.load(Ordering::SeqCst) {
        let Some(req) = server.recv_timeout(Duration::from_millis(200))? else {
            continue;
        };
        let _ = respond(req, &viewer, &ply, &info);
    }
    println!("stopped");
    Ok(())
}

/// What the page needs to place its camera: the first view of the orbit (around a splat file,
/// or inside the room looking at its centre), in the world frame.
fn scene_info(
    name: &str,
    subject: &Subject,
    gaussians: usize,
    background: [f32; 3],
) -> Result<String> {
    // Fly speed in metres per second: walking pace in a room, the cloud's size per second.
    let speed = match subject {
        Subject::Scene(_) => 1.5,
        Subject::Cloud { min, max } => {
            let diag = (0..3)
                .map(|k| (max[k] - min[k]).powi(2))
                .sum::<f64>()
                .sqrt();
            diag.max(0.1)
        }
    };
    let size = Size {
        width: 640,
        height: 480,
    };
    // A room opens on an overview from high in a corner; a lone cloud on its orbit's first view.
    let cam: Camera = match subject {
        Subject::Scene(scene) => overview_camera(scene, size.width, size.height),
        Subject::Cloud { .. } => cameras(&Trajectory::Orbit, subject, 1, Some(size))?
            .into_iter()
            .next()
            .ok_or_else(|| anyhow!("no start view"))?,
    };
    let forward = [cam.rotation[0][2], cam.rotation[1][2], cam.rotation[2][2]];
    // Orbit about the point the first view looks at: the cloud's centre, or the room's floor.
    let centre = match subject {
        Subject::Scene(s) => [0.0, 0.0, 0.15 * s.room[2].min(4.0)],
        Subject::Cloud { min, max } => [0, 1, 2].map(|k| 0.5 * (min[k] + max[k])),
    };
    let c = [0, 1, 2].map(|k| centre[k] - cam.position[k]);
    let reach = (c[0] * forward[0] + c[1] * forward[1] + c[2] * forward[2]).max(0.5);
    let target = [0, 1, 2].map(|k| cam.position[k] + reach * forward[k]);
    let fov_y = 2.0 * (0.5 * cam.height as f64 / cam.fy).atan();
    Ok(serde_json::json!({
        "name": name,
        "gaussians": gaussians,
        "background": background,
        "fly_speed": speed,
        "camera": {"position": cam.position, "target": target, "fov_y_deg": fov_y.to_degrees()},
    })
    .to_string())
}

fn respond(req: Request, viewer: &Path, ply: &[u8], info: &str) -> std::io::Result<()> {
    let url = req
        .url()
        .split(['?', '#'])
        .next()
        .unwrap_or("/")
        .to_string();
    let get = matches!(
        req.method(),
        tiny_http::Method::Get | tiny_http::Method::Head
    );
    let body: Option<(Vec<u8>, &str)> = if !get {
        None
    } else {
        match url.as_str() {
            "/" | "/index.html" => read(&viewer.join("index.html")),
            "/main.js" => read(&viewer.join("main.js")),
            "/scene.ply" => Some((ply.to_vec(), "application/octet-stream")),
            "/scene-info.json" => Some((info.as_bytes().to_vec(), "application/json")),
            u => u
                .strip_prefix("/node_modules/")
                .and_then(safe_relative)
                .and_then(|rel| read(&viewer.join("node_modules").join(rel))),
        }
    };
    match body {
        Some((bytes, mime)) => {
            let header = Header::from_bytes("Content-Type", mime).expect("valid header");
            req.respond(Response::from_data(bytes).with_header(header))
        }
        None => req.respond(Response::from_string("not found").with_status_code(404)),
    }
}

/// A URL path as a relative file path, refused when it could leave its directory.
fn safe_relative(p: &str) -> Option<PathBuf> {
    let path = PathBuf::from(p);
    path.components()
        .all(|c| matches!(c, Component::Normal(_)))
        .then_some(path)
}

fn read(path: &Path) -> Option<(Vec<u8>, &'static str)> {
    let mime = match path.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js") | Some("mjs") => "text/javascript; charset=utf-8",
        Some("json") | Some("map") => "application/json",
        Some("wasm") => "application/wasm",
        _ => "application/octet-stream",
    };
    std::fs::read(path).ok().map(|b| (b, mime))
}
