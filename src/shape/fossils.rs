//! A dinosaur skeleton on its museum stand: a plinth, steel posts under the hips and chest, a
//! spine of vertebrae from the tail's tip over the hips to the skull, ribs hanging from the
//! back, a pelvis, two long hind legs with knees and toes, small arms, and a skull with an eye
//! socket and a jaw. It stands along the longer side of its footprint, skull towards +x (+y when
//! deeper than wide). Bones only: no body.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{rot_z, V3};

/// Draws the skeleton at the builder's size.
pub fn dinosaur_skeleton(b: &mut Builder) {
    let first = b.parts.len();
    let along_y = b.d > b.w;
    let (w, d) = (b.w, b.d);
    if along_y {
        (b.w, b.d) = (d, w);
    }
    draw_along_x(b);
    if along_y {
        (b.w, b.d) = (w, d);
        b.turn_from(first, rot_z(std::f64::consts::FRAC_PI_2));
    }
}

fn lerp(a: V3, b: V3, t: f64) -> V3 {
    [0, 1, 2].map(|i| a[i] + t * (b[i] - a[i]))
}

fn draw_along_x(b: &mut Builder) {
    let (hl, ha, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = 0.08 * h;
    b.cuboid(Stone, [-hl, -0.8 * ha, 0.0], [hl, 0.8 * ha, plinth]);
    // The spine: tail tip, hips, shoulders, neck, the skull's back.
    let spine: [V3; 6] = [
        [-0.98 * hl, 0.0, 0.3 * h],
        [-0.6 * hl, 0.0, 0.5 * h],
        [-0.15 * hl, 0.0, 0.64 * h],
        [0.3 * hl, 0.0, 0.62 * h],
        [0.5 * hl, 0.0, 0.72 * h],
        [0.62 * hl, 0.0, 0.84 * h],
    ];
    let bone = 0.012 * h;
    b.polyline(Body, &spine, bone);
    for w in spine.windows(2) {
        for k in 0..6 {
            let p = lerp(w[0], w[1], k as f64 / 6.0);
            let r = 0.02 * h * (0.6 + 0.4 * (p[2] / h));
            b.ellipsoid(Body, p, [r, r, 1.4 * r]);
            // A spine's process standing up from each vertebra.
            b.rod(Body, p, [p[0], 0.0, p[2] + 2.5 * r], 0.3 * r);
        }
    }
    // Ribs from the hips to the shoulders, longest in the middle, curving out and down.
    let (hip, shoulder) = (spine[2], spine[3]);
    for k in 0..8 {
        let t = (k as f64 + 0.5) / 8.0;
        let s = lerp(hip, shoulder, t);
        let len = 0.28 * h * (0.6 + 0.4 * (std::f64::consts::PI * t).sin());
        let out = (0.7 * ha).min(0.5 * len);
        for sy in [-1.0, 1.0] {
            let pts = [
                s,
                [s[0], sy * 0.8 * out, s[2] - 0.15 * len],
                [s[0] + 0.03 * hl, sy * out, s[2] - 0.55 * len],
                [s[0] + 0.06 * hl, sy * 0.55 * out, s[2] - len],
            ];
            b.polyline(Body, &pts, 0.6 * bone);
        }
    }
    // The pelvis and two hind legs: thigh, shin, foot, toes.
    b.ellipsoid(Body, hip, [0.12 * hl, 0.3 * ha, 0.07 * h]);
    for sy in [-1.0, 1.0] {
        let y = sy * 0.3 * ha;
        let leg = [
            [hip[0], y, hip[2] - 0.02 * h],
            [hip[0] + 0.12 * hl, y, 0.36 * h],
            [hip[0] - 0.02 * hl, y, 0.16 * h],
            [hip[0] + 0.1 * hl, y, plinth + 0.02 * h],
        ];
        b.polyline(Body, &leg, 2.0 * bone);
        for p in &leg[1..3] {
            b.ellipsoid(Body, *p, [3.0 * bone, 3.0 * bone, 3.0 * bone]);
        }
        for dy in [-1.0, 0.0, 1.0] {
            let toe = [leg[3][0] + 0.12 * hl, y + dy * 0.12 * ha, plinth + 0.01 * h];
            b.rod(Body, leg[3], toe, bone);
        }
        // A small arm hanging from the chest.
        let sh = [shoulder[0], sy * 0.25 * ha, shoulder[2] - 0.1 * h];
        let arm = [
            sh,
            [sh[0] + 0.05 * hl, sy * 0.3 * ha, sh[2] - 0.08 * h],
            [sh[0] + 0.1 * hl, sy * 0.3 * ha, sh[2] - 0.06 * h],
        ];
        b.polyline(Body, &arm, bone);
    }
    // The skull: a long cranium, an eye socket each side and an open jaw below.
    let top = spine[5];
    let sc = [top[0] + 0.14 * hl, 0.0, top[2] + 0.02 * h];
    let (sl, sw, sh) = (0.2 * hl, (0.16 * ha).min(0.1 * h), 0.08 * h);
    b.ellipsoid(Body, sc, [sl, sw, sh]);
    for sy in [-1.0, 1.0] {
        let e = 0.35 * sh;
        b.ellipsoid(
            Interior,
            [sc[0] - 0.3 * sl, sy * 0.85 * sw, sc[2] + 0.2 * sh],
            [e, 0.3 * e, e],
        );
    }
    let jaw0 = [sc[0] - 0.6 * sl, 0.0, sc[2] - 0.6 * sh];
    let jaw1 = [sc[0] + 0.9 * sl, 0.0, sc[2] - 1.6 * sh];
    b.rod(Body, jaw0, jaw1, 0.35 * sh);
    // Steel posts from the plinth under the hips and the chest.
    for p in [hip, lerp(shoulder, spine[4], 0.3)] {
        b.rod(
            Metal,
            [p[0], 0.0, plinth],
            [p[0], 0.0, p[2] - 0.03 * h],
            0.01 * h,
        );
    }
    b.cylinder(
        Metal,
        [spine[1][0], 0.0, plinth],
        0.008 * h,
        spine[1][2] - plinth,
    );
}
