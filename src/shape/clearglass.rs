//! Layouts of glass things whose glass must be seen through ([`Role::Pane`]): a barrister
//! bookcase (stacked shelves of books behind lift-up glass doors), a supermarket freezer case
//! (a white chest whose glass lids show the goods in its well), a lab fume hood (a cabinet with
//! a raised glass sash over a worktop of flasks), a terrarium (a framed glass box of soil, moss,
//! a fern and a stone) and a crystal ball (a clear globe with a glow inside, on a claw stand).
//! The front faces +y.
//!
//! [`Role::Pane`]: super::materials::Role::Pane
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x, IDENTITY};
use super::vitrines::{edges, glass_fridge, goods};

/// A row of upright books from `x0` to `x1` standing at height `z` against the back plane
/// `y0`, at most `depth` deep and `tall` high; widths and heights vary book to book.
fn books(b: &mut Builder, x: [f64; 2], y0: f64, z: f64, depth: f64, tall: f64, v: &mut u32) {
    let mut xc = x[0];
    let mut k = *v as u64;
    while xc < x[1] - 0.02 {
        // A small hash of the book's index: its width and height.
        k = k
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let r1 = ((k >> 33) % 1000) as f64 / 1000.0;
        let r2 = ((k >> 13) % 1000) as f64 / 1000.0;
        let wb = (0.025 + 0.025 * r1).min(x[1] - xc);
        let hb = tall * (0.72 + 0.28 * r2);
        b.cuboid_v(
            Books,
            *v,
            [xc, y0, z],
            [xc + wb - 0.002, y0 + depth * (0.8 + 0.2 * r2), z + hb],
        );
        xc += wb;
        *v += 1;
    }
}

/// A barrister bookcase: a plinth, stacked sections of books each behind its own glass door
/// hinged at the top (a rail along its top and bottom, a knob), and a cornice.
pub fn barrister_bookcase(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (plinth, cornice, t) = (0.08, 0.05, 0.025);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd, plinth]);
    b.cuboid(Top, [-hw, -hd, h - cornice], [hw, hd, h]);
    let sections = (((h - plinth - cornice) / 0.4).round() as usize).clamp(1, 6);
    let pitch = (h - plinth - cornice) / sections as f64;
    let yf = hd - 0.01;
    // The sides and the back, whole height.
    for x in [-hw, hw - t] {
        b.cuboid(Body, [x, -hd, plinth], [x + t, hd, h - cornice]);
    }
    b.cuboid(
        Interior,
        [-hw + t, -hd, plinth],
        [hw - t, -hd + 0.012, h - cornice],
    );
    let mut v = 0;
    for k in 0..sections {
        let z = plinth + k as f64 * pitch;
        // Each section's floor shows in front as a band between the doors.
        b.cuboid(Body, [-hw + t, -hd + 0.012, z], [hw - t, hd, z + 0.03]);
        books(
            b,
            [-hw + t + 0.01, hw - t - 0.01],
            -hd + 0.015,
            z + 0.03,
            0.8 * (yf - (-hd + 0.015)),
            pitch - 0.09,
            &mut v,
        );
        // The door: glass in a frame of a top and a bottom rail and two stiles, a knob.
        let (z0, z1) = (z + 0.03, z + pitch);
        b.cuboid(Pane, [-hw + t, yf - 0.006, z0], [hw - t, yf, z1]);
        b.cuboid(Frame, [-hw + t, yf - 0.012, z0], [hw - t, hd, z0 + 0.03]);
        b.cuboid(Frame, [-hw + t, yf - 0.012, z1 - 0.025], [hw - t, hd, z1]);
        for x in [-hw + t, hw - t - 0.03] {
            b.cuboid(Frame, [x, yf - 0.012, z0], [x + 0.03, hd, z1]);
        }
        for x in [-0.25 * b.w, 0.25 * b.w] {
            b.cuboid(
                Handle,
                [x - 0.01, hd - 0.004, z0 + 0.005],
                [x + 0.01, hd, z0 + 0.025],
            );
        }
    }
}

