//! Layouts of racks drawn with what they hold: a magazine rack (slots of magazines standing up
//! between end frames, a carrying handle over them), a shoe rack (tiers of slats with pairs of
//! shoes on them), a plate rack (a dish drainer: plates on edge between rows of pegs on a drip
//! tray) and a book cart (shelves sloping down to a middle spine on both faces, books leaning
//! on them, castors and push handles). The front faces +y.
use super::archetypes::Builder;
use super::fittings::{castor, disc, pad, X};
use super::materials::Role::*;
use super::parts::rot_x;

/// A magazine rack: a base board on short feet, end frames, three slots parted by low slats,
/// two or three magazines standing in each slot leaning a little, and a handle bar on posts.
pub fn magazine_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.015;
    let zb = 0.05;
    let zs = 0.62 * h;
    b.legs(Frame, 0.025, 0.01, 0.0, zb);
    b.cuboid(Frame, [-hw, -hd, zb], [hw, hd, zb + t]);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Frame, [x - t / 2.0, -hd, zb], [x + t / 2.0, hd, zs]);
        b.rod(Frame, [x, 0.0, zs], [x, 0.0, h - 0.02], 0.012);
    }
    b.rod(
        Frame,
        [-hw + t, 0.0, h - 0.02],
        [hw - t, 0.0, h - 0.02],
        0.014,
    );
    let slots = 3;
    let pitch = b.d / slots as f64;
    for k in 1..slots {
        let y = -hd + k as f64 * pitch;
        b.cuboid(
            Frame,
            [-hw + t, y - 0.005, zb],
            [hw - t, y + 0.005, 0.7 * zs],
        );
    }
    b.cuboid(Frame, [-hw + t, -hd, zb], [hw - t, -hd + 0.008, 0.7 * zs]);
    b.cuboid(Frame, [-hw + t, hd - 0.008, zb], [hw - t, hd, 0.7 * zs]);
    let mh = (0.62 * h).min(0.32);
    for k in 0..slots {
        let y0 = -hd + k as f64 * pitch + 0.015;
        for m in 0..3 {
            if (k + m) % 4 == 3 {
                continue;
            }
            let lean = 0.12 + 0.05 * m as f64;
            let y = y0 + 0.012 * m as f64;
            let zc = zb + t + 0.5 * mh * lean.cos();
            let yc = y + 0.5 * mh * lean.sin();
            let half = [hw - t - 0.02 - 0.015 * m as f64, 0.004, 0.5 * mh];
            b.push(
                Books,
                (k * 3 + m) as u32,
                super::parts::Primitive::Cuboid {
                    centre: [0.0, yc, zc],
                    half,
                    rot: rot_x(-lean),
                },
            );
        }
    }
}

/// A shoe: a sole, a rounded upper over the toe and a heel counter, toes towards +y.
fn shoe(b: &mut Builder, x: f64, y: f64, z: f64, len: f64, variant: u32) {
    let w = 0.36 * len;
    b.cuboid_v(
        Interior,
        0,
        [x - w / 2.0, y, z],
        [x + w / 2.0, y + len, z + 0.015],
    );
    b.ellipsoid_rot(
        Books,
        variant,
        [x, y + 0.62 * len, z + 0.015],
        [w / 2.0, 0.38 * len, 0.3 * len],
        super::parts::IDENTITY,
    );
    b.cuboid_v(
        Books,
        variant,
        [x - w / 2.0, y, z + 0.015],
        [x + w / 2.0, y + 0.35 * len, z + 0.3 * len],
    );
}

