//! Layouts of everyday things people name that used to borrow another thing's drawing: a
//! pottery wheel (once a boxy appliance with a window: now a wheel head in a round splash pan on
//! a low body, clay on the head, a foot pedal), a sarcophagus (once a strapped chest: now an oval
//! case on a plinth under a domed figure lid with a face, a headdress, bands and crossed arms), a
//! tripod lamp (once a floor lamp on a round base: now three splayed legs under a drum shade) and
//! a mushroom (once an umbrella: a thick pale stalk under a domed spotted cap with gills). The
//! front faces +y; each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use std::f64::consts::{PI, TAU};

/// A half ellipsoid dome standing on `base`: equatorial radius `r` (times `ay` along y) and
/// height `h`, open at the bottom.
fn dome(b: &mut Builder, role: super::materials::Role, base: [f64; 3], r: f64, ay: f64, h: f64) {
    let n = 12;
    let profile = (0..=n)
        .map(|i| {
            let phi = i as f64 / n as f64 * 0.5 * PI;
            [r * phi.cos(), h * phi.sin()]
        })
        .collect();
    b.revolved(role, 0, base, super::parts::IDENTITY, ay, profile);
}

/// A pottery wheel: a low body on a plinth, a round splash pan open at the top towards the
/// front, the wheel head (a thick metal disc) in the pan's middle with a lump of clay on it,
/// and a foot pedal on the floor at its right.
pub fn pottery_wheel(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let c = [0.0, hd - r];
    let zp = 0.62 * h;
    // The body: a squat box behind and under the pan, on a dark plinth.
    b.cuboid(
        Frame,
        [-0.8 * hw, -hd, 0.0],
        [0.8 * hw, hd - 0.3 * r, 0.05 * h],
    );
    b.cuboid(
        Body,
        [-0.7 * hw, -0.9 * hd, 0.05 * h],
        [0.7 * hw, hd - 0.4 * r, zp],
    );
    // The splash pan: a shallow basin flaring out, open at the top.
    let pan = vec![[0.0, 0.0], [0.8 * r, 0.0], [0.98 * r, 0.2 * h]];
    b.revolved(Top, 0, [c[0], c[1], zp], super::parts::IDENTITY, 1.0, pan);
    // The wheel head and the clay thrown on it.
    let zh = zp + 0.08 * h;
    b.cylinder(Metal, [c[0], c[1], zp], 0.12 * r, 0.08 * h);
    b.cylinder(Metal, [c[0], c[1], zh], 0.6 * r, 0.04 * h);
    let zc = zh + 0.04 * h;
    b.frustum(Soil, [c[0], c[1], zc], 0.3 * r, 0.3 * r, 0.7, 0.12 * h);
    b.ellipsoid(
        Soil,
        [c[0], c[1], zc + 0.12 * h],
        [0.21 * r, 0.21 * r, 0.04 * h],
    );
    // The foot pedal on the floor at the right, on a cable.
    let px = 0.85 * hw;
    b.slab(
        Handle,
        [px, hd - 0.45 * r, 0.05 * h],
        [0.12 * hw, 0.18 * r, 0.02 * h],
        rot_x(-0.25),
    );
    b.rod(
        Tyre,
        [0.7 * hw, 0.0, 0.03 * h],
        [px, hd - 0.6 * r, 0.03 * h],
        0.008,
    );
}

/// A rotation by `a` radians about x.
fn rot_x(a: f64) -> [[f64; 3]; 3] {
    let (s, c) = a.sin_cos();
    [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
}

/// A sarcophagus: a stone plinth, an oval case, and a domed lid carved as a figure lying face
/// up with its head to the front (+y): a golden face at the head end framed by a striped
/// headdress, arms crossed on the chest, painted bands across the legs.
pub fn sarcophagus(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.08 * h]);
    let (a, ay) = (0.95 * hw, 0.97 * hd / hw);
    let zc = 0.55 * h;
    b.frustum(Body, [0.0, 0.0, 0.08 * h], a, a * ay, 1.0, zc - 0.08 * h);
    // The lid: a dome over the case; its height over a point (x, y) is `lid(x, y)`.
    let (bb, c) = (a * ay, h - zc);
    dome(b, Top, [0.0, 0.0, zc], a, ay, c);
    let lid = |x: f64, y: f64| zc + c * (1.0 - (x / a).powi(2) - (y / bb).powi(2)).max(0.0).sqrt();
    // The head: a face on the lid's crown at the head end, headdress flaps either side.
    let yf = 0.72 * bb;
    let zf = lid(0.0, yf);
    let fr = 0.36 * a;
    b.ellipsoid(Skin, [0.0, yf, zf], [fr, 0.75 * fr, 0.35 * fr]);
    for sx in [-1.0, 1.0] {
        let x = sx * 1.05 * fr;
        b.ellipsoid(
            Canvas,
            [x, yf - 0.3 * fr, lid(x, yf - 0.3 * fr)],
            [0.45 * fr, 1.6 * fr, 0.3 * fr],
        );
    }
    // Arms crossed on the chest.
    let (y0, y1) = (0.25 * bb, 0.45 * bb);
    for sx in [-1.0, 1.0] {
        let p = |x: f64, y: f64| [x, y, lid(x, y) + 0.01];
        b.polyline(
            Handle,
            &[
                p(sx * 0.55 * a, y0),
                p(0.0, 0.5 * (y0 + y1)),
                p(-sx * 0.3 * a, y1),
            ],
            0.06 * a,
        );
    }
    // Painted bands across the legs, each hugging the lid's cross-section there.
    for k in 0..4 {
        let y = -0.75 * bb + 0.22 * bb * k as f64;
        let s = (1.0 - (y / bb).powi(2)).max(0.0).sqrt();
        b.ellipsoid(
            Canvas,
            [0.0, y, zc],
            [1.02 * a * s, 0.03 * bb, 1.02 * c * s],
        );
    }
}

