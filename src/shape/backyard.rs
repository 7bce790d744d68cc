//! Layouts of garden fixtures with a shape of their own: a pergola (posts carrying two beams
//! and a row of rafters, open to the sky, a vine climbing a post), a mailbox (a round-topped
//! box on a post, its door at the front and a red flag at its side) and a hot tub (a square
//! tub in a panelled skirt, a wide rim, water in the rim with bubbles on it, a step at the
//! front). Each faces +y and stays inside the size box.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A pergola: four or six square posts, a beam along each long side on top of them, rafters
/// across the beams with their ends out past them, and no roof; a vine climbs one post and
/// trails along its beam.
pub fn pergola(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let s = (0.04 * b.w.min(b.d)).clamp(0.1, 0.16); // post side
    let overhang = (0.08 * b.w.min(b.d)).min(0.3);
    let (bh, rh) = (0.2 * (h / 2.6).min(1.0), 0.16 * (h / 2.6).min(1.0));
    let zb = h - rh - bh; // the beams' underside: the posts' tops
                          // Posts: at the corners, inset by the overhang; a middle pair along a long pergola.
    let (px, py) = (hw - overhang, hd - 0.5 * overhang);
    let mut ys = vec![-py + s / 2.0, py - s / 2.0];
    if b.d > 4.0 {
        ys.push(0.0);
    }
    for sx in [-1.0, 1.0] {
        let x = sx * (px - s / 2.0);
        for &y in &ys {
            b.cuboid(
                Frame,
                [x - s / 2.0, y - s / 2.0, 0.0],
                [x + s / 2.0, y + s / 2.0, zb],
            );
        }
        // The beam along the posts, its ends out past the end posts.
        b.cuboid(Top, [x - 0.4 * s, -hd, zb], [x + 0.4 * s, hd, zb + bh]);
    }
    // Rafters across the beams, spaced about 0.4 m, their ends out past the beams.
    let n = ((b.d / 0.4).round() as usize).max(4);
    let t = 0.025;
    for i in 0..n {
        let y = -hd + 0.1 + i as f64 * (b.d - 0.2) / (n - 1) as f64;
        b.cuboid(Frame, [-hw, y - t, zb + bh], [hw, y + t, h]);
    }
    // A vine up the left front post, along its beam and out over the front rafters: a stem
    // with leaves along it, each a small flat blade at its own angle.
    let (x, y) = (-(px - s / 2.0), py - s / 2.0);
    let mut pts = vec![];
    for k in 0..8 {
        let z = k as f64 / 7.0 * zb;
        let a = k as f64 * 1.7;
        pts.push([x + 0.6 * s * a.cos(), y + 0.6 * s * a.sin(), z]);
    }
    let top = zb + bh + 0.02;
    pts.push([x, y, top]);
    pts.push([x, -py + s, top]);
    b.polyline(Trunk, &pts, 0.015);
    let rafter = [x, y - 0.2, h + 0.01];
    b.polyline(
        Trunk,
        &[[x, y - 0.2, top], rafter, [x + 0.6 * hw, y - 0.2, h + 0.01]],
        0.01,
    );
    let mut path = pts.clone();
    path.push(rafter);
    path.push([x + 0.6 * hw, y - 0.2, h + 0.01]);
    let leaf = 0.07 * (h / 2.6).clamp(0.5, 1.0);
    let mut k = 0u32;
    for w in path.windows(2) {
        let d: f64 = (0..3)
            .map(|i| (w[1][i] - w[0][i]).powi(2))
            .sum::<f64>()
            .sqrt();
        let n = (d / (0.8 * leaf)).ceil() as usize;
        for j in 0..n {
            let t = j as f64 / n as f64;
            let c = [0, 1, 2].map(|i| w[0][i] + t * (w[1][i] - w[0][i]));
            k += 1;
            let a = k as f64 * 2.4;
            let off = [
                0.6 * leaf * a.cos(),
                0.6 * leaf * a.sin(),
                0.3 * leaf * (1.3 * a).sin(),
            ];
            let c = [c[0] + off[0], c[1] + off[1], (c[2] + off[2]).min(h - 0.01)];
            let rot = super::parts::mat_mul(
                &super::parts::rot_z(a),
                &super::parts::rot_x(0.6 * (0.7 * a).sin()),
            );
            b.ellipsoid_rot(Foliage, k % 5, c, [leaf, 0.6 * leaf, 0.12 * leaf], rot);
        }
    }
}

