//! Time of a draft's frames when a timeline plays: composing every frame with its light baked
//! again (as `compose_at` did before the light was kept) against [`Animated::at`], which keeps
//! the room's light and re-casts only the shadows of objects that moved:
//! `cargo run --release --example timeline_light -- DIR [FRAMES]` (DIR a draft with a timeline,
//! made by `dreamscene edit DIR animate ...`). Prints milliseconds per frame for both and the
//! largest colour difference between them.
use anyhow::Result;
use dreamscene::scene::compose::{merge, place};
use dreamscene::scene::dir::light_draft;
use dreamscene::scene::timeline::{frame_times, scene_at, Animated};
use dreamscene::splat::cloud::SH_C0;
use std::time::Instant;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = std::path::PathBuf::from(args.first().map_or("", String::as_str));
    let frames: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(30);
    let anim = Animated::open(&dir)?;
    let times = anim.scene.timeline.as_ref().map_or(vec![0.0], frame_times);
    let times: Vec<f64> = times.iter().copied().take(frames).collect();
    let env = dreamscene::splat::ply::read_ply(&dir.join("environment.ply"))?;
    let clouds: std::collections::HashMap<String, _> = anim
        .scene
        .objects
        .iter()
        .filter_map(|o| Some((o.ply.clone(), anim.object_cloud(&o.ply)?.clone())))
        .collect();
    // Baked again every frame.
    let t0 = Instant::now();
    let mut again = vec![];
    for &t in &times {
        let at = scene_at(&anim.scene, t);
        let mut parts: Vec<_> = at
            .objects
            .iter()
            .map(|o| place(&clouds[&o.ply], &o.placement()))
            .collect();
        let mut e = env.clone();
        light_draft(&at, &|rel| clouds.get(rel), &mut e);
        parts.push(e);
        again.push(merge(&parts));
    }
    let baked = t0.elapsed().as_secs_f64() * 1e3 / times.len() as f64;
    let t1 = Instant::now();
    let kept: Vec<_> = times.iter().map(|&t| anim.at(t)).collect();
    let cached = t1.elapsed().as_secs_f64() * 1e3 / times.len() as f64;
    // The light alone: baked again against kept, over the same frames.
    let openings = dreamscene::scene::env::openings_of(anim.scene.extra.get("openings"));
    let room = anim.scene.room.size;
    let bounds = |rel: &str| {
        clouds
            .get(rel)
            .and_then(dreamscene::scene::dir::object_bounds)
    };
    let boxes: Vec<_> = times
        .iter()
        .map(|&t| dreamscene::scene::dir::draft_boxes(&scene_at(&anim.scene, t), &bounds))
        .collect();
    let t2 = Instant::now();
    for b in &boxes {
        let mut e = env.clone();
        dreamscene::scene::env::bake_light(&mut e, anim.scene.scene_type, room, b, &openings);
    }
    let light_again = t2.elapsed().as_secs_f64() * 1e3 / times.len() as f64;
    let mut light = dreamscene::scene::env::DraftLight::new(
        env.clone(),
        anim.scene.scene_type,
        room,
        &openings,
    );
    let t3 = Instant::now();
    for b in &boxes {
        light.lit(b);
    }
    let light_kept = t3.elapsed().as_secs_f64() * 1e3 / times.len() as f64;
    println!("light alone: baked again {light_again:.1} ms/frame, kept {light_kept:.1} ms/frame");
    let mut worst = 0.0f64;
    for (a, b) in again.iter().zip(&kept) {
        anyhow::ensure!(a.len() == b.len(), "frames differ in size");
        for (x, y) in a.sh.iter().zip(&b.sh) {
            worst = worst.max(SH_C0 * (x - y).abs() as f64);
        }
    }
    println!(
        "{} frames of {} Gaussians: baked again {baked:.1} ms/frame, kept light {cached:.1} ms/frame; largest colour difference {worst:.2e}",
        times.len(),
        kept.first().map_or(0, |g| g.len())
    );
    Ok(())
}
