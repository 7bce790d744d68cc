//! Layouts of road vehicles bigger than a car, each with its own proportions and parts: a van
//! (one tall box body with a short bonnet, a sliding side door and rear doors), a bus (a long
//! box with a row of windows down each side, a tall windscreen, a destination sign and a door),
//! a pickup (a cab over a bonnet and an open bed behind it) and a lorry (a cab in front of a
//! tall cargo box on a chassis, two rear axles). The front faces +y; everything stays inside
//! the planned size box.
use super::archetypes::Builder;
use super::materials::Role::*;

/// Gap by which windows and lamps stand proud of a body, more than a surfel's jitter.
fn proud(b: &Builder) -> f64 {
    (0.004 * b.d).clamp(0.015, 0.03)
}

/// A pair of wheels of radius `r` and tread `tw` on the axle at `y`, flush with the sides.
fn axle(b: &mut Builder, y: f64, r: f64, tw: f64) {
    let hw = b.w / 2.0;
    for sx in [-1.0, 1.0] {
        b.rod(Tyre, [sx * (hw - tw), y, r], [sx * hw, y, r], r);
        b.rod(Metal, [sx * (hw - 0.004), y, r], [sx * hw, y, r], 0.55 * r);
    }
}

/// Headlights and a grille on the front face at `y`, lamps at height `z`, the grille below.
fn front_face(b: &mut Builder, y: f64, x: f64, z: f64, lamp: f64) {
    let g = proud(b);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Light,
            [sx * x - lamp, y, z],
            [sx * x + lamp, y + g, z + 0.5 * lamp],
        );
    }
    b.cuboid(
        Interior,
        [-x + 1.3 * lamp, y, z - 0.2 * lamp],
        [x - 1.3 * lamp, y + g, z + 0.6 * lamp],
    );
}

/// Rear lamps on the back face at `y`.
fn rear_lamps(b: &mut Builder, y: f64, x: f64, z: f64, lamp: f64) {
    let g = proud(b);
    for sx in [-1.0, 1.0] {
        b.cuboid_v(
            Books,
            0,
            [sx * x - 0.4 * lamp, y - g, z],
            [sx * x + 0.4 * lamp, y, z + lamp],
        );
    }
}

/// A bumper across the face at `y` (`dir` +1 front, −1 back).
fn bumper(b: &mut Builder, y: f64, dir: f64, z: f64, t: f64) {
    let (hw, g) = (b.w / 2.0, 2.0 * proud(b));
    let (y0, y1) = if dir > 0.0 { (y - g, y) } else { (y, y + g) };
    b.cuboid(Frame, [-hw + 0.02, y0, z], [hw - 0.02, y1, z + t]);
}

/// Side windows on both sides (at |x| = `x`) from `y0` to `y1`, `z0` to `z1`, split into `n`
/// panes by pillars.
fn side_windows(b: &mut Builder, x: f64, (y0, y1): (f64, f64), (z0, z1): (f64, f64), n: usize) {
    let g = proud(b);
    let pillar = (0.1 * (y1 - y0) / n as f64).max(0.05);
    let step = (y1 - y0) / n as f64;
    for sx in [-1.0, 1.0] {
        let (xa, xb) = if sx < 0.0 { (-x - g, -x) } else { (x, x + g) };
        for i in 0..n {
            let ya = y0 + i as f64 * step + pillar / 2.0;
            b.cuboid(Glass, [xa, ya, z0], [xb, ya + step - pillar, z1]);
        }
    }
}

/// A van: one tall box body over most of its length with a short sloping bonnet in front,
/// a windscreen and cab windows, a panel side with a sliding door's seams, rear doors with
/// windows.
pub fn van(b: &mut Builder) {
    let g = proud(b);
    // Lamps, windows and bumpers stand proud of the body, all inside the size box.
    let (hw, hd, h) = (b.w / 2.0 - g, b.d / 2.0 - 2.5 * g, b.h);
    let r = (0.17 * h).min(0.08 * b.d);
    let tw = (0.12 * b.w).min(0.25);
    let zf = 0.45 * r;
    let yb = hd - 0.15 * b.d;
    b.cuboid(Body, [-hw + 0.02, -hd, zf], [hw - 0.02, yb, h]);
    // The bonnet, and the windscreen above it.
    let zh = 0.5 * h;
    b.cuboid(Body, [-hw + 0.04, yb, zf], [hw - 0.04, hd, zh]);
    b.cuboid(
        Glass,
        [-0.85 * hw, yb, 0.55 * h],
        [0.85 * hw, yb + g, 0.9 * h],
    );
    front_face(b, hd, 0.7 * hw, 0.3 * h, 0.1 * hw);
    bumper(b, hd, 1.0, zf, 0.08 * h);
    // Cab windows, then panel sides with a sliding door's seam on the right (+x).
    side_windows(
        b,
        hw - 0.02,
        (yb - 0.22 * b.d, yb - 0.02),
        (0.52 * h, 0.88 * h),
        1,
    );
    let ys = yb - 0.24 * b.d;
    for y in [ys, ys - 0.22 * b.d] {
        b.cuboid(
            Interior,
            [hw - 0.02, y - 0.01, zf + 0.1],
            [hw - 0.02 + g, y + 0.01, 0.92 * h],
        );
    }
    // Rear doors: a seam down the middle and two windows.
    b.cuboid(Interior, [-0.01, -hd - g, zf + 0.1], [0.01, -hd, 0.95 * h]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Glass,
            [sx * 0.1 * hw, -hd - g, 0.6 * h],
            [sx * 0.8 * hw, -hd, 0.88 * h],
        );
    }
    rear_lamps(b, -hd, 0.88 * hw, 0.35 * h, 0.12 * h);
    bumper(b, -hd, -1.0, zf, 0.08 * h);
    axle(b, hd - 0.2 * b.d, r, tw);
    axle(b, -hd + 0.18 * b.d, r, tw);
}

