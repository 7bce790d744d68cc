//! Layouts of everyday things whose archetype had another function: prams, hedges, flower beds,
//! logs, hydrants, treatment tables, lecterns, globes, barrows and small houses. The front faces
//! +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{rot_x, rot_y, Primitive, IDENTITY};
use std::f64::consts::PI;

/// A wheel of radius `r` and width `t` at `centre`, its axle along x.
fn wheel(b: &mut Builder, centre: [f64; 3], r: f64, t: f64) {
    let a = [centre[0] - t / 2.0, centre[1], centre[2]];
    let c = [centre[0] + t / 2.0, centre[1], centre[2]];
    b.rod(Tyre, a, c, r);
    let hub = [centre[0] + t / 2.0 + 0.003, centre[1], centre[2]];
    b.rod(Metal, c, hub, 0.35 * r);
}

/// An open tub (a pram's carrycot, a barrow's bin) centred at `y`: a shell from `z.0` to `z.1`
/// of half width `r.0` and half depth `r.1` at the rim, with a flat bottom `foot` times the rim
/// wide and a knee of the wall at (`knee.0` of the rim's radius, `knee.1` of the height); a
/// dark lining `lining` times the rim wide just under the rim.
fn tub(
    b: &mut Builder,
    y: f64,
    z: (f64, f64),
    r: (f64, f64),
    foot: f64,
    knee: (f64, f64),
    lining: f64,
) {
    let ((z0, z1), (rw, rd)) = (z, r);
    b.revolved(
        Body,
        0,
        [0.0, y, z0],
        IDENTITY,
        rd / rw,
        vec![
            [0.0, 0.0],
            [foot * rw, 0.0],
            [knee.0 * rw, knee.1 * (z1 - z0)],
            [rw, z1 - z0],
        ],
    );
    b.frustum(
        Interior,
        [0.0, y, z1 - 0.01],
        lining * rw,
        lining * rd,
        1.0,
        0.008,
    );
}

/// A pram (stroller): four small wheels, a deep carrycot with a folding hood at the back and a
/// push handle rising behind it.
pub fn pram(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.12 * h).clamp(0.05, 0.14);
    let t = 0.04;
    for sx in [-1.0, 1.0] {
        for sy in [-0.62, 0.55] {
            wheel(b, [sx * (hw - t / 2.0), sy * hd, r], r, t);
        }
        // The side frame from the axles up to the carrycot.
        b.rod(
            Metal,
            [sx * (hw - t), -0.62 * hd, r],
            [sx * 0.8 * hw, 0.0, 0.45 * h],
            0.012,
        );
        b.rod(
            Metal,
            [sx * (hw - t), 0.55 * hd, r],
            [sx * 0.8 * hw, 0.0, 0.45 * h],
            0.012,
        );
        // The push handle's side bars, rising to the back.
        b.rod(
            Frame,
            [sx * 0.8 * hw, -0.3 * hd, 0.5 * h],
            [sx * 0.8 * hw, -hd + 0.02, h - 0.02],
            0.014,
        );
    }
    b.rod(
        Frame,
        [-0.8 * hw, -hd + 0.02, h - 0.02],
        [0.8 * hw, -hd + 0.02, h - 0.02],
        0.018,
    );
    // The carrycot: a rounded tub, open on top, a dark lining inside.
    let (cw, cd) = (0.85 * hw, 0.6 * hd);
    let (z0, z1) = (0.42 * h, 0.72 * h);
    tub(b, 0.05 * hd, (z0, z1), (cw, cd), 0.8, (1.0, 0.35), 0.93);
    // The hood: a quarter shell over the back half of the cot.
    b.ellipsoid_rot(
        Shade,
        0,
        [0.0, -0.25 * hd, z1],
        [cw, 0.5 * cd, (h - z1).min(0.75 * cw)],
        IDENTITY,
    );
}

