//! Layout of the overhead surgical light of an operating room: a plate on the ceiling, a drop
//! tube to a hub, two arms reaching out left and right, each bent down to a wide round lamp
//! head whose lit face looks down, a sterile handle at its centre. It hangs from the top of
//! its size box and stays inside it.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::IDENTITY;

/// An overhead surgical light with two lamp heads.
pub fn surgical_light(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let head_r = (0.45 * hd).min(0.5 * hw).min(0.35);
    let head_h = (0.55 * head_r).min(0.16);
    // The ceiling plate and the drop tube down to the hub.
    b.cylinder(Metal, [0.0, 0.0, h - 0.03], 0.15 * hd.min(hw) + 0.05, 0.03);
    let zh = 0.55 * h;
    b.cylinder(Metal, [0.0, 0.0, zh], 0.04, h - zh - 0.03);
    b.ellipsoid(Frame, [0.0, 0.0, zh], [0.07, 0.07, 0.06]);
    // Two arms: out and a little down from the hub, then down in a yoke to each head.
    let zhead = 0.02 + 0.02 + head_h; // the heads' rims: their handles stand under them
    for (sx, sy) in [(-1.0, 0.25), (1.0, -0.25)] {
        let (x, y) = (sx * (hw - head_r), sy * (hd - head_r));
        let elbow = [0.55 * x, 0.55 * y, zh - 0.05];
        b.polyline(Frame, &[[0.0, 0.0, zh], elbow, [x, y, zh - 0.12]], 0.025);
        b.polyline(
            Frame,
            &[[x, y, zh - 0.12], [x, y, zhead + head_h + 0.02]],
            0.02,
        );
        // The head: a deep dome over a rim, its lit face down with a ring of lamps in it;
        // drawn about its own centre, then set at the arm's end.
        let first = b.parts.len();
        b.revolved(
            Shade,
            0,
            [0.0, 0.0, 0.0],
            IDENTITY,
            1.0,
            vec![
                [0.0, 0.0],
                [head_r, 0.0],
                [head_r, 0.15 * head_h],
                [0.85 * head_r, 0.6 * head_h],
                [0.45 * head_r, head_h],
                [0.0, head_h + 0.02],
            ],
        );
        b.cylinder(Light, [0.0, 0.0, -0.004], 0.85 * head_r, 0.004);
        for k in 0..6 {
            let a = k as f64 / 6.0 * std::f64::consts::TAU;
            let (lx, ly) = (0.55 * head_r * a.cos(), 0.55 * head_r * a.sin());
            b.cylinder(Metal, [lx, ly, -0.008], 0.12 * head_r, 0.004);
        }
        b.translate_from(first, [x, y, zhead]);
        b.rod(Handle, [x, y, zhead - 0.004], [x, y, 0.0], 0.015);
    }
}
