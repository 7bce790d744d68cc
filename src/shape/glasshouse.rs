//! Layout of a greenhouse: glazing on a slender frame, a low base wall and a pitched glass roof,
//! the ridge along its width. The front (with the door) faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{rot_x, Primitive};

/// Glazing bars about every 0.6 m, the frame 4 cm thick.
const BAY: f64 = 0.6;
const BAR: f64 = 0.04;

pub fn greenhouse(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let base = (0.15 * h).min(0.4);
    let eave = 0.65 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, base]);
    // Glass walls set just inside the frame, so the bars stand proud of them.
    let g = 0.5 * BAR;
    b.cuboid(Pane, [-hw + g, -hd + g, base], [hw - g, hd - g, eave]);
    // Posts round the walls and the eave and sill rails.
    let bays = |len: f64| ((len / BAY).round() as usize).max(1);
    let (nx, ny) = (bays(b.w), bays(b.d));
    for i in 0..=nx {
        let x = -hw + BAR / 2.0 + (b.w - BAR) * i as f64 / nx as f64;
        for y in [-hd + BAR / 2.0, hd - BAR / 2.0] {
            post(b, x, y, base, eave);
        }
    }
    for j in 1..ny {
        let y = -hd + BAR / 2.0 + (b.d - BAR) * j as f64 / ny as f64;
        for x in [-hw + BAR / 2.0, hw - BAR / 2.0] {
            post(b, x, y, base, eave);
        }
    }
    for z in [base, eave - BAR] {
        b.cuboid(Metal, [-hw, -hd, z], [hw, -hd + BAR, z + BAR]);
        b.cuboid(Metal, [-hw, hd - BAR, z], [hw, hd, z + BAR]);
        b.cuboid(Metal, [-hw, -hd, z], [-hw + BAR, hd, z + BAR]);
        b.cuboid(Metal, [hw - BAR, -hd, z], [hw, hd, z + BAR]);
    }
    // The door: a framed panel in the middle of the front.
    let dw = (0.3 * b.w).clamp(0.6, 0.9);
    let dh = (eave - base).min(1.9);
    b.cuboid(
        Metal,
        [-dw / 2.0, hd, base],
        [-dw / 2.0 + BAR, hd + 0.01, base + dh],
    );
    b.cuboid(
        Metal,
        [dw / 2.0 - BAR, hd, base],
        [dw / 2.0, hd + 0.01, base + dh],
    );
    b.cuboid(
        Metal,
        [-dw / 2.0, hd, base + dh - BAR],
        [dw / 2.0, hd + 0.01, base + dh],
    );
    // The roof: two glass planes meeting at a ridge along x, with rafters over them.
    let rise = h - eave;
    let slope = (rise / hd).atan();
    let len = hd.hypot(rise);
    for sy in [-1.0, 1.0] {
        let centre = [0.0, sy * 0.5 * hd, eave + 0.5 * rise];
        let rot = rot_x(-sy * slope);
        b.push(
            Pane,
            0,
            Primitive::Cuboid {
                centre,
                half: [hw, 0.5 * len, 0.01],
                rot,
            },
        );
        for i in 0..=nx {
            let x = -hw + BAR / 2.0 + (b.w - BAR) * i as f64 / nx as f64;
            b.push(
                Metal,
                0,
                Primitive::Cuboid {
                    centre: [x, centre[1], centre[2] + 0.02],
                    half: [BAR / 2.0, 0.5 * len, BAR / 2.0],
                    rot,
                },
            );
        }
    }
    // Gable ends: glass triangles as stacked slabs narrowing to the ridge.
    let n = 5;
    for k in 0..n {
        let z0 = eave + rise * k as f64 / n as f64;
        let z1 = eave + rise * (k + 1) as f64 / n as f64;
        let y = hd * (1.0 - (k as f64 + 0.5) / n as f64);
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - g);
            b.cuboid(Pane, [x - 0.005, -y, z0], [x + 0.005, y, z1]);
        }
    }
    b.cuboid(Metal, [-hw, -BAR, h - BAR], [hw, BAR, h]);
    staging(b, base);
}

/// Inside, seen through the glass: a staging bench along the back wall with a row of potted
/// plants on it, and taller plants in pots on the floor at the ends.
fn staging(b: &mut Builder, base: f64) {
    let (hw, hd) = b.half();
    if hw < 0.6 || hd < 0.6 {
        return;
    }
    let (x0, x1) = (-hw + 0.2, hw - 0.2);
    let (y0, y1) = (-hd + 0.1, -hd + 0.1 + (0.3 * b.d).min(0.7));
    let zt = 0.8;
    b.cuboid(Top, [x0, y0, zt - 0.04], [x1, y1, zt]);
    for x in [x0, x1 - 0.05] {
        for y in [y0, y1 - 0.05] {
            b.cuboid(Frame, [x, y, 0.0], [x + 0.05, y + 0.05, zt - 0.04]);
        }
    }
    let n = ((x1 - x0) / 0.35).floor().max(1.0) as usize;
    let yc = 0.5 * (y0 + y1);
    for i in 0..n {
        let x = x0 + (i as f64 + 0.5) * (x1 - x0) / n as f64;
        b.frustum(Pot, [x, yc, zt], 0.07, 0.07, 1.3, 0.12);
        b.ellipsoid_rot(
            Foliage,
            i as u32,
            [x, yc, zt + 0.22],
            [0.14, 0.14, 0.14],
            super::parts::IDENTITY,
        );
    }
    for (k, x) in [x0 + 0.1, x1 - 0.1].into_iter().enumerate() {
        let y = hd - 0.45;
        b.frustum(Pot, [x, y, base.min(0.05)], 0.15, 0.15, 1.2, 0.3);
        b.ellipsoid_rot(
            Foliage,
            k as u32 + 2,
            [x, y, 0.75],
            [0.28, 0.28, 0.4],
            super::parts::IDENTITY,
        );
    }
}

/// A vertical frame post at (x, y) from `z0` to `z1`.
fn post(b: &mut Builder, x: f64, y: f64, z0: f64, z1: f64) {
    let r = BAR / 2.0 + 0.004;
    b.cuboid(Metal, [x - r, y - r, z0], [x + r, y + r, z1]);
}
