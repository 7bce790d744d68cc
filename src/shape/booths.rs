//! Layouts of booths, gates and studio sets that people walk into or through: a fitting room
//! (three walls and a pleated curtain on a rail), a photo booth (a cabinet with a curtained
//! doorway, a screen and a photo slot), a walk-through security gate (two pillars under a
//! lintel), a tripod turnstile (a pedestal with three arms round a tilted hub) and a photo
//! backdrop (a paper sweep hanging from a bar between two stands and curving onto the floor).
//! The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::drapes::curtain;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};

/// A fitting room: back and side walls, a curtain across the open front on a rail, a stool
/// and a hook inside.
pub fn fitting_room(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.04;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, -hd + t, h]);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Body, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, hd, h]);
    }
    b.cuboid(Frame, [-hw, hd - 0.06, h - 0.08], [hw, hd, h]);
    let y = hd - 0.1;
    // The curtain, drawn over two thirds of the opening.
    curtain(b, -hw + t, hw - t - 0.3 * b.w, y, 0.05, h - 0.12);
    b.cuboid(Interior, [-hw + t, -hd + t, 0.0], [hw - t, hd - 0.12, 0.01]);
    b.cylinder(Seat, [0.5 * hw, -0.3 * hd, 0.0], 0.15, 0.45);
    b.cuboid(
        Handle,
        [0.3 * hw, -hd + t, 1.6],
        [0.4 * hw, -hd + t + 0.05, 1.65],
    );
}

/// A photo booth: a cabinet with a doorway on its front left hung with a curtain, a stool
/// inside, the right side with a screen, a photo slot and a sign lit along its top.
pub fn photo_booth(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.05;
    let xd = -hw + 0.55 * b.w;
    let top = 0.86 * h;
    // The cabinet: back, both ends, the machine's body on the right and a roof.
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, -hd + t, top]);
    b.cuboid(Body, [-hw, -hd, 0.0], [-hw + t, hd, top]);
    b.cuboid(Body, [xd, -hd, 0.0], [hw, hd, top]);
    b.cuboid(Top, [-hw, -hd, top], [hw, hd, h]);
    b.cuboid(
        Light,
        [-hw + 0.05, hd - 0.01, top + 0.02],
        [hw - 0.05, hd, h - 0.02],
    );
    curtain(b, -hw + t, xd, hd - 0.08, 0.3, top - 0.04);
    b.cylinder(Seat, [-hw + 0.3 * b.w, 0.0, 0.0], 0.16, 0.5);
    b.cuboid(Interior, [-hw + t, -hd + t, 0.0], [xd, hd - 0.1, 0.01]);
    // The machine's front: a screen, a slot where the prints come out, a coin box.
    let (x0, x1) = (xd + 0.08, hw - 0.08);
    b.cuboid(Screen, [x0, hd - 0.005, 0.55 * h], [x1, hd, 0.75 * h]);
    b.cuboid(
        Interior,
        [x0 + 0.05, hd - 0.005, 0.3 * h],
        [x1 - 0.05, hd, 0.33 * h],
    );
    b.cuboid(Handle, [x1 - 0.12, hd - 0.02, 0.42 * h], [x1, hd, 0.48 * h]);
}

/// A walk-through security gate: two slim pillars joined by a lintel carrying a light bar.
pub fn security_gate(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.12 * b.w).min(0.12);
    let lintel = 0.1 * h;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Body, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, hd, h - lintel]);
        b.cuboid(
            Frame,
            [x - t / 2.0 - 0.005, -hd, 0.0],
            [x + t / 2.0 + 0.005, hd, 0.04],
        );
    }
    b.cuboid(Top, [-hw, -hd, h - lintel], [hw, hd, h]);
    b.cuboid(
        Light,
        [-0.3 * hw, hd - 0.005, h - 0.7 * lintel],
        [0.3 * hw, hd, h - 0.3 * lintel],
    );
    b.cuboid(
        Screen,
        [hw - t, hd - 0.005, h - 1.8 * lintel],
        [hw - 0.01, hd, h - 1.2 * lintel],
    );
}