/// A supermarket freezer case: a white chest on a dark kick plinth with a bumper rail along
/// its front, a frosty well full of boxes and tubs seen through two sliding glass lids in a
/// steel frame, a lit price strip along the front edge and a lit header along the back. A tall one is a glass-door freezer.
pub fn freezer_case(b: &mut Builder) {
    if b.h > 1.4 {
        glass_fridge(b);
        return;
    }
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (kick, wall) = (0.08, 0.06);
    b.cuboid(
        Metal,
        [-hw + 0.03, -hd + 0.03, 0.0],
        [hw - 0.03, hd - 0.03, kick],
    );
    // The chest stops below the lit header along its back.
    let hc = 0.85 * h;
    // The four walls of the chest round an open well.
    b.cuboid(Body, [-hw, hd - wall, kick], [hw, hd, hc - 0.03]);
    b.cuboid(Body, [-hw, -hd, kick], [hw, -hd + wall, hc - 0.03]);
    for x in [-hw, hw - wall] {
        b.cuboid(Body, [x, -hd, kick], [x + wall, hd, hc - 0.03]);
    }
    let floor = 0.62 * hc;
    b.cuboid(
        Interior,
        [-hw + wall, -hd + wall, kick],
        [hw - wall, hd - wall, floor],
    );
    // Goods in the well: two rows of boxes and tubs, and a second layer on part of them.
    let mut v = 0;
    let s = (0.22 * (b.d - 2.0 * wall)).clamp(0.06, 0.16);
    let x = [-hw + wall + 0.02, hw - wall - 0.02];
    for (y, z) in [
        (-0.3 * (hd - wall), floor),
        (0.3 * (hd - wall), floor),
        (0.0, floor + 0.7 * s),
        (-0.25 * (hd - wall), floor + 1.4 * s),
    ] {
        goods(b, x, y, z, s, &mut v);
    }
    // Bumper rail and a lit price strip along the front.
    b.cuboid(Metal, [-hw, hd - 0.005, 0.35 * hc], [hw, hd, 0.42 * hc]);
    b.cuboid(
        Light,
        [-hw + wall, hd - 0.004, hc - 0.1],
        [hw - wall, hd, hc - 0.06],
    );
    // The lids: two sliding panes in a steel frame, both slid over the left half (the back one
    // a little higher), so the right half of the well is open.
    let zl = hc - 0.03;
    edges(b, Frame, [-hw, -hd, zl], [hw, hd, hc], 0.025);
    b.cuboid(Frame, [-0.0125, -hd, zl], [0.0125, hd, hc]);
    b.cuboid(
        Pane,
        [-hw + 0.02, -hd + 0.02, zl + 0.006],
        [0.0, hd - 0.02, zl + 0.009],
    );
    b.cuboid(
        Pane,
        [-hw + 0.06, -hd + 0.02, zl + 0.02],
        [0.04, hd - 0.02, zl + 0.023],
    );
    b.cuboid(
        Metal,
        [0.0, -hd + 0.02, zl + 0.02],
        [0.04, hd - 0.02, zl + 0.027],
    );
    // The lit header standing along the back edge.
    b.cuboid(Body, [-hw, -hd, hc - 0.03], [hw, -hd + 0.05, h]);
    b.cuboid(
        Light,
        [-hw + 0.05, -hd + 0.05, hc + 0.2 * (h - hc)],
        [hw - 0.05, -hd + 0.055, h - 0.2 * (h - hc)],
    );
}

