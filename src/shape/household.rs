//! Layouts of small things people name in a room: a cactus with its arms, a teddy bear, a lit
//! pillar candle, an electric kettle, a toaster, a record player, a tea set (a round-bellied
//! teapot with spout and handle beside cups on saucers, on a tray). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::frustum_profile;

/// A column of radius `r` from `base` up `h` with a rounded top.
fn column(b: &mut Builder, base: [f64; 3], r: f64, h: f64) {
    b.cylinder(Foliage, base, r, (h - r).max(0.0));
    b.ellipsoid(
        Foliage,
        [base[0], base[1], base[2] + (h - r).max(0.0)],
        [r, r, r],
    );
}

/// A cactus: a ribbed column with two arms bending upwards, in a pot unless it is tree-sized.
pub fn cactus(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let potted = h < 1.5;
    let z0 = if potted {
        let ph = 0.25 * h;
        b.frustum(Pot, [0.0, 0.0, 0.0], 0.8 * m, 0.8 * m, 1.2, ph);
        b.cylinder(Soil, [0.0, 0.0, ph - 0.01], 0.9 * m, 0.012);
        ph
    } else {
        0.0
    };
    let r = if potted { 0.45 * m } else { 0.22 * m };
    column(b, [0.0, 0.0, z0], r, h - z0);
    // Ribs: darker thin columns round the trunk.
    for k in 0..8 {
        let a = k as f64 * std::f64::consts::TAU / 8.0;
        let (x, y) = (0.93 * r * a.cos(), 0.93 * r * a.sin());
        b.cylinder(Trunk, [x, y, z0 + 0.05 * h], 0.1 * r, 0.8 * (h - z0 - r));
    }
    // Arms: out sideways, then up.
    let ra = 0.7 * r;
    for (sx, zf, top) in [(-1.0, 0.45, 0.78), (1.0, 0.58, 0.9)] {
        let za = z0 + zf * (h - z0);
        let xa = sx * (hw - ra - 0.01);
        b.rod(Foliage, [0.0, 0.0, za], [xa, 0.0, za], ra);
        b.ellipsoid(Foliage, [xa, 0.0, za], [ra, ra, ra]);
        column(b, [xa, 0.0, za], ra, z0 + top * (h - z0) - za);
    }
}

/// A teddy bear sitting: a round body, legs forward, arms at its sides, a head with ears, a
/// lighter muzzle, dark eyes and nose.
pub fn teddy_bear(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.ellipsoid(
        Upholstery,
        [0.0, -0.1 * hd, 0.3 * h],
        [0.6 * hw, 0.55 * hd, 0.3 * h],
    );
    for sx in [-1.0, 1.0] {
        // Legs forward with lighter pads, arms hanging at the sides.
        b.ellipsoid(
            Upholstery,
            [sx * 0.45 * hw, 0.45 * hd, 0.1 * h],
            [0.28 * hw, 0.5 * hd, 0.1 * h],
        );
        b.ellipsoid(
            Cushion,
            [sx * 0.45 * hw, 0.93 * hd, 0.1 * h],
            [0.2 * hw, 0.05 * hd, 0.08 * h],
        );
        b.ellipsoid(
            Upholstery,
            [sx * 0.78 * hw, 0.1 * hd, 0.32 * h],
            [0.2 * hw, 0.25 * hd, 0.16 * h],
        );
        // Ears and eyes.
        b.ellipsoid(
            Upholstery,
            [sx * 0.45 * hw, -0.1 * hd, 0.93 * h],
            [0.17 * hw, 0.12 * hd, 0.07 * h],
        );
        b.ellipsoid(
            BlackKeys,
            [sx * 0.17 * hw, 0.45 * hd, 0.8 * h],
            [0.045 * hw, 0.03 * hd, 0.03 * h],
        );
    }
    b.ellipsoid(
        Upholstery,
        [0.0, 0.0, 0.74 * h],
        [0.52 * hw, 0.55 * hd, 0.19 * h],
    );
    b.ellipsoid(
        Cushion,
        [0.0, 0.5 * hd, 0.7 * h],
        [0.2 * hw, 0.15 * hd, 0.08 * h],
    );
    b.ellipsoid(
        BlackKeys,
        [0.0, 0.64 * hd, 0.73 * h],
        [0.06 * hw, 0.04 * hd, 0.03 * h],
    );
}

