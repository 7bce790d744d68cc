//! Dressing furniture: a vanity (a dressing table under an oval mirror, drawers either side of
//! a knee gap), a salon station (a wall-side counter under a tall mirror ringed with bulbs, tool
//! shelves either side), and a footstool (a tufted, piped cushion on short legs; its legs are
//! longer where the footprint is small, so a dressing stool stands as a padded stool).
//! Layout only: colours come from the archetype table.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::IDENTITY;

/// Drawer fronts (with a knob each) stacked on the face y = `y` between `x0` and `x1`, from
/// `z0` to `z1`.
fn drawer_stack(b: &mut Builder, x0: f64, x1: f64, y: f64, z0: f64, z1: f64, rows: usize) {
    let fh = (z1 - z0) / rows as f64;
    for r in 0..rows {
        let (a, c) = (z0 + r as f64 * fh + 0.006, z0 + (r + 1) as f64 * fh - 0.006);
        b.cuboid(Door, [x0 + 0.01, y - 0.012, a], [x1 - 0.01, y, c]);
        let (xc, zc) = (0.5 * (x0 + x1), 0.5 * (a + c));
        b.ellipsoid(Handle, [xc, y + 0.008, zc], [0.014, 0.01, 0.014]);
    }
}

/// A dressing table: a top on two drawer pedestals with a shallow drawer over the knee gap, and
/// an oval mirror in a frame standing on the top at the back.
pub fn vanity(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = (0.55 * h).min(0.76);
    let t = 0.03;
    b.cuboid(Top, [-hw, -hd, zt - t], [hw, hd, zt]);
    let pw = (0.28 * b.w).min(0.4);
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw + 0.02, -hw + 0.02 + pw)
        } else {
            (hw - 0.02 - pw, hw - 0.02)
        };
        b.cuboid(Body, [x0, -hd + 0.02, 0.06], [x1, hd - 0.03, zt - t]);
        drawer_stack(b, x0, x1, hd - 0.018, 0.07, zt - t - 0.01, 3);
        // Short turned feet under each pedestal's corners.
        for x in [x0 + 0.03, x1 - 0.03] {
            for y in [-hd + 0.05, hd - 0.06] {
                b.frustum(Frame, [x, y, 0.0], 0.022, 0.022, 0.7, 0.06);
            }
        }
    }
    // The shallow drawer over the knee gap, and a back panel behind it.
    let (gx0, gx1) = (-hw + 0.02 + pw, hw - 0.02 - pw);
    b.cuboid(
        Body,
        [gx0, -hd + 0.03, zt - t - 0.1],
        [gx1, hd - 0.03, zt - t],
    );
    drawer_stack(b, gx0, gx1, hd - 0.018, zt - t - 0.1, zt - t - 0.005, 1);
    b.cuboid(Body, [gx0, -hd + 0.02, 0.3 * zt], [gx1, -hd + 0.04, zt - t]);
    // The mirror: an oval glass in a wide oval frame on two uprights at the back of the top.
    let room = h - zt;
    let (rz, rx) = (0.46 * room, (0.32 * b.w).min(0.46 * room));
    let zc = zt + 0.04 + rz;
    let y = -hd + 0.05;
    for sx in [-1.0, 1.0] {
        let x = sx * (rx + 0.02);
        b.cuboid(
            Frame,
            [x - 0.02, y - 0.02, zt],
            [x + 0.02, y + 0.02, zc + 0.2 * rz],
        );
        b.ellipsoid(Handle, [x, y, zc], [0.025, 0.03, 0.025]);
    }
    b.cuboid(
        Frame,
        [-rx - 0.04, y - 0.03, zt],
        [rx + 0.04, y + 0.03, zt + 0.04],
    );
    b.ellipsoid_rot(Frame, 0, [0.0, y, zc], [rx, 0.014, rz], IDENTITY);
    b.ellipsoid_rot(
        Canvas,
        0,
        [0.0, y + 0.006, zc],
        [0.86 * rx, 0.012, rz - 0.14 * rx],
        IDENTITY,
    );
}

