//! Layouts of ovens that are built, not bought: a wood-fired pizza oven (a masonry stand with a
//! log store under a stone hearth, a brick dome on the hearth, an entry vault in front of the dome
//! with an arched dark mouth and the glow of a fire inside, a flue rising from the vault). Reads
//! as a dome from every side, never as a fireplace's box. The front faces +y.
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
