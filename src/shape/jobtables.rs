//! Tables fitted for one job: a poker table (a felt oval inside a padded rail, chip stacks at
//! the seats and a chip tray at the dealer's place), a fabric cutting table (a gridded cutting
//! mat over shelves of fabric bolts), a grooming table (a ribbed non-slip top on folding legs
//! under a grooming arm with its loop) and a produce stand (tiers of tilted crates of produce
//! under a price sign). Layout only: colours come from the archetype table.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{mul, rot_x, IDENTITY, M3, V3};

/// Points of an ellipse of radii `rx`, `ry` at height `z`, closed (`n` segments).
fn ellipse(rx: f64, ry: f64, z: f64, n: usize) -> Vec<V3> {
    (0..=n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            [rx * a.cos(), ry * a.sin(), z]
        })
        .collect()
}

pub fn poker_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rr = (0.07 * hd).clamp(0.04, 0.07);
    // The padded rail round the edge, a wooden race under it, the felt sunk inside it.
    b.polyline(Cushion, &ellipse(hw - rr, hd - rr, h - rr, 48), rr);
    b.frustum(
        Frame,
        [0.0, 0.0, h - 2.0 * rr - 0.06],
        hw - 0.01,
        hd - 0.01,
        0.97,
        0.07,
    );
    b.frustum(
        Upholstery,
        [0.0, 0.0, h - 2.0 * rr - 0.01],
        hw - 1.6 * rr,
        hd - 1.6 * rr,
        1.0,
        rr,
    );
    // Chip stacks at the seats round the rail, the dealer's tray of chips at the front.
    let seats = 8;
    for k in 0..seats {
        let a = std::f64::consts::TAU * (k as f64 + 0.5) / seats as f64;
        let (x, y) = (
            0.72 * (hw - 2.0 * rr) * a.cos(),
            0.72 * (hd - 2.0 * rr) * a.sin(),
        );
        for j in 0..2 {
            let r = 0.02;
            b.cylinder(
                Books,
                [x + 0.045 * j as f64, y, h - rr - 0.01],
                r,
                0.02 + 0.015 * j as f64,
            );
            b.parts.last_mut().expect("just drawn").variant = (k + j) as u32;
        }
    }
    let ty = hd - 2.0 * rr - 0.09;
    b.cuboid(
        Interior,
        [-0.22, ty - 0.06, h - rr - 0.012],
        [0.22, ty + 0.06, h - rr - 0.005],
    );
    for k in 0..6 {
        let x = -0.19 + 0.076 * k as f64;
        b.cuboid_v(
            Books,
            k,
            [x - 0.028, ty - 0.05, h - rr - 0.01],
            [x + 0.028, ty + 0.05, h - rr + 0.005],
        );
    }
    // Two pedestals on cross feet.
    let zt = h - 2.0 * rr - 0.06;
    for s in [-1.0, 1.0] {
        let x = s * 0.45 * hw;
        b.cylinder(Frame, [x, 0.0, 0.05], (0.09 * hd).max(0.04), zt - 0.05);
        b.cuboid(
            Frame,
            [x - 0.05, -0.8 * hd, 0.0],
            [x + 0.05, 0.8 * hd, 0.05],
        );
        b.cuboid(
            Frame,
            [x - 0.25 * hw, -0.05, 0.0],
            [x + 0.25 * hw, 0.05, 0.05],
        );
    }
}