/// A tripod turnstile: a pedestal on the left with a sloping top, a hub on its right side whose
/// axis leans towards the front, and three arms at 120° round it, one level across the
/// passage.
pub fn turnstile(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pw = 0.28 * b.w;
    let px = -hw + pw;
    let ph = 0.9 * h;
    b.cuboid(Body, [-hw, -0.6 * hd, 0.0], [px, 0.6 * hd, ph]);
    b.cuboid(Top, [-hw, -0.6 * hd, ph], [px, 0.6 * hd, h]);
    b.cuboid(
        Light,
        [-hw + 0.04, 0.6 * hd, 0.8 * h],
        [px - 0.04, 0.6 * hd + 0.005, 0.86 * h],
    );
    // The hub's axis points out over the passage and down at 45°; the arms lie on a cone
    // round it, one level across the passage and two reaching down to either side.
    let beta = std::f64::consts::FRAC_PI_4;
    let (sb, cb) = beta.sin_cos();
    let axis = [cb, 0.0, -sb];
    let hub = [px + 0.04, 0.0, 0.78 * h];
    b.revolved(
        Metal,
        0,
        [px, 0.0, hub[2]],
        frame_along(axis),
        1.0,
        frustum_profile(0.07, 0.05, 0.06),
    );
    let len = (hw - hub[0] - 0.01).min((hd - 0.02) / (0.866 * sb));
    for k in 0..3 {
        let th = k as f64 * 2.0 * std::f64::consts::PI / 3.0;
        let (s, c) = th.sin_cos();
        // The level arm [1, 0, 0] turned by `th` about the axis (Rodrigues).
        let dir = [c + cb * cb * (1.0 - c), -sb * s, -cb * sb * (1.0 - c)];
        let end = [0, 1, 2].map(|i| hub[i] + len * dir[i]);
        b.rod(Metal, hub, end, 0.018);
    }
}

/// A photo backdrop: two light stands on tripod feet, a crossbar between their tops carrying
/// a paper roll, and the paper hanging from it and sweeping forward onto the floor.
pub fn photo_backdrop(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let roll_r = (0.05 * h).min(0.2 * hd).min(0.06);
    let yb = -hd + 0.12 * b.d;
    let zr = h - roll_r;
    // Stands: a pole on three feet at each end.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.04);
        b.rod(Metal, [x, yb, 0.25], [x, yb, h - 0.01], 0.015);
        for k in 0..3 {
            let a = std::f64::consts::PI / 2.0 + k as f64 * 2.0 * std::f64::consts::PI / 3.0;
            let reach = 0.9 * (hd - 0.01 + yb).abs().min(0.3);
            let foot = [x + 0.03 * sx * a.cos().abs(), yb + reach * a.sin(), 0.0];
            let foot = [foot[0].clamp(-hw, hw), foot[1].clamp(-hd, hd), 0.0];
            b.rod(Metal, [x, yb, 0.25], foot, 0.01);
        }
    }
    b.rod(Metal, [-hw + 0.02, yb, zr], [hw - 0.02, yb, zr], 0.012);
    // The paper roll and the sheet off its front.
    let (x0, x1) = (-hw + 0.1, hw - 0.1);
    b.revolved(
        Canvas,
        0,
        [x0, yb, zr],
        frame_along([1.0, 0.0, 0.0]),
        1.0,
        frustum_profile(roll_r, roll_r, x1 - x0),
    );
    let t = 0.004;
    let ys = yb + roll_r;
    let r = (hd - ys).min(0.5 * h).max(0.05) * 0.6;
    let half_w = 0.5 * (x1 - x0);
    b.cuboid(Canvas, [x0, ys, r], [x1, ys + t, zr]);
    // The sweep: a quarter circle of narrow strips from upright to flat.
    let n = 8;
    for k in 0..n {
        let a = (k as f64 + 0.5) / n as f64 * std::f64::consts::FRAC_PI_2;
        let c = [0.0, ys + r - r * a.cos(), r - r * a.sin()];
        let strip = std::f64::consts::FRAC_PI_2 * r / n as f64;
        b.slab(Canvas, c, [half_w, t / 2.0, 0.55 * strip], rot_x(a));
    }
    b.cuboid(Canvas, [x0, ys + r, 0.0], [x1, hd, t]);
}
