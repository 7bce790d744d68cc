//! Layouts of figures that are not a person standing: a scarecrow (a cross of poles dressed in
//! a straw-stuffed shirt, straw at its cuffs and collar, a sacking head under a wide hat, the
//! pole bare below the shirt) and a statue (a figure on a moulded plinth, all of one stone).
//! Each faces +y and stays inside the size box.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A scarecrow: an upright pole with a crossbar at the shoulders, a shirt over them (a body
/// and two sleeves along the bar; cloth, so "a straw scarecrow" keeps its shirt's colour),
/// straw tufts out of the cuffs, the collar and the hem, a sacking head with two dark eyes, a
/// wide-brimmed hat.
pub fn scarecrow(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pr = (0.02 * h).clamp(0.02, 0.045);
    // The head's radius; the shoulders (the crossbar) leave room over them for the head and
    // its hat to reach the top.
    let hr = (0.075 * h).min(0.8 * hd).min(0.6 * hw);
    let zs = (h - 0.05 - 2.4 * hr).min(0.8 * h);
    b.cylinder(Trunk, [0.0, 0.0, 0.0], pr, zs + 0.05 + hr);
    b.rod(Trunk, [-hw, 0.0, zs], [hw, 0.0, zs], 0.8 * pr);
    // The shirt: a stuffed body hanging from the bar, its sleeves along it.
    let tw = (0.32 * hw).max(0.1);
    let td = (0.7 * hd).min(tw);
    let hem = 0.42 * h;
    b.ellipsoid(
        Duvet,
        [0.0, 0.0, 0.5 * (hem + zs)],
        [tw, td, 0.5 * (zs - hem) + 0.03],
    );
    let sr = (0.55 * td).min(0.07);
    let cuff = hw - 0.1 * hw;
    for sx in [-1.0, 1.0] {
        b.rod(
            Duvet,
            [sx * 0.6 * tw, 0.0, zs - 0.02],
            [sx * cuff, 0.0, zs],
            sr,
        );
        // Straw out of the cuff, hanging and splaying.
        for k in 0..4 {
            let dz = -0.04 * k as f64;
            b.rod(
                Cushion,
                [sx * cuff, 0.0, zs],
                [sx * (hw - 0.01), 0.02 * (k as f64 - 1.5), zs + dz - 0.03],
                0.012,
            );
        }
    }
    // Straw from the hem and round the collar.
    for k in 0..7 {
        let x = (k as f64 / 6.0 - 0.5) * 1.4 * tw;
        b.rod(
            Cushion,
            [x, 0.0, hem + 0.03],
            [1.1 * x, 0.3 * td, hem - 0.08],
            0.012,
        );
    }
    b.frustum(
        Cushion,
        [0.0, 0.0, zs + 0.01],
        0.5 * tw,
        0.5 * td,
        0.6,
        0.05,
    );
    // The head: a sack stuffed round, tied at the neck, two eyes; a hat with a wide brim.
    let zh = zs + 0.05 + hr;
    b.ellipsoid(Canvas, [0.0, 0.0, zh], [hr, 0.9 * hr, 1.05 * hr]);
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Interior,
            [sx * 0.35 * hr, 0.85 * hr, zh + 0.15 * hr],
            [0.14 * hr, 0.05 * hr, 0.14 * hr],
        );
    }
    let brim = (2.0 * hr).min(hw).min(hd);
    let zb = zh + 0.6 * hr;
    b.frustum(Top, [0.0, 0.0, zb], brim, brim, 1.0, 0.015);
    b.frustum(
        Top,
        [0.0, 0.0, zb],
        0.8 * hr,
        0.8 * hr,
        0.8,
        (h - zb).clamp(0.02, 0.8 * hr),
    );
}

/// A statue: a plinth with a moulded base and cap, and on it a standing figure with one arm
/// raised, every part in the stone's colour.
pub fn statue(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zp = 0.22 * h; // the plinth's top
    b.cuboid(Top, [-hw, -hd, 0.0], [hw, hd, 0.04 * h]);
    b.cuboid(
        Body,
        [-0.85 * hw, -0.85 * hd, 0.0],
        [0.85 * hw, 0.85 * hd, zp - 0.03 * h],
    );
    b.cuboid(
        Top,
        [-0.95 * hw, -0.95 * hd, zp - 0.03 * h],
        [0.95 * hw, 0.95 * hd, zp],
    );
    // The figure, in proportion to the height left: legs, a draped body, a head.
    let fh = h - zp;
    let (fw, fd) = (0.6 * hw, 0.6 * hd);
    let lr = (0.07 * fh).min(0.35 * fw);
    for sx in [-1.0, 1.0] {
        b.frustum(Body, [sx * 0.4 * fw, 0.0, zp], lr, lr, 0.8, 0.47 * fh);
    }
    // A robe: a skirt widening to the knees, a torso over it.
    b.frustum(
        Body,
        [0.0, 0.0, zp + 0.2 * fh],
        0.95 * fw,
        fd.min(0.95 * fw),
        0.75,
        0.35 * fh,
    );
    b.ellipsoid(
        Body,
        [0.0, 0.0, zp + 0.66 * fh],
        [0.75 * fw, fd.min(0.7 * fw), 0.2 * fh],
    );
    let ar = 0.7 * lr;
    let shoulder = zp + 0.78 * fh;
    // One arm down at the side, the other raised overhead.
    b.rod(
        Body,
        [-0.7 * fw, 0.0, shoulder],
        [-0.95 * fw, 0.1 * fd, zp + 0.5 * fh],
        ar,
    );
    b.polyline(
        Body,
        &[
            [0.7 * fw, 0.0, shoulder],
            [0.95 * fw, 0.0, shoulder + 0.1 * fh],
            [0.9 * fw, 0.0, h - 0.02],
        ],
        ar,
    );
    let hr = (0.075 * fh).min(0.5 * fw);
    b.rod(
        Body,
        [0.0, 0.0, shoulder],
        [0.0, 0.0, shoulder + 0.06 * fh],
        0.4 * lr + 0.02,
    );
    b.ellipsoid(
        Body,
        [0.0, 0.0, shoulder + 0.06 * fh + hr],
        [hr, hr.min(fd), 1.15 * hr],
    );
}
