//! Layouts of things that used to borrow another thing's drawing and read as it: a bicycle
//! repair stand (once a microphone stand: now a stout tripod post with a tool tray and a big
//! jawed clamp on a forward arm), a school desk (once an office desk with drawers: now a small
//! top on a metal tube frame with a book shelf under it) and a boxing ring (once a stage: now a
//! raised canvas inside corner posts and three ropes a side) and a chest freezer (once a
//! strapped treasure chest: now a white cabinet under a lid with a handle, a dial and lights),
//! a dartboard (once a narrow whiteboard), stepping stones (once a rug), a cooler (once a
//! treasure chest) and a standing desk (once an office desk with drawers). The front faces +y;
//! each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use std::f64::consts::TAU;

/// A bicycle repair stand: three splayed legs with rubber feet under a collar, a thick post
/// with a lock ring where its upper tube slides in, a round tool tray at hand height with tools
/// in it, and at the top an arm angled forward and up to a clamp head: a body between two
/// rubber jaws, a spindle and a red lever out of its back.
pub fn repair_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let reach = 0.95 * hw.min(hd);
    let r = (0.022 * h).clamp(0.018, 0.03);
    let collar = 0.28 * h;
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU + TAU / 4.0 + TAU / 6.0;
        let foot = [reach * a.cos(), reach * a.sin(), 0.02];
        b.rod(Frame, [0.0, 0.0, collar], foot, 0.7 * r);
        b.cylinder(Tyre, [foot[0], foot[1], 0.0], 1.4 * r, 0.025);
    }
    b.cylinder(Metal, [0.0, 0.0, collar - 0.04], 1.6 * r, 0.08);
    // The post: a lower tube, a lock ring, a thinner upper tube.
    let (mid, top) = (0.55 * h, 0.74 * h);
    b.cylinder(Frame, [0.0, 0.0, 0.0], r, mid);
    b.cylinder(Handle, [0.0, 0.0, mid - 0.02], 1.5 * r, 0.04);
    b.cylinder(Metal, [0.0, 0.0, mid], 0.75 * r, top - mid);
    // The tool tray: a shallow round dish on a bracket, beside the post, tools lying in it.
    let tr = (0.55 * hw).min(0.18);
    let zt = 0.5 * h;
    let tc = [0.0, -(r + tr), zt];
    b.rod(
        Metal,
        [0.0, 0.0, zt - 0.01],
        [tc[0], tc[1], zt - 0.01],
        0.01,
    );
    b.frustum(
        Top,
        [tc[0], tc[1], zt - 0.015],
        0.9 * tr,
        0.9 * tr,
        1.1,
        0.03,
    );
    for (k, l) in [(0.0, 0.8), (0.5, 0.6), (1.0, 0.7)] {
        let a = 0.6 + 1.1 * k;
        let (c, s) = (l * 0.8 * tr * f64::cos(a), l * 0.8 * tr * f64::sin(a));
        b.rod(
            Handle,
            [tc[0] - c, tc[1] - s, zt + 0.02],
            [tc[0] + c, tc[1] + s, zt + 0.02],
            0.008,
        );
    }
    // The arm, forward and up from the post's top to the clamp head.
    let jaw = (0.07 * h).clamp(0.06, 0.1);
    let head = [0.0, (0.75 * hd).min(0.35 * h), h - 1.1 * jaw];
    b.rod(Frame, [0.0, 0.0, top - 0.02], head, 0.8 * r);
    b.ellipsoid(Metal, [0.0, 0.0, top], [1.2 * r, 1.2 * r, 1.2 * r]);
    // The clamp head: a body, two rubber jaws rising either side of an open gap across it,
    // the spindle and lever out of its back.
    let bw = 1.6 * jaw;
    b.cuboid(
        Handle,
        [-0.5 * bw, head[1] - 0.5 * jaw, head[2] - 0.4 * jaw],
        [0.5 * bw, head[1] + 0.5 * jaw, head[2] + 0.3 * jaw],
    );
    for sy in [-1.0, 1.0] {
        let y = head[1] + sy * 0.4 * jaw;
        b.cuboid(
            Tyre,
            [-0.45 * bw, y - 0.1 * jaw, head[2] + 0.3 * jaw],
            [0.45 * bw, y + 0.1 * jaw, h],
        );
    }
    b.rod(
        Metal,
        [0.0, head[1] - 0.5 * jaw, head[2]],
        [0.0, head[1] - 1.1 * jaw, head[2]],
        0.01,
    );
    b.rod(
        Handle,
        [0.0, head[1] - 1.1 * jaw, head[2]],
        [0.0, head[1] - 1.3 * jaw, head[2] - 0.9 * jaw],
        0.015,
    );
}

