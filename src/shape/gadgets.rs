//! Layouts of the rarer machines people name: a stand mixer (base, column, arm over a bowl), a
//! paper shredder (a bin with a slotted head), a 3D printer (an open frame over a bed), a
//! portable generator (a tube frame round an engine, a tank and wheels) and a radiator
//! (vertical fins between headers). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A stand mixer seen from its front: the column on the left, the arm reaching right over a
/// steel bowl on the base, a beater down into the bowl.
pub fn stand_mixer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.08 * h;
    b.cuboid(Body, [-hw, -0.6 * hd, 0.0], [0.9 * hw, 0.6 * hd, zb]);
    // The column, wider at its foot, rising at the left.
    let xc = -hw + 0.25 * b.w;
    let rc = (0.13 * b.w).min(0.8 * hd);
    b.frustum(Body, [xc, 0.0, zb], rc, 0.8 * rc, 0.8, 0.62 * h);
    // The arm: a long rounded head from over the column to over the bowl, a nose at its end.
    let za = 0.8 * h;
    let ra = (0.14 * h).min(0.8 * hd);
    b.ellipsoid(Body, [-0.08 * b.w, 0.0, za], [0.4 * b.w, 0.85 * ra, ra]);
    b.ellipsoid(
        Metal,
        [0.33 * b.w, 0.0, za],
        [0.05 * b.w, 0.5 * ra, 0.55 * ra],
    );
    b.rod(
        Handle,
        [xc, 0.75 * rc, 0.6 * h],
        [xc, 0.75 * rc + 0.02, 0.6 * h],
        0.02,
    );
    // The bowl on the base, its beater hanging from the arm into it.
    let xb = 0.18 * b.w;
    let rb = (0.19 * b.w).min(0.7 * hd);
    let hb = 0.42 * h;
    b.frustum(Metal, [xb, 0.0, zb], rb, rb, 1.35, hb);
    b.cylinder(Interior, [xb, 0.0, zb + hb], 1.2 * rb, 0.003);
    b.rod(Metal, [xb, 0.0, za - ra], [xb, 0.0, zb + 0.5 * hb], 0.012);
    b.ellipsoid(
        Metal,
        [xb, 0.0, zb + 0.4 * hb],
        [0.4 * rb, 0.15 * rb, 0.3 * hb],
    );
}

/// A paper shredder: a bin with a window showing the shreds, a darker head on top with the
/// feed slot across it and a lit button. The bin is `Metal` (plastic or steel), so the word
/// "paper" in its name does not paint it as paper.
pub fn shredder(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zh = 0.78 * h;
    let i = 0.015;
    // The bin: back, sides, bottom and a front frame round a window.
    b.cuboid(Metal, [-hw + i, -hd + i, 0.0], [hw - i, -hd + i + 0.01, zh]);
    for x in [-hw + i, hw - i - 0.01] {
        b.cuboid(Metal, [x, -hd + i, 0.0], [x + 0.01, hd - i, zh]);
    }
    let yf = hd - i;
    let (wx, wz0, wz1) = (0.6 * hw, 0.15 * h, 0.62 * h);
    b.cuboid(Metal, [-hw + i, yf - 0.01, 0.0], [hw - i, yf, wz0]);
    b.cuboid(Metal, [-hw + i, yf - 0.01, wz1], [hw - i, yf, zh]);
    b.cuboid(Metal, [-hw + i, yf - 0.01, wz0], [-wx, yf, wz1]);
    b.cuboid(Metal, [wx, yf - 0.01, wz0], [hw - i, yf, wz1]);
    b.cuboid(Pane, [-wx, yf - 0.004, wz0], [wx, yf, wz1]);
    // Shreds heaped in the bin: thin white strips.
    for k in 0..14 {
        let x = -hw + 0.05 + (k as f64 / 13.0) * (b.w - 0.1);
        let z = 0.02 + 0.3 * h * (0.6 + 0.4 * ((k * 7 % 5) as f64 / 4.0));
        b.rod(
            Canvas,
            [x, -0.5 * hd, 0.01],
            [x + 0.03 * if k % 2 == 0 { 1.0 } else { -1.0 }, 0.4 * hd, z],
            0.006,
        );
    }
    // The head: a box over the bin, the slot across its top, a button.
    b.cuboid(Top, [-hw, -hd, zh], [hw, hd, h]);
    b.cuboid(
        Interior,
        [-0.8 * hw, -0.05 * hd, h - 0.002],
        [0.8 * hw, 0.08 * hd, h],
    );
    b.cylinder(Light, [0.7 * hw, 0.6 * hd, h - 0.004], 0.012, 0.004);
}

