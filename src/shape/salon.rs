//! Layouts of the chairs of a trade: a barber chair (a padded seat on a round chrome pedestal,
//! arms, a back with a headrest on a stem and a chrome footrest in front), a dentist's chair (a
//! reclined couch on a pedestal plate with an overhead lamp on an arm, an instrument tray and a
//! rinsing bowl; its couch is `pub(super)` for the recliners of `recliners.rs`), a pedicure
//! chair (a throne-like padded seat raised on a plinth with a foot basin in front of it, and at
//! the back of its plinth a grille and the basin's plumbing) and a hood dryer chair (an armchair
//! under a domed hood on a stem). The front faces +y; backs at -y.
use super::archetypes::Builder;
use super::fittings::{band, disc, pad, pedestal};
use super::materials::Role::*;
use super::parts::rot_x;

/// A barber chair: the pedestal, a seat box, the seat, padded arms on chrome supports, a
/// slightly reclined back, a headrest above it on a stem, and a chrome footrest reaching out
/// in front, its ribbed plate low over the floor.
pub fn barber_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = (0.4 * h).clamp(0.35, 0.5);
    let (ys0, ys1) = (-hd + 0.2, (0.3 * hd).max(-hd + 0.6));
    pedestal(
        b,
        Metal,
        0.5 * (ys0 + ys1),
        (0.8 * hw).min(0.3),
        0.07,
        zs - 0.1,
    );
    b.cuboid(Body, [-hw + 0.1, ys0, zs - 0.1], [hw - 0.1, ys1, zs - 0.02]);
    b.cuboid(
        Upholstery,
        [-hw + 0.11, ys0, zs - 0.02],
        [hw - 0.11, ys1 + 0.02, zs + 0.1],
    );
    // Arms: a chrome support at the front, a padded rest on top.
    let za = zs + 0.24;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.055);
        b.cuboid(
            Metal,
            [x - 0.02, ys1 - 0.08, zs - 0.08],
            [x + 0.02, ys1 - 0.02, za],
        );
        b.cuboid(
            Metal,
            [x - 0.02, ys0, zs - 0.08],
            [x + 0.02, ys0 + 0.06, za],
        );
        b.cuboid(
            Frame,
            [x - 0.045, ys0 - 0.02, za],
            [x + 0.045, ys1 + 0.01, za + 0.02],
        );
        b.cuboid(
            Upholstery,
            [x - 0.04, ys0, za + 0.02],
            [x + 0.04, ys1, za + 0.07],
        );
    }
    // The back, leaning 12°, and the headrest on a stem above it.
    let zt = h - 0.2;
    let lean = 0.12 * (zt - zs);
    pad(
        b,
        Upholstery,
        0.0,
        [ys0 + 0.01, zs + 0.05],
        [ys0 - lean + 0.04, zt],
        hw - 0.11,
        0.12,
    );
    let yh = ys0 - lean + 0.02;
    b.rod(
        Metal,
        [0.0, yh - 0.03, zt - 0.05],
        [0.0, yh - 0.04, h - 0.12],
        0.015,
    );
    b.cuboid(
        Upholstery,
        [-0.14, yh - 0.09, h - 0.14],
        [0.14, yh - 0.01, h - 0.005],
    );
    // The footrest: a chrome bracket from under the seat to a ribbed plate.
    let yf = hd - 0.13;
    pad(
        b,
        Metal,
        0.0,
        [ys1 - 0.02, zs - 0.08],
        [yf, 0.16],
        0.05,
        0.025,
    );
    b.cuboid(Metal, [-0.22, yf - 0.02, 0.12], [0.22, hd - 0.01, 0.15]);
    for k in 0..5 {
        let y = yf + k as f64 * (hd - 0.03 - yf) / 4.0;
        b.rod(Handle, [-0.21, y, 0.155], [0.21, y, 0.155], 0.006);
    }
    // The pump lever at the right of the base.
    b.rod(
        Handle,
        [hw - 0.12, ys0 + 0.1, 0.1],
        [hw - 0.02, ys0 + 0.02, 0.3],
        0.012,
    );
}

/// Where a treatment couch put its parts: the seat height, the seat's back edge, the top of the
/// back rest (`[y, z]`) and the couch's half width.
pub(super) struct Couch {
    pub zs: f64,
    pub ys0: f64,
    pub top: [f64; 2],
    pub cw: f64,
}

