//! Layouts of strength and boxing gear: a weight bench (a padded bench on a steel frame, with
//! uprights at its head holding a loaded barbell) and a punching bag hanging on a chain from
//! the arm of its stand, clear of the floor, and a squat rack (a cage of four steel uprights
//! with a loaded barbell on hooks at shoulder height). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A barbell plate: a disc of radius `r` on the bar at `x`, `w` thick, at (`y`, `z`).
fn plate(b: &mut Builder, x: f64, y: f64, z: f64, r: f64, w: f64) {
    b.rod(Metal, [x - w / 2.0, y, z], [x + w / 2.0, y, z], r);
    b.rod(
        Handle,
        [x - w / 2.0 - 0.004, y, z],
        [x + w / 2.0 + 0.004, y, z],
        0.25 * r,
    );
}

/// A weight bench: a long pad and a short seat pad on a steel spine with a foot at each end,
/// two uprights at the head end (-y) with hooks, a loaded barbell resting on them.
pub fn weight_bench(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pw = (0.14 * b.w).clamp(0.12, 0.16);
    let zp = (0.36 * h).min(0.45);
    let s = 0.05;
    // The steel frame: a spine under the pad, a T-foot at the front, the uprights' base behind.
    b.cuboid(
        Frame,
        [-s / 2.0, -hd + 0.25, zp - 0.12],
        [s / 2.0, hd - 0.08, zp - 0.07],
    );
    b.cuboid(
        Frame,
        [-s / 2.0, hd - 0.13, 0.0],
        [s / 2.0, hd - 0.08, zp - 0.07],
    );
    b.cuboid(Frame, [-2.0 * pw, hd - 0.13, 0.0], [2.0 * pw, hd - 0.08, s]);
    let xu = (0.62 * hw).max(pw + 0.1);
    let yu = -hd + 0.12;
    b.cuboid(Frame, [-xu - s, yu - 0.1, 0.0], [xu + s, yu + 0.1, s]);
    b.cuboid(Frame, [-s / 2.0, yu, 0.0], [s / 2.0, -hd + 0.25 + s, s]);
    b.cuboid(
        Frame,
        [-s / 2.0, -hd + 0.25, s],
        [s / 2.0, -hd + 0.25 + s, zp - 0.07],
    );
    // The pads: a long back pad and a short seat pad with a gap, on brackets.
    let y_split = hd - 0.42;
    b.cuboid(
        Upholstery,
        [-pw, -hd + 0.2, zp - 0.07],
        [pw, y_split - 0.02, zp],
    );
    b.cuboid(
        Upholstery,
        [-pw, y_split + 0.02, zp - 0.07],
        [pw, hd - 0.02, zp],
    );
    // The uprights with J hooks, a bar across them with plates at both ends.
    let zb = h - 0.2;
    for sx in [-1.0, 1.0] {
        let x = sx * xu;
        b.cuboid(
            Frame,
            [x - s / 2.0, yu - s / 2.0, s],
            [x + s / 2.0, yu + s / 2.0, zb + 0.08],
        );
        b.cuboid(
            Metal,
            [x - s / 2.0, yu, zb - 0.04],
            [x + s / 2.0, yu + 0.07, zb - 0.02],
        );
        b.cuboid(
            Metal,
            [x - s / 2.0, yu + 0.05, zb - 0.04],
            [x + s / 2.0, yu + 0.07, zb + 0.02],
        );
    }
    let yb = yu + 0.035;
    let zbar = zb - 0.02 + 0.015;
    b.rod(Handle, [-hw, yb, zbar], [hw, yb, zbar], 0.015);
    let rp = (h - zbar - 0.005).min(0.19);
    for sx in [-1.0, 1.0] {
        plate(b, sx * (hw - 0.12), yb, zbar, rp, 0.05);
        plate(b, sx * (hw - 0.065), yb, zbar, 0.75 * rp, 0.04);
    }
}

