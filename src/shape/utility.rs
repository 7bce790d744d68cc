//! Layouts of outdoor utility things: a satellite dish, a solar panel, a gas cylinder and a
//! bike rack. The front faces +y, z up, the bottom face's centre at the origin.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::{rot_x, V3};
use std::f64::consts::PI;

fn add(a: V3, b: V3, k: f64) -> V3 {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

/// A satellite dish: a shallow parabolic bowl looking forward and up, a feed arm holding the
/// receiver at its focus, on a mast with a bracket behind the bowl and a foot plate.
pub fn dish(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tilt = 30f64.to_radians();
    let axis = [0.0, tilt.cos(), tilt.sin()];
    let up = [0.0, -tilt.sin(), tilt.cos()];
    // The rim spans 2R·cos(tilt) in height and R·sin(tilt) + depth in depth on each side.
    let r = (0.97 * hw).min(0.3 * h).min(0.9 * hd / (tilt.sin() + 0.35));
    let f = 0.6 * r;
    let depth = r * r / (4.0 * f);
    let centre = [
        0.0,
        hd - r * tilt.sin() - 0.02 * hd,
        h - r * tilt.cos() - 0.01 * h,
    ];
    let vertex = add(centre, axis, -depth);
    let profile: Vec<[f64; 2]> = (0..=12)
        .map(|i| {
            let p = r * i as f64 / 12.0;
            [p, p * p / (4.0 * f)]
        })
        .collect();
    b.revolved(Body, 0, vertex, frame_along(axis), 1.0, profile);
    // The feed arm from the rim's bottom to the receiver at the focus.
    let low = add(centre, up, -r);
    let focus = add(vertex, axis, f);
    b.polyline(Metal, &[low, focus], 0.012 * r.max(0.5));
    b.ellipsoid(Handle, focus, [0.05 * r, 0.08 * r, 0.05 * r]);
    // The bracket and the mast.
    let back = add(vertex, axis, -0.08 * r);
    b.ellipsoid(Metal, back, [0.12 * r, 0.08 * r, 0.12 * r]);
    let foot = [0.0, vertex[1] - 0.1 * hd, 0.0];
    b.rod(Metal, foot, back, 0.03 * r.max(0.5));
    b.cuboid(
        Metal,
        [-0.5 * hw, (foot[1] - 0.35 * hd).max(-hd), 0.0],
        [0.5 * hw, (foot[1] + 0.35 * hd).min(hd), 0.02],
    );
}

/// A solar panel: a flat dark module of cells in an aluminium frame, tilted to face forward
/// and up, on short front legs and long back legs.
pub fn solar_panel(b: &mut Builder) {
    let (hw, h) = (b.w / 2.0, b.h);
    let tilt = 35f64.to_radians();
    let len = (0.96 * b.d / tilt.cos()).min(0.85 * h / tilt.sin());
    let t = 0.02;
    // The module's lower edge at the front, its upper edge at the back, top near the box's.
    let z_hi = h - t;
    let y_hi = -0.5 * len * tilt.cos();
    let mid = [0.0, 0.0, z_hi - 0.5 * len * tilt.sin()];
    let rot = rot_x(-tilt);
    b.slab(Frame, mid, [hw, 0.5 * len, t], rot);
    // Cells: a grid of dark panes standing just proud of the frame.
    let normal = [0.0, tilt.sin(), tilt.cos()];
    let slope = [0.0, tilt.cos(), -tilt.sin()];
    let (nx, ny) = (((b.w / 0.18).round() as usize).clamp(3, 12), 4usize);
    let (cw, cl) = ((b.w - 0.04) / nx as f64, (len - 0.04) / ny as f64);
    for i in 0..nx {
        for j in 0..ny {
            let u = -hw + 0.02 + (i as f64 + 0.5) * cw;
            let v = -0.5 * len + 0.02 + (j as f64 + 0.5) * cl;
            let c = add(add([u, mid[1], mid[2]], slope, v), normal, t + 0.002);
            b.slab(Glass, c, [0.44 * cw, 0.45 * cl, 0.002], rot);
        }
    }
    // Legs: two short at the front edge, two long at the back edge, and a rail between.
    let z_lo = z_hi - len * tilt.sin();
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.08 * b.w);
        let front = 0.5 * len * tilt.cos() - 0.05;
        b.cuboid(
            Metal,
            [x - 0.02, front - 0.02, 0.0],
            [x + 0.02, front + 0.02, z_lo],
        );
        let back = y_hi + 0.05;
        b.cuboid(
            Metal,
            [x - 0.02, back - 0.02, 0.0],
            [x + 0.02, back + 0.02, z_hi - 0.08],
        );
        b.cuboid(Metal, [x - 0.02, back, 0.0], [x + 0.02, front, 0.04]);
    }
}

