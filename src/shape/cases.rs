//! Layouts of case goods and fixtures: cabinets, dressers, wardrobes, shelves,
//! lamps, rugs, counters, sinks, fireplaces, pianos, bathtubs and toilets. The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::goods::{fill, Bay, Draws};
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_y, IDENTITY};

/// A case (cabinet, dresser, wardrobe): carcass on a plinth or legs, top, fronts with handles.
/// `drawers` rows of drawers above `doors` doors (side by side); `legs` lifts it on legs.
fn case(b: &mut Builder, doors: usize, drawers: usize, legs: bool) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let base = if legs {
        (0.15 * h).min(0.15)
    } else {
        (0.06 * h).min(0.08)
    };
    let top = 0.025;
    let face = hd - 0.035;
    if legs {
        b.legs(Frame, 0.04, 0.03, 0.0, base);
    } else {
        b.cuboid(
            Frame,
            [-hw + 0.02, -hd + 0.02, 0.0],
            [hw - 0.02, face - 0.02, base],
        );
    }
    b.cuboid(Body, [-hw, -hd, base], [hw, face, h - top]);
    b.cuboid(Top, [-hw, -hd, h - top], [hw, hd - 0.01, h]);
    let (z_lo, z_hi) = (base + 0.01, h - top - 0.01);
    let gap = 0.005;
    let cols = if b.w > 1.0 && doors == 0 { 2 } else { 1 };
    let front = |b: &mut Builder, x0: f64, x1: f64, z0: f64, z1: f64| {
        b.cuboid(
            Door,
            [x0 + gap, face, z0 + gap],
            [x1 - gap, hd - 0.014, z1 - gap],
        );
    };
    let drawer_h = if doors > 0 {
        ((z_hi - z_lo) * 0.18).min(0.2)
    } else {
        (z_hi - z_lo) / drawers.max(1) as f64
    };
    let mut z = z_hi;
    for _ in 0..drawers {
        let cw = (b.w - 0.02) / cols as f64;
        for c in 0..cols {
            let x0 = -hw + 0.01 + c as f64 * cw;
            front(b, x0, x0 + cw, z - drawer_h, z);
            let (xc, zc) = (x0 + cw / 2.0, z - drawer_h / 2.0);
            let hl = (0.15 * cw).min(0.07);
            b.cuboid(
                Handle,
                [xc - hl, hd - 0.014, zc - 0.008],
                [xc + hl, hd, zc + 0.008],
            );
        }
        z -= drawer_h;
    }
    if doors > 0 {
        let dw = (b.w - 0.02) / doors as f64;
        for i in 0..doors {
            let x0 = -hw + 0.01 + i as f64 * dw;
            front(b, x0, x0 + dw, z_lo, z);
            // Handle on the door's inner edge (towards the centre), at a comfortable height.
            let xc = if x0 + dw / 2.0 < 0.0 {
                x0 + dw - 0.04
            } else {
                x0 + 0.04
            };
            let zc = (z_lo + 0.55 * (z - z_lo)).min(1.1);
            let hl = (0.06 * (z - z_lo)).clamp(0.03, 0.12);
            b.cuboid(
                Handle,
                [xc - 0.008, hd - 0.014, zc - hl],
                [xc + 0.008, hd, zc + hl],
            );
        }
    }
}

pub fn cabinet(b: &mut Builder) {
    let doors = if b.w < 0.6 { 1 } else { 2 };
    case(b, doors, 0, false);
}

pub fn dresser(b: &mut Builder) {
    let rows = ((b.h / 0.22).round() as usize).clamp(2, 6);
    case(b, 0, rows, b.h < 1.2);
}

pub fn wardrobe(b: &mut Builder) {
    let doors = ((b.w / 0.5).round() as usize).clamp(1, 4);
    case(b, doors, 1, false);
}

pub fn sideboard(b: &mut Builder) {
    let doors = ((b.w / 0.45).round() as usize).clamp(1, 5);
    case(b, doors, 0, true);
}

