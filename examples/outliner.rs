//! Draws the object tree Blender builds from an engine glb, as its outliner lists it (headless
//! Blender has no window to capture): the `RESULT {json}` line that
//! `blender -b --factory-startup --python tests/node/blender_import.py -- FILE.glb` prints,
//! one row per object (type, name, a few custom properties), children indented under parents.
//! `cargo run --release --example outliner BLENDER_LOG OUT.png`
use font8x8::UnicodeFonts;
use image::{Rgb, RgbImage};
use serde_json::Value;

const ROW: u32 = 22;
const SCALE: u32 = 2;

fn text(img: &mut RgbImage, x: u32, y: u32, s: &str, c: Rgb<u8>) {
    for (k, ch) in s.chars().enumerate() {
        let Some(glyph) = font8x8::BASIC_FONTS.get(ch) else {
            continue;
        };
        for (row, bits) in glyph.iter().enumerate() {
            for col in 0..8 {
                if bits & (1 << col) != 0 {
                    for sy in 0..SCALE {
                        for sx in 0..SCALE {
                            let px = x + (k as u32 * 8 + col) * SCALE + sx;
                            let py = y + row as u32 * SCALE + sy;
                            if px < img.width() && py < img.height() {
                                img.put_pixel(px, py, c);
                            }
                        }
                    }
                }
            }
        }
    }
}

fn rows(
    objs: &serde_json::Map<String, Value>,
    parent: Option<&str>,
    depth: u32,
    out: &mut Vec<(u32, String, String, String)>,
) {
    let mut names: Vec<&String> = objs
        .iter()
        .filter(|(_, o)| o["parent"].as_str() == parent)
        .map(|(n, _)| n)
        .collect();
    names.sort();
    for n in names {
        let o = &objs[n];
        let props = &o["props"];
        let detail = if let Some(c) = props["category"].as_str() {
            format!("category={c} instance_id={}", props["instance_id"])
        } else if let Some(c) = props["collider_of"].as_str() {
            format!("collider of {c}, {} vertices", o["vertices"])
        } else if props["agent_radius"].is_number() {
            format!("agent_radius={}", props["agent_radius"])
        } else {
            String::new()
        };
        let kind = o["type"].as_str().unwrap_or("?").to_string();
        out.push((depth, kind, n.clone(), detail));
        rows(objs, Some(n), depth + 1, out);
    }
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(log), Some(out)) = (args.first(), args.get(1)) else {
        anyhow::bail!("usage: outliner BLENDER_LOG OUT.png");
    };
    let log = std::fs::read_to_string(log)?;
    let line = log
        .lines()
        .find_map(|l| l.strip_prefix("RESULT "))
        .ok_or_else(|| anyhow::anyhow!("no RESULT line in the log"))?;
    let v: Value = serde_json::from_str(line)?;
    let objs = v
        .as_object()
        .ok_or_else(|| anyhow::anyhow!("not an object"))?;
    let mut list = vec![];
    rows(objs, None, 0, &mut list);
    let mut img = RgbImage::from_pixel(1400, (list.len() as u32 + 2) * ROW, Rgb([40, 40, 40]));
    text(
        &mut img,
        8,
        6,
        "Blender 3.4 outliner (glTF import of the engine glb)",
        Rgb([255, 255, 255]),
    );
    for (k, (depth, kind, name, detail)) in list.iter().enumerate() {
        let y = (k as u32 + 1) * ROW + 6;
        if k % 2 == 0 {
            for yy in y - 3..y + ROW - 3 {
                for x in 0..img.width() {
                    img.put_pixel(x, yy, Rgb([48, 48, 48]));
                }
            }
        }
        let x = 12 + depth * 32;
        let colour = match kind.as_str() {
            "MESH" => Rgb([120, 200, 255]),
            "EMPTY" => Rgb([255, 200, 120]),
            _ => Rgb([200, 200, 200]),
        };
        let tag = if kind == "MESH" { "[mesh]" } else { "[empty]" };
        text(&mut img, x, y, tag, colour);
        text(&mut img, x + 124, y, name, Rgb([235, 235, 235]));
        text(&mut img, 620, y, detail, Rgb([160, 160, 160]));
    }
    img.save(out)?;
    println!("wrote {out} ({} objects)", list.len());
    Ok(())
}
