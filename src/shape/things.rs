//! Layouts of things people name by function: optics on tripods, consoles, robots, loungers,
//! dispensers, animals (a quadruped and a bird at their real size), cauldrons, easels and grills.
//! The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use std::f64::consts::TAU;

/// Three splayed legs from a head at `head` to the floor within the footprint.
fn tripod_legs(b: &mut Builder, head: [f64; 3], r: f64) {
    let (hw, hd) = b.half();
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU + 0.5 * TAU / 3.0 - 0.25 * TAU;
        let foot = [0.9 * hw * a.cos(), 0.9 * hd * a.sin(), 0.0];
        b.rod(Metal, foot, head, r);
    }
}

/// An optical instrument on a tripod: a tube (telescope) tilted up towards the front, or a box
/// body with a lens when the object is short (cameras, theodolites).
pub fn tripod(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let head = [0.0, 0.0, 0.68 * h];
    tripod_legs(b, head, (0.012 * h).max(0.008));
    b.ellipsoid(Metal, head, [0.03, 0.03, 0.03]);
    let len = 1.6 * hw.max(hd);
    if len > 0.4 * h {
        // A telescope tube, eyepiece at the back, pointing up at ~25°.
        let (c, s) = (25f64.to_radians().cos(), 25f64.to_radians().sin());
        let back = [0.0, -0.35 * len * c, head[2] + 0.05 - 0.35 * len * s];
        let front = [0.0, 0.65 * len * c, head[2] + 0.05 + 0.65 * len * s];
        let r = (0.08 * len).clamp(0.03, 0.15);
        let front = [front[0], front[1].min(hd - r), front[2].min(h - r)];
        b.rod(Body, back, front, r);
        b.rod(
            Glass,
            front,
            [front[0], front[1] + 0.01, front[2] + 0.005],
            0.85 * r,
        );
        b.rod(
            Metal,
            back,
            [back[0], back[1] - 0.08, back[2] - 0.03],
            0.3 * r,
        );
    } else {
        let s = 0.25 * hw.min(hd).max(0.1);
        b.cuboid(
            Body,
            [-s, -s, head[2] + 0.03],
            [s, s, head[2] + 0.03 + 1.2 * s],
        );
        b.rod(
            Glass,
            [0.0, s, head[2] + 0.03 + 0.6 * s],
            [0.0, s + 0.6 * s, head[2] + 0.03 + 0.6 * s],
            0.45 * s,
        );
    }
}

/// A console or control desk: a low base, a sloped panel of lit buttons facing the user (+y)
/// and a row of screens at the back.
pub fn console(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let desk = 0.72 * h.min(1.4);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.15 * b.d, desk - 0.05]);
    // The sloped panel: thin steps rising from the front edge to the back.
    let steps = 6;
    for i in 0..steps {
        let t = i as f64 / steps as f64;
        let y0 = hd - t * 0.45 * b.d;
        let y1 = hd - (t + 1.0 / steps as f64) * 0.45 * b.d;
        let z = desk - 0.05 + t * 0.12;
        b.cuboid(Top, [-hw, y1, z], [hw, y0, z + 0.05]);
        let n = ((b.w / 0.12) as usize).max(3);
        for j in 0..n {
            if (i * 7 + j * 3) % 4 == 0 {
                continue;
            }
            let x = -hw + (j as f64 + 0.5) * b.w / n as f64;
            b.cuboid_v(
                Books,
                ((i + j) % 6) as u32,
                [x - 0.025, 0.5 * (y0 + y1) - 0.02, z + 0.05],
                [x + 0.025, 0.5 * (y0 + y1) + 0.02, z + 0.06],
            );
        }
    }
    let ys = hd - 0.47 * b.d;
    let top = h.min(desk + 0.6);
    let screens = ((b.w / 0.7) as usize).clamp(1, 4);
    let sw = b.w / screens as f64;
    for k in 0..screens {
        let x0 = -hw + k as f64 * sw;
        b.cuboid(
            Body,
            [x0 + 0.02, -hd, desk + 0.12],
            [x0 + sw - 0.02, ys, top],
        );
        b.cuboid(
            Screen,
            [x0 + 0.05, ys, desk + 0.15],
            [x0 + sw - 0.05, ys + 0.004, top - 0.03],
        );
    }
}

