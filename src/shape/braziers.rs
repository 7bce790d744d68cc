//! A brazier: an iron fire bowl with a rolled rim on three splayed legs joined by a ring,
//! heaped with glowing coals under tongues of flame that rise to the top of its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::IDENTITY;
use std::f64::consts::TAU;

/// Draws the brazier at the builder's size.
pub fn brazier(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let (z0, z1) = (0.45 * h, 0.68 * h);
    let r = 0.95 * m;
    let rod = (0.035 * m).max(0.008);
    // The bowl: open at the top, its wall a thin shell, a rolled rim.
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, z0],
        IDENTITY,
        hd.min(hw) / m,
        vec![
            [0.0, 0.0],
            [0.45 * r, 0.05 * (z1 - z0)],
            [0.8 * r, 0.35 * (z1 - z0)],
            [r, z1 - z0],
            [0.96 * r, z1 - z0],
            [0.76 * r, 0.38 * (z1 - z0)],
            [0.0, 0.1 * (z1 - z0)],
        ],
    );
    let ring: Vec<[f64; 3]> = (0..=24)
        .map(|i| {
            let a = i as f64 / 24.0 * TAU;
            [0.98 * r * a.cos(), 0.98 * r * a.sin(), z1]
        })
        .collect();
    b.polyline(Metal, &ring, 1.2 * rod);
    // Three legs splayed out to the floor, a ring joining them low down.
    let low = 0.15 * h;
    let mut feet = vec![];
    for k in 0..3 {
        let a = k as f64 / 3.0 * TAU + 0.5;
        let (c, s) = (a.cos(), a.sin());
        let top = [0.7 * r * c, 0.7 * r * s, z0 + 0.3 * (z1 - z0)];
        let knee = [0.85 * m * c, 0.85 * m * s, low];
        let foot = [0.95 * m * c, 0.95 * m * s, 0.0];
        b.polyline(Metal, &[top, knee, foot], rod);
        b.ellipsoid(Metal, foot, [2.0 * rod, 2.0 * rod, rod]);
        feet.push(knee);
    }
    feet.push(feet[0]);
    b.polyline(Metal, &feet, 0.7 * rod);
    // Coals heaped in the bowl, glowing, a few dark.
    let coal = 0.16 * r;
    for ring_i in 0..3 {
        let rr = [0.0, 0.38, 0.7][ring_i] * r;
        let n = [1, 6, 10][ring_i];
        for k in 0..n {
            let a = k as f64 / n as f64 * TAU + 0.3 * ring_i as f64;
            let c = [rr * a.cos(), rr * a.sin(), z1 - 0.1 * (z1 - z0) - 0.25 * rr];
            let role = if (k + ring_i) % 4 == 0 { Interior } else { Top };
            b.ellipsoid(role, c, [coal, coal, 0.7 * coal]);
        }
    }
    // Flames: a tall tongue at the centre and shorter ones around it, each swelling from the
    // coals and drawn out to a wavering tip.
    let base = z1 - 0.05 * (z1 - z0);
    flame(b, [0.0, 0.0, base], 0.4 * r, h - base, 0.0);
    for k in 0..5 {
        let a = k as f64 / 5.0 * TAU + 0.2;
        let c = [0.5 * r * a.cos(), 0.5 * r * a.sin(), base];
        let tall = (0.5 + 0.12 * (k % 3) as f64) * (h - base);
        flame(b, c, 0.22 * r, tall, a);
    }
}

/// A tongue of flame standing on `base`: round below, leaning out along `a` to its tip.
fn flame(b: &mut Builder, base: [f64; 3], r: f64, tall: f64, a: f64) {
    let lean = if r > 0.0 { 0.25 * r } else { 0.0 };
    let pts = [
        (0.0, 0.6),
        (0.25, 1.0),
        (0.5, 0.7),
        (0.75, 0.35),
        (0.95, 0.08),
    ];
    for w in pts.windows(2) {
        let at = |(t, _): (f64, f64)| {
            let off = lean * t * t;
            [
                base[0] + off * a.cos(),
                base[1] + off * a.sin(),
                base[2] + t * tall,
            ]
        };
        super::beasts::taper(b, Light, at(w[0]), at(w[1]), w[0].1 * r, w[1].1 * r);
    }
    b.ellipsoid(
        Top,
        [base[0], base[1], base[2] + 0.2 * tall],
        [0.6 * r, 0.6 * r, 0.2 * tall],
    );
}
