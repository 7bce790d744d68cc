//! Things of a hotel room and lobby that carry luggage or clothes, drawn as what they are: a
//! bellhop's luggage cart (a carpeted deck on castors, two brass uprights curving into a
//! hanging bar over it, suitcases on the deck), a folding luggage rack (crossed legs, webbing
//! straps, a suitcase on it) and a clothes valet (a shoulder hanger with a jacket on it, a
//! trouser bar, a tray on a post). The front faces +y.
use super::archetypes::Builder;
use super::fittings::castor;
use super::materials::Role::*;

/// A suitcase lying from `lo` to `hi`: a shell, a darker band round its seam, a handle on top.
pub(super) fn suitcase(b: &mut Builder, variant: u32, lo: [f64; 3], hi: [f64; 3]) {
    b.cuboid_v(Books, variant, lo, hi);
    let zm = 0.5 * (lo[2] + hi[2]);
    b.cuboid(
        Frame,
        [lo[0] - 0.003, lo[1] - 0.003, zm - 0.01],
        [hi[0] + 0.003, hi[1] + 0.003, zm + 0.01],
    );
    let (xc, yc) = (0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]));
    let l = 0.25 * (hi[0] - lo[0]).max(hi[1] - lo[1]).min(0.4);
    let along_x = hi[0] - lo[0] >= hi[1] - lo[1];
    let (a, c) = if along_x {
        ([xc - l / 2.0, yc, hi[2]], [xc + l / 2.0, yc, hi[2]])
    } else {
        ([xc, yc - l / 2.0, hi[2]], [xc, yc + l / 2.0, hi[2]])
    };
    let lift = |p: [f64; 3]| [p[0], p[1], p[2] + 0.025];
    b.polyline(Frame, &[a, lift(a), lift(c), c], 0.006);
}

/// A bellhop's luggage cart: a carpeted deck in a brass rim on four castors, two brass uprights
/// rising from the ends of the deck and curving in to a hanging bar along the top, suitcases
/// stacked on the deck.
pub fn luggage_cart(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.06 * h).clamp(0.04, 0.08);
    let deck = 2.0 * r + 0.05;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            castor(b, sx * (hw - 0.08), sy * (hd - 0.08), r, deck - 0.02);
        }
    }
    b.cuboid(Metal, [-hw, -hd, deck - 0.03], [hw, hd, deck]);
    b.cuboid(
        Upholstery,
        [-hw + 0.02, -hd + 0.02, deck],
        [hw - 0.02, hd - 0.02, deck + 0.01],
    );
    // Uprights: a pair of tubes at each end, curving inwards to the bar.
    let rt = 0.016;
    let top = h - rt;
    let xu = hw - 0.03;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - 0.04);
            b.polyline(
                Metal,
                &[
                    [sx * xu, y, deck],
                    [sx * xu, y, 0.72 * h],
                    [sx * xu, 0.5 * y, 0.86 * h],
                    [sx * (xu - 0.05), 0.1 * y, 0.95 * h],
                    [sx * (xu - 0.12), 0.0, top],
                ],
                rt,
            );
        }
        // A cross bar joining the pair low down.
        b.rod(
            Metal,
            [sx * xu, -hd + 0.04, deck + 0.25],
            [sx * xu, hd - 0.04, deck + 0.25],
            0.8 * rt,
        );
        b.ellipsoid(
            Metal,
            [sx * (xu - 0.12), 0.0, top],
            [2.0 * rt, 2.0 * rt, rt],
        );
    }
    b.rod(Metal, [-(xu - 0.12), 0.0, top], [xu - 0.12, 0.0, top], rt);
    // Luggage: a big case standing, a smaller one lying, a bag on top.
    let z = deck + 0.01;
    suitcase(
        b,
        0,
        [-hw + 0.06, -0.3 * b.d, z],
        [-0.05 * b.w, 0.3 * b.d, z + 0.22],
    );
    suitcase(
        b,
        4,
        [0.0, -0.35 * b.d, z],
        [hw - 0.08, 0.1 * b.d, z + 0.45],
    );
    suitcase(
        b,
        5,
        [-hw + 0.1, -0.22 * b.d, z + 0.22],
        [-0.12 * b.w, 0.2 * b.d, z + 0.36],
    );
}