/// A school desk: a small top on a welded metal frame (a tube leg at each corner, foot rails
/// joining front and back legs, an apron rail under the top), an open book shelf under the top
/// with a back panel, no drawers.
pub fn school_desk(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.025;
    let zt = h - t;
    b.cuboid(Top, [-hw, -hd, zt], [hw, hd, h]);
    let r = 0.013;
    let (lx, ly) = (hw - 0.04, hd - 0.04);
    for sx in [-1.0, 1.0] {
        let x = sx * lx;
        for sy in [-1.0, 1.0] {
            b.cylinder(Metal, [x, sy * ly, 0.0], r, zt);
        }
        b.rod(Metal, [x, -ly, 0.06], [x, ly, 0.06], 0.9 * r);
        b.rod(Metal, [x, -ly, zt - 0.03], [x, ly, zt - 0.03], 0.9 * r);
    }
    b.rod(Metal, [-lx, -ly, zt - 0.03], [lx, -ly, zt - 0.03], 0.9 * r);
    // The book shelf: a tray under the top, open at the front, a back and sides of sheet.
    let zs = zt - (0.2 * h).clamp(0.1, 0.16);
    let (sx0, sx1) = (-lx + r, lx - r);
    let (sy0, sy1) = (-ly + r, 0.55 * hd);
    b.cuboid(Body, [sx0, sy0, zs], [sx1, sy1, zs + 0.008]);
    b.cuboid(Body, [sx0, sy0, zs], [sx1, sy0 + 0.006, zt - 0.02]);
    for x in [sx0, sx1 - 0.006] {
        b.cuboid(Body, [x, sy0, zs], [x + 0.006, sy1, zt - 0.02]);
    }
    // A few books lying on the shelf.
    for (k, (x, th)) in [(-0.5, 0.03), (-0.1, 0.025), (0.35, 0.035)]
        .iter()
        .enumerate()
    {
        let (x0, x1) = (x * (sx1 - sx0), (x + 0.28) * (sx1 - sx0));
        b.cuboid_v(
            Books,
            k as u32,
            [x0, sy0 + 0.02, zs + 0.008],
            [x1, sy1 - 0.03, zs + 0.008 + th],
        );
    }
}

/// A boxing ring: a raised platform with a dark apron round its sides, a pale canvas on top,
/// a padded post in each corner and three ropes along each side between them, with steps up
/// to one corner.
pub fn boxing_ring(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zp = 0.36 * h;
    let step = (0.08 * hw.min(hd)).min(0.4);
    // The platform inside a margin for the steps, the apron round it, the canvas on it.
    let (pw, pd) = (hw - step, hd - step);
    b.cuboid(Body, [-pw, -pd, 0.0], [pw, pd, zp - 0.04]);
    b.cuboid(Canvas, [-pw, -pd, zp - 0.04], [pw, pd, zp]);
    // The posts, inset from the corners, padded where the ropes meet them.
    let inset = 0.15;
    let (px, py) = (pw - inset, pd - inset);
    let pr = 0.05;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(Metal, [sx * px, sy * py, zp], pr, h - zp);
            let pad = if sx * sy > 0.0 { Handle } else { Cushion };
            b.cylinder(
                pad,
                [sx * px, sy * py, zp + 0.1 * (h - zp)],
                1.6 * pr,
                0.88 * (h - zp),
            );
        }
    }
    // Three ropes a side between the posts.
    let corners = [[-px, -py], [px, -py], [px, py], [-px, py]];
    for k in 1..=3 {
        let z = zp + (h - zp) * (0.3 * k as f64);
        for i in 0..4 {
            let (a, c) = (corners[i], corners[(i + 1) % 4]);
            b.rod(Frame, [a[0], a[1], z], [c[0], c[1], z], 0.02);
        }
    }
    // Steps up to the front right corner, in the margin before the platform, the highest
    // nearest it.
    let n = 3;
    for k in 0..n {
        let z = zp * (k + 1) as f64 / (n + 1) as f64;
        let y1 = pd + step * (n - k) as f64 / n as f64;
        b.cuboid(Top, [pw - 0.9, pd, 0.0], [pw - 0.1, y1.min(hd), z]);
    }
}