/// A robot: box legs, a boxy torso with a lit panel, jointed arms, a head with two lit eyes
/// and an antenna; a wheeled machine base when the object is wider than tall.
pub fn robot(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lw = 0.28 * hw;
    let leg_h = 0.4 * h;
    for sx in [-1.0, 1.0] {
        let x = sx * 0.45 * hw;
        b.cuboid(
            Metal,
            [x - lw, -0.6 * hd, 0.0],
            [x + lw, 0.8 * hd, 0.05 * h],
        );
        b.cuboid(
            Body,
            [x - 0.8 * lw, -0.4 * hd, 0.05 * h],
            [x + 0.8 * lw, 0.4 * hd, leg_h],
        );
    }
    let (tw, t0, t1) = (0.7 * hw, leg_h, 0.78 * h);
    b.cuboid(Body, [-tw, -0.6 * hd, t0], [tw, 0.6 * hd, t1]);
    b.cuboid(
        Light,
        [-0.4 * tw, 0.6 * hd, t0 + 0.45 * (t1 - t0)],
        [0.4 * tw, 0.6 * hd + 0.004, t0 + 0.75 * (t1 - t0)],
    );
    for sx in [-1.0, 1.0] {
        let shoulder = [sx * (tw + 0.06 * hw), 0.0, t1 - 0.05 * h];
        b.ellipsoid(Metal, shoulder, [0.08 * hw, 0.08 * hw, 0.08 * hw]);
        let elbow = [sx * (hw - 0.1 * hw), 0.1 * hd, t0 + 0.3 * (t1 - t0)];
        b.rod(Metal, shoulder, elbow, 0.06 * hw);
        b.rod(
            Metal,
            elbow,
            [sx * (hw - 0.1 * hw), 0.7 * hd, t0 + 0.3 * (t1 - t0)],
            0.05 * hw,
        );
    }
    b.cuboid(
        Metal,
        [-0.1 * hw, -0.1 * hd, t1],
        [0.1 * hw, 0.1 * hd, t1 + 0.03 * h],
    );
    let (hz0, hz1) = (t1 + 0.03 * h, 0.95 * h);
    let hh = 0.45 * hw;
    b.cuboid(Body, [-hh, -0.5 * hd, hz0], [hh, 0.5 * hd, hz1]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Light,
            [sx * 0.45 * hh - 0.1 * hh, 0.5 * hd, hz0 + 0.5 * (hz1 - hz0)],
            [
                sx * 0.45 * hh + 0.1 * hh,
                0.5 * hd + 0.004,
                hz0 + 0.7 * (hz1 - hz0),
            ],
        );
    }
    b.rod(Metal, [0.0, 0.0, hz1], [0.0, 0.0, h - 0.02], 0.01);
    b.ellipsoid(Light, [0.0, 0.0, h - 0.02], [0.02, 0.02, 0.02]);
}

/// A lounger or deckchair: a long low frame, a flat seat and a raised back at the rear (−y),
/// on short legs; a canvas sling seat when the object is short in depth (deckchairs).
pub fn lounger(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let seat = (0.35 * h).min(0.35);
    let back_y = -hd + 0.35 * b.d;
    b.legs(Frame, 0.04, 0.03, 0.0, seat - 0.04);
    b.cuboid(Frame, [-hw, back_y, seat - 0.06], [hw, hd, seat - 0.02]);
    b.cuboid(
        Upholstery,
        [-hw + 0.03, back_y, seat - 0.02],
        [hw - 0.03, hd - 0.02, seat + 0.03],
    );
    // The back: a slab tilted ~35° from vertical, rising from the seat's rear edge to -y.
    let steps = 10;
    for i in 0..steps {
        let (t0, t1) = (i as f64 / steps as f64, (i + 1) as f64 / steps as f64);
        let y0 = back_y - t0 * (back_y + hd - 0.02);
        let y1 = back_y - t1 * (back_y + hd - 0.02);
        let z0 = seat + t0 * (h - seat - 0.03);
        let z1 = seat + t1 * (h - seat - 0.03);
        b.cuboid(Upholstery, [-hw + 0.03, y1, z0], [hw - 0.03, y0, z1 + 0.03]);
    }
    for sx in [-1.0, 1.0] {
        b.rod(
            Frame,
            [sx * (hw - 0.02), -hd + 0.03, 0.0],
            [sx * (hw - 0.02), -hd + 0.05, h - 0.02],
            0.015,
        );
    }
}

/// A water cooler or dispenser: a cabinet with a dispensing recess, taps and an upturned bottle
/// on top (a blue one for water coolers).
pub fn dispenser(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let body = 0.62 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, body]);
    b.cuboid(
        Interior,
        [-0.6 * hw, hd - 0.004, 0.55 * body],
        [0.6 * hw, hd, 0.8 * body],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Handle,
            [sx * 0.3 * hw - 0.02, hd, 0.82 * body],
            [sx * 0.3 * hw + 0.02, hd + 0.003, 0.88 * body],
        );
    }
    let r = 0.85 * hw.min(hd);
    b.frustum(Glass, [0.0, 0.0, body], 0.3 * r, 0.3 * r, 1.0, 0.04 * h);
    b.frustum(
        Glass,
        [0.0, 0.0, body + 0.04 * h],
        r,
        r,
        1.0,
        h - body - 0.1 * h,
    );
    b.frustum(Glass, [0.0, 0.0, h - 0.06 * h], r, r, 0.6, 0.06 * h);
}

