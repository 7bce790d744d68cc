//! A row of lockers: narrow metal doors side by side on a plinth, each with vent slots at its
//! top and bottom, a latch handle and a number plate, so a locker never reads as a wardrobe's
//! two wooden doors. The front is +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// Lockers: as many doors about 0.3 m wide as the row holds.
pub fn lockers(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = 0.08_f64.min(0.08 * h);
    b.cuboid(
        Interior,
        [-hw + 0.02, -hd, 0.0],
        [hw - 0.02, hd - 0.03, plinth],
    );
    b.cuboid(Body, [-hw, -hd, plinth], [hw, hd - 0.012, h]);
    let n = ((b.w / 0.3).round() as usize).max(1);
    let dw = b.w / n as f64;
    let gap = 0.006;
    let y0 = hd - 0.012;
    let (z0, z1) = (plinth + 0.01, h - 0.01);
    for i in 0..n {
        let x0 = -hw + i as f64 * dw + gap;
        let x1 = x0 + dw - 2.0 * gap;
        b.cuboid(Door, [x0, y0, z0], [x1, hd, z1]);
        // Vent slots near the top and the bottom of the door.
        for zc in [z1 - 0.12 * h, z0 + 0.07 * h] {
            for k in 0..4 {
                let z = zc + k as f64 * 0.018;
                b.cuboid(
                    Interior,
                    [x0 + 0.2 * dw, hd, z],
                    [x1 - 0.2 * dw, hd + 0.002, z + 0.007],
                );
            }
        }
        // A latch handle at the opening edge and a number plate above it.
        let xh = x1 - 0.15 * dw;
        b.cuboid(
            Handle,
            [xh - 0.012, hd, 0.5 * h - 0.06],
            [xh + 0.012, hd + 0.02, 0.5 * h + 0.06],
        );
        let xm = 0.5 * (x0 + x1);
        b.cuboid(
            Canvas,
            [xm - 0.025, hd, z1 - 0.2 * h],
            [xm + 0.025, hd + 0.003, z1 - 0.2 * h + 0.03],
        );
    }
}