/// A fabric cutting table: a counter-high top under a green cutting mat ruled in a grid (with a
/// long ruler and a rolled bolt on it), on end panels with two shelves of folded fabric.
pub fn cutting_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.04;
    // The mat's surface, leaving the box's last few centimetres to the bolt lying on it.
    let zm = h - 0.085;
    b.cuboid(Top, [-hw, -hd, zm - t - 0.006], [hw, hd, zm - 0.006]);
    let (mx, my) = (hw - 0.05, hd - 0.05);
    b.cuboid(Canvas, [-mx, -my, zm - 0.006], [mx, my, zm]);
    let step = 0.15;
    let nx = (2.0 * mx / step).floor() as usize;
    for i in 1..nx {
        let x = -mx + i as f64 * 2.0 * mx / nx as f64;
        b.cuboid(Handle, [x - 0.003, -my, zm], [x + 0.003, my, zm + 0.002]);
    }
    let ny = (2.0 * my / step).floor() as usize;
    for i in 1..ny {
        let y = -my + i as f64 * 2.0 * my / ny as f64;
        b.cuboid(Handle, [-mx, y - 0.003, zm], [mx, y + 0.003, zm + 0.002]);
    }
    b.cuboid(
        Metal,
        [-0.7 * mx, my - 0.12, zm],
        [0.5 * mx, my - 0.07, zm + 0.006],
    );
    b.rod(
        Books,
        [-0.3 * mx, -my + 0.1, zm + 0.04],
        [0.6 * mx, -my + 0.1, zm + 0.04],
        0.04,
    );
    // End panels, a back panel, two shelves of folded fabric in stacks of colours.
    let zt = zm - t - 0.006;
    for x in [-hw, hw - 0.04] {
        b.cuboid(Body, [x, -hd + 0.04, 0.0], [x + 0.04, hd - 0.04, zt]);
    }
    b.cuboid(
        Body,
        [-hw + 0.04, -hd + 0.04, 0.08],
        [hw - 0.04, -hd + 0.06, zt],
    );
    let shelves = [0.08, 0.48 * zt];
    let n = ((2.0 * hw - 0.12) / 0.3).floor().max(2.0) as usize;
    let pitch = (2.0 * hw - 0.12) / n as f64;
    for (j, z) in shelves.into_iter().enumerate() {
        b.cuboid(
            Frame,
            [-hw + 0.04, -hd + 0.06, z - 0.025],
            [hw - 0.04, hd - 0.06, z],
        );
        for k in 0..n {
            let x = -hw + 0.06 + (k as f64 + 0.5) * pitch;
            let v = (k * 3 + j * 5) as u32;
            let top = z + (0.18 + 0.05 * ((k + j) % 3) as f64).min(0.8 * (shelves[1] - 0.1));
            b.cuboid_v(
                Books,
                v,
                [x - 0.42 * pitch, -0.7 * hd, z],
                [x + 0.42 * pitch, 0.7 * hd, top],
            );
        }
    }
}

/// A grooming table: a small top with a ribbed rubber mat on folding steel legs, and a grooming
/// arm (an upright at a back corner, bent over the table) with a loop hanging from its end.
pub fn grooming_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = (0.48 * h).min(0.85);
    b.cuboid(Metal, [-hw, -hd, zt - 0.05], [hw, hd, zt - 0.01]);
    b.cuboid(
        Upholstery,
        [-hw + 0.01, -hd + 0.01, zt - 0.01],
        [hw - 0.01, hd - 0.01, zt],
    );
    let ribs = ((b.w - 0.06) / 0.04).floor() as usize;
    for k in 0..ribs {
        let x = -hw + 0.03 + (k as f64 + 0.5) * (b.w - 0.06) / ribs as f64;
        b.cuboid(
            Cushion,
            [x - 0.006, -hd + 0.03, zt],
            [x + 0.006, hd - 0.03, zt + 0.006],
        );
    }
    // Folding legs: an X-free pair of U-frames with a cross bar each, on rubber feet.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.08);
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - 0.05);
            b.rod(Metal, [x, y, 0.02], [x, y, zt - 0.05], 0.014);
            b.ellipsoid(Tyre, [x, y, 0.02], [0.022, 0.022, 0.02]);
        }
        b.rod(Metal, [x, -hd + 0.05, 0.15], [x, hd - 0.05, 0.15], 0.01);
    }
    // The arm: upright at the back right, then over the middle of the table.
    let (xa, ya) = (hw - 0.05, -hd + 0.04);
    let top = h - 0.03;
    b.cuboid(
        Metal,
        [xa - 0.04, ya - 0.03, zt - 0.06],
        [xa + 0.04, ya + 0.03, zt - 0.01],
    );
    b.rod(Metal, [xa, ya, zt - 0.02], [xa, ya, top], 0.016);
    b.rod(Metal, [xa, ya, top], [0.0, ya, top], 0.014);
    b.ellipsoid(Handle, [xa, ya, top], [0.025, 0.025, 0.025]);
    // The loop: a clip, a lead down, a ring at the bottom.
    let zl = zt + 0.45 * (top - zt);
    b.rod(Canvas, [0.0, ya, top], [0.0, ya + 0.06, zl + 0.1], 0.006);
    let ring: Vec<V3> = (0..=16)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 16.0;
            [0.07 * a.sin(), ya + 0.06, zl + 0.07 * (1.0 + a.cos())]
        })
        .collect();
    b.polyline(Canvas, &ring, 0.007);
}

