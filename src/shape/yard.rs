//! Layouts of garden, playground and shop things: a garden gnome (boots, a round coat with a
//! belt, a white beard under a face and nose, a tall pointed hat), a seesaw (a long plank
//! balanced on a central pivot, a seat and an upright handle at each end), a lawn mower (a
//! low deck on four wheels, the engine on it, a grass bag behind and a long handle rising back
//! over the bag) and a shopping cart (a wire basket on a wheeled frame, a tray under it, a
//! handle at the back). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_y, IDENTITY};

/// A garden gnome.
pub fn gnome(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = hw.min(hd);
    // Boots, and a round coat from the boots to the shoulders.
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            BlackKeys,
            [sx * 0.35 * s, 0.15 * s, 0.04 * h],
            [0.28 * s, 0.42 * s, 0.04 * h],
        );
    }
    b.frustum(Body, [0.0, 0.0, 0.04 * h], 0.8 * s, 0.75 * s, 0.8, 0.36 * h);
    b.ellipsoid(Body, [0.0, 0.0, 0.4 * h], [0.64 * s, 0.6 * s, 0.06 * h]);
    b.frustum(
        Frame,
        [0.0, 0.0, 0.17 * h],
        0.73 * s,
        0.69 * s,
        0.98,
        0.04 * h,
    );
    b.cuboid(
        Metal,
        [-0.1 * s, 0.66 * s, 0.17 * h],
        [0.1 * s, 0.72 * s, 0.21 * h],
    );
    // Arms hanging at the sides, hands in front.
    for sx in [-1.0, 1.0] {
        b.rod(
            Body,
            [sx * 0.7 * s, 0.0, 0.4 * h],
            [sx * 0.65 * s, 0.35 * s, 0.22 * h],
            0.16 * s,
        );
        b.ellipsoid(
            Skin,
            [sx * 0.6 * s, 0.45 * s, 0.2 * h],
            [0.14 * s, 0.14 * s, 0.03 * h],
        );
    }
    // The head: a face, a round nose, and a white beard down over the chest.
    let zf = 0.52 * h;
    b.ellipsoid(Skin, [0.0, 0.0, zf], [0.48 * s, 0.46 * s, 0.08 * h]);
    b.ellipsoid(Skin, [0.0, 0.46 * s, zf], [0.12 * s, 0.12 * s, 0.02 * h]);
    b.ellipsoid(
        Canvas,
        [0.0, 0.28 * s, 0.42 * h],
        [0.42 * s, 0.3 * s, 0.12 * h],
    );
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            BlackKeys,
            [sx * 0.16 * s, 0.42 * s, zf + 0.02 * h],
            [0.05 * s, 0.04 * s, 0.01 * h],
        );
    }
    // The hat: a brim round the head and a tall cone leaning back a little.
    b.frustum(
        Upholstery,
        [0.0, 0.0, zf + 0.04 * h],
        0.52 * s,
        0.5 * s,
        0.95,
        0.03 * h,
    );
    b.revolved(
        Upholstery,
        0,
        [0.0, 0.0, zf + 0.06 * h],
        super::parts::rot_x(0.12),
        0.96,
        frustum_profile(0.47 * s, 0.03 * s, h - zf - 0.07 * h),
    );
}

