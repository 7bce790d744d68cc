//! Layouts of lounge seats that are not armchairs: a chaise longue (a long seat with one raised
//! end), an egg chair (a shell on a pedestal), a papasan (a bowl cushion on a round rattan base),
//! a hanging chair (a basket on a chain from an arched stand) and a recliner with its footrest
//! out. The front faces +y, backs at -y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{rot_x, rot_y, V3};

/// A bowl open along `dir`: its pole at `pole`, its rim `depth` further along `dir`, of radius
/// `r` there (`ay` stretches the rim across the second axis).
fn cup(b: &mut Builder, role: Role, pole: V3, dir: V3, r: f64, depth: f64, ay: f64) {
    let profile = (0..=10)
        .map(|i| {
            let t = i as f64 / 10.0;
            [r * (1.0 - (1.0 - t) * (1.0 - t)).sqrt(), t * depth]
        })
        .collect();
    b.revolved(role, 0, pole, frame_along(dir), ay, profile);
}

fn unit(v: V3) -> V3 {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|q| q / l)
}

fn plus(a: V3, d: V3, t: f64) -> V3 {
    [a[0] + d[0] * t, a[1] + d[1] * t, a[2] + d[2] * t]
}

/// A chaise longue: a long upholstered base on short legs, a seat cushion, the head end raised
/// in a back rest leaning out with a bolster in its crook, and a low back along part of the
/// back side falling towards the foot.
pub fn chaise(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zl = 0.12;
    let zb = (0.45 * h).min(0.38);
    b.legs(Frame, 0.045, 0.04, 0.0, zl);
    b.cuboid(Upholstery, [-hw, -hd, zl], [hw, hd, zb]);
    b.cuboid(
        Cushion,
        [-hw + 0.3, -hd + 0.03, zb],
        [hw - 0.02, hd - 0.02, zb + 0.08],
    );
    // The raised end, leaning out by 20°.
    let a = 20f64.to_radians();
    let len = (h - zb) / a.cos() - 0.06;
    let foot = [-hw + 0.2, 0.0, zb];
    let up = [-a.sin(), 0.0, a.cos()];
    b.slab(
        Upholstery,
        plus(foot, up, len / 2.0),
        [0.07, hd, len / 2.0],
        rot_y(-a),
    );
    b.rod(
        Pillow,
        [-hw + 0.33, -hd + 0.04, zb + 0.1],
        [-hw + 0.33, hd - 0.04, zb + 0.1],
        0.09,
    );
    // The low back, its top falling towards the foot.
    let tilt = 12f64.to_radians();
    let bl = 0.55 * b.w;
    b.slab(
        Upholstery,
        [-hw + 0.1 + bl / 2.0, -hd + 0.05, zb + 0.12],
        [bl / 2.0, 0.05, 0.16],
        rot_y(tilt),
    );
}

/// An egg chair: a round disc foot and a column under a shell open to the front and tilted up,
/// upholstered inside, with a seat cushion.
pub fn egg_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.87 * hw).min(0.36 * h);
    let zc = h - r - 0.01;
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.7 * hw, 0.7 * hd, 0.9, 0.03);
    b.cylinder(Metal, [0.0, 0.0, 0.03], 0.035, zc - 0.95 * r);
    let dir = unit([0.0, 1.0, 0.27]);
    let depth = 1.3 * r;
    let rim = [0.0, 0.4 * hd, zc];
    let pole = plus(rim, dir, -depth);
    cup(b, Body, pole, dir, r, depth, 1.0);
    cup(
        b,
        Upholstery,
        plus(pole, dir, 0.03),
        dir,
        0.95 * r,
        depth - 0.03,
        1.0,
    );
    b.ellipsoid(
        Cushion,
        [0.0, 0.05 * hd, zc - 0.55 * r],
        [0.7 * r, 0.55 * r, 0.13 * r],
    );
}

