//! Layouts of sports and waterside things: a football goal with its net, a court net between
//! two posts, a diving board on its stand and a marker buoy. The front faces +y, z up, the
//! bottom face's centre at the origin.
use super::archetypes::Builder;
use super::materials::Role::{self, *};
use super::parts::V3;

/// A net over the quadrilateral `p0 p1 p2 p3` (p0→p1 and p3→p2 are its two long edges): cords
/// of radius `r` about `mesh` apart both ways.
fn mesh(b: &mut Builder, role: Role, q: [V3; 4], mesh: f64, r: f64) {
    let lerp = |a: V3, c: V3, t: f64| [0, 1, 2].map(|i| a[i] + t * (c[i] - a[i]));
    let len = |a: V3, c: V3| (0..3).map(|i| (c[i] - a[i]).powi(2)).sum::<f64>().sqrt();
    let across = (len(q[0], q[1]).max(len(q[3], q[2])) / mesh)
        .ceil()
        .max(1.0) as usize;
    let along = (len(q[0], q[3]).max(len(q[1], q[2])) / mesh)
        .ceil()
        .max(1.0) as usize;
    for i in 0..=across {
        let t = i as f64 / across as f64;
        let (a, c) = (lerp(q[0], q[1], t), lerp(q[3], q[2], t));
        if len(a, c) > r {
            b.rod(role, a, c, r);
        }
    }
    for j in 0..=along {
        let t = j as f64 / along as f64;
        let (a, c) = (lerp(q[0], q[3], t), lerp(q[1], q[2], t));
        if len(a, c) > r {
            b.rod(role, a, c, r);
        }
    }
}

/// A football goal: two posts and a crossbar across the front, the net running back from the
/// crossbar and sloping to a ground frame at the back.
pub fn goal(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.03 * h).clamp(0.02, 0.06);
    let yf = hd - r;
    let x = hw - r;
    for sx in [-1.0, 1.0] {
        b.rod(Frame, [sx * x, yf, 0.0], [sx * x, yf, h - 2.0 * r], r);
    }
    b.rod(Frame, [-hw, yf, h - r], [hw, yf, h - r], r);
    // The net's frame: a roof from the crossbar back, then a slope to the ground at the back.
    let (ym, yb) = (yf - 0.3 * b.d, -hd + 0.6 * r);
    let zt = h - r;
    let g = 0.6 * r;
    b.rod(Metal, [-x, yb, g], [x, yb, g], 0.6 * r);
    for sx in [-1.0, 1.0] {
        let xs = sx * x;
        b.rod(Metal, [xs, yf, g], [xs, yb, g], 0.6 * r);
        b.rod(Metal, [xs, yf, zt], [xs, ym, zt], 0.6 * r);
        b.rod(Metal, [xs, ym, zt], [xs, yb, g], 0.6 * r);
    }
    let (cell, cord) = (
        (0.12 * h).clamp(0.08, 0.25),
        (0.004 * h).clamp(0.004, 0.012),
    );
    let top = |xs: f64, y: f64| [xs, y, zt];
    let low = |xs: f64, y: f64| [xs, y, g];
    mesh(
        b,
        Canvas,
        [top(-x, yf), top(x, yf), top(x, ym), top(-x, ym)],
        cell,
        cord,
    );
    mesh(
        b,
        Canvas,
        [top(-x, ym), top(x, ym), low(x, yb), low(-x, yb)],
        cell,
        cord,
    );
    for sx in [-1.0, 1.0] {
        let xs = sx * x;
        mesh(
            b,
            Canvas,
            [top(xs, yf), top(xs, ym), low(xs, yb), low(xs, yf)],
            cell,
            cord,
        );
    }
}

