//! Layouts of small things people name in rooms: a game console (a flat box with a lit strip
//! and its controller before it), a microphone stand (tripod, pole, boom and microphone), a
//! blender (a base under a see-through jug with a lid), a rice cooker (a round body under a
//! domed lid, a carry handle and a panel) and a birdcage (a domed cage of thin bars, on a stand
//! when tall). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::IDENTITY;
use std::f64::consts::TAU;

/// An open band round the vertical axis: radius `r` from `z` to `z + t` (a hoop, a rim).
fn hoop(b: &mut Builder, r: f64, z: f64, t: f64) {
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, z],
        IDENTITY,
        1.0,
        vec![[r, 0.0], [r, t]],
    );
}

/// A game console: a slim box across the back with vents and a lit strip, a disc slot and two
/// ports, and a controller lying before it (a body with two grips, two sticks, four buttons).
pub fn game_console(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yc = -hd + 0.58 * b.d;
    let hb = 0.75 * h;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, yc, hb]);
    b.cuboid(
        Light,
        [-hw + 0.01, yc, 0.45 * hb],
        [hw - 0.01, yc + 0.002, 0.52 * hb],
    );
    b.cuboid(
        Interior,
        [-0.6 * hw, yc, 0.7 * hb],
        [0.2 * hw, yc + 0.002, 0.76 * hb],
    );
    for x in [0.45 * hw, 0.6 * hw] {
        b.cuboid(
            BlackKeys,
            [x, yc, 0.15 * hb],
            [x + 0.04 * hw, yc + 0.002, 0.3 * hb],
        );
    }
    for k in 0..6 {
        let y = -hd + 0.1 * b.d + k as f64 * 0.07 * b.d;
        b.cuboid(
            Interior,
            [-0.8 * hw, y, hb],
            [0.8 * hw, y + 0.02 * b.d, hb + 0.002],
        );
    }
    // The controller: before the console, a little to the right.
    let s = (0.45 * b.w).min(0.9 * (hd - yc + hd) / 1.2).min(0.16);
    let (cx, cy, cz) = (0.3 * hw, 0.5 * (yc + hd), 0.2 * s);
    b.ellipsoid(Body, [cx, cy + 0.05 * s, cz], [0.33 * s, 0.2 * s, 0.14 * s]);
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Body,
            [cx + sx * 0.32 * s, cy - 0.1 * s, 0.8 * cz],
            [0.16 * s, 0.24 * s, 0.13 * s],
        );
        b.cylinder(
            BlackKeys,
            [cx + sx * 0.12 * s, cy - 0.02 * s, cz + 0.1 * s],
            0.055 * s,
            0.06 * s,
        );
    }
    for (k, (dx, dy)) in [(0.0, 0.06), (0.06, 0.0), (0.0, -0.06), (-0.06, 0.0)]
        .into_iter()
        .enumerate()
    {
        b.ellipsoid_rot(
            Books,
            k as u32,
            [cx + (0.24 + dx) * s, cy + (0.12 + dy) * s, cz + 0.12 * s],
            [0.025 * s, 0.025 * s, 0.02 * s],
            IDENTITY,
        );
    }
}

/// A microphone stand: three splayed legs under a hub, a pole with a clutch, a boom pivoting
/// at its top with a counterweight behind, and the microphone in its clip at the boom's end,
/// its grille head up and forward.
pub fn mic_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let reach = 0.95 * hw.min(hd);
    let hub = 0.2 * h;
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU + TAU / 4.0 + TAU / 6.0;
        b.rod(
            Metal,
            [0.0, 0.0, hub],
            [reach * a.cos(), reach * a.sin(), 0.012],
            0.01,
        );
        b.cylinder(Tyre, [reach * a.cos(), reach * a.sin(), 0.0], 0.02, 0.02);
    }
    b.cylinder(Metal, [0.0, 0.0, hub - 0.03], 0.025, 0.06);
    let top = 0.76 * h;
    b.cylinder(Metal, [0.0, 0.0, 0.0], 0.012, top);
    b.cylinder(Handle, [0.0, 0.0, 0.5 * h], 0.02, 0.04);
    // The boom through a pivot at the pole's top, its weight behind.
    let back = [0.0, -0.7 * reach, top - 0.1 * h];
    let end = [0.0, 0.75 * reach, top + 0.16 * h];
    b.rod(Metal, back, end, 0.009);
    b.ellipsoid(Handle, [0.0, 0.0, top], [0.025, 0.025, 0.025]);
    b.rod(
        Metal,
        [back[0], back[1] - 0.03, back[2] - 0.018],
        [back[0], back[1] + 0.04, back[2] + 0.024],
        0.03,
    );
    // The microphone: a handle in its clip and a round grille.
    let tip = [0.0, end[1] + 0.06, end[2] + 0.08];
    b.rod(BlackKeys, [end[0], end[1] - 0.01, end[2] - 0.02], tip, 0.02);
    let r = 0.035;
    let head = [0.0, tip[1] + 0.3 * r, (tip[2] + 0.6 * r).min(h - r)];
    b.ellipsoid(Canvas, head, [r, r, r]);
}

