//! Contact sheet of procedural shape priors, each rendered from a 3/4 front view:
//! `cargo run --release --example shape_gallery [OUT.png] [CLOSEUP_CATEGORY]`.
//! Writes the sheet (4 x 3 tiles of 256², default `/tmp/shape_gallery.png`) and a 512² close-up
//! of one category (default `sofa`) beside it as `*_closeup.png`.
use dreamscene::camera::Camera;
use dreamscene::gpu::Context;
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{build, ShapeOptions};
use dreamscene::splat::raster::Rasterizer;

const CATEGORIES: [&str; 12] = [
    "dining chair",
    "sofa",
    "dining table",
    "bed",
    "bookshelf",
    "floor lamp",
    "potted plant",
    "tv",
    "cabinet",
    "armchair",
    "desk",
    "rug",
];

/// A camera at azimuth 30° (towards +x from the front), elevation 20°, framing the size box's
/// bounding sphere.
fn three_quarter(size: [f64; 3], px: u32) -> Camera {
    let r = 0.5 * size.iter().map(|v| v * v).sum::<f64>().sqrt();
    let fov = 40f64.to_radians();
    let dist = 1.05 * r / (0.5 * fov).sin();
    let (az, el) = (30f64.to_radians(), 20f64.to_radians());
    let target = [0.0, 0.0, 0.5 * size[2]];
    let eye = [
        target[0] + dist * el.cos() * az.sin(),
        target[1] + dist * el.cos() * az.cos(),
        target[2] + dist * el.sin(),
    ];
    Camera::look_at(eye, target, [0.0, 0.0, 1.0], px, px, fov)
}

fn render(
    ctx: &Context,
    raster: &Rasterizer,
    category: &str,
    px: u32,
) -> anyhow::Result<Vec<[f32; 3]>> {
    let kb = KnowledgeBase::builtin();
    let kind = kb
        .object(category)
        .ok_or_else(|| anyhow::anyhow!("unknown category {category}"))?;
    let g = build(
        category,
        kind.size,
        &kind.description,
        &ShapeOptions::default(),
    )?;
    println!(
        "{category}: {} ({}), {} Gaussians",
        kind.description,
        kind.archetype,
        g.len()
    );
    let cam = three_quarter(kind.size, px);
    Ok(raster.render(ctx, &g, &cam, [0.93, 0.93, 0.95])?.color)
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let out = args
        .get(1)
        .cloned()
        .unwrap_or_else(|| "/tmp/shape_gallery.png".into());
    let closeup = args.get(2).cloned().unwrap_or_else(|| "sofa".into());
    let ctx = Context::new()?;
    let raster = Rasterizer::new(&ctx)?;
    let tile = 256u32;
    let (cols, rows) = (4u32, 3u32);
    let mut sheet = image::RgbImage::new(cols * tile, rows * tile);
    for (i, cat) in CATEGORIES.iter().enumerate() {
        let img = render(&ctx, &raster, cat, tile)?;
        let (ox, oy) = ((i as u32 % cols) * tile, (i as u32 / cols) * tile);
        for (j, c) in img.iter().enumerate() {
            let (x, y) = (j as u32 % tile, j as u32 / tile);
            let p = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
            sheet.put_pixel(ox + x, oy + y, image::Rgb(p));
        }
    }
    sheet.save(&out)?;
    let big = 512u32;
    let img = render(&ctx, &raster, &closeup, big)?;
    let mut one = image::RgbImage::new(big, big);
    for (j, c) in img.iter().enumerate() {
        let p = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        one.put_pixel(j as u32 % big, j as u32 / big, image::Rgb(p));
    }
    let close = out.replace(".png", "_closeup.png");
    one.save(&close)?;
    println!("wrote {out} and {close}");
    Ok(())
}
