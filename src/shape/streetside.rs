//! Things that stand at the side of a street or a beach, each facing +y and inside its size box:
//! a newsstand (a closed kiosk with a roof overhanging its front, magazines face-out in rows on
//! its front wall and a counter window under them), a tiki bar (a thatched roof on four bamboo
//! posts over a bamboo counter, stools along its front) and a street lamp (a tall tapered iron
//! post on a base, a lantern head on top, a short crossbar under it).
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// A newsstand: a kiosk box, a roof jutting out at the front, rows of magazines face-out on the
/// front wall above a serving window and a counter ledge.
pub fn newsstand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let front = 0.55 * hd; // the kiosk's front wall; the roof and ledge reach on to hd
    let eave = 0.86 * h;
    let back = -hd + 0.03; // the back wall, its door and poster standing proud of it
    b.cuboid(Body, [-hw + 0.05, back, 0.0], [hw - 0.05, front, eave]);
    newsstand_back(b, back, eave);
    // The roof: a slab overhanging the front, sloping down to it, and a sign band under it.
    let run = 2.0 * hd;
    let rise = h - eave - 0.06;
    b.slab(
        Top,
        [0.0, 0.0, eave + 0.5 * rise + 0.03],
        [hw, 0.5 * run.hypot(rise), 0.025],
        rot_x(-rise.atan2(run)),
    );
    b.cuboid(Top, [-hw, -hd, eave], [hw, front + 0.02, eave + 0.03]);
    b.cuboid(
        Canvas,
        [-hw + 0.08, front, 0.76 * h],
        [hw - 0.08, front + 0.02, 0.84 * h],
    );
    // The serving window and the counter ledge under it.
    let (w0, w1) = (0.36 * h, 0.52 * h);
    b.cuboid(
        Interior,
        [-0.3 * hw, front, w0],
        [0.3 * hw, front + 0.01, w1],
    );
    b.cuboid(Frame, [-hw + 0.05, front, w0 - 0.03], [hw - 0.05, hd, w0]);
    // Magazines face-out in rows: above the window across the front, and in columns either
    // side of it down to the ledge.
    let (mw, mh) = (0.2_f64.min(0.12 * hw), 0.26_f64.min(0.1 * h));
    let mut k = 0u32;
    let mut mag = |b: &mut Builder, x: f64, z: f64| {
        b.cuboid_v(
            Books,
            k,
            [x - 0.5 * mw, front + 0.01, z],
            [x + 0.5 * mw, front + 0.03, z + mh],
        );
        k += 1;
    };
    let cols = ((2.0 * hw - 0.2) / (1.25 * mw)) as usize;
    for row in 0..2 {
        let z = w1 + 0.03 + row as f64 * (mh + 0.03);
        if z + mh > 0.75 * h {
            break;
        }
        for c in 0..cols {
            let x = -hw + 0.1 + (c as f64 + 0.5) * (2.0 * hw - 0.2) / cols as f64;
            mag(b, x, z);
        }
    }
    for sx in [-1.0, 1.0] {
        let mut z = w0 + 0.02;
        while z + mh < w1 + 0.01 {
            for j in 0..2 {
                let x = sx * (0.42 * hw + j as f64 * 1.25 * mw + 0.5 * mw);
                if x.abs() + 0.5 * mw < hw - 0.05 {
                    mag(b, x, z);
                }
            }
            z += mh + 0.03;
        }
    }
    // Papers stacked on the ledge.
    for sx in [-1.0, 1.0] {
        b.cuboid_v(
            Books,
            7,
            [sx * 0.6 * hw - 0.12, front + 0.03, w0],
            [sx * 0.6 * hw + 0.12, hd - 0.03, w0 + 0.06],
        );
    }
}

/// A newsstand's back: a service door with a handle on one side and, on the other, a framed
/// advertising poster with a headline band, so the kiosk is no blank box from behind.
fn newsstand_back(b: &mut Builder, back: f64, eave: f64) {
    let hw = b.w / 2.0;
    let y0 = -b.d / 2.0;
    let dw = (0.8 * hw).min(0.8);
    let (dx0, dx1) = (-hw + 0.15, -hw + 0.15 + dw);
    b.cuboid(Top, [dx0, y0 + 0.01, 0.02], [dx1, back, 0.85 * eave]);
    b.ellipsoid(
        Frame,
        [dx1 - 0.08, y0 + 0.008, 0.45 * eave],
        [0.03, 0.01, 0.03],
    );
    let (px0, px1) = ((dx1 + 0.1).min(hw - 0.3), hw - 0.15);
    if px1 - px0 < 0.15 {
        return;
    }
    let (z0, z1) = (0.3 * eave, 0.85 * eave);
    b.cuboid(Frame, [px0, y0 + 0.012, z0], [px1, back, z1]);
    let m = 0.04;
    b.cuboid(
        Cushion,
        [px0 + m, y0 + 0.004, z0 + m],
        [px1 - m, y0 + 0.012, z1 - m],
    );
    b.cuboid(
        Canvas,
        [px0 + 2.0 * m, y0, z1 - 0.3 * (z1 - z0)],
        [px1 - 2.0 * m, y0 + 0.004, z1 - 2.0 * m],
    );
}