/// A lit pillar candle on a holder plate: a wax column narrower than the plate, a wick and a
/// flame.
pub fn candle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let zt = 0.72 * h;
    b.frustum(Metal, [0.0, 0.0, 0.0], m, m, 0.92, 0.05 * h);
    b.cylinder(Body, [0.0, 0.0, 0.05 * h], 0.55 * m, zt - 0.05 * h);
    b.cylinder(Interior, [0.0, 0.0, zt], 0.05 * m, 0.05 * h);
    b.ellipsoid(
        Light,
        [0.0, 0.0, zt + 0.15 * h],
        [0.16 * m, 0.16 * m, 0.12 * h],
    );
}

/// An electric kettle: a body narrowing to its lid, a spout at the front, a handle at the back,
/// a water window, on a dark power base.
pub fn kettle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.62 * hw.min(hd / 0.75);
    let yc = -0.05 * b.d;
    b.cylinder(Handle, [0.0, yc, 0.0], 1.05 * r, 0.07 * h);
    b.revolved(
        Body,
        0,
        [0.0, yc, 0.07 * h],
        super::parts::IDENTITY,
        1.0,
        frustum_profile(r, 0.8 * r, 0.78 * h),
    );
    b.cylinder(Handle, [0.0, yc, 0.85 * h], 0.8 * r, 0.03 * h);
    b.ellipsoid(Handle, [0.0, yc, 0.89 * h], [0.2 * r, 0.2 * r, 0.1 * h]);
    b.rod(
        Body,
        [0.0, yc + 0.85 * r, 0.7 * h],
        [0.0, hd - 0.01, 0.84 * h],
        0.12 * r,
    );
    b.cuboid(
        Glass,
        [-0.12 * r, yc + 0.9 * r, 0.2 * h],
        [0.12 * r, yc + 1.0 * r, 0.65 * h],
    );
    let yb = -hd + 0.02;
    b.polyline(
        Handle,
        &[
            [0.0, yc - 0.8 * r, 0.85 * h],
            [0.0, yb, 0.8 * h],
            [0.0, yb, 0.3 * h],
            [0.0, yc - 0.9 * r, 0.2 * h],
        ],
        0.02,
    );
}

/// A cooking pot: a squat straight-sided steel body, a lid a little domed with a knob, and a
/// loop handle either side (a saucepan or stockpot on a hob).
pub fn cooking_pot(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.78 * hw.min(hd);
    b.cylinder(Body, [0.0, 0.0, 0.0], r, 0.78 * h);
    b.cylinder(Interior, [0.0, 0.0, 0.78 * h - 0.01], 0.94 * r, 0.012);
    b.frustum(
        Metal,
        [0.0, 0.0, 0.78 * h],
        1.02 * r,
        1.02 * r,
        0.75,
        0.1 * h,
    );
    b.ellipsoid(Handle, [0.0, 0.0, 0.92 * h], [0.14 * r, 0.14 * r, 0.08 * h]);
    for s in [-1.0, 1.0] {
        let x0 = s * 0.98 * r;
        let x1 = s * (hw - 0.01).max(1.12 * r);
        b.rod(
            Handle,
            [x0, -0.3 * r, 0.62 * h],
            [x1, -0.2 * r, 0.64 * h],
            0.05 * r,
        );
        b.rod(
            Handle,
            [x1, -0.2 * r, 0.64 * h],
            [x1, 0.2 * r, 0.64 * h],
            0.05 * r,
        );
        b.rod(
            Handle,
            [x1, 0.2 * r, 0.64 * h],
            [x0, 0.3 * r, 0.62 * h],
            0.05 * r,
        );
    }
}

/// A toaster: a rounded body with two bread slots on top, a lever and a knob on the front, a
/// dark foot.
pub fn toaster(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(
        Handle,
        [-hw + 0.01, -hd + 0.01, 0.0],
        [hw - 0.01, hd - 0.02, 0.1 * h],
    );
    b.cuboid(Body, [-hw, -hd, 0.1 * h], [hw, hd - 0.015, h - 0.02]);
    b.cuboid(
        Body,
        [-hw + 0.01, -hd + 0.01, h - 0.02],
        [hw - 0.01, hd - 0.025, h],
    );
    for y in [-0.22 * b.d, 0.12 * b.d] {
        b.cuboid(
            Interior,
            [-0.38 * b.w, y - 0.015, h - 0.001],
            [0.38 * b.w, y + 0.015, h],
        );
    }
    b.cuboid(
        BlackKeys,
        [0.25 * b.w, hd - 0.015, 0.55 * h],
        [0.38 * b.w, hd, 0.62 * h],
    );
    b.cylinder(BlackKeys, [-0.3 * b.w, hd - 0.015, 0.35 * h], 0.012, 0.015);
}

