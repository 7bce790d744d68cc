//! Layouts of seats that carry someone who needs the help: a wheelchair (two big spoked wheels
//! at the back with push rims outside them, small castors in front, a sling seat and back
//! between tube frames, armrests, push handles and footplates) and a child's high chair (four
//! splayed legs, a seat with sides well above the floor, a tray in front and a footrest). The
//! front faces +y.
use super::archetypes::Builder;
use super::fittings::{band, castor, pad, spoked_wheel, X};
use super::materials::Role::*;

/// A wheelchair: the big wheels stand at the sides of the back half and reach most of its
/// height; the seat, back and footplates sit between them.
pub fn wheelchair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.34 * h).min(0.7 * hd).min(0.33);
    let yw = -hd + r + 0.01;
    let xt = hw - 0.045;
    for sx in [-1.0, 1.0] {
        spoked_wheel(b, [sx * xt, yw, r], r, 0.032, 12);
        // The push rim, just outside the tyre on four stand-offs.
        let xp = sx * (hw - 0.008);
        band(b, Metal, [xp, yw, r], X, 0.86 * r, 0.012, 0.012);
        for k in 0..4 {
            let a = k as f64 * std::f64::consts::FRAC_PI_2 + 0.4;
            let (y, z) = (yw + 0.8 * r * a.cos(), r + 0.8 * r * a.sin());
            b.rod(Metal, [sx * xt, y, z], [xp, y, z], 0.005);
        }
    }
    // The side frames: a seat rail, the back post rising to a push handle, a front post down to
    // the castor, a low rail to the axle and a hanger out to the footplate.
    let xs = hw - 0.1;
    let zs = (0.55 * h).min(0.52);
    let (y_back, y_front) = (yw - 0.1, (yw + 0.42).min(hd - 0.3));
    let tube = 0.012;
    let yc = y_front - 0.02;
    let rc = (0.08 * h).clamp(0.05, 0.08);
    for sx in [-1.0, 1.0] {
        let x = sx * xs;
        b.rod(Frame, [x, y_back, zs], [x, y_front, zs], tube);
        b.polyline(
            Frame,
            &[
                [x, y_back + 0.02, zs - 0.12],
                [x, y_back - 0.04, h - 0.08],
                [x, y_back - 0.12, h - 0.06],
            ],
            tube,
        );
        b.rod(
            Handle,
            [x, y_back - 0.1, h - 0.06],
            [x, y_back - 0.2, h - 0.05],
            0.02,
        );
        b.rod(Frame, [x, y_front, zs], [x, yc, 2.0 * rc + 0.02], tube);
        b.rod(Frame, [x, yw, r], [x, y_front, 0.6 * r], tube);
        b.rod(Frame, [x, y_front, zs], [x, hd - 0.12, 0.2], tube);
        castor(b, x, yc, rc, 2.0 * rc + 0.03);
        // The armrest: a padded bar on two posts.
        let za = zs + 0.22;
        b.rod(Frame, [x, y_back + 0.08, zs], [x, y_back + 0.08, za], tube);
        b.rod(Frame, [x, y_back + 0.3, zs], [x, y_back + 0.3, za], tube);
        b.cuboid(
            Upholstery,
            [x - 0.03, y_back + 0.04, za],
            [x + 0.03, y_back + 0.36, za + 0.035],
        );
        // The footplate, hinged at the hanger's foot.
        b.cuboid(
            Frame,
            [x.min(sx * 0.04), hd - 0.17, 0.15],
            [x.max(sx * 0.04), hd - 0.01, 0.17],
        );
    }
    // The sling seat sagging a little between the rails, the sling back between the posts, and
    // the folding cross-brace under the seat.
    b.cuboid(
        Upholstery,
        [-xs, y_back, zs - 0.025],
        [xs, y_front, zs + 0.01],
    );
    pad(
        b,
        Upholstery,
        0.0,
        [y_back + 0.01, zs + 0.04],
        [y_back - 0.035, h - 0.14],
        xs,
        0.02,
    );
    let ym = 0.5 * (y_back + y_front);
    b.rod(Frame, [-xs, ym, zs - 0.02], [xs, ym, 0.6 * r], tube);
    b.rod(Frame, [xs, ym, zs - 0.02], [-xs, ym, 0.6 * r], tube);
}

/// A child's high chair: four legs splayed out to a footprint wider than the seat, a seat with
/// a back and sides well above the floor, a tray in front at elbow height, a footrest and rails
/// between the legs.
pub fn high_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = 0.58 * h;
    let (sx0, sy0, sy1) = ((0.3 * b.w).min(0.2), -0.55 * hd, 0.25 * hd);
    let leg = 0.018;
    for sx in [-1.0, 1.0] {
        for (sy, ys) in [(-1.0, sy0), (1.0, sy1)] {
            let top = [sx * sx0, ys, zs];
            let foot = [sx * (hw - leg), sy * (hd - leg), 0.0];
            b.rod(Frame, foot, top, leg);
        }
    }
    // Rails between the legs low down and a footrest bar at the front.
    let lerp = |t: f64, a: f64, c: f64| a + t * (c - a);
    for (t, role) in [(0.25, Frame), (0.55, Top)] {
        let z = t * zs;
        let x = lerp(t, hw - leg, sx0);
        let yb = lerp(t, -(hd - leg), sy0);
        let yf = lerp(t, hd - leg, sy1);
        if role == Frame {
            b.rod(Frame, [-x, yb, z], [x, yb, z], 0.012);
            for sx in [-1.0, 1.0] {
                b.rod(Frame, [sx * x, yb, z], [sx * x, yf, z], 0.012);
            }
        } else {
            b.cuboid(Top, [-x, yf - 0.05, z - 0.012], [x, yf + 0.01, z + 0.012]);
        }
    }
    // The seat, its cushion, the sides and the back.
    b.cuboid(
        Seat,
        [-sx0 - 0.01, sy0 - 0.01, zs],
        [sx0 + 0.01, sy1 + 0.02, zs + 0.03],
    );
    b.cuboid(
        Cushion,
        [-sx0 + 0.01, sy0 + 0.02, zs + 0.03],
        [sx0 - 0.01, sy1, zs + 0.06],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * (sx0 + 0.005);
        b.cuboid(
            Seat,
            [x - 0.012, sy0, zs],
            [x + 0.012, sy1 - 0.03, zs + 0.2],
        );
    }
    pad(
        b,
        Seat,
        0.0,
        [sy0 - 0.005, zs + 0.02],
        [sy0 - 0.06, h - 0.02],
        sx0 + 0.01,
        0.024,
    );
    // The tray: a board with a raised lip reaching out in front of the seat at elbow height.
    let zt = zs + 0.2;
    let (tx, ty0, ty1) = ((0.8 * hw).max(sx0 + 0.04), sy1 - 0.05, hd - 0.02);
    b.cuboid(Top, [-tx, ty0, zt], [tx, ty1, zt + 0.018]);
    b.cuboid(Top, [-tx, ty1 - 0.015, zt + 0.018], [tx, ty1, zt + 0.045]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Top,
            [sx * tx - 0.0075 * (sx + 1.0), ty0, zt + 0.018],
            [sx * tx - 0.0075 * (sx - 1.0), ty1, zt + 0.045],
        );
    }
}
