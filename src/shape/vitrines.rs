//! Layouts of glass cases that show what they hold behind see-through panes
//! ([`Role::Pane`](super::materials::Role::Pane)): a shop's display case with goods on its
//! shelves, an aquarium with water, fish and plants, a shower with a tray, a glass screen and a
//! head. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::{self, *};
use super::parts::{frustum_profile, rot_x, IDENTITY};
use std::f64::consts::FRAC_PI_2;

/// Thin frame bars along the twelve edges of the box `lo..hi`.
pub(super) fn edges(b: &mut Builder, role: Role, lo: [f64; 3], hi: [f64; 3], t: f64) {
    for sy in [lo[1], hi[1] - t] {
        for sz in [lo[2], hi[2] - t] {
            b.cuboid(role, [lo[0], sy, sz], [hi[0], sy + t, sz + t]);
        }
    }
    for sx in [lo[0], hi[0] - t] {
        for sz in [lo[2], hi[2] - t] {
            b.cuboid(role, [sx, lo[1], sz], [sx + t, hi[1], sz + t]);
        }
        for sy in [lo[1], hi[1] - t] {
            b.cuboid(role, [sx, sy, lo[2]], [sx + t, sy + t, hi[2]]);
        }
    }
}

/// A row of goods on a shelf at height `z` between `x0` and `x1`, at depth `y`: blocks and
/// rounds of the goods palette, alternating, about `s` across.
pub(super) fn goods(b: &mut Builder, x: [f64; 2], y: f64, z: f64, s: f64, v: &mut u32) {
    let n = ((x[1] - x[0]) / (1.4 * s)).floor().max(1.0) as usize;
    let pitch = (x[1] - x[0]) / n as f64;
    for i in 0..n {
        let xc = x[0] + (i as f64 + 0.5) * pitch;
        if (i + *v as usize).is_multiple_of(2) {
            let profile = frustum_profile(0.5 * s, 0.47 * s, 0.55 * s);
            b.revolved(Books, *v, [xc, y, z], IDENTITY, 1.0, profile);
        } else {
            b.cuboid_v(
                Books,
                *v,
                [xc - 0.45 * s, y - 0.4 * s, z],
                [xc + 0.45 * s, y + 0.4 * s, z + 0.7 * s],
            );
        }
        *v += 1;
    }
}

/// A shop's display case (pastries, jewellery, deli): a base cabinet and a glass box above it
/// whose front slopes back towards the top, with a metal frame, and goods on the base and on
/// glass shelves, seen through the panes.
pub fn display_case(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = if h > 1.4 { 0.35 * h } else { 0.5 * h };
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, zb]);
    b.cuboid(
        Door,
        [-hw + 0.02, hd - 0.002, 0.05],
        [hw - 0.02, hd, zb - 0.04],
    );
    let f = 0.02;
    // The front's depth at height z: full at the base, `slope` less at the top.
    let slope = 0.35 * b.d;
    let front = |z: f64| hd - slope * ((z - zb) / (h - zb)).clamp(0.0, 1.0);
    let yt = front(h);
    b.cuboid(Interior, [-hw + f, -hd, zb], [hw - f, -hd + 0.01, h - f]);
    for x in [-hw, hw - f] {
        b.cuboid(Frame, [x, -hd, zb], [x + f, -hd + f, h]);
        b.cuboid(Frame, [x, -hd, h - f], [x + f, yt, h]);
        b.cuboid(Frame, [x, -hd, zb], [x + f, hd, zb + f]);
        b.rod(
            Frame,
            [x + f / 2.0, hd - f / 2.0, zb],
            [x + f / 2.0, yt - f / 2.0, h],
            f / 2.0,
        );
    }
    b.cuboid(Frame, [-hw, yt - f, h - f], [hw, yt, h]);
    b.cuboid(Frame, [-hw, -hd, h - f], [hw, -hd + f, h]);
    // Goods on the floor of the case and on shelves above it, kept behind the sloping front.
    let s = (0.1 * (h - zb)).clamp(0.05, 0.1);
    let levels = (((h - zb) / (3.0 * s)).floor() as usize).clamp(1, 4);
    let pitch = (h - zb - f) / levels as f64;
    let mut v = 0;
    let mut draws = super::goods::Draws::new(levels as u64 * 7919 + (b.w * 1000.0) as u64);
    for k in 0..levels {
        let z = zb + k as f64 * pitch;
        let yf = front(z + pitch) - 0.02;
        if k > 0 {
            b.cuboid(Pane, [-hw + f, -hd + 0.01, z - 0.008], [hw - f, yf, z]);
        }
        let depth = yf + hd - 0.01;
        let rows = if depth > 0.45 { 2 } else { 1 };
        for r in 0..rows {
            let y = -hd + 0.01 + (r as f64 + 0.5) * depth / rows as f64;
            match b.goods {
                // what the case shows (a bookshop's books, a museum's artefacts)
                Some(g) => {
                    let bay = super::goods::Bay {
                        x0: -hw + f + 0.02,
                        x1: hw - f - 0.02,
                        y0: y - 0.45 * depth / rows as f64,
                        depth: 0.9 * depth / rows as f64,
                        z,
                        room: (pitch - 0.03).min(3.0 * s),
                    };
                    super::goods::fill(b, g, bay, &mut draws);
                }
                None => goods(b, [-hw + f + 0.02, hw - f - 0.02], y, z, s, &mut v),
            }
        }
    }
    // The panes: a sloping front, a top, and sides stepping back with the front.
    let (dz, dy) = (h - zb, slope);
    let len = (dz * dz + dy * dy).sqrt();
    let c = [0.0, hd - 0.5 * dy, zb + 0.5 * dz];
    b.slab(Pane, c, [hw - f, 0.003, 0.5 * len], rot_x((dy / dz).atan()));
    b.cuboid(Pane, [-hw + f, -hd + f, h - 0.006], [hw - f, yt - f, h]);
    let steps = 6;
    for i in 0..steps {
        let z0 = zb + i as f64 * dz / steps as f64;
        let z1 = z0 + dz / steps as f64;
        let y1 = front(0.5 * (z0 + z1));
        b.cuboid(Pane, [-hw, -hd + f, z0], [-hw + 0.006, y1, z1]);
        b.cuboid(Pane, [hw - 0.006, -hd + f, z0], [hw, y1, z1]);
    }
}

