//! Layout of an anatomy skeleton model hanging on its stand: thin pale bones (skull, spine,
//! rib cage, pelvis, arms and legs) hung from a pole behind the spine on a castored base.
//! The front faces +y, z up, the bottom face's centre at the origin.
use super::archetypes::Builder;
use super::materials::Role::*;
use std::f64::consts::TAU;

/// A skeleton model on a stand, standing upright with its arms at its sides.
pub fn skeleton(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    // The stand: five feet on castors spread over the whole footprint round a hub behind the
    // spine, a pole up from the hub to a hook under the skull.
    let yp = -0.75 * hd;
    for k in 0..5 {
        let a = k as f64 * TAU / 5.0 + TAU / 4.0;
        let foot = [0.95 * hw * a.cos(), 0.95 * hd * a.sin(), 0.03];
        b.rod(Metal, [0.0, yp, 0.05], foot, 0.014);
        b.ellipsoid(BlackKeys, [foot[0], foot[1], 0.025], [0.025, 0.025, 0.025]);
    }
    b.frustum(Metal, [0.0, yp, 0.0], 0.05, 0.05, 0.6, 0.08);
    b.cylinder(Metal, [0.0, yp, 0.02], 0.012, 0.9 * h);
    b.rod(
        Metal,
        [0.0, yp, 0.92 * h],
        [0.0, -0.05 * hd, 0.92 * h],
        0.008,
    );
    let bone = (0.009 * h).clamp(0.005, 0.016);
    let joint = [1.6 * bone; 3];
    // Skull and jaw with dark eye sockets.
    let sr = (0.055 * h).min(0.8 * m);
    let zs = h - 1.15 * sr;
    b.ellipsoid(Body, [0.0, 0.0, zs], [0.85 * sr, sr, 1.1 * sr]);
    b.ellipsoid(
        Body,
        [0.0, 0.35 * sr, zs - 0.95 * sr],
        [0.6 * sr, 0.55 * sr, 0.3 * sr],
    );
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Interior,
            [sx * 0.35 * sr, 0.82 * sr, zs + 0.05 * sr],
            [0.2 * sr, 0.12 * sr, 0.18 * sr],
        );
    }
    b.ellipsoid(
        Interior,
        [0.0, 0.95 * sr, zs - 0.35 * sr],
        [0.08 * sr, 0.06 * sr, 0.1 * sr],
    );
    // Spine: vertebrae from the neck to the pelvis.
    let (z_neck, z_hip) = (zs - 1.3 * sr, 0.52 * h);
    let n = 14;
    for k in 0..=n {
        let z = z_hip + (z_neck - z_hip) * k as f64 / n as f64;
        b.ellipsoid(
            Body,
            [0.0, -0.25 * m, z],
            [1.5 * bone, 1.5 * bone, 1.0 * bone],
        );
    }
    // Rib cage: ribs curving round from the spine, widest in the middle.
    let (zr0, zr1) = (0.62 * h, z_neck - 0.04 * h);
    let ribs = 7;
    let cage = 0.55 * hw;
    for k in 0..ribs {
        let f = k as f64 / (ribs - 1) as f64;
        let z = zr0 + (zr1 - zr0) * f;
        let wr = cage * (0.75 + 0.35 * (std::f64::consts::PI * (0.3 + 0.6 * f)).sin() - 0.25 * f);
        let dr = 0.55 * m;
        let pts: Vec<[f64; 3]> = (0..=10)
            .map(|i| {
                let a = -TAU / 4.0 + i as f64 / 10.0 * TAU * 0.92 - TAU * 0.21;
                [
                    wr * a.cos(),
                    -0.25 * m + dr * (1.0 + a.sin()) * 0.9,
                    z - 0.02 * h * (1.0 + a.sin()),
                ]
            })
            .collect();
        b.polyline(Body, &pts, 0.7 * bone);
    }
    b.cuboid(Body, [-0.04 * hw, 0.7 * m, zr0], [0.04 * hw, 0.75 * m, zr1]);
    // Shoulders, arms hanging at the sides, hands.
    let zsh = z_neck - 0.02 * h;
    let xs = 0.8 * hw;
    b.rod(Body, [-xs, 0.1 * m, zsh], [xs, 0.1 * m, zsh], bone);
    for sx in [-1.0, 1.0] {
        let sh = [sx * xs, 0.0, zsh];
        let el = [sx * 0.88 * hw, 0.0, 0.6 * h];
        let wr = [sx * 0.85 * hw, 0.15 * m, 0.45 * h];
        b.ellipsoid(Body, sh, joint);
        b.rod(Body, sh, el, bone);
        b.ellipsoid(Body, el, joint);
        b.rod(Body, el, wr, 0.8 * bone);
        b.ellipsoid(
            Body,
            [wr[0], wr[1], wr[2] - 0.04 * h],
            [0.04 * hw, 0.2 * m, 0.04 * h],
        );
    }
    // Pelvis, legs and feet.
    b.ellipsoid(
        Body,
        [0.0, -0.05 * m, z_hip],
        [0.42 * hw, 0.4 * m, 0.05 * h],
    );
    for sx in [-1.0, 1.0] {
        let hip = [sx * 0.25 * hw, 0.0, z_hip - 0.02 * h];
        let knee = [sx * 0.22 * hw, 0.05 * m, 0.28 * h];
        let ankle = [sx * 0.2 * hw, 0.0, 0.06 * h];
        b.rod(Body, hip, knee, 1.3 * bone);
        b.ellipsoid(Body, knee, [2.0 * bone; 3]);
        b.rod(Body, knee, ankle, 1.1 * bone);
        b.ellipsoid(
            Body,
            [ankle[0], ankle[1] + 0.35 * m, 0.05 * h],
            [0.05 * hw, 0.4 * m, 0.012 * h],
        );
    }
}