/// A court net: a post at each end and a net hung between them under a white tape; a tall net
/// (volleyball, badminton) hangs in a band high up, a low one (tennis) reaches the ground.
pub fn sports_net(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.02 * h).clamp(0.03, 0.05).min(0.5 * hd);
    let x = hw - 2.0 * r;
    for sx in [-1.0, 1.0] {
        let xs = sx * x;
        b.cuboid(Metal, [xs - r, -r, 0.0], [xs + r, r, h]);
        // A foot plate across the post's base.
        b.cuboid(Metal, [xs - 2.0 * r, -hd, 0.0], [xs + 2.0 * r, hd, 0.02]);
    }
    let tape = (0.05 * h).clamp(0.04, 0.07);
    let top = h - 0.02;
    let bottom = if h > 1.6 { top - 1.0 } else { 0.03 };
    b.cuboid(Canvas, [-x + r, -0.012, top - tape], [x - r, 0.012, top]);
    let (cell, cord) = (0.1, 0.005);
    mesh(
        b,
        Body,
        [
            [-x + r, 0.0, top - tape],
            [x - r, 0.0, top - tape],
            [x - r, 0.0, bottom],
            [-x + r, 0.0, bottom],
        ],
        cell,
        cord,
    );
    if h > 1.6 {
        b.cuboid(
            Canvas,
            [-x + r, -0.008, bottom - 0.01],
            [x - r, 0.008, bottom + 0.01],
        );
    }
}

/// A springboard: a long board running forward (+y) from a pedestal at the back over a
/// fulcrum, its front end free over the water.
pub fn diving_board(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.05 * h).clamp(0.04, 0.08);
    let zb = h - t;
    b.cuboid(Top, [-0.85 * hw, -hd, zb], [0.85 * hw, hd, h]);
    // The stand at the back, and the fulcrum a third along.
    let back = (0.18 * b.d).min(0.6);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, -hd + back, zb]);
    let yf = -hd + 0.4 * b.d;
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [sx * 0.7 * hw - 0.04, yf - 0.05, 0.0],
            [sx * 0.7 * hw + 0.04, yf + 0.05, zb],
        );
    }
    b.cuboid(
        Metal,
        [-0.8 * hw, yf - 0.06, zb - 0.06],
        [0.8 * hw, yf + 0.06, zb],
    );
    b.cuboid(
        Metal,
        [-0.8 * hw, -hd + back, 0.0],
        [0.8 * hw, yf + 0.06, 0.05],
    );
}

/// A marker buoy: a round float with a white band, a narrower body above it and a small light
/// on a cage at the top.
pub fn buoy(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let zf = 0.4 * h;
    b.ellipsoid(Body, [0.0, 0.0, 0.5 * zf], [r, r, 0.5 * zf]);
    b.cylinder(Canvas, [0.0, 0.0, 0.4 * zf], 0.97 * r, 0.2 * zf);
    let zt = 0.78 * h;
    b.frustum(
        Body,
        [0.0, 0.0, 0.8 * zf],
        0.55 * r,
        0.55 * r,
        0.8,
        zt - 0.8 * zf,
    );
    b.cylinder(Canvas, [0.0, 0.0, 0.5 * (zf + zt)], 0.5 * r, 0.1 * h);
    let rc = 0.25 * r;
    let zl = h - 0.12 * h;
    for k in 0..3 {
        let a = k as f64 * std::f64::consts::TAU / 3.0;
        let (x, y) = (rc * a.cos(), rc * a.sin());
        b.rod(Metal, [x, y, zt], [x, y, zl], 0.02 * r.max(0.5));
    }
    b.ellipsoid(
        Light,
        [0.0, 0.0, zl + 0.06 * h],
        [0.2 * r, 0.2 * r, 0.06 * h],
    );
}