/// An aquarium on its stand: a tank of water (a tinted back, a gravel floor, the surface) with
/// plants and fish behind glass, a dark hood on top.
pub fn aquarium(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zs = if h > 0.9 { 0.45 * h } else { 0.0 };
    if zs > 0.0 {
        b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, zs]);
        b.cuboid(Door, [-hw + 0.02, hd - 0.003, 0.04], [-0.01, hd, zs - 0.04]);
        b.cuboid(Door, [0.01, hd - 0.003, 0.04], [hw - 0.02, hd, zs - 0.04]);
    }
    let hood = 0.08 * (h - zs);
    let top = h - hood;
    b.cuboid(Top, [-hw, -hd, top], [hw, hd, h]);
    let f = 0.015;
    edges(b, Frame, [-hw, -hd, zs], [hw, hd, top], f);
    b.cuboid(Water, [-hw + f, -hd, zs], [hw - f, -hd + 0.01, top]);
    let gravel = zs + 0.05 * (top - zs);
    b.cuboid(Soil, [-hw + f, -hd + 0.01, zs], [hw - f, hd - f, gravel]);
    // Plants: tall blades rising from the gravel at the back.
    let th = top - gravel;
    for (k, x) in [-0.38, -0.3, 0.25, 0.34, -0.05].into_iter().enumerate() {
        let hgt = (0.5 + 0.1 * k as f64) * th;
        b.ellipsoid(
            Foliage,
            [x * b.w, -0.2 * b.d, gravel + 0.5 * hgt],
            [0.035 * b.w, 0.05 * b.d, 0.5 * hgt],
        );
    }
    // Fish: a body and a tail each, facing along x, at several depths.
    let fl = (0.09 * b.w).clamp(0.04, 0.1);
    let fish = [
        (-0.15, 0.1, 0.62),
        (0.1, -0.05, 0.45),
        (0.28, 0.15, 0.72),
        (-0.3, -0.1, 0.35),
        (0.0, 0.2, 0.82),
    ];
    for (k, (x, y, z)) in fish.into_iter().enumerate() {
        let c = [x * b.w, y * b.d, gravel + z * th];
        let dir = if k % 2 == 0 { 1.0 } else { -1.0 };
        b.ellipsoid_rot(
            Books,
            k as u32 + 2,
            c,
            [0.5 * fl, 0.18 * fl, 0.3 * fl],
            IDENTITY,
        );
        b.ellipsoid_rot(
            Books,
            k as u32 + 2,
            [c[0] - dir * 0.55 * fl, c[1], c[2]],
            [0.12 * fl, 0.05 * fl, 0.22 * fl],
            IDENTITY,
        );
    }
    // The water's surface just under the hood, and the glass.
    b.cuboid(
        Pane,
        [-hw + f, -hd + 0.01, top - 0.04],
        [hw - f, hd - f, top - 0.038],
    );
    b.cuboid(Pane, [-hw + f, hd - 0.006, zs], [hw - f, hd, top]);
    b.cuboid(Pane, [-hw, -hd + f, zs], [-hw + 0.006, hd - f, top]);
    b.cuboid(Pane, [hw - 0.006, -hd + f, zs], [hw, hd - f, top]);
}