/// A folding luggage rack: two pairs of crossed legs at its ends, top rails along the front and
/// back joined by webbing straps, and a suitcase lying on them.
pub fn luggage_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.022;
    let top = h - 0.2 * h;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.04);
        b.rod(Frame, [x, -hd + 0.02, 0.0], [x, hd - 0.04, top], s);
        b.rod(Frame, [x, hd - 0.02, 0.0], [x, -hd + 0.04, top], s);
    }
    for sy in [-1.0, 1.0] {
        let y = sy * (hd - 0.04);
        b.cuboid(
            Frame,
            [-hw, y - 0.02, top - 0.02],
            [hw, y + 0.02, top + 0.02],
        );
    }
    for k in 0..3 {
        let x = (k as f64 - 1.0) * 0.3 * b.w;
        b.cuboid(
            Upholstery,
            [x - 0.03, -hd + 0.04, top + 0.015],
            [x + 0.03, hd - 0.04, top + 0.022],
        );
    }
    suitcase(
        b,
        0,
        [-0.8 * hw, -0.7 * hd, top + 0.022],
        [0.8 * hw, 0.7 * hd, h - 0.03],
    );
}

/// A clothes valet: a cross foot, a post with a tray, a shoulder hanger on top carrying a
/// jacket, and a trouser bar with trousers folded over it.
pub fn clothes_valet(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = 0.03;
    b.cuboid(Frame, [-hw, -0.03, 0.0], [hw, 0.03, 0.04]);
    b.cuboid(Frame, [-0.03, -hd, 0.0], [0.03, hd, 0.04]);
    let yp = -0.25 * b.d;
    b.cuboid(
        Frame,
        [-s / 2.0, yp - s / 2.0, 0.04],
        [s / 2.0, yp + s / 2.0, 0.9 * h],
    );
    // The tray half way up, before the post.
    b.cuboid(
        Top,
        [-0.3 * b.w, yp + s / 2.0, 0.55 * h],
        [0.3 * b.w, yp + 0.3 * b.d, 0.57 * h],
    );
    // The shoulder hanger: a bow across the top.
    let zt = 0.9 * h;
    let bow: Vec<[f64; 3]> = (0..=8)
        .map(|k| {
            let f = k as f64 / 8.0 * 2.0 - 1.0;
            [f * (hw - 0.02), yp, zt + 0.06 * (1.0 - f * f)]
        })
        .collect();
    b.polyline(Frame, &bow, 0.018);
    b.cylinder(Frame, [0.0, yp, zt], 0.015, h - zt);
    // The jacket on the hanger: a body with sleeves, hanging to below the tray.
    let (jw, jl) = (hw - 0.03, 0.45 * h);
    let jt = 0.12_f64.min(b.d / 3.0);
    b.cuboid_v(
        Books,
        0,
        [-jw, yp - jt / 2.0, zt - jl],
        [jw, yp + jt / 2.0, zt + 0.04],
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Books,
            [sx * jw, yp, zt],
            [sx * (jw - 0.01), yp + 0.02, zt - 0.75 * jl],
            0.04,
        );
    }
    b.cuboid(
        Canvas,
        [-0.06, yp + jt / 2.0, zt - 0.25 * jl],
        [0.06, yp + jt / 2.0 + 0.004, zt + 0.03],
    );
    // The trouser bar in front of the post, trousers folded over it.
    let (zb, yb) = (0.38 * h, 0.25 * b.d);
    b.cuboid(Frame, [-0.015, yp, zb - 0.015], [0.015, yb, zb + 0.015]);
    b.rod(Frame, [-0.8 * hw, yb, zb], [0.8 * hw, yb, zb], 0.012);
    b.cuboid_v(
        Books,
        5,
        [-0.7 * hw, yb - 0.025, zb - 0.28 * h],
        [0.7 * hw, yb + 0.025, zb + 0.015],
    );
}
