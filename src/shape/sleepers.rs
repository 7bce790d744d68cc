//! Layouts of beds that are more than a mattress on a frame: a hospital bed (a deck on a lift
//! over a castored base, its head section raised, head and foot boards, split side rails) and a
//! cabin bed or mid-sleeper (a single bed raised on posts with a guard rail all round, a ladder
//! at its foot end and drawers beneath it). The head is at -y, the foot at +y.
use super::archetypes::Builder;
use super::fittings::{castor, pad};
use super::materials::Role::*;

/// A hospital bed: castors at the corners, a base frame, a lift column, the mattress deck with
/// its head section raised at 30°, a pillow on it, a folded blanket, a white head board and a
/// lower foot board, and side rails at the head half on both sides.
pub fn hospital_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rc = 0.06;
    let zb = 2.0 * rc + 0.05;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            castor(b, sx * (hw - 0.1), sy * (hd - 0.15), rc, zb);
        }
    }
    b.cuboid(
        Frame,
        [-hw + 0.12, -hd + 0.1, zb],
        [hw - 0.12, hd - 0.1, zb + 0.05],
    );
    for y in [-0.25 * hd, 0.25 * hd] {
        b.cuboid(
            Metal,
            [-0.1, y - 0.08, zb + 0.05],
            [0.1, y + 0.08, 0.45 * h],
        );
    }
    // The deck and the mattress: flat from the hinge to the foot, raised behind it.
    let zd = (0.5 * h).min(0.55);
    let mt = 0.13;
    b.cuboid(
        Frame,
        [-hw + 0.06, -hd + 0.06, zd - 0.04],
        [hw - 0.06, hd - 0.06, zd],
    );
    let xm = hw - 0.08;
    let hinge = -hd + 0.06 + (0.36 * b.d).min(0.8);
    b.cuboid(Mattress, [-xm, hinge, zd], [xm, hd - 0.07, zd + mt]);
    let a = 30f64.to_radians();
    let len = ((h - 0.04 - zd - mt) / a.sin()).min(hinge + hd - 0.1);
    let mid = zd + mt / 2.0;
    let head = [hinge - len * a.cos(), mid + len * a.sin()];
    pad(b, Mattress, 0.0, [hinge + 0.02, mid], head, xm, mt);
    // The deck's raised section under it.
    let under = [
        head[0] + 0.5 * mt * a.sin(),
        head[1] - 0.5 * mt * a.cos() - 0.02,
    ];
    pad(b, Frame, 0.0, [hinge, zd - 0.02], under, hw - 0.06, 0.03);
    let p = 0.75;
    let pil = [
        hinge + p * (head[0] - hinge) + 0.06 * a.sin(),
        mid + p * (head[1] - mid) + 0.06 * a.cos() + 0.04,
    ];
    pad(
        b,
        Pillow,
        0.0,
        [pil[0] + 0.12 * a.cos(), pil[1] - 0.12 * a.sin()],
        [pil[0] - 0.12 * a.cos(), pil[1] + 0.12 * a.sin()],
        0.6 * xm,
        0.08,
    );
    b.cuboid(
        Duvet,
        [-xm - 0.01, hinge + 0.25, zd + mt],
        [xm + 0.01, hd - 0.12, zd + mt + 0.05],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * (xm + 0.005);
        b.cuboid(
            Duvet,
            [x - 0.005, hinge + 0.25, zd + 0.03],
            [x + 0.005, hd - 0.12, zd + mt + 0.05],
        );
    }
    // Head board to the full height, foot board lower, both plastic panels on posts.
    b.cuboid(
        Body,
        [-hw + 0.02, -hd, zd - 0.08],
        [hw - 0.02, -hd + 0.05, h],
    );
    b.cuboid(
        Body,
        [-hw + 0.02, hd - 0.05, zd - 0.08],
        [hw - 0.02, hd, zd + 0.35],
    );
    b.cuboid(
        Screen,
        [-0.15, hd - 0.003, zd + 0.12],
        [0.15, hd, zd + 0.26],
    );
    // Split side rails at the head half: two bars on three posts, off the mattress's side.
    let (y0, y1) = (-hd + 0.15, hinge + 0.15);
    let (z0, z1) = (zd + mt + 0.06, zd + mt + 0.26);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.02);
        for z in [z0, z1] {
            b.rod(Metal, [x, y0, z], [x, y1, z], 0.014);
        }
        for t in [0.0, 0.5, 1.0] {
            let y = y0 + t * (y1 - y0);
            b.rod(Metal, [x, y, zd - 0.02], [x, y, z1], 0.012);
        }
        b.cuboid(Top, [x - 0.01, y0, z0 + 0.03], [x + 0.01, y1, z1 - 0.03]);
    }
}