/// A tripod floor lamp: three wooden legs splayed out to the floor from a collar under a drum
/// shade, a short metal stem up into the shade, a bulb inside it.
pub fn tripod_lamp(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let reach = 0.92 * hw.min(hd);
    let zc = 0.62 * h;
    let r = (0.015 * h).clamp(0.012, 0.025);
    for k in 0..3 {
        let ang = TAU / 4.0 + k as f64 / 3.0 * TAU;
        let foot = [reach * ang.cos(), reach * ang.sin(), 0.0];
        b.rod(Frame, [0.0, 0.0, zc], foot, r);
        b.cylinder(Metal, [foot[0], foot[1], 0.0], 1.2 * r, 0.02);
    }
    b.cylinder(Metal, [0.0, 0.0, zc - 0.03], 2.0 * r, 0.06);
    let zs = 0.72 * h;
    b.cylinder(Metal, [0.0, 0.0, zc], 0.5 * r, zs - zc + 0.05);
    let sr = 0.9 * hw.min(hd);
    let shade = vec![[sr, 0.0], [0.85 * sr, h - zs]];
    b.revolved(Shade, 0, [0.0, 0.0, zs], super::parts::IDENTITY, 1.0, shade);
    b.ellipsoid(Light, [0.0, 0.0, zs + 0.08], [0.05, 0.05, 0.06]);
}

/// A mushroom (a toadstool): a thick pale stalk flaring at its foot with a ring under the cap,
/// a domed cap wider than the stalk by far with pale gills under it and white spots on it.
pub fn mushroom(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let zc = 0.55 * h;
    b.frustum(
        Trunk,
        [0.0, 0.0, 0.0],
        0.34 * r,
        0.34 * r,
        0.75,
        zc + 0.02 * h,
    );
    b.frustum(
        Trunk,
        [0.0, 0.0, 0.72 * zc],
        0.32 * r,
        0.32 * r,
        1.2,
        0.05 * h,
    );
    // The gills: a pale disc under the cap's rim.
    b.frustum(Interior, [0.0, 0.0, zc], 0.97 * r, 0.97 * r, 1.0, 0.01 * h);
    let ch = h - zc;
    dome(b, Shade, [0.0, 0.0, zc], r, 1.0, ch);
    // White spots on the cap, in two rings and one on the crown.
    let on_cap = |rho: f64| zc + ch * (1.0 - (rho / r).powi(2)).max(0.0).sqrt();
    b.ellipsoid(
        Canvas,
        [0.0, 0.0, h - 0.03 * ch],
        [0.14 * r, 0.14 * r, 0.05 * ch],
    );
    for (ring, n, off) in [(0.5, 5, 0.0), (0.8, 8, 0.4)] {
        for k in 0..n {
            let ang = (k as f64 + off) / n as f64 * TAU;
            let rho = ring * r;
            b.ellipsoid(
                Canvas,
                [rho * ang.cos(), rho * ang.sin(), on_cap(rho)],
                [0.1 * r, 0.1 * r, 0.1 * ch],
            );
        }
    }
}

