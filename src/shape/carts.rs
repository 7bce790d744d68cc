//! Layouts of a serving cart (two trays on four castors with a push bar at one end, bottles,
//! glasses and boxes on the trays) and a clothes airer (an A-frame of rails with laundry
//! hanging over them). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, IDENTITY};
use super::racks::along;

/// A tray from `-hw`..`hw` by `-hd`..`hd` at height `z`, with a low rim round it.
fn tray(b: &mut Builder, hw: f64, hd: f64, z: f64) {
    b.cuboid(Top, [-hw, -hd, z - 0.015], [hw, hd, z]);
    let (t, r) = (0.01, 0.03);
    b.cuboid(Frame, [-hw, -hd, z], [hw, -hd + t, z + r]);
    b.cuboid(Frame, [-hw, hd - t, z], [hw, hd, z + r]);
    b.cuboid(Frame, [-hw, -hd, z], [-hw + t, hd, z + r]);
    b.cuboid(Frame, [hw - t, -hd, z], [hw, hd, z + r]);
}

/// A serving cart: four slim posts on castors, a lower and an upper tray, a push bar rising at
/// the left end; bottles and glasses on the upper tray, boxes and a basket below.
pub fn cart(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rc = 0.035;
    let (tw, td) = (hw - 0.02, hd - 0.02);
    let z_low = 0.2 + rc;
    let z_up = h - 0.3;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (tw - 0.012), sy * (td - 0.012));
            let top = if sx < 0.0 { h - 0.015 } else { z_up + 0.03 };
            b.rod(Metal, [x, y, 2.0 * rc], [x, y, top], 0.012);
            b.ellipsoid(Tyre, [x, y, rc], [rc, 0.6 * rc, rc]);
        }
    }
    let xb = -(tw - 0.012);
    b.rod(
        Handle,
        [xb, -td + 0.012, h - 0.015],
        [xb, td - 0.012, h - 0.015],
        0.015,
    );
    tray(b, tw, td, z_low);
    tray(b, tw, td, z_up);
    // Upper tray: a row of bottles at the back, glasses in front.
    let n = ((2.0 * tw - 0.1) / 0.11).floor().clamp(2.0, 6.0) as usize;
    let pitch = (2.0 * tw - 0.1) / n as f64;
    let bh = (h - z_up - 0.02).min(0.3);
    for i in 0..n {
        let x = -tw + 0.05 + (i as f64 + 0.5) * pitch;
        let r = (0.35 * pitch).min(0.04);
        let role = if i % 2 == 0 { Glass } else { BlackKeys };
        along(
            b,
            role,
            0,
            [x, -0.35 * td, z_up],
            [0.0, 0.0, 1.0],
            0.0,
            1.0,
            vec![
                [0.0, 0.0],
                [r, 0.0],
                [r, 0.6 * bh],
                [0.3 * r, 0.78 * bh],
                [0.3 * r, bh],
                [0.0, bh],
            ],
        );
        if i % 2 == 1 {
            b.revolved(
                Pane,
                0,
                [x, 0.45 * td, z_up],
                IDENTITY,
                1.0,
                frustum_profile(0.025, 0.03, 0.09),
            );
        }
    }
    // Lower tray: boxes and a basket.
    let room = z_up - z_low - 0.05;
    b.cuboid_v(
        Books,
        2,
        [-tw + 0.04, -0.6 * td, z_low],
        [-0.1 * tw, 0.6 * td, z_low + 0.6 * room],
    );
    b.revolved(
        Canvas,
        0,
        [0.5 * tw, 0.0, z_low],
        IDENTITY,
        1.0,
        vec![[0.0, 0.0], [0.3 * tw, 0.0], [0.36 * tw, 0.5 * room]],
    );
}

/// A clothes airer: two frames of rails leaning together in an A over the width, laundry of
/// several colours hanging over the rails on both sides.
pub fn airer(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.01;
    let apex = h - r;
    let rails = 5;
    for sy in [-1.0, 1.0] {
        let foot = sy * (hd - r);
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - r);
            b.rod(Frame, [x, foot, 0.0], [x, 0.0, apex], 1.4 * r);
        }
        for k in 0..rails {
            let t = (k as f64 + 1.0) / (rails as f64 + 0.5);
            let (y, z) = (foot * (1.0 - t), apex * t);
            b.rod(Metal, [-hw + r, y, z], [hw - r, y, z], 0.6 * r);
            // Laundry over every other rail, hanging straight down on the outside.
            if k % 2 == 1 || k + 1 == rails {
                let m = ((b.w - 0.1) / 0.45).floor().max(1.0) as usize;
                let pitch = (b.w - 0.1) / m as f64;
                for j in 0..m {
                    let x0 = -hw + 0.05 + j as f64 * pitch + 0.03;
                    let drop = (0.55 * z).min(0.45) * (0.7 + 0.3 * ((j + k) % 2) as f64);
                    let yo = y + sy * 0.012;
                    b.cuboid_v(
                        Books,
                        (j * 3 + k) as u32 + if sy > 0.0 { 0 } else { 7 },
                        [x0, yo.min(yo + sy * 0.006), z - drop],
                        [x0 + pitch - 0.06, yo.max(yo + sy * 0.006), z],
                    );
                }
            }
        }
    }
}
