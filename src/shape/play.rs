//! Layouts of things people play on or with: a trampoline, a playground merry-go-round, a
//! surfboard, an inflatable pool ring, a skateboard ramp, a child's play kitchen and a little
//! pile of toys. The front faces +y, z up, the
//! bottom face's centre at the origin.
use super::archetypes::{frame_along, Builder};
use super::heritage::slab;
use super::materials::Role::*;
use super::parts::{rot_x, IDENTITY};
use std::f64::consts::{FRAC_PI_2, TAU};

/// A closed ring (a torus) about the vertical axis through `(0, 0, z)`: centre-line radius
/// `rc`, tube radius `r`.
fn ring(b: &mut Builder, role: super::materials::Role, z: f64, rc: f64, r: f64) {
    let profile: Vec<[f64; 2]> = (0..=24)
        .map(|k| {
            let t = k as f64 / 24.0 * TAU;
            [rc + r * t.cos(), r + r * t.sin()]
        })
        .collect();
    b.revolved(
        role,
        0,
        [0.0, 0.0, z - r],
        super::parts::IDENTITY,
        1.0,
        profile,
    );
}

/// A flat annulus between radii `r0` and `r1` from `z0` to `z1` (a disc when `r0` is 0).
fn annulus(b: &mut Builder, role: super::materials::Role, r0: f64, r1: f64, z0: f64, z1: f64) {
    let profile = vec![
        [r0, 0.0],
        [r1, 0.0],
        [r1, z1 - z0],
        [r0, z1 - z0],
        [r0, 0.0],
    ];
    b.revolved(
        role,
        0,
        [0.0, 0.0, z0],
        super::parts::IDENTITY,
        1.0,
        profile,
    );
}

/// A round garden trampoline: a black jumping mat inside a padded rim on a steel ring, standing
/// on W-shaped legs.
pub fn trampoline(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let tube = (0.015 * r).clamp(0.015, 0.03);
    let top = h - 0.02;
    ring(b, Metal, top - 0.04, r - tube - 0.01, tube);
    annulus(b, Cushion, 0.8 * r, r - 0.005, top - 0.05, top);
    annulus(b, Interior, 0.0, 0.8 * r, top - 0.04, top - 0.02);
    // Six W-legs: two uprights each, joined by a bar on the ground.
    for k in 0..6 {
        let a = k as f64 / 6.0 * TAU + FRAC_PI_2;
        let rl = r - 2.0 * tube - 0.01;
        let at = |da: f64, z: f64| [rl * (a + da).cos(), rl * (a + da).sin(), z];
        for da in [-0.1, 0.1] {
            b.rod(Metal, at(da, tube), at(da, top - 0.04), tube);
        }
        b.rod(Metal, at(-0.1, tube), at(0.1, tube), tube);
    }
}

/// A playground merry-go-round: a low round deck on a central hub, with handrails rising from
/// its edge to a post in the middle.
pub fn merry_go_round(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let deck = (0.25 * h).min(0.25);
    b.cylinder(Metal, [0.0, 0.0, 0.0], 0.12 * r, deck - 0.05);
    annulus(b, Top, 0.0, r, deck - 0.05, deck);
    annulus(b, Frame, r - 0.04, r, deck - 0.06, deck + 0.005);
    let rail = 0.02;
    b.cylinder(Metal, [0.0, 0.0, deck], 0.05, h - deck - rail);
    let top = h - rail;
    for k in 0..6 {
        let a = k as f64 / 6.0 * TAU;
        let (c, s) = (a.cos(), a.sin());
        let re = 0.8 * r;
        b.rod(Metal, [re * c, re * s, deck], [re * c, re * s, top], rail);
        b.rod(
            Metal,
            [re * c, re * s, top],
            [0.05 * c, 0.05 * s, top],
            rail,
        );
        // A grip bar halfway up, to the next rail.
        let (c2, s2) = ((a + TAU / 6.0).cos(), (a + TAU / 6.0).sin());
        let z = 0.5 * (deck + top);
        b.rod(
            Metal,
            [re * c, re * s, z],
            [0.6 * re * (c + c2), 0.6 * re * (s + s2), z],
            0.8 * rail,
        );
    }
}

