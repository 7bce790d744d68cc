//! Layouts of vehicles that are told from a van or a bus by one working part: a food truck (a
//! van's cab and box with a serving hatch cut in its right side (+x), a counter under it and
//! an awning propped open over it, a lit menu band, a name board over the windscreen and a roof vent) and a tram (a long low body
//! alike at both ends, each with a windscreen and a destination sign, doors on both sides, small
//! wheels behind a skirt on two bogies and a pantograph on the roof). Built from the shared
//! chassis and faces of `vehicles.rs`. The front faces +y; everything stays inside the size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_y;
use super::vehicles::{
    axle_between, box_body, bumper, chassis, rear, side_windows, van_cab, Chassis,
};

/// A food truck: a van's cab and tall box, narrowed on the right by the awning's reach; in the
/// box's right side a dark serving hatch with a counter shelf under it and an awning propped
/// open above it on two struts, a lit menu band along the top of both sides, a roof vent.
pub fn food_truck(b: &mut Builder) {
    let full = chassis(b, 0.15, 0.08, 0.25, 0.45);
    // The awning and counter reach `out` past the body's right side.
    let out = (0.17 * b.w).clamp(0.12, 0.4);
    let c = Chassis {
        hw: full.hw - 0.5 * out,
        ..full
    };
    // The body is shifted left by half the reach so its right side stands at `xs`.
    let shift = -0.5 * out;
    let (g, hd, h) = (c.g, c.hd, c.h);
    let xs = shift + c.hw - 0.02;
    let first = b.parts.len();
    let roof = h - 0.12;
    let yb = van_cab(b, &c, roof);
    // The hatch: a dark opening over the middle of the box with a frame round it.
    let (y0, y1) = (-hd + 0.15 * b.d, yb - 0.3 * b.d);
    let (z0, z1) = (0.42 * h, 0.78 * h);
    b.cuboid(Interior, [c.hw - 0.02, y0, z0], [c.hw - 0.02 + g, y1, z1]);
    // A lit menu band along the top of both sides.
    for sx in [-1.0, 1.0] {
        let x = sx * (c.hw - 0.02);
        let (xa, xb) = if sx < 0.0 { (x - g, x) } else { (x, x + g) };
        b.cuboid(Light, [xa, -hd + 0.05, 0.83 * h], [xb, y1, 0.9 * h]);
    }
    // A lit name board over the windscreen, standing up past the roof.
    b.cuboid(
        Light,
        [-c.hw + 0.05, yb - 0.1, 0.9 * h],
        [c.hw - 0.05, yb + g, h],
    );
    // Rear doors' seam, lamps and bumper.
    b.cuboid(
        Interior,
        [-0.01, -hd - g, c.zf + 0.1],
        [0.01, -hd, 0.95 * h],
    );
    rear(b, &c, 0.8 * c.hw, 0.35 * h, 0.12 * h, 0.08 * h);
    // A roof vent over the kitchen.
    let yv = 0.5 * (y0 + y1);
    b.cylinder(Metal, [0.0, yv, roof], 0.1, 0.09);
    b.cuboid(Metal, [-0.16, yv - 0.16, h - 0.03], [0.16, yv + 0.16, h]);
    b.translate_from(first, [shift, 0.0, 0.0]);
    // The counter shelf under the hatch and the awning over it, on two struts.
    b.cuboid(
        Top,
        [xs, y0 - 0.05, z0 - 0.04],
        [xs + 0.9 * out, y1 + 0.05, z0],
    );
    let tilt = 30f64.to_radians();
    let reach = out / tilt.cos();
    let za = z1 + 0.04 + 0.5 * out * tilt.tan();
    b.slab(
        Canvas,
        [xs + 0.5 * out, 0.5 * (y0 + y1), za],
        [0.5 * reach, 0.5 * (y1 - y0) + 0.08, 0.015],
        rot_y(-tilt),
    );
    for y in [y0 + 0.05, y1 - 0.05] {
        b.rod(
            Metal,
            [xs, y, z1 - 0.1],
            [xs + 0.9 * out, y, za + 0.4 * out * tilt.tan() - 0.02],
            0.012,
        );
    }
    let (xl, xr) = (shift - c.hw - c.g, xs + 0.02 + c.g);
    axle_between(b, (xl, xr), hd - 0.2 * b.d, c.r, c.tw);
    axle_between(b, (xl, xr), -hd + 0.18 * b.d, c.r, c.tw);
}

