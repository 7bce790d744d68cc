//! Layouts of ovens that are built, not bought: a wood-fired pizza oven (a masonry stand with a
//! log store under a stone hearth, a brick dome on the hearth, an entry vault in front of the dome
//! with an arched dark mouth and the glow of a fire inside, a flue rising from the vault). Reads
//! as a dome from every side, never as a fireplace's box) and a sauna stove (a black steel
//! firebox on short legs with a glass fire door, a cage of rails above it heaped with round grey
//! stones, a flue at the back): a heap of stones on a box, never a kitchen range. The front faces
//! +y.
use super::archetypes::Builder;
use super::fittings::{disc, Y};
use super::materials::Role::*;

/// A wood-fired pizza oven: stand, log store, hearth slab, dome, entry vault with its arched
/// mouth, the fire's glow inside and the flue on the vault.
pub fn pizza_oven(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The stand, the log store cut into its front, and the hearth slab over it.
    let zb = 0.5 * h;
    let slab = (0.04 * h).clamp(0.04, 0.08);
    b.cuboid(
        Stone,
        [-hw + 0.04, -hd + 0.04, 0.0],
        [hw - 0.04, hd - 0.06, zb],
    );
    let (sw, sz) = (0.6 * hw, 0.7 * zb);
    b.cuboid(Interior, [-sw, hd - 0.06, 0.1], [sw, hd - 0.055, 0.1 + sz]);
    for (i, z) in [0.15, 0.15, 0.27].into_iter().enumerate() {
        let x = [-0.3, 0.3, 0.0][i] * sw;
        b.rod(
            Trunk,
            [x, hd - 0.05, 0.1 + z * sz],
            [x, hd - 0.45 * b.d, 0.1 + z * sz],
            0.12 * sz,
        );
    }
    b.cuboid(Top, [-hw, -hd, zb], [hw, hd - 0.02, zb + slab]);
    // The dome over the back of the hearth, as tall as the size box leaves after the flue.
    let zh = zb + slab;
    let rz = (0.85 * (h - zh)).min(0.9 * hw);
    let yd = -0.12 * b.d;
    let rd = (hd + yd - 0.02).min(hw - 0.03);
    b.ellipsoid(Body, [0.0, yd, zh], [hw - 0.03, rd, rz]);
    // The entry vault in front of the dome, and its arched mouth.
    let yv = hd - 0.04;
    let (vw, vh) = (0.38 * hw, 0.5 * rz);
    b.cuboid(Body, [-vw, yd + 0.4 * rd, zh], [vw, yv, zh + vh]);
    let mw = 0.7 * vw;
    let zm = zh + 0.45 * vh;
    b.cuboid(Interior, [-mw, yv, zh], [mw, yv + 0.006, zm]);
    disc(b, Interior, [0.0, yv + 0.003, zm], Y, mw, 0.006);
    // The arch's brick ring round the mouth.
    b.cuboid(Frame, [-vw, yv, zm + mw], [vw, yv + 0.004, zh + vh]);
    // The fire's glow deep in the mouth.
    b.ellipsoid(
        Light,
        [0.0, yv - 0.05, zh + 0.03],
        [0.5 * mw, 0.04, 0.25 * vh],
    );
    // The flue on the vault, up to the top of the size box.
    let rf = (0.12 * hw).max(0.05);
    b.cylinder(
        Metal,
        [0.0, yv - 0.5 * (yv - yd - 0.4 * rd), zh + vh],
        rf,
        h - zh - vh,
    );
}

