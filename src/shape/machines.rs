//! Layouts of the commonest machines of a kitchen, an office and a shop, each by what it shows
//! from the front (+y): a dishwasher's full-height door under a control strip, a microwave's
//! window door beside a keypad, an espresso machine's group head over a drip tray, a till's
//! screen above its cash drawer, a printer's paper trays.
use super::archetypes::Builder;
use super::laundry::BACK;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};
use std::f64::consts::FRAC_PI_2;

/// A disc of radius `r` (times `az` in height) and thickness `t` facing +y, its back at `y`.
fn front_disc(b: &mut Builder, role: super::materials::Role, c: [f64; 3], r: f64, az: f64, t: f64) {
    b.revolved(role, 0, c, rot_x(-FRAC_PI_2), az, frustum_profile(r, r, t));
}

/// A horizontal bar handle on two stand-offs, `x0..x1` at height `z`, in front of face `y`.
fn bar_handle(b: &mut Builder, x0: f64, x1: f64, y: f64, z: f64) {
    let r = 0.009;
    let yb = y + 0.022;
    b.rod(Handle, [x0, yb, z], [x1, yb, z], r);
    for x in [x0 + 0.01, x1 - 0.01] {
        b.rod(Handle, [x, y, z], [x, yb, z], 0.006);
    }
}

/// A grid of `cols` × `rows` small keys on the front plane `y`, in `[x0, x1] × [z0, z1]`.
fn keypad(b: &mut Builder, x: [f64; 2], z: [f64; 2], y: f64, cols: usize, rows: usize) {
    let (kw, kh) = ((x[1] - x[0]) / cols as f64, (z[1] - z[0]) / rows as f64);
    for i in 0..cols {
        for j in 0..rows {
            let (x0, z0) = (x[0] + i as f64 * kw, z[0] + j as f64 * kh);
            b.cuboid(
                Keys,
                [x0 + 0.15 * kw, y, z0 + 0.15 * kh],
                [x0 + 0.85 * kw, y + 0.006, z0 + 0.85 * kh],
            );
        }
    }
}

/// A small appliance's back at `y` (its body above `z0`): a grid of vent slots, a rating
/// plate and a power cord leaving it and falling to the floor behind.
fn vented_back(b: &mut Builder, y: f64, z0: f64) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (x0, x1) = (-0.35 * b.w, 0.1 * b.w);
    for j in 0..4 {
        let z = z0 + (0.45 + 0.1 * j as f64) * (h - z0);
        let n = 8;
        for i in 0..n {
            let x = x0 + (i as f64 + 0.5) / n as f64 * (x1 - x0);
            b.cuboid(
                Interior,
                [x - 0.004, y - 0.002, z - 0.015],
                [x + 0.004, y, z + 0.015],
            );
        }
    }
    b.cuboid(
        Canvas,
        [0.18 * b.w, y - 0.002, 0.5 * h],
        [0.36 * b.w, y, 0.75 * h],
    );
    b.polyline(
        Frame,
        &[
            [0.3 * b.w, y, z0 + 0.2 * (h - z0)],
            [0.3 * b.w, -hd + 0.005, z0 + 0.1 * (h - z0)],
            [0.38 * b.w.min(hw), -hd + 0.005, 0.005],
        ],
        0.004,
    );
}

/// A dishwasher: one full-height door with a dark control strip along its top, a bar handle
/// under the strip and a recessed kick plate.
pub fn dishwasher(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.045;
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd + BACK, 0.0],
        [hw - 0.02, face - 0.03, 0.1],
    );
    b.cuboid(Body, [-hw, -hd + BACK, 0.1], [hw, face, h]);
    b.cuboid(
        Door,
        [-hw + 0.005, face, 0.1],
        [hw - 0.005, face + 0.02, h - 0.005],
    );
    let strip = (0.12 * h).clamp(0.06, 0.11);
    b.cuboid(
        Screen,
        [-hw + 0.01, face + 0.02, h - strip],
        [hw - 0.01, face + 0.023, h - 0.01],
    );
    for k in 0..4 {
        let x = 0.08 * b.w + k as f64 * 0.09 * b.w;
        b.cuboid(
            Light,
            [x - 0.012, face + 0.023, h - 0.6 * strip],
            [x + 0.012, face + 0.025, h - 0.4 * strip],
        );
    }
    bar_handle(b, -0.32 * b.w, 0.32 * b.w, face + 0.02, h - strip - 0.05);
    // The back: the tub in its insulating blanket, hoses and cord along the floor.
    super::backs::dishwasher_back(b);
}