/// A record player: a wooden plinth, a platter with a black record and its label, a tonearm
/// from its rest at the back right across to the record, a smoked lid standing open behind.
pub fn record_player(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zp = 0.45 * h;
    b.cuboid(Body, [-hw, -hd + 0.02, 0.0], [hw, hd, zp]);
    for x in [-hw + 0.04, hw - 0.04] {
        b.cylinder(Handle, [x, hd - 0.04, zp - 0.06], 0.012, 0.06);
    }
    let rp = (0.42 * b.d).min(0.36 * b.w);
    let (xp, yp) = (-0.12 * b.w, 0.02 * b.d);
    b.cylinder(Metal, [xp, yp, zp], 1.02 * rp, 0.015);
    b.cylinder(BlackKeys, [xp, yp, zp + 0.015], rp, 0.004);
    b.cylinder(Light, [xp, yp, zp + 0.019], 0.33 * rp, 0.001);
    let pivot = [hw - 0.08, -0.25 * hd, zp];
    b.cylinder(Metal, pivot, 0.02, 0.03);
    b.rod(
        Metal,
        [pivot[0], pivot[1], zp + 0.03],
        [xp + 0.55 * rp, yp + 0.55 * rp, zp + 0.03],
        0.005,
    );
    // The lid, open, leaning back along the rear edge.
    b.cuboid(Glass, [-hw, -hd, zp], [hw, -hd + 0.012, h]);
}

/// A tea set: a tray, a round-bellied teapot on its left with a spout to the right, a lid
/// knob and a loop handle, and on its right cups of tea on saucers in a row front to back.
pub fn tea_set(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tray = (0.08 * h).min(0.015);
    b.cuboid(Top, [-hw, -hd, 0.0], [hw, hd, tray]);
    // The teapot, its belly filling most of the height.
    let rp = (0.85 * h / 2.0).min(0.3 * hw).min(0.8 * hd);
    let xc = -hw + 1.3 * rp;
    let zc = tray + 0.9 * rp;
    b.ellipsoid(Body, [xc, 0.0, zc], [rp, rp, 0.9 * rp]);
    b.cylinder(Body, [xc, 0.0, zc + 0.8 * rp], 0.45 * rp, 0.12 * rp);
    b.ellipsoid(
        Handle,
        [xc, 0.0, zc + 0.98 * rp],
        [0.12 * rp, 0.12 * rp, 0.1 * rp],
    );
    b.rod(
        Body,
        [xc + 0.8 * rp, 0.0, zc - 0.1 * rp],
        [xc + 1.35 * rp, 0.0, zc + 0.6 * rp],
        0.1 * rp,
    );
    b.polyline(
        Handle,
        &[
            [xc - 0.85 * rp, 0.0, zc + 0.5 * rp],
            [xc - 1.25 * rp, 0.0, zc + 0.35 * rp],
            [xc - 1.25 * rp, 0.0, zc - 0.2 * rp],
            [xc - 0.9 * rp, 0.0, zc - 0.35 * rp],
        ],
        0.06 * rp,
    );
    // The cups on their saucers, as many as fit front to back on the tray's right.
    let rs = (0.22 * hd).min(0.3 * (hw - 0.6 * rp)).clamp(0.02, 0.07);
    let xs = hw - 1.2 * rs;
    let n = ((2.0 * hd) / (2.3 * rs)).floor().clamp(1.0, 3.0) as usize;
    let rc = 0.62 * rs;
    let hc = (0.9 * rc).min(h - tray - 0.01);
    for k in 0..n {
        let y = -hd + (k as f64 + 0.5) * 2.0 * hd / n as f64;
        b.cylinder(Body, [xs, y, tray], rs, 0.008);
        b.revolved(
            Body,
            1,
            [xs, y, tray + 0.008],
            super::parts::IDENTITY,
            1.0,
            frustum_profile(0.7 * rc, rc, hc),
        );
        b.cylinder(Interior, [xs, y, tray + 0.008 + 0.8 * hc], 0.92 * rc, 0.002);
        b.rod(
            Handle,
            [xs + rc, y, tray + 0.3 * hc],
            [xs + 1.35 * rc, y, tray + 0.6 * hc],
            0.12 * rc,
        );
    }
}