/// A tram: a long low body with a row of windows and three doors down each side, both ends
/// alike (a windscreen under a lit destination sign, headlights and a coupler bumper), a skirt
/// hiding small wheels on two bogies, and on the roof an equipment box and a pantograph, a
/// folded diamond of rods carrying a collector bar up to the top of the size box.
pub fn tram(b: &mut Builder) {
    let c = chassis(b, 0.1, 0.03, 0.2, 1.0);
    let (g, hw, hd, h, zf) = (c.g, c.hw, c.hd, c.h, c.zf);
    let zr = 0.8 * h;
    box_body(b, &c, (-hd, hd), zr, 0.02);
    b.cuboid(
        Top,
        [-hw + 0.08, -hd + 0.1, zr],
        [hw - 0.08, hd - 0.1, zr + 0.03],
    );
    // Windows down both sides, then three doors proud of them.
    let (y0, y1) = (-hd + 0.06 * b.d, hd - 0.06 * b.d);
    let n = ((y1 - y0) / 1.2).round().max(3.0) as usize;
    side_windows(b, hw - 0.02, (y0, y1), (0.45 * zr, 0.88 * zr), n);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.02);
        let (xa, xb) = if sx < 0.0 {
            (x - 2.0 * g, x)
        } else {
            (x, x + 2.0 * g)
        };
        let (dh, gh) = ((0.05 * b.d).min(0.6), (0.025 * b.d).min(0.3));
        for k in [-0.3, 0.0, 0.3] {
            let y = k * b.d;
            b.cuboid(Pane, [xa, y - dh, zf + 0.03], [xb, y + dh, 0.92 * zr]);
            for dy in [-gh, gh] {
                let (xa, xb) = if sx < 0.0 { (xa - g, xa) } else { (xb, xb + g) };
                b.cuboid(
                    Glass,
                    [xa, y + dy - 0.8 * gh, 0.3 * zr],
                    [xb, y + dy + 0.8 * gh, 0.85 * zr],
                );
            }
        }
        // The skirt over the wheels.
        b.cuboid(Frame, [xa, -hd + 0.05, zf], [xb, hd - 0.05, zf + 0.08 * h]);
    }
    // Both ends alike: windscreen, destination sign, headlights, bumper.
    for dir in [-1.0, 1.0] {
        let y = dir * hd;
        let (ya, yb) = if dir > 0.0 { (y, y + g) } else { (y - g, y) };
        b.cuboid(
            Glass,
            [-hw + 0.05, ya, 0.4 * zr],
            [hw - 0.05, yb, 0.85 * zr],
        );
        b.cuboid(
            Light,
            [-0.6 * hw, ya.min(yb + dir * g), 0.87 * zr],
            [0.6 * hw, yb.max(ya + dir * g), 0.97 * zr],
        );
        for sx in [-1.0, 1.0] {
            b.cuboid(
                Light,
                [sx * 0.7 * hw - 0.12, ya, 0.25 * zr],
                [sx * 0.7 * hw + 0.12, yb, 0.3 * zr],
            );
        }
        bumper(b, y, dir, zf, 0.12 * h);
    }
    // Small wheels on two bogies under the skirt.
    let r = 0.8 * c.r;
    for yb in [hd - 0.18 * b.d, -hd + 0.18 * b.d] {
        for dy in [-1.0, 1.0].map(|k| k * (0.075 * b.d).min(0.9)) {
            axle_between(b, (-hw + 0.1, hw - 0.1), yb + dy, r, c.tw);
        }
    }
    // The roof: an equipment box and a pantograph over the middle.
    let zt = zr + 0.03;
    b.cuboid(
        Metal,
        [-0.5 * hw, -0.15 * b.d, zt],
        [0.5 * hw, -0.03 * b.d, zt + 0.25],
    );
    let yp = 0.08 * b.d;
    b.cuboid(
        Frame,
        [-0.4 * hw, yp - 0.5, zt],
        [0.4 * hw, yp + 0.5, zt + 0.08],
    );
    let (zk, zc) = (zt + 0.5 * (h - zt), h - 0.04);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.3 * hw;
        b.polyline(
            Metal,
            &[[x, yp - 0.4, zt + 0.08], [x, yp + 0.35, zk], [x, yp, zc]],
            0.02,
        );
    }
    b.rod(Metal, [-0.6 * hw, yp, zc], [0.6 * hw, yp, zc], 0.03);
}