/// A shoe rack: corner posts, tiers of two slats each, a top board,
/// and pairs of shoes on every tier.
pub fn shoe_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.02;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - t / 2.0);
            b.cuboid(
                Frame,
                [x - t / 2.0, y - t / 2.0, 0.0],
                [x + t / 2.0, y + t / 2.0, h],
            );
        }
    }
    b.cuboid(Top, [-hw, -hd, h - t], [hw, hd, h]);
    let tiers = ((h / 0.28).floor() as usize).clamp(2, 5);
    let pitch = (h - t) / tiers as f64;
    let len = (b.d - 0.04).clamp(0.1, 0.27);
    let pairs = ((b.w - 0.04) / 0.24).floor().max(1.0) as usize;
    for k in 0..tiers {
        let z = 0.04 + k as f64 * pitch;
        // Two slats a tier, front and back; the shoes stand across them.
        for (y, dz) in [(hd - 0.05, 0.0), (-hd + 0.05, 0.0)] {
            b.cuboid(
                Top,
                [-hw + t, y - 0.02, z + dz - 0.015],
                [hw - t, y + 0.02, z + dz],
            );
        }
        for sx in [-1.0, 1.0] {
            b.cuboid(
                Frame,
                [sx * (hw - t) - 0.01, -hd, z - 0.015],
                [sx * (hw - t) + 0.01, hd, z + 0.04],
            );
        }
        let cell = (b.w - 2.0 * t) / pairs as f64;
        for p in 0..pairs {
            if (k + p) % 5 == 4 {
                continue;
            }
            let xc = -hw + t + (p as f64 + 0.5) * cell;
            let v = (k * pairs + p) as u32;
            for dx in [-0.055, 0.055] {
                shoe(b, xc + dx, -hd + 0.03, z + 0.012, len, v);
            }
        }
    }
}

/// A plate rack (a dish drainer): a drip tray, two rows of pegs along it, plates standing on
/// edge between the pegs facing the sides, and cups upside down on the tray at one end.
pub fn plate_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.03;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.012]);
    for sy in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [-hw, sy * hd - 0.005 * (sy + 1.0), 0.012],
            [hw, sy * hd - 0.005 * (sy - 1.0), zt],
        );
    }
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [sx * hw - 0.005 * (sx + 1.0), -hd, 0.012],
            [sx * hw - 0.005 * (sx - 1.0), hd, zt],
        );
    }
    b.cuboid(
        Frame,
        [-hw + 0.01, -hd + 0.01, zt - 0.006],
        [hw - 0.01, hd - 0.01, zt],
    );
    let r = (0.45 * (h - zt)).min(0.45 * b.d).min(0.13);
    let zc = zt + r + 0.004;
    let pitch = 0.04;
    let x_end = hw - 0.02 - 0.14f64.min(0.3 * b.w);
    let n = (((x_end + hw - 0.02) / pitch).floor() as usize).max(2);
    let ry = 0.75 * r;
    for i in 0..=n {
        let x = -hw + 0.02 + i as f64 * pitch;
        for y in [-ry, ry] {
            b.rod(Frame, [x, y, zt], [x, y, zt + 0.8 * r], 0.004);
        }
        b.rod(Frame, [x, -ry, zt + 0.8 * r], [x, ry, zt + 0.8 * r], 0.003);
        if i < n && i % 3 != 2 {
            let xp = x + 0.5 * pitch;
            disc(b, Canvas, [xp, 0.0, zc], X, r, 0.008);
            disc(b, Pot, [xp, 0.0, zc], X, 0.55 * r, 0.01);
        }
    }
    // Two cups upside down at the free end.
    let xc = 0.5 * (x_end + hw);
    for y in [-0.45 * hd, 0.45 * hd] {
        let rc = (0.35 * hd).min(0.045);
        b.frustum(Canvas, [xc, y, zt], rc, rc, 0.8, (0.8 * h).min(0.09));
    }
}