/// An open crate tilted by `tilt` towards the front, its bottom's centre at `c`, `hw` × `hd`
/// inside, `wall` high, heaped with produce of colour variant `v`.
fn crate_of_produce(b: &mut Builder, c: V3, hw: f64, hd: f64, wall: f64, tilt: f64, v: u32) {
    let m: M3 = rot_x(-tilt);
    let at = |p: V3| {
        let q = mul(&m, p);
        [c[0] + q[0], c[1] + q[1], c[2] + q[2]]
    };
    let th = 0.01;
    b.slab(Frame, at([0.0, 0.0, th]), [hw + th, hd + th, th], m);
    for s in [-1.0, 1.0] {
        b.slab(
            Frame,
            at([0.0, s * (hd + th), wall / 2.0]),
            [hw + th, th, wall / 2.0],
            m,
        );
        b.slab(
            Frame,
            at([s * (hw + th), 0.0, wall / 2.0]),
            [th, hd, wall / 2.0],
            m,
        );
    }
    let r = (0.3 * hw.min(hd)).clamp(0.03, 0.05);
    let (nx, ny) = (
        ((hw / r).floor() as usize).max(1),
        ((hd / r).floor() as usize).max(1),
    );
    for layer in 0..2 {
        let off = layer as f64 * r;
        let (cx, cy) = (nx - layer, ny - layer);
        for i in 0..cx {
            for j in 0..cy {
                let x = -hw + r + off + i as f64 * 2.0 * (hw - r - off) / (cx.max(2) - 1) as f64;
                let y = -hd + r + off + j as f64 * 2.0 * (hd - r - off) / (cy.max(2) - 1) as f64;
                let z = 2.0 * th + r * (0.9 + 1.5 * layer as f64);
                b.ellipsoid_rot(Books, v, at([x, y, z]), [r, r, 0.9 * r], IDENTITY);
            }
        }
    }
}

/// A produce stand: a stepped wooden stand holding two tiers of crates tilted to the buyer,
/// each heaped with one kind of produce, and a price board on two posts at the back.
pub fn produce_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (z_front, z_back) = (0.4 * h, 0.6 * h);
    b.cuboid(
        Body,
        [-hw + 0.03, 0.0, 0.0],
        [hw - 0.03, hd - 0.05, z_front],
    );
    b.cuboid(
        Body,
        [-hw + 0.03, -hd + 0.08, 0.0],
        [hw - 0.03, 0.0, z_back],
    );
    // Plank seams across the fronts of both steps.
    for (y, z0, z1) in [(hd - 0.05, 0.0, z_front), (0.0, z_front, z_back)] {
        let seams = ((z1 - z0) / 0.12).floor() as usize;
        for k in 1..=seams {
            let z = z0 + k as f64 * (z1 - z0) / (seams + 1) as f64;
            b.cuboid(
                Frame,
                [-hw + 0.03, y, z - 0.006],
                [hw - 0.03, y + 0.006, z + 0.006],
            );
        }
    }
    let n = ((b.w / 0.45).floor() as usize).clamp(2, 5);
    let cw = (b.w - 0.06) / n as f64;
    let tilt = 20f64.to_radians();
    for (tier, (y, z)) in [(0.5 * (hd - 0.05), z_front), (-0.5 * hd + 0.04, z_back)]
        .into_iter()
        .enumerate()
    {
        for k in 0..n {
            let x = -hw + 0.03 + (k as f64 + 0.5) * cw;
            // The crate's front edge rests on the tier, its back raised on a wedge.
            let chd = 0.2 * hd;
            let zc = z + chd * tilt.sin() + 0.01;
            let wedge = 2.0 * chd * tilt.sin();
            b.cuboid(
                Body,
                [x - 0.3 * cw, y - chd, z],
                [x + 0.3 * cw, y - 0.6 * chd, z + wedge],
            );
            crate_of_produce(
                b,
                [x, y, zc],
                0.5 * cw - 0.03,
                chd,
                0.09,
                tilt,
                (k + tier * n) as u32,
            );
        }
    }
    // The sign: a dark board on two posts, chalk lines of prices on it.
    let ys = -hd + 0.03;
    for s in [-1.0, 1.0] {
        let x = s * (hw - 0.06);
        b.cuboid(
            Frame,
            [x - 0.025, ys - 0.025, z_back],
            [x + 0.025, ys + 0.025, h],
        );
    }
    let (s0, s1) = (h - 0.28, h - 0.02);
    b.cuboid(
        Canvas,
        [-hw + 0.1, ys - 0.01, s0],
        [hw - 0.1, ys + 0.012, s1],
    );
    for k in 0..3 {
        let z = s0 + 0.06 + k as f64 * 0.07;
        let len = (0.5 - 0.1 * k as f64) * hw;
        b.cuboid(
            Handle,
            [-len, ys + 0.012, z - 0.008],
            [len, ys + 0.016, z + 0.008],
        );
    }
}