/// A bus: a long box body on small wheels, a row of side windows over its length, a tall
/// windscreen with a lit destination sign above it, a folding door on the right (+x) near the
/// front, a rear window and lamps.
pub fn bus(b: &mut Builder) {
    let g = proud(b);
    // Lamps, windows and bumpers stand proud of the body, all inside the size box.
    let (hw, hd, h) = (b.w / 2.0 - g, b.d / 2.0 - 2.5 * g, b.h);
    let r = (0.15 * h).min(0.05 * b.d);
    let tw = (0.12 * b.w).min(0.3);
    let zf = 0.4 * r;
    b.cuboid(Body, [-hw + 0.02, -hd, zf], [hw - 0.02, hd, 0.97 * h]);
    // A roof a little narrower than the body, like its rounded edges.
    b.cuboid(
        Top,
        [-hw + 0.1, -hd + 0.1, 0.97 * h],
        [hw - 0.1, hd - 0.1, h],
    );
    // A skirt of a darker band along the bottom.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.02);
        let (xa, xb) = if sx < 0.0 { (x - g, x) } else { (x, x + g) };
        b.cuboid(Frame, [xa, -hd + 0.05, zf], [xb, hd - 0.05, zf + 0.1 * h]);
    }
    // The row of windows: panes about a metre long, past the door.
    let (y0, y1) = (-hd + 0.05 * b.d, hd - 0.12 * b.d);
    let n = ((y1 - y0) / 1.15).round().max(3.0) as usize;
    side_windows(b, hw - 0.02, (y0, y1), (0.5 * h, 0.86 * h), n);
    // The door, with its glass down to the step, on the right near the front.
    let yd = hd - 0.1 * b.d;
    b.cuboid(
        Door,
        [hw - 0.02, yd - 0.05 * b.d, zf + 0.05],
        [hw - 0.02 + g, yd + 0.05 * b.d, 0.9 * h],
    );
    for k in [-1.0, 1.0] {
        let yc = yd + k * 0.025 * b.d;
        b.cuboid(
            Glass,
            [hw - 0.02 + g, yc - 0.02 * b.d, 0.2 * h],
            [hw - 0.02 + 2.0 * g, yc + 0.02 * b.d, 0.85 * h],
        );
    }
    // The front is all windscreen, destination sign and a deep bumper with lamps in it.
    b.cuboid(
        Glass,
        [-hw + 0.02, hd, 0.3 * h],
        [hw - 0.02, hd + g, 0.86 * h],
    );
    b.cuboid(
        Light,
        [-hw + 0.02, hd, 0.87 * h],
        [hw - 0.02, hd + 1.5 * g, 0.96 * h],
    );
    bumper(b, hd, 1.0, zf, 0.3 * h - zf);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Light,
            [sx * 0.75 * hw - 0.15, hd, 0.18 * h],
            [sx * 0.75 * hw + 0.15, hd + 2.5 * g, 0.25 * h],
        );
    }
    b.cuboid(
        Glass,
        [-0.8 * hw, -hd - g, 0.6 * h],
        [0.8 * hw, -hd, 0.85 * h],
    );
    rear_lamps(b, -hd, 0.85 * hw, 0.25 * h, 0.1 * h);
    bumper(b, -hd, -1.0, zf, 0.07 * h);
    axle(b, hd - 0.17 * b.d, r, tw);
    axle(b, -hd + 0.22 * b.d, r, tw);
}

