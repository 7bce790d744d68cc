//! Renders draft environments into one contact sheet of 256² views, a row per scene:
//! `cargo run --release --example env_preview [out.png] [scene text]` (default
//! /tmp/env_preview.png). Rows: a 5 x 4 x 2.8 m room (the text, default "a cozy living room")
//! from four stage-1 cameras; a bar with brick walls and a marble floor from four floor-viewing
//! stage-3 cameras; a 20 x 20 m garden and a beach at sunset from four outdoor stage-1 cameras.
use dreamscene::camera::scene::{stage_cameras, SceneBox, Stage};
use dreamscene::gpu::Context;
use dreamscene::plan::spec::SceneType;
use dreamscene::scene::env::{draft_colours, init_environment, EnvOptions};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;

const SIZE: u32 = 256;

fn concat(a: &Gaussians, b: &Gaussians) -> Gaussians {
    let mut g = a.clone();
    g.means.extend(&b.means);
    g.scales.extend(&b.scales);
    g.rotations.extend(&b.rotations);
    g.opacities.extend(&b.opacities);
    g.sh.extend(&b.sh);
    g
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let out = args
        .get(1)
        .cloned()
        .unwrap_or("/tmp/env_preview.png".into());
    let ctx = Context::new()?;
    let raster = Rasterizer::new(&ctx)?;
    let scenes = [
        (
            SceneType::Indoor,
            args.get(2)
                .map_or("a cozy living room", |s| s.as_str())
                .to_string(),
            [5.0, 4.0, 2.8],
        ),
        (
            SceneType::Indoor,
            "a bar with brick walls and a marble floor".to_string(),
            [5.0, 4.0, 2.8],
        ),
        (
            SceneType::Outdoor,
            "a garden".to_string(),
            [20.0, 20.0, 10.0],
        ),
        (
            SceneType::Outdoor,
            "a beach at sunset".to_string(),
            [20.0, 20.0, 10.0],
        ),
    ];
    let mut sheet = image::RgbImage::new(4 * SIZE, scenes.len() as u32 * SIZE);
    for (row, (st, text, room)) in scenes.iter().enumerate() {
        let colours = draft_colours(*st, text);
        let env = init_environment(*st, *room, &colours, &EnvOptions::default());
        println!(
            "{text}: {} env + {} floor Gaussians",
            env.env.len(),
            env.floor.len()
        );
        let g = GpuGaussians::upload(&ctx, &concat(&env.env, &env.floor))?;
        let scene = SceneBox {
            scene_type: *st,
            room: *room,
            openings: vec![],
            objects: vec![],
        };
        // Four views spread around the room: every other sector of stage 1 (every third
        // outdoors, where there are twelve); the second row from stage 3, which looks down more.
        let (stage, step) = match (row, st) {
            (1, _) => (Stage::Three, 1),
            (_, SceneType::Indoor) => (Stage::One, 2),
            (_, SceneType::Outdoor) => (Stage::One, 3),
        };
        let cams = stage_cameras(stage, &scene, 12, SIZE, SIZE, 3);
        for (k, cam) in cams.iter().step_by(step).take(4).enumerate() {
            let img = raster.forward(&ctx, &g, cam, [0.0, 0.0, 0.0])?.read()?;
            for (i, c) in img.color.iter().enumerate() {
                let (x, y) = (i as u32 % SIZE, i as u32 / SIZE);
                let px = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
                sheet.put_pixel(k as u32 * SIZE + x, row as u32 * SIZE + y, image::Rgb(px));
            }
        }
    }
    sheet.save(&out)?;
    println!("wrote {out}");
    Ok(())
}
