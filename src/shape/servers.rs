//! The server rack: a tall black cabinet whose front and back doors are perforated mesh (drawn
//! as a faint dark pane in a solid frame), through which rows of rack units with blinking lights
//! show at the front and their cables at the back; fan vents on its roof, levelling feet. The
//! front faces +y.
use super::archetypes::Builder;
use super::fittings::disc;
use super::materials::Role::*;

/// A tall server rack (see the module docs).
pub fn server_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let feet = 0.03;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(Metal, [sx * (hw - 0.05), sy * (hd - 0.06), 0.0], 0.02, feet);
        }
    }
    let t = 0.02;
    // Side panels, a roof and a plinth.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Body, [x - t / 2.0, -hd + t, feet], [x + t / 2.0, hd - t, h]);
    }
    b.cuboid(Body, [-hw, -hd + t, h - t], [hw, hd - t, h]);
    b.cuboid(Body, [-hw, -hd + t, feet], [hw, hd - t, feet + 0.08]);
    for k in 0..2 {
        let y = (k as f64 - 0.5) * 0.5 * b.d;
        disc(
            b,
            Interior,
            [0.0, y, h + 0.001],
            [0.0, 0.0, 1.0],
            0.09 * b.w.min(b.d) * 2.0,
            0.002,
        );
    }
    // The units: a stack of dark fronts, each with a row of lights, inside the frame.
    let (z0, z1) = (feet + 0.1, h - t - 0.06);
    let yu = hd - 0.09;
    let n = ((z1 - z0) / 0.09).floor().max(4.0) as usize;
    let u = (z1 - z0) / n as f64;
    for i in 0..n {
        let z = z0 + i as f64 * u;
        // Every fourth slot is blank, as racks are never full.
        if i % 4 == 3 {
            b.cuboid(
                Interior,
                [-hw + t, yu - 0.05, z],
                [hw - t, yu - 0.04, z + u],
            );
            continue;
        }
        b.cuboid_v(
            Metal,
            (i % 3) as u32,
            [-hw + t + 0.01, -hd + 0.15, z + 0.004],
            [hw - t - 0.01, yu, z + u - 0.004],
        );
        for k in 0..4 {
            let x = -hw + t + 0.04 + k as f64 * 0.025;
            let role = if (i + k) % 3 == 0 { Handle } else { Light };
            b.cuboid(
                role,
                [x - 0.006, yu, z + 0.4 * u],
                [x + 0.006, yu + 0.004, z + 0.6 * u],
            );
        }
        // A drive bay strip on the right.
        b.cuboid(
            Interior,
            [0.05 * b.w, yu, z + 0.25 * u],
            [hw - t - 0.03, yu + 0.003, z + 0.75 * u],
        );
    }
    // The doors: a solid frame round a mesh pane, a handle on the right of the front one.
    for (y, front) in [(hd - 0.015, true), (-hd + 0.005, false)] {
        let (y0, y1) = (y - 0.005, y + 0.005 + if front { 0.005 } else { 0.0 });
        let m = 0.04;
        b.cuboid(Frame, [-hw, y0, feet], [hw, y1, feet + m]);
        b.cuboid(Frame, [-hw, y0, h - m], [hw, y1, h]);
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - m / 2.0);
            b.cuboid(Frame, [x - m / 2.0, y0, feet], [x + m / 2.0, y1, h]);
        }
        b.cuboid(Pane, [-hw + m, y0, feet + m], [hw - m, y0 + 0.002, h - m]);
        if front {
            b.cuboid(
                Handle,
                [hw - 0.03, y1, 0.45 * h],
                [hw - 0.015, y1 + 0.004, 0.55 * h],
            );
        }
    }
    // Cables at the back: bundles falling from the units to the plinth.
    let yc = -hd + 0.05;
    for k in 0..4 {
        let x = -0.3 * b.w + k as f64 * 0.2 * b.w;
        b.polyline(
            Canvas,
            &[
                [x, -hd + 0.15, z1 - 0.1],
                [x, yc, z1 - 0.2],
                [x, yc, feet + 0.1],
            ],
            0.012,
        );
    }
}
