//! Wall racks that hold things on hooks, drawn with what they hold: a row of coat hooks (a
//! wooden rail along the top with hooks, coats and a bag hanging from them) and a pegboard (a
//! perforated panel with tools hanging on its pegs: a hammer, wrenches, a saw, screwdrivers,
//! pliers). Both hang on a wall: the back at -y, the front +y.
use super::archetypes::Builder;
use super::fittings::{disc, Y};
use super::materials::Role::{self, *};

/// A hook standing off the wall face `y` at (`x`, `z`): a stem out of length `l`, then a tip
/// turned up, with a knob.
pub(super) fn hook(b: &mut Builder, role: Role, x: f64, y: f64, z: f64, l: f64) {
    let r = (0.06 * l).clamp(0.003, 0.008);
    b.polyline(
        role,
        &[
            [x, y, z],
            [x, y + l, z - 0.3 * l],
            [x, y + 1.1 * l, z + 0.15 * l],
        ],
        r,
    );
    b.ellipsoid(
        role,
        [x, y + 1.1 * l, z + 0.15 * l],
        [1.6 * r, 1.6 * r, 1.6 * r],
    );
}

/// A coat hanging from a hook at `[x, y0, z]` (`y0` the wall face), `[l, hw, t]`: `l` long, up
/// to `hw` half wide and `t` thick; shoulders, a body widening to its hem, sleeves at its sides.
fn coat(b: &mut Builder, variant: u32, [x, y0, z]: [f64; 3], [l, hw, t]: [f64; 3]) {
    let yc = y0 + t / 2.0 + 0.005;
    b.push(
        Books,
        variant,
        super::parts::Primitive::Revolved {
            origin: [x, yc, z - l],
            rot: super::parts::IDENTITY,
            ay: t / (2.0 * hw),
            profile: vec![
                [0.0, 0.0],
                [hw, 0.0],
                [0.85 * hw, 0.6 * l],
                [0.8 * hw, 0.88 * l],
                [0.35 * hw, l],
                [0.0, l],
            ],
        },
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Books,
            [x + sx * 0.78 * hw, yc, z - 0.12 * l],
            [x + sx * 0.95 * hw, yc + 0.1 * t, z - 0.62 * l],
            0.18 * hw,
        );
    }
    // The collar round the hook.
    b.cuboid_v(
        Books,
        variant,
        [x - 0.3 * hw, yc + 0.3 * t, z - 0.1 * l],
        [x + 0.3 * hw, yc + 0.45 * t, z],
    );
}

/// A row of coat hooks: a wooden rail near the top of the wall, five hooks, three coats, a bag
/// on its strap and a hat.
pub fn coat_hooks(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rail = (0.12 * h).clamp(0.06, 0.1);
    let y0 = -hd;
    b.cuboid(Top, [-hw, y0, h - rail], [hw, y0 + 0.025, h]);
    let yf = y0 + 0.025;
    let n = 5;
    let zh = h - 0.55 * rail;
    let l = (0.35 * b.d).clamp(0.03, 0.06);
    let xs: Vec<f64> = (0..n)
        .map(|k| -hw + (k as f64 + 0.5) / n as f64 * b.w)
        .collect();
    for x in &xs {
        hook(b, Metal, *x, yf, zh, l);
        disc(b, Metal, [*x, yf + 0.002, zh], Y, 0.012, 0.004);
    }
    let t = (b.d - 0.04).clamp(0.05, 0.2);
    let cw = (0.36 * b.w / n as f64 * 2.0).min(0.24);
    let len = h - rail - 0.02;
    // The longest coat hangs to the floor of the size box: the drawn object rests on its hem.
    coat(b, 0, [xs[0], yf, zh], [zh, cw / 2.0, t]);
    coat(b, 3, [xs[1], yf, zh], [0.8 * len, cw / 2.0, 0.9 * t]);
    coat(b, 5, [xs[3], yf, zh], [0.9 * len, cw / 2.0, t]);
    // A bag on a long strap from the fourth hook... the third holds a hat.
    let (xb, zb) = (xs[4], zh - 0.45 * len);
    b.polyline(
        Frame,
        &[[xb - 0.01, yf + l, zh], [xb - 0.08, yf + 0.05, zb + 0.1]],
        0.006,
    );
    b.polyline(
        Frame,
        &[[xb + 0.01, yf + l, zh], [xb + 0.08, yf + 0.05, zb + 0.1]],
        0.006,
    );
    b.cuboid(
        Frame,
        [xb - 0.11, yf + 0.01, zb - 0.12],
        [xb + 0.11, yf + 0.09_f64.min(b.d - 0.04), zb + 0.1],
    );
    let xh = xs[2];
    b.frustum(
        Cushion,
        [xh, yf + 0.07_f64.min(hd), zh - 0.1],
        0.07,
        0.06,
        0.9,
        0.08,
    );
}