/// A 3D printer: a base with a small screen, an open cube of dark posts and rails, the print
/// bed with a part on it, a gantry carrying the print head, and a spool of filament on top.
pub fn printer_3d(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.15 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, zb]);
    b.cuboid(
        Screen,
        [-0.3 * hw, hd - 0.003, 0.3 * zb],
        [0.3 * hw, hd, 0.8 * zb],
    );
    let t = 0.025;
    let zt = 0.86 * h;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - t / 2.0), sy * (hd - t / 2.0));
            b.cuboid(
                Frame,
                [x - t / 2.0, y - t / 2.0, zb],
                [x + t / 2.0, y + t / 2.0, zt],
            );
        }
    }
    b.cuboid(Frame, [-hw, -hd, zt - t], [hw, -hd + t, zt]);
    b.cuboid(Frame, [-hw, hd - t, zt - t], [hw, hd, zt]);
    b.cuboid(Frame, [-hw, -hd, zt - t], [-hw + t, hd, zt]);
    b.cuboid(Frame, [hw - t, -hd, zt - t], [hw, hd, zt]);
    // The bed on a carriage, a printed part on it.
    let zbed = zb + 0.25 * (zt - zb);
    b.cuboid(
        Metal,
        [-0.1 * hw, -hd + t, zbed - 0.04],
        [0.1 * hw, hd - t, zbed - 0.01],
    );
    b.cuboid(
        Top,
        [-0.75 * hw, -0.75 * hd, zbed - 0.01],
        [0.75 * hw, 0.75 * hd, zbed],
    );
    b.frustum(
        Upholstery,
        [0.0, 0.0, zbed],
        0.18 * hw,
        0.18 * hd,
        0.6,
        0.18 * (zt - zb),
    );
    // The gantry across the width and the print head on it.
    let zg = zb + 0.7 * (zt - zb);
    b.rod(Metal, [-hw + t, 0.0, zg], [hw - t, 0.0, zg], 0.01);
    b.cuboid(
        Body,
        [0.05 * b.w, -0.12 * hd, zg - 0.05],
        [0.2 * b.w, 0.12 * hd, zg + 0.05],
    );
    b.frustum(
        Metal,
        [0.125 * b.w, 0.0, zg - 0.08],
        0.006,
        0.006,
        2.5,
        0.03,
    );
    // The spool on a holder over the top frame.
    let rs = (0.5 * (h - zt)).min(0.3 * hd);
    b.cuboid(Frame, [-0.02, -hd + t, zt], [0.02, -hd + 2.0 * t, h - rs]);
    b.rod(
        Upholstery,
        [-0.12 * b.w, -hd + rs, h - rs],
        [0.12 * b.w, -hd + rs, h - rs],
        rs,
    );
}

