//! Layouts of the other archetypes: plants, screens and boards, appliances, simple solids,
//! vehicles, figures and outdoor structures. The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{rot_z, IDENTITY};
use super::Mount;
use std::f64::consts::{PI, TAU};

pub fn solid_box(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lid = (0.08 * h).min(0.05);
    b.cuboid(
        Body,
        [-hw + 0.005, -hd + 0.005, 0.0],
        [hw - 0.005, hd - 0.005, h - lid],
    );
    b.cuboid(Top, [-hw, -hd, h - lid], [hw, hd, h]);
}

/// Foliage blobs of horizontal radius `r` and vertical radius `rz`, centres spread by a golden
/// angle spiral between heights `z0` and `z1`, kept inside the size box.
fn blobs(b: &mut Builder, n: usize, r: f64, rz: f64, z0: f64, z1: f64, spread: f64) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (r, rz) = (r.min(hw.min(hd)), rz.min(h / 2.0));
    for i in 0..n {
        let t = if n > 1 {
            i as f64 / (n - 1) as f64
        } else {
            0.5
        };
        let a = i as f64 * 2.399_963;
        let rho = spread * (0.45 + 0.55 * (0.5 * PI * t).sin());
        let x = (rho * a.cos() * (hw - r)).clamp(-(hw - r), hw - r);
        let y = (rho * a.sin() * (hd - r)).clamp(-(hd - r), hd - r);
        let z = (z0 + (z1 - z0) * t).clamp(rz, h - rz);
        let k = 0.85 + 0.15 * ((i * 7) % 5) as f64 / 4.0;
        b.ellipsoid_rot(
            Foliage,
            i as u32,
            [x, y, z],
            [r * k, r * k * 0.95, rz * k],
            rot_z(a),
        );
    }
}

pub fn plant(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let ph = (0.3 * h).min(0.35);
    let (rx, ry) = (0.72 * hw, 0.72 * hd);
    b.frustum(Pot, [0.0, 0.0, 0.0], 0.75 * rx, 0.75 * ry, 1.0 / 0.75, ph);
    b.frustum(Soil, [0.0, 0.0, ph], 0.95 * rx, 0.95 * ry, 1.0, 0.005);
    b.cylinder(Trunk, [0.0, 0.0, ph], 0.015, 0.6 * (h - ph));
    // Leaf clusters: flattened blobs fanning out as they rise, a crown on top.
    let r = 0.42 * hw.min(hd);
    let rz = (0.1 * (h - ph)).max(0.55 * r);
    blobs(b, 16, r, rz, ph + 0.6 * rz, h - rz, 1.0);
    b.ellipsoid(Foliage, [0.0, 0.0, h - rz], [0.7 * r, 0.7 * r, rz]);
}

pub fn tree(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let m = hw.min(hd);
    b.frustum(
        Trunk,
        [0.0, 0.0, 0.0],
        (0.1 * m).min(0.3),
        (0.1 * m).min(0.3),
        0.6,
        0.6 * h,
    );
    b.ellipsoid(
        Foliage,
        [0.0, 0.0, 0.68 * h],
        [0.75 * hw, 0.75 * hd, 0.3 * h],
    );
    blobs(b, 12, 0.45 * m, 0.17 * h, 0.45 * h, 0.95 * h, 1.0);
}

pub fn bush(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.ellipsoid(Foliage, [0.0, 0.0, h / 2.0], [hw, hd, h / 2.0]);
    let n = ((b.w / b.d.min(b.h)).round() as usize).clamp(1, 6) * 4;
    blobs(
        b,
        n,
        0.55 * hd.min(h / 2.0),
        0.3 * h,
        0.3 * h,
        0.75 * h,
        1.0,
    );
}

