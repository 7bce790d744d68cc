//! Layouts of things that hang: from the ceiling (a chandelier, a pendant light, a flush
//! ceiling light, a ceiling fan), their top face against the ceiling, and on a wall: a cloth
//! banner on a rod, a hanging scroll between two rollers and a string of lights in swags. The front faces +y, z up, the bottom face's centre at the origin.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{mat_mul, rot_x, rot_y, rot_z, IDENTITY};
use std::f64::consts::TAU;

/// A small round plate against the ceiling at the top (where a rod or cord is fixed).
fn canopy(b: &mut Builder, r: f64) {
    let h = b.h;
    b.frustum(Metal, [0.0, 0.0, h - 0.03], 0.7 * r, 0.7 * r, 1.4, 0.03);
}

/// A chandelier: a rod from a ceiling plate down to a turned stem ending in a ball finial, a
/// ring of curved arms round the stem, each carrying a candle sleeve with a lit bulb, and
/// crystal drops hanging from the arms.
pub fn chandelier(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    canopy(b, 0.16 * m);
    let zs = 0.55 * h;
    b.cylinder(Metal, [0.0, 0.0, zs], 0.012, h - zs);
    // The stem: a vase between two knops and a ball finial under the arms.
    b.ellipsoid(Metal, [0.0, 0.0, zs], [0.06 * m, 0.06 * m, 0.04 * h]);
    b.frustum(
        Metal,
        [0.0, 0.0, 0.25 * h],
        0.05 * m,
        0.05 * m,
        1.6,
        0.3 * h,
    );
    b.ellipsoid(Metal, [0.0, 0.0, 0.2 * h], [0.16 * m, 0.16 * m, 0.06 * h]);
    b.ellipsoid(Metal, [0.0, 0.0, 0.07 * h], [0.06 * m, 0.06 * m, 0.07 * h]);
    let n = 6;
    let r = 0.78 * m;
    let zc = 0.3 * h;
    for k in 0..n {
        let a = k as f64 * TAU / n as f64;
        let (c, s) = (a.cos(), a.sin());
        let p = |rr: f64, z: f64| [rr * c, rr * s, z];
        // An arm: out and down from the hub, then up to its cup.
        b.polyline(
            Metal,
            &[
                p(0.12 * m, 0.2 * h),
                p(0.45 * m, 0.14 * h),
                p(0.7 * m, 0.18 * h),
                p(r, zc - 0.02),
            ],
            0.012,
        );
        b.frustum(Metal, p(r, zc - 0.03), 0.06 * m, 0.06 * m, 1.3, 0.03);
        b.cylinder(Body, p(r, zc), 0.025, 0.12 * h);
        b.ellipsoid(Light, p(r, zc + 0.12 * h + 0.03), [0.025, 0.025, 0.04]);
        // A crystal drop under the arm's bend.
        b.cylinder(Glass, p(0.58 * m, 0.08 * h), 0.003, 0.07 * h);
        b.ellipsoid(Glass, p(0.58 * m, 0.07 * h), [0.018, 0.018, 0.03]);
    }
}

/// A pendant light: a cord from a ceiling plate down to a cone shade, its glowing bulb showing
/// under the rim.
pub fn pendant_light(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    canopy(b, 0.35 * m);
    let sh = (0.4 * h).min(1.1 * m);
    b.cylinder(BlackKeys, [0.0, 0.0, sh], 0.006, h - sh);
    b.cylinder(Metal, [0.0, 0.0, sh - 0.01], 0.15 * m, 0.05);
    b.frustum(Shade, [0.0, 0.0, 0.02], m, m, 0.22, sh - 0.02);
    b.cylinder(Light, [0.0, 0.0, 0.017], 0.9 * m, 0.004);
    b.ellipsoid(Light, [0.0, 0.0, 0.03], [0.3 * m, 0.3 * m, 0.03]);
}

/// A flush ceiling light: a metal ring against the ceiling and a glowing opal dome under it.
pub fn ceiling_light(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ring = (0.2 * h).min(0.03);
    b.frustum(Metal, [0.0, 0.0, h - ring], hw, hd, 1.0, ring);
    let rz = h - ring;
    let n = 12;
    let mut profile: Vec<[f64; 2]> = (0..=n)
        .map(|i| {
            let phi = i as f64 / n as f64 * TAU / 4.0;
            [0.94 * hw * phi.sin(), -rz * phi.cos()]
        })
        .collect();
    profile.push([0.0, 0.0]);
    b.revolved(Light, 0, [0.0, 0.0, rz], IDENTITY, hd / hw, profile);
}

