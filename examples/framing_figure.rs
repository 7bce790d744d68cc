//! The framing figures of the render views, measured from the cameras and the layout boxes
//! (occlusion ignored), each prompt planned offline and laid out with seed 0:
//! - framed well: at least two objects in view and no object over 40% of the frame;
//! - subject repeats: the most views one object is the subject of (fills the most of the frame);
//! - back views: views that see their subject from behind (facing cosine < −0.5);
//! - foreground views: views with an object covering part of the frame within 1.2 m;
//! - objects in view, on average.
//!
//! Also compares the chosen views (`render_views`, what `generate` writes) with the exploring path.
//!
//! `cargo run --release --example framing_figure [CORPUS.json|"PROMPT;PROMPT…"] [N] [VIEWS]`
//! (defaults: /work/shared/prompts/fidelity_dev.json, 30 prompts, 8 views of 512²).
use dreamscene::camera::scene::{explore_path, frame_share, render_views, view_stats, SceneBox};
use dreamscene::camera::Camera;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;

/// Index of the (non-flat) object filling most of the frame, and the cosine between its facing
/// and the direction from it to the camera.
fn subject(scene: &SceneBox, cam: &Camera) -> Option<(usize, f64)> {
    let (k, o, _) = scene
        .objects
        .iter()
        .enumerate()
        .filter(|(_, o)| o.size[2] > 0.05)
        .map(|(k, o)| (k, o, frame_share(cam, o)))
        .filter(|(_, _, s)| *s > 0.0)
        .max_by(|a, b| a.2.total_cmp(&b.2))?;
    let (s, c) = o.yaw.to_radians().sin_cos();
    let (dx, dy) = (
        cam.position[0] - o.position[0],
        cam.position[1] - o.position[1],
    );
    Some((k, (-s * dx + c * dy) / dx.hypot(dy).max(1e-9)))
}

/// Horizontal distance from the camera to the nearest object covering part of the frame.
fn nearest(scene: &SceneBox, cam: &Camera) -> f64 {
    scene
        .objects
        .iter()
        .filter(|o| frame_share(cam, o) > 0.03)
        .map(|o| {
            let (s, c) = o.yaw.to_radians().sin_cos();
            let (dx, dy) = (
                cam.position[0] - o.position[0],
                cam.position[1] - o.position[1],
            );
            let (lx, ly) = (c * dx + s * dy, -s * dx + c * dy);
            let ox = (lx.abs() - 0.5 * o.size[0]).max(0.0);
            let oy = (ly.abs() - 0.5 * o.size[1]).max(0.0);
            ox.hypot(oy)
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let corpus = args
        .get(1)
        .cloned()
        .unwrap_or_else(|| "/work/shared/prompts/fidelity_dev.json".into());
    let n: usize = args.get(2).map_or(Ok(30), |s| s.parse())?;
    let views: usize = args.get(3).map_or(Ok(8), |s| s.parse())?;
    let prompts: Vec<String> = if corpus.ends_with(".json") {
        let text = std::fs::read_to_string(&corpus)?;
        let items: Vec<serde_json::Value> = serde_json::from_str(&text)?;
        items
            .iter()
            .map(|i| i["prompt"].as_str().unwrap_or_default().to_string())
            .collect()
    } else {
        corpus.split(';').map(|s| s.trim().to_string()).collect()
    };
    let (mut good, mut good_old, mut total) = (0usize, 0usize, 0usize);
    let (mut repeats, mut back, mut fore, mut shown) = (0usize, 0usize, 0usize, 0usize);
    for prompt in prompts.iter().take(n) {
        let spec = match plan_prompt(prompt) {
            Ok(p) => p.spec,
            Err(e) => {
                println!("skipped: {e}");
                continue;
            }
        };
        let l = layout(&spec, LayoutOptions::seeded(0))?;
        let scene = SceneBox::from_layout(&l);
        let cams = render_views(&scene, views, 512, 512);
        let old = explore_path(&scene, views, 512, 512);
        let stats: Vec<_> = cams.iter().map(|c| view_stats(&scene, c)).collect();
        let g = stats.iter().filter(|s| s.framed_well()).count();
        let go = old
            .iter()
            .filter(|c| view_stats(&scene, c).framed_well())
            .count();
        let subjects: Vec<_> = cams.iter().filter_map(|c| subject(&scene, c)).collect();
        let rep = (0..scene.objects.len())
            .map(|k| subjects.iter().filter(|s| s.0 == k).count())
            .max()
            .unwrap_or(0);
        let b = subjects.iter().filter(|s| s.1 < -0.5).count();
        let f = cams.iter().filter(|c| nearest(&scene, c) < 1.2).count();
        let iv: usize = stats.iter().map(|s| s.in_view).sum();
        println!(
            "{g}/{} (path {go}/{}) repeats {rep} back {b} fore {f} in view {:.1} | {} objects: {:.50}",
            cams.len(),
            old.len(),
            iv as f64 / cams.len().max(1) as f64,
            l.objects.len(),
            prompt
        );
        good += g;
        good_old += go;
        total += cams.len();
        repeats += rep;
        back += b;
        fore += f;
        shown += iv;
    }
    println!(
        "framing: {good}/{total} views framed well ({:.1}%); the exploring path: {good_old}/{total} ({:.1}%)",
        100.0 * good as f64 / total.max(1) as f64,
        100.0 * good_old as f64 / total.max(1) as f64
    );
    println!(
        "summed subject repeats {repeats}, back views {back}, foreground views {fore}, objects in view {:.2} a view",
        shown as f64 / total.max(1) as f64
    );
    Ok(())
}
