//! Layouts of a few things that were a plain box or post: a headstone (a stone slab with a
//! rounded top and an engraved panel on a plinth), a flagpole (a tall pole with a ball finial
//! and a flag flying from it), a portable toilet (a plastic cabin with a pale roof, a door with
//! a vent and a lock sign, a vent pipe) and a projector (a flat case with a lens, vents and
//! feet). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;
use std::f64::consts::FRAC_PI_2;

/// A headstone: a low plinth, a slab with a rounded top, an engraved panel of lines.
pub fn headstone(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = 0.1 * h;
    b.cuboid(Stone, [-hw, -hd, 0.0], [hw, hd, plinth]);
    let t = 0.55 * hd;
    let sw = 0.85 * hw;
    let arch = sw.min(0.5 * (h - plinth));
    let zs = h - arch;
    b.cuboid(Body, [-sw, -t, plinth], [sw, t, zs]);
    // The rounded top: a half disc of the slab's thickness.
    b.revolved(
        Body,
        0,
        [0.0, -t, zs],
        rot_x(-FRAC_PI_2),
        1.0,
        vec![[0.0, 0.0], [sw, 0.0], [sw, 2.0 * t], [0.0, 2.0 * t]],
    );
    // Engraving: a cross-shaped mark and lines of lettering.
    let yf = t + 0.003;
    let zc = zs - 0.05 * h;
    b.cuboid(
        Interior,
        [-0.03 * sw, t, zc - 0.12 * h],
        [0.03 * sw, yf, zc + 0.02 * h],
    );
    b.cuboid(
        Interior,
        [-0.15 * sw, t, zc - 0.03 * h],
        [0.15 * sw, yf, zc - 0.01 * h],
    );
    for k in 0..4 {
        let z = plinth + 0.15 * h + k as f64 * 0.08 * h;
        let w = if k % 2 == 0 { 0.6 } else { 0.45 };
        b.cuboid(Interior, [-w * sw, t, z], [w * sw, yf, z + 0.02 * h]);
    }
}

/// A flagpole: a base, a tall tapering pole, a ball finial, a flag of two colour bands flying
/// out along x in a few panels that ripple.
pub fn flagpole(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let r = (0.006 * h).clamp(0.02, 0.6 * m);
    // The pole stands at the left end of the box, the flag flies to the right.
    let xp = -hw + m;
    b.frustum(Stone, [xp, 0.0, 0.0], 0.9 * m, 0.9 * m, 0.8, 0.08);
    b.frustum(Metal, [xp, 0.0, 0.08], r, r, 0.6, h - 0.1);
    b.ellipsoid(Handle, [xp, 0.0, h - 0.05], [0.05, 0.05, 0.05]);
    // The flag: panels from the pole outwards, within the size box's width.
    let fl = (hw - xp - 0.02).min(0.25 * h);
    let fh = (0.6 * fl).min(0.15 * h);
    let top = h - 0.12;
    let n = 4;
    for i in 0..n {
        let (x0, x1) = (
            xp + fl * i as f64 / n as f64,
            xp + fl * (i + 1) as f64 / n as f64,
        );
        let y = 0.35 * hd * if i % 2 == 0 { 1.0 } else { -1.0 } * (i as f64 / n as f64);
        for (k, role) in [Upholstery, Cushion].into_iter().enumerate() {
            let z1 = top - k as f64 * 0.5 * fh;
            b.cuboid(role, [x0, y - 0.004, z1 - 0.5 * fh], [x1, y + 0.004, z1]);
        }
    }
}

/// A portable toilet: a plastic cabin on a base, a pale roof with a vent pipe, a door with a
/// handle, a lock sign and a louvred vent at its top.
pub fn portable_toilet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let roof = 0.08 * h;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.06]);
    b.cuboid(
        Body,
        [-0.95 * hw, -0.95 * hd, 0.06],
        [0.95 * hw, 0.95 * hd, h - roof],
    );
    b.frustum(
        Top,
        [0.0, 0.0, h - roof],
        0.95 * hw,
        0.95 * hd,
        0.8,
        roof - 0.05,
    );
    b.cylinder(Metal, [0.6 * hw, -0.6 * hd, h - roof], 0.04, roof);
    // The door on the front.
    let yf = 0.95 * hd;
    b.cuboid(
        Door,
        [-0.75 * hw, yf, 0.1],
        [0.75 * hw, yf + 0.01, h - roof - 0.06],
    );
    b.cuboid(
        Handle,
        [0.55 * hw, yf + 0.01, 0.45 * h],
        [0.62 * hw, yf + 0.04, 0.5 * h],
    );
    b.cuboid(
        Seat,
        [0.4 * hw, yf + 0.01, 0.55 * h],
        [0.65 * hw, yf + 0.015, 0.58 * h],
    );
    for k in 0..4 {
        let z = h - roof - 0.25 + k as f64 * 0.04;
        b.cuboid(
            Interior,
            [-0.5 * hw, yf + 0.01, z],
            [0.5 * hw, yf + 0.015, z + 0.02],
        );
    }
}

/// A projector: a flat case on four small feet, a round lens on its front at one side, a ring
/// round it, vents along the other side, a lit button on top.
pub fn projector(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let feet = 0.1 * h;
    for sx in [-0.8, 0.8] {
        for sy in [-0.8, 0.8] {
            b.cylinder(BlackKeys, [sx * hw, sy * hd, 0.0], 0.012, feet);
        }
    }
    b.cuboid(Body, [-hw, -hd, feet], [hw, 0.9 * hd, h - 0.006]);
    let r = (0.35 * (h - feet)).min(0.25 * hw);
    let (xl, zl) = (0.45 * hw, feet + 0.5 * (h - feet));
    b.revolved(
        Metal,
        0,
        [xl, 0.9 * hd, zl],
        rot_x(-FRAC_PI_2),
        1.0,
        vec![
            [0.0, 0.0],
            [1.3 * r, 0.0],
            [1.2 * r, 0.1 * hd],
            [0.0, 0.1 * hd],
        ],
    );
    b.revolved(
        Glass,
        0,
        [xl, hd - 0.004, zl],
        rot_x(-FRAC_PI_2),
        1.0,
        vec![[0.0, 0.0], [r, 0.0], [0.0, 0.004]],
    );
    for k in 0..5 {
        let x = -0.8 * hw + k as f64 * 0.12 * hw;
        b.cuboid(
            Interior,
            [x, 0.9 * hd, feet + 0.25 * (h - feet)],
            [x + 0.05 * hw, 0.9 * hd + 0.003, h - 0.25 * (h - feet)],
        );
    }
    b.cuboid(
        Light,
        [-0.3 * hw, 0.2 * hd, h - 0.008],
        [-0.2 * hw, 0.3 * hd, h],
    );
}