pub fn conifer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cylinder(Trunk, [0.0, 0.0, 0.0], 0.06 * hw.min(hd) + 0.02, 0.2 * h);
    let tiers = 4;
    for i in 0..tiers {
        let f = 1.0 - 0.2 * i as f64;
        let z = 0.12 * h + i as f64 * 0.2 * h;
        b.frustum(
            Foliage,
            [0.0, 0.0, z],
            f * hw,
            f * hd,
            0.05,
            (0.38 * h).min(h - z - 0.05 * h),
        );
    }
    for k in 0..14 {
        let t = k as f64 / 14.0;
        let a = k as f64 * 2.4;
        let z = 0.2 * h + 0.6 * h * t;
        let f = 0.85 * (1.0 - 0.8 * t);
        b.ellipsoid_rot(
            Books,
            k,
            [f * hw * a.cos(), f * hd * a.sin(), z],
            [0.035, 0.035, 0.035],
            IDENTITY,
        );
    }
    b.ellipsoid(Light, [0.0, 0.0, h - 0.05 * h], [0.05, 0.05, 0.05 * h]);
}

/// A flat screen: standing, on a foot and a neck; hung on a wall, the panel alone over its
/// whole box, its back to the wall.
pub fn screen(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pd = (0.5 * b.d).min(0.06);
    let (zp, y0) = if b.mount == Mount::Stand {
        let zp = if h / b.w > 0.7 { 0.3 * h } else { 0.1 * h };
        let y0 = -0.5 * pd;
        b.cuboid(Metal, [-0.22 * b.w, -hd, 0.0], [0.22 * b.w, hd, 0.015]);
        b.cuboid(
            Metal,
            [-0.04 * b.w, y0 - 0.015, 0.015],
            [0.04 * b.w, y0, zp + 0.1 * h],
        );
        (zp, y0)
    } else {
        (0.0, -0.5 * pd)
    };
    b.cuboid(Body, [-hw, y0, zp], [hw, y0 + pd, h]);
    let bezel = (0.015 * b.w).max(0.01);
    b.cuboid(
        Screen,
        [-hw + bezel, y0 + pd, zp + bezel],
        [hw - bezel, y0 + pd + 0.003, h - bezel],
    );
}

/// A panel on two posts with feet: the surface (`role`) faces +y from `z0` up.
fn panel(b: &mut Builder, role: Role, z0: f64) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let post = 0.035;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - post / 2.0);
        b.cuboid(
            Frame,
            [x - post / 2.0, -hd, 0.0],
            [x + post / 2.0, hd, 0.03],
        );
        b.cuboid(
            Frame,
            [x - post / 2.0, -post / 2.0, 0.0],
            [x + post / 2.0, post / 2.0, h],
        );
    }
    let t = (0.4 * b.d).min(0.03);
    let fw = 0.03;
    b.cuboid(Frame, [-hw + post, -t / 2.0, z0], [hw - post, t / 2.0, h]);
    let (x0, x1, z1) = (-hw + post + fw, hw - post - fw, h - fw);
    b.cuboid(role, [x0, t / 2.0, z0 + fw], [x1, t / 2.0 + 0.003, z1]);
}

/// A board: standing, a panel on two posts with feet; hung on a wall, the framed panel alone
/// over its whole box with a ledge (a pen or chalk tray) along its foot, nothing below it.
pub fn board(b: &mut Builder) {
    if b.mount != Mount::Stand {
        return wall_panel(b, Canvas);
    }
    let z0 = if b.h > 1.5 { 0.35 * b.h } else { 0.1 * b.h };
    panel(b, Canvas, z0);
}

/// A panel hung flat on a wall (its back at −y): a frame over the whole box, the surface
/// (`role`) inside it, and a ledge along its foot standing out from the face.
fn wall_panel(b: &mut Builder, role: Role) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.4 * b.d).clamp(0.005, 0.025);
    let fw = (0.03 * b.w.min(h)).clamp(0.015, 0.035);
    let ledge = (0.04 * h).clamp(0.02, 0.05);
    b.cuboid(Frame, [-hw, -hd, ledge], [hw, -hd + t, h]);
    b.cuboid(
        role,
        [-hw + fw, -hd + t, ledge + fw],
        [hw - fw, -hd + t + 0.003, h - fw],
    );
    // The ledge: a shelf as deep as the box, running most of the panel's width.
    b.cuboid(Metal, [-0.9 * hw, -hd, 0.0], [0.9 * hw, hd, ledge]);
}