/// A counter-top microwave: a window door on the left with a pull handle, a control column on
/// the right (display over a keypad), on four small feet.
pub fn microwave(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let feet = 0.012;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(
                Metal,
                [sx * (hw - 0.04), sy * (hd - 0.05), 0.0],
                0.012,
                feet,
            );
        }
    }
    let face = hd - 0.03;
    let back = -hd + 0.015;
    b.cuboid(Body, [-hw, back, feet], [hw, face, h]);
    vented_back(b, back, feet);
    let xd = hw - 0.27 * b.w;
    b.cuboid(
        Door,
        [-hw + 0.01, face, feet + 0.01],
        [xd, face + 0.012, h - 0.01],
    );
    b.cuboid(
        Screen,
        [-hw + 0.05, face + 0.012, feet + 0.05],
        [xd - 0.07, face + 0.015, h - 0.05],
    );
    b.rod(
        Handle,
        [xd - 0.035, face + 0.025, feet + 0.05],
        [xd - 0.035, face + 0.025, h - 0.05],
        0.008,
    );
    for z in [feet + 0.05, h - 0.05] {
        b.rod(
            Handle,
            [xd - 0.035, face + 0.012, z],
            [xd - 0.035, face + 0.025, z],
            0.005,
        );
    }
    let (x0, x1) = (xd + 0.025, hw - 0.025);
    b.cuboid(Screen, [x0, face, h - 0.09], [x1, face + 0.006, h - 0.04]);
    keypad(b, [x0, x1], [feet + 0.05, h - 0.11], face, 3, 4);
}

/// An espresso machine: a body whose front steps back over a drip tray, a group head with its
/// portafilter handle, a cup on the tray, a steam wand and a bean hopper on top.
pub fn coffee_machine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let hopper = if h > 0.35 { 0.28 * h } else { 0.0 };
    let top = h - hopper;
    let back = hd - 0.55 * b.d;
    let base = 0.12 * top;
    let head = 0.62 * top;
    // Base with the drip tray, a back tower, an upper head reaching to the front.
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.02, base]);
    b.cuboid(
        Metal,
        [-0.4 * b.w, back, base],
        [0.4 * b.w, hd - 0.03, base + 0.012],
    );
    b.cuboid(Body, [-hw, -hd, base], [hw, back, top]);
    b.cuboid(
        Interior,
        [-hw + 0.02, back, base],
        [hw - 0.02, back + 0.003, head],
    );
    b.cuboid(Body, [-hw, back, head], [hw, hd - 0.02, top]);
    b.cuboid(
        Metal,
        [-hw + 0.01, hd - 0.02, head + 0.02],
        [hw - 0.01, hd - 0.012, top - 0.02],
    );
    // Two pressure gauges on the front.
    for x in [-0.22 * b.w, 0.22 * b.w] {
        front_disc(
            b,
            Canvas,
            [x, hd - 0.012, 0.5 * (head + top)],
            0.028,
            1.0,
            0.01,
        );
    }
    // Group head, portafilter and its handle towards the front.
    let yc = 0.5 * (back + hd);
    b.cylinder(Metal, [0.0, yc, head - 0.05], 0.045, 0.05);
    b.cylinder(Metal, [0.0, yc, head - 0.08], 0.04, 0.03);
    b.rod(
        Handle,
        [0.0, yc + 0.03, head - 0.065],
        [0.0, hd - 0.005, head - 0.09],
        0.012,
    );
    // A cup under it, a steam wand beside it.
    b.frustum(Canvas, [0.0, yc, base + 0.012], 0.03, 0.03, 1.2, 0.06);
    b.rod(
        Metal,
        [0.36 * b.w, yc, head],
        [0.38 * b.w, yc + 0.03, base + 0.06],
        0.006,
    );
    if hopper > 0.0 {
        // A smoked glass hopper, half full of beans, under a lid.
        let (x, y, r) = (-0.25 * b.w, -0.1 * b.d, 0.1 * b.w.min(b.d));
        b.frustum(Interior, [x, y, top], 0.9 * r, 0.9 * r, 1.2, 0.45 * hopper);
        b.frustum(Pane, [x, y, top], r, r, 1.5, 0.85 * hopper);
        b.frustum(
            Handle,
            [x, y, top + 0.85 * hopper],
            1.55 * r,
            1.55 * r,
            0.8,
            0.15 * hopper,
        );
    }
}