/// A four-legged animal at the planned size: body, neck and head, tail. It stands along the
/// longer side of its footprint, head towards +y (or +x when wider than deep: a rocking horse).
pub fn quadruped(b: &mut Builder) {
    let along_x = b.w > b.d;
    // Lay the animal out in (across, along) coordinates, then map them to the object frame.
    let (ha, hl, h) = if along_x {
        (b.d / 2.0, b.w / 2.0, b.h)
    } else {
        (b.w / 2.0, b.d / 2.0, b.h)
    };
    let map = |p: [f64; 3]| if along_x { [p[1], -p[0], p[2]] } else { p };
    let rad = |r: [f64; 3]| if along_x { [r[1], r[0], r[2]] } else { r };
    let leg_h = 0.5 * h;
    let lr = (0.16 * ha).min(0.05 * 2.0 * hl).max(0.01);
    for sx in [-1.0, 1.0] {
        for y in [-0.62 * hl, 0.55 * hl] {
            b.frustum(
                Body,
                map([sx * 0.5 * ha, y, 0.0]),
                lr,
                lr,
                1.3,
                leg_h + 0.05 * h,
            );
        }
    }
    let bz = leg_h + 0.16 * h;
    b.ellipsoid(
        Body,
        map([0.0, -0.05 * hl, bz]),
        rad([0.92 * ha, 0.7 * hl, 0.2 * h]),
    );
    let neck0 = map([0.0, 0.55 * hl, bz + 0.05 * h]);
    let head = [0.0, 0.82 * hl, 0.86 * h];
    b.rod(Body, neck0, map(head), 0.45 * ha);
    b.ellipsoid(Body, map(head), rad([0.5 * ha, 0.18 * hl, 0.09 * h]));
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Body,
            map([sx * 0.3 * ha, 0.78 * hl, 0.96 * h]),
            rad([0.1 * ha, 0.04 * hl, 0.04 * h]),
        );
        b.ellipsoid(
            Interior,
            map([sx * 0.25 * ha, 0.88 * hl, 0.9 * h]),
            rad([0.05 * ha, 0.02 * hl, 0.02 * h]),
        );
    }
    b.rod(
        Body,
        map([0.0, -0.75 * hl, bz + 0.05 * h]),
        map([0.0, -0.97 * hl, bz - 0.2 * h]),
        0.12 * ha,
    );
}

/// A cauldron or large pot: a round-bellied pot on three short legs, a rim and a liquid
/// surface inside.
pub fn cauldron(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let leg = 0.12 * h;
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU;
        b.cylinder(
            Metal,
            [0.55 * hw * a.cos(), 0.55 * hd * a.sin(), 0.0],
            0.04 * hw,
            leg + 0.1 * h,
        );
    }
    let c = [0.0, 0.0, leg + 0.42 * h];
    b.ellipsoid(Body, c, [hw, hd, 0.42 * h]);
    b.frustum(
        Body,
        [0.0, 0.0, 0.88 * h],
        0.78 * hw,
        0.78 * hd,
        1.05,
        0.12 * h - 0.01,
    );
    b.frustum(
        Water,
        [0.0, 0.0, 0.9 * h],
        0.74 * hw,
        0.74 * hd,
        1.0,
        0.1 * h - 0.02,
    );
}

/// An easel: three legs (two front, one back), a ledge and a canvas leaning on it.
pub fn easel(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = [0.0, 0.0, h];
    for sx in [-1.0, 1.0] {
        b.rod(
            Frame,
            [sx * 0.8 * hw, 0.6 * hd, 0.0],
            [sx * 0.05, 0.0, h - 0.02],
            0.018,
        );
    }
    b.rod(Frame, [0.0, -0.9 * hd, 0.0], top, 0.015);
    let ledge = 0.42 * h;
    let cy = 0.6 * hd * (1.0 - ledge / h);
    b.cuboid(
        Frame,
        [-0.6 * hw, cy, ledge - 0.03],
        [0.6 * hw, cy + 0.08, ledge],
    );
    let (c0, c1) = (ledge, (ledge + 0.5 * h).min(h - 0.02));
    let yc = 0.6 * hd * (1.0 - c0 / h) + 0.03;
    b.cuboid(Canvas, [-0.55 * hw, yc - 0.02, c0], [0.55 * hw, yc, c1]);
    b.cuboid_v(
        Books,
        3,
        [-0.4 * hw, yc, c0 + 0.15 * (c1 - c0)],
        [0.1 * hw, yc + 0.003, c0 + 0.6 * (c1 - c0)],
    );
    b.cuboid_v(
        Books,
        1,
        [0.0, yc, c0 + 0.45 * (c1 - c0)],
        [0.45 * hw, yc + 0.004, c0 + 0.9 * (c1 - c0)],
    );
}

