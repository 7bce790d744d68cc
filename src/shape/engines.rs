//! Layouts of emergency vehicles: a fire engine (a red crew cab with two rows of windows and a
//! light bar, a body behind it with roller-shutter lockers down both sides over a white band,
//! a ladder lying along its roof, a pump panel, one front and two rear axles). Built from the
//! shared chassis and faces of `vehicles.rs`. The front faces +y; everything stays inside the
//! size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::vehicles::{axle, bumper, chassis, flat_cab, rear_lamps};

/// A fire engine: a crew cab with a windscreen, two rows of side windows and a blue light bar
/// on its roof; behind it a red body with three roller-shutter lockers on each side over a
/// white band, a ladder (two rails and rungs) on the roof resting on two gantries, a pump
/// panel of gauges at the back of the cab; one front axle and two rear axles.
pub fn fire_engine(b: &mut Builder) {
    let c = chassis(b, 0.14, 0.06, 0.3, 0.6);
    let (g, hw, hd, h, zf, r, tw) = (c.g, c.hw, c.hd, c.h, c.zf, c.r, c.tw);
    let zl = 0.84 * h; // the body's roof: the ladder rides above it
    let ycab = hd - 0.3 * b.d;
    // The crew cab.
    let zc = 0.74 * h;
    flat_cab(b, &c, ycab, zc, 0.02, 0.1, 2, 0.2 * h);
    // The light bar across the cab roof.
    b.cuboid(
        Seat,
        [-0.7 * hw, hd - 0.12 * (hd - ycab), zc],
        [0.7 * hw, hd - 0.04, zc + 0.06 * h],
    );
    // The body: lockers down both sides over a white band.
    let yb = ycab - 0.015 * b.d;
    b.cuboid(Body, [-hw, -hd, zf], [hw, yb, zl]);
    let (zs0, zs1) = (zf + 0.18 * (zl - zf), zl - 0.06 * h);
    let n = 3;
    let bay = (yb + hd - 0.1) / n as f64;
    for sx in [-1.0, 1.0] {
        let (xa, xb) = if sx < 0.0 {
            (-hw - g, -hw)
        } else {
            (hw, hw + g)
        };
        b.cuboid(Canvas, [xa, -hd, zf + 0.04], [xb, yb, zs0 - 0.02]);
        for i in 0..n {
            let y0 = -hd + 0.05 + i as f64 * bay;
            b.cuboid(Top, [xa, y0 + 0.04, zs0], [xb, y0 + bay - 0.04, zs1]);
            // Shutter slats and a bar handle at the foot.
            let slats = 8;
            for k in 1..slats {
                let z = zs0 + k as f64 * (zs1 - zs0) / slats as f64;
                let (xc, xd) = if sx < 0.0 {
                    (xa - 0.004, xa)
                } else {
                    (xb, xb + 0.004)
                };
                b.cuboid(
                    Frame,
                    [xc, y0 + 0.05, z - 0.006],
                    [xd, y0 + bay - 0.05, z + 0.006],
                );
            }
        }
    }
    // The pump panel behind the cab: gauges on a steel plate on each side.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw + 0.5 * g);
        b.cuboid(
            Metal,
            [x - 0.5 * g, yb - 0.01, zs0],
            [x + 0.5 * g, ycab + 0.01, zs1],
        );
    }
    // The ladder on the roof on two gantries, out over the cab.
    let lw = 0.35 * hw;
    let (ly0, ly1) = (-hd + 0.05, hd - 0.15 * (hd - ycab));
    let zr = h - 0.04;
    for y in [-hd + 0.2 * b.d, ycab - 0.05] {
        b.cuboid(
            Metal,
            [-lw - 0.04, y - 0.05, zl],
            [lw + 0.04, y + 0.05, zr - 0.03],
        );
    }
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [sx * lw - 0.03, ly0, zr - 0.03],
            [sx * lw + 0.03, ly1, h],
        );
    }
    let rungs = ((ly1 - ly0) / 0.3) as usize;
    for k in 0..=rungs {
        let y = ly0 + k as f64 * (ly1 - ly0) / rungs as f64;
        b.rod(Metal, [-lw, y, zr - 0.01], [lw, y, zr - 0.01], 0.015);
    }
    // The back: lamps, a bumper, a step; the axles.
    rear_lamps(b, -hd, 0.85 * hw, zf, 0.08 * h);
    bumper(b, -hd, -1.0, zf, 0.05 * h);
    axle(b, hd - 0.12 * b.d, r, tw);
    for y in [-hd + 0.15 * b.d, -hd + 0.15 * b.d + 2.3 * r] {
        axle(b, y, r, tw);
    }
}