/// A papasan: a wide bowl of rattan tilted back on a round rattan base, filled with a thick
/// round cushion.
pub fn papasan(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    let zb = 0.36 * h;
    b.revolved(
        Frame,
        0,
        [0.0, 0.0, 0.0],
        super::parts::IDENTITY,
        1.0,
        vec![
            [0.62 * m, 0.0],
            [0.68 * m, 0.05],
            [0.5 * m, zb - 0.02],
            [0.42 * m, zb],
        ],
    );
    b.revolved(
        Frame,
        0,
        [0.0, 0.0, 0.0],
        super::parts::IDENTITY,
        1.0,
        super::parts::frustum_profile(0.66 * m, 0.66 * m, 0.02),
    );
    let dir = unit([0.0, 0.45, 1.0]);
    let r = 0.97 * m;
    let depth = 0.6 * r;
    let pole = [0.0, -0.12 * m, zb - 0.06];
    cup(b, Frame, pole, dir, r, depth, 1.0);
    b.ellipsoid_rot(
        Cushion,
        0,
        plus(pole, dir, 0.62 * depth),
        [0.93 * r, 0.93 * r, 0.17 * r],
        frame_along(dir),
    );
}

/// A hanging chair: a round foot with an arched post rising from its back edge over the seat,
/// a chain from its tip to a rattan basket open to the front, clear of the floor, with a
/// cushion inside.
pub fn hanging_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.9 * hw, 0.9 * hd, 0.95, 0.03);
    let yb = -0.88 * hd;
    let top = h - 0.04;
    let arc: Vec<V3> = (0..=12)
        .map(|i| {
            let t = i as f64 / 12.0 * std::f64::consts::FRAC_PI_2;
            [0.0, yb * t.cos(), 0.03 + (top - 0.03) * t.sin()]
        })
        .collect();
    b.polyline(Metal, &arc, 0.03);
    // The basket: an egg open to the front, its top on the chain.
    let r = 0.42 * b.w.min(b.h / 2.2);
    let ay = 1.15;
    let dir = unit([0.0, 1.0, 0.2]);
    let depth = 1.5 * r;
    let zc = 0.5 * h;
    let rim = [0.0, hd - 0.05 - 0.2 * r, zc];
    let pole = plus(rim, dir, -depth);
    cup(b, Frame, pole, dir, r, depth, ay);
    let hook = [0.0, 0.0, top];
    let ring = [0.0, 0.0, zc + ay * r + 0.02];
    let links = 5;
    for k in 0..links {
        let z0 = hook[2] - (hook[2] - ring[2]) * k as f64 / links as f64;
        let z1 = hook[2] - (hook[2] - ring[2]) * (k + 1) as f64 / links as f64;
        b.ellipsoid(
            Metal,
            [0.0, 0.0, 0.5 * (z0 + z1)],
            [0.012, 0.012, 0.5 * (z0 - z1)],
        );
    }
    b.ellipsoid(
        Cushion,
        [0.0, 0.1 * hd, zc - 0.55 * r],
        [0.75 * r, 0.6 * r, 0.16 * r],
    );
    b.ellipsoid(Cushion, [0.0, -0.25 * hd, zc], [0.6 * r, 0.14 * r, 0.5 * r]);
}

/// A recliner lying back with its footrest out: padded arms, a seat, a back leaning back with a
/// head cushion, and the footrest held out in front of the seat on a metal linkage.
pub fn recliner(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let arm = (0.17 * b.w).min(0.17);
    let front = hd - 0.38 * b.d;
    let zs = 0.4 * h;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw, -hw + arm)
        } else {
            (hw - arm, hw)
        };
        b.cuboid(Upholstery, [x0, -hd + 0.06, 0.0], [x1, front, 0.56 * h]);
        b.rod(
            Upholstery,
            [0.5 * (x0 + x1), -hd + 0.06, 0.56 * h],
            [0.5 * (x0 + x1), front, 0.56 * h],
            arm / 2.0,
        );
    }
    let (xi0, xi1) = (-hw + arm, hw - arm);
    b.cuboid(Upholstery, [xi0, -hd + 0.1, 0.0], [xi1, front, zs]);
    b.cuboid(Cushion, [xi0, -hd + 0.3, zs], [xi1, front, zs + 0.1]);
    // The back, leaning back by 28°.
    let a = 28f64.to_radians();
    let len = (h - zs - 0.06) / a.cos();
    let foot = [0.0, -hd + 0.4, zs];
    let up = [0.0, -a.sin(), a.cos()];
    b.slab(
        Upholstery,
        plus(foot, up, len / 2.0),
        [hw - arm, 0.08, len / 2.0],
        rot_x(a),
    );
    let head = plus(foot, up, len - 0.08);
    b.rod(
        Cushion,
        [xi0 + 0.03, head[1] + 0.12, head[2]],
        [xi1 - 0.03, head[1] + 0.12, head[2]],
        0.07,
    );
    // The footrest out in front, tipped up a little, on a scissor linkage.
    let zf = zs - 0.02;
    b.slab(
        Upholstery,
        [0.0, 0.5 * (front + 0.05 + hd), zf],
        [hw - arm - 0.02, 0.5 * (hd - front - 0.05) - 0.01, 0.045],
        rot_x(0.2),
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.6 * (hw - arm);
        b.rod(
            Metal,
            [x, front - 0.02, 0.12],
            [x, hd - 0.12, zf - 0.05],
            0.012,
        );
        b.rod(
            Metal,
            [x, front - 0.02, zf - 0.04],
            [x, hd - 0.2, 0.14],
            0.012,
        );
    }
}

