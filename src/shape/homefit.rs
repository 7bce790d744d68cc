//! Layouts of household things that used to borrow a neighbour's drawing: a folding chair
//! (once a plain four-legged chair: now legs crossing in an X on each side under a slatted
//! seat), a loft bed (once a bunk bed with a lower bunk: now one bed high on posts with a desk
//! under it), a watering can (once a kettle: now a low tank with a long rising spout and a
//! rose, a loop handle over it), a wall mirror (once a board on a foot: now a moulded frame
//! round the glass with its hanging wire at the back) and a window seat (once an open bench
//! on legs: now a built-in panelled box under a thick cushion between two end panels, with
//! pillows against the back). The front faces +y; each stays inside its size box.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::frustum_profile;

/// A folding chair: on each side two tubes crossing in an X under the seat (one from the
/// front foot up to the seat's back, one from the back foot up to the seat's front) pinned
/// where they cross, the back posts rising from the seat's back to a curved back panel, a
/// slatted seat and floor bars joining the feet.
pub fn folding_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = 0.55 * h;
    let r = 0.012 * (h / 0.8).clamp(0.7, 1.5);
    let x = hw - r;
    let (yf, yb) = (0.88 * hd, -0.88 * hd);
    let (sf, sb) = (0.8 * hd, -0.55 * hd);
    for sx in [-1.0, 1.0] {
        let x = sx * x;
        b.rod(Metal, [x, yf, r], [x, sb, zs], r);
        b.rod(Metal, [x, yb, r], [x, sf, zs], r);
        // the pin where they cross
        let t = (yf - sb) / ((yf - sb) + (sf - yb));
        b.rod(
            Handle,
            [x - sx * 1.5 * r, yf + t * (sb - yf), t * zs],
            [x + sx * 0.5 * r, yf + t * (sb - yf), t * zs],
            1.6 * r,
        );
        // the back post, leaning back a little from the seat's back to the top
        b.rod(Metal, [x, sb, zs], [x, -hd + r, h - r], r);
        // the seat's side rail
        b.rod(Metal, [x, sb, zs], [x, sf, zs], r);
    }
    // floor bars joining the feet, a bar under the seat's front
    b.rod(Metal, [-x, yf, r], [x, yf, r], r);
    b.rod(Metal, [-x, yb, r], [x, yb, r], r);
    // the slatted seat
    let n = 4;
    let pitch = (sf - sb) / n as f64;
    for k in 0..n {
        let y = sb + (k as f64 + 0.5) * pitch;
        b.cuboid(
            Seat,
            [-x, y - 0.42 * pitch, zs + r],
            [x, y + 0.42 * pitch, zs + r + 0.02],
        );
    }
    // the back panel between the posts' tops
    let yt = -hd + r;
    b.cuboid(
        Seat,
        [-x + r, yt - 0.01, h - 0.22 * h],
        [x - r, yt + 0.02, h - 0.03 * h],
    );
}