/// A tiki bar: a shaggy thatched roof on four bamboo posts, a bamboo-fronted counter under it
/// and stools along the front.
pub fn tiki_bar(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let bar = (0.42 * h).min(1.1);
    let (cy0, cy1) = (-0.25 * hd, 0.15 * hd); // the counter's depth
    let eave = 0.72 * h;
    let p = 0.05_f64.min(0.05 * hw);
    // The posts stand inside the thatch's oval so none pokes out at a corner.
    for sx in [-1.0, 1.0] {
        for y in [-0.6 * hd, cy1] {
            b.rod(
                Frame,
                [sx * 0.65 * hw, y, 0.0],
                [sx * 0.65 * hw, y, eave],
                p,
            );
        }
    }
    // The counter: upright bamboo canes across its front and sides, a wooden top.
    let cane = 0.035;
    let n = ((2.0 * hw - 0.5) / (2.2 * cane)) as usize;
    for k in 0..n {
        let x = -hw + 0.25 + (k as f64 + 0.5) * (2.0 * hw - 0.5) / n as f64;
        b.rod(Frame, [x, cy1, 0.0], [x, cy1, bar - 0.04], cane);
    }
    b.cuboid(
        Body,
        [-hw + 0.25, cy0, 0.0],
        [hw - 0.25, cy1 - cane, bar - 0.04],
    );
    b.cuboid(
        Top,
        [-hw + 0.2, cy0 - 0.05, bar - 0.04],
        [hw - 0.2, cy1 + 0.12, bar],
    );
    // A back shelf of bottles.
    let bottles = ((2.0 * hw) / 0.25) as usize;
    for k in 0..bottles {
        let x = -hw + 0.3 + k as f64 * (2.0 * hw - 0.6) / bottles.max(2) as f64;
        b.cylinder(Glass, [x, -hd + 0.2, bar + 0.1], 0.035, 0.25);
    }
    b.cuboid(
        Top,
        [-hw + 0.2, -hd + 0.1, bar + 0.07],
        [hw - 0.2, -hd + 0.3, bar + 0.1],
    );
    // The thatch: layered shaggy skirts, each wider and lower than the one above, to a peak.
    let layers = 4;
    for l in 0..layers {
        let t = l as f64 / layers as f64;
        let z = eave + (h - eave) * t;
        let s = 1.0 - 0.75 * t;
        b.frustum(
            Shade,
            [0.0, 0.0, z - 0.06 * h],
            s * hw,
            s * hd,
            0.72,
            (h - eave) / layers as f64 + 0.06 * h,
        );
    }
    // A ragged fringe of straw hanging from the eave.
    let tufts = ((2.0 * (hw + hd)) / 0.09) as usize;
    for k in 0..tufts {
        let a = k as f64 / tufts as f64 * std::f64::consts::TAU;
        let (x, y) = (0.97 * hw * a.cos(), 0.97 * hd * a.sin());
        let long = 0.05 * h * (1.0 + 0.5 * ((k * 7 % 5) as f64 / 4.0));
        b.ellipsoid(Shade, [x, y, eave - 0.6 * long], [0.05, 0.05, long]);
    }
    // Stools in front of the counter.
    let stools = ((2.0 * hw - 0.5) / 0.7).floor().max(1.0) as usize;
    let seat = (bar - 0.32).max(0.3);
    for k in 0..stools {
        let x = -hw + 0.25 + (k as f64 + 0.5) * (2.0 * hw - 0.5) / stools as f64;
        let y = (cy1 + 0.45).min(hd - 0.2);
        b.rod(Metal, [x, y, 0.0], [x, y, seat], 0.03);
        b.cylinder(Metal, [x, y, 0.0], 0.15, 0.02);
        b.cylinder(Seat, [x, y, seat], 0.18, 0.06);
    }
}

/// A street lamp: a stepped base, a tall post tapering up with collars, a crossbar under the
/// head and a lantern on top (a glass body under a pointed cap).
pub fn street_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.7 * m, 0.7 * m, 0.7, 0.08 * h);
    b.cylinder(Metal, [0.0, 0.0, 0.08 * h], 0.42 * m, 0.03 * h);
    let top = 0.8 * h;
    let r = (0.18 * m).max(0.025);
    b.frustum(Metal, [0.0, 0.0, 0.11 * h], r, r, 0.6, top - 0.11 * h);
    for z in [0.11 * h, 0.3 * h, top - 0.04 * h] {
        b.cylinder(Metal, [0.0, 0.0, z], 1.5 * r, 0.015 * h);
    }
    // The crossbar (a ladder rest) with small scrolls at its ends.
    let bar = top - 0.08 * h;
    b.rod(Metal, [-0.8 * hw, 0.0, bar], [0.8 * hw, 0.0, bar], 0.3 * r);
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Metal,
            [sx * 0.8 * hw, 0.0, bar],
            [0.6 * r, 0.6 * r, 0.6 * r],
        );
    }
    // The lantern head: a flared glass body, a pointed cap, a finial.
    let head = 0.55 * m;
    b.cylinder(Metal, [0.0, 0.0, top], 0.5 * head, 0.01 * h);
    b.frustum(
        Light,
        [0.0, 0.0, top + 0.01 * h],
        0.55 * head,
        0.55 * head,
        1.6,
        0.09 * h,
    );
    for k in 0..4 {
        let a = k as f64 * std::f64::consts::FRAC_PI_2 + std::f64::consts::FRAC_PI_4;
        let (c, s) = (a.cos(), a.sin());
        b.rod(
            Metal,
            [0.55 * head * c, 0.55 * head * s, top + 0.01 * h],
            [0.88 * head * c, 0.88 * head * s, top + 0.1 * h],
            0.1 * r,
        );
    }
    b.frustum(Metal, [0.0, 0.0, top + 0.1 * h], head, head, 0.15, 0.07 * h);
    b.ellipsoid(
        Metal,
        [0.0, 0.0, h - 0.02 * h],
        [0.2 * head, 0.2 * head, 0.02 * h],
    );
}