/// A trimmed hedge: a long block of foliage with flat sides and top, leaf clumps on its faces.
pub fn hedge(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let c = (0.18 * hd).min(0.08);
    b.cuboid(Foliage, [-hw + c, -hd + c, 0.0], [hw - c, hd - c, h - c]);
    // Clumps on the top and both long faces, in a regular spiral of shades.
    let r = (0.45 * hd).min(0.25);
    let nx = ((b.w / r).ceil() as usize).max(2);
    let mut k = 0u32;
    for i in 0..nx {
        let x = -hw + r + (b.w - 2.0 * r) * i as f64 / (nx - 1) as f64;
        for (y, z) in [
            (0.0, h - r),
            (hd - r, 0.7 * h),
            (-(hd - r), 0.7 * h),
            (hd - r, 0.3 * h),
            (-(hd - r), 0.3 * h),
        ] {
            let z = z.clamp(r, h - r);
            b.ellipsoid_rot(Foliage, k, [x, y, z], [r, r, r], IDENTITY);
            k += 1;
        }
    }
}

/// A flower bed: a low edging around dark soil, leafy clumps and blooms of several colours.
pub fn flower_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let e = (0.35 * h).min(0.15);
    let t = bed_edging(b, e);
    let r = (0.22 * (hd - t)).clamp(0.04, 0.2);
    let nx = (((b.w - 2.0 * t) / (1.6 * r)).floor() as usize).max(2);
    let ny = (((b.d - 2.0 * t) / (1.6 * r)).floor() as usize).max(1);
    const BLOOMS: [u32; 6] = [0, 3, 5, 6, 8, 1];
    let mut k = 0usize;
    for i in 0..nx {
        for j in 0..ny {
            let x = -hw + t + r + (b.w - 2.0 * t - 2.0 * r) * i as f64 / (nx - 1) as f64;
            let y = if ny > 1 {
                -hd + t + r + (b.d - 2.0 * t - 2.0 * r) * j as f64 / (ny - 1) as f64
            } else {
                0.0
            };
            let lz = (0.5 * (h - e)).max(0.03);
            b.ellipsoid_rot(
                Foliage,
                k as u32,
                [x, y, e + 0.5 * lz],
                [r, r, lz],
                IDENTITY,
            );
            let fr = 0.45 * r;
            b.ellipsoid_rot(
                Books,
                BLOOMS[k % BLOOMS.len()],
                [x + 0.2 * r, y - 0.1 * r, (h - fr).max(e + lz)],
                [fr, fr, 0.6 * fr],
                IDENTITY,
            );
            k += 1;
        }
    }
}

/// The boards round a bed's soil, `e` high; returns their thickness.
fn bed_edging(b: &mut Builder, e: f64) -> f64 {
    let (hw, hd) = b.half();
    let t = 0.05f64.min(0.1 * hd);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + t, e]);
    b.cuboid(Frame, [-hw, hd - t, 0.0], [hw, hd, e]);
    b.cuboid(Frame, [-hw, -hd + t, 0.0], [-hw + t, hd - t, e]);
    b.cuboid(Frame, [hw - t, -hd + t, 0.0], [hw, hd - t, e]);
    b.cuboid(Soil, [-hw + t, -hd + t, 0.0], [hw - t, hd - t, e - 0.02]);
    t
}

/// A raised vegetable bed: boards about knee high (most of its height) round the soil, and
/// rows of crops along its length with bare soil between them, all green: round cabbage heads
/// in loose outer leaves, then a row of feathery upright tops (carrots, leeks), in turn. The
/// boards' height is what tells it from a flower bed's low edging at a glance.
pub fn vegetable_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let e = 0.7 * h;
    let t = bed_edging(b, e);
    let soil = e - 0.02;
    let lz = h - soil;
    let rows = (((b.d - 2.0 * t) / (2.2 * lz).max(0.2)).floor() as usize).max(1);
    let pitch = (b.d - 2.0 * t) / rows as f64;
    let r = (0.32 * pitch).min(0.9 * lz);
    for j in 0..rows {
        let y = -hd + t + (j as f64 + 0.5) * pitch;
        let n = (((b.w - 2.0 * t) / (2.4 * r)).floor() as usize).max(1);
        let step = (b.w - 2.0 * t) / n as f64;
        for i in 0..n {
            let x = -hw + t + (i as f64 + 0.5) * step;
            let k = (i + j) as u32;
            if j % 2 == 0 {
                // A cabbage: a paler head in a ring of spread outer leaves.
                b.ellipsoid_rot(
                    Foliage,
                    k,
                    [x, y, soil + 0.15 * lz],
                    [r, r, 0.3 * lz],
                    IDENTITY,
                );
                b.ellipsoid_rot(
                    Foliage,
                    k + 3,
                    [x, y, soil + 0.45 * lz],
                    [0.6 * r, 0.6 * r, 0.5 * lz],
                    IDENTITY,
                );
            } else {
                // Feathery tops: thin stems fanning up from one root.
                for q in 0..5 {
                    let a = q as f64 * 2.0 * PI / 5.0 + k as f64;
                    let top = [x + 0.6 * r * a.cos(), y + 0.6 * r * a.sin(), h - 0.01];
                    b.rod(Foliage, [x, y, soil], top, (0.06 * r).max(0.004));
                }
            }
        }
    }
}