/// A loft bed: four tall posts, the bed frame high on them with its mattress, duvet and
/// pillow, guard rails round the top, a ladder up the front right, and a desk under it (a top
/// across the posts, a drawer pedestal at the left).
pub fn loft_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let p = 0.06;
    b.legs(Frame, p, 0.0, 0.0, h);
    let zb = 0.62 * h;
    b.cuboid(Frame, [-hw + p, -hd, zb], [hw - p, hd, zb + 0.08]);
    b.cuboid(
        Mattress,
        [-hw + p, -hd + p, zb + 0.08],
        [hw - p, hd - p, zb + 0.2],
    );
    b.cuboid(
        Duvet,
        [-hw + p, -hd + 0.55, zb + 0.2],
        [hw - p, hd - p, zb + 0.23],
    );
    b.ellipsoid(
        Pillow,
        [0.0, -hd + p + 0.18, zb + 0.25],
        [0.3 * b.w, 0.14, 0.05],
    );
    // guard rails: both ends and the wall side full length, the room side up to the ladder
    let zr = (zb + 0.4).min(h - 0.02);
    let ly = hd - 0.4;
    b.cuboid(Frame, [-hw, -hd, zr - 0.06], [hw, -hd + p, zr]);
    b.cuboid(Frame, [-hw, hd - p, zr - 0.06], [hw, hd, zr]);
    b.cuboid(Frame, [-hw, -hd + p, zr - 0.06], [-hw + 0.04, hd - p, zr]);
    b.cuboid(Frame, [hw - 0.04, -hd + p, zr - 0.06], [hw, ly - 0.22, zr]);
    // the ladder on the room side (+x) near the foot
    for dy in [-0.18, 0.18] {
        b.cuboid(
            Frame,
            [hw - 0.04, ly + dy - 0.02, 0.0],
            [hw, ly + dy + 0.02, zr],
        );
    }
    let mut z = 0.28;
    while z < zb + 0.05 {
        b.rod(
            Frame,
            [hw - 0.02, ly - 0.18, z],
            [hw - 0.02, ly + 0.18, z],
            0.015,
        );
        z += 0.28;
    }
    // the desk under the bed: a top between the posts, a drawer pedestal at the left
    let zt = (0.42 * h).min(0.76);
    let (d0, d1) = (-0.45 * hd, 0.55 * hd);
    b.cuboid(Top, [-hw + p, d0, zt - 0.03], [hw - p, d1, zt]);
    let (pw, pd) = (0.8 * (hw - p), (0.8 * (d1 - d0)).min(0.45));
    b.cuboid(Body, [-hw + p, d0, 0.0], [-hw + p + pw, d0 + pd, zt - 0.03]);
    for k in 0..3 {
        let z0 = 0.04 + k as f64 * (zt - 0.1) / 3.0;
        b.cuboid(
            Door,
            [-hw + p + 0.02, d0 + pd, z0],
            [
                -hw + p + pw - 0.02,
                d0 + pd + 0.01,
                z0 + (zt - 0.1) / 3.0 - 0.02,
            ],
        );
    }
}

/// A watering can: a low oval tank at the back (-x) with a round filling hole on top, a long
/// spout rising from the tank's foot at the front (+x) to a flared rose, and a loop handle
/// arching over the tank from its back to its top.
pub fn watering_can(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (rx, ry) = (0.55 * hw, 0.95 * hd);
    let cx = -hw + rx;
    let zt = 0.62 * h;
    b.frustum(Body, [cx, 0.0, 0.0], rx, ry, 0.92, zt);
    b.frustum(Body, [cx, 0.0, zt], 0.92 * rx, 0.92 * ry, 0.55, 0.08 * h);
    b.cylinder(
        Interior,
        [cx + 0.2 * rx, 0.0, zt + 0.08 * h],
        0.22 * rx.min(ry),
        0.005,
    );
    // The spout from low on the tank's front up to the rose.
    let r = 0.05 * h.clamp(0.2, 0.5);
    let a = [cx + 0.8 * rx, 0.0, 0.15 * h];
    let tip = [0.8 * hw, 0.0, 0.84 * h];
    b.rod(Body, a, tip, r);
    // The rose: a short flared cone on the spout's end, its perforated face out.
    let d = [tip[0] - a[0], tip[1] - a[1], tip[2] - a[2]];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let u = d.map(|v| v / l);
    let rr = (2.4 * r).min(0.9 * hd).min(hw - tip[0] + 0.5 * r);
    let len = 0.06 * h.max(0.2);
    b.revolved(
        Metal,
        0,
        tip,
        frame_along(d),
        1.0,
        frustum_profile(r, rr, len),
    );
    b.revolved(
        Interior,
        0,
        [tip[0] + u[0] * len, tip[1], tip[2] + u[2] * len],
        frame_along(d),
        1.0,
        frustum_profile(0.8 * rr, 0.8 * rr, 0.003),
    );
    // The handle arching over the tank.
    let hr = 0.045 * h.clamp(0.2, 0.5);
    b.polyline(
        Handle,
        &[
            [-hw + hr, 0.0, 0.35 * h],
            [-hw + hr, 0.0, 0.8 * h],
            [cx - 0.3 * rx, 0.0, h - hr],
            [cx + 0.4 * rx, 0.0, h - hr],
            [cx + 0.7 * rx, 0.0, zt + 0.04 * h],
        ],
        hr,
    );
}