pub fn chalkboard(b: &mut Builder) {
    board(b);
}

/// A picture hung on a wall: a frame over its whole box with the canvas and its subject in
/// front, its back against the wall (-y); no posts or feet, since it hangs.
pub fn painting(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.8 * b.d).clamp(0.005, 0.04);
    let fw = (0.06 * b.w.min(h)).clamp(0.015, 0.06);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + t, h]);
    let y = -hd + t;
    let (x0, x1, z0, z1) = (-hw + fw, hw - fw, fw, h - fw);
    b.cuboid(Canvas, [x0, y, z0], [x1, y + 0.003, z1]);
    // Its subject: a few overlapping colour fields, laid out and coloured by its variant (a
    // landscape's ground and sky with two shapes, a horizon high or low, a still life's blocks).
    let (pw, ph) = (x1 - x0, z1 - z0);
    const SUBJECTS: [[(f64, f64, f64, f64); 4]; 4] = [
        [
            (0.0, 0.0, 1.0, 0.45),
            (0.0, 0.45, 1.0, 1.0),
            (0.2, 0.2, 0.55, 0.7),
            (0.6, 0.1, 0.85, 0.5),
        ],
        [
            (0.0, 0.0, 1.0, 0.7),
            (0.0, 0.7, 1.0, 1.0),
            (0.55, 0.6, 0.8, 0.85),
            (0.1, 0.15, 0.45, 0.4),
        ],
        [
            (0.0, 0.0, 1.0, 0.25),
            (0.0, 0.25, 1.0, 1.0),
            (0.1, 0.25, 0.3, 0.8),
            (0.4, 0.25, 0.9, 0.55),
        ],
        [
            (0.0, 0.0, 1.0, 1.0),
            (0.1, 0.1, 0.5, 0.9),
            (0.5, 0.3, 0.9, 0.7),
            (0.3, 0.6, 0.7, 0.85),
        ],
    ];
    let v = b.variant as usize % SUBJECTS.len();
    for (k, (u0, v0, u1, v1)) in SUBJECTS[v].iter().enumerate() {
        let yk = y + 0.003 + 0.002 * k as f64;
        b.cuboid_v(
            Books,
            [3, 1, 0, 5][k] + 2 * v as u32,
            [x0 + u0 * pw, yk, z0 + v0 * ph],
            [x0 + u1 * pw, yk + 0.002, z0 + v1 * ph],
        );
    }
}

pub fn mirror(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.5 * b.d).min(0.03);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + t, h]);
    b.cuboid(
        Canvas,
        [-hw + 0.04, -hd + t, 0.04],
        [hw - 0.04, -hd + t + 0.003, h - 0.04],
    );
    super::mirrors::sheen(
        b,
        [0.0, -hd + t + 0.003, 0.5 * h],
        hw - 0.04,
        0.5 * h - 0.04,
    );
    if b.mount == Mount::Stand {
        // the foot it stands on (hung on a wall, it needs none)
        b.cuboid(Frame, [-0.1 * b.w, -hd, 0.0], [0.1 * b.w, hd, 0.02]);
    }
}

pub fn cone(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, 0.03]);
    let (r0, top) = (0.8, 0.12);
    let seg = [(0.03, 0.45, Body), (0.45, 0.62, Canvas), (0.62, 1.0, Body)];
    for (f0, f1, role) in seg {
        let k0 = r0 * (1.0 - (1.0 - top) * f0);
        let k1 = r0 * (1.0 - (1.0 - top) * f1);
        b.frustum(
            role,
            [0.0, 0.0, f0 * h],
            k0 * hw,
            k0 * hd,
            k1 / k0,
            (f1 - f0) * h,
        );
    }
}

