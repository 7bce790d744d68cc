//! A kitchen cart (a butcher-block top with a drawer, slatted shelves with a basket, a towel
//! bar and casters) and a candelabra (a tall candlestick whose arms hold candles round a middle
//! one, on a turned stem and a wide foot). Layout only: colours come from the archetype table.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, IDENTITY};

pub fn kitchen_cart(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rc = 0.035;
    let t = (0.06 * h).clamp(0.04, 0.06);
    // The butcher block: a thick top laid in strips of wood.
    let strips = ((b.w / 0.05).floor() as usize).max(6);
    let sw = b.w / strips as f64;
    for k in 0..strips {
        let x = -hw + k as f64 * sw;
        b.cuboid_v(Top, k as u32 % 3, [x, -hd, h - t], [x + sw, hd, h]);
    }
    // Legs on casters, a drawer under the top, two slatted shelves.
    let s = 0.04;
    let (lx, ly) = (hw - 0.03 - s / 2.0, hd - 0.03 - s / 2.0);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * lx, sy * ly);
            b.cuboid(
                Frame,
                [x - s / 2.0, y - s / 2.0, 2.0 * rc],
                [x + s / 2.0, y + s / 2.0, h - t],
            );
            b.ellipsoid(Tyre, [x, y, rc], [0.6 * rc, rc, rc]);
        }
    }
    let zd = h - t - 0.13;
    b.cuboid(Body, [-lx, -ly, zd], [lx, ly, h - t]);
    b.cuboid(
        Door,
        [-lx + 0.03, ly, zd + 0.015],
        [lx - 0.03, ly + s / 2.0, h - t - 0.015],
    );
    b.cuboid(
        Handle,
        [-0.08, ly + s / 2.0, zd + 0.055],
        [0.08, ly + s / 2.0 + 0.015, zd + 0.075],
    );
    let shelves = [2.0 * rc + 0.1, 0.5 * (2.0 * rc + 0.1 + zd)];
    for z in shelves {
        let n = ((2.0 * ly) / 0.06).floor() as usize;
        for k in 0..n {
            let y = -ly + (k as f64 + 0.5) * 2.0 * ly / n as f64;
            b.cuboid(Frame, [-lx, y - 0.02, z - 0.02], [lx, y + 0.02, z]);
        }
    }
    // A wicker basket on the lower shelf, bowls on the upper one.
    let z0 = shelves[0];
    b.cuboid(
        Canvas,
        [-0.7 * lx, -0.7 * ly, z0],
        [0.1 * lx, 0.7 * ly, z0 + 0.16],
    );
    b.cuboid(
        Interior,
        [-0.65 * lx, -0.6 * ly, z0 + 0.16],
        [0.05 * lx, 0.6 * ly, z0 + 0.162],
    );
    let z1 = shelves[1];
    for (k, x) in [-0.45 * lx, 0.0, 0.45 * lx].into_iter().enumerate() {
        b.revolved(
            Books,
            k as u32,
            [x, 0.0, z1],
            IDENTITY,
            1.0,
            frustum_profile(0.05, 0.09, 0.08),
        );
    }
    // The towel bar on the right end, a towel over it.
    let xb = hw - 0.012;
    for y in [-ly + 0.02, ly - 0.02] {
        b.rod(Metal, [lx, y, h - t - 0.06], [xb, y, h - t - 0.06], 0.008);
    }
    b.rod(
        Metal,
        [xb, -ly + 0.02, h - t - 0.06],
        [xb, ly - 0.02, h - t - 0.06],
        0.01,
    );
    b.cuboid(
        Cushion,
        [xb - 0.012, -0.5 * ly, h - t - 0.32],
        [xb + 0.004, 0.5 * ly, h - t - 0.05],
    );
}

/// A candelabra: a wide foot, a turned stem with knops, and arms curving out and up from a
/// crown to cups, each with a candle and its flame, round a middle candle.
pub fn candelabra(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let candle = (0.16 * h).min(0.22);
    let flame = 0.05;
    let cup = (h - candle - flame - 0.06).max(0.5 * h);
    let crown = cup - (0.2 * h).min(0.25);
    // The foot: a stepped disc on three small feet.
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, 0.02],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [0.55 * m, 0.0],
            [0.5 * m, 0.03],
            [0.2 * m, 0.08],
            [0.05, 0.12],
            [0.0, 0.12],
        ],
    );
    for k in 0..3 {
        let a = std::f64::consts::TAU * k as f64 / 3.0;
        b.ellipsoid(
            Metal,
            [0.5 * m * a.cos(), 0.5 * m * a.sin(), 0.02],
            [0.03, 0.03, 0.02],
        );
    }
    // The stem with knops along it.
    b.rod(Metal, [0.0, 0.0, 0.12], [0.0, 0.0, crown], 0.018);
    for f in [0.25, 0.55, 0.85] {
        let z = 0.12 + f * (crown - 0.12);
        b.ellipsoid(Metal, [0.0, 0.0, z], [0.04, 0.04, 0.03]);
    }
    b.frustum(Metal, [0.0, 0.0, crown - 0.02], 0.03, 0.03, 1.8, 0.05);
    // Arms: out from the crown, then up to a cup, a candle in each.
    let arms = 4;
    let reach = 0.85 * m - 0.03;
    let mut tops = vec![[0.0, 0.0]];
    for k in 0..arms {
        let a = std::f64::consts::TAU * (k as f64 + 0.5) / arms as f64;
        let (c, s) = (a.cos(), a.sin());
        let pts: Vec<[f64; 3]> = (0..=8)
            .map(|i| {
                let u = i as f64 / 8.0;
                let r = reach * u;
                // A curve that dips a little below the crown, then rises to the cup.
                let z =
                    crown + 0.02 - 0.06 * (std::f64::consts::PI * u).sin() + (cup - crown) * u * u;
                [r * c, r * s, z]
            })
            .collect();
        b.polyline(Metal, &pts, 0.012);
        tops.push([reach * c, reach * s]);
    }
    b.rod(Metal, [0.0, 0.0, crown], [0.0, 0.0, cup + 0.03], 0.016);
    for (i, [x, y]) in tops.into_iter().enumerate() {
        let zc = if i == 0 { cup + 0.03 } else { cup };
        b.frustum(Metal, [x, y, zc - 0.03], 0.02, 0.02, 2.0, 0.04);
        b.frustum(Metal, [x, y, zc], 0.045, 0.045, 1.0, 0.008);
        let ch = if i == 0 { candle } else { 0.9 * candle };
        b.cylinder(Body, [x, y, zc + 0.008], 0.018, ch);
        b.ellipsoid(Light, [x, y, zc + 0.008 + ch + 0.02], [0.012, 0.012, 0.022]);
    }
}