/// A grill or barbecue: a kettle or box firebox on legs, a grate of bars, a hood raised at the
/// back and side shelves when wide.
pub fn grill(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let fire = 0.62 * h;
    let wide = b.w > 1.4 * b.d;
    let bw = if wide { 0.55 * hw } else { 0.95 * hw };
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.rod(
                Metal,
                [sx * 0.8 * bw, sy * 0.7 * hd, 0.0],
                [sx * 0.6 * bw, sy * 0.5 * hd, fire - 0.1 * h],
                0.02,
            );
        }
    }
    b.cuboid(
        Body,
        [-bw, -0.9 * hd, fire - 0.15 * h],
        [bw, 0.9 * hd, fire],
    );
    let n = ((2.0 * bw / 0.05) as usize).max(4);
    for i in 0..n {
        let x = -bw + (i as f64 + 0.5) * 2.0 * bw / n as f64;
        b.rod(
            Metal,
            [x, -0.85 * hd, fire + 0.01],
            [x, 0.85 * hd, fire + 0.01],
            0.006,
        );
    }
    for i in 0..3 {
        let x = -0.5 * bw + i as f64 * 0.5 * bw;
        b.cuboid(
            Interior,
            [x - 0.08, -0.2 * hd, fire + 0.02],
            [x + 0.08, 0.2 * hd, fire + 0.04],
        );
    }
    b.cuboid(Body, [-bw, -hd, fire], [bw, -0.8 * hd, h]);
    b.cuboid(Handle, [-0.4 * bw, -hd, h - 0.03], [0.4 * bw, -0.8 * hd, h]);
    if wide {
        for sx in [-1.0, 1.0] {
            b.cuboid(
                Top,
                [sx * bw, -0.8 * hd, fire - 0.04],
                [sx * hw, 0.8 * hd, fire],
            );
        }
    }
}

/// A string instrument on a stand, its face towards +y: a waisted body of two lobes, a neck
/// with a head, strings and a sound hole (guitars, cellos, harps read as their body).
pub fn string_instrument(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.6 * hd).min(0.12);
    let bw = hw.min(0.22 * h);
    let (low, up) = ([0.0, 0.0, 0.22 * h], [0.0, 0.0, 0.42 * h]);
    b.ellipsoid(Body, low, [bw, t, 0.2 * h]);
    b.ellipsoid(Body, up, [0.78 * bw, t, 0.15 * h]);
    b.ellipsoid(Interior, [0.0, t, 0.36 * h], [0.22 * bw, 0.005, 0.22 * bw]);
    let top = [0.0, 0.3 * t, 0.9 * h];
    b.rod(Frame, [0.0, 0.3 * t, 0.5 * h], top, (0.12 * bw).max(0.012));
    b.cuboid(Frame, [-0.2 * bw, 0.0, 0.9 * h], [0.2 * bw, 0.6 * t, h]);
    for k in 0..4 {
        let x = (k as f64 - 1.5) * 0.04 * bw;
        b.rod(Metal, [x, 0.98 * t, 0.12 * h], [x, 0.5 * t, 0.9 * h], 0.002);
    }
    b.rod(Metal, [0.0, -0.9 * hd, 0.0], [0.0, -0.8 * t, 0.5 * h], 0.01);
}

/// A treadmill or similar gym machine: a long low deck with a belt, two uprights at the front
/// (+y) and a console with handles.
pub fn treadmill(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let deck = (0.12 * h).clamp(0.1, 0.25);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.1 * b.d, deck]);
    b.cuboid(
        Interior,
        [-0.8 * hw, -hd + 0.02, deck],
        [0.8 * hw, hd - 0.12 * b.d, deck + 0.01],
    );
    let y = hd - 0.12 * b.d;
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [sx * 0.9 * hw, y, deck],
            [sx * 0.9 * hw, hd - 0.03, 0.92 * h],
            0.03,
        );
        b.rod(
            Metal,
            [sx * 0.9 * hw, hd - 0.05, 0.75 * h],
            [sx * 0.9 * hw, hd - 0.35 * b.d, 0.75 * h],
            0.02,
        );
    }
    b.cuboid(Body, [-0.9 * hw, hd - 0.12, 0.88 * h], [0.9 * hw, hd, h]);
    b.cuboid(
        Screen,
        [-0.5 * hw, hd, 0.9 * h],
        [0.5 * hw, hd + 0.003, 0.98 * h],
    );
}