/// A lab fume hood: a base cupboard with two doors under a dark worktop; above it a box with
/// solid sides, a lit top and an airflow panel, and in front a glass sash raised to show the
/// flasks and a bottle on the worktop; a bar handle along the sash's foot.
pub fn fume_hood(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = (0.4 * h).min(0.9);
    let side = 0.08;
    // The base cupboard and the worktop.
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, hd - 0.01, zt - 0.04]);
    for (x0, x1) in [(-hw + 0.03, -0.005), (0.005, hw - 0.03)] {
        b.cuboid(Door, [x0, hd - 0.01, 0.08], [x1, hd, zt - 0.08]);
    }
    for x in [-0.06, 0.06] {
        b.cuboid(
            Handle,
            [x - 0.01, hd, zt - 0.25],
            [x + 0.01, hd + 0.0, zt - 0.12],
        );
    }
    b.cuboid(Top, [-hw, -hd, zt - 0.04], [hw, hd, zt]);
    // The hood: sides, back, the top box with a lit panel under it.
    let zh = h - 0.3 * (h - zt);
    for x in [-hw, hw - side] {
        b.cuboid(Body, [x, -hd, zt], [x + side, hd, h]);
    }
    b.cuboid(Interior, [-hw + side, -hd, zt], [hw - side, -hd + 0.03, h]);
    b.cuboid(Body, [-hw + side, -hd, zh], [hw - side, hd, h]);
    b.cuboid(
        Light,
        [-hw + side, -hd + 0.03, zh - 0.01],
        [hw - side, hd - 0.1, zh],
    );
    // The airflow monitor on the right side's front.
    b.cuboid(
        Screen,
        [hw - side + 0.01, hd - 0.002, zt + 0.55 * (zh - zt)],
        [hw - 0.01, hd, zt + 0.65 * (zh - zt)],
    );
    // Glassware on the worktop: conical flasks, a round flask, a tall bottle.
    let r = (0.06 * b.w).clamp(0.04, 0.08);
    for (i, fx) in [-0.55, -0.3, 0.1, 0.45].into_iter().enumerate() {
        let c = [fx * hw, -0.1 * hd, zt];
        match i % 3 {
            0 => {
                b.frustum(Glass, c, r, r, 0.3, 2.0 * r);
                b.cylinder(Glass, [c[0], c[1], zt + 2.0 * r], 0.3 * r, 0.8 * r);
                b.cylinder(Water, c, 0.9 * r, 0.6 * r);
            }
            1 => {
                b.ellipsoid(Glass, [c[0], c[1], zt + r], [r, r, r]);
                b.cylinder(Glass, [c[0], c[1], zt + 1.8 * r], 0.3 * r, r);
            }
            _ => {
                b.cylinder(Canvas, c, 0.7 * r, 3.0 * r);
                b.cylinder(Top, [c[0], c[1], zt + 3.0 * r], 0.4 * r, 0.5 * r);
            }
        }
    }
    // A shelf of reagent bottles along the back, and a retort stand holding a round flask
    // over a burner, both standing up behind the sash's glass.
    let zsh = zt + 0.5 * (zh - zt);
    let ysh = -hd + 0.03;
    b.cuboid(
        Frame,
        [-hw + side, ysh, zsh - 0.02],
        [hw - side, ysh + 0.16, zsh],
    );
    let rb = 0.03;
    let nb = ((b.w - 2.0 * side - 0.1) / (3.0 * rb)).floor().max(1.0) as usize;
    for k in 0..nb {
        let x = -hw + side + 0.05 + (k as f64 + 0.5) * (b.w - 2.0 * side - 0.1) / nb as f64;
        let hb = 0.14 + 0.06 * (k % 3) as f64;
        b.revolved(
            Books,
            k as u32,
            [x, ysh + 0.08, zsh],
            IDENTITY,
            1.0,
            frustum_profile(rb, rb, hb),
        );
        b.cylinder(Top, [x, ysh + 0.08, zsh + hb], 0.5 * rb, 0.03);
    }
    let xr = 0.6 * hw;
    b.cuboid(
        Metal,
        [xr - 0.1, -0.3 * hd, zt],
        [xr + 0.1, -0.1 * hd, zt + 0.015],
    );
    b.cylinder(Metal, [xr, -0.25 * hd, zt], 0.01, 0.75 * (zh - zt));
    let zf = zt + 0.55 * (zh - zt);
    b.rod(
        Metal,
        [xr, -0.25 * hd, zf + 1.2 * r],
        [xr - 0.2, -0.25 * hd, zf + 1.2 * r],
        0.008,
    );
    b.ellipsoid(
        Glass,
        [xr - 0.2, -0.25 * hd, zf],
        [1.3 * r, 1.3 * r, 1.3 * r],
    );
    b.ellipsoid(
        Water,
        [xr - 0.2, -0.25 * hd, zf - 0.5 * r],
        [1.0 * r, 1.0 * r, 0.7 * r],
    );
    b.cylinder(Glass, [xr - 0.2, -0.25 * hd, zf + r], 0.35 * r, 1.2 * r);
    // The sash: raised to about half the opening, a frame round its glass, the handle bar.
    let (z0, z1) = (zt + 0.45 * (zh - zt), zh + 0.2 * (h - zh));
    let yf = hd - 0.03;
    b.cuboid(Pane, [-hw + side, yf, z0], [hw - side, yf + 0.008, z1]);
    b.cuboid(
        Metal,
        [-hw + side, yf, z0 - 0.04],
        [hw - side, yf + 0.02, z0],
    );
    for x in [-hw + side, hw - side - 0.02] {
        b.cuboid(Metal, [x, yf, z0], [x + 0.02, yf + 0.02, z1]);
    }
    b.rod(
        Handle,
        [-hw + side + 0.05, hd - 0.01, z0 - 0.02],
        [hw - side - 0.05, hd - 0.01, z0 - 0.02],
        0.012,
    );
}

