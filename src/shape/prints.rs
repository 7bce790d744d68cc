//! Layouts of printed sheets on a wall that are not a poster: a framed world map (a blue sea
//! with green and sand-coloured land masses, a grid of lines over it) and a wall calendar (a
//! picture over a grid of day boxes under a red month band, hung from a nail). The back lies
//! against the wall at -y; the print faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A world map in a thin frame: the sea, continents as flat blobs, and lines of latitude and
/// longitude over them.
pub fn wall_map(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let f = (0.04 * b.w.min(h)).clamp(0.01, 0.04);
    let y = -hd + 0.004;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, y, h]);
    let (x0, x1, z0, z1) = (-hw + f, hw - f, f, h - f);
    let (pw, ph) = (x1 - x0, z1 - z0);
    b.cuboid(Water, [x0, y, z0], [x1, y + 0.002, z1]);
    // Land masses, in map fractions (x, z, half width, half height); green, then sand.
    let land = [
        (0.22, 0.68, 0.11, 0.14, 0u32),
        (0.30, 0.32, 0.06, 0.15, 0),
        (0.52, 0.72, 0.07, 0.08, 1),
        (0.54, 0.42, 0.07, 0.16, 1),
        (0.74, 0.66, 0.17, 0.13, 0),
        (0.83, 0.27, 0.06, 0.05, 1),
    ];
    for (fx, fz, rx, rz, v) in land {
        let role = if v == 0 { Foliage } else { Soil };
        b.ellipsoid(
            role,
            [x0 + fx * pw, y + 0.004, z0 + fz * ph],
            [rx * pw, 0.001, rz * ph],
        );
    }
    let t = 0.0012;
    for k in 1..4 {
        let z = z0 + k as f64 / 4.0 * ph;
        b.cuboid(Canvas, [x0, y + 0.006, z - t], [x1, y + 0.007, z + t]);
    }
    for k in 1..6 {
        let x = x0 + k as f64 / 6.0 * pw;
        b.cuboid(Canvas, [x - t, y + 0.006, z0], [x + t, y + 0.007, z1]);
    }
}

/// A wall calendar: a white sheet with a picture at the top, a red band with the month, a grid
/// of day boxes (five weeks of seven days), hung from a nail at the top.
pub fn calendar(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y = -hd + 0.004;
    b.cuboid(Canvas, [-hw, -hd, 0.0], [hw, y, 0.97 * h]);
    let m = 0.06 * b.w;
    let (x0, x1) = (-hw + m, hw - m);
    let pw = x1 - x0;
    // The picture, a landscape: sky over a green hill.
    let (pz0, pz1) = (0.52 * h, 0.93 * h);
    b.cuboid(Body, [x0, y, pz0], [x1, y + 0.002, pz1]);
    let r = 0.25 * (pz1 - pz0);
    b.ellipsoid(Foliage, [0.0, y + 0.003, pz0 + r], [0.5 * pw, 0.001, r]);
    // The month band, then the day boxes, each a pale square with a gap round it.
    b.cuboid(Top, [x0, y, 0.44 * h], [x1, y + 0.002, 0.49 * h]);
    let (gz0, gz1) = (0.04 * h, 0.42 * h);
    let (cw, ch) = (pw / 7.0, (gz1 - gz0) / 5.0);
    for r in 0..5 {
        for c in 0..7 {
            let (cx, cz) = (x0 + c as f64 * cw, gz0 + r as f64 * ch);
            let role = if c == 6 { Handle } else { Frame };
            b.cuboid(
                role,
                [cx + 0.1 * cw, y, cz + 0.1 * ch],
                [cx + 0.9 * cw, y + 0.002, cz + 0.9 * ch],
            );
        }
    }
    b.cuboid(
        Metal,
        [-0.02 * hw - 0.004, -hd, 0.97 * h],
        [0.02 * hw + 0.004, y + 0.004, h],
    );
}