/// A surfboard lying flat: a long board with a rounded tail and a pointed nose towards +y, a
/// stripe across its nose.
pub fn surfboard(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // Half width along the board, as a share of the widest (tail at 0, nose at 1).
    const OUTLINE: [(f64, f64); 10] = [
        (0.0, 0.0),
        (0.005, 0.5),
        (0.1, 0.8),
        (0.25, 0.95),
        (0.45, 1.0),
        (0.65, 0.92),
        (0.8, 0.72),
        (0.9, 0.48),
        (0.97, 0.2),
        (1.0, 0.0),
    ];
    let l = 2.0 * hd;
    let ay = (0.5 * h) / hw;
    let along = frame_along([0.0, 1.0, 0.0]);
    let profile = OUTLINE.iter().map(|(t, s)| [s * hw, t * l]).collect();
    b.revolved(Body, 0, [0.0, -hd, 0.5 * h], along, ay, profile);
    // The stripe: a band a little proud of the board.
    let width = |t: f64| {
        let i = OUTLINE
            .iter()
            .position(|(u, _)| *u >= t)
            .unwrap_or(9)
            .max(1);
        let ((t0, s0), (t1, s1)) = (OUTLINE[i - 1], OUTLINE[i]);
        s0 + (s1 - s0) * (t - t0) / (t1 - t0)
    };
    let (t0, t1) = (0.72, 0.77);
    let band = vec![
        [0.0, t0 * l],
        [1.02 * hw * width(t0), t0 * l],
        [1.02 * hw * width(t1), t1 * l],
        [0.0, t1 * l],
    ];
    b.revolved(Frame, 0, [0.0, -hd, 0.5 * h], along, ay, band);
}

/// An inflatable pool ring: a plump torus.
pub fn pool_float(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let tube = (0.5 * h).min(0.25 * r);
    // Short tubes joined by balls: closed solids, so the ring reads as filled from the side.
    let rc = r - tube;
    let at = |k: usize| {
        let t = k as f64 / 32.0 * TAU;
        [rc * t.cos(), rc * t.sin(), tube]
    };
    for k in 0..32 {
        b.rod(Body, at(k), at(k + 1), 0.97 * tube);
        b.ellipsoid(Body, at(k), [tube, tube, tube]);
    }
    // A valve on the top of the tube.
    b.cylinder(
        Cushion,
        [0.0, r - tube, 2.0 * tube - 0.01],
        0.12 * tube,
        0.01,
    );
}

/// A skateboard ramp (a quarter pipe): a curved riding surface rising from the front to a deck
/// at the back, with a steel coping along its lip and closed sides.
pub fn ramp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let deck_d = (0.2 * b.d).clamp(0.3, 0.6);
    // The transition: an arc of radius `rr` ending short of vertical at the deck.
    let end = 80f64.to_radians();
    let rr = (h / (1.0 - end.cos())).min((b.d - deck_d) / end.sin());
    let yc = -hd + deck_d + rr * end.sin();
    let at = |p: f64| [yc - rr * p.sin(), rr * (1.0 - p.cos())];
    let top = at(end)[1];
    let n = 14;
    let t = 0.03;
    for i in 0..n {
        let (p0, p1) = (end * i as f64 / n as f64, end * (i + 1) as f64 / n as f64);
        let (a, c) = (at(p0), at(p1));
        let (dy, dz) = (c[0] - a[0], c[1] - a[1]);
        let len = (dy * dy + dz * dz).sqrt();
        // The board sits just under the curve (its normal points up and to the front).
        let (ny, nz) = (dz / len, -dy / len);
        let (ny, nz) = if nz < 0.0 { (-ny, -nz) } else { (ny, nz) };
        let centre = [
            0.0,
            0.5 * (a[0] + c[0]) - 0.5 * t * ny,
            0.5 * (a[1] + c[1]) - 0.5 * t * nz,
        ];
        slab(
            b,
            Body,
            0,
            centre,
            [hw - 0.02, 0.5 * len + 0.004, 0.5 * t],
            rot_x(dz.atan2(dy)),
        );
        // The sides close the space under the curve.
        let z = 0.5 * (a[1] + c[1]);
        for sx in [-1.0, 1.0] {
            b.cuboid(
                Frame,
                [sx * hw - 0.01, c[0], 0.0],
                [sx * hw + 0.01, a[0], z],
            );
        }
    }
    // The flat run from the foot of the arc to the front edge.
    if yc < hd {
        b.cuboid(Body, [-hw + 0.02, yc, 0.0], [hw - 0.02, hd, 0.01]);
    }
    b.cuboid(Top, [-hw, -hd, top - 0.04], [hw, -hd + deck_d, top]);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + 0.02, top - 0.04]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [sx * hw - 0.01, -hd, 0.0],
            [sx * hw + 0.01, -hd + deck_d, top - 0.04],
        );
    }
    let lip = -hd + deck_d;
    b.rod(Metal, [-hw, lip, top - 0.02], [hw, lip, top - 0.02], 0.03);
}

