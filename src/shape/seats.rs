//! Layouts of seats and beds whose form is their point: a slouching bean bag, a rocking chair on
//! its rockers, a crib's barred sides; and a coat stand with its hooks. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A bean bag: a squashed round body with a slumped back rising behind the seat hollow.
pub fn bean_bag(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.ellipsoid(
        Upholstery,
        [0.0, 0.05 * b.d, 0.3 * h],
        [hw, 0.9 * hd, 0.3 * h],
    );
    b.ellipsoid(
        Upholstery,
        [0.0, -0.22 * b.d, 0.58 * h],
        [0.85 * hw, 0.5 * hd, 0.42 * h],
    );
    b.ellipsoid(
        Cushion,
        [0.0, 0.12 * b.d, 0.5 * h],
        [0.55 * hw, 0.45 * hd, 0.08 * h],
    );
}

/// A rocking chair: two curved rockers under the legs, a seat, arms and a tall back of
/// spindles under a top rail.
pub fn rocking_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.018;
    let zs = 0.42 * h;
    let rocker_z = |y: f64| r + 0.1 * (y / hd).powi(2);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.05);
        let pts: Vec<[f64; 3]> = (0..=12)
            .map(|i| {
                let y = -hd + r + (i as f64 / 12.0) * (2.0 * hd - 2.0 * r);
                [x, y, rocker_z(y)]
            })
            .collect();
        b.polyline(Frame, &pts, r);
        for y in [-0.3 * b.d, 0.3 * b.d] {
            b.rod(Frame, [x, y, rocker_z(y)], [x, y, zs], 0.02);
        }
        // Arm from the front leg to the back.
        let ya = -0.32 * b.d;
        b.rod(Frame, [x, 0.3 * b.d, zs], [x, 0.3 * b.d, zs + 0.22], 0.015);
        b.rod(Frame, [x, 0.33 * b.d, zs + 0.22], [x, ya, zs + 0.24], 0.02);
    }
    b.cuboid(
        Seat,
        [-hw + 0.03, -0.34 * b.d, zs],
        [hw - 0.03, 0.34 * b.d, zs + 0.04],
    );
    // The back leans back: posts, spindles and a top rail.
    let (yb, yt) = (-0.32 * b.d, -hd + 0.03);
    let xb = hw - 0.07;
    for k in 0..7 {
        let x = -xb + k as f64 * 2.0 * xb / 6.0;
        let rr = if k == 0 || k == 6 { 0.02 } else { 0.01 };
        b.rod(Frame, [x, yb, zs + 0.04], [x, yt, h - 0.06], rr);
    }
    b.rod(
        Frame,
        [-xb - 0.02, yt, h - 0.05],
        [xb + 0.02, yt, h - 0.05],
        0.03,
    );
}

/// A crib: corner posts, top and bottom rails and bars all round, a mattress inside.
pub fn crib(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let p = 0.045;
    super::fittings::corner_posts(b, Frame, p, h);
    let zb = 0.25 * h;
    let zm = zb + 0.12;
    b.cuboid(Mattress, [-hw + p, -hd + p, zb], [hw - p, hd - p, zm]);
    b.cuboid(
        Duvet,
        [-hw + p + 0.02, -0.1 * b.d, zm],
        [hw - p - 0.02, hd - p - 0.03, zm + 0.04],
    );
    let t = 0.03;
    let bar = 0.012;
    // Rails along the long sides (y) and the ends (x), with bars between them.
    let sides: [(bool, f64); 4] = [
        (true, -hw + t / 2.0),
        (true, hw - t / 2.0),
        (false, -hd + t / 2.0),
        (false, hd - t / 2.0),
    ];
    for (along_y, c) in sides {
        let span = if along_y { hd - p } else { hw - p };
        for z in [zb - 0.04, h - t] {
            if along_y {
                b.cuboid(Frame, [c - t / 2.0, -span, z], [c + t / 2.0, span, z + t]);
            } else {
                b.cuboid(Frame, [-span, c - t / 2.0, z], [span, c + t / 2.0, z + t]);
            }
        }
        let n = ((2.0 * span) / 0.08).floor() as usize;
        for i in 1..n {
            let u = -span + i as f64 * 2.0 * span / n as f64;
            let (a, bb) = if along_y {
                ([c, u, zb - 0.01], [c, u, h - t])
            } else {
                ([u, c, zb - 0.01], [u, c, h - t])
            };
            b.rod(Frame, a, bb, bar);
        }
    }
}

/// A coat stand: a pole on splayed feet, two rings of hooks near the top, a knob, and a coat
/// hanging from one hook.
pub fn coat_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    b.rod(Frame, [0.0, 0.0, 0.0], [0.0, 0.0, h - 0.06], 0.022);
    b.ellipsoid(Frame, [0.0, 0.0, h - 0.04], [0.035, 0.035, 0.04]);
    for k in 0..4 {
        let a = k as f64 * std::f64::consts::FRAC_PI_2 + 0.4;
        b.rod(
            Frame,
            [0.0, 0.0, 0.25],
            [0.95 * m * a.cos(), 0.95 * m * a.sin(), 0.015],
            0.015,
        );
    }
    for (z, n, l) in [(h - 0.16, 6, 0.6 * m), (h - 0.36, 4, 0.5 * m)] {
        for k in 0..n {
            let a = k as f64 * std::f64::consts::TAU / n as f64;
            let tip = [l * a.cos(), l * a.sin(), z + 0.08];
            b.rod(Handle, [0.0, 0.0, z], tip, 0.008);
            b.ellipsoid(Handle, tip, [0.014, 0.014, 0.014]);
        }
    }
    // A coat on the hook towards +x: shoulders under the hook, hanging to below the middle.
    let x = 0.55 * m;
    let top = h - 0.2;
    b.ellipsoid(Upholstery, [x, 0.0, top - 0.06], [0.06, 0.16, 0.06]);
    b.cuboid(
        Upholstery,
        [x - 0.06, -0.15, top - 0.85],
        [x + 0.05, 0.15, top - 0.06],
    );
}
