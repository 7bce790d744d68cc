//! Layouts of instruments that are neither pianos nor plucked: a church organ (a case at the
//! back carrying ranks of metal pipes in three flats above a console of stepped manuals, stop
//! knobs, a music desk, a pedalboard and the bench; from behind, panel doors under an open back
//! showing a rank of wooden pipes) and a bowed string instrument (a cello or a double bass: a
//! waisted body with f-holes, a long black fingerboard, a bridge, four strings, a pegbox ending
//! in a scroll, standing on its end pin in a stand, its bow leaning on the stand). The front
//! faces +y.
use super::archetypes::Builder;
use super::fittings::{disc, pad};
use super::materials::Role::*;

/// One organ pipe standing at (`x`, `y`) on `z0`: a conical foot, a dark mouth above it and a
/// cylindrical body up to `z1`.
fn pipe(b: &mut Builder, x: f64, y: f64, z0: f64, z1: f64, r: f64) {
    let foot = (0.2 * (z1 - z0)).min(0.18);
    b.frustum(Metal, [x, y, z0], 0.3 * r, 0.3 * r, 1.0 / 0.3, foot);
    b.cylinder(Metal, [x, y, z0 + foot], r, z1 - z0 - foot);
    b.cuboid(
        Interior,
        [x - 0.55 * r, y + 0.9 * r, z0 + foot + 0.01],
        [x + 0.55 * r, y + r + 0.003, z0 + foot + 0.01 + 0.5 * r],
    );
}

/// The back of an organ's case at `yr`: below the impost height `zi` two framed panel doors
/// with knobs for the tuner, above it the open back showing a rank of square wooden pipes
/// standing in the dark of the case, graded from the middle out, a cornice over them.
fn case_back(b: &mut Builder, yr: f64, zi: f64) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.3 * (yr + hd);
    for sx in [-1.0, 1.0] {
        let (x0, x1) = (sx * 0.04, sx * (hw - 0.06));
        let (xa, xb) = (x0.min(x1), x0.max(x1));
        for (lo, hi) in [
            ([xa, yr - t, 0.1], [xb, yr, 0.16]),
            ([xa, yr - t, zi - 0.22], [xb, yr, zi - 0.16]),
            ([xa, yr - t, 0.1], [xa + 0.06, yr, zi - 0.16]),
            ([xb - 0.06, yr - t, 0.1], [xb, yr, zi - 0.16]),
        ] {
            b.cuboid(Frame, lo, hi);
        }
        b.rod(
            Handle,
            [sx * 0.1, yr - t, 0.5 * zi],
            [sx * 0.1, yr - 1.5 * t, 0.5 * zi],
            0.015,
        );
    }
    // A case too low for an upper back keeps its doors only.
    if zi + 0.3 > h - 0.14 {
        return;
    }
    b.cuboid(
        Interior,
        [-hw + 0.06, yr - 0.004, zi],
        [hw - 0.06, yr, h - 0.14],
    );
    let n = ((b.w - 0.2) / 0.12).floor().max(3.0) as usize;
    let side = ((yr + hd) * 0.7).min(0.08);
    for i in 0..n {
        let u = (i as f64 + 0.5) / n as f64;
        let x = -hw + 0.1 + u * (b.w - 0.2);
        let z1 = zi + (0.4 + 0.5 * (1.0 - (2.0 * u - 1.0).abs())) * (h - 0.2 - zi);
        b.cuboid(
            Frame,
            [x - 0.5 * side, -hd + 0.005, zi + 0.02],
            [x + 0.5 * side, -hd + 0.005 + side, z1],
        );
    }
    b.cuboid(Top, [-hw, -hd, h - 0.14], [hw, yr, h - 0.08]);
}