/// A treatment couch: a base plate and lift column, a seat, a back reclined `recline` degrees
/// above level from the seat's back edge with a headrest beyond it, a leg rest falling to the
/// front, and small armrests on posts at both sides of the seat.
pub(super) fn couch(b: &mut Builder, recline: f64) -> Couch {
    let (hd, h) = (b.d / 2.0, b.h);
    let zs = (0.4 * h).clamp(0.4, 0.5);
    b.cuboid(Body, [-0.25, -0.35, 0.0], [0.25, 0.4, 0.04]);
    b.cuboid(Body, [-0.12, -0.12, 0.04], [0.12, 0.12, zs - 0.1]);
    b.cuboid(Body, [-0.24, -0.3, zs - 0.1], [0.24, 0.3, zs - 0.04]);
    let cw = (0.35 * b.w).min(0.28);
    let t = 0.09;
    // Seat, back and headrest, and the leg rest falling forward.
    let (ys0, ys1) = (-0.15, 0.25);
    pad(b, Upholstery, 0.0, [ys0, zs], [ys1, zs + 0.02], cw, t);
    let a = recline.to_radians();
    let back = ((ys0 + hd - 0.25).max(0.2) / a.cos()).min((h - zs - 0.1) / a.sin());
    let top = [ys0 - back * a.cos(), zs + back * a.sin()];
    pad(b, Upholstery, 0.0, [ys0, zs], top, cw, t);
    let head = [top[0] - 0.2, top[1] + 0.06];
    pad(
        b,
        Cushion,
        0.0,
        [top[0] + 0.02, top[1] + 0.01],
        head,
        0.6 * cw,
        0.08,
    );
    pad(
        b,
        Upholstery,
        0.0,
        [ys1, zs + 0.02],
        [hd - 0.04, zs - 0.2],
        cw,
        t,
    );
    for sx in [-1.0, 1.0] {
        let x = sx * (cw + 0.05);
        b.cuboid(
            Body,
            [x - 0.015, ys0 + 0.05, zs - 0.05],
            [x + 0.015, ys0 + 0.1, zs + 0.15],
        );
        b.cuboid(
            Upholstery,
            [x - 0.04, ys0 - 0.05, zs + 0.15],
            [x + 0.04, ys0 + 0.3, zs + 0.2],
        );
    }
    Couch { zs, ys0, top, cw }
}

/// A dentist's chair: a base plate and lift column, a couch reclined from the leg rest at the
/// front to the headrest at the back, small armrests, a lamp on an arm from a post reaching over
/// the couch, an instrument tray on a swing arm and a rinsing bowl on a column.
pub fn dentist_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let Couch { zs, top, .. } = couch(b, 25.0);
    // The lamp: a post on its own foot behind the back right, an arm reaching over the couch
    // and a head facing down at the patient's chest.
    let (xp, yp) = (hw - 0.04, -hd + 0.08);
    disc(
        b,
        Body,
        [xp - 0.04, yp + 0.04, 0.015],
        [0.0, 0.0, 1.0],
        0.07,
        0.03,
    );
    b.rod(Metal, [xp, yp, 0.03], [xp, yp, h - 0.06], 0.025);
    let yl = top[0] + 0.25;
    b.polyline(
        Metal,
        &[[xp, yp, h - 0.06], [0.1, yl, h - 0.06], [0.0, yl, h - 0.1]],
        0.018,
    );
    b.cuboid(
        Body,
        [-0.16, yl - 0.07, h - 0.2],
        [0.16, yl + 0.07, h - 0.1],
    );
    b.cuboid(
        Light,
        [-0.13, yl - 0.05, h - 0.205],
        [0.13, yl + 0.05, h - 0.2],
    );
    // The instrument tray on its column at the left, over the leg rest's side.
    let xt = -hw + 0.01;
    let zt = zs + 0.3;
    b.cylinder(Body, [xt + 0.05, 0.55, 0.0], 0.03, zt);
    b.cuboid(Top, [xt, 0.4, zt], [xt + 0.2, 0.75, zt + 0.03]);
    for k in 0..4 {
        let y = 0.45 + 0.07 * k as f64;
        b.rod(
            Handle,
            [xt + 0.03, y, zt + 0.04],
            [xt + 0.17, y + 0.02, zt + 0.04],
            0.008,
        );
    }
    // The rinsing bowl on a column at the back right, beside the headrest.
    let (xb, yb) = (hw - 0.075, -0.45);
    b.cylinder(Body, [xb, yb, 0.0], 0.04, zs + 0.2);
    b.frustum(Canvas, [xb, yb, zs + 0.2], 0.05, 0.05, 1.45, 0.08);
    disc(b, Water, [xb, yb, zs + 0.281], [0.0, 0.0, 1.0], 0.06, 0.004);
}

/// The back of a pedicure chair's plinth, `zp` high: a steel vent grille, the hot and cold
/// supply pipes rising from the floor into it and the basin's drain hose leaving it, all in the
/// 6 cm it is set in from the back of the size box.
fn plumbing(b: &mut Builder, zp: f64) {
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    let yb = -hd + 0.06;
    for k in 0..5 {
        let z = 0.25 * zp + 0.1 * zp * k as f64;
        b.cuboid(
            Metal,
            [-0.4 * hw, yb - 0.006, z],
            [0.4 * hw, yb, z + 0.04 * zp],
        );
    }
    for x in [-0.7 * hw, -0.55 * hw] {
        b.polyline(
            Metal,
            &[
                [x, -hd + 0.025, 0.0],
                [x, -hd + 0.025, 0.7 * zp],
                [x, yb, 0.7 * zp],
            ],
            0.012,
        );
    }
    let x = 0.6 * hw;
    b.polyline(
        Frame,
        &[
            [x, yb, 0.5 * zp],
            [x, -hd + 0.025, 0.45 * zp],
            [x + 0.05, -hd + 0.025, 0.03],
        ],
        0.022,
    );
}