pub fn vehicle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.22 * h).min(0.2 * b.d);
    let tw = (0.12 * b.w).min(0.25);
    let zb = 0.6 * h;
    // Windows stand proud of the cabin by more than a surfel's jitter, so no body shows through.
    let g = (0.01 * b.d).clamp(0.012, 0.03);
    b.cuboid(Body, [-hw + 0.02, -hd, 0.45 * r], [hw - 0.02, hd, zb]);
    let (c0, c1) = (-0.55 * hd, 0.3 * hd);
    b.cuboid(Body, [-0.88 * hw, c0, zb], [0.88 * hw, c1, h]);
    b.cuboid(
        Glass,
        [-0.8 * hw, c1, zb + 0.05 * h],
        [0.8 * hw, c1 + g, h - 0.05 * h],
    );
    b.cuboid(
        Glass,
        [-0.8 * hw, c0 - g, zb + 0.05 * h],
        [0.8 * hw, c0, h - 0.05 * h],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.88 * hw;
        let (xa, xb) = if sx < 0.0 { (x - g, x) } else { (x, x + g) };
        b.cuboid(
            Glass,
            [xa, c0 + 0.06, zb + 0.05 * h],
            [xb, c1 - 0.06, h - 0.05 * h],
        );
        for y in [-0.62 * hd, 0.62 * hd] {
            let xo = sx * hw;
            let xi = sx * (hw - tw);
            b.rod(Tyre, [xi, y, r], [xo, y, r], r);
            b.rod(Metal, [xo - sx * 0.004, y, r], [xo, y, r], 0.6 * r);
        }
        b.cuboid(
            Light,
            [sx * 0.75 * hw - 0.1, hd - 0.005, 0.8 * zb],
            [sx * 0.75 * hw + 0.1, hd, 0.9 * zb],
        );
        b.cuboid_v(
            Books,
            0,
            [sx * 0.75 * hw - 0.1, -hd, 0.8 * zb],
            [sx * 0.75 * hw + 0.1, -hd + 0.005, 0.9 * zb],
        );
    }
}

/// A hull with thwarts; a boat taller than it is wide (a sailboat) is a low hull with a mast
/// and a triangular sail reaching back from it.
pub fn boat(b: &mut Builder) {
    let (hw, hd, full) = (b.w / 2.0, b.d / 2.0, b.h);
    let sails = full > b.w;
    let h = if sails { full.min(0.6 * b.w) } else { full };
    // The lower half of a hull lying along y, centred at the gunwale (the upper half falls
    // outside the box): a blunt stern at -y and a pointed bow at +y.
    hull(b, Body, hw, hd, h, h / hw);
    if sails {
        // A decked yacht: a thin deck of the hull's outline at the gunwale.
        hull(b, Top, 0.98 * hw, 0.99 * hd, h, (0.02 * h).max(0.01) / hw);
    }
    for y in [-0.4 * hd, 0.0, 0.4 * hd] {
        b.cuboid(
            Frame,
            [-0.85 * hw, y - 0.1, 0.6 * h],
            [0.85 * hw, y + 0.1, 0.6 * h + 0.03],
        );
    }
    if sails {
        let mast_y = 0.2 * hd;
        let r = (0.02 * full).min(0.2 * hw);
        b.cylinder(Frame, [0.0, mast_y, 0.3 * h], r, full - 0.3 * h);
        // The sail: strips from the boom up the mast, each shorter towards the head.
        let (z0, z1) = (h + 0.1 * (full - h), full - 0.02 * full);
        let foot = mast_y + 0.85 * hd;
        let n = 16;
        for i in 0..n {
            let (t0, t1) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
            let reach = foot * (1.0 - t0);
            b.cuboid(
                Canvas,
                [-0.01, mast_y - reach, z0 + (z1 - z0) * t0],
                [0.01, mast_y - r, z0 + (z1 - z0) * t1],
            );
        }
        b.rod(Frame, [0.0, mast_y, z0], [0.0, mast_y - foot, z0], 0.7 * r);
    }
}