/// A punching bag on its stand: a base frame with counterweights, an upright at the back, an
/// arm reaching forward, a chain and four straps down to a long round bag that hangs clear of
/// the floor.
pub fn punching_bag(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.06;
    let yp = -hd + s;
    // The base: two rails front to back and a cross member behind; weight plates on pegs.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - s / 2.0);
        b.cuboid(Frame, [x - s / 2.0, -hd, 0.0], [x + s / 2.0, hd, s]);
        let xin = sx * (hw - s - 0.04);
        b.rod(
            Metal,
            [xin - 0.02, -hd + 0.2, s + 0.1],
            [xin + 0.02, -hd + 0.2, s + 0.1],
            0.1,
        );
    }
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + 2.0 * s, s]);
    b.cuboid(
        Frame,
        [-s / 2.0, yp - s / 2.0, s],
        [s / 2.0, yp + s / 2.0, h - 0.02],
    );
    // The arm over the bag, with a brace down to the upright.
    let yb = 0.25 * hd;
    b.cuboid(
        Frame,
        [-s / 2.0, yp - s / 2.0, h - 0.07],
        [s / 2.0, yb + 0.05, h - 0.02],
    );
    b.rod(Frame, [0.0, yp, h - 0.45], [0.0, yp + 0.3, h - 0.07], 0.02);
    // The bag: rounded ends, a seam band near the top, hanging clear of the floor.
    let r = (0.6 * hw.min(hd)).min(0.18);
    let z0 = 0.3 * h;
    let z1 = h - 0.5;
    let e = 0.06;
    b.revolved(
        Upholstery,
        0,
        [0.0, yb, z0],
        super::parts::IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [0.8 * r, 0.01],
            [r, e],
            [r, z1 - z0 - e],
            [0.8 * r, z1 - z0 - 0.01],
            [0.0, z1 - z0],
        ],
    );
    b.cylinder(Cushion, [0.0, yb, z1 - 0.16], 1.01 * r, 0.04);
    // Chain from the arm to a ring, straps from the ring to the bag's top.
    let ring = z1 + 0.18;
    let links = 6;
    for k in 0..links {
        let za = h - 0.07 - (h - 0.07 - ring) * k as f64 / links as f64;
        let zb = h - 0.07 - (h - 0.07 - ring) * (k + 1) as f64 / links as f64;
        b.ellipsoid(
            Metal,
            [0.0, yb, 0.5 * (za + zb)],
            [0.012, 0.012, 0.5 * (za - zb)],
        );
    }
    for k in 0..4 {
        let a = std::f64::consts::FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
        let (sa, ca) = a.sin_cos();
        b.rod(
            Metal,
            [0.0, yb, ring],
            [0.7 * r * ca, yb + 0.7 * r * sa, z1 - 0.01],
            0.006,
        );
    }
}

/// An exercise bike: no wheels to ride on, but a heavy flywheel at the front under a cover,
/// a frame on two floor stabilisers, a saddle on its post, cranks with pedals, and a column at
/// the front carrying the handlebars and a small console.
pub fn exercise_bike(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.045;
    // The stabilisers across the floor, front and back.
    let (yf, yr) = (hd - 0.08, -hd + 0.08);
    for y in [yf, yr] {
        b.cuboid(Frame, [-0.9 * hw, y - s, 0.0], [0.9 * hw, y + s, s]);
    }
    // The flywheel at the front, a heavy disc across x, and its half cover.
    let rf = (0.22 * h).min(0.3 * hd);
    let (yw, zw) = (yf - rf - 0.05, rf + 0.08);
    b.rod(Metal, [-0.03, yw, zw], [0.03, yw, zw], rf);
    b.rod(Tyre, [-0.035, yw, zw], [0.035, yw, zw], 0.3 * rf);
    // The frame: a beam from the back foot up to the saddle post, a front column up to the bars.
    let post = [0.0, -0.35 * hd, 0.5 * h];
    let saddle = [0.0, -0.4 * hd, 0.72 * h];
    let bars = [0.0, yf - 0.2, 0.92 * h];
    let crank = [0.0, -0.05 * hd, zw];
    b.polyline(Frame, &[[0.0, yr, s], crank, [0.0, yw, zw]], 0.03);
    b.polyline(Frame, &[crank, post, saddle], 0.028);
    b.polyline(
        Frame,
        &[[0.0, yf, s], [0.0, yw + 0.05, zw + rf], bars],
        0.03,
    );
    b.rod(Frame, post, [0.0, yw + 0.05, zw + rf], 0.025);
    b.ellipsoid(
        Seat,
        [0.0, saddle[1], saddle[2] + 0.03],
        [0.09, 0.15, 0.035],
    );
    // The handlebars: a bar across with grips reaching back, a console above them.
    let gx = 0.8 * hw.min(0.3);
    b.rod(
        Metal,
        [-gx, bars[1], bars[2]],
        [gx, bars[1], bars[2]],
        0.016,
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Upholstery,
            [sx * gx, bars[1], bars[2]],
            [sx * gx, bars[1] - 0.18, bars[2] + 0.04],
            0.02,
        );
    }
    b.cuboid(
        Screen,
        [-0.1, bars[1] + 0.02, bars[2] + 0.05],
        [0.1, bars[1] + 0.07, (bars[2] + 0.17).min(h)],
    );
    // The cranks and pedals either side of the crank hub.
    for sx in [-1.0, 1.0] {
        let p = [sx * 0.09, crank[1] + 0.05 * sx, crank[2] - 0.12 * sx];
        b.rod(Metal, [sx * 0.06, crank[1], crank[2]], p, 0.012);
        b.cuboid(
            Upholstery,
            [p[0] - 0.05, p[1] - 0.05, p[2] - 0.012],
            [p[0] + 0.05, p[1] + 0.05, p[2] + 0.012],
        );
    }
}