/// A sectional (corner) sofa: a long seat along the back with an arm at its left end, and a
/// chaise running forward from its right end to the front of the footprint, its outer arm low
/// along the chaise's side; seat cushions along the back, one long cushion on the chaise, back
/// cushions against the back rest. Seen from above, an L.
pub fn sectional(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lh = (0.1 * h).min(0.1);
    let base_top = 0.42 * h;
    let back = (0.14 * b.d).min(0.22);
    let arm = (0.06 * b.w).clamp(0.12, 0.2);
    // The seat along the back is a sofa's depth; the chaise a seat's width.
    let sd = (0.55 * b.d).clamp(0.8, 1.0).min(b.d - 0.3);
    let cw = (0.3 * b.w).clamp(0.7, 0.95);
    let (xc, yf) = (hw - arm - cw, -hd + sd);
    // Legs under the L's corners (none under the open front corner).
    for (x, y) in [
        (-hw + 0.03, -hd + 0.03),
        (hw - 0.08, -hd + 0.03),
        (hw - 0.08, hd - 0.08),
        (-hw + 0.03, yf - 0.08),
        (xc, hd - 0.08),
        (xc, yf - 0.08),
    ] {
        b.cuboid(Frame, [x, y, 0.0], [x + 0.05, y + 0.05, lh]);
    }
    b.cuboid(Upholstery, [-hw + arm, -hd, lh], [hw - arm, yf, base_top]);
    b.cuboid(Upholstery, [xc, yf, lh], [hw - arm, hd - 0.01, base_top]);
    b.cuboid(Upholstery, [-hw, -hd, lh], [hw, -hd + back, h]);
    let arm_top = 0.66 * h;
    b.cuboid(Upholstery, [-hw, -hd + back, lh], [-hw + arm, yf, arm_top]);
    b.cuboid(Upholstery, [hw - arm, -hd + back, lh], [hw, hd, arm_top]);
    let zc = base_top + 0.12 * h;
    let gap = 0.008;
    // Seat cushions along the back, as many as the straight run holds.
    let run = xc - (-hw + arm);
    let seats = ((run / 0.65).round() as usize).max(1);
    let sw = run / seats as f64;
    for i in 0..seats {
        let x0 = -hw + arm + i as f64 * sw;
        b.cuboid(
            Cushion,
            [x0 + gap, -hd + back, base_top],
            [x0 + sw - gap, yf - 0.01, zc],
        );
    }
    b.cuboid(
        Cushion,
        [xc + gap, -hd + back, base_top],
        [hw - arm - gap, hd - 0.02, zc],
    );
    // Back cushions along the whole back, the chaise's included.
    let n = seats + 1;
    let bw = (hw - arm - (-hw + arm)) / n as f64;
    for i in 0..n {
        let x0 = -hw + arm + i as f64 * bw;
        b.cuboid(
            Cushion,
            [x0 + gap, -hd + back, zc],
            [x0 + bw - gap, -hd + back + 0.18, 0.93 * h],
        );
    }
}