/// A portable generator: a frame of dark tubes round an engine block and a round alternator,
/// a coloured fuel tank on top with its cap, a control panel at the front, two wheels at one
/// end and a handle at the other.
pub fn generator(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rw = (0.2 * h).min(0.3 * hd);
    let r = 0.018;
    // Tube frame: two end loops joined by rails at the bottom and the top.
    let xw = hw - rw - 0.01;
    let (x0, x1) = (-hw + 0.1 * b.w, xw - 0.02);
    let (y0, y1) = (-hd + r, hd - r);
    let (z0, z1) = (rw, 0.72 * h);
    for x in [x0, x1] {
        b.polyline(
            Frame,
            &[
                [x, y0, z0],
                [x, y0, z1],
                [x, y1, z1],
                [x, y1, z0],
                [x, y0, z0],
            ],
            r,
        );
    }
    for y in [y0, y1] {
        for z in [z0, z1] {
            b.rod(Frame, [x0, y, z], [x1, y, z], r);
        }
    }
    // Feet under the handle end, wheels on an axle at the other.
    for y in [y0, y1] {
        let yi = y - 0.04 * y.signum();
        b.cuboid(
            Tyre,
            [x0 - 0.03, yi - 0.03, 0.0],
            [x0 + 0.03, yi + 0.03, z0],
        );
        b.rod(Tyre, [xw, yi, rw], [xw, y - 0.1 * y.signum(), rw], rw);
    }
    b.rod(Metal, [xw, y0, rw], [xw, y1, rw], 0.012);
    // The engine block and the alternator inside the frame.
    b.cuboid(Metal, [x0 + 0.05, -0.6 * hd, z0], [0.0, 0.6 * hd, 0.62 * h]);
    b.rod(
        Metal,
        [0.0, 0.0, 0.45 * h],
        [x1 - 0.04, 0.0, 0.45 * h],
        0.35 * hd.min(0.2 * h),
    );
    // The tank on top, its cap, the panel with sockets at the front.
    b.cuboid(
        Body,
        [x0 + 0.02, -0.8 * hd, z1 - 0.02],
        [x1 - 0.02, 0.8 * hd, 0.93 * h],
    );
    b.cylinder(Interior, [0.3 * (x0 + x1), 0.0, 0.93 * h], 0.04, 0.07 * h);
    b.cuboid(
        Top,
        [0.05, hd - 0.12, 0.25 * h],
        [x1 - 0.04, hd - 0.1, 0.62 * h],
    );
    for k in 0..3 {
        let x = 0.1 + (k as f64 + 0.5) * (x1 - 0.19) / 3.0;
        b.cylinder(Screen, [x, hd - 0.1, 0.4 * h], 0.025, 0.004);
    }
    // The handle: a bar rising from the frame at the left end.
    b.polyline(
        Frame,
        &[
            [x0, y0, z1],
            [-hw + r, y0, h - r],
            [-hw + r, y1, h - r],
            [x0, y1, z1],
        ],
        r,
    );
}

/// A column radiator: vertical fins side by side between top and bottom headers, on two feet,
/// with a valve at the lower right.
pub fn radiator(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let z0 = (0.12 * h).min(0.1);
    let fin = 0.045;
    let gap = 0.018;
    let n = ((b.w - 0.06 + gap) / (fin + gap)).floor().max(2.0) as usize;
    let pitch = (b.w - 0.06) / n as f64;
    for i in 0..n {
        let x = -hw + 0.03 + (i as f64 + 0.5) * pitch;
        let half = 0.5 * (pitch - gap);
        b.cuboid(
            Body,
            [x - half, -0.8 * hd, z0],
            [x + half, 0.8 * hd, h - 0.01],
        );
    }
    // Headers through the fins near the top and bottom, rounded ends.
    for z in [z0 + 0.04, h - 0.05] {
        b.rod(
            Body,
            [-hw + 0.02, 0.0, z],
            [hw - 0.02, 0.0, z],
            (0.45 * hd).min(0.025),
        );
    }
    for x in [-hw + 0.1, hw - 0.1] {
        b.cuboid(Body, [x - 0.02, -0.5 * hd, 0.0], [x + 0.02, 0.5 * hd, z0]);
    }
    b.rod(
        Metal,
        [hw - 0.02, 0.0, z0 + 0.04],
        [hw, 0.0, z0 + 0.04],
        0.015,
    );
    b.cylinder(Handle, [hw - 0.012, 0.0, z0 + 0.06], 0.012, 0.04);
}