/// A cabin bed (a mid-sleeper): four posts carrying a single bed well above the floor, a guard
/// rail on all four sides with a gap at the ladder, the ladder down from the foot end, and a
/// chest of drawers under the deck beside it.
pub fn cabin_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let post = 0.06;
    let zd = (0.62 * h).clamp(0.6, 1.3);
    let zm = zd + 0.16;
    let top = h;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - post / 2.0), sy * (hd - post / 2.0));
            b.cuboid(
                Frame,
                [x - post / 2.0, y - post / 2.0, 0.0],
                [x + post / 2.0, y + post / 2.0, top],
            );
        }
    }
    // The deck's side boards and the mattress with a duvet and a pillow.
    b.cuboid(Frame, [-hw, -hd, zd - 0.14], [hw, hd, zd]);
    b.cuboid(
        Mattress,
        [-hw + post, -hd + post, zd],
        [hw - post, hd - post, zm],
    );
    b.cuboid(
        Duvet,
        [-hw + post, -hd + 0.55, zm],
        [hw - post, hd - post, zm + 0.05],
    );
    b.cuboid(
        Pillow,
        [-hw + 0.15, -hd + post + 0.05, zm],
        [hw - 0.15, -hd + 0.45, zm + 0.1],
    );
    // Guard rails: full at the head and along both sides; at the foot, up to the ladder's
    // opening.
    let ladder_w = (0.45 * b.w).min(0.45);
    let (xa, xb) = (hw - post - ladder_w, hw - post - 0.02);
    let rail = |b: &mut Builder, x: [f64; 2], y: [f64; 2]| {
        b.cuboid(Frame, [x[0], y[0], top - 0.06], [x[1], y[1], top]);
        b.cuboid(Frame, [x[0], y[0], zm + 0.02], [x[1], y[1], zm + 0.06]);
    };
    rail(b, [-hw + post, hw - post], [-hd, -hd + 0.03]);
    rail(b, [-hw + post, xa - 0.02], [hd - 0.03, hd]);
    rail(b, [-hw, -hw + 0.03], [-hd + post, hd - post]);
    rail(b, [hw - 0.03, hw], [-hd + post, hd - post]);
    b.cuboid(Frame, [xa - 0.06, hd - 0.03, zd], [xa - 0.02, hd, top]);
    // The ladder at the foot end: two stiles and flat treads in a natural wood.
    let yl = hd - 0.02;
    for x in [xa, xb] {
        b.cuboid(
            Top,
            [x - 0.02, yl - 0.02, 0.0],
            [x + 0.02, yl + 0.02, top - 0.06],
        );
    }
    let rungs = ((zd / 0.27).round() as usize).max(2);
    for k in 1..=rungs {
        let z = k as f64 * zd / rungs as f64;
        b.cuboid(
            Top,
            [xa + 0.02, yl - 0.03, z - 0.02],
            [xb - 0.02, yl + 0.02, z + 0.01],
        );
    }
    // A chest of drawers under the deck at the foot end, beside the ladder, facing the room.
    let (x0, x1) = (-hw + post, xa - 0.08);
    let (y0, y1) = (hd - 0.5, hd - 0.04);
    let zt = (0.8 * zd).min(zd - 0.2);
    b.cuboid(Body, [x0, y0, 0.0], [x1, y1, zt]);
    let n = 3;
    for k in 0..n {
        let z0 = 0.04 + k as f64 * (zt - 0.06) / n as f64;
        let z1 = z0 + (zt - 0.06) / n as f64 - 0.02;
        b.cuboid(Door, [x0 + 0.02, y1, z0], [x1 - 0.02, y1 + 0.02, z1]);
        let zh = 0.5 * (z0 + z1);
        let xm = 0.5 * (x0 + x1);
        b.cuboid(
            Handle,
            [xm - 0.06, y1 + 0.02, zh - 0.01],
            [xm + 0.06, y1 + 0.035, zh + 0.01],
        );
    }
}
