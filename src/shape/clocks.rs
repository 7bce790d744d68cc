//! Layouts of clocks drawn as clocks: a wall clock (a round case with a white dial, hour marks
//! and hands, hung flat on its wall) and a grandfather clock (a tall case on a plinth, a glazed
//! waist showing its pendulum, and a hood high up holding the dial under a crest). The front
//! faces +y; a wall clock's back is its -y face.
use super::archetypes::Builder;
use super::fittings::{band, clock_face, disc, Y};
use super::materials::Role::*;

/// A wall clock: a round case as large as the box allows, a bezel standing proud of the dial,
/// and the dial with its marks and hands; its corners stay empty.
pub fn wall_clock(b: &mut Builder) {
    let (hd, h) = (b.d / 2.0, b.h);
    let r = 0.5 * b.w.min(h);
    let zc = h / 2.0;
    let t = (0.6 * b.d).clamp(0.004, 0.05);
    disc(b, Frame, [0.0, -hd + t / 2.0, zc], Y, r, t);
    let lip = (b.d - t).clamp(0.002, 0.015);
    band(
        b,
        Frame,
        [0.0, -hd + t + lip / 2.0, zc],
        Y,
        r,
        0.08 * r,
        lip,
    );
    clock_face(b, [0.0, -hd + t + 0.001, zc], 0.9 * r);
}

/// A grandfather clock: a plinth, a narrower waist with a glazed door over a dark case in which
/// a brass pendulum hangs, a hood with turned columns either side of the dial, and a crest with
/// finials on top.
pub fn grandfather_clock(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (z_plinth, z_waist, z_hood) = (0.13 * h, 0.66 * h, 0.92 * h);
    // The plinth with a moulding on top, and bun feet under it.
    b.cuboid(Body, [-hw, -hd, 0.03], [hw, hd, z_plinth]);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cuboid(
                Frame,
                [
                    sx * hw - 0.03 * (sx + 1.0),
                    sy * hd - 0.03 * (sy + 1.0),
                    0.0,
                ],
                [
                    sx * hw - 0.03 * (sx - 1.0),
                    sy * hd - 0.03 * (sy - 1.0),
                    0.03,
                ],
            );
        }
    }
    b.cuboid(Frame, [-hw, -hd, z_plinth], [hw, hd, z_plinth + 0.02]);
    // The waist: a narrower case with a door whose window shows the pendulum.
    let (ww, wd) = (0.8 * hw, hd - 0.03);
    b.cuboid(Body, [-ww, -hd, z_plinth + 0.02], [ww, -hd + 0.02, z_waist]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Body,
            [sx * ww - 0.01 * (sx + 1.0), -hd, z_plinth + 0.02],
            [sx * ww - 0.01 * (sx - 1.0), wd, z_waist],
        );
    }
    b.cuboid(
        Interior,
        [-ww + 0.02, -hd + 0.02, z_plinth + 0.02],
        [ww - 0.02, -hd + 0.03, z_waist],
    );
    let (wz0, wz1) = (z_plinth + 0.22 * (z_waist - z_plinth), z_waist - 0.05);
    let wx = 0.6 * ww;
    // The door: a frame round the window; the window itself is open glass.
    b.cuboid(Door, [-ww, wd - 0.02, z_plinth + 0.02], [ww, wd, wz0]);
    b.cuboid(Door, [-ww, wd - 0.02, wz1], [ww, wd, z_waist]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Door,
            [sx * wx - (ww - wx) * 0.5 * (1.0 - sx), wd - 0.02, wz0],
            [sx * wx + (ww - wx) * 0.5 * (1.0 + sx), wd, wz1],
        );
    }
    b.cuboid(Pane, [-wx, wd - 0.012, wz0], [wx, wd - 0.008, wz1]);
    // The pendulum: a rod from the hood down to a round brass bob low in the window.
    let yp = 0.5 * (-hd + 0.03 + wd - 0.02);
    let rb = (0.7 * wx).min(0.08);
    let zb = wz0 + rb + 0.04;
    b.rod(Metal, [0.0, yp, z_waist], [0.0, yp, zb], 0.006);
    disc(b, Metal, [0.0, yp, zb], Y, rb, 0.012);
    // Two weights on chains behind the window's top.
    for sx in [-1.0, 1.0] {
        b.cylinder(Metal, [sx * 0.55 * wx, yp - 0.04, wz1 - 0.22], 0.025, 0.16);
    }
    // The hood: full width, with a square dial plate, columns at its front corners.
    b.cuboid(Frame, [-hw, -hd, z_waist], [hw, hd, z_waist + 0.025]);
    b.cuboid(
        Body,
        [-hw + 0.01, -hd, z_waist + 0.025],
        [hw - 0.01, hd - 0.04, z_hood],
    );
    let r = (0.78 * (hw - 0.05)).min(0.42 * (z_hood - z_waist));
    let zc = 0.5 * (z_waist + 0.025 + z_hood);
    b.cuboid(
        Top,
        [-r - 0.02, hd - 0.045, zc - r - 0.02],
        [r + 0.02, hd - 0.035, zc + r + 0.02],
    );
    band(b, Handle, [0.0, hd - 0.03, zc], Y, r + 0.01, 0.02, 0.012);
    clock_face(b, [0.0, hd - 0.03, zc], r);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.03);
        b.cylinder(
            Frame,
            [x, hd - 0.03, z_waist + 0.025],
            0.018,
            z_hood - z_waist - 0.025,
        );
    }
    // The crest: a cornice, a swan-neck pediment block and three finials.
    b.cuboid(Frame, [-hw, -hd, z_hood], [hw, hd, z_hood + 0.025]);
    let top = h - 0.06;
    b.cuboid(
        Body,
        [-hw + 0.04, -hd + 0.02, z_hood + 0.025],
        [hw - 0.04, hd - 0.03, top - 0.02],
    );
    b.ellipsoid(Frame, [0.0, hd - 0.06, top - 0.03], [hw - 0.06, 0.03, 0.04]);
    for x in [-hw + 0.05, 0.0, hw - 0.05] {
        b.ellipsoid(Metal, [x, 0.0, h - 0.03], [0.025, 0.025, 0.03]);
    }
}