/// A lake: a wide sheet of water with no stone rim, its outline a few overlapping lobes, a band
/// of muddy shore just under its edge all round; flat, so that a boat can float on it.
pub fn lake(b: &mut Builder) {
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    let zw = b.h.min(0.05);
    // Lobes: (centre x, centre y, radius x, radius y) as fractions of the half size.
    const LOBES: [[f64; 4]; 4] = [
        [0.0, 0.0, 0.8, 0.78],
        [-0.38, 0.3, 0.6, 0.62],
        [0.42, -0.25, 0.56, 0.7],
        [0.3, 0.45, 0.52, 0.5],
    ];
    for [cx, cy, rx, ry] in LOBES {
        let c = [cx * hw, cy * hd, 0.0];
        // The water a flat open disc (no rim: where lobes overlap no seam shows) over a closed
        // low disc of soil (the sheet's side, seen edge on), whose rim shows past the water.
        let r = rx * hw;
        let soil = vec![[0.0, 0.0], [r, 0.0], [r, 0.6 * zw], [0.0, 0.6 * zw]];
        let water = vec![[0.0, zw], [0.94 * r, zw]];
        for (role, disc) in [(Soil, soil), (Water, water)] {
            b.revolved(
                role,
                0,
                c,
                super::parts::IDENTITY,
                ry * hd / (rx * hw),
                disc,
            );
        }
    }
}

/// The sea, not a pool: water out to the size box's back and sides, lighter in the shallows by
/// the shore and deeper blue-green away from it; at its front (+y, towards the land) a band of
/// wet sand, a ragged line of foam along the water's edge, and behind it broken crests, short
/// white dashes here and there, fewer further out; all standing a little over the water, flat.
pub fn sea(b: &mut Builder) {
    let (hw, hd) = (b.w / 2.0, b.d / 2.0);
    let zw = 0.6 * b.h;
    let band = shore_band(b.d);
    let shore = hd - band;
    // the beach's edge: dry sand, then a darker wet band the waves reach
    b.cuboid(Soil, [-hw, shore + 0.5 * band, 0.0], [hw, hd, 0.5 * zw]);
    b.cuboid(
        Interior,
        [-hw, shore, 0.0],
        [hw, shore + 0.5 * band, 0.5 * zw],
    );
    // shallows (variant 2), open water, the deep (variant 1) beyond
    let (shallow, deep) = (shore - 0.15 * b.d, -hd + 0.45 * b.d);
    b.cuboid_v(Water, 2, [-hw, shallow, 0.0], [hw, shore, zw]);
    b.cuboid_v(Water, 0, [-hw, deep, 0.0], [hw, shallow, zw]);
    b.cuboid_v(Water, 1, [-hw, -hd, 0.0], [hw, deep, zw]);
    // the foam line: short pieces of uneven depth along a wavering edge
    let piece = (0.04 * b.w).clamp(0.2, 0.8);
    let n = (b.w / piece).ceil() as usize;
    let foam = (0.03 * b.d).min(0.3);
    for k in 0..n {
        let x0 = -hw + k as f64 * piece;
        let x1 = (x0 + piece).min(hw);
        let wave = foam * (0.8 * (x0 * 1.3).sin() + 0.5 * (x0 * 0.37 + 1.0).sin());
        let depth = foam * (0.6 + 0.8 * wobble(k, 1));
        let y1 = (shore - 0.5 * foam + wave).min(shore);
        b.cuboid(Canvas, [x0, y1 - depth, 0.0], [x1, y1, b.h]);
    }
    // broken crests: dashes at rows further out, each row sparser and thinner
    for (row, y) in [shore - 0.12 * b.d, shore - 0.3 * b.d, shore - 0.5 * b.d]
        .into_iter()
        .enumerate()
    {
        let t = foam / (1.5 + row as f64);
        let dashes = ((b.w / (3.0 + 2.0 * row as f64)) as usize).max(2);
        for k in 0..dashes {
            let j = k + 17 * row;
            let len = piece * (1.5 + 2.5 * wobble(j, 2)) / (1.0 + 0.5 * row as f64);
            let x = -hw + (k as f64 + wobble(j, 3)) * b.w / dashes as f64;
            let x1 = (x + len).min(hw);
            let yy = y + 0.1 * b.d * (wobble(j, 4) - 0.5);
            // each crest bowed towards the shore, in three pieces
            let (step, bow) = ((x1 - x) / 3.0, 0.6 * foam);
            for (q, lift) in [0.0, 1.0, 0.0].into_iter().enumerate() {
                let (xa, xb) = (x + q as f64 * step, x + (q + 1) as f64 * step);
                let yc = (yy + bow * lift).min(shore - foam);
                if xb > xa {
                    b.cuboid(Canvas, [xa, yc - t, 0.0], [xb, yc, b.h]);
                }
            }
        }
    }
}

/// The band of beach (dry and wet sand) at the front of a drawn sea `depth` deep: its water
/// line lies this far behind its front (the environment carries the water on from there).
pub fn shore_band(depth: f64) -> f64 {
    (0.12 * depth).min(1.5)
}

/// A deterministic number in [0, 1) for index `k` and stream `s` (sizes that differ without a
/// random source, so a drawing is the same every time).
pub(super) fn wobble(k: usize, s: u32) -> f64 {
    let x = ((k as f64 + 1.0) * 12.9898 + s as f64 * 78.233).sin() * 43_758.547;
    x - x.floor()
}
