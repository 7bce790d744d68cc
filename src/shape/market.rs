//! Layouts of things of streets, markets and halls: a market stall, a bus shelter, a suit of
//! armour and a cooper's barrel. The front faces +y.
use super::archetypes::Builder;
use super::heritage::slab;
use super::materials::Role::*;
use super::parts::{rot_x, IDENTITY};
use std::f64::consts::PI;

/// A market stall: a counter across the front with crates of produce on it, four posts and a
/// striped awning sloping down to the front with a valance.
pub fn stall(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let counter = 0.38 * h;
    b.cuboid(
        Body,
        [-hw + 0.05, 0.1 * hd, 0.0],
        [hw - 0.05, hd - 0.05, counter],
    );
    b.cuboid(Top, [-hw, 0.05 * hd, counter], [hw, hd, counter + 0.03]);
    let crates = ((b.w / 0.45) as usize).clamp(2, 6);
    let cw = (2.0 * hw - 0.2) / crates as f64;
    for k in 0..crates {
        let x0 = -hw + 0.1 + k as f64 * cw;
        b.cuboid(
            Frame,
            [x0 + 0.02, 0.2 * hd, counter + 0.03],
            [x0 + cw - 0.02, 0.9 * hd, counter + 0.1],
        );
        b.cuboid_v(
            Books,
            k as u32,
            [x0 + 0.05, 0.25 * hd, counter + 0.1],
            [x0 + cw - 0.05, 0.85 * hd, counter + 0.14],
        );
    }
    let p = 0.035;
    let (back_top, front_top) = (0.95 * h, 0.8 * h);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - p);
        b.cuboid(Frame, [x - p, -hd, 0.0], [x + p, -hd + 2.0 * p, back_top]);
        b.cuboid(
            Frame,
            [x - p, hd - 2.0 * p, counter],
            [x + p, hd, front_top],
        );
    }
    // The awning: strips across x, alternating colours, sloping from the back to the front.
    let slope = (back_top - front_top).atan2(2.0 * hd);
    let half_len = 0.5 * (2.0 * hd).hypot(back_top - front_top);
    let strips = ((b.w / 0.3) as usize).clamp(4, 12);
    let sw = 2.0 * hw / strips as f64;
    for k in 0..strips {
        let role = if k % 2 == 0 { Shade } else { Canvas };
        let x = -hw + (k as f64 + 0.5) * sw;
        slab(
            b,
            role,
            0,
            [x, 0.0, 0.5 * (back_top + front_top) + 0.01],
            [0.5 * sw, half_len, 0.008],
            rot_x(slope),
        );
        // The valance hanging at the front edge.
        b.cuboid(
            role,
            [x - 0.5 * sw, hd - 0.01, front_top - 0.07 * h],
            [x + 0.5 * sw, hd, front_top],
        );
    }
}

/// A bus shelter: glass back and side panels in a metal frame, a flat roof, a bench along the
/// back and a sign at one end; open at the front.
pub fn shelter(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let roof = 0.9 * h;
    let p = 0.04;
    for x in [-hw + p, 0.0, hw - p] {
        b.cuboid(Metal, [x - p, -hd, 0.0], [x + p, -hd + 2.0 * p, roof]);
    }
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [sx * (hw - p) - p, 0.3 * hd, 0.0],
            [sx * (hw - p) + p, 0.3 * hd + 2.0 * p, roof],
        );
        b.cuboid(
            Glass,
            [sx * (hw - p) - 0.01, -hd + 2.0 * p, 0.1 * h],
            [sx * (hw - p) + 0.01, 0.3 * hd, 0.85 * h],
        );
    }
    b.cuboid(
        Glass,
        [-hw + 2.0 * p, -hd + 0.03, 0.1 * h],
        [hw - 2.0 * p, -hd + 0.05, 0.85 * h],
    );
    b.cuboid(Top, [-hw, -hd, roof], [hw, hd, h]);
    let seat = 0.18 * h;
    b.cuboid(
        Seat,
        [-0.6 * hw, -hd + 0.08, seat],
        [0.6 * hw, -hd + 0.08 + 0.35 * hd.min(1.0), seat + 0.04],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [sx * 0.55 * hw - p, -hd + 0.1, 0.0],
            [sx * 0.55 * hw + p, -hd + 0.16, seat],
        );
    }
    b.cuboid(
        Body,
        [hw - 0.6 * hw.min(1.0), 0.3 * hd, 0.62 * h],
        [hw - 0.05, 0.3 * hd + 0.03, 0.84 * h],
    );
}

