//! `layout.png`: a top-down drawing of a layout: the room outline, each footprint filled and
//! labelled with its id, and an arrow for its facing. North (+y) is up.
use super::check::Box2;
use super::spec::{Layout, PlacedBy, SceneType};
use font8x8::UnicodeFonts;
use image::{Rgb, RgbImage};

const MARGIN: f64 = 40.0;

struct Canvas {
    img: RgbImage,
    scale: f64,
    origin: [f64; 2],
}

impl Canvas {
    fn to_px(&self, p: [f64; 2]) -> [f64; 2] {
        [
            MARGIN + (p[0] - self.origin[0]) * self.scale,
            self.img.height() as f64 - MARGIN - (p[1] - self.origin[1]) * self.scale,
        ]
    }

    fn put(&mut self, x: i64, y: i64, c: Rgb<u8>) {
        if x >= 0 && y >= 0 && (x as u32) < self.img.width() && (y as u32) < self.img.height() {
            self.img.put_pixel(x as u32, y as u32, c);
        }
    }

    fn line(&mut self, a: [f64; 2], b: [f64; 2], c: Rgb<u8>, width: f64) {
        let (pa, pb) = (self.to_px(a), self.to_px(b));
        let len = ((pb[0] - pa[0]).powi(2) + (pb[1] - pa[1]).powi(2)).sqrt();
        let steps = (len * 2.0).ceil().max(1.0) as usize;
        let r = (width / 2.0).ceil() as i64;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let x = pa[0] + (pb[0] - pa[0]) * t;
            let y = pa[1] + (pb[1] - pa[1]) * t;
            for dy in -r..=r {
                for dx in -r..=r {
                    if ((dx * dx + dy * dy) as f64) <= (width / 2.0).powi(2) + 0.5 {
                        self.put(x as i64 + dx, y as i64 + dy, c);
                    }
                }
            }
        }
    }

    fn fill_box(&mut self, b: &Box2, c: Rgb<u8>) {
        let [x0, y0, x1, y1] = b.aabb();
        let (p0, p1) = (self.to_px([x0, y1]), self.to_px([x1, y0]));
        for py in p0[1].floor() as i64..=p1[1].ceil() as i64 {
            for px in p0[0].floor() as i64..=p1[0].ceil() as i64 {
                let w = [
                    self.origin[0] + (px as f64 + 0.5 - MARGIN) / self.scale,
                    self.origin[1]
                        + (self.img.height() as f64 - MARGIN - (py as f64 + 0.5)) / self.scale,
                ];
                if b.contains(w) {
                    self.put(px, py, c);
                }
            }
        }
    }

    fn text(&mut self, centre: [f64; 2], s: &str, c: Rgb<u8>) {
        let p = self.to_px(centre);
        let scale = 1i64;
        let w = s.chars().count() as i64 * 8 * scale;
        let (x0, y0) = (p[0] as i64 - w / 2, p[1] as i64 - 4 * scale);
        for (k, ch) in s.chars().enumerate() {
            let Some(g) = font8x8::BASIC_FONTS.get(ch) else {
                continue;
            };
            for (row, bits) in g.iter().enumerate() {
                for col in 0..8 {
                    if bits & (1 << col) != 0 {
                        for sy in 0..scale {
                            for sx in 0..scale {
                                self.put(
                                    x0 + (k as i64 * 8 + col) * scale + sx,
                                    y0 + row as i64 * scale + sy,
                                    c,
                                );
                            }
                        }
                    }
                }
            }
        }
    }
}

fn colour(name: &str) -> Rgb<u8> {
    // A stable pastel per category.
    let h = name
        .bytes()
        .fold(2166136261u32, |h, b| (h ^ b as u32).wrapping_mul(16777619));
    let f = |s: u32| 150 + ((h >> s) & 0x5f) as u8;
    Rgb([f(0), f(8), f(16)])
}

/// Draws `l` about 900 pixels across.
pub fn draw_layout(l: &Layout) -> RgbImage {
    let [w, d, _] = l.room.size;
    let scale = 900.0 / w.max(d);
    let img = RgbImage::from_pixel(
        (w * scale + 2.0 * MARGIN) as u32,
        (d * scale + 2.0 * MARGIN) as u32,
        Rgb([255, 255, 255]),
    );
    let mut cv = Canvas {
        img,
        scale,
        origin: [-0.5 * w, -0.5 * d],
    };
    let (hw, hd) = (0.5 * w, 0.5 * d);
    let floor = match l.scene_type {
        SceneType::Indoor => Rgb([245, 240, 230]),
        SceneType::Outdoor => Rgb([225, 240, 220]),
    };
    cv.fill_box(&Box2::new([0.0, 0.0], 0.0, [w, d], 0.0, 1.0), floor);
    // Larger and lower things first, so stacked objects stay visible.
    let mut order: Vec<usize> = (0..l.objects.len()).collect();
    order.sort_by(|&a, &b| {
        let (oa, ob) = (&l.objects[a], &l.objects[b]);
        oa.position[2]
            .total_cmp(&ob.position[2])
            .then((ob.size[0] * ob.size[1]).total_cmp(&(oa.size[0] * oa.size[1])))
    });
    let dark = Rgb([40, 40, 40]);
    for &i in &order {
        let o = &l.objects[i];
        let b = Box2::of(o);
        cv.fill_box(&b, colour(&o.category));
        let c = b.corners();
        let edge = if o.placed_by == PlacedBy::Fallback {
            Rgb([200, 30, 30])
        } else {
            dark
        };
        for k in 0..4 {
            cv.line(c[k], c[(k + 1) % 4], edge, 2.0);
        }
        // Facing arrow from the centre to the front edge.
        let tip = [b.c[0] + b.ey[0] * b.half[1], b.c[1] + b.ey[1] * b.half[1]];
        cv.line(b.c, tip, dark, 2.0);
        let head = 0.25 * b.half[1].min(b.half[0]).max(0.05);
        for s in [-1.0, 1.0] {
            let back = [
                tip[0] - b.ey[0] * head + s * b.ex[0] * head * 0.7,
                tip[1] - b.ey[1] * head + s * b.ex[1] * head * 0.7,
            ];
            cv.line(tip, back, dark, 2.0);
        }
    }
    for &i in &order {
        let o = &l.objects[i];
        cv.text([o.position[0], o.position[1]], &o.id, Rgb([0, 0, 0]));
    }
    let outline = Rgb([20, 20, 20]);
    let corners = [[-hw, -hd], [hw, -hd], [hw, hd], [-hw, hd]];
    for k in 0..4 {
        cv.line(corners[k], corners[(k + 1) % 4], outline, 4.0);
    }
    let label = format!("{:.1} m x {:.1} m", w, d);
    cv.text([0.0, -hd - 14.0 / scale], &label, outline);
    cv.img
}