/// A ceiling fan: a down rod from a ceiling plate to a motor housing, five pitched blades on
/// arms round it, and a light bowl underneath.
pub fn ceiling_fan(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    canopy(b, 0.12 * m);
    let zm = (0.3 * h).max(0.2).min(h - 0.05);
    b.cylinder(Metal, [0.0, 0.0, zm], 0.018, h - zm);
    b.frustum(Body, [0.0, 0.0, zm - 0.06], 0.17 * m, 0.17 * m, 0.75, 0.12);
    b.frustum(Body, [0.0, 0.0, zm - 0.1], 0.12 * m, 0.12 * m, 1.4, 0.04);
    let blade_w = 0.2 * m;
    let (r0, r1) = (0.22 * m, 0.98 * m);
    let zb = zm - 0.03;
    for k in 0..5 {
        let a = k as f64 * TAU / 5.0;
        let (c, s) = (a.cos(), a.sin());
        let rot = mat_mul(&rot_z(a), &rot_x(0.2));
        let mid = 0.5 * (r0 + r1);
        b.rod(
            Metal,
            [0.1 * m * c, 0.1 * m * s, zb],
            [(r0 + 0.05) * c, (r0 + 0.05) * s, zb],
            0.012,
        );
        b.slab(
            Frame,
            [mid * c, mid * s, zb],
            [0.5 * (r1 - r0), 0.5 * blade_w, 0.006],
            rot,
        );
    }
    // The light kit: a frosted bowl under the housing.
    let lz = (zm - 0.14).max(0.03);
    b.cylinder(Metal, [0.0, 0.0, lz], 0.06 * m, 0.04);
    b.ellipsoid(Light, [0.0, 0.0, lz], [0.12 * m, 0.12 * m, lz.min(0.06)]);
}

/// A cloth banner hung against the wall: a rod with knobbed ends hung by a cord, the cloth
/// falling from it to a pointed foot, a round emblem on its face. No frame.
pub fn banner(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = -hd + 0.012;
    let zr = h - 0.12 * h.min(1.0);
    b.rod(Frame, [-hw, y, zr], [hw, y, zr], 0.012);
    for sx in [-1.0, 1.0] {
        b.ellipsoid(Metal, [sx * hw, y, zr], [0.022, 0.022, 0.022]);
        b.rod(
            BlackKeys,
            [sx * 0.8 * hw, y - 0.004, zr],
            [0.0, y - 0.004, h - 0.005],
            0.003,
        );
    }
    // The cloth: a straight drop, then a point as deep as half its width (a square turned 45°
    // behind the straight part's foot) where the banner is tall enough for it.
    let cw = 0.88 * hw;
    let t = 0.004;
    let pointed = cw < 0.3 * h;
    let zf = if pointed { 0.02 + cw } else { 0.02 };
    b.cuboid(Canvas, [-cw, y - t, zf], [cw, y + t, zr - 0.01]);
    if pointed {
        let s = cw / std::f64::consts::SQRT_2;
        b.slab(Canvas, [0.0, y, zf], [s, t, s], rot_y(TAU / 8.0));
    }
    // Edging stripes down the sides and an emblem on the face.
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Cushion,
            [sx * 0.86 * cw, y + t, zf],
            [sx * 0.94 * cw, y + t + 0.002, zr - 0.01],
        );
    }
    let er = (0.45 * cw).min(0.18 * (zr - zf));
    let ez = zf + 0.6 * (zr - zf);
    b.revolved(
        Cushion,
        0,
        [0.0, y + t, ez],
        rot_x(-TAU / 4.0),
        1.0,
        vec![[0.0, 0.0], [er, 0.0], [er, 0.003], [0.0, 0.003]],
    );
}