/// A squat rack: four steel uprights on floor rails joined at the top, a row of holes down the
/// front pair, J hooks on them holding a loaded barbell across the front at shoulder height,
/// safety arms below it and a peg of spare plates at each back corner.
pub fn squat_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.06;
    // The bar's plates stand out past the uprights: the cage is narrower than the bar.
    let xu = (hw - 0.25).max(0.45 * hw);
    let (yf, yb) = (0.45 * hd, -hd + s);
    for x in [-xu, xu] {
        b.cuboid(Frame, [x - s / 2.0, -hd, 0.0], [x + s / 2.0, hd, s]);
        for y in [yf, yb] {
            b.cuboid(
                Frame,
                [x - s / 2.0, y - s / 2.0, s],
                [x + s / 2.0, y + s / 2.0, h],
            );
        }
        b.cuboid(Frame, [x - s / 2.0, yb, h - s], [x + s / 2.0, yf, h]);
        // Holes down the front upright.
        let mut z = 0.4;
        while z < h - 0.15 {
            b.cuboid(
                Interior,
                [x - 0.01, yf + s / 2.0, z],
                [x + 0.01, yf + s / 2.0 + 0.002, z + 0.02],
            );
            z += 0.1;
        }
    }
    for y in [yf, yb] {
        b.cuboid(Frame, [-xu, y - s / 2.0, h - s], [xu, y + s / 2.0, h]);
    }
    b.cuboid(Frame, [-xu, yb - s / 2.0, 0.0], [xu, yb + s / 2.0, s]);
    // J hooks and the loaded bar on them, the safety arms lower, through the cage.
    let zb = (0.62 * h).min(1.45);
    let yh = yf + s / 2.0 + 0.04;
    for x in [-xu, xu] {
        b.cuboid(
            Metal,
            [x - s / 2.0, yf + s / 2.0, zb - 0.05],
            [x + s / 2.0, yh + 0.03, zb - 0.03],
        );
        b.cuboid(
            Metal,
            [x - s / 2.0, yh + 0.01, zb - 0.05],
            [x + s / 2.0, yh + 0.03, zb + 0.03],
        );
        b.cuboid(
            Metal,
            [x - 0.025, yb, 0.45 * zb - 0.02],
            [x + 0.025, hd, 0.45 * zb + 0.02],
        );
    }
    let zbar = zb - 0.015;
    b.rod(Handle, [-hw, yh, zbar], [hw, yh, zbar], 0.015);
    let r = (0.22f64).min(hd - yh).min(zbar - 0.45 * zb - 0.03).max(0.1);
    for sx in [-1.0, 1.0] {
        for (k, rr) in [r, 0.8 * r].into_iter().enumerate() {
            plate(b, sx * (xu + 0.08 + 0.045 * k as f64), yh, zbar, rr, 0.04);
        }
        // A peg of spare plates standing out from a post on the floor rail.
        let (xp, yp, rp) = (sx * (xu + 0.06), -hd + 0.27, 0.25);
        b.cuboid(
            Frame,
            [sx * xu - 0.025, yp - 0.025, s],
            [sx * xu + 0.025, yp + 0.025, 0.33],
        );
        b.rod(Metal, [sx * xu, yp, 0.3], [xp + sx * 0.12, yp, 0.3], 0.02);
        for k in 0..3 {
            plate(
                b,
                xp + sx * 0.045 * k as f64,
                yp,
                0.3,
                rp - 0.03 * k as f64,
                0.04,
            );
        }
    }
}