/// A salon station: a counter at the wall with a cupboard and an open shelf of products under
/// it, a tall rectangular mirror above ringed by bulbs, narrow tool shelves of bottles either
/// side of the mirror and a dryer holster on one side.
pub fn salon_station(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zc = (0.48 * h).min(0.86);
    let t = 0.035;
    b.cuboid(Top, [-hw, -hd, zc - t], [hw, hd, zc]);
    // Under the counter: a cupboard door on the left, an open shelf of products on the right.
    b.cuboid(
        Body,
        [-hw + 0.02, -hd + 0.02, 0.0],
        [hw - 0.02, hd - 0.05, zc - t],
    );
    let xm = -hw + 0.02 + 0.45 * (b.w - 0.04);
    b.cuboid(
        Door,
        [-hw + 0.03, hd - 0.05, 0.05],
        [xm - 0.01, hd - 0.035, zc - t - 0.02],
    );
    b.cuboid(
        Handle,
        [xm - 0.05, hd - 0.035, 0.5 * zc - 0.06],
        [xm - 0.035, hd - 0.02, 0.5 * zc + 0.06],
    );
    b.cuboid(
        Interior,
        [xm, hd - 0.06, 0.05],
        [hw - 0.03, hd - 0.049, zc - t - 0.02],
    );
    let shelf = 0.45 * (zc - t);
    b.cuboid(
        Frame,
        [xm, hd - 0.3, shelf - 0.012],
        [hw - 0.03, hd - 0.02, shelf + 0.012],
    );
    let n = (((hw - 0.03 - xm) / 0.08).floor() as usize).clamp(2, 6);
    let pitch = (hw - 0.05 - xm) / n as f64;
    for (i, z) in [0.05, shelf + 0.012].into_iter().enumerate() {
        for k in 0..n {
            let x = xm + 0.01 + (k as f64 + 0.5) * pitch;
            let v = (k + 2 * i) as u32;
            b.cylinder(Books, [x, hd - 0.1, z], 0.025, 0.12 + 0.02 * (k % 3) as f64);
            b.cuboid_v(
                Books,
                v,
                [x - 0.02, hd - 0.1, z],
                [x + 0.02, hd - 0.08, z + 0.01],
            );
        }
    }
    // The mirror panel against the wall, glass inset, bulbs around it.
    let side = (0.2 * b.w).clamp(0.12, 0.25);
    let (mx, my) = (hw - side, -hd);
    let (z0, z1) = (zc + 0.06, h - 0.02);
    b.cuboid(Frame, [-mx, my, z0], [mx, my + 0.04, z1]);
    b.cuboid(
        Canvas,
        [-mx + 0.07, my + 0.04, z0 + 0.07],
        [mx - 0.07, my + 0.045, z1 - 0.07],
    );
    let nb = ((z1 - z0) / 0.16).floor().max(3.0) as usize;
    for k in 0..nb {
        let z = z0 + 0.07 + (k as f64 + 0.5) * (z1 - z0 - 0.14) / nb as f64;
        for sx in [-1.0, 1.0] {
            b.ellipsoid(
                Light,
                [sx * (mx - 0.035), my + 0.06, z],
                [0.022, 0.022, 0.022],
            );
        }
    }
    let nt = ((2.0 * mx) / 0.16).floor().max(3.0) as usize;
    for k in 0..nt {
        let x = -mx + 0.07 + (k as f64 + 0.5) * (2.0 * mx - 0.14) / nt as f64;
        b.ellipsoid(Light, [x, my + 0.06, z1 - 0.035], [0.022, 0.022, 0.022]);
    }
    // Tool shelves either side of the mirror: side boards with three shelves of bottles.
    for sx in [-1.0, 1.0] {
        let (xa, xb) = if sx < 0.0 {
            (-hw, -mx - 0.02)
        } else {
            (mx + 0.02, hw)
        };
        b.cuboid(Frame, [xa, my, z0], [xb, my + 0.02, z0 + 0.62 * (z1 - z0)]);
        for j in 0..3 {
            let z = z0 + 0.05 + j as f64 * 0.2 * (z1 - z0);
            b.cuboid(Frame, [xa, my, z - 0.012], [xb, my + 0.16, z]);
            let cx = 0.5 * (xa + xb);
            let bw = 0.22 * (xb - xa);
            for (k, x) in [cx - bw, cx + bw].into_iter().enumerate() {
                b.push(
                    Books,
                    (j * 2 + k) as u32,
                    super::parts::Primitive::Revolved {
                        origin: [x, my + 0.08, z],
                        rot: IDENTITY,
                        ay: 1.0,
                        profile: super::parts::frustum_profile(0.025, 0.015, 0.11),
                    },
                );
            }
        }
    }
    // The dryer in its holster on the right end of the counter.
    let xd = hw - 0.08;
    b.rod(Metal, [xd, hd - 0.05, zc], [xd, hd - 0.05, zc + 0.12], 0.03);
    b.ellipsoid(Handle, [xd, hd - 0.08, zc + 0.17], [0.04, 0.08, 0.045]);
}

/// An upholstered footstool: a piped cushion with a tufted top (buttons in a grid) on four
/// short turned legs. The cushion is at most about half the footprint thick, so a small stool
/// stands higher on its legs.
pub fn footstool(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pad = (0.58 * b.w.min(b.d)).min(0.8 * h);
    let z0 = h - pad;
    // The cushion: a rounded-square body (an elliptic frustum slightly swelling at the top)
    // and its crowned top.
    b.frustum(
        Upholstery,
        [0.0, 0.0, z0],
        0.94 * hw,
        0.94 * hd,
        1.05,
        pad - 0.04,
    );
    b.frustum(
        Upholstery,
        [0.0, 0.0, h - 0.045],
        0.985 * hw,
        0.985 * hd,
        0.97,
        0.03,
    );
    b.frustum(Frame, [0.0, 0.0, z0 - 0.01], 0.9 * hw, 0.9 * hd, 1.0, 0.02);
    // Piping round the top edge.
    let n = 24;
    let ring: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            [0.985 * hw * a.cos(), 0.985 * hd * a.sin(), h - 0.045]
        })
        .collect();
    b.polyline(Cushion, &ring, 0.008);
    // Buttons: a diamond grid on the top.
    let r = (0.05 * b.w.min(b.d)).clamp(0.014, 0.024);
    for (fx, fy) in [
        (0.0, 0.0),
        (-0.45, 0.0),
        (0.45, 0.0),
        (0.0, -0.45),
        (0.0, 0.45),
    ] {
        b.ellipsoid(Cushion, [fx * hw, fy * hd, h - 0.012], [r, r, 0.01]);
    }
    // Four turned legs, splayed a little.
    let lh = z0;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * 0.62 * hw, sy * 0.62 * hd);
            let lr = (0.06 * b.w.min(b.d)).clamp(0.015, 0.03);
            b.frustum(Frame, [x, y, 0.0], 0.6 * lr, 0.6 * lr, 1.6, lh);
        }
    }
}