/// A basketball hoop on a pole: a weighted foot at the back, the pole, an arm reaching forward
/// to a white backboard facing +y, an orange rim in front of it with a net below.
pub fn hoop(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pole = (0.04 * hw.min(hd) + 0.04).min(0.08);
    let yp = -hd + 2.0 * pole;
    b.cuboid(
        Body,
        [-hw.min(0.4), -hd, 0.0],
        [hw.min(0.4), -hd + 0.5 * b.d, 0.12],
    );
    let bh = (0.3 * h).min(1.05);
    let zb = h - bh;
    b.cylinder(Metal, [0.0, yp, 0.12], pole, zb + 0.5 * bh - 0.12);
    // The backboard, 10 cm behind the rim's back.
    let rr = (0.2 * hw.min(0.5 * b.d)).clamp(0.1, 0.23);
    let yb = (hd - 2.0 * rr - 0.15).max(yp + 2.0 * pole);
    b.rod(
        Metal,
        [0.0, yp, zb + 0.5 * bh],
        [0.0, yb, zb + 0.5 * bh],
        0.7 * pole,
    );
    b.cuboid(Canvas, [-hw, yb, zb], [hw, yb + 0.04, h]);
    b.cuboid(
        Frame,
        [-0.3 * hw, yb + 0.04, zb + 0.15 * bh],
        [0.3 * hw, yb + 0.05, zb + 0.55 * bh],
    );
    let zr = zb + 0.15 * bh;
    let (cy, tube) = (yb + 0.05 + rr + 0.02, 0.012);
    let profile: Vec<[f64; 2]> = (0..=16)
        .map(|k| {
            let t = k as f64 / 16.0 * std::f64::consts::TAU;
            [rr + tube * t.cos(), tube + tube * t.sin()]
        })
        .collect();
    b.revolved(
        Top,
        0,
        [0.0, cy, zr - tube],
        super::parts::IDENTITY,
        1.0,
        profile,
    );
    b.rod(Top, [0.0, yb + 0.04, zr], [0.0, cy - rr, zr], tube);
    let net = vec![[0.0, 0.0], [0.6 * rr, 0.0], [rr, 0.4 * bh], [0.0, 0.4 * bh]];
    b.revolved(
        Cushion,
        0,
        [0.0, cy, zr - 0.4 * bh],
        super::parts::IDENTITY,
        1.0,
        net,
    );
}

/// A rowing machine: a long rail rising from a foot at the back to a flywheel housing at the
/// front (+y), a sliding seat on the rail, foot plates before the flywheel and a handle.
pub fn rower(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rail = (0.06 * h).clamp(0.03, 0.05);
    let (zb, zf) = (0.25 * h, 0.45 * h);
    let yf = hd - 0.45 * h;
    b.cuboid(Metal, [-0.8 * hw, -hd, 0.0], [0.8 * hw, -hd + 0.08, zb]);
    b.rod(Frame, [0.0, -hd + 0.04, zb], [0.0, yf, zf], rail);
    // The flywheel housing: a disc on its side, standing on a foot across the front.
    let r = (0.5 * h).min(0.45 * hd);
    b.revolved(
        Body,
        0,
        [-0.12 * hw, hd - r, h - r],
        super::parts::rot_y(std::f64::consts::FRAC_PI_2),
        1.0,
        vec![[0.0, 0.0], [r, 0.0], [r, 0.24 * hw], [0.0, 0.24 * hw]],
    );
    b.cuboid(
        Metal,
        [-0.8 * hw, hd - 2.0 * r, 0.0],
        [0.8 * hw, hd - 0.05, 0.05],
    );
    b.rod(Metal, [0.0, hd - r, 0.05], [0.0, hd - r, h - r], rail);
    // The seat a third along the rail, the foot plates before the flywheel.
    let t = 0.35;
    let (ys, zs) = (-hd + t * (yf + hd), zb + t * (zf - zb));
    b.cuboid(
        Seat,
        [-0.35 * hw, ys - 0.15, zs + rail],
        [0.35 * hw, ys + 0.15, zs + rail + 0.06],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Top,
            [sx * 0.15 * hw, yf - 0.35, zf - 0.02],
            [sx * 0.75 * hw, yf - 0.3, zf + 0.22 * h],
        );
    }
    b.rod(
        Handle,
        [-0.45 * hw, yf - 0.1, zf + 0.15 * h],
        [0.45 * hw, yf - 0.1, zf + 0.15 * h],
        0.015,
    );
}