/// A mailbox: a square post set in the ground, a box with a round top lying along it (its
/// door at the front with a handle), a red flag on an arm at its side.
pub fn mailbox(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let bw = (0.55 * hw).min(0.12); // the box's half width
    let flag = (hw - bw).min(0.06);
    let bx = -flag / 2.0; // the box leans left to leave the flag room at its right
    let zt = h - bw; // the round top's axis
    let zb = zt - 0.9 * bw; // the box's floor
    let s = (0.35 * bw).max(0.035);
    b.cuboid(Frame, [bx - s, -s, 0.0], [bx + s, s, zb]);
    b.cuboid(
        Frame,
        [bx - 1.4 * s, -0.8 * hd, zb - 0.03],
        [bx + 1.4 * s, 0.8 * hd, zb],
    );
    b.cuboid(Body, [bx - bw, -hd, zb], [bx + bw, hd - 0.01, zt]);
    b.rod(Body, [bx, -hd, zt], [bx, hd - 0.01, zt], bw);
    // The door: the front face, a handle on it.
    b.cuboid(Door, [bx - bw, hd - 0.01, zb], [bx + bw, hd - 0.004, zt]);
    b.rod(Door, [bx, hd - 0.01, zt], [bx, hd - 0.004, zt], bw);
    b.rod(Metal, [bx, hd - 0.004, zt], [bx, hd, zt], 0.2 * bw);
    // The flag on its arm at the right side, raised.
    let xf = bx + bw;
    b.rod(
        Handle,
        [xf + 0.01, -0.3 * hd, zb + 0.2 * bw],
        [xf + 0.01, -0.3 * hd, h - 0.01],
        0.01,
    );
    b.cuboid(
        Handle,
        [xf + 0.004, -0.3 * hd, h - 0.6 * bw],
        [xf + 0.016, -0.3 * hd + 0.9 * bw, h - 0.01],
    );
}

/// A hot tub: a square tub in a panelled skirt, a wide rim round it, water standing just under
/// the rim with bubbles on it and a headrest in each corner, a step up at the front.
pub fn hot_tub(b: &mut Builder) {
    let (hw, hd0, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let step_d = (0.14 * b.d).clamp(0.25, 0.4);
    let hd = hd0 - 0.5 * step_d; // the tub's half depth: the step stands before it
    let yc = -0.5 * step_d; // the tub's centre
    let rim = (0.08 * hw.min(hd)).clamp(0.1, 0.18);
    let corner = 2.5 * rim;
    // The skirt: the tub's body, panels on its faces.
    let zw = h - 0.09; // the water's surface
    b.cuboid(Body, [-hw, yc - hd, 0.0], [hw, yc + hd, zw - 0.06]);
    let n = 6;
    for i in 0..=n {
        let x = -hw + i as f64 * b.w / n as f64;
        b.cuboid(
            Frame,
            [x - 0.01, yc + hd, 0.05],
            [x + 0.01, yc + hd + 0.008, h - 0.08],
        );
    }
    b.cuboid(Frame, [-hw, yc + hd, 0.0], [hw, yc + hd + 0.01, 0.05]);
    // The tub's walls up to the rim, the skirt's top band outside: four bands round the water.
    let (x0, x1, y0, y1) = (-hw + rim, hw - rim, yc - hd + rim, yc + hd - rim);
    for (lo, hi) in [
        ([-hw, yc - hd, zw - 0.06], [hw, y0, h - 0.04]),
        ([-hw, y1, zw - 0.06], [hw, yc + hd, h - 0.04]),
        ([-hw, y0, zw - 0.06], [x0, y1, h - 0.04]),
        ([x1, y0, zw - 0.06], [hw, y1, h - 0.04]),
    ] {
        b.cuboid(Body, lo, hi);
        b.cuboid(Top, [lo[0], lo[1], h - 0.04], [hi[0], hi[1], h]);
    }
    // The water just under the rim, corner headrests, bubbles over the jets.
    b.cuboid(Interior, [x0, y0, zw - 0.05], [x1, y1, zw - 0.005]);
    b.cuboid(Water, [x0, y0, zw], [x1, y1, zw + 0.01]);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - corner), yc + sy * (hd - corner));
            b.ellipsoid(
                Cushion,
                [x, y, zw + 0.02],
                [0.5 * corner, 0.5 * corner, 0.025],
            );
        }
    }
    for (fx, fy) in [
        (0.0, 0.0),
        (-0.3, 0.25),
        (0.3, -0.25),
        (0.25, 0.3),
        (-0.25, -0.3),
    ] {
        let (x, y) = (fx * (x1 - x0), yc + fy * (y1 - y0));
        for k in 0..4 {
            let a = k as f64 * 1.57 + fx;
            b.ellipsoid(
                Canvas,
                [x + 0.05 * a.cos(), y + 0.05 * a.sin(), zw + 0.01],
                [0.03, 0.03, 0.012],
            );
        }
    }
    // The step at the front.
    let sw = 0.4 * hw;
    b.cuboid(Frame, [-sw, yc + hd, 0.0], [sw, hd0, 0.45 * h]);
    b.cuboid(
        Top,
        [-sw - 0.01, yc + hd + 0.01, 0.45 * h],
        [sw + 0.01, hd0, 0.45 * h + 0.03],
    );
}