/// A sauna stove: a black steel firebox on short legs with a small glowing fire door, and above
/// it an open cage of rails heaped with rounded stones, a flue pipe rising at the back.
pub fn sauna_stove(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let legs = (0.08 * h).clamp(0.04, 0.1);
    let zb = 0.55 * h;
    b.legs(Metal, 0.02, 0.04, 0.0, legs);
    b.cuboid(
        Body,
        [-hw + 0.02, -hd + 0.04, legs],
        [hw - 0.02, hd - 0.02, zb],
    );
    // The fire door with its glow.
    let (z0, z1) = (legs + 0.2 * (zb - legs), legs + 0.7 * (zb - legs));
    b.cuboid(
        Door,
        [-0.45 * hw, hd - 0.02, z0],
        [0.45 * hw, hd - 0.005, z1],
    );
    b.cuboid(
        Light,
        [-0.35 * hw, hd - 0.006, z0 + 0.03],
        [0.35 * hw, hd - 0.002, z1 - 0.03],
    );
    // The cage: corner posts and two rails round it, the stones heaped inside and over it.
    let top = h - 0.02;
    let (cx, cy) = (hw - 0.03, hd - 0.03);
    for (x, y) in [(-cx, -cy), (cx, -cy), (cx, cy), (-cx, cy)] {
        b.rod(Metal, [x, y, zb], [x, y, 0.85 * top], 0.01);
    }
    for z in [zb + 0.35 * (top - zb), 0.85 * top] {
        b.polyline(
            Metal,
            &[
                [-cx, -cy, z],
                [cx, -cy, z],
                [cx, cy, z],
                [-cx, cy, z],
                [-cx, -cy, z],
            ],
            0.008,
        );
    }
    let stone = (0.2 * hw.min(hd)).clamp(0.035, 0.07);
    let (nx, ny) = (
        ((2.0 * cx) / (1.7 * stone)).floor().max(2.0) as usize,
        ((2.0 * cy) / (1.7 * stone)).floor().max(2.0) as usize,
    );
    let layers = (((top - zb) / (1.5 * stone)).floor() as usize).clamp(2, 6);
    for l in 0..layers {
        // Each layer a little narrower, so the heap crowns above the cage.
        let shrink = 1.0 - 0.12 * l as f64;
        for i in 0..nx {
            for j in 0..ny {
                let k = (l * nx * ny + i * ny + j) as u32;
                let jitter = 0.25 * stone * (((k * 37 % 11) as f64 / 11.0) - 0.5);
                let x = shrink
                    * (-cx + stone + (i as f64 + 0.5) / nx as f64 * (2.0 * cx - 2.0 * stone));
                let y = shrink
                    * (-cy + stone + (j as f64 + 0.5) / ny as f64 * (2.0 * cy - 2.0 * stone));
                let z = zb + stone + l as f64 * 1.4 * stone + jitter;
                if z + stone > top {
                    continue;
                }
                b.ellipsoid_rot(
                    Stone,
                    k % 3,
                    [x + jitter, y - jitter, z],
                    [1.1 * stone, stone, 0.8 * stone],
                    super::parts::rot_z(0.7 * k as f64),
                );
            }
        }
    }
    // The flue at the back.
    let r = (0.12 * hw).clamp(0.04, 0.07);
    b.rod(Metal, [0.0, -hd + r, zb], [0.0, -hd + r, h], r);
}

/// A wood stove: a squat black cast-iron firebox on four short legs, a glass door glowing with
/// the fire, a top plate proud of the body, and a flue pipe rising from the top to the top of
/// the size box (the stovepipe to the ceiling, which tells it from a kitchen range or a safe).
pub fn wood_stove(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The body is a stove's height whatever the pipe above it.
    let body = (0.75 * b.w).clamp(0.45, 0.85).min(0.6 * h);
    let legs = 0.18 * body;
    b.legs(Metal, 0.025, 0.06, 0.0, legs + 0.01);
    b.cuboid(
        Body,
        [-hw + 0.04, -hd + 0.04, legs],
        [hw - 0.04, hd - 0.06, body],
    );
    // A plinth rail and the top plate, both a little proud of the body.
    b.cuboid(
        Metal,
        [-hw + 0.02, -hd + 0.02, legs],
        [hw - 0.02, hd - 0.04, legs + 0.03],
    );
    b.cuboid(Top, [-hw, -hd, body], [hw, hd - 0.02, body + 0.03]);
    // The fire door: a frame, the glass lit by the fire, a handle at its side.
    let (z0, z1) = (legs + 0.18 * (body - legs), legs + 0.82 * (body - legs));
    let (dx, y) = (0.72 * hw, hd - 0.06);
    b.cuboid(Door, [-dx, y, z0], [dx, y + 0.03, z1]);
    b.cuboid(
        Light,
        [-0.8 * dx, y + 0.03, z0 + 0.04],
        [0.8 * dx, y + 0.035, z1 - 0.04],
    );
    b.ellipsoid(
        Interior,
        [0.0, y + 0.036, z0 + 0.07],
        [0.6 * dx, 0.004, 0.05],
    );
    b.rod(
        Metal,
        [dx + 0.01, y + 0.05, z0 + 0.1],
        [dx + 0.01, y + 0.05, z1 - 0.1],
        0.012,
    );
    // The stovepipe from the top plate up, with a collar where it leaves the stove.
    let r = (0.16 * hw.min(hd)).clamp(0.06, 0.09);
    let py = -0.15 * b.d;
    b.cylinder(Metal, [0.0, py, body + 0.03], 1.3 * r, 0.05);
    b.cylinder(Metal, [0.0, py, body + 0.03], r, h - body - 0.03);
}