/// Shelves filled with what the category holds ([`Builder::goods`], books by default): side
/// panels, a plinth, boards, and (`back`) a back panel; the goods builder fills each board.
fn shelves(b: &mut Builder, back: bool) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.025;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Frame, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, hd, h]);
    }
    if back {
        b.cuboid(Interior, [-hw + t, -hd, 0.0], [hw - t, -hd + 0.012, h]);
    }
    let rows = ((h / 0.38).round() as usize).max(2);
    let plinth = 0.06;
    let pitch = (h - plinth - t) / rows as f64;
    b.cuboid(Frame, [-hw + t, -hd + 0.012, 0.0], [hw - t, hd, plinth]);
    let goods = b.goods.unwrap_or_default();
    let mut draws = Draws::new(0x2545_f491_4f6c_dd1d);
    for r in 0..=rows {
        let z = plinth + r as f64 * pitch;
        b.cuboid(
            Frame,
            [-hw + t, -hd + 0.012, z.min(h - t)],
            [hw - t, hd, (z + t).min(h)],
        );
        if r == rows {
            break;
        }
        // Goods stand towards the front edge, where a deep rack shows them.
        let depth = (0.8 * b.d).min(0.45);
        let bay = Bay {
            x0: -hw + t + 0.01,
            x1: hw - t - 0.01,
            y0: (hd - 0.02 - depth).max(-hd + 0.014),
            depth,
            z: z + t,
            room: pitch - t - 0.02,
        };
        fill(b, goods, bay, &mut draws);
    }
}

pub fn shelf(b: &mut Builder) {
    shelves(b, true);
}

pub fn rack(b: &mut Builder) {
    shelves(b, false);
}

pub fn floor_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.7 * hw, 0.7 * hd, 0.8, 0.03);
    let sh = (0.22 * h).min(0.4);
    b.cylinder(Metal, [0.0, 0.0, 0.03], 0.012, h - sh - 0.02);
    b.frustum(Shade, [0.0, 0.0, h - sh], hw, hd, 0.7, sh);
    b.cylinder(Light, [0.0, 0.0, h - sh - 0.03], 0.03, 0.04);
}

pub fn table_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.42 * h;
    b.cylinder(Metal, [0.0, 0.0, 0.0], 0.45 * hw.min(hd), 0.02);
    b.ellipsoid(
        Body,
        [0.0, 0.0, zb / 2.0 + 0.01],
        [0.55 * hw, 0.55 * hd, zb / 2.0],
    );
    b.cylinder(Metal, [0.0, 0.0, zb], 0.008, 0.12 * h);
    let sh = 0.45 * h;
    b.frustum(Shade, [0.0, 0.0, h - sh], hw, hd, 0.65, sh);
}

/// A desk lamp: a weighted round foot at the back, an arm rising from it to an elbow and a
/// second arm reaching forward, and a cone of a shade at its end tipped down over the desk,
/// its bulb in the mouth (a task lamp, never a bedside lamp's drum on a bulb base).
pub fn task_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let foot = hw.min(0.4 * hd);
    let yb = -hd + foot;
    b.cylinder(Metal, [0.0, yb, 0.0], foot, 0.03);
    let arm = (0.012 * h / 0.5).clamp(0.006, 0.02);
    let elbow = [0.0, -hd + 0.4 * foot, 0.88 * h];
    b.rod(Metal, [0.0, yb, 0.03], elbow, arm);
    // the shade's mouth faces down and forward; its apex sits at the end of the upper arm
    let sl = (0.3 * h).min(0.9 * hd);
    let sr = (0.9 * hw).min(0.45 * sl);
    let axis: [f64; 3] = [0.0, 0.45, -1.0];
    let l = (axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let dir: [f64; 3] = [0.0, axis[1] / l, axis[2] / l];
    let mouth_y = hd - sr * dir[2].abs();
    let apex = [0.0, mouth_y - sl * dir[1], h - 0.02];
    b.rod(Metal, elbow, apex, arm);
    // a spring beside each arm, as on an anglepoise
    for (a, c) in [([0.0, yb, 0.03], elbow), (elbow, apex)] {
        b.rod(
            Metal,
            [a[0] + 2.5 * arm, a[1], a[2] + 0.1 * (c[2] - a[2]).abs()],
            [c[0] + 2.5 * arm, c[1], c[2] - 0.02],
            0.4 * arm,
        );
    }
    b.cylinder(Metal, [0.0, elbow[1], elbow[2] - arm], 1.6 * arm, 2.0 * arm);
    b.revolved(
        Shade,
        0,
        apex,
        frame_along(dir),
        1.0,
        frustum_profile(0.25 * sr, sr, sl),
    );
    let bulb = [0, 1, 2].map(|k| apex[k] + 0.8 * sl * dir[k]);
    b.ellipsoid(Light, bulb, [0.35 * sr, 0.35 * sr, 0.35 * sr]);
}

