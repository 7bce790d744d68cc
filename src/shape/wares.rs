//! Goods that are no shop stock but what a thing is said to hold or a place shows: flowers (a
//! vase's bouquet), plates (a kitchen dresser's rack), jewellery (a jeweller's case) and
//! artefacts (a museum's case), one item a call in a row that `goods::fill` lays; and goods
//! spread flat on a table's top (a bookshop's table of new releases). Colours come from the
//! goods palette by variant (each kind's first entries are its fixed colours: a stem's green, a
//! plate's white glaze, a jewellery pad's velvet, a bust's marble).
use super::builder::{frame_along, Builder};
use super::goods::{Draws, Goods, Slot};
use super::materials::Role::Books;
use super::parts::{frustum_profile, mul, rot_x, rot_z, IDENTITY};
use std::f64::consts::FRAC_PI_2;

/// A rod from `a` to `b` of radius `r` in goods colour `v`.
fn stick(b: &mut Builder, v: u32, a: [f64; 3], to: [f64; 3], r: f64) {
    let d = [to[0] - a[0], to[1] - a[1], to[2] - a[2]];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-9);
    b.revolved(Books, v, a, frame_along(d), 1.0, frustum_profile(r, r, l));
}

/// A disc of radius `r` and thickness `t` facing +y, centred at `c`, in goods colour `v`.
fn disc(b: &mut Builder, v: u32, c: [f64; 3], r: f64, t: f64) {
    b.revolved(
        Books,
        v,
        c,
        rot_x(-FRAC_PI_2),
        1.0,
        frustum_profile(r, r, t),
    );
}

/// A bunch of flowers standing in the slot: green stems fanning up to coloured blooms.
pub(super) fn flowers(b: &mut Builder, r: &mut Draws, s: Slot) -> f64 {
    let w = 0.12f64.min(s.x1 - s.x);
    let (xc, yc) = (s.x + 0.5 * w, 0.5 * (s.y0 + s.y1));
    let top = s.z + 0.85 * s.room;
    let bloom = (0.18 * s.room).clamp(0.015, 0.04);
    for k in 0..3 {
        let dx = (k as f64 - 1.0) * 0.3 * w;
        let zt = top - bloom - 0.25 * s.room * r.next();
        stick(b, 0, [xc, yc, s.z], [xc + dx, yc, zt], 0.004);
        let v = Goods::Flowers.accent(r.next());
        b.ellipsoid_rot(
            Books,
            v,
            [xc + dx, yc, zt],
            [bloom, bloom, 0.8 * bloom],
            IDENTITY,
        );
    }
    w + 0.01
}

/// A plate standing on its rim against the back: a patterned rim round a white well.
pub(super) fn plate(b: &mut Builder, r: &mut Draws, s: Slot) -> f64 {
    let pr = (0.45 * s.room).min(0.13).min(0.5 * (s.x1 - s.x));
    if pr < 0.03 {
        return s.x1 - s.x;
    }
    let c = [s.x + pr, s.y0 + 0.02, s.z + pr];
    disc(b, Goods::Plates.accent(r.next()), c, pr, 0.01);
    disc(b, 0, [c[0], c[1] + 0.01, c[2]], 0.65 * pr, 0.002);
    2.0 * pr + 0.015
}

/// A jeweller's pad: dark velvet with a ring, a chain and a stone on it.
pub(super) fn jewels(b: &mut Builder, r: &mut Draws, s: Slot) -> f64 {
    let w = 0.16f64.min(s.x1 - s.x);
    let d = 0.12f64.min(s.y1 - s.y0);
    if w < 0.06 || d < 0.04 {
        return s.x1 - s.x;
    }
    let (y0, t) = (0.5 * (s.y0 + s.y1) - 0.5 * d, 0.015f64.min(0.3 * s.room));
    b.cuboid_v(Books, 0, [s.x, y0, s.z], [s.x + w, y0 + d, s.z + t]);
    let z = s.z + t;
    let yc = y0 + 0.5 * d;
    // a ring of gold or silver
    let metal = 1 + (r.next() * 2.0) as u32;
    b.ellipsoid_rot(
        Books,
        metal,
        [s.x + 0.25 * w, yc, z + 0.008],
        [0.012, 0.012, 0.008],
        IDENTITY,
    );
    // a chain laid in a loop
    let pts: Vec<[f64; 3]> = (0..=8)
        .map(|k| {
            let a = k as f64 / 8.0 * std::f64::consts::TAU;
            [
                s.x + 0.62 * w + 0.22 * w * a.cos(),
                yc + 0.3 * d * a.sin(),
                z + 0.003,
            ]
        })
        .collect();
    for p in pts.windows(2) {
        stick(b, metal, p[0], p[1], 0.0025);
    }
    // a stone
    let gem = Goods::Jewels.accent(r.next());
    b.ellipsoid_rot(
        Books,
        gem,
        [s.x + 0.62 * w, yc - 0.3 * d, z + 0.008],
        [0.01; 3],
        IDENTITY,
    );
    w + 0.03
}