/// A suit of armour on a low stand: steel legs, a breastplate, shoulder plates, arms with
/// gauntlets, and a closed helmet with a dark visor slit and a crest.
pub fn armour(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(
        Frame,
        [-0.8 * hw, -0.8 * hd, 0.0],
        [0.8 * hw, 0.8 * hd, 0.04 * h],
    );
    let lr = (0.055 * h).min(0.3 * hw).min(0.7 * hd);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.3 * hw;
        b.frustum(Body, [x, 0.0, 0.04 * h], 0.9 * lr, 0.9 * lr, 1.1, 0.44 * h);
        b.ellipsoid(
            Metal,
            [x, 0.3 * lr, 0.26 * h],
            [1.1 * lr, 1.1 * lr, 0.04 * h],
        );
        b.cuboid(Body, [x - lr, -lr, 0.04 * h], [x + lr, 1.8 * lr, 0.08 * h]);
    }
    let tw = 0.62 * hw;
    b.frustum(
        Body,
        [0.0, 0.0, 0.46 * h],
        0.8 * tw,
        (0.7 * hd).min(0.8 * tw),
        1.25,
        0.32 * h,
    );
    b.ellipsoid(
        Body,
        [0.0, 0.05 * hd, 0.68 * h],
        [0.95 * tw, (0.75 * hd).min(tw), 0.12 * h],
    );
    let ar = 0.65 * lr;
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Metal,
            [sx * 0.95 * tw, 0.0, 0.77 * h],
            [0.35 * tw, 0.3 * tw, 0.06 * h],
        );
        let hand = [sx * (hw - ar), 0.12 * hd, 0.46 * h];
        b.rod(Body, [sx * 0.95 * tw, 0.0, 0.76 * h], hand, ar);
        b.ellipsoid(Metal, hand, [1.3 * ar, 1.3 * ar, 1.6 * ar]);
    }
    let hr = (0.07 * h).min(0.7 * hw);
    let hz = h - 1.25 * hr - 0.03 * h;
    b.rod(Metal, [0.0, 0.0, 0.78 * h], [0.0, 0.0, hz], 0.6 * hr);
    b.ellipsoid(Body, [0.0, 0.0, hz], [hr, (1.05 * hr).min(hd), 1.25 * hr]);
    let ry = (1.05 * hr).min(hd);
    b.cuboid(
        Interior,
        [-0.6 * hr, 0.8 * ry, hz + 0.1 * hr],
        [0.6 * hr, ry + 0.005, hz + 0.25 * hr],
    );
    b.cuboid(
        Metal,
        [-0.08 * hr, -0.8 * ry, hz + 0.6 * hr],
        [0.08 * hr, 0.8 * ry, h],
    );
}

/// A barrel: staves bulging at the middle, iron hoops near the ends and the belly, and a lid.
pub fn barrel(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = |z: f64| hw * (0.8 + 0.2 * (PI * z / h).sin());
    let n = 12;
    let mut profile = vec![[0.0, 0.0]];
    profile.extend((0..=n).map(|i| {
        let z = h * i as f64 / n as f64;
        [r(z), z]
    }));
    profile.push([0.0, h]);
    b.revolved(Body, 0, [0.0, 0.0, 0.0], IDENTITY, hd / hw, profile);
    for z in [0.1 * h, 0.33 * h, 0.67 * h, 0.9 * h] {
        let rz = 1.02 * r(z);
        b.frustum(
            Metal,
            [0.0, 0.0, z - 0.015 * h],
            rz,
            rz * hd / hw,
            1.0,
            0.03 * h,
        );
    }
    let lid = 0.76 * hw;
    b.frustum(Top, [0.0, 0.0, h - 0.006], lid, lid * hd / hw, 1.0, 0.006);
}