pub fn rug(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let bw = (0.08 * b.w.min(b.d)).min(0.15);
    b.cuboid(Cushion, [-hw, -hd, 0.0], [hw, -hd + bw, h]);
    b.cuboid(Cushion, [-hw, hd - bw, 0.0], [hw, hd, h]);
    b.cuboid(Cushion, [-hw, -hd + bw, 0.0], [-hw + bw, hd - bw, h]);
    b.cuboid(Cushion, [hw - bw, -hd + bw, 0.0], [hw, hd - bw, h]);
    b.cuboid(Upholstery, [-hw + bw, -hd + bw, 0.0], [hw - bw, hd - bw, h]);
}

/// Base cabinets with doors and a top: the top's thickness is `top`.
fn base_cabinets(b: &mut Builder, top_z: f64) {
    let (hw, hd) = b.half();
    let face = hd - 0.045;
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd, 0.0],
        [hw - 0.02, face - 0.04, 0.09],
    );
    b.cuboid(Body, [-hw, -hd, 0.09], [hw, face, top_z]);
    let doors = ((b.w / 0.55).round() as usize).max(1);
    let dw = (b.w - 0.01) / doors as f64;
    for i in 0..doors {
        let x0 = -hw + 0.005 + i as f64 * dw;
        b.cuboid(
            Door,
            [x0 + 0.004, face, 0.1],
            [x0 + dw - 0.004, hd - 0.025, top_z - 0.01],
        );
        let xc = x0 + dw / 2.0;
        b.cuboid(
            Handle,
            [xc - 0.07, hd - 0.025, top_z - 0.07],
            [xc + 0.07, hd - 0.01, top_z - 0.055],
        );
    }
}

pub fn counter(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    base_cabinets(b, h - 0.04);
    b.cuboid(Top, [-hw, -hd, h - 0.04], [hw, hd, h]);
}

pub fn sink(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // A vessel basin on the counter (bathroom) or an inset tub with a rim (kitchen).
    let bowl = (0.16 * h).min(0.15);
    let zt = h - bowl;
    base_cabinets(b, zt - 0.035);
    b.cuboid(Top, [-hw, -hd, zt - 0.035], [hw, hd, zt]);
    // a top long enough for two people to wash side by side (a double vanity) has two basins
    let basins: usize = if b.w >= 1.3 { 2 } else { 1 };
    let rx = (0.3 * b.w / basins as f64).min(0.3);
    let ry = (0.32 * b.d).min(0.22);
    let yc = 0.05 * b.d;
    let profile = vec![
        [0.6 * rx, 0.0],
        [rx, bowl * 0.7],
        [rx, bowl],
        [0.9 * rx, bowl],
        [0.55 * rx, 0.02],
        [0.0, 0.02],
    ];
    for i in 0..basins {
        let xc = if basins == 1 {
            0.0
        } else {
            (i as f64 - 0.5) * b.w / 2.0
        };
        b.revolved(Canvas, 0, [xc, yc, zt], IDENTITY, ry / rx, profile.clone());
        let yf = yc - ry - 0.05;
        b.cylinder(
            Metal,
            [xc, yf, zt],
            0.018,
            bowl + 0.1_f64.min(h - zt - bowl) - 0.005,
        );
        b.rod(Metal, [xc, yf, h - 0.02], [xc, yf + 0.12, h - 0.02], 0.012);
    }
}

