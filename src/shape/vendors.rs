//! Things food and tickets are sold from that are not a market stall: a street food cart (a
//! box body on two wheels at one end and a stand at the other, a push bar, lidded wells on its
//! top and an umbrella over it on a pole) and a ticket booth (a small cabin with a window over a
//! counter at its front, a sign band over the window, a door at its side and a roof that
//! overhangs). The front faces +y; a cart's length runs along its longer side.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_z;

/// A food cart (hot dogs, ice cream) at the builder's size.
pub fn food_cart(b: &mut Builder) {
    let first = b.parts.len();
    let along_y = b.d > b.w;
    let (w, d) = (b.w, b.d);
    if along_y {
        (b.w, b.d) = (d, w);
    }
    cart_along_x(b);
    if along_y {
        (b.w, b.d) = (w, d);
        b.turn_from(first, rot_z(std::f64::consts::FRAC_PI_2));
    }
}

fn cart_along_x(b: &mut Builder) {
    let (hl, ha, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (z0, z1) = (0.2 * h, 0.46 * h);
    let (x0, x1) = (-0.72 * hl, 0.9 * hl);
    let tyre = (0.05 * ha).max(0.03);
    b.cuboid(Body, [x0, -0.8 * ha, z0], [x1, 0.8 * ha, z1]);
    b.cuboid(
        Metal,
        [x0 - 0.01, -0.82 * ha, z1],
        [x1 + 0.01, 0.82 * ha, z1 + 0.02 * h],
    );
    // Lidded wells along the top.
    for k in 0..3 {
        let x = x0 + (k as f64 + 0.6) / 3.4 * (x1 - x0);
        b.cylinder(
            Metal,
            [x, 0.0, z1 + 0.02 * h],
            0.5 * ha.min(0.25 * hl),
            0.03 * h,
        );
        b.ellipsoid(
            Handle,
            [x, 0.0, z1 + 0.055 * h],
            [0.03 * h, 0.03 * h, 0.012 * h],
        );
    }
    // Two wheels at the far end, one each side.
    let r = 0.17 * h;
    let wx = 0.5 * hl;
    for sy in [-1.0, 1.0] {
        let y = sy * (ha - tyre);
        b.rod(Tyre, [wx, y - sy * tyre, r], [wx, y + sy * tyre, r], r);
        b.rod(
            Metal,
            [wx, y - sy * 1.2 * tyre, r],
            [wx, y + sy * 1.1 * tyre, r],
            0.35 * r,
        );
    }
    // A stand at the near end and the push bar out past it.
    for sy in [-1.0, 1.0] {
        b.rod(
            Metal,
            [x0 + 0.05 * hl, sy * 0.6 * ha, z0],
            [x0 + 0.05 * hl, sy * 0.6 * ha, 0.0],
            0.015 * h,
        );
        b.polyline(
            Handle,
            &[
                [x0, sy * 0.6 * ha, z1 - 0.02 * h],
                [-0.98 * hl, sy * 0.6 * ha, z1 + 0.04 * h],
            ],
            0.012 * h,
        );
    }
    b.rod(
        Handle,
        [-0.98 * hl, -0.62 * ha, z1 + 0.04 * h],
        [-0.98 * hl, 0.62 * ha, z1 + 0.04 * h],
        0.014 * h,
    );
    // The umbrella: a pole from the top up to a shallow cone with a valance round its rim.
    let pole = 0.012 * h;
    b.cylinder(Frame, [0.1 * hl, 0.0, z1], pole, 0.97 * h - z1);
    let (rx, ry) = (0.98 * hl, 0.98 * ha);
    b.frustum(
        Shade,
        [0.1 * hl, 0.0, 0.8 * h],
        rx.min(hl - 0.1 * hl + 0.9 * hl),
        ry,
        0.06,
        0.17 * h,
    );
    b.frustum(Canvas, [0.1 * hl, 0.0, 0.77 * h], rx, ry, 1.0, 0.03 * h);
}

/// A ticket booth at the builder's size.
pub fn ticket_booth(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let eave = 0.08 * hw.min(hd);
    let (w0, d0) = (hw - eave, hd - eave);
    let roof = 0.84 * h;
    let wall = 0.05;
    b.cuboid(Top, [-hw, -hd, 0.0], [hw, hd, 0.04 * h]);
    // Walls: solid under the window and round it, the window across most of the front.
    let (win0, win1) = (0.42 * h, 0.72 * h);
    b.cuboid(Body, [-w0, -d0, 0.04 * h], [w0, d0 - wall, roof]);
    b.cuboid(Body, [-w0, d0 - wall, 0.04 * h], [w0, d0, win0]);
    b.cuboid(Body, [-w0, d0 - wall, win1], [w0, d0, roof]);
    for sx in [-1.0, 1.0] {
        b.cuboid(Body, [sx * w0, d0 - wall, win0], [sx * 0.75 * w0, d0, win1]);
    }
    b.cuboid(
        Glass,
        [-0.75 * w0, d0 - 0.6 * wall, win0],
        [0.75 * w0, d0 - 0.5 * wall, win1],
    );
    b.cuboid(
        Interior,
        [-0.15 * w0, d0 - 0.45 * wall, win0],
        [0.15 * w0, d0 - 0.4 * wall, win0 + 0.04 * h],
    );
    // The counter under the window and the sign band over it.
    b.cuboid(Top, [-0.8 * w0, d0, win0 - 0.03 * h], [0.8 * w0, hd, win0]);
    b.cuboid(
        Canvas,
        [-0.7 * w0, d0, win1 + 0.02 * h],
        [0.7 * w0, d0 + 0.01, roof - 0.02 * h],
    );
    // A door at the side.
    b.cuboid(
        Frame,
        [w0, -0.6 * d0, 0.05 * h],
        [w0 + 0.01, 0.1 * d0, 0.78 * h],
    );
    b.cuboid(
        Handle,
        [w0 + 0.01, 0.0, 0.4 * h],
        [w0 + 0.03, 0.05 * d0, 0.44 * h],
    );
    // The roof: a slab over the eaves and a low pyramid.
    b.cuboid(Top, [-hw, -hd, roof], [hw, hd, roof + 0.04 * h]);
    b.frustum(
        Shade,
        [0.0, 0.0, roof + 0.04 * h],
        hw * std::f64::consts::SQRT_2,
        hd * std::f64::consts::SQRT_2,
        0.05,
        h - roof - 0.04 * h,
    );
}