/// A seesaw: a plank along x balanced on a pivot at its middle (a bar on two splayed posts),
/// tilted so one end is near the ground; a seat pad and a T handle near each end.
pub fn seesaw(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The plank, tilted about the pivot so its low end is near the ground and the handle at
    // its high end stays under the top of the box.
    let t = 0.045;
    let half = 0.97 * hw;
    let hh = 0.3 * h;
    let sin = ((0.92 * h - 0.06 * h - t - hh) / (half + 0.62 * hw)).clamp(0.0, 0.3);
    let tilt = sin.asin();
    let zp = 0.06 * h + half * sin - 0.04;
    let rot = rot_y(tilt);
    // The pivot: an axle across on an A frame at each side.
    for sy in [-1.0, 1.0] {
        let y = sy * 0.75 * hd;
        for sx in [-1.0, 1.0] {
            b.rod(Frame, [sx * 0.12 * hw, y, 0.0], [0.0, y, zp], 0.03);
        }
    }
    b.rod(Metal, [0.0, -0.85 * hd, zp], [0.0, 0.85 * hd, zp], 0.04);
    let at = |u: f64, v: f64, w: f64| {
        let p = super::parts::mul(&rot, [u, v, w]);
        [p[0], p[1], zp + 0.04 + p[2]]
    };
    b.slab(Top, at(0.0, 0.0, t / 2.0), [half, 0.45 * hd, t / 2.0], rot);
    b.slab(Frame, at(0.0, 0.0, -0.012), [0.1 * hw, 0.5 * hd, 0.01], rot);
    for sx in [-1.0, 1.0] {
        let u = sx * 0.8 * hw;
        b.slab(
            Seat,
            at(u, 0.0, t + 0.02),
            [0.12 * hw, 0.46 * hd, 0.02],
            rot,
        );
        // The handle in front of the seat (towards the middle): a post and a crossbar.
        let uh = sx * 0.62 * hw;
        let p0 = at(uh, 0.0, t);
        b.rod(Handle, p0, [p0[0], p0[1], p0[2] + hh], 0.025);
        b.rod(
            Handle,
            [p0[0], -0.6 * hd, p0[2] + hh],
            [p0[0], 0.6 * hd, p0[2] + hh],
            0.025,
        );
    }
}

/// A push lawn mower: the deck (a low round-fronted shell) on four wheels at the front, its
/// engine on top, the grass bag behind the deck and the handle: two bars from the deck up and
/// back to a grip with its lever.
pub fn lawn_mower(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.1 * h).min(0.2 * hw);
    let (y0, y1) = (hd - 0.5 * b.d, hd - 0.02);
    let zd = 0.2 * h;
    let (yc, ry) = (0.5 * (y0 + y1), 0.5 * (y1 - y0));
    // The deck: a flat shell with a skirt, rounded at the front.
    b.cuboid(Body, [-0.78 * hw, y0, 0.5 * r], [0.78 * hw, yc, zd]);
    b.revolved(
        Body,
        0,
        [0.0, yc, 0.5 * r],
        IDENTITY,
        ry / (0.78 * hw),
        frustum_profile(0.78 * hw, 0.7 * hw, zd - 0.5 * r),
    );
    // Wheels at the four corners of the deck.
    for sx in [-1.0, 1.0] {
        for y in [y0 + 0.8 * r, y1 - r] {
            b.rod(Tyre, [sx * 0.78 * hw, y, r], [sx * hw, y, r], r);
            b.rod(Metal, [sx * (hw - 0.004), y, r], [sx * hw, y, r], 0.5 * r);
        }
    }
    // The engine: a block and its round cover, a pull cord handle.
    b.cuboid(
        Frame,
        [-0.35 * hw, yc - 0.4 * ry, zd],
        [0.35 * hw, yc + 0.4 * ry, zd + 0.08 * h],
    );
    b.cylinder(Top, [0.0, yc, zd + 0.08 * h], 0.4 * hw, 0.1 * h);
    b.rod(
        Handle,
        [0.3 * hw, yc - 0.3 * ry, zd + 0.2 * h],
        [0.3 * hw, yc - 0.5 * ry, zd + 0.22 * h],
        0.012,
    );
    // The grass bag behind the deck.
    let yb = -hd + 0.08 * b.d;
    b.cuboid(Canvas, [-0.6 * hw, yb, 0.08 * h], [0.6 * hw, y0, 0.42 * h]);
    b.cuboid(
        Frame,
        [-0.6 * hw, yb - 0.01, 0.38 * h],
        [0.6 * hw, y0, 0.44 * h],
    );
    // The handle: two bars from the back of the deck up over the bag, a grip across.
    let (ya, za) = (y0 + 0.02, zd);
    let (yt, zt) = (-hd + 0.01, 0.97 * h);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.62 * hw;
        b.rod(Metal, [x, ya, za], [x, yt + 0.03, zt], 0.014);
    }
    b.rod(
        Handle,
        [-0.66 * hw, yt + 0.03, zt],
        [0.66 * hw, yt + 0.03, zt],
        0.02,
    );
    b.rod(
        Metal,
        [-0.6 * hw, yt + 0.06, zt - 0.06],
        [0.6 * hw, yt + 0.06, zt - 0.06],
        0.008,
    );
}