/// A pedicure chair: a plinth that raises a throne-like seat (thick arms, a tall padded back)
/// above the floor, and in front of it a low step carrying a foot basin with a tap.
pub fn pedicure_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ys = (-hd + 0.8).min(0.15 * hd);
    let zp = (0.3 * h).min(0.35);
    let zs = zp + 0.18;
    // The plinth (set in at the back for the plumbing) and the seat on it, between thick arms.
    b.cuboid(Body, [-hw, -hd + 0.06, 0.0], [hw, ys, zp]);
    plumbing(b, zp);
    let arm = (0.17 * b.w).min(0.16);
    b.cuboid(
        Upholstery,
        [-hw + arm, -hd + 0.2, zp],
        [hw - arm, ys - 0.02, zs],
    );
    for sx in [-1.0, 1.0] {
        let (x0, x1) = (sx * hw, sx * (hw - arm));
        b.cuboid(
            Body,
            [x0.min(x1), -hd + 0.05, zp],
            [x0.max(x1), ys, zs + 0.2],
        );
        b.cuboid(
            Upholstery,
            [x0.min(x1) + 0.01, -hd + 0.1, zs + 0.2],
            [x0.max(x1) - 0.01, ys - 0.01, zs + 0.26],
        );
    }
    // The back: a shell and a tall padded back rest leaning 15°, with a head roll.
    let top = h - 0.03;
    pad(
        b,
        Body,
        0.0,
        [-hd + 0.2, zp],
        [-hd + 0.06, top],
        hw - 0.02,
        0.1,
    );
    pad(
        b,
        Upholstery,
        0.0,
        [-hd + 0.3, zs],
        [-hd + 0.17, top - 0.04],
        hw - arm - 0.01,
        0.14,
    );
    b.rod(
        Cushion,
        [-0.6 * (hw - arm), -hd + 0.22, top - 0.12],
        [0.6 * (hw - arm), -hd + 0.22, top - 0.12],
        0.07,
    );
    // The step and the basin on it, with a tap at its back.
    let zstep = 0.12;
    b.cuboid(Top, [-hw + 0.05, ys, 0.0], [hw - 0.05, hd, zstep]);
    let yb = 0.5 * (ys + hd);
    let rb = (0.45 * (hd - ys)).min(0.28);
    let zb = zstep + (0.25 * h).min(0.26);
    b.frustum(
        Canvas,
        [0.0, yb, zstep],
        0.8 * rb,
        0.75 * rb,
        1.25,
        zb - zstep,
    );
    band(b, Canvas, [0.0, yb, zb], [0.0, 0.0, 1.0], rb, 0.03, 0.03);
    disc(
        b,
        Water,
        [0.0, yb, zb + 0.002],
        [0.0, 0.0, 1.0],
        0.88 * rb,
        0.004,
    );
    let yt = yb - rb - 0.01;
    b.polyline(
        Metal,
        &[
            [0.0, yt, zstep],
            [0.0, yt, zb + 0.15],
            [0.0, yt + 0.12, zb + 0.12],
        ],
        0.015,
    );
}

/// A hood dryer chair: an armchair as high as a seat, and behind it a stem on a round foot that
/// rises past the back and leans a domed hood forward over the sitter's head, its dark mouth
/// facing down and forward.
pub fn hood_dryer_chair(b: &mut Builder) {
    let (hd, h) = (b.d / 2.0, b.h);
    let full = b.h;
    b.h = (0.62 * h).clamp(0.6, 1.0);
    super::furniture::armchair(b);
    b.h = full;
    let ys = -hd + 0.05;
    disc(
        b,
        Metal,
        [0.0, ys + 0.12, 0.01],
        [0.0, 0.0, 1.0],
        0.14,
        0.02,
    );
    let r = (0.22 * b.w).clamp(0.12, 0.25);
    let zh = h - r;
    let yh = (-hd + 0.3 + 0.9 * r).min(0.05);
    b.polyline(
        Metal,
        &[
            [0.0, ys, 0.02],
            [0.0, ys, zh + 0.1],
            [0.0, yh - 0.5 * r, zh + 0.1],
        ],
        0.02,
    );
    let tilt = rot_x(-30f64.to_radians());
    b.ellipsoid_rot(Body, 0, [0.0, yh, zh], [r, r, 0.8 * r], tilt);
    disc(
        b,
        Interior,
        [0.0, yh + 0.25 * r, zh - 0.45 * r],
        [0.0, 0.5, -0.87],
        0.85 * r,
        0.01,
    );
}