/// A poster: a paper sheet flat on the wall with no frame, printed edge to edge: a colour
/// field, a large round motif across it, a pale title band near the top and lines of small print
/// at the foot, and a pin at each top corner.
pub fn poster(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = -hd + 0.002;
    b.cuboid(Canvas, [-hw, -hd, 0.0], [hw, y, h]);
    let m = (0.05 * b.w.min(h)).clamp(0.01, 0.04);
    let (x0, x1, z0, z1) = (-hw + m, hw - m, m, h - m);
    let (pw, ph) = (x1 - x0, z1 - z0);
    // The printed field, then the motif over it, nearer the viewer: a disc (variant 0), a
    // bold diagonal band, two offset blocks, or a low disc over stripes (variants 1-3), the
    // later ones in colours of their own.
    let v = b.variant;
    let (field, motif) = if v == 0 {
        ((Body, 0), (Cushion, 0))
    } else {
        ((Books, 2 * v + 1), (Books, 3 * v + 4))
    };
    b.cuboid_v(
        field.0,
        field.1,
        [x0, y, z0 + 0.18 * ph],
        [x1, y + 0.002, z1],
    );
    let r = 0.32 * pw.min(ph);
    match v {
        1 => {
            let a = (ph / pw).atan();
            b.slab_v(
                motif.0,
                motif.1,
                [0.0, y + 0.004, z0 + 0.55 * ph],
                [
                    0.55 * (pw * pw + ph * ph).sqrt().min(1.6 * ph),
                    0.001,
                    0.09 * ph,
                ],
                rot_y(-a),
            );
        }
        2 => {
            for (k, (u0, v0, u1, v1)) in [(0.1, 0.55, 0.6, 0.8), (0.4, 0.3, 0.9, 0.58)]
                .iter()
                .enumerate()
            {
                b.cuboid_v(
                    motif.0,
                    motif.1 + 2 * k as u32,
                    [x0 + u0 * pw, y + 0.004 + 0.001 * k as f64, z0 + v0 * ph],
                    [x0 + u1 * pw, y + 0.005 + 0.001 * k as f64, z0 + v1 * ph],
                );
            }
        }
        3 => {
            for k in 0..4 {
                let z = z0 + (0.22 + 0.07 * k as f64) * ph;
                b.cuboid_v(
                    motif.0,
                    motif.1 + k,
                    [x0, y + 0.003, z],
                    [x1, y + 0.004, z + 0.035 * ph],
                );
            }
            b.ellipsoid_rot(
                Cushion,
                0,
                [0.0, y + 0.005, z0 + 0.62 * ph],
                [0.8 * r, 0.001, 0.8 * r],
                IDENTITY,
            );
        }
        _ => b.ellipsoid(motif.0, [0.0, y + 0.004, z0 + 0.52 * ph], [r, 0.001, r]),
    }
    b.cuboid(
        Canvas,
        [x0 + 0.1 * pw, y + 0.004, z0 + 0.84 * ph],
        [x1 - 0.1 * pw, y + 0.006, z0 + 0.93 * ph],
    );
    for k in 0..3 {
        let z = z0 + (0.04 + 0.045 * k as f64) * ph;
        let x_end = x1 - (0.1 + 0.15 * k as f64) * pw;
        b.cuboid(
            Frame,
            [x0 + 0.08 * pw, y, z],
            [x_end, y + 0.002, z + 0.018 * ph],
        );
    }
    for x in [x0 + 0.02, x1 - 0.02] {
        b.ellipsoid(Metal, [x, y + 0.004, z1 - 0.01], [0.008, 0.004, 0.008]);
    }
}