/// A spindle along y with its centre line at `(0, 0, z)`: half width `hw`, half length `hd`, a
/// blunt end towards -y and a pointed one towards +y; its height is `ay` times its width.
fn hull(b: &mut Builder, role: super::materials::Role, hw: f64, hd: f64, z: f64, ay: f64) {
    let n = 32;
    let profile: Vec<[f64; 2]> = (0..=n)
        .map(|k| {
            let s = 2.0 * k as f64 / n as f64 - 1.0;
            let r = if s < 0.0 {
                (1.0 - s.powi(4)).max(0.0).sqrt()
            } else {
                1.0 - s * s
            };
            [hw * r, (s + 1.0) * hd]
        })
        .collect();
    b.revolved(
        role,
        0,
        [0.0, -hd, z],
        super::archetypes::frame_along([0.0, 1.0, 0.0]),
        ay,
        profile,
    );
}

/// A ring about the x axis: a wheel's tyre at `(x, y, z)`.
fn wheel(b: &mut Builder, c: [f64; 3], r: f64, t: f64, width: f64) {
    let profile = vec![
        [r - t, -width],
        [r, -width],
        [r, width],
        [r - t, width],
        [r - t, -width],
    ];
    b.revolved(Tyre, 0, c, frame_along([1.0, 0.0, 0.0]), 1.0, profile);
    for k in 0..6 {
        let a = k as f64 / 6.0 * TAU;
        b.rod(
            Metal,
            c,
            [c[0], c[1] + (r - t) * a.cos(), c[2] + (r - t) * a.sin()],
            0.006,
        );
    }
}

pub fn bicycle(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let motor = b.w > 0.7;
    let r = (0.36 * h).min(0.28 * b.d);
    let (yf, yr) = (hd - r, -hd + r);
    let t = if motor { 0.35 * r } else { 0.1 * r };
    let tw = if motor { 0.06 } else { 0.02 };
    wheel(b, [0.0, yf, r], r, t, tw);
    wheel(b, [0.0, yr, r], r, t, tw);
    let seat = [0.0, yr + 0.35 * (yf - yr), 0.85 * h];
    let bar = [0.0, yf - 0.1 * r, 0.95 * h];
    let crank = [0.0, yr + 0.45 * (yf - yr), r];
    for (a, c) in [
        (crank, seat),
        (crank, bar),
        (seat, bar),
        ([0.0, yr, r], crank),
        ([0.0, yr, r], seat),
        ([0.0, yf, r], bar),
    ] {
        b.rod(Frame, a, c, 0.018);
    }
    b.rod(
        Metal,
        [-0.9 * hw.min(0.3), bar[1], bar[2]],
        [0.9 * hw.min(0.3), bar[1], bar[2]],
        0.014,
    );
    b.ellipsoid(
        Seat,
        [0.0, seat[1] - 0.03, seat[2] + 0.02],
        [0.08, 0.14, 0.03],
    );
    if motor {
        b.ellipsoid(
            Frame,
            [0.0, 0.1 * hd, 0.65 * h],
            [0.22, 0.35 * hd, 0.12 * h],
        );
        b.cuboid(Metal, [-0.15, yr + r, 0.25 * h], [0.15, yf - r, 0.5 * h]);
    }
}

