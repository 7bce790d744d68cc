//! Layouts of road vehicles bigger than a car, each with its own proportions and parts: a van
//! (one tall box body with a short bonnet, a sliding side door and rear doors), a bus (a long
//! box with a row of windows down each side, a tall windscreen, a destination sign and a door),
//! a pickup (a cab over a bonnet and an open bed behind it) and a lorry (a cab in front of a
//! tall cargo box on a chassis, two rear axles). The front faces +y; everything stays inside
//! the planned size box. Their shared measures ([`Chassis`]), wheels, faces and box body are
//! `pub(super)` so the transit vehicles of `transit.rs` are built from the same parts.
use super::archetypes::Builder;
use super::materials::Role::*;

/// Gap by which windows and lamps stand proud of a body, more than a surfel's jitter.
fn proud(b: &Builder) -> f64 {
    (0.004 * b.d).clamp(0.015, 0.03)
}

/// The measures every road vehicle shares: the proud gap `g`, the half width `hw` and half
/// depth `hd` its body keeps so lamps, windows and bumpers stand proud inside the size box,
/// the height `h`, the wheel radius `r`, the tread `tw` and the floor height `zf`.
pub(super) struct Chassis {
    pub g: f64,
    pub hw: f64,
    pub hd: f64,
    pub h: f64,
    pub r: f64,
    pub tw: f64,
    pub zf: f64,
}

/// The chassis of a vehicle whose wheels are `rh` of its height but at most `rd` of its
/// length, with treads of at most `tread` metres and the floor `zf` wheel radii up.
pub(super) fn chassis(b: &Builder, rh: f64, rd: f64, tread: f64, zf: f64) -> Chassis {
    let g = proud(b);
    let (hw, hd, h) = (b.w / 2.0 - g, b.d / 2.0 - 2.5 * g, b.h);
    let r = (rh * h).min(rd * b.d);
    let tw = (0.12 * b.w).min(tread);
    Chassis {
        g,
        hw,
        hd,
        h,
        r,
        tw,
        zf: zf * r,
    }
}

/// The box body from `y0` to `y1`, from the floor up to `z1`, inset `inset` from the sides.
pub(super) fn box_body(b: &mut Builder, c: &Chassis, (y0, y1): (f64, f64), z1: f64, inset: f64) {
    b.cuboid(Body, [-c.hw + inset, y0, c.zf], [c.hw - inset, y1, z1]);
}

/// A pair of wheels of radius `r` and tread `tw` on the axle at `y`, flush with the sides.
pub(super) fn axle(b: &mut Builder, y: f64, r: f64, tw: f64) {
    let hw = b.w / 2.0;
    axle_between(b, (-hw, hw), y, r, tw);
}

/// A pair of wheels flush with sides at `x0` and `x1` (a body narrower than its size box).
pub(super) fn axle_between(b: &mut Builder, (x0, x1): (f64, f64), y: f64, r: f64, tw: f64) {
    for (x, sx) in [(x0, -1.0), (x1, 1.0)] {
        b.rod(Tyre, [x - sx * tw, y, r], [x, y, r], r);
        b.rod(Metal, [x - sx * 0.004, y, r], [x, y, r], 0.55 * r);
    }
}

/// The back of a vehicle at `-c.hd`: rear lamps `x` out from the middle at height `z` (of
/// size `lamp`) and a bumper of height `t` on the floor line.
pub(super) fn rear(b: &mut Builder, c: &Chassis, x: f64, z: f64, lamp: f64, t: f64) {
    rear_lamps(b, -c.hd, x, z, lamp);
    bumper(b, -c.hd, -1.0, c.zf, t);
}