/// A cash register (till): a cash drawer with a pull, a sloping keyboard above it, a screen on a
/// neck at the back facing the front, and a receipt slot with its paper.
pub fn till(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let dz = 0.32 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.015, dz]);
    b.cuboid(
        Door,
        [-hw + 0.015, hd - 0.015, 0.02],
        [hw - 0.015, hd, dz - 0.02],
    );
    b.cuboid(
        Interior,
        [-0.15 * b.w, hd - 0.002, 0.45 * dz],
        [0.15 * b.w, hd, 0.6 * dz],
    );
    // Keyboard: a wedge rising to the back, with its keys on the slope.
    let (y0, y1) = (hd - 0.02, -hd + 0.35 * b.d);
    let rise = 0.18 * h;
    let tilt = (rise / (y0 - y1)).atan();
    let len = ((y0 - y1).powi(2) + rise * rise).sqrt();
    let rot = rot_x(-tilt);
    let c = [0.0, 0.5 * (y0 + y1), dz + 0.5 * rise];
    b.cuboid(
        Body,
        [-hw + 0.01, y1, dz],
        [hw - 0.01, y0 - 0.04, dz + 0.5 * rise],
    );
    b.slab(Body, c, [hw - 0.01, 0.5 * len, 0.012], rot);
    let (cols, rows) = (6, 4);
    for i in 0..cols {
        for j in 0..rows {
            let u = -0.8 * hw + (i as f64 + 0.5) * 1.6 * hw / cols as f64;
            let v = -0.4 * len + (j as f64 + 0.5) * 0.8 * len / rows as f64;
            let p = super::parts::mul(&rot, [u, v, 0.016]);
            b.slab(
                Keys,
                [c[0] + p[0], c[1] + p[1], c[2] + p[2]],
                [
                    0.35 * 1.6 * hw / cols as f64,
                    0.3 * 0.8 * len / rows as f64,
                    0.006,
                ],
                rot,
            );
        }
    }
    // The screen on its neck, its face to the front.
    let (zs0, zs1) = (dz + rise + 0.06 * h, h);
    let ys = -0.02 * b.d;
    b.cylinder(Metal, [0.0, ys, dz], 0.02, zs0 - dz + 0.02);
    b.cuboid(Body, [-0.36 * b.w, ys - 0.03, zs0], [0.36 * b.w, ys, zs1]);
    b.cuboid(
        Screen,
        [-0.32 * b.w, ys, zs0 + 0.015],
        [0.32 * b.w, ys + 0.004, zs1 - 0.015],
    );
    // Receipt printer at the back right with a curl of paper.
    b.cuboid(
        Body,
        [0.2 * b.w, -hd, dz],
        [hw - 0.01, -hd + 0.12 * b.d, dz + 0.5 * rise],
    );
    b.cuboid(
        Canvas,
        [0.25 * b.w, -hd + 0.03, dz + 0.5 * rise],
        [hw - 0.05, -hd + 0.032, dz + 0.5 * rise + 0.05],
    );
}

/// An office printer or copier: a body on paper drawers, a scanner lid on top with a control
/// panel tilted at the front right, an output slot with a sheet in it.
pub fn printer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.02;
    let lid = 0.12 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, face, h - lid]);
    // Paper drawers with their grips.
    let drawers = if h > 0.6 { 3 } else { 1 };
    let dh = 0.45 * (h - lid) / drawers as f64;
    for k in 0..drawers {
        let z0 = 0.02 + k as f64 * dh;
        b.cuboid(
            Door,
            [-hw + 0.015, face, z0 + 0.004],
            [hw - 0.015, hd, z0 + dh - 0.004],
        );
        b.cuboid(
            Interior,
            [-0.12 * b.w, hd - 0.001, z0 + 0.6 * dh],
            [0.12 * b.w, hd, z0 + 0.8 * dh],
        );
    }
    // Output slot under the lid, with a sheet of paper sticking out.
    let zo = h - lid - 0.3 * (h - lid);
    b.cuboid(
        Interior,
        [-0.4 * b.w, face - 0.001, zo],
        [0.3 * b.w, face, zo + 0.05],
    );
    b.cuboid(
        Canvas,
        [-0.3 * b.w, face - 0.15 * b.d, zo + 0.01],
        [0.2 * b.w, face, zo + 0.014],
    );
    // Scanner lid (dark) and the control panel.
    b.cuboid(Top, [-hw, -hd, h - lid], [hw, hd - 0.06, h]);
    let c = [0.28 * b.w, hd - 0.05, h - lid - 0.01];
    let rot = rot_x(-0.5);
    b.slab(Top, c, [0.18 * b.w, 0.05, 0.02], rot);
    let p = super::parts::mul(&rot, [0.0, 0.0, 0.021]);
    b.slab(
        Screen,
        [c[0] + p[0], c[1] + p[1], c[2] + p[2]],
        [0.15 * b.w, 0.035, 0.002],
        rot,
    );
}