/// A book cart: two open end frames on castors, a base shelf, tiers of shelves on both faces that
/// slope down to a middle spine so the books on them lean back against it, a top tray, and a
/// push handle at each end.
pub fn book_cart(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rc = 0.05;
    let z0 = 2.0 * rc + 0.04;
    let xe = hw - 0.05;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            castor(b, sx * (xe - 0.04), sy * (hd - 0.06), rc, z0);
        }
        // The end frame: two posts, a low panel and a top rail, open between so the sloped
        // shelves show from the side.
        for sy in [-1.0, 1.0] {
            let y = sy * (hd - 0.02);
            b.cuboid(
                Frame,
                [sx * xe - 0.012, y - 0.02, z0],
                [sx * xe + 0.012, y + 0.02, h - 0.04],
            );
        }
        b.cuboid(
            Frame,
            [sx * xe - 0.01, -hd, z0],
            [sx * xe + 0.01, hd, z0 + 0.08],
        );
        b.cuboid(
            Frame,
            [sx * xe - 0.01, -hd, h - 0.1],
            [sx * xe + 0.01, hd, h - 0.04],
        );
        // The push handle: a loop out from the end frame.
        let x = sx * (hw - 0.015);
        b.polyline(
            Metal,
            &[
                [sx * xe, -0.6 * hd, h - 0.12],
                [x, -0.6 * hd, h - 0.12],
                [x, 0.6 * hd, h - 0.12],
                [sx * xe, 0.6 * hd, h - 0.12],
            ],
            0.013,
        );
    }
    b.cuboid(Frame, [-xe, -hd, z0], [xe, hd, z0 + 0.02]);
    b.cuboid(Frame, [-xe, -0.008, z0], [xe, 0.008, h - 0.04]);
    b.cuboid(Top, [-xe - 0.01, -hd, h - 0.04], [xe + 0.01, hd, h - 0.02]);
    // Sloped shelves, two tiers a face, each with a back board leaning in at the same angle
    // (an A-frame), and books standing square to the shelf, leaning back on the board.
    let tiers = 2;
    let pitch = (h - 0.06 - z0) / tiers as f64;
    let slope = 0.25f64;
    let bh = (0.7 * pitch).min(0.28);
    let y_back = 0.012 + bh * slope.tan();
    let bd = (0.9 * (hd - y_back - 0.02)).clamp(0.03, 0.17);
    for k in 0..tiers {
        let z = z0 + 0.03 + k as f64 * pitch;
        for sy in [-1.0, 1.0] {
            let rise = (hd - 0.01 - y_back) * slope.tan();
            pad(
                b,
                Frame,
                0.0,
                [sy * y_back, z],
                [sy * 0.012, z + bh],
                xe,
                0.012,
            );
            pad(
                b,
                Top,
                0.0,
                [sy * y_back, z],
                [sy * (hd - 0.01), z + rise],
                xe,
                0.015,
            );
            b.cuboid(
                Top,
                [-xe, sy * hd - 0.01 * (sy + 1.0), z + rise],
                [xe, sy * hd - 0.01 * (sy - 1.0), z + rise + 0.03],
            );
            let mut x = -xe + 0.02;
            let mut i = 0u32;
            while x < xe - 0.06 {
                let bt = 0.025 + 0.01 * ((i * 7 + k as u32 * 3) % 4) as f64;
                let hh = bh * (0.8 + 0.05 * ((i * 5 + 1) % 5) as f64);
                if (i + k as u32) % 9 != 8 {
                    // The book's foot rests on the shelf against the back board.
                    let up = [-sy * slope.sin(), slope.cos()];
                    let along = [sy * slope.cos(), slope.sin()];
                    let foot = [
                        sy * (y_back + 0.008) + along[0] * bd / 2.0,
                        z + 0.008 + along[1] * bd / 2.0,
                    ];
                    let c = [foot[0] + up[0] * hh / 2.0, foot[1] + up[1] * hh / 2.0];
                    b.push(
                        Books,
                        i + 17 * k as u32 + if sy > 0.0 { 0 } else { 40 },
                        super::parts::Primitive::Cuboid {
                            centre: [x + bt / 2.0, c[0], c[1]],
                            half: [bt / 2.0 - 0.002, bd / 2.0, hh / 2.0],
                            rot: rot_x(sy * slope),
                        },
                    );
                }
                x += bt;
                i += 1;
            }
        }
    }
}