pub fn fireplace(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let mantel = 0.06;
    b.cuboid(
        Body,
        [-hw + 0.05, -hd, 0.0],
        [hw - 0.05, hd - 0.12, h - mantel],
    );
    b.cuboid(Top, [-hw, -hd, h - mantel], [hw, hd - 0.05, h]);
    b.cuboid(Body, [-hw + 0.02, -hd, 0.0], [hw - 0.02, hd, 0.08]);
    let (ow, oh) = (0.55 * b.w, 0.6 * (h - mantel));
    b.cuboid(
        Interior,
        [-ow / 2.0, hd - 0.125, 0.08],
        [ow / 2.0, hd - 0.115, 0.08 + oh],
    );
    for k in 0..3 {
        let x = (k as f64 - 1.0) * 0.12 * b.w;
        b.ellipsoid(Light, [x, hd - 0.2, 0.16], [0.05 * b.w, 0.04, 0.07 * h]);
    }
}

pub fn piano(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zk = 0.58 * h.min(1.25);
    let body_front = -hd + 0.55 * b.d;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, body_front, h]);
    // Keyboard shelf, white and black keys, legs under it.
    b.cuboid(
        Body,
        [-hw, body_front, zk - 0.08],
        [hw, hd - 0.02, zk - 0.02],
    );
    b.cuboid(
        Keys,
        [-hw + 0.08, body_front, zk - 0.02],
        [hw - 0.08, hd - 0.04, zk],
    );
    let n = ((b.w - 0.16) / 0.0235 * 5.0 / 7.0) as usize;
    let kw = (b.w - 0.16) / n as f64;
    for i in 0..n {
        if [1, 3, 6, 8, 10].contains(&(i % 12)) || i % 2 == 1 {
            continue;
        }
        let x = -hw + 0.08 + (i as f64 + 0.75) * kw;
        b.cuboid(
            BlackKeys,
            [x, body_front + 0.01, zk],
            [x + 0.6 * kw, body_front + 0.09, zk + 0.012],
        );
    }
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.05);
        b.cuboid(Frame, [x - 0.03, hd - 0.06, 0.0], [x + 0.03, hd, zk - 0.08]);
    }
    b.cuboid(
        Frame,
        [-0.25 * b.w, body_front, 0.08],
        [0.25 * b.w, body_front + 0.04, 0.12],
    );
}

pub fn grand_piano(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The case stands about a metre tall; what the size box has above it is the open lid's.
    let hc = h.min(1.0);
    let zb = 0.6 * hc;
    let kd = 0.25;
    // The case: a wing, straight along the bass side (+x, the player's left), its bentside
    // curving in from the treble side (-x) to a narrow tail at the back (-y). Drawn as slices
    // across its length so its outline (a grand's mark from above and behind) is the wing's.
    let (y0, y1) = (-hd, hd - kd);
    let ht = hc - 0.1_f64.min(0.25 * (hc - zb));
    // The lid, hinged along the straight side, propped open on its stick as far as the box
    // allows (at most 40°); shut where the box has no room above the case.
    let sin_lid = ((h - ht - 0.03) / (2.0 * hw)).clamp(0.0, 40f64.to_radians().sin());
    let lid = sin_lid.asin();
    let n = 28;
    let rim = 0.04;
    let mut stick = None;
    for i in 0..n {
        let (ta, tb) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
        let (ya, yb) = (y1 - ta * (y1 - y0), y1 - tb * (y1 - y0));
        // From the keyboard end the bentside keeps the full width, then sweeps in to the tail.
        let t = tb.max(ta);
        let inward = if t < 0.3 {
            0.0
        } else {
            ((t - 0.3) / 0.7).powf(1.6)
        };
        let left = -hw + inward * 1.55 * hw;
        b.cuboid(Body, [left, yb, zb], [hw, ya + 0.001, ht - 0.03]);
        if lid < 0.05 {
            b.cuboid(Top, [left, yb, ht - 0.03], [hw, ya + 0.001, ht]);
            continue;
        }
        // Open: the case's rim, the golden plate and strings inside it, and the lid above.
        b.cuboid(Top, [left, yb, ht - 0.03], [left + rim, ya + 0.001, ht]);
        b.cuboid(Top, [hw - rim, yb, ht - 0.03], [hw, ya + 0.001, ht]);
        b.cuboid(
            Metal,
            [left + rim, yb, ht - 0.06],
            [hw - rim, ya + 0.001, ht - 0.045],
        );
        let dx = 0.5 * (hw - left);
        b.slab(
            Top,
            [
                hw - dx * lid.cos(),
                0.5 * (ya + yb),
                ht + 0.012 + dx * lid.sin(),
            ],
            [dx, 0.5 * (ya - yb) + 0.0005, 0.012],
            rot_y(lid),
        );
        if stick.is_none() && t > 0.35 {
            stick = Some((left + 0.08, 0.5 * (ya + yb)));
        }
    }
    // The stick, from the treble rim up to the lid's underside.
    if let Some((x, y)) = stick {
        let top = ht + (hw - x) * lid.tan();
        b.rod(Frame, [x, y, ht], [x, y, top], 0.012);
    }
    // The key bed, the keys and the music desk standing behind them.
    b.cuboid(Body, [-hw, hd - kd - 0.1, zb], [hw, hd - 0.05, zb + 0.12]);
    b.cuboid(
        Keys,
        [-hw + 0.1, hd - kd, zb + 0.1],
        [hw - 0.1, hd - 0.03, zb + 0.12],
    );
    b.cuboid(
        Body,
        [-0.55 * hw, hd - kd - 0.06, ht],
        [0.55 * hw, hd - kd - 0.03, (ht + 0.25).min(h)],
    );
    for (x, y) in [
        (-hw + 0.08, hd - kd),
        (hw - 0.08, hd - kd),
        (0.78 * hw, -hd + 0.15),
    ] {
        b.cylinder(Frame, [x, y, 0.0], 0.05, zb);
    }
    b.cuboid(Frame, [-0.12, hd - 0.2, 0.0], [0.12, hd - 0.1, 0.05]);
}