/// A blender: a squat base with a dial and buttons, a see-through jug on a collar, half full,
/// with its blades, a handle on its side, and a lid with a cap.
pub fn blender(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.9 * hw.min(hd);
    let zb = 0.3 * h;
    b.frustum(Body, [0.0, 0.0, 0.0], r, r, 0.85, zb);
    b.rod(
        Handle,
        [0.0, 0.85 * r, 0.45 * zb],
        [0.0, 0.95 * r, 0.45 * zb],
        0.22 * r,
    );
    for x in [-0.45 * r, 0.45 * r] {
        b.ellipsoid(
            Light,
            [x, 0.86 * r, 0.45 * zb],
            [0.1 * r, 0.05 * r, 0.08 * r],
        );
    }
    // The jug: a collar, the blades, what it holds, its glass, the handle and the lid.
    let (rj0, rj1) = (0.6 * r, 0.82 * r);
    let zl = 0.9 * h;
    b.frustum(Top, [0.0, 0.0, zb], 0.7 * r, 0.7 * r, 0.95, 0.06 * h);
    let zj = zb + 0.06 * h;
    for a in [0.0, std::f64::consts::FRAC_PI_2] {
        let (c, s) = (0.5 * rj0 * a.cos(), 0.5 * rj0 * a.sin());
        b.rod(Metal, [-c, -s, zj + 0.02], [c, s, zj + 0.02], 0.008);
    }
    let fill = 0.5 * (zl - zj);
    let rf = rj0 + (rj1 - rj0) * fill / (zl - zj);
    b.frustum(
        Water,
        [0.0, 0.0, zj],
        0.97 * rj0,
        0.97 * rj0,
        rf / rj0,
        fill,
    );
    b.frustum(Pane, [0.0, 0.0, zj], rj0, rj0, rj1 / rj0, zl - zj);
    b.polyline(
        Top,
        &[
            [0.8 * rj1, 0.0, zl - 0.05 * h],
            [0.99 * hw, 0.0, zl - 0.1 * h],
            [0.99 * hw, 0.0, zj + 0.15 * h],
            [0.75 * rj0, 0.0, zj + 0.1 * h],
        ],
        0.07 * r,
    );
    b.frustum(Top, [0.0, 0.0, zl], 1.02 * rj1, 1.02 * rj1, 1.0, 0.05 * h);
    b.cylinder(
        Top,
        [0.0, 0.0, zl + 0.05 * h],
        0.35 * rj1,
        h - zl - 0.05 * h,
    );
}

/// A rice cooker: a round body swelling from its foot, a domed lid with a steam vent, a carry
/// handle arching over the lid from hinges on the sides, and a dark panel of buttons in front.
pub fn rice_cooker(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.92 * hw.min(hd);
    let zb = 0.6 * h;
    b.revolved(
        Body,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [0.82 * r, 0.0],
            [0.97 * r, 0.12 * zb],
            [r, 0.5 * zb],
            [0.98 * r, 0.9 * zb],
            [0.94 * r, zb],
            [0.0, zb],
        ],
    );
    // The lid: a dome, its seam, the vent.
    let dome = 0.78 * (h - zb);
    b.revolved(
        Top,
        0,
        [0.0, 0.0, zb],
        IDENTITY,
        1.0,
        (0..=12)
            .map(|i| {
                let a = i as f64 / 12.0 * std::f64::consts::FRAC_PI_2;
                [0.93 * r * a.cos(), dome * a.sin()]
            })
            .collect(),
    );
    b.cylinder(
        Metal,
        [0.0, -0.35 * r, zb + 0.6 * dome],
        0.12 * r,
        0.45 * dome,
    );
    // The handle: hinges at the sides, folded back to lie over the lid's back half.
    let lean = 0.9f64;
    let arch: Vec<[f64; 3]> = (0..=10)
        .map(|i| {
            let a = i as f64 / 10.0 * std::f64::consts::PI;
            let up = (h - 0.04 * h - zb) * a.sin();
            [r * a.cos(), -up * lean.sin(), zb + up * lean.cos()]
        })
        .collect();
    b.polyline(Handle, &arch, 0.03 * h);
    for x in [-r, r] {
        b.ellipsoid(Handle, [x, 0.0, zb], [0.06 * r, 0.12 * r, 0.08 * r]);
    }
    // The seam round the lid, a latch button at its front.
    b.revolved(
        Handle,
        0,
        [0.0, 0.0, zb - 0.01 * h],
        IDENTITY,
        1.0,
        vec![[0.95 * r, 0.0], [0.95 * r, 0.02 * h]],
    );
    b.ellipsoid(
        Handle,
        [0.0, 0.9 * r, zb + 0.02 * h],
        [0.15 * r, 0.08 * r, 0.06 * r],
    );
    // The panel in front, a display and two buttons.
    b.cuboid(
        Screen,
        [-0.35 * r, 0.94 * r, 0.35 * zb],
        [0.35 * r, r + 0.01, 0.75 * zb],
    );
    b.cuboid(
        Light,
        [-0.15 * r, r + 0.01, 0.55 * zb],
        [0.15 * r, r + 0.014, 0.68 * zb],
    );
    for x in [-0.2 * r, 0.2 * r] {
        b.ellipsoid(
            Books,
            [x, r + 0.005, 0.43 * zb],
            [0.07 * r, 0.03 * r, 0.05 * r],
        );
    }
}