/// A log lying on its side along its longer footprint axis: bark around, pale cut ends.
pub fn log(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let along_x = b.w >= b.d;
    let (half_len, across) = if along_x { (hw, hd) } else { (hd, hw) };
    let r = (0.5 * h).min(across);
    let end = |s: f64| {
        if along_x {
            [s, 0.0, r]
        } else {
            [0.0, s, r]
        }
    };
    let cap = 0.01;
    b.rod(Trunk, end(-(half_len - cap)), end(half_len - cap), r);
    for s in [-1.0, 1.0] {
        b.rod(Top, end(s * (half_len - cap)), end(s * half_len), 0.92 * r);
    }
    // A stub of a cut branch on top.
    let mid = end(0.2 * half_len);
    b.rod(
        Trunk,
        [mid[0], mid[1], 1.6 * r],
        [mid[0], mid[1], (2.0 * r).min(h) - 0.01],
        0.25 * r,
    );
}

/// A fire hydrant: a flanged foot, a barrel, a domed bonnet with a nut, and three outlets.
pub fn hydrant(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.45 * hw.min(hd);
    b.cylinder(Body, [0.0, 0.0, 0.0], (1.5 * r).min(hw.min(hd)), 0.06 * h);
    b.cylinder(Body, [0.0, 0.0, 0.06 * h], r, 0.64 * h);
    b.cylinder(Top, [0.0, 0.0, 0.68 * h], 1.25 * r, 0.05 * h);
    b.revolved(
        Top,
        0,
        [0.0, 0.0, 0.73 * h],
        IDENTITY,
        1.0,
        super::parts::ellipsoid_profile(1.05 * r, 0.17 * h)
            .into_iter()
            .filter(|p| p[1] >= 0.0)
            .collect(),
    );
    b.cylinder(Metal, [0.0, 0.0, 0.88 * h], 0.3 * r, h - 0.88 * h);
    // Side outlets and the larger front one, with caps.
    for sx in [-1.0, 1.0] {
        b.rod(
            Body,
            [0.0, 0.0, 0.55 * h],
            [sx * (hw - 0.02), 0.0, 0.55 * h],
            0.35 * r,
        );
        b.rod(
            Metal,
            [sx * (hw - 0.02), 0.0, 0.55 * h],
            [sx * hw, 0.0, 0.55 * h],
            0.4 * r,
        );
    }
    b.rod(
        Body,
        [0.0, 0.0, 0.45 * h],
        [0.0, hd - 0.02, 0.45 * h],
        0.5 * r,
    );
    b.rod(
        Metal,
        [0.0, hd - 0.02, 0.45 * h],
        [0.0, hd, 0.45 * h],
        0.55 * r,
    );
}

/// A padded treatment table (examination, massage, operating): a base on legs or a pedestal,
/// a long padded top along the longer footprint axis and a raised head section at one end.
pub fn padded_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let along_y = b.d >= b.w;
    let pad = (0.12 * h).clamp(0.06, 0.1);
    let (len, wid) = if along_y { (b.d, b.w) } else { (b.w, b.d) };
    let head = 0.28 * len;
    let tilt = 0.3f64;
    let top = (h - pad - head * tilt.sin()).max(0.45 * h);
    // Legs at the corners, a shelf between them.
    b.legs(Frame, 0.05, 0.04, 0.0, top - 0.04);
    b.cuboid(
        Frame,
        [-hw + 0.02, -hd + 0.02, top - 0.06],
        [hw - 0.02, hd - 0.02, top],
    );
    b.cuboid(
        Frame,
        [-hw + 0.06, -hd + 0.06, 0.15],
        [hw - 0.06, hd - 0.06, 0.17],
    );
    // The pad: most of the length flat, the head end (the back third) tilted up.
    if along_y {
        b.cuboid(Upholstery, [-hw, -hd + head, top], [hw, hd, top + pad]);
        b.push(
            Upholstery,
            0,
            Primitive::Cuboid {
                centre: [
                    0.0,
                    -hd + head - 0.5 * head * tilt.cos(),
                    top + 0.5 * pad + 0.5 * head * tilt.sin(),
                ],
                half: [0.5 * wid, 0.5 * head, 0.5 * pad],
                rot: rot_x(-tilt),
            },
        );
    } else {
        b.cuboid(Upholstery, [-hw + head, -hd, top], [hw, hd, top + pad]);
        b.push(
            Upholstery,
            0,
            Primitive::Cuboid {
                centre: [
                    -hw + head - 0.5 * head * tilt.cos(),
                    0.0,
                    top + 0.5 * pad + 0.5 * head * tilt.sin(),
                ],
                half: [0.5 * head, 0.5 * wid, 0.5 * pad],
                rot: rot_y(tilt),
            },
        );
    }
}