pub fn bathtub(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rim = 0.05;
    let profile = vec![
        [0.0, 0.06],
        [0.8 * hw, 0.06],
        [hw, h],
        [hw - rim, h],
        [0.85 * (hw - rim), 0.2 * h],
        [0.0, 0.2 * h],
    ];
    b.revolved(Body, 0, [0.0, 0.0, 0.0], IDENTITY, hd / hw, profile);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(Metal, [sx * 0.6 * hw, sy * 0.55 * hd, 0.0], 0.03, 0.08);
        }
    }
    b.revolved(
        Canvas,
        0,
        [0.0, 0.0, 0.2 * h + 0.005],
        IDENTITY,
        hd / hw,
        frustum_profile(0.8 * (hw - rim), 0.8 * (hw - rim), 0.002),
    );
}

pub fn toilet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = 0.42_f64.min(0.52 * h);
    let tank_d = 0.2 * b.d;
    b.cuboid(Body, [-hw, -hd, zs - 0.05], [hw, -hd + tank_d, h]);
    b.cuboid(Top, [-hw, -hd, h - 0.03], [hw, -hd + tank_d + 0.01, h]);
    let yc = -hd + tank_d + 0.5 * (b.d - tank_d) - 0.01;
    let (rx, ry) = (hw * 0.95, 0.5 * (b.d - tank_d) - 0.01);
    b.frustum(
        Body,
        [0.0, yc - 0.05, 0.0],
        0.5 * rx,
        0.5 * ry,
        1.2,
        zs * 0.7,
    );
    let profile = vec![
        [0.6 * rx, 0.0],
        [rx, 0.75 * (zs - 0.7 * zs)],
        [rx, zs * 0.3 - 0.02],
        [0.7 * rx, zs * 0.3 - 0.02],
        [0.4 * rx, 0.0],
        [0.0, 0.0],
    ];
    b.revolved(Body, 0, [0.0, yc, zs * 0.7], IDENTITY, ry / rx, profile);
    let seat = vec![[rx, 0.0], [rx, 0.02], [0.68 * rx, 0.02], [0.68 * rx, 0.0]];
    b.revolved(Top, 0, [0.0, yc, zs - 0.02], IDENTITY, ry / rx, seat);
}