pub fn figure(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lr = (0.06 * h).min(0.35 * hw).min(0.8 * hd);
    for sx in [-1.0, 1.0] {
        b.frustum(Body, [sx * 0.35 * hw, 0.0, 0.0], lr, lr, 0.9, 0.48 * h);
    }
    let tw = 0.7 * hw;
    b.ellipsoid(
        Body,
        [0.0, 0.0, 0.65 * h],
        [tw, (0.7 * hd).min(tw), 0.2 * h],
    );
    let ar = 0.7 * lr;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - ar);
        b.rod(
            Body,
            [sx * tw * 0.85, 0.0, 0.78 * h],
            [x, 0.1 * hd, 0.48 * h],
            ar,
        );
    }
    b.rod(
        Body,
        [0.0, 0.0, 0.8 * h],
        [0.0, 0.0, 0.87 * h],
        0.3 * lr + 0.02,
    );
    let hr = (0.065 * h).min(0.8 * hw);
    b.ellipsoid(
        Skin,
        [0.0, 0.0, h - hr * 1.2],
        [hr, (hr * 1.1).min(hd), hr * 1.2],
    );
}

pub fn umbrella(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Metal, [0.0, 0.0, 0.0], 0.15 * hw, 0.15 * hd, 0.8, 0.06);
    b.cylinder(Frame, [0.0, 0.0, 0.06], 0.02, h - 0.1);
    let ch = 0.22 * h;
    b.frustum(Shade, [0.0, 0.0, h - ch - 0.05], hw, hd, 0.02, ch);
    b.ellipsoid(Frame, [0.0, 0.0, h - 0.04], [0.03, 0.03, 0.04]);
}

pub fn pavilion(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.frustum(Body, [0.0, 0.0, 0.0], hw, hd, 1.0, 0.12);
    let posts = 6;
    for k in 0..posts {
        let a = (k as f64 + 0.5) / posts as f64 * TAU;
        b.cylinder(
            Body,
            [0.88 * hw * a.cos(), 0.88 * hd * a.sin(), 0.12],
            0.06,
            0.7 * h - 0.12,
        );
    }
    b.frustum(Body, [0.0, 0.0, 0.7 * h], hw, hd, 1.0, 0.08);
    b.frustum(
        Top,
        [0.0, 0.0, 0.7 * h + 0.08],
        hw,
        hd,
        0.03,
        0.3 * h - 0.08,
    );
}

pub fn chest(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let lid = 0.3 * h;
    b.cuboid(
        Body,
        [-hw + 0.01, -hd + 0.01, 0.0],
        [hw - 0.01, hd - 0.01, h - lid],
    );
    b.cuboid(Top, [-hw, -hd, h - lid], [hw, hd, h]);
    for x in [-0.6 * hw, 0.6 * hw] {
        b.cuboid(Metal, [x - 0.025, -hd, 0.0], [x + 0.025, hd, h]);
    }
    b.cuboid(
        Handle,
        [-0.05, hd - 0.005, h - lid - 0.08],
        [0.05, hd, h - lid + 0.03],
    );
}

pub fn fence(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.6 * b.d).min(0.04);
    let posts = ((b.w / 1.2).ceil() as usize).max(1) + 1;
    for i in 0..posts {
        let x = -hw + 0.04 + i as f64 * (b.w - 0.08) / (posts - 1) as f64;
        b.cuboid(Frame, [x - 0.04, -hd, 0.0], [x + 0.04, hd, h]);
    }
    for z in [0.25 * h, 0.75 * h] {
        b.cuboid(Frame, [-hw, -hd, z - 0.03], [hw, -hd + 0.02, z + 0.03]);
    }
    let n = (b.w / 0.12) as usize;
    for i in 0..n {
        let x = -hw + (i as f64 + 0.5) * b.w / n as f64;
        b.cuboid(
            Frame,
            [x - 0.035, -hd + 0.02, 0.05],
            [x + 0.035, -hd + 0.02 + t * 0.5, h - 0.06],
        );
        b.cuboid(
            Frame,
            [x - 0.025, -hd + 0.02, h - 0.06],
            [x + 0.025, -hd + 0.02 + t * 0.5, h],
        );
    }
}