/// A wall mirror: a moulded frame round the glass, standing proud of it, on a thin backing
/// board, and the hanging wire between two rings at the back near the top (it hangs on the
/// wall: nothing stands out under it).
pub fn wall_mirror(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let f = (0.12 * hw.min(0.5 * h)).clamp(0.025, 0.08);
    let back = -hd + 0.3 * b.d;
    b.cuboid(
        Body,
        [-hw + 0.5 * f, -hd + 0.2 * b.d, 0.5 * f],
        [hw - 0.5 * f, back, h - 0.5 * f],
    );
    b.cuboid(Canvas, [-hw + f, back, f], [hw - f, back + 0.004, h - f]);
    super::mirrors::sheen(b, [0.0, back + 0.004, 0.5 * h], hw - f, 0.5 * h - f);
    // the frame: four mouldings, a raised lip on each
    for (lo, hi) in [
        ([-hw, -hd, 0.0], [hw, hd - 0.3 * b.d, f]),
        ([-hw, -hd, h - f], [hw, hd - 0.3 * b.d, h]),
        ([-hw, -hd, f], [-hw + f, hd - 0.3 * b.d, h - f]),
        ([hw - f, -hd, f], [hw, hd - 0.3 * b.d, h - f]),
    ] {
        b.cuboid(Frame, lo, hi);
    }
    let lip = 0.35 * f;
    b.cuboid(Frame, [-hw + lip, hd - 0.3 * b.d, 0.0], [hw - lip, hd, lip]);
    b.cuboid(
        Frame,
        [-hw + lip, hd - 0.3 * b.d, h - lip],
        [hw - lip, hd, h],
    );
    b.cuboid(Frame, [-hw, hd - 0.3 * b.d, 0.0], [-hw + lip, hd, h]);
    b.cuboid(Frame, [hw - lip, hd - 0.3 * b.d, 0.0], [hw, hd, h]);
    // the hanging wire at the back between two rings
    let zw = 0.78 * h;
    let yw = -hd + 0.002;
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [sx * 0.5 * hw, yw, zw - 0.01],
            [sx * 0.5 * hw, yw, zw + 0.01],
            0.006,
        );
    }
    b.polyline(
        Metal,
        &[
            [-0.5 * hw, yw, zw],
            [0.0, yw, zw + 0.12 * h.min(0.8)],
            [0.5 * hw, yw, zw],
        ],
        0.002,
    );
}

/// A window seat: a built-in box base with panelled doors and a recessed plinth, a thick
/// cushion on it, two end panels rising past the cushion (the bay's cheeks), a sill board
/// along the back at the top, and pillows leaning against the back.
pub fn window_seat(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let e = (0.04 * b.w).clamp(0.03, 0.06);
    let zs = (0.42 * h / 0.8).min(0.6 * h);
    let zc = zs + (0.1 * h / 0.8).min(0.2 * h);
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw, -hw + e)
        } else {
            (hw - e, hw)
        };
        b.cuboid(Frame, [x0, -hd, 0.0], [x1, hd, h]);
    }
    b.cuboid(
        Frame,
        [-hw + e, -hd, h - 0.04 * h],
        [hw - e, -hd + 0.3 * b.d, h],
    );
    let (x0, x1) = (-hw + e, hw - e);
    b.cuboid(Interior, [x0, -hd, 0.0], [x1, hd - 0.06, 0.08]);
    b.cuboid(Body, [x0, -hd, 0.08], [x1, hd - 0.02, zs]);
    let n = ((x1 - x0) / 0.45).round().max(1.0) as usize;
    let pw = (x1 - x0) / n as f64;
    for k in 0..n {
        let a = x0 + k as f64 * pw;
        b.cuboid(
            Door,
            [a + 0.03, hd - 0.02, 0.12],
            [a + pw - 0.03, hd - 0.005, zs - 0.05],
        );
        b.cuboid(
            Handle,
            [a + 0.5 * pw - 0.03, hd - 0.005, zs - 0.1],
            [a + 0.5 * pw + 0.03, hd, zs - 0.08],
        );
    }
    b.cuboid(Top, [x0, -hd, zs - 0.02], [x1, hd, zs]);
    b.cuboid(
        Cushion,
        [x0 + 0.01, -hd + 0.01, zs],
        [x1 - 0.01, hd - 0.03, zc],
    );
    // pillows against the back
    let m = ((x1 - x0) / 0.5).floor().max(1.0) as usize;
    let ph = (h - zc - 0.04 * h).max(0.05);
    for k in 0..m {
        let x = x0 + (k as f64 + 0.5) * (x1 - x0) / m as f64;
        b.ellipsoid(
            Pillow,
            [x, -hd + 0.07, zc + 0.5 * ph],
            [0.18 * (x1 - x0) / m as f64 * 2.0, 0.06, 0.5 * ph],
        );
    }
}