/// A gas cylinder: a tall steel bottle on a foot ring with a rounded shoulder of another
/// colour, a brass valve with a hand wheel, inside an open guard collar.
pub fn gas_cylinder(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.98 * hw.min(hd);
    let ay = (hd / hw).min(hw / hd).max(0.5);
    let shoulder = h - 0.12 * h - 0.9 * r;
    b.revolved(
        Body,
        0,
        [0.0, 0.0, 0.0],
        super::parts::IDENTITY,
        ay,
        vec![
            [0.0, 0.0],
            [0.88 * r, 0.0],
            [0.88 * r, 0.03 * h],
            [r, 0.045 * h],
            [r, shoulder],
            [0.0, shoulder],
        ],
    );
    let dome: Vec<[f64; 2]> = std::iter::once([0.0, shoulder])
        .chain((0..=8).map(|i| {
            let a = 0.5 * PI * i as f64 / 8.0;
            [r * a.cos().max(0.28), shoulder + 0.9 * r * a.sin()]
        }))
        .chain([[0.0, shoulder + 0.9 * r]])
        .collect();
    b.revolved(Top, 0, [0.0, 0.0, 0.0], super::parts::IDENTITY, ay, dome);
    // The valve: a neck, a body and a hand wheel on top.
    let z = shoulder + 0.9 * r;
    b.cylinder(Handle, [0.0, 0.0, z], 0.22 * r, 0.04 * h);
    b.cuboid(
        Handle,
        [-0.2 * r, -0.2 * r, z + 0.04 * h],
        [0.2 * r, 0.2 * r, z + 0.07 * h],
    );
    b.rod(
        Handle,
        [0.2 * r, 0.0, z + 0.055 * h],
        [0.45 * r, 0.0, z + 0.055 * h],
        0.06 * r,
    );
    b.cylinder(Metal, [0.0, 0.0, z + 0.07 * h], 0.35 * r, 0.012 * h);
    // The guard: an open ring round the valve.
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, z - 0.02 * h],
        super::parts::IDENTITY,
        ay,
        vec![[0.62 * r, 0.0], [0.62 * r, (h - z + 0.02 * h).min(0.1 * h)]],
    );
}

/// A bike rack: a row of steel hoops (inverted U's standing front to back, a bike parks on
/// each side of one) on two floor rails.
pub fn bike_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.025f64.min(0.05 * hd.min(h));
    let rr = (hd - t).min(0.45 * h);
    let n = ((b.w / 0.55).floor() as usize + 1).clamp(2, 10);
    let step = (b.w - 2.0 * t - 0.1 * b.w) / (n - 1) as f64;
    for i in 0..n {
        let x = -hw + t + 0.05 * b.w + i as f64 * step;
        let zc = h - t - rr;
        let mut pts = vec![[x, -rr, 0.0]];
        pts.extend((0..=10).map(|k| {
            let a = PI * k as f64 / 10.0;
            [x, -rr * a.cos(), zc + rr * a.sin()]
        }));
        pts.push([x, rr, 0.0]);
        b.polyline(Frame, &pts, t);
    }
    for sy in [-1.0, 1.0] {
        b.cuboid(
            Metal,
            [-hw, sy * rr - 0.03, 0.0],
            [hw, sy * rr + 0.03, 0.015],
        );
    }
}