/// A birdcage: a tray, a ring of thin upright bars between hoops, a dome of bars meeting at a
/// finial with a ring, a perch with a small bird inside. A tall one stands on a pole over
/// three splayed feet, its cage in the top part.
pub fn birdcage(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rc = 0.92 * hw.min(hd);
    let cage = if h > 2.5 * rc {
        (2.4 * rc).min(0.7 * h)
    } else {
        h
    };
    let z0 = h - cage;
    if z0 > 0.0 {
        for k in 0..3 {
            let a = k as f64 / 3.0 * TAU + TAU / 12.0;
            b.rod(
                Metal,
                [0.0, 0.0, 0.15 * z0],
                [
                    0.95 * hw.min(hd) * a.cos(),
                    0.95 * hw.min(hd) * a.sin(),
                    0.01,
                ],
                0.012,
            );
        }
        b.cylinder(Metal, [0.0, 0.0, 0.0], 0.018, z0);
        b.ellipsoid(Metal, [0.0, 0.0, 0.6 * z0], [0.04, 0.04, 0.05]);
    }
    // The tray and the cage's walls.
    let tray = 0.08 * cage;
    b.frustum(Body, [0.0, 0.0, z0], 0.9 * rc, 0.9 * rc, 1.1, tray);
    let wall = z0 + 0.62 * cage;
    let dome = h - 0.06 * cage - wall;
    let bars = 24;
    let bar = (0.012 * rc).max(0.004);
    for k in 0..bars {
        let a = k as f64 / bars as f64 * TAU;
        let (c, s) = (a.cos(), a.sin());
        let mut pts = vec![[rc * c, rc * s, z0 + tray], [rc * c, rc * s, wall]];
        for i in 1..=6 {
            let t = i as f64 / 6.0 * std::f64::consts::FRAC_PI_2;
            let rho = rc * t.cos();
            pts.push([rho * c, rho * s, wall + dome * t.sin()]);
        }
        b.polyline(Metal, &pts, bar);
    }
    for z in [z0 + tray, z0 + 0.3 * cage, wall] {
        hoop(b, rc, z - 0.01, 0.02);
    }
    // The finial and its ring.
    let top = wall + dome;
    b.ellipsoid(Metal, [0.0, 0.0, top], [0.1 * rc, 0.1 * rc, 0.08 * rc]);
    b.rod(
        Metal,
        [0.0, 0.0, top],
        [0.0, 0.0, h - 0.03 * cage],
        0.015 * rc,
    );
    b.polyline(
        Metal,
        &(0..=12)
            .map(|i| {
                let a = i as f64 / 12.0 * TAU;
                [
                    0.0,
                    0.12 * rc * a.sin(),
                    h - 0.12 * rc * (1.0 - a.cos()) - 0.001,
                ]
            })
            .collect::<Vec<_>>(),
        0.012 * rc,
    );
    // A perch across the cage and a bird on it.
    let zp = z0 + 0.35 * cage;
    b.rod(Trunk, [-0.9 * rc, 0.0, zp], [0.9 * rc, 0.0, zp], 0.02 * rc);
    let s = 0.22 * rc;
    b.ellipsoid_rot(
        Books,
        4,
        [0.1 * rc, 0.0, zp + 0.6 * s],
        [0.5 * s, 0.45 * s, 0.6 * s],
        IDENTITY,
    );
    b.ellipsoid_rot(
        Books,
        4,
        [0.1 * rc, 0.2 * s, zp + 1.25 * s],
        [0.3 * s, 0.3 * s, 0.3 * s],
        IDENTITY,
    );
    b.ellipsoid(
        Handle,
        [0.1 * rc, 0.48 * s, zp + 1.22 * s],
        [0.08 * s, 0.1 * s, 0.06 * s],
    );
    b.ellipsoid_rot(
        Books,
        4,
        [0.1 * rc, -0.5 * s, zp + 0.1 * s],
        [0.15 * s, 0.08 * s, 0.4 * s],
        frame_along([0.0, -0.4, -0.6]),
    );
}