/// A play kitchen: a child-high unit in bright colours, a worktop at a child's waist with two
/// black hob rings and a steel sink bowl with a tap, an oven door with a dark window and a
/// bar handle under the hob, a cupboard door under the sink, big round knobs along the front,
/// and a back panel rising behind with a shelf across it.
pub fn play_kitchen(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = (0.55 * h).min(0.55);
    let tt = 0.03;
    let yb = -hd + 0.03;
    // Back panel and its shelf, a rounded top bar.
    b.cuboid(Canvas, [-hw, -hd, 0.0], [hw, yb, h - 0.03]);
    b.rod(
        Canvas,
        [-hw, -hd + 0.015, h - 0.03],
        [hw, -hd + 0.015, h - 0.03],
        0.015,
    );
    let zs = zt + 0.6 * (h - zt);
    b.cuboid(
        Top,
        [-hw + 0.03, yb, zs - 0.02],
        [hw - 0.03, yb + 0.12_f64.min(0.5 * b.d), zs],
    );
    // The unit, the worktop on it.
    b.cuboid(Body, [-hw, yb, 0.04], [hw, hd - 0.015, zt - tt]);
    b.cuboid(
        Frame,
        [-hw + 0.02, yb + 0.02, 0.0],
        [hw - 0.02, hd - 0.04, 0.04],
    );
    b.cuboid(Top, [-hw, yb, zt - tt], [hw, hd, zt]);
    // The hob (left) and the sink (right).
    let xl = -0.5 * hw;
    let yc = 0.5 * (yb + hd);
    let rr = (0.2 * hw).min(0.3 * (hd - yb)).min(0.1);
    for (dx, dy) in [(-0.45, 0.0), (0.45, 0.0)] {
        b.revolved(
            BlackKeys,
            0,
            [xl + dx * hw * 0.6, yc + dy, zt],
            IDENTITY,
            1.0,
            vec![[0.0, 0.0], [rr, 0.0], [rr, 0.008], [0.0, 0.008]],
        );
    }
    let xr = 0.5 * hw;
    let sr = (0.6 * hw).min(0.8 * (hd - yb)) / 2.0;
    b.revolved(
        Metal,
        0,
        [xr, yc, zt - 0.08],
        IDENTITY,
        1.0,
        vec![[0.0, 0.0], [0.7 * sr, 0.0], [sr, 0.082], [0.9 * sr, 0.082]],
    );
    b.cuboid(
        Metal,
        [xr - 0.015, yb, zt],
        [xr + 0.015, yb + 0.03, zt + 0.14],
    );
    b.rod(
        Metal,
        [xr, yb + 0.02, zt + 0.14],
        [xr, yc - 0.3 * sr, zt + 0.14],
        0.012,
    );
    // The oven door with a window and a handle; the cupboard door with a knob.
    let (z0, z1) = (0.08, zt - tt - 0.1);
    b.cuboid(Door, [-hw + 0.04, hd - 0.015, z0], [-0.04, hd - 0.003, z1]);
    b.cuboid(
        Screen,
        [-hw + 0.1, hd - 0.003, z0 + 0.06],
        [-0.1, hd - 0.001, z1 - 0.1],
    );
    b.rod(
        Handle,
        [-hw + 0.1, hd - 0.013, z1 - 0.05],
        [-0.1, hd - 0.013, z1 - 0.05],
        0.012,
    );
    b.cuboid(Door, [0.04, hd - 0.015, z0], [hw - 0.04, hd - 0.003, z1]);
    b.ellipsoid(
        Handle,
        [0.1, hd - 0.012, 0.5 * (z0 + z1)],
        [0.02, 0.01, 0.02],
    );
    // Knobs along the front under the worktop.
    for k in 0..4 {
        let x = -hw + (k as f64 + 0.5) * hw / 2.0;
        b.ellipsoid(
            Handle,
            [x, hd - 0.012, zt - tt - 0.05],
            [0.025, 0.01, 0.025],
        );
    }
}

/// Toys: a little pile of them, a ball, a stack of building blocks in bright colours and a
/// wooden car on four black wheels.
pub fn toys(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.3 * hw).min(0.45 * h).min(hd);
    b.ellipsoid(Cushion, [-hw + r, hd - r, r], [r, r, r]);
    let s = (0.22 * b.w).min(0.3 * h);
    for k in 0..3u32 {
        let z = k as f64 * s;
        let x = 0.2 * hw + 0.1 * s * (k as f64 - 1.0);
        b.cuboid_v(
            Books,
            k * 2 + 1,
            [x - s / 2.0, -hd + 0.02, z],
            [x + s / 2.0, -hd + 0.02 + s, z + s],
        );
    }
    // The car: a body, a cab on it, four wheels, across the front right.
    let (cl, cw) = ((0.7 * hw).min(0.3), (0.5 * hd).min(0.12));
    let (cx, cy) = (hw - cl / 2.0 - 0.01, hd - cw / 2.0 - 0.01);
    let wr = 0.25 * cw;
    b.cuboid(
        Body,
        [cx - cl / 2.0, cy - cw / 2.0, wr],
        [cx + cl / 2.0, cy + cw / 2.0, wr + 0.5 * cw],
    );
    b.cuboid(
        Top,
        [cx - 0.25 * cl, cy - 0.4 * cw, wr + 0.5 * cw],
        [cx + 0.1 * cl, cy + 0.4 * cw, wr + 0.9 * cw],
    );
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.rod(
                Tyre,
                [cx + sx * 0.32 * cl, cy + sy * (0.5 * cw - 0.01), wr],
                [cx + sx * 0.32 * cl, cy + sy * 0.5 * cw, wr],
                wr,
            );
        }
    }
}