/// A chest freezer: a plain white cabinet on a dark plinth, rounded at its top edge, a lid a
/// little proud of it with a dark seal line under it and a long handle recessed in its front
/// edge, a lock and a thermostat dial with two lights low on the front, a vent grille in its
/// right side. No straps.
pub fn chest_freezer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = 0.05;
    let lid = (0.12 * h).clamp(0.06, 0.1);
    let zl = h - lid;
    b.cuboid(
        Interior,
        [-hw + 0.03, -hd + 0.03, 0.0],
        [hw - 0.03, hd - 0.03, plinth],
    );
    b.cuboid(
        Body,
        [-hw + 0.01, -hd + 0.01, plinth],
        [hw - 0.01, hd - 0.01, zl - 0.012],
    );
    b.cuboid(
        Interior,
        [-hw + 0.012, -hd + 0.012, zl - 0.012],
        [hw - 0.012, hd - 0.012, zl],
    );
    b.cuboid(Top, [-hw, -hd, zl], [hw, hd, h]);
    // The handle: a dark grip along the lid's front edge.
    b.cuboid(
        Handle,
        [-0.3 * hw, hd - 0.006, zl + 0.01],
        [0.3 * hw, hd, zl + 0.035],
    );
    // The controls low at the front right: a dial and two lights; a lock by the handle.
    let x = 0.7 * hw;
    b.rod(Metal, [x, hd - 0.01, 0.22 * h], [x, hd, 0.22 * h], 0.025);
    for (k, dz) in [0.0, 0.05].iter().enumerate() {
        b.cuboid_v(
            Light,
            k as u32,
            [x - 0.09, hd - 0.006, 0.2 * h + dz],
            [x - 0.07, hd, 0.2 * h + dz + 0.02],
        );
    }
    b.rod(
        Metal,
        [0.4 * hw, hd - 0.01, zl - 0.04],
        [0.4 * hw, hd, zl - 0.04],
        0.01,
    );
    // The vent grille in the right side.
    for k in 0..6 {
        let y = -0.5 * hd + k as f64 * 0.18 * hd;
        b.cuboid(
            Interior,
            [hw - 0.011, y, 0.12 * h],
            [hw - 0.009, y + 0.06 * hd, 0.4 * h],
        );
    }
}

/// A dartboard on its stand: a tall dark backboard, a black catch ring round the board, and
/// the board's rings from the rim in (numbers ring, doubles, outer singles with pale segments,
/// trebles, inner singles, the bull and the bullseye), the bullseye at 0.68 of the height (at
/// the regulation 1.73 m when hung, as planned, with its foot 0.5 m up the wall).
pub fn dartboard(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.3 * b.d).min(0.03);
    b.cuboid(Frame, [-0.8 * hw, -hd, 0.0], [0.8 * hw, -hd + t, h]);
    let zc = 0.68 * h;
    let r = (0.75 * hw).min(0.3 * h);
    let mut y = -hd + t;
    disc(b, &mut y, Interior, 1.15 * r, 0.02, zc);
    disc(b, &mut y, Body, r, 0.02, zc);
    disc(b, &mut y, Handle, 0.76 * r, 0.002, zc);
    disc(b, &mut y, Body, 0.72 * r, 0.002, zc);
    // Pale segments of the outer singles: spokes through the centre, every other segment.
    for k in 0..5 {
        let a = (k as f64 * 36.0 + 9.0).to_radians();
        b.slab(
            Canvas,
            [0.0, y + 0.001, zc],
            [0.7 * r, 0.001, 0.1 * r],
            super::parts::rot_y(a),
        );
    }
    y += 0.002;
    disc(b, &mut y, Top, 0.48 * r, 0.002, zc);
    disc(b, &mut y, Body, 0.44 * r, 0.002, zc);
    disc(b, &mut y, Top, 0.1 * r, 0.002, zc);
    disc(b, &mut y, Handle, 0.04 * r, 0.002, zc);
}

