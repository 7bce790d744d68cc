//! `layout.png`: a top-down drawing of a layout: the room outline, each footprint filled with
//! an arrow for its facing (a thing hung from the ceiling as a dashed outline over what stands
//! below), a numbered marker per object (moved off crowded spots with a leader
//! line back to its object, so that no two markers overlap) and a legend beside the plan that
//! names each number. North (+y) is up.
use super::check::Box2;
use super::spec::{Layout, OpeningKind, PlacedBy, SceneType};
use font8x8::UnicodeFonts;
use image::{Rgb, RgbImage};

const MARGIN: f64 = 40.0;
/// Length of a dash (and of its gap) in the outline of a thing hung from the ceiling (m).
const DASH: f64 = 0.08;

/// Whether `o` hangs from the ceiling of a room `height` high (its top there, off the floor).
fn hangs_from_ceiling(o: &super::spec::PlacedObject, height: f64) -> bool {
    o.position[2] > 0.0 && (o.position[2] + o.size[2] - height).abs() <= 0.01
}

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
        let Some((pa, pb)) = self.clip(self.to_px(a), self.to_px(b), width) else {
            return;
        };
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

    /// The part of the pixel segment a-b that lies on the image (grown by `width`), so that a
    /// line's cost is bounded by the image's size, not by how far off it an end lies (an object
    /// moved by hand to x = 1e8). None when none of it does.
    /// [`Canvas::line`] in dashes of [`DASH`] metres with gaps as long.
    fn dashed(&mut self, a: [f64; 2], b: [f64; 2], c: Rgb<u8>, width: f64) {
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        let n = (len / DASH).ceil().max(1.0) as usize;
        for k in (0..n).step_by(2) {
            let (t0, t1) = (k as f64 / n as f64, ((k + 1) as f64 / n as f64).min(1.0));
            let at = |t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
            self.line(at(t0), at(t1), c, width);
        }
    }

    fn clip(&self, a: [f64; 2], b: [f64; 2], width: f64) -> Option<([f64; 2], [f64; 2])> {
        let lo = -width - 1.0;
        let hi = [
            self.img.width() as f64 + width + 1.0,
            self.img.height() as f64 + width + 1.0,
        ];
        let d = [b[0] - a[0], b[1] - a[1]];
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for k in 0..2 {
            for (p, q) in [(-d[k], a[k] - lo), (d[k], hi[k] - a[k])] {
                if p == 0.0 {
                    if q < 0.0 {
                        return None;
                    }
                } else {
                    let r = q / p;
                    if p < 0.0 {
                        t0 = t0.max(r);
                    } else {
                        t1 = t1.min(r);
                    }
                }
            }
        }
        if t0.is_nan() || t1.is_nan() || t0 > t1 {
            return None;
        }
        let at = |t: f64| [a[0] + d[0] * t, a[1] + d[1] * t];
        Some((at(t0), at(t1)))
    }

    /// A one-pixel line between pixel positions.
    fn px_line(&mut self, a: [f64; 2], b: [f64; 2], c: Rgb<u8>) {
        let Some((a, b)) = self.clip(a, b, 1.0) else {
            return;
        };
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        let steps = (len * 2.0).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let x = a[0] + (b[0] - a[0]) * t;
            let y = a[1] + (b[1] - a[1]) * t;
            self.put(x as i64, y as i64, c);
        }
    }

    /// 8x8 text with its top-left corner at pixel (x0, y0).
    fn px_text(&mut self, x0: i64, y0: i64, s: &str, c: Rgb<u8>) {
        for (k, ch) in s.chars().enumerate() {
            let Some(g) = font8x8::BASIC_FONTS.get(ch) else {
                continue;
            };
            for (row, bits) in g.iter().enumerate() {
                for col in 0..8 {
                    if bits & (1 << col) != 0 {
                        self.put(x0 + k as i64 * 8 + col, y0 + row as i64, c);
                    }
                }
            }
        }
    }

    fn fill_box(&mut self, b: &Box2, c: Rgb<u8>) {
        let [x0, y0, x1, y1] = b.aabb();
        let (p0, p1) = (self.to_px([x0, y1]), self.to_px([x1, y0]));
        // Only the pixels on the image are visited, however far off it the box lies.
        let (w, h) = (self.img.width() as f64, self.img.height() as f64);
        let ys = p0[1].floor().max(0.0) as i64..=p1[1].ceil().min(h) as i64;
        let xs = p0[0].floor().max(0.0) as i64..=p1[0].ceil().min(w) as i64;
        for py in ys {
            for px in xs.clone() {
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

/// The room-size caption.
fn caption(l: &Layout) -> String {
    format!("{:.1} m x {:.1} m", l.room.size[0], l.room.size[1])
}

/// Legend line height and column width, pixels.
const LEGEND_ROW: i64 = 12;
const LEGEND_COL: i64 = 180;

/// Pixel size of the plan part and of the legend for `l`: (plan width, height, legend width).
fn geometry(l: &Layout) -> (f64, u32, u32, u32) {
    let [w, d, _] = l.room.size;
    let scale = 900.0 / w.max(d);
    let plan_w = (w * scale + 2.0 * MARGIN) as u32;
    let h = ((d * scale + 2.0 * MARGIN) as u32).max(240);
    let rows = ((h as i64 - 2 * MARGIN as i64) / LEGEND_ROW).max(1);
    let cols = (l.objects.len() as i64 + rows - 1) / rows;
    (scale, plan_w, h, (cols.max(1) * LEGEND_COL) as u32)
}

/// Where each object's numbered marker goes: pixel rectangles [x0, y0, x1, y1] (inclusive-
/// exclusive), one per object in layout order, none overlapping another, all inside the plan
/// area's margins; and whether each was moved off its object's centre.
pub fn label_boxes(l: &Layout) -> Vec<([i64; 4], bool)> {
    let [w, d, _] = l.room.size;
    let (scale, plan_w, h, _) = geometry(l);
    let to_px = |p: [f64; 3]| {
        [
            MARGIN + (p[0] + 0.5 * w) * scale,
            h as f64 - MARGIN - (p[1] + 0.5 * d) * scale,
        ]
    };
    // The room-size caption under the plan is taken.
    let caption = caption(l);
    let cx = (MARGIN + 0.5 * w * scale) as i64;
    let cy = (h as f64 - MARGIN + 14.0) as i64;
    let half = caption.len() as i64 * 4;
    let mut placed: Vec<[i64; 4]> = vec![[cx - half, cy - 4, cx + half, cy + 4]];
    let mut out = vec![];
    // Smaller objects first: they have the least room around them.
    let mut order: Vec<usize> = (0..l.objects.len()).collect();
    order.sort_by(|&a, &b| {
        let area = |i: usize| l.objects[i].size[0] * l.objects[i].size[1];
        area(a).total_cmp(&area(b))
    });
    let mut result = vec![([0i64; 4], false); l.objects.len()];
    for i in order {
        let c = to_px(l.objects[i].position);
        let text_w = (format!("{}", i + 1).len() as i64) * 8 + 4;
        let rect_at = |x: f64, y: f64| {
            let x0 = x.round() as i64 - text_w / 2;
            let y0 = y.round() as i64 - 6;
            [x0, y0, x0 + text_w, y0 + 12]
        };
        let free = |r: &[i64; 4], placed: &[[i64; 4]]| {
            r[0] >= 2
                && r[1] >= 2
                && r[2] <= plan_w as i64 - 2
                && r[3] <= h as i64 - 2
                && placed
                    .iter()
                    .all(|p| r[2] < p[0] || p[2] < r[0] || r[3] < p[1] || p[3] < r[1])
        };
        let mut chosen = None;
        'search: for ring in 0..60 {
            let radius = ring as f64 * 7.0;
            let steps = if ring == 0 { 1 } else { 8 + 2 * ring };
            for k in 0..steps {
                let a = k as f64 / steps as f64 * std::f64::consts::TAU;
                let r = rect_at(c[0] + radius * a.cos(), c[1] - radius * a.sin());
                if free(&r, &placed) {
                    chosen = Some((r, ring > 0));
                    break 'search;
                }
            }
        }
        // Nowhere free near the object (hundreds of objects): stack down the left margin.
        let (r, moved) = chosen.unwrap_or_else(|| {
            let mut y = 2;
            loop {
                let r = [2, y, 2 + text_w, y + 12];
                if placed
                    .iter()
                    .all(|p| r[3] < p[1] || p[3] < r[1] || r[2] < p[0] || p[2] < r[0])
                {
                    break (r, true);
                }
                y += 13;
            }
        });
        placed.push(r);
        result[i] = (r, moved);
    }
    out.extend(result);
    out
}

/// Draws `l` about 900 pixels across.
pub fn draw_layout(l: &Layout) -> RgbImage {
    let [w, d, _] = l.room.size;
    let (scale, plan_w, h, legend_w) = geometry(l);
    let img = RgbImage::from_pixel(plan_w + legend_w, h, Rgb([255, 255, 255]));
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
        if hangs_from_ceiling(o, l.room.size[2]) {
            // as on an architect's plan: a dashed outline over what stands below
            let Rgb([r, g, bl]) = colour(&o.category);
            let ink = Rgb([r / 2, g / 2, bl / 2]);
            let c = b.corners();
            for k in 0..4 {
                cv.dashed(c[k], c[(k + 1) % 4], ink, 3.0);
            }
            continue;
        }
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
    // Numbered markers (leader lines first, so markers draw over them), then the legend.
    let boxes = label_boxes(l);
    for (i, (r, moved)) in boxes.iter().enumerate() {
        if *moved {
            let o = &l.objects[i];
            let c = cv.to_px([o.position[0], o.position[1]]);
            let m = [0.5 * (r[0] + r[2]) as f64, 0.5 * (r[1] + r[3]) as f64];
            cv.px_line(c, m, Rgb([90, 90, 90]));
        }
    }
    for (i, (r, _)) in boxes.iter().enumerate() {
        for y in r[1]..r[3] {
            for x in r[0]..r[2] {
                let edge = y == r[1] || y == r[3] - 1 || x == r[0] || x == r[2] - 1;
                cv.put(
                    x,
                    y,
                    if edge {
                        Rgb([60, 60, 60])
                    } else {
                        Rgb([255, 255, 255])
                    },
                );
            }
        }
        cv.px_text(r[0] + 2, r[1] + 2, &format!("{}", i + 1), Rgb([0, 0, 0]));
    }
    let rows = ((h as i64 - 2 * MARGIN as i64) / LEGEND_ROW).max(1);
    for (i, o) in l.objects.iter().enumerate() {
        let (col, row) = (i as i64 / rows, i as i64 % rows);
        let x = plan_w as i64 + col * LEGEND_COL + 4;
        let y = MARGIN as i64 + row * LEGEND_ROW;
        let fallback = o.placed_by == PlacedBy::Fallback;
        let mut line = format!("{:>2}{}{}", i + 1, if fallback { "*" } else { " " }, o.id);
        line.truncate(((LEGEND_COL - 8) / 8) as usize);
        let colour_box = colour(&o.category);
        for yy in y..y + 8 {
            for xx in x..x + 8 {
                cv.put(xx, yy, colour_box);
            }
        }
        let ink = if fallback {
            Rgb([200, 30, 30])
        } else {
            Rgb([0, 0, 0])
        };
        cv.px_text(x + 12, y, &line, ink);
    }
    if l.objects.iter().any(|o| o.placed_by == PlacedBy::Fallback) {
        let y = h as i64 - MARGIN as i64 + 8;
        cv.px_text(
            plan_w as i64 + 4,
            y,
            "* fallback: constraints unmet",
            Rgb([200, 30, 30]),
        );
    }
    let outline = Rgb([20, 20, 20]);
    let corners = [[-hw, -hd], [hw, -hd], [hw, hd], [-hw, hd]];
    for k in 0..4 {
        cv.line(corners[k], corners[(k + 1) % 4], outline, 4.0);
    }
    draw_openings(&mut cv, l);
    cv.text([0.0, -hd - 14.0 / scale], &caption(l), outline);
    if l.objects.iter().any(|o| o.placed_by == PlacedBy::Fallback) {
        // The key to the red outlines, in the top margin.
        let red = Rgb([200, 30, 30]);
        for k in 0..4 {
            cv.px_line(
                [4.0, 4.0 + k as f64 * 2.0],
                [20.0, 4.0 + k as f64 * 2.0],
                red,
            );
        }
        cv.px_text(
            24,
            4,
            "red outline: placed by fallback (a relation relaxed)",
            red,
        );
    }
    cv.img
}

/// Doors (a gap in the wall with the leaf swung open into the room) and windows (a pale blue
/// pane in the wall).
fn draw_openings(cv: &mut Canvas, l: &Layout) {
    for o in &l.openings {
        let (a, b) = o.span();
        let n = o.wall.inward();
        match o.kind {
            OpeningKind::Door => {
                cv.line(a, b, Rgb([255, 255, 255]), 6.0);
                // the leaf, open at right angles, and its swing
                let leaf = [a[0] + n[0] * o.width, a[1] + n[1] * o.width];
                cv.line(a, leaf, Rgb([150, 90, 40]), 3.0);
                let steps = 12;
                let along = [b[0] - a[0], b[1] - a[1]];
                let mut prev = b;
                for k in 1..=steps {
                    let t = k as f64 / steps as f64 * std::f64::consts::FRAC_PI_2;
                    let p = [
                        a[0] + along[0] * t.cos() + n[0] * o.width * t.sin(),
                        a[1] + along[1] * t.cos() + n[1] * o.width * t.sin(),
                    ];
                    cv.line(prev, p, Rgb([170, 140, 110]), 1.0);
                    prev = p;
                }
            }
            OpeningKind::Window => {
                cv.line(a, b, Rgb([120, 180, 235]), 6.0);
                cv.line(a, b, Rgb([40, 90, 160]), 1.0);
            }
        }
    }
}
