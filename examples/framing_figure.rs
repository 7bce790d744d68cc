//! The framing figure of the render views: over the first N prompts of a corpus (planned offline
//! and laid out with seed 0), the share of views with at least two objects in view and no object
//! over 40% of the frame, measured from the cameras and the layout boxes (occlusion ignored).
//! Compares the chosen views (`render_views`, what `generate` writes) with the exploring path.
//!
//! `cargo run --release --example framing_figure [CORPUS.json] [N] [VIEWS]`
//! (defaults: /work/shared/prompts/fidelity_dev.json, 30 prompts, 8 views of 512²).
use dreamscene::camera::scene::{explore_path, render_views, view_stats, SceneBox};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let corpus = args
        .get(1)
        .cloned()
        .unwrap_or_else(|| "/work/shared/prompts/fidelity_dev.json".into());
    let n: usize = args.get(2).map_or(Ok(30), |s| s.parse())?;
    let views: usize = args.get(3).map_or(Ok(8), |s| s.parse())?;
    let text = std::fs::read_to_string(&corpus)?;
    let items: Vec<serde_json::Value> = serde_json::from_str(&text)?;
    let (mut good, mut good_old, mut total) = (0usize, 0usize, 0usize);
    for item in items.iter().take(n) {
        let prompt = item["prompt"].as_str().unwrap_or_default();
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
        let g = cams
            .iter()
            .filter(|c| view_stats(&scene, c).framed_well())
            .count();
        let go = old
            .iter()
            .filter(|c| view_stats(&scene, c).framed_well())
            .count();
        let worst = cams
            .iter()
            .map(|c| view_stats(&scene, c))
            .filter(|s| !s.framed_well())
            .map(|s| format!("({} in view, {:.0}%)", s.in_view, 100.0 * s.largest))
            .collect::<Vec<_>>()
            .join(" ");
        println!(
            "{g}/{} (exploring path {go}/{}) {} objects: {:.60} {worst}",
            cams.len(),
            old.len(),
            l.objects.len(),
            prompt
        );
        good += g;
        good_old += go;
        total += cams.len();
    }
    println!(
        "framing: {good}/{total} views framed well ({:.1}%); the exploring path: {good_old}/{total} ({:.1}%)",
        100.0 * good as f64 / total.max(1) as f64,
        100.0 * good_old as f64 / total.max(1) as f64
    );
    Ok(())
}
