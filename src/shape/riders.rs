//! A playground spring rider: a moulded horse (the animal table's `horse` row, short-legged and
//! stocky) on a coil spring set in a base plate, with a handle bar through its neck and foot
//! pegs at its sides. It stands along the longer side of its footprint, head towards +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{rot_z, V3};

/// Draws the rider at the builder's size.
pub fn spring_rider(b: &mut Builder) {
    let first = b.parts.len();
    let along_x = b.w > b.d;
    let (w, d) = (b.w, b.d);
    if along_x {
        (b.w, b.d) = (d, w);
    }
    draw_along_y(b);
    if along_x {
        (b.w, b.d) = (w, d);
        b.turn_from(first, rot_z(-std::f64::consts::FRAC_PI_2));
    }
}

fn draw_along_y(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plate = 0.03 * h;
    b.frustum(Frame, [0.0, 0.0, 0.0], 0.95 * hw, 0.5 * hd, 0.9, plate);
    // The coil: five turns from the plate up to the horse's belly.
    let (z0, z1) = (plate, 0.4 * h);
    let rs = 0.5 * hw.min(0.5 * hd);
    let wire = 0.12 * rs;
    let n = 5 * 16;
    let coil: Vec<V3> = (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let a = t * 5.0 * std::f64::consts::TAU;
            [
                rs * a.cos(),
                rs * a.sin(),
                z0 + wire + t * (z1 - z0 - 2.0 * wire),
            ]
        })
        .collect();
    b.polyline(Metal, &coil, wire);
    b.cylinder(Metal, [0.0, 0.0, z1 - wire], 1.2 * rs, 2.0 * wire);
    // The horse, moulded stocky on short legs that meet the spring's top.
    let mut horse = super::animals::animal_of("horse")
        .cloned()
        .unwrap_or_else(|| super::animals::default_animal().clone());
    horse.legs = 0.12;
    horse.body = 0.5;
    horse.girth = 1.0;
    horse.thick = 0.3;
    let first = b.parts.len();
    let body_h = h - z1 + 0.05 * h;
    b.h = body_h;
    super::beasts::draw(b, &horse);
    b.h = h;
    b.translate_from(first, [0.0, 0.0, z1 - 0.05 * h]);
    // A handle bar through the neck and foot pegs below the saddle.
    let r = 0.05 * hw;
    let (hy, hz) = (0.45 * hd, 0.88 * h);
    b.rod(Handle, [-0.95 * hw, hy, hz], [0.95 * hw, hy, hz], r);
    let (fy, fz) = (0.05 * hd, 0.5 * h);
    b.rod(Handle, [-0.95 * hw, fy, fz], [0.95 * hw, fy, fz], 1.3 * r);
}