/// A pickup: a low body the whole length, a bonnet in front of a cab with a windscreen and
/// side windows, and behind the cab an open bed with low walls and a tailgate.
pub fn pickup(b: &mut Builder) {
    let g = proud(b);
    // Lamps, windows and bumpers stand proud of the body, all inside the size box.
    let (hw, hd, h) = (b.w / 2.0 - g, b.d / 2.0 - 2.5 * g, b.h);
    let r = (0.2 * h).min(0.07 * b.d);
    let tw = (0.12 * b.w).min(0.25);
    let zf = 0.5 * r;
    let zl = 0.45 * h;
    let (yc0, yc1) = (-0.1 * b.d, 0.18 * b.d);
    // The lower body under the bonnet and the cab, and the bonnet.
    b.cuboid(Body, [-hw + 0.02, yc0, zf], [hw - 0.02, hd, zl]);
    b.cuboid(
        Body,
        [-hw + 0.03, yc1, zl],
        [hw - 0.03, hd - 0.02, 0.58 * h],
    );
    // The cab with its windows.
    b.cuboid(Body, [-hw + 0.05, yc0, zl], [hw - 0.05, yc1, h]);
    b.cuboid(
        Glass,
        [-0.85 * hw, yc1, 0.62 * h],
        [0.85 * hw, yc1 + g, 0.95 * h],
    );
    b.cuboid(
        Glass,
        [-0.8 * hw, yc0 - g, 0.66 * h],
        [0.8 * hw, yc0, 0.93 * h],
    );
    side_windows(
        b,
        hw - 0.05,
        (yc0 + 0.05, yc1 - 0.05),
        (0.62 * h, 0.93 * h),
        2,
    );
    // A big chrome grille between the headlights, a pickup's face.
    b.cuboid(
        Metal,
        [-0.7 * hw, hd, 0.22 * h],
        [0.7 * hw, hd + g, 0.55 * h],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Light,
            [sx * 0.85 * hw - 0.08, hd, 0.42 * h],
            [sx * 0.85 * hw + 0.08, hd + g, 0.52 * h],
        );
    }
    bumper(b, hd, 1.0, zf, 0.22 * h - zf);
    // The open bed: a floor low in the body, two side walls, the tailgate.
    let t = 0.05 * b.w;
    let (zb, zw) = (0.3 * h, 0.6 * h);
    b.cuboid(Body, [-hw + 0.02, -hd, zf], [hw - 0.02, yc0, zb]);
    b.cuboid(Interior, [-hw + t, -hd + t, zb], [hw - t, yc0, zb + 0.01]);
    for sx in [-1.0, 1.0] {
        let (xa, xb) = if sx < 0.0 {
            (-hw + 0.02, -hw + t)
        } else {
            (hw - t, hw - 0.02)
        };
        b.cuboid(Body, [xa, -hd, zb], [xb, yc0, zw]);
    }
    b.cuboid(Body, [-hw + 0.02, -hd, zb], [hw - 0.02, -hd + t, zw]);
    rear_lamps(b, -hd, 0.88 * hw, 0.45 * h, 0.1 * h);
    bumper(b, -hd, -1.0, zf, 0.08 * h);
    axle(b, hd - 0.17 * b.d, r, tw);
    axle(b, -hd + 0.2 * b.d, r, tw);
}

/// A lorry: a cab at the front (flat face, windscreen, side windows), a chassis of two rails
/// behind it carrying a tall cargo box with rear doors, one front axle and two rear axles.
pub fn lorry(b: &mut Builder) {
    let g = proud(b);
    // Lamps, windows and bumpers stand proud of the body, all inside the size box.
    let (hw, hd, h) = (b.w / 2.0 - g, b.d / 2.0 - 2.5 * g, b.h);
    let r = (0.14 * h).min(0.06 * b.d);
    let tw = (0.12 * b.w).min(0.3);
    let zf = 0.6 * r;
    let ycab = hd - 0.24 * b.d;
    // The cab.
    let zc = 0.78 * h;
    b.cuboid(Body, [-hw + 0.04, ycab, zf], [hw - 0.04, hd, zc]);
    b.cuboid(
        Glass,
        [-0.85 * hw, hd, 0.5 * zc],
        [0.85 * hw, hd + g, 0.9 * zc],
    );
    side_windows(
        b,
        hw - 0.04,
        (ycab + 0.35 * (hd - ycab), hd - 0.08),
        (0.55 * zc, 0.9 * zc),
        1,
    );
    front_face(b, hd, 0.72 * hw, 0.22 * h, 0.1 * hw);
    bumper(b, hd, 1.0, zf, 0.06 * h);
    // The chassis rails, and the cargo box on them.
    let yx = ycab - 0.02 * b.d;
    for sx in [-1.0, 1.0] {
        let x = sx * 0.5 * hw;
        b.cuboid(Frame, [x - 0.08, -hd + 0.05, zf], [x + 0.08, ycab, 2.0 * r]);
    }
    let zx = 2.0 * r + 0.02;
    b.cuboid(Canvas, [-hw, -hd, zx], [hw, yx, h]);
    // The box's rear doors: a seam, hinges and a bar.
    b.cuboid(Interior, [-0.01, -hd - g, zx + 0.05], [0.01, -hd, h - 0.05]);
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [sx * 0.25 * hw, -hd - 2.0 * g, zx + 0.1],
            [sx * 0.25 * hw, -hd - 2.0 * g, h - 0.1],
            0.02,
        );
    }
    rear_lamps(b, -hd, 0.85 * hw, zf, 0.08 * h);
    axle(b, hd - 0.12 * b.d, r, tw);
    for y in [-hd + 0.15 * b.d, -hd + 0.15 * b.d + 2.3 * r] {
        axle(b, y, r, tw);
    }
}