/// A hanging scroll (kakejiku): a tall strip of silk mounting hung by a cord from a thin top
/// rod, a paper panel in it with an ink picture (misty peaks, a column of brush strokes and a
/// red seal), and a heavier wooden roller across the foot with knobs standing out past the
/// silk. No frame.
pub fn hanging_scroll(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = -hd + 0.025;
    let t = 0.003;
    let rr = (0.03 * b.w).clamp(0.012, 0.02);
    // The foot roller's knobs (1.3 times its radius) rest on the box's floor.
    let zb = 1.3 * rr;
    let zt = h - 0.1 * h.min(1.0);
    // The cord in a triangle from the rod's ends to a hook at the top.
    for sx in [-1.0, 1.0] {
        b.rod(
            BlackKeys,
            [sx * 0.6 * hw, y, zt],
            [0.0, y, h - 0.005],
            0.003,
        );
    }
    let sw = 0.8 * hw;
    b.rod(Frame, [-sw, y, zt], [sw, y, zt], 0.6 * rr);
    b.rod(Frame, [-hw + 0.02, y, zb], [hw - 0.02, y, zb], rr);
    for sx in [-1.0, 1.0] {
        b.rod(
            Handle,
            [sx * (hw - 0.02), y, zb],
            [sx * hw, y, zb],
            1.3 * rr,
        );
    }
    // The silk mounting, the paper panel on it with a wider band of silk above than below.
    b.cuboid(Body, [-sw, y - t, zb], [sw, y + t, zt]);
    let (px, pz0, pz1) = (0.8 * sw, zb + 0.13 * (zt - zb), zt - 0.2 * (zt - zb));
    let yp = y + t + 0.002;
    b.cuboid(Canvas, [-px, y + t, pz0], [px, yp, pz1]);
    // Peaks: ink triangles laid as narrowing strips, the nearer ones darker and lower.
    let ph = pz1 - pz0;
    for (x, z, s, v) in [
        (-0.3, 0.28, 0.55, 0u32),
        (0.3, 0.3, 0.4, 1),
        (0.0, 0.12, 0.35, 0),
    ] {
        let (half, top) = (s * px, s * 0.55 * ph);
        let z0 = pz0 + z * ph;
        let n = 8;
        for j in 0..n {
            let f = j as f64 / n as f64;
            let hwj = half * (1.0 - f);
            b.cuboid_v(
                Interior,
                v,
                [x * px - hwj, yp, z0 + f * top],
                [x * px + hwj, yp + 0.001, z0 + (f + 1.0 / n as f64) * top],
            );
        }
    }
    // Brush strokes in a column down the right, a red seal under them.
    for k in 0..5 {
        let z = pz1 - 0.06 * ph - k as f64 * 0.07 * ph;
        let wv = if k % 2 == 0 { 0.06 } else { 0.035 };
        b.cuboid(
            Interior,
            [0.62 * px - wv * px, yp, z - 0.035 * ph],
            [0.62 * px + wv * px, yp + 0.002, z],
        );
    }
    let sz = 0.05 * px.min(ph);
    let zs = pz1 - 0.45 * ph;
    b.cuboid(
        Cushion,
        [0.62 * px - sz, yp, zs - 2.0 * sz],
        [0.62 * px + sz, yp + 0.003, zs],
    );
}

/// String lights hung on a wall: a wire in swags between hooks along the top of the box, small
/// round bulbs in dark sockets hanging from it every few hand widths.
pub fn string_lights(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = -hd + 0.5 * b.d.min(0.1);
    let br = (0.12 * h).clamp(0.02, 0.035);
    let ztop = h - 0.02;
    let sag = (h - 0.02 - 4.0 * br).max(0.05);
    let swags = ((b.w / 1.5).round() as usize).max(1);
    let sw = b.w / swags as f64;
    let wire = |x: f64| {
        let u = ((x + hw) / sw).fract() * 2.0 - 1.0;
        ztop - sag * (1.0 - u * u)
    };
    for k in 0..=swags {
        let x = (-hw + k as f64 * sw).clamp(-hw + 0.015, hw - 0.015);
        b.ellipsoid(Metal, [x, y, ztop], [0.012, 0.012, 0.015]);
    }
    for k in 0..swags {
        let x0 = -hw + k as f64 * sw;
        let pts: Vec<[f64; 3]> = (0..=12)
            .map(|i| {
                let x = x0 + sw * i as f64 / 12.0;
                let u = 2.0 * i as f64 / 12.0 - 1.0;
                [x, y, ztop - sag * (1.0 - u * u)]
            })
            .collect();
        b.polyline(BlackKeys, &pts, 0.005);
    }
    let n = ((b.w / 0.18).round() as usize).max(3);
    let mut low = f64::INFINITY;
    for i in 0..n {
        let x = -hw + (i as f64 + 0.5) * b.w / n as f64;
        let z = wire(x);
        b.cylinder(BlackKeys, [x, y, z - 0.025], 0.008, 0.025);
        b.ellipsoid(Light, [x, y, z - 0.025 - br], [br, br, 1.1 * br]);
        low = low.min(z - 0.025 - 2.1 * br);
    }
    // The lowest bulb rests on the box's floor (the prior stands every drawing on it).
    b.translate_from(0, [0.0, 0.0, -low]);
}