/// A small hand tool hanging flat on the pegboard face `y` with its top at (`x`, `z`), its
/// size set by `s`: `kind` 0 a hammer, 1 a wrench, 2 a screwdriver, 3 pliers, 4 a saw.
fn tool(b: &mut Builder, kind: usize, x: f64, y: f64, z: f64, s: f64) {
    let t = 0.012;
    let (y0, y1) = (y + 0.004, y + 0.004 + t);
    match kind {
        0 => {
            b.cuboid(Metal, [x - 0.5 * s, y0, z - 0.09 * s], [x + 0.5 * s, y1, z]);
            b.cuboid(
                Frame,
                [x - 0.06 * s, y0, z - 1.3 * s],
                [x + 0.06 * s, y1, z - 0.09 * s],
            );
        }
        1 => {
            b.cuboid(
                Metal,
                [x - 0.05 * s, y0, z - 1.5 * s],
                [x + 0.05 * s, y1, z - 0.15 * s],
            );
            b.cuboid(
                Metal,
                [x - 0.14 * s, y0, z - 0.2 * s],
                [x + 0.14 * s, y1, z],
            );
        }
        2 => {
            b.cuboid(
                Handle,
                [x - 0.07 * s, y0, z - 0.55 * s],
                [x + 0.07 * s, y1, z],
            );
            b.cuboid(
                Metal,
                [x - 0.02 * s, y0, z - 1.4 * s],
                [x + 0.02 * s, y1, z - 0.55 * s],
            );
        }
        3 => {
            b.cuboid(Metal, [x - 0.1 * s, y0, z - 0.35 * s], [x + 0.1 * s, y1, z]);
            for sx in [-1.0, 1.0] {
                b.cuboid(
                    Handle,
                    [x + sx * 0.1 * s - 0.04 * s, y0, z - 1.1 * s],
                    [x + sx * 0.1 * s + 0.04 * s, y1, z - 0.35 * s],
                );
            }
        }
        _ => {
            b.cuboid(
                Frame,
                [x - 0.18 * s, y0, z - 0.35 * s],
                [x + 0.18 * s, y1, z],
            );
            b.cuboid(
                Metal,
                [x - 0.12 * s, y0, z - 1.6 * s],
                [x + 0.1 * s, y0 + 0.003, z - 0.35 * s],
            );
        }
    }
}

/// A pegboard: a hardboard panel on a frame, pierced with a grid of holes, with hand tools
/// hanging on pegs in two rows.
pub fn pegboard(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let y0 = -hd;
    let face = y0 + 0.012;
    b.cuboid(Top, [-hw, y0, 0.0], [hw, face, h]);
    let pitch = (b.w.min(h) / 12.0).clamp(0.04, 0.1);
    let (nx, nz) = ((b.w / pitch) as usize, (h / pitch) as usize);
    for i in 0..nx {
        for j in 0..nz {
            let x = -hw + (i as f64 + 0.5) * b.w / nx as f64;
            let z = (j as f64 + 0.5) * h / nz as f64;
            b.cuboid(
                Interior,
                [x - 0.004, face, z - 0.004],
                [x + 0.004, face + 0.001, z + 0.004],
            );
        }
    }
    let s = (0.22 * h).min(0.16 * b.w).clamp(0.05, 0.22);
    let peg = (b.d - 0.03).clamp(0.01, 0.03);
    let rows = [0.92 * h, 0.45 * h];
    let per = ((b.w / (0.5 * s + 0.08)) as usize).clamp(3, 8);
    for (r, zr) in rows.iter().enumerate() {
        for k in 0..per {
            let x = -hw + (k as f64 + 0.5) / per as f64 * b.w;
            let kind = (k + 2 * r) % 5;
            b.rod(
                Metal,
                [x, face, zr + 0.01],
                [x, face + peg, zr + 0.02],
                0.003,
            );
            tool(b, kind, x, face, *zr, 0.6 * s);
        }
    }
}
