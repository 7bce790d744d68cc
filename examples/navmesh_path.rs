//! Draws the engine export's navmesh over a scene's `layout.png` drawing: walkable cells in
//! green, spawn points in blue and, given the JSON that `node tests/node/engine.mjs recast`
//! prints, each Detour path in red.
//! `cargo run --release --example navmesh_path SCENE_DIR OUT.png [PATHS.json]`
use dreamscene::export::engine::{door_points, encode, read_input, EngineOptions};
use dreamscene::plan::draw::draw_layout;
use dreamscene::plan::spec::Layout;
use std::path::Path;

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(dir), Some(out)) = (args.first(), args.get(1)) else {
        anyhow::bail!("usage: navmesh_path SCENE_DIR OUT.png [PATHS.json]");
    };
    let dir = Path::new(dir);
    let layout: Layout = serde_json::from_str(&std::fs::read_to_string(dir.join("layout.json"))?)?;
    let mut img = draw_layout(&layout);
    let input = read_input(dir)?;
    let (_, nav) = encode(&input, &EngineOptions::default())?;
    let [w, d, _] = layout.room.size;
    // The drawing's mapping (plan/draw.rs): 40 px margin, 900 px for the longer side, north up.
    let s = 900.0 / w.max(d);
    let h = f64::from(img.height());
    let px = |x: f64, y: f64| (40.0 + (x + w / 2.0) * s, h - 40.0 - (y + d / 2.0) * s);
    let mut blend = |x: i64, y: i64, c: [u8; 3], a: f64| {
        if x >= 0 && y >= 0 && (x as u32) < img.width() && (y as u32) < img.height() {
            let p = img.get_pixel_mut(x as u32, y as u32);
            for (v, &ck) in p.0.iter_mut().zip(&c) {
                *v = (f64::from(*v) * (1.0 - a) + f64::from(ck) * a) as u8;
            }
        }
    };
    for j in 0..nav.ny {
        for i in 0..nav.nx {
            if !nav.walkable[j * nav.nx + i] {
                continue;
            }
            let x0 = nav.origin[0] + i as f64 * nav.cell;
            let y0 = nav.origin[1] + j as f64 * nav.cell;
            let (a, b) = (px(x0, y0 + nav.cell), px(x0 + nav.cell, y0));
            for y in a.1.round() as i64..b.1.round() as i64 {
                for x in a.0.round() as i64..b.0.round() as i64 {
                    blend(x, y, [60, 190, 90], 0.35);
                }
            }
        }
    }
    let mut dot = |x: f64, y: f64, r: f64, c: [u8; 3]| {
        let (cx, cy) = px(x, y);
        for dy in -(r as i64)..=r as i64 {
            for dx in -(r as i64)..=r as i64 {
                if ((dx * dx + dy * dy) as f64) <= r * r {
                    blend(cx as i64 + dx, cy as i64 + dy, c, 1.0);
                }
            }
        }
    };
    if let Some(paths) = args.get(2) {
        let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(paths)?)?;
        for p in v["paths"].as_array().into_iter().flatten() {
            let pts: Vec<[f64; 2]> = p["path"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(|q| Some([q[0].as_f64()?, -q[2].as_f64()?]))
                .collect();
            for seg in pts.windows(2) {
                for k in 0..=200 {
                    let t = f64::from(k) / 200.0;
                    let x = seg[0][0] + (seg[1][0] - seg[0][0]) * t;
                    let y = seg[0][1] + (seg[1][1] - seg[0][1]) * t;
                    dot(x, y, 2.5, [220, 30, 30]);
                }
            }
            if let Some(e) = pts.last() {
                dot(e[0], e[1], 6.0, [220, 30, 30]);
            }
        }
    }
    for (p, _) in nav.spawn_points(&door_points(&input), 2) {
        dot(p[0], p[1], 8.0, [30, 60, 220]);
    }
    img.save(out)?;
    println!("wrote {out} ({:.1} m² walkable)", nav.area());
    Ok(())
}