/// One layer of a board facing +y: a disc of radius `r`, `dy` thick, in front of `y` (which it
/// moves to its face), centred at height `zc`.
fn disc(b: &mut Builder, y: &mut f64, role: super::materials::Role, r: f64, dy: f64, zc: f64) {
    b.rod(role, [0.0, *y, zc], [0.0, *y + dy, zc], r);
    *y += dy;
}

/// Stepping stones: a row of flat, rounded stones set along the path's length, each a little
/// off the line to either side and turned a little, greyer and browner by turns.
pub fn stepping_stones(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let step = 0.55f64.min(b.d);
    let n = ((b.d / step).floor() as usize).max(1);
    let r = (0.42 * step).min(0.85 * hw);
    for k in 0..n {
        let y = -hd + (k as f64 + 0.5) * b.d / n as f64;
        let x = if k % 2 == 0 { -1.0 } else { 1.0 } * (hw - r).max(0.0) * 0.6;
        let a = 0.4 * k as f64;
        b.ellipsoid_rot(
            Stone,
            k as u32,
            [x, y, 0.0],
            [r, 0.8 * r, h.max(0.02)],
            super::parts::rot_z(a),
        );
    }
}

/// A cooler: a moulded box, a white lid a little proud of it with a hinge line at its back and
/// a latch at the front, a swing handle from end to end arching over the lid, and a drain plug
/// low on the front.
pub fn cooler(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.78 * h;
    let lid = (0.18 * top).clamp(0.04, 0.1);
    let zl = top - lid;
    b.cuboid(
        Body,
        [-hw + 0.03, -hd + 0.01, 0.0],
        [hw - 0.03, hd - 0.01, zl],
    );
    b.cuboid(
        Top,
        [-hw + 0.025, -hd + 0.005, zl],
        [hw - 0.025, hd - 0.005, top],
    );
    b.cuboid(
        Interior,
        [-hw + 0.04, -hd + 0.004, zl - 0.006],
        [hw - 0.04, -hd + 0.01, zl + 0.006],
    );
    b.cuboid(
        Canvas,
        [-0.08, hd - 0.006, zl - 0.05],
        [0.08, hd, zl + 0.01],
    );
    // The swing handle: a pivot at each end, arms up past the lid, a grip along the top.
    let r = 0.012;
    let zp = zl - 0.03;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - r);
        b.rod(Handle, [sx * (hw - 0.03), 0.0, zp], [x, 0.0, zp], 0.02);
        b.rod(Handle, [x, 0.0, zp], [x, 0.0, h - r], r);
    }
    b.rod(
        Handle,
        [-(hw - r), 0.0, h - r],
        [hw - r, 0.0, h - r],
        1.3 * r,
    );
    b.rod(
        Canvas,
        [0.6 * hw, hd - 0.01, 0.05],
        [0.6 * hw, hd, 0.05],
        0.015,
    );
}

/// A standing desk: a wide top on two telescoping columns (a wider lower stage, a slimmer
/// upper one), each on a long foot running front to back, a crossbar between them under the
/// top and a control pad at the front right under its edge. No drawers.
pub fn standing_desk(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.03;
    let zt = h - t;
    b.cuboid(Top, [-hw, -hd, zt], [hw, hd, h]);
    let xc = hw - (0.12 * b.w).min(0.15);
    for sx in [-1.0, 1.0] {
        let x = sx * xc;
        b.cuboid(
            Metal,
            [x - 0.03, -hd + 0.02, 0.0],
            [x + 0.03, hd - 0.02, 0.04],
        );
        b.cuboid(Metal, [x - 0.04, -0.04, 0.04], [x + 0.04, 0.04, 0.5 * zt]);
        b.cuboid(
            Metal,
            [x - 0.032, -0.032, 0.5 * zt],
            [x + 0.032, 0.032, zt - 0.03],
        );
        b.cuboid(
            Metal,
            [x - 0.04, -0.6 * hd, zt - 0.03],
            [x + 0.04, 0.6 * hd, zt],
        );
    }
    b.cuboid(Metal, [-xc, -0.03, zt - 0.09], [xc, 0.03, zt - 0.03]);
    b.cuboid(
        Handle,
        [0.6 * hw, hd - 0.08, zt - 0.025],
        [0.6 * hw + 0.1, hd - 0.01, zt],
    );
}