/// An exhibit: an urn, a bust on a little plinth or a tablet on a stand, by turns.
pub(super) fn artefact(b: &mut Builder, r: &mut Draws, s: Slot) -> f64 {
    let h = (0.8 * s.room).min(0.35);
    let rad = (0.3 * h).min(0.45 * (s.y1 - s.y0)).min(0.5 * (s.x1 - s.x));
    if rad < 0.02 {
        return s.x1 - s.x;
    }
    let c = [s.x + rad, 0.5 * (s.y0 + s.y1), s.z];
    let v = Goods::Artefacts.accent(r.next());
    match (r.next() * 3.0) as u32 {
        0 => {
            // an urn: a foot, a swelling body, a neck and a lip
            let profile = vec![
                [0.0, 0.0],
                [0.5 * rad, 0.0],
                [0.45 * rad, 0.1 * h],
                [rad, 0.45 * h],
                [0.55 * rad, 0.85 * h],
                [0.45 * rad, 0.9 * h],
                [0.6 * rad, h],
                [0.0, h],
            ];
            b.revolved(Books, v, c, IDENTITY, 1.0, profile);
        }
        1 => {
            // a bust: a plinth, shoulders and a head
            let p = 0.25 * h;
            b.cuboid_v(
                Books,
                0,
                [c[0] - 0.7 * rad, c[1] - 0.7 * rad, c[2]],
                [c[0] + 0.7 * rad, c[1] + 0.7 * rad, c[2] + p],
            );
            b.ellipsoid_rot(
                Books,
                v,
                [c[0], c[1], c[2] + p + 0.15 * h],
                [rad, 0.6 * rad, 0.18 * h],
                IDENTITY,
            );
            b.ellipsoid_rot(
                Books,
                v,
                [c[0], c[1], c[2] + p + 0.5 * h],
                [0.55 * rad, 0.6 * rad, 0.22 * h],
                IDENTITY,
            );
        }
        _ => {
            // a tablet or plate on a small stand, leaning back
            b.cuboid_v(
                Books,
                0,
                [c[0] - 0.5 * rad, c[1] - 0.5 * rad, c[2]],
                [c[0] + 0.5 * rad, c[1] + 0.5 * rad, c[2] + 0.02],
            );
            b.slab_v(
                Books,
                v,
                [c[0], c[1], c[2] + 0.02 + 0.45 * h],
                [0.9 * rad, 0.008, 0.45 * h],
                rot_x(-0.15),
            );
        }
    }
    2.0 * rad + 0.04
}

/// Goods laid flat on a table's top at height `z`, within `hw` × `hd` of its centre (a disc of
/// radius `hw` when `round`), at most `room` high: books and magazines in low stacks, other
/// goods in rows.
pub(super) fn on_top(
    b: &mut Builder,
    goods: Goods,
    z: f64,
    hw: f64,
    hd: f64,
    round: bool,
    room: f64,
) {
    let mut r = Draws::new(((hw * 1000.0) as u64) << 8 | goods as u64);
    if matches!(goods, Goods::Books | Goods::Magazines) {
        books_on_top(b, goods, z, hw, hd, round, room, &mut r);
        return;
    }
    let rows = ((2.0 * hd) / 0.3).floor().max(1.0) as usize;
    let depth = 2.0 * hd / rows as f64;
    for k in 0..rows {
        let y0 = -hd + k as f64 * depth;
        let yc = y0 + 0.5 * depth;
        let half = if round {
            (hw * hw - yc * yc).max(0.0).sqrt() * 0.85
        } else {
            0.92 * hw
        };
        let bay = super::goods::Bay {
            x0: -half,
            x1: half,
            y0: y0 + 0.03,
            depth: depth - 0.06,
            z,
            room,
        };
        super::goods::fill(b, goods, bay, &mut r);
    }
}

/// Footprint of a book laid flat on a table (metres): a hardback's, across and deep.
const BOOK: [f64; 2] = [0.15, 0.21];
/// Grid a table of books is laid out on (metres, across and deep): a book and a finger's gap.
const BOOK_PITCH: [f64; 2] = [0.18, 0.24];