/// A church organ: the case, an impost ledge carrying three flats of pipes (a tall middle tower
/// peaking at its centre, the side flats rising to the outside), the console with two manuals
/// and stop jambs, the pedalboard under it and the bench in front.
pub fn church_organ(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yc = -hd + (0.45 * b.d).min(0.6);
    let zi = (0.5 * h).clamp(1.1, 1.4);
    // The case (its back wall set in to leave room for the back's fittings), its impost ledge
    // and a cornice on top.
    let yr = -hd + (0.06 * b.d).clamp(0.04, 0.1);
    b.cuboid(Body, [-hw, yr, 0.0], [hw, yc, h - 0.08]);
    case_back(b, yr, zi);
    b.cuboid(Top, [-hw, -hd, h - 0.08], [hw, yc + 0.04, h]);
    b.cuboid(Top, [-hw, yc - 0.02, zi - 0.06], [hw, yc + 0.1, zi]);
    b.cuboid(
        Interior,
        [-hw + 0.06, yc, zi + 0.02],
        [hw - 0.06, yc + 0.002, h - 0.12],
    );
    // Three flats of pipes on the ledge.
    let r = (0.022 * b.w).clamp(0.025, 0.05);
    let pitch = 2.3 * r;
    let n = ((b.w - 0.12) / pitch).floor() as usize;
    let top = h - 0.14;
    let low = zi + 0.35 * (top - zi);
    let third = n / 3;
    for i in 0..n {
        let x = -hw + 0.06 + (i as f64 + 0.5) * (b.w - 0.12) / n as f64;
        // Within its flat, each pipe's height: the middle tower peaks at its centre, the side
        // flats rise towards the outside.
        let (u, tall) = if i < third {
            ((third - i) as f64 / third as f64, 0.85)
        } else if i >= n - third {
            ((i + 1 - (n - third)) as f64 / third as f64, 0.85)
        } else {
            let m = (n - 2 * third) as f64;
            (
                1.0 - ((i - third) as f64 + 0.5 - m / 2.0).abs() / (m / 2.0),
                1.0,
            )
        };
        let z1 = low + tall * u.clamp(0.0, 1.0) * (top - low);
        pipe(b, x, yc + 0.05, zi, z1.max(low), r);
    }
    // The console: two cheeks, the stepped manuals, the stop jambs, the music desk.
    let (cw, y0) = ((0.32 * b.w).min(0.7), yc + 0.04);
    let yk = (y0 + 0.45).min(hd - 0.45);
    let zk = 0.72;
    for sx in [-1.0, 1.0] {
        let x = sx * cw;
        b.cuboid(Body, [x - 0.03, y0, 0.0], [x + 0.03, yk + 0.05, zk + 0.32]);
        // Stop knobs in rows on the jamb, angled towards the player.
        for row in 0..4 {
            for col in 0..3 {
                let xs = x - sx * (0.08 + 0.06 * col as f64);
                let z = zk + 0.12 + 0.06 * row as f64;
                b.rod(Handle, [xs, yk - 0.12, z], [xs, yk - 0.08, z], 0.013);
            }
        }
        b.cuboid(
            Body,
            [x - sx * 0.25 - 0.01, yk - 0.2, zk],
            [x - sx * 0.03, yk - 0.12, zk + 0.32],
        );
    }
    b.cuboid(Body, [-cw, y0, zk - 0.1], [cw, yk - 0.05, zk]);
    for (dy, dz) in [(0.0, 0.0), (-0.12, 0.1)] {
        let (xk, yf, z) = (cw - 0.27, yk + dy, zk + dz);
        b.cuboid(Body, [-xk, yf - 0.2, z - 0.03], [xk, yf - 0.15, z + 0.02]);
        b.cuboid(Keys, [-xk, yf - 0.15, z], [xk, yf, z + 0.02]);
        let keys = ((2.0 * xk) / 0.0235).floor() as usize;
        for i in 0..keys {
            if matches!(i % 7, 0 | 1 | 3 | 4 | 5) {
                let x = -xk + (i as f64 + 1.0) * 0.0235;
                b.cuboid(
                    BlackKeys,
                    [x - 0.006, yf - 0.15, z + 0.02],
                    [x + 0.006, yf - 0.06, z + 0.032],
                );
            }
        }
    }
    pad(
        b,
        Frame,
        0.0,
        [yk - 0.2, zk + 0.2],
        [yk - 0.26, zk + 0.45],
        0.35,
        0.02,
    );
    // The pedalboard: long wooden keys on the floor fanning towards the player.
    b.cuboid(Frame, [-cw, y0, 0.0], [cw, yk + 0.3, 0.05]);
    let pedals = 13;
    for i in 0..pedals {
        let x = (i as f64 - (pedals - 1) as f64 / 2.0) * 2.0 * (cw - 0.1) / pedals as f64;
        let role = if matches!(i % 7, 1 | 3 | 5) {
            BlackKeys
        } else {
            Keys
        };
        b.cuboid(
            role,
            [x - 0.02, y0 + 0.05, 0.05],
            [x + 0.02, yk + 0.28, 0.075],
        );
    }
    // The bench in front of the console.
    let yb = (yk + 0.45).min(hd - 0.18);
    b.cuboid(
        Seat,
        [-cw + 0.05, yb - 0.16, 0.52],
        [cw - 0.05, yb + 0.16, 0.57],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [sx * (cw - 0.08) - 0.02, yb - 0.15, 0.0],
            [sx * (cw - 0.08) + 0.02, yb + 0.15, 0.52],
        );
    }
}