/// A shopping cart: a wire basket (wider at the back, a grid of thin bars on every side and
/// the floor) on a frame of two rails on four casters, a tray low between the rails, and a
/// plastic-covered handle at the back above the fold-down child seat.
pub fn shopping_cart(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rw = 0.05f64.min(0.1 * h);
    // Casters and the two base rails.
    let cw = 0.78 * hw;
    for sx in [-1.0, 1.0] {
        for (y, x) in [(hd - 0.1 * b.d, 0.7 * cw), (-hd + 0.12 * b.d, cw)] {
            let x = sx * x;
            b.rod(Tyre, [x - 0.015, y, rw], [x + 0.015, y, rw], rw);
            b.rod(Metal, [x, y, 2.0 * rw], [x, y, 3.0 * rw], 0.01);
        }
        b.rod(
            Metal,
            [sx * 0.7 * cw, hd - 0.1 * b.d, 3.0 * rw],
            [sx * cw, -hd + 0.12 * b.d, 3.0 * rw],
            0.012,
        );
    }
    // The low tray.
    let zt = 0.22 * h;
    b.cuboid(
        Frame,
        [-0.6 * cw, -hd + 0.15 * b.d, zt],
        [0.6 * cw, hd - 0.15 * b.d, zt + 0.01],
    );
    // The basket: its back uprights carry it on the rails.
    let (zb, zu) = (0.5 * h, 0.88 * h);
    let (yf, yk) = (hd - 0.02, -hd + 0.14 * b.d);
    let (xf, xk) = (0.72 * hw, 0.96 * hw);
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [sx * cw, -hd + 0.12 * b.d, 3.0 * rw],
            [sx * xk, yk, zb],
            0.012,
        );
        b.rod(
            Metal,
            [sx * 0.7 * cw, hd - 0.1 * b.d, 3.0 * rw],
            [sx * xf * 0.9, yf - 0.05, zb],
            0.012,
        );
    }
    let wr = 0.005;
    let lerp = |a: f64, c: f64, t: f64| a + (c - a) * t;
    // Bars along y on the floor and on both sides, front to back.
    let n = 9;
    for i in 0..=n {
        let t = i as f64 / n as f64;
        let (xa, xb) = (lerp(-xf, xf, t), lerp(-xk, xk, t));
        b.rod(Metal, [xa, yf, zb], [xb, yk, zb], wr);
    }
    let m = 6;
    for k in 0..=m {
        let z = lerp(zb, zu, k as f64 / m as f64);
        for sx in [-1.0, 1.0] {
            b.rod(Metal, [sx * xf, yf, z], [sx * xk, yk, z], wr);
        }
        b.rod(Metal, [-xf, yf, z], [xf, yf, z], wr);
        b.rod(Metal, [-xk, yk, z], [xk, yk, z], wr);
    }
    // Uprights along the sides, the front and the back.
    let u = 10;
    for i in 0..=u {
        let t = i as f64 / u as f64;
        let (y, x) = (lerp(yf, yk, t), lerp(xf, xk, t));
        for sx in [-1.0, 1.0] {
            b.rod(Metal, [sx * x, y, zb], [sx * x, y, zu], wr);
        }
    }
    for i in 0..=8 {
        let t = i as f64 / 8.0;
        b.rod(
            Metal,
            [lerp(-xf, xf, t), yf, zb],
            [lerp(-xf, xf, t), yf, zu],
            wr,
        );
        b.rod(
            Metal,
            [lerp(-xk, xk, t), yk, zb],
            [lerp(-xk, xk, t), yk, zu],
            wr,
        );
    }
    // The rim, and the handle on two arms behind the basket.
    for sx in [-1.0, 1.0] {
        b.rod(Frame, [sx * xf, yf, zu], [sx * xk, yk, zu], 0.01);
        b.rod(
            Frame,
            [sx * xk, yk, zu],
            [sx * xk, -hd + 0.03, 0.97 * h],
            0.012,
        );
    }
    b.rod(Frame, [-xf, yf, zu], [xf, yf, zu], 0.01);
    b.rod(
        Handle,
        [-xk, -hd + 0.03, 0.97 * h],
        [xk, -hd + 0.03, 0.97 * h],
        0.025,
    );
}