/// Headlights and a grille on the front face at `y`, lamps at height `z`, the grille below.
pub(super) fn front_face(b: &mut Builder, y: f64, x: f64, z: f64, lamp: f64) {
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
pub(super) fn rear_lamps(b: &mut Builder, y: f64, x: f64, z: f64, lamp: f64) {
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
pub(super) fn bumper(b: &mut Builder, y: f64, dir: f64, z: f64, t: f64) {
    let (hw, g) = (b.w / 2.0, 2.0 * proud(b));
    let (y0, y1) = if dir > 0.0 { (y - g, y) } else { (y, y + g) };
    b.cuboid(Frame, [-hw + 0.02, y0, z], [hw - 0.02, y1, z + t]);
}

/// Side windows on both sides (at |x| = `x`) from `y0` to `y1`, `z0` to `z1`, split into `n`
/// panes by pillars.
pub(super) fn side_windows(
    b: &mut Builder,
    x: f64,
    (y0, y1): (f64, f64),
    (z0, z1): (f64, f64),
    n: usize,
) {
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

/// A flat-faced cab from `ycab` to the front, `zc` high and inset `inset` from the sides: a
/// windscreen, `panes` side windows from `from` of its length on to the front, headlights and a
/// grille at height `lamps`, and the front bumper (a lorry's, a fire engine's).
#[allow(clippy::too_many_arguments, reason = "what one cab differs in")]
pub(super) fn flat_cab(
    b: &mut Builder,
    c: &Chassis,
    ycab: f64,
    zc: f64,
    inset: f64,
    from: f64,
    panes: usize,
    lamps: f64,
) {
    let (hw, hd) = (c.hw, c.hd);
    b.cuboid(Body, [-hw + inset, ycab, c.zf], [hw - inset, hd, zc]);
    b.cuboid(
        Glass,
        [-0.85 * hw, hd, 0.5 * zc],
        [0.85 * hw, hd + c.g, 0.9 * zc],
    );
    side_windows(
        b,
        hw - inset,
        (ycab + from * (hd - ycab), hd - 0.08),
        (0.55 * zc, 0.9 * zc),
        panes,
    );
    front_face(b, hd, 0.72 * hw, lamps, 0.1 * hw);
    bumper(b, hd, 1.0, c.zf, 0.06 * c.h);
}

/// A van: one tall box body over most of its length with a short sloping bonnet in front,
/// a windscreen and cab windows, a panel side with a sliding door's seams, rear doors with
/// windows.
pub fn van(b: &mut Builder) {
    let c = chassis(b, 0.17, 0.08, 0.25, 0.45);
    let yb = van_cab(b, &c, c.h);
    let (g, hw, hd, h, zf) = (c.g, c.hw, c.hd, c.h, c.zf);
    // Panel sides with a sliding door's seam on the right (+x).
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
    rear(b, &c, 0.88 * hw, 0.35 * h, 0.12 * h, 0.08 * h);
    axle(b, hd - 0.2 * b.d, c.r, c.tw);
    axle(b, -hd + 0.18 * b.d, c.r, c.tw);
}

/// A van's tall box body with a short bonnet, a windscreen, the face and front bumper, and cab
/// windows on both sides, the box's roof at `roof`; returns the y where the bonnet meets the box.
pub(super) fn van_cab(b: &mut Builder, c: &Chassis, roof: f64) -> f64 {
    let (g, hw, hd, h) = (c.g, c.hw, c.hd, c.h);
    let yb = hd - 0.15 * b.d;
    box_body(b, c, (-hd, yb), roof, 0.02);
    // The bonnet, and the windscreen above it.
    b.cuboid(Body, [-hw + 0.04, yb, c.zf], [hw - 0.04, hd, 0.5 * h]);
    b.cuboid(
        Glass,
        [-0.85 * hw, yb, 0.55 * h],
        [0.85 * hw, yb + g, 0.9 * h],
    );
    front_face(b, hd, 0.7 * hw, 0.3 * h, 0.1 * hw);
    bumper(b, hd, 1.0, c.zf, 0.08 * h);
    side_windows(
        b,
        hw - 0.02,
        (yb - 0.22 * b.d, yb - 0.02),
        (0.52 * h, 0.88 * h),
        1,
    );
    yb
}

/// A bus: a long box body on small wheels, a row of side windows over its length, a tall
/// windscreen with a lit destination sign above it, a folding door on the right (+x) near the
/// front, a rear window and lamps.
pub fn bus(b: &mut Builder) {
    let c = chassis(b, 0.15, 0.05, 0.3, 0.4);
    let (g, hw, hd, h, zf) = (c.g, c.hw, c.hd, c.h, c.zf);
    box_body(b, &c, (-hd, hd), 0.97 * h, 0.02);
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
    rear(b, &c, 0.85 * hw, 0.25 * h, 0.1 * h, 0.07 * h);
    axle(b, hd - 0.17 * b.d, c.r, c.tw);
    axle(b, -hd + 0.22 * b.d, c.r, c.tw);
}

/// A pickup: a low body the whole length, a bonnet in front of a cab with a windscreen and
/// side windows, and behind the cab an open bed with low walls and a tailgate.
pub fn pickup(b: &mut Builder) {
    let c = chassis(b, 0.2, 0.07, 0.25, 0.5);
    let (g, hw, hd, h, zf) = (c.g, c.hw, c.hd, c.h, c.zf);
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
    rear(b, &c, 0.88 * hw, 0.45 * h, 0.1 * h, 0.08 * h);
    axle(b, hd - 0.17 * b.d, c.r, c.tw);
    axle(b, -hd + 0.2 * b.d, c.r, c.tw);
}

/// A lorry: a cab at the front (flat face, windscreen, side windows), a chassis of two rails
/// behind it carrying a tall cargo box with rear doors, one front axle and two rear axles.
pub fn lorry(b: &mut Builder) {
    let c = chassis(b, 0.14, 0.06, 0.3, 0.6);
    let (g, hw, hd, h, zf, r, tw) = (c.g, c.hw, c.hd, c.h, c.zf, c.r, c.tw);
    let ycab = hd - 0.24 * b.d;
    // The cab.
    let zc = 0.78 * h;
    flat_cab(b, &c, ycab, zc, 0.04, 0.35, 1, 0.22 * h);
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
