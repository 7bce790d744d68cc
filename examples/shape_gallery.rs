//! Contact sheets of procedural shape priors, each rendered from 3/4 views:
//! `cargo run --release --example shape_gallery [OUT.png] [CLOSEUP_CATEGORY] [CATEGORIES|all|archetypes]`.
//! Writes the sheet (tiles of 256², default twelve everyday categories, `/tmp/shape_gallery.png`)
//! and a 512² close-up of one category (default `sofa`) beside it as `*_closeup.png`.
//! `all` draws every knowledge-base category (turntable pairs: front 3/4 and back 3/4), in
//! sheets of 48 tiles `OUT_1.png`, `OUT_2.png`…; `archetypes` one category per archetype; a comma
//! separated list draws those categories, and `CATEGORY=DESCRIPTION` one as that description
//! shapes it (`"full length mirror=a round mirror"`). Each drawn name is printed in tile order.
use dreamscene::camera::Camera;
use dreamscene::gpu::Context;
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{archetype_described, archetype_names, archetype_of, build, ShapeOptions};
use dreamscene::splat::raster::Rasterizer;

const EVERYDAY: [&str; 12] = [
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

/// A camera at azimuth `az` degrees (towards +x from the front), elevation 20°, framing the
/// size box's bounding sphere.
fn view(size: [f64; 3], px: u32, az: f64) -> Camera {
    let r = 0.5 * size.iter().map(|v| v * v).sum::<f64>().sqrt();
    let fov = 40f64.to_radians();
    let dist = 1.05 * r / (0.5 * fov).sin();
    let (az, el) = (az.to_radians(), 20f64.to_radians());
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
    az: f64,
) -> anyhow::Result<Vec<[f32; 3]>> {
    let kb = KnowledgeBase::builtin();
    let (category, description) = split(category);
    let kind = kb
        .object(category)
        .ok_or_else(|| anyhow::anyhow!("unknown category {category}"))?;
    let description = description.unwrap_or(&kind.description);
    let g = build(category, kind.size, description, &ShapeOptions::default())?;
    let cam = view(kind.size, px, az);
    Ok(raster.render(ctx, &g, &cam, [0.93, 0.93, 0.95])?.color)
}

/// `CATEGORY=DESCRIPTION` split in two; a bare category has no description of its own.
fn split(entry: &str) -> (&str, Option<&str>) {
    match entry.split_once('=') {
        Some((c, d)) => (c.trim(), Some(d.trim())),
        None => (entry, None),
    }
}

fn put(sheet: &mut image::RgbImage, img: &[[f32; 3]], tile: u32, ox: u32, oy: u32) {
    for (j, c) in img.iter().enumerate() {
        let (x, y) = (j as u32 % tile, j as u32 / tile);
        let p = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        sheet.put_pixel(ox + x, oy + y, image::Rgb(p));
    }
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let out = args
        .get(1)
        .cloned()
        .unwrap_or_else(|| "/tmp/shape_gallery.png".into());
    let closeup = args.get(2).cloned().unwrap_or_else(|| "sofa".into());
    let kb = KnowledgeBase::builtin();
    let (cats, pairs): (Vec<String>, bool) = match args.get(3).map(String::as_str) {
        None => (EVERYDAY.iter().map(|s| s.to_string()).collect(), false),
        Some("all") => (
            kb.objects.iter().map(|o| o.category.clone()).collect(),
            true,
        ),
        Some("archetypes") => (
            archetype_names()
                .iter()
                .filter_map(|a| {
                    kb.objects
                        .iter()
                        .find(|o| archetype_of(&o.category) == *a)
                        .map(|o| o.category.clone())
                })
                .collect(),
            true,
        ),
        Some(list) => (
            list.split(',').map(|s| s.trim().to_string()).collect(),
            true,
        ),
    };
    let ctx = Context::new()?;
    let raster = Rasterizer::new(&ctx)?;
    let tile = 256u32;
    let (cols, rows) = if pairs { (8u32, 6u32) } else { (4, 3) };
    let per_sheet = if pairs { cols * rows / 2 } else { cols * rows } as usize;
    for (s, chunk) in cats.chunks(per_sheet).enumerate() {
        let n = chunk.len() as u32 * if pairs { 2 } else { 1 };
        let rows = n.div_ceil(cols).min(rows);
        let mut sheet = image::RgbImage::new(cols * tile, rows * tile);
        for (i, cat) in chunk.iter().enumerate() {
            let views: &[f64] = if pairs { &[30.0, 150.0] } else { &[30.0] };
            for (k, az) in views.iter().enumerate() {
                let t = (i * views.len() + k) as u32;
                let img = render(&ctx, &raster, cat, tile, *az)?;
                put(&mut sheet, &img, tile, (t % cols) * tile, (t / cols) * tile);
            }
            let (c, d) = split(cat);
            let arch = d.map_or_else(|| archetype_of(c), |d| archetype_described(c, d));
            println!("sheet {} tile {i}: {cat} ({arch})", s + 1);
        }
        let path = if cats.len() > per_sheet {
            out.replace(".png", &format!("_{}.png", s + 1))
        } else {
            out.clone()
        };
        sheet.save(&path)?;
        println!("wrote {path}");
    }
    let big = 512u32;
    let img = render(&ctx, &raster, &closeup, big, 30.0)?;
    let mut one = image::RgbImage::new(big, big);
    put(&mut one, &img, big, 0, 0);
    let close = out.replace(".png", "_closeup.png");
    one.save(&close)?;
    println!("wrote {close}");
    Ok(())
}