/// A terrarium: a framed glass box on a shallow base, soil with pebbles, moss mounds, a fern of
/// fronds and a stone, seen through the glass; a low glass roof rising to a ridge.
pub fn terrarium(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let base = 0.06 * h;
    let walls = 0.78 * h;
    let f = (0.04 * b.w).clamp(0.005, 0.02);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, base]);
    b.cuboid(
        Soil,
        [-hw + f, -hd + f, base],
        [hw - f, hd - f, base + 0.2 * h],
    );
    let zs = base + 0.2 * h;
    // Moss mounds and a stone on the soil.
    let r = 0.22 * hw.min(hd);
    for (x, y, s) in [(-0.5, 0.4, 1.0), (0.45, 0.45, 0.8), (0.4, -0.4, 1.1)] {
        b.ellipsoid(Foliage, [x * hw, y * hd, zs], [s * r, s * r, 0.5 * s * r]);
    }
    b.ellipsoid(
        Stone,
        [0.1 * hw, 0.45 * hd, zs],
        [0.8 * r, 0.6 * r, 0.5 * r],
    );
    // A fern: fronds leaning out from a crown.
    let crown = [-0.2 * hw, -0.1 * hd, zs];
    for k in 0..7 {
        let a = k as f64 / 7.0 * std::f64::consts::TAU;
        let tip = [
            crown[0] + 0.45 * hw * a.cos(),
            crown[1] + 0.45 * hd * a.sin(),
            zs + 0.45 * (walls - zs) + 0.1 * h * (k % 2) as f64,
        ];
        let mid = [
            0.5 * (crown[0] + tip[0]),
            0.5 * (crown[1] + tip[1]),
            0.5 * (crown[2] + tip[2]),
        ];
        let dir = [tip[0] - crown[0], tip[1] - crown[1], tip[2] - crown[2]];
        let len = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
        b.ellipsoid_rot(
            Foliage,
            1,
            mid,
            [0.12 * len, 0.04 * len, 0.5 * len],
            frame_along(dir),
        );
    }
    // The frame's edges and the glass walls.
    edges(b, Frame, [-hw, -hd, base], [hw, hd, walls], f);
    b.cuboid(Pane, [-hw + f, hd - 0.003, base], [hw - f, hd, walls]);
    b.cuboid(Pane, [-hw + f, -hd, base], [hw - f, -hd + 0.003, walls]);
    for x in [-hw, hw - 0.003] {
        b.cuboid(Pane, [x, -hd + f, base], [x + 0.003, hd - f, walls]);
    }
    // The roof: two glass slopes to a ridge along x, and its bars.
    let rise = h - walls;
    let half = (hd * hd + rise * rise).sqrt();
    let tilt = (rise / hd).atan();
    for s in [-1.0, 1.0] {
        let c = [0.0, s * 0.5 * hd, walls + 0.5 * rise];
        let rot = rot_x(-s * tilt);
        b.slab(Pane, c, [hw - f, 0.5 * half, 0.0015], rot);
        for x in [-hw + 0.5 * f, hw - 0.5 * f] {
            b.slab(Frame, [x, c[1], c[2]], [0.5 * f, 0.5 * half, 0.5 * f], rot);
        }
    }
    b.cuboid(Frame, [-hw, -0.5 * f, h - f], [hw, 0.5 * f, h]);
}

/// A crystal ball: a clear glass globe holding a glowing mist, held by three claws on a turned
/// stand of dark wood with a metal ring.
pub fn crystal_ball(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = (0.95 * hw.min(hd)).min(0.42 * h);
    let zc = h - r;
    let stand = (zc - 0.55 * r).max(0.1 * h);
    // The stand: a wide foot, a waist and a cup.
    b.revolved(
        Trunk,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [0.8 * r, 0.0],
            [0.8 * r, 0.12 * stand],
            [0.45 * r, 0.35 * stand],
            [0.35 * r, 0.7 * stand],
            [0.55 * r, stand],
            [0.0, stand],
        ],
    );
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, 0.12 * stand],
        IDENTITY,
        1.0,
        frustum_profile(0.82 * r, 0.82 * r, 0.04 * stand),
    );
    // Three claws from the cup up round the globe's lower half.
    for k in 0..3 {
        let a = k as f64 / 3.0 * std::f64::consts::TAU + 0.5;
        let (c, s) = (a.cos(), a.sin());
        let p = |rho: f64, z: f64| [rho * c, rho * s, z];
        b.polyline(
            Metal,
            &[
                p(0.45 * r, stand),
                p(0.75 * r, zc - 0.6 * r),
                p(0.92 * r, zc - 0.3 * r),
            ],
            0.06 * r,
        );
    }
    // The glow inside and the globe.
    b.ellipsoid(Light, [0.0, 0.0, zc], [0.45 * r, 0.45 * r, 0.45 * r]);
    b.ellipsoid(
        Glass,
        [0.1 * r, -0.05 * r, zc - 0.1 * r],
        [0.2 * r, 0.2 * r, 0.2 * r],
    );
    b.ellipsoid(Pane, [0.0, 0.0, zc], [r, r, r]);
}