/// A shower: a low tray, a tiled back and side wall, a glass screen on the open sides with a
/// metal frame and a door pull, a riser pipe with a round head and a mixer.
pub fn shower(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tray = 0.06;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, tray]);
    b.cuboid(Interior, [-0.04, -0.04, tray], [0.04, 0.04, tray + 0.002]);
    let t = 0.03;
    b.cuboid(Canvas, [-hw, -hd, tray], [hw, -hd + t, h]);
    b.cuboid(Canvas, [-hw, -hd + t, tray], [-hw + t, hd, h]);
    // Glass on the front and the right, framed along the top and the corner.
    let f = 0.02;
    b.cuboid(Pane, [-hw + t, hd - 0.008, tray], [hw - f, hd, h - f]);
    b.cuboid(Pane, [hw - 0.008, -hd + t, tray], [hw, hd - f, h - f]);
    b.cuboid(Metal, [-hw + t, hd - f, h - f], [hw, hd, h]);
    b.cuboid(Metal, [hw - f, -hd + t, h - f], [hw, hd, h]);
    b.cuboid(Metal, [hw - f, hd - f, tray], [hw, hd, h - f]);
    b.cuboid(Metal, [-hw + t, hd - f, tray], [-hw + t + f, hd, h - f]);
    b.rod(
        Handle,
        [0.1 * b.w, hd, 0.45 * h],
        [0.1 * b.w, hd, 0.6 * h],
        0.008,
    );
    // Riser, arm and head on the back wall; the mixer below.
    let y = -hd + t;
    let zh = 0.88 * h;
    b.rod(
        Metal,
        [0.0, y + 0.02, 0.45 * h],
        [0.0, y + 0.02, zh + 0.05],
        0.012,
    );
    b.rod(
        Metal,
        [0.0, y + 0.02, zh + 0.05],
        [0.0, y + 0.22, zh + 0.05],
        0.01,
    );
    b.revolved(
        Metal,
        0,
        [0.0, y + 0.25, zh + 0.01],
        IDENTITY,
        1.0,
        frustum_profile(0.13, 0.04, 0.04),
    );
    b.revolved(
        Handle,
        0,
        [0.0, y, 0.45 * h],
        rot_x(-FRAC_PI_2),
        1.0,
        frustum_profile(0.05, 0.04, 0.04),
    );
}

/// Rows of bottles (a body and a neck each, of the goods palette) on shelves from the back
/// plane `y[0]` to the front plane `y[1]`, in `[x0, x1]` from `z0` to `z1`.
fn bottle_shelves(b: &mut Builder, x: [f64; 2], y: [f64; 2], z: [f64; 2], v: &mut u32) {
    let yf = y[1];
    let shelves = (((z[1] - z[0]) / 0.3).floor() as usize).max(2);
    let pitch = (z[1] - z[0]) / shelves as f64;
    for k in 0..shelves {
        let z = z[0] + k as f64 * pitch;
        b.cuboid(Frame, [x[0], y[0], z - 0.01], [x[1], yf - 0.02, z]);
        let r = (0.15 * pitch).min(0.035);
        let n = ((x[1] - x[0]) / (2.6 * r)).floor().max(1.0) as usize;
        let step = (x[1] - x[0]) / n as f64;
        for i in 0..n {
            let xc = x[0] + (i as f64 + 0.5) * step;
            let y = yf - 0.03 - r;
            let body = 0.5 * pitch;
            b.revolved(
                Books,
                *v,
                [xc, y, z],
                IDENTITY,
                1.0,
                frustum_profile(r, r, body),
            );
            b.revolved(
                Books,
                *v,
                [xc, y, z + body],
                IDENTITY,
                1.0,
                frustum_profile(0.45 * r, 0.35 * r, 0.3 * pitch),
            );
            *v += 1;
        }
    }
}