/// A lectern: a foot, a narrow front panel rising to a top sloped down towards the reader at
/// the back, with a lip for the book.
pub fn lectern(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let foot = (0.05 * h).min(0.05);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, foot]);
    let slope = 0.3f64;
    let rise = (b.d - 0.04) * slope.sin();
    let z_top = h - rise - 0.03;
    b.cuboid(
        Body,
        [-0.7 * hw, -0.4 * hd, foot],
        [0.7 * hw, 0.5 * hd, z_top],
    );
    b.push(
        Top,
        0,
        Primitive::Cuboid {
            centre: [0.0, 0.0, z_top + 0.5 * rise + 0.015],
            half: [hw, 0.5 * (b.d - 0.04) / slope.cos().max(0.5) * 0.98, 0.015],
            rot: rot_x(slope),
        },
    );
    // The book lip along the low (back) edge.
    b.cuboid(
        Top,
        [-hw, -hd, z_top - 0.01],
        [hw, -hd + 0.03, z_top + 0.05],
    );
    // An open book on the desk.
    b.push(
        Canvas,
        0,
        Primitive::Cuboid {
            centre: [0.0, 0.0, z_top + 0.5 * rise + 0.04],
            half: [0.55 * hw, 0.3 * hd, 0.012],
            rot: rot_x(slope),
        },
    );
}

/// A globe: a round sphere (never stretched to the size box) on a meridian ring, a stem and a
/// foot, with land patches on the ocean.
pub fn globe(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let foot = (0.08 * h).clamp(0.01, 0.06);
    let r = (hw.min(hd) / 1.08).min(0.5 * (h - foot) / 1.1);
    let cz = h - 1.05 * r;
    b.frustum(
        Frame,
        [0.0, 0.0, 0.0],
        0.8 * hw.min(hd),
        0.8 * hw.min(hd),
        0.7,
        foot,
    );
    b.cylinder(
        Frame,
        [0.0, 0.0, foot],
        0.02f64.min(0.1 * r),
        cz - r - foot + 0.01,
    );
    b.ellipsoid(Body, [0.0, 0.0, cz], [r, r, r]);
    // The meridian half ring, tilted like the earth's axis.
    let tilt = 23.5f64.to_radians();
    let ring = 1.05 * r;
    let n = 16;
    for k in 0..n {
        let (a0, a1) = (PI * k as f64 / n as f64, PI * (k + 1) as f64 / n as f64);
        let p = |a: f64| [ring * a.sin(), 0.0, cz - ring * a.cos()];
        let (p0, p1) = (p(a0), p(a1));
        let rot = |v: [f64; 3]| {
            let (x, z) = (v[0], v[2] - cz);
            [
                x * tilt.cos() - z * tilt.sin(),
                0.0,
                cz + x * tilt.sin() + z * tilt.cos(),
            ]
        };
        b.rod(Metal, rot(p0), rot(p1), 0.012f64.min(0.06 * r));
    }
    // Continents: flattened patches just outside the ocean.
    for k in 0..7u32 {
        let lon = k as f64 * 2.4;
        let lat = (k as f64 * 0.9).sin() * 0.8;
        let n = [lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin()];
        let s = 0.35 * r * (0.7 + 0.3 * ((k * 3) % 4) as f64 / 3.0);
        let centre = [n[0] * 0.97 * r, n[1] * 0.97 * r, cz + n[2] * 0.97 * r];
        b.push(
            Foliage,
            k,
            Primitive::Revolved {
                origin: centre,
                rot: super::archetypes::frame_along(n),
                ay: 0.7,
                profile: super::parts::ellipsoid_profile(s, 0.06 * r),
            },
        );
    }
}

