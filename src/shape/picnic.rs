//! Layout of a picnic table with its two benches attached: a slatted top and two bench seats
//! along its long sides, carried by an A-frame of crossed legs at each end. The front faces +y,
//! z up, the bottom face's centre at the origin.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// A picnic table: the top planks along x in the middle of the depth, a bench of two planks
/// along each long side at seat height, and at each end two legs splayed from the top's edges
/// to the ground beyond the benches, tied by a cross beam under the seats.
pub fn picnic_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.035;
    // The benches take the outer 0.28 of the depth each side (less on a narrow table).
    let bench = (0.2 * b.d).min(0.28);
    let top = hd - bench - 0.12;
    let seat = (0.6 * h).min(0.46);
    let gap = 0.008;
    let planks = 4;
    let pw = 2.0 * top / planks as f64;
    for k in 0..planks {
        let y0 = -top + k as f64 * pw;
        b.cuboid(Top, [-hw, y0 + gap, h - t], [hw, y0 + pw - gap, h]);
    }
    let bl = 0.92 * hw;
    for sy in [-1.0, 1.0] {
        for k in 0..2 {
            let y0 = sy * (hd - bench) + sy * k as f64 * bench / 2.0;
            let y1 = y0 + sy * bench / 2.0;
            b.cuboid(
                Seat,
                [-bl, y0 + sy * gap, seat - t],
                [bl, y1 - sy * gap, seat],
            );
        }
    }
    let lx = hw - 0.22 * hw.min(1.0);
    let (lw, lt) = (0.045, 0.07);
    for sx in [-1.0, 1.0] {
        let x = sx * lx;
        // Crossed legs: each from the top's edge down and out to the ground past the bench.
        for sy in [-1.0, 1.0] {
            let (y0, z0) = (sy * (top - 0.05), h - t);
            let (y1, z1) = (sy * (hd - 0.04), 0.0);
            let (dy, dz) = (y1 - y0, z1 - z0);
            let len = (dy * dy + dz * dz).sqrt();
            let ang = dy.atan2(-dz);
            b.slab(
                Frame,
                [x, 0.5 * (y0 + y1), 0.5 * (z0 + z1)],
                [lw / 2.0, lt / 2.0, len / 2.0],
                rot_x(ang),
            );
        }
        // Cross beams under the seats and under the top.
        b.cuboid(
            Frame,
            [x - lw, -hd + 0.02, seat - t - lt],
            [x + lw, hd - 0.02, seat - t],
        );
        b.cuboid(Frame, [x - lw, -top, h - t - 0.06], [x + lw, top, h - t]);
    }
}