/// A cello or a double bass on its end pin in a stand: the waisted body (lower bout, waist,
/// upper bout) with two f-holes, a bridge and a tailpiece, the black fingerboard running up
/// from the upper bout along the neck, four strings, the pegbox with its pegs and the scroll on
/// top; the stand's post and cradle behind.
pub fn bowed_instrument(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.45 * hd).min(0.1);
    let bw = hw.min(0.19 * h);
    let pin = 0.1 * h;
    let (zl, zw, zu) = (pin + 0.16 * h, pin + 0.3 * h, pin + 0.43 * h);
    let zb = pin + 0.56 * h;
    b.ellipsoid(Body, [0.0, 0.0, zl], [bw, t, 0.16 * h]);
    b.ellipsoid(Body, [0.0, 0.0, zw], [0.6 * bw, t, 0.1 * h]);
    b.ellipsoid(Body, [0.0, 0.0, zu], [0.8 * bw, t, 0.13 * h]);
    // The f-holes either side of the bridge.
    for sx in [-1.0, 1.0] {
        let x = sx * 0.4 * bw;
        b.rod(
            Interior,
            [x, 0.97 * t, zw - 0.06 * h],
            [x + sx * 0.04 * bw, 0.97 * t, zw + 0.06 * h],
            0.007,
        );
    }
    b.cuboid(
        Top,
        [-0.2 * bw, 0.9 * t, zw - 0.02],
        [0.2 * bw, 1.25 * t, zw + 0.05 * h],
    );
    b.cuboid(
        BlackKeys,
        [-0.12 * bw, 0.85 * t, pin + 0.05 * h],
        [0.12 * bw, 1.05 * t, zw - 0.08 * h],
    );
    // The neck and fingerboard, the pegbox and the scroll.
    let zf = pin + 0.83 * h;
    b.cuboid(
        Frame,
        [-0.06 * bw, 0.4 * t, zb - 0.02],
        [0.06 * bw, 0.9 * t, zf],
    );
    pad(
        b,
        BlackKeys,
        0.0,
        [1.0 * t, zw + 0.1 * h],
        [1.0 * t, zf],
        0.12 * bw,
        0.02,
    );
    b.cuboid(
        Frame,
        [-0.07 * bw, 0.45 * t, zf],
        [0.07 * bw, 0.95 * t, h - 0.06 * h],
    );
    for sx in [-1.0, 1.0] {
        for k in 0..2 {
            let z = zf + 0.02 * h + 0.025 * h * k as f64;
            b.rod(
                Trunk,
                [sx * 0.07 * bw, 0.7 * t, z],
                [sx * 0.2 * bw, 0.7 * t, z],
                0.01,
            );
        }
    }
    disc(
        b,
        Frame,
        [0.0, 0.7 * t, h - 0.035 * h],
        [1.0, 0.0, 0.0],
        0.035 * h,
        0.1 * bw,
    );
    for k in 0..4 {
        let x = (k as f64 - 1.5) * 0.08 * bw;
        b.rod(
            Metal,
            [x, 1.02 * t, zw - 0.08 * h],
            [x, 1.27 * t, zw + 0.05 * h],
            0.0025,
        );
        b.rod(
            Metal,
            [x, 1.27 * t, zw + 0.05 * h],
            [x * 0.5, 1.12 * t, zf],
            0.0025,
        );
    }
    // The end pin down to the floor, and the stand: a post behind with a cradle at the neck.
    b.rod(Metal, [0.0, 0.0, pin + 0.01], [0.0, 0.0, 0.0], 0.008);
    let ys = -hd + 0.03;
    b.rod(Metal, [0.0, ys, 0.0], [0.0, ys, zb + 0.05 * h], 0.012);
    b.rod(
        Metal,
        [0.0, ys, zb + 0.05 * h],
        [0.0, 0.0, zb + 0.05 * h],
        0.01,
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [0.0, ys, 0.02],
            [sx * (hw - 0.02), ys + 0.5 * hd, 0.0],
            0.01,
        );
    }
    disc(b, Frame, [0.0, 0.0, 0.01], [0.0, 0.0, 1.0], 0.06, 0.02);
    // The bow leaning on the stand at the left: a dark stick, its pale hair a finger's width
    // in front of it, the frog at its foot.
    let (foot, tip) = (
        [-(hw - 0.04), ys + 0.04, 0.01],
        [-0.15 * hw, ys + 0.04, 0.6 * h],
    );
    b.rod(Trunk, foot, tip, 0.006);
    let hair = |p: [f64; 3]| [p[0] + 0.012, p[1] + 0.012, p[2]];
    b.rod(Canvas, hair([foot[0], foot[1], 0.06]), hair(tip), 0.004);
    b.cuboid(
        BlackKeys,
        [foot[0] - 0.012, foot[1] - 0.01, 0.04],
        [foot[0] + 0.024, foot[1] + 0.024, 0.09],
    );
}