/// A barrow or cart: a tray on wheels, handles or a shaft at the back. One wheel at the front
/// when narrow (a wheelbarrow), two large side wheels when wide (a cart).
pub fn barrow(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    if b.w < 0.9 {
        let r = (0.25 * h).clamp(0.1, 0.2);
        wheel(b, [0.0, hd - r, r], r, 0.08);
        let (z0, z1) = (0.4 * h, h);
        let (tw, td) = (0.95 * hw, 0.5 * hd);
        tub(b, 0.05 * hd, (z0, z1), (tw, td), 0.7, (0.9, 0.6), 0.96);
        for sx in [-1.0, 1.0] {
            let x = sx * 0.55 * hw;
            b.rod(Frame, [0.0, hd - r, r], [x, -hd, 0.55 * h], 0.018);
            b.rod(Frame, [x, -0.2 * hd, 0.5 * h], [x, -0.2 * hd, 0.0], 0.018);
        }
        return;
    }
    let r = (0.35 * h).min(0.45 * hd);
    let t = 0.06;
    for sx in [-1.0, 1.0] {
        wheel(b, [sx * (hw - t / 2.0), 0.0, r], r, t);
    }
    let z0 = r + 0.02;
    let bed = (hw - t - 0.02, 0.65 * hd);
    b.cuboid(Top, [-bed.0, -bed.1, z0], [bed.0, bed.1, z0 + 0.05]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Body,
            [sx * bed.0 - 0.02, -bed.1, z0],
            [sx * bed.0 + 0.02, bed.1, (z0 + 0.35).min(h)],
        );
    }
    for sy in [-1.0, 1.0] {
        b.cuboid(
            Body,
            [-bed.0, sy * bed.1 - 0.02, z0],
            [bed.0, sy * bed.1 + 0.02, (z0 + 0.35).min(h)],
        );
    }
    // The shaft forward to the draught animal.
    for sx in [-0.4, 0.4] {
        b.rod(
            Frame,
            [sx * bed.0, bed.1, z0 + 0.02],
            [sx * 0.6 * bed.0, hd, 0.5 * z0],
            0.025,
        );
    }
}

/// A small house (a shed, a hut, a barn, a coop): walls, a pitched roof with eaves, a door and
/// a window at the front.
pub fn house(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let eave = (0.06 * b.w.min(b.d)).min(0.2);
    let wall = 0.62 * h;
    b.cuboid(
        Body,
        [-hw + eave, -hd + eave, 0.0],
        [hw - eave, hd - eave, wall],
    );
    // Gable ends and two roof planes, the ridge along x.
    let rise = h - wall - 0.04;
    let run = hd - eave;
    let slope = (rise / run).atan();
    let low = wall - rise * eave / run;
    let len = hd * (1.0 + (rise / run).powi(2)).sqrt();
    for sy in [-1.0, 1.0] {
        b.push(
            Top,
            0,
            Primitive::Cuboid {
                centre: [0.0, sy * 0.5 * hd, 0.5 * (wall + rise + low)],
                half: [hw, 0.5 * len, 0.02],
                rot: rot_x(-sy * slope),
            },
        );
    }
    // The gables: stacked slabs narrowing towards the ridge.
    let n = 6;
    for k in 0..n {
        let z0 = wall + rise * k as f64 / n as f64;
        let z1 = wall + rise * (k + 1) as f64 / n as f64;
        let y = run * (1.0 - (k as f64 + 0.5) / n as f64);
        b.cuboid(Body, [-hw + eave, -y, z0], [hw - eave, y, z1]);
    }
    // Door and window on the front.
    let dw = (0.35 * b.w).min(0.9);
    let dh = (0.85 * wall).min(2.0);
    b.cuboid(
        Door,
        [-0.25 * hw - dw / 2.0, hd - eave, 0.0],
        [-0.25 * hw + dw / 2.0, hd - eave + 0.02, dh],
    );
    let ww = (0.25 * b.w).min(0.7);
    b.cuboid(
        Glass,
        [0.55 * hw - ww / 2.0, hd - eave, 0.45 * wall],
        [0.55 * hw + ww / 2.0, hd - eave + 0.02, 0.8 * wall],
    );
}