/// A glass-door fridge (drinks, wine): a cabinet with a lit header and a see-through door on
/// bottles in rows, a long handle.
pub fn glass_fridge(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.03;
    let header = if h > 1.2 { 0.12 * h } else { 0.0 };
    // The body stops short of the back for the condenser coil (`backs.rs`).
    let back = -hd + super::laundry::BACK;
    b.cuboid(
        Interior,
        [-hw + 0.02, back, 0.0],
        [hw - 0.02, face - 0.03, 0.06],
    );
    b.cuboid(Body, [-hw, back, 0.06], [-hw + 0.04, face, h]);
    b.cuboid(Body, [hw - 0.04, back, 0.06], [hw, face, h]);
    b.cuboid(Body, [-hw, back, 0.06], [hw, back + 0.04, h]);
    b.cuboid(Body, [-hw, back, 0.06], [hw, face, 0.12]);
    b.cuboid(Body, [-hw, back, h - header - 0.04], [hw, face, h]);
    if header > 0.0 {
        b.cuboid(
            Light,
            [-hw + 0.03, face, h - header],
            [hw - 0.03, face + 0.005, h - 0.02],
        );
    }
    b.cuboid(
        Interior,
        [-hw + 0.04, back + 0.04, 0.12],
        [hw - 0.04, back + 0.05, h - header - 0.04],
    );
    let mut v = 0;
    bottle_shelves(
        b,
        [-hw + 0.05, hw - 0.05],
        [-hd + 0.05, face],
        [0.14, h - header - 0.06],
        &mut v,
    );
    // The door: a frame round a see-through pane, a handle up its right side.
    let (z0, z1) = (0.08, h - header - 0.02);
    edges_front(b, [-hw + 0.01, z0], [hw - 0.01, z1], face, 0.035);
    b.cuboid(
        Pane,
        [-hw + 0.04, face, z0 + 0.03],
        [hw - 0.04, face + 0.006, z1 - 0.03],
    );
    let x = -hw + 0.06;
    b.rod(
        Handle,
        [x, hd - 0.01, 0.4 * h],
        [x, hd - 0.01, 0.4 * h + 0.35 * (z1 - z0)],
        0.012,
    );
    super::backs::fridge_back(b);
}

/// A door frame on the front plane `y`: four bars of width `t` round `[x0, z0]..[x1, z1]`.
fn edges_front(b: &mut Builder, lo: [f64; 2], hi: [f64; 2], y: f64, t: f64) {
    b.cuboid(Door, [lo[0], y, lo[1]], [hi[0], y + 0.02, lo[1] + t]);
    b.cuboid(Door, [lo[0], y, hi[1] - t], [hi[0], y + 0.02, hi[1]]);
    b.cuboid(Door, [lo[0], y, lo[1]], [lo[0] + t, y + 0.02, hi[1]]);
    b.cuboid(Door, [hi[0] - t, y, lo[1]], [hi[0], y + 0.02, hi[1]]);
}

/// A vending machine: a window on goods in rows over a pick-up flap, a keypad and coin slot
/// column on the right, a lit header.
pub fn vending(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let face = hd - 0.03;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, -hd + 0.04, h]);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, face, 0.3 * h]);
    b.cuboid(Body, [-hw, -hd, 0.0], [-hw + 0.03, face, h]);
    b.cuboid(Body, [-hw, -hd, 0.9 * h], [hw, face, h]);
    let xc = hw - 0.28 * b.w;
    b.cuboid(Body, [xc, -hd, 0.0], [hw, face, h]);
    b.cuboid(
        Light,
        [-hw + 0.03, face, 0.91 * h],
        [hw - 0.03, face + 0.005, h - 0.02],
    );
    b.cuboid(
        Interior,
        [-hw + 0.03, -hd + 0.04, 0.3 * h],
        [xc, -hd + 0.05, 0.9 * h],
    );
    // Goods on spiral shelves behind the window.
    let rows = 5;
    let pitch = 0.6 * h / rows as f64;
    let mut v = 0;
    for k in 0..rows {
        let z = 0.3 * h + k as f64 * pitch;
        b.cuboid(
            Metal,
            [-hw + 0.03, -hd + 0.05, z],
            [xc, face - 0.02, z + 0.01],
        );
        goods(
            b,
            [-hw + 0.06, xc - 0.03],
            face - 0.12,
            z + 0.01,
            (0.5 * pitch).min(0.1),
            &mut v,
        );
    }
    b.cuboid(
        Pane,
        [-hw + 0.03, face, 0.3 * h],
        [xc, face + 0.006, 0.9 * h],
    );
    b.cuboid(
        Interior,
        [-hw + 0.08, face, 0.08 * h],
        [xc - 0.05, hd, 0.2 * h],
    );
    let (x0, x1) = (xc + 0.04, hw - 0.04);
    b.cuboid(Screen, [x0, face, 0.72 * h], [x1, face + 0.005, 0.8 * h]);
    for i in 0..3 {
        for j in 0..4 {
            let (x, z) = (
                x0 + (i as f64 + 0.5) * (x1 - x0) / 3.0,
                0.5 * h + j as f64 * 0.045,
            );
            b.cuboid(
                Keys,
                [x - 0.015, face, z],
                [x + 0.015, face + 0.008, z + 0.03],
            );
        }
    }
    b.cuboid(
        Handle,
        [x0 + 0.03, face, 0.42 * h],
        [x1 - 0.03, face + 0.01, 0.46 * h],
    );
}