/// A table top covered in books, as a bookshop lays out its new releases: the whole top to its
/// edge in a grid of places, most a low stack of books laid flat (each a little turned, one to
/// three high), every few a pair standing up on end leaning back, covers facing out from the
/// table's middle. Within `hw` × `hd` of the centre (a disc of radius `hw` when `round`), at
/// most `room` high above `z`.
#[allow(clippy::too_many_arguments, reason = "the on_top bay and its draws")]
fn books_on_top(
    b: &mut Builder,
    goods: Goods,
    z: f64,
    hw: f64,
    hd: f64,
    round: bool,
    room: f64,
    r: &mut Draws,
) {
    let n = [0, 1].map(|a| ((2.0 * [hw, hd][a]) / BOOK_PITCH[a]).floor().max(1.0) as i64);
    let t = (room / 3.0).min(0.03);
    for i in 0..n[0] {
        for j in 0..n[1] {
            let x = -hw + (i as f64 + 0.5) * 2.0 * hw / n[0] as f64;
            let y = -hd + (j as f64 + 0.5) * 2.0 * hd / n[1] as f64;
            let reach = (x.abs() + 0.5 * BOOK[0]).hypot(y.abs() + 0.5 * BOOK[1]);
            if round && reach > 0.97 * hw {
                continue;
            }
            if (i + 2 * j) % 3 == 1 && goods == Goods::Books {
                // two standing on end, covers out from the middle, leaning back a little
                let out = if y < 0.0 { -1.0 } else { 1.0 };
                let bh = 0.95 * room;
                let bw = (0.7 * bh).min(0.5 * BOOK[0]);
                for k in [-0.5, 0.5] {
                    let v = goods.accent(r.next());
                    // (rot_x(a) leans the top towards −y for a > 0: back, to the middle)
                    let tilt = rot_x(out * 0.12);
                    let c = mul(&tilt, [0.0, 0.0, 0.5 * bh]);
                    b.slab_v(
                        Books,
                        v,
                        [x + k * (bw + 0.01), y + c[1], z + c[2]],
                        [0.5 * bw, 0.012, 0.5 * bh - 0.004],
                        tilt,
                    );
                }
                continue;
            }
            let high = 1 + (r.next() * 3.0) as usize;
            for k in 0..high {
                let v = goods.accent(r.next());
                let turn = rot_z(0.25 * (r.next() - 0.5));
                b.slab_v(
                    Books,
                    v,
                    [x, y, z + (k as f64 + 0.5) * t],
                    [0.5 * BOOK[0], 0.5 * BOOK[1], 0.5 * t - 0.001],
                    turn,
                );
            }
        }
    }
}

/// A bouquet rising from a vase's neck at height `z` (of radius `neck`) to `top`: stems
/// fanning out to blooms and a few leaves, in the flower palette.
pub(super) fn bouquet(b: &mut Builder, z: f64, neck: f64, top: f64) {
    let span = top - z;
    if span < 0.05 {
        return;
    }
    let mut r = Draws::new((span * 1e4) as u64 | 1);
    let bloom = (0.12 * span).clamp(0.015, 0.05);
    let n = 7;
    for k in 0..n {
        let a = k as f64 / n as f64 * std::f64::consts::TAU + 0.4 * r.next();
        // the middle stem stands tallest, the others lean out
        let (out, up) = if k == 0 {
            (0.0, 1.0)
        } else {
            (0.5 * span * (0.5 + 0.5 * r.next()), 0.75 + 0.15 * r.next())
        };
        // (inside the box: what leaves it is not drawn)
        let out = out.min(0.5 * b.w.min(b.d) - bloom).max(0.0);
        let tip = [out * a.cos(), out * a.sin(), z + up * (span - bloom)];
        let foot = [0.3 * neck * a.cos(), 0.3 * neck * a.sin(), z - 0.05 * span];
        stick(b, 0, foot, tip, 0.003);
        let v = Goods::Flowers.accent(r.next());
        b.ellipsoid_rot(Books, v, tip, [bloom, bloom, 0.75 * bloom], IDENTITY);
        if k % 2 == 1 {
            let mid = [
                0.5 * (foot[0] + tip[0]),
                0.5 * (foot[1] + tip[1]),
                0.5 * (foot[2] + tip[2]),
            ];
            b.ellipsoid_rot(
                Books,
                0,
                mid,
                [0.6 * bloom, 0.6 * bloom, 0.25 * bloom],
                IDENTITY,
            );
        }
    }
}
