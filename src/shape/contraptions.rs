//! Layouts of machines people name that used to borrow a boxy appliance's drawing (a white
//! cabinet with a window and a door): a printing press (an iron staple over a long bed, the
//! screw and platen in it, a bar handle out to the side, paper on the tympan), an x-ray machine
//! (a patient table, a column with an arm carrying the tube head over the table) and a time
//! machine (a velvet seat on a brass sled, a control pillar before it with levers, the great
//! disc behind it). The front faces +y; each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use std::f64::consts::TAU;

/// A hand printing press: a long bed on four legs running front to back, an iron staple (two
/// cheeks and a crown) over its middle, the screw down from the crown to the platen just over
/// the bed, the type forme under it, a sheet on the tympan at the front of the bed, the bar
/// handle swinging out to the right with a wooden grip, and the rounce (the bed's crank) at
/// the front right.
pub fn printing_press(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.5 * h;
    let bw = 0.32 * hw;
    // The bed's stand: four legs and two rails front to back.
    let leg = 0.05 * hw.min(hd).max(0.4);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (bw - leg), sy * (0.9 * hd - leg));
            b.cuboid(
                Frame,
                [x - leg, y - leg, 0.0],
                [x + leg, y + leg, zb - 0.03 * h],
            );
        }
        b.cuboid(
            Frame,
            [sx * bw - leg, -0.95 * hd, zb - 0.06 * h],
            [sx * bw + leg, 0.95 * hd, zb - 0.02 * h],
        );
    }
    // The bed, the forme on it under the platen, the tympan with its sheet at the front.
    b.cuboid(Body, [-bw, -0.95 * hd, zb - 0.02 * h], [bw, 0.95 * hd, zb]);
    b.cuboid(
        Interior,
        [-0.7 * bw, -0.3 * hd, zb],
        [0.7 * bw, 0.3 * hd, zb + 0.02 * h],
    );
    b.cuboid(
        Frame,
        [-0.85 * bw, 0.4 * hd, zb],
        [0.85 * bw, 0.93 * hd, zb + 0.01 * h],
    );
    b.cuboid(
        Canvas,
        [-0.75 * bw, 0.45 * hd, zb + 0.01 * h],
        [0.75 * bw, 0.88 * hd, zb + 0.014 * h],
    );
    // The staple: a heavy foot under the bed, two cheeks up either side, the crown over them.
    let (cx0, cx1) = (bw + 0.02 * hw, bw + 0.14 * hw);
    let cy = 0.16 * hd;
    b.cuboid(Metal, [-cx1, -cy, 0.0], [cx1, cy, 0.08 * h]);
    for sx in [-1.0, 1.0] {
        let (a, c) = if sx < 0.0 { (-cx1, -cx0) } else { (cx0, cx1) };
        b.cuboid(Metal, [a, -cy, 0.08 * h], [c, cy, 0.86 * h]);
    }
    b.cuboid(Metal, [-cx1, -1.2 * cy, 0.8 * h], [cx1, 1.2 * cy, 0.9 * h]);
    // The counterweight's finial on the crown.
    b.ellipsoid(
        Handle,
        [0.0, 0.0, 0.94 * h],
        [0.12 * hw, 0.7 * cy, 0.06 * h],
    );
    // The screw and the platen hung from it over the forme.
    let zp = zb + 0.1 * h;
    b.cylinder(Metal, [0.0, 0.0, zp + 0.02 * h], 0.05 * hw, 0.78 * h);
    b.cuboid(
        Metal,
        [-0.8 * bw, -0.36 * hd, zp],
        [0.8 * bw, 0.36 * hd, zp + 0.03 * h],
    );
    // The bar handle out to the right, its wooden grip at the end.
    let zh = 0.72 * h;
    let end = [0.8 * hw, 0.55 * hd, zh - 0.04 * h];
    b.polyline(
        Metal,
        &[[0.0, 0.0, zh], [cx1 + 0.05 * hw, 0.2 * hd, zh], end],
        0.022 * h.min(1.6),
    );
    b.rod(
        Frame,
        end,
        [0.98 * hw, 0.62 * hd, zh - 0.05 * h],
        0.03 * h.min(1.6),
    );
    // The rounce: a crank of four spokes on the bed's right side at the front.
    let (rx, ry, rz) = (bw + 0.06 * hw, 0.75 * hd, zb - 0.04 * h);
    b.rod(Metal, [bw, ry, rz], [rx, ry, rz], 0.02);
    let r = 0.12 * h.min(1.6);
    for k in 0..4 {
        let a = k as f64 / 4.0 * TAU + 0.4;
        let tip = [rx, ry + r * a.cos(), rz + r * a.sin()];
        b.rod(Frame, [rx, ry, rz], tip, 0.015);
    }
}

/// An x-ray machine: a padded patient table on a pedestal at the front, a column at the back
/// rising nearly to the top with an arm reaching forward from it, the tube head hung from
/// the arm over the table's middle with its collimator (lit crosshair) pointing down, and the
/// detector tray under the table top.
pub fn xray_machine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.4 * h;
    let (y0, y1) = (-0.15 * hd, hd);
    let yc = 0.5 * (y0 + y1);
    // The table: a pedestal, the detector tray under the top, the padded top.
    b.cuboid(
        Body,
        [-0.3 * hw, yc - 0.2 * hd, 0.0],
        [0.3 * hw, yc + 0.2 * hd, 0.05 * h],
    );
    b.cuboid(
        Body,
        [-0.15 * hw, yc - 0.12 * hd, 0.05 * h],
        [0.15 * hw, yc + 0.12 * hd, zt - 0.06 * h],
    );
    b.cuboid(
        Metal,
        [-0.5 * hw, y0 + 0.05 * hd, zt - 0.06 * h],
        [0.5 * hw, y1 - 0.05 * hd, zt - 0.03 * h],
    );
    b.cuboid(Top, [-hw, y0, zt - 0.03 * h], [hw, y1, zt]);
    b.cuboid(
        Cushion,
        [-0.97 * hw, y0 + 0.03 * hd, zt],
        [0.97 * hw, y1 - 0.03 * hd, zt + 0.015 * h],
    );
    // The column on its floor plate at the back, the arm forward from it.
    let cs = 0.1 * hw.min(hd).max(0.3);
    b.cuboid(
        Metal,
        [-2.0 * cs, -hd, 0.0],
        [2.0 * cs, -hd + 3.0 * cs, 0.02 * h],
    );
    b.cuboid(
        Body,
        [-cs, -hd + 0.5 * cs, 0.0],
        [cs, -hd + 2.5 * cs, 0.97 * h],
    );
    let za = 0.8 * h;
    b.cuboid(
        Body,
        [-0.8 * cs, -hd + 2.5 * cs, za],
        [0.8 * cs, yc, za + 0.06 * h],
    );
    // The tube head across the arm's end, the collimator under it.
    let zh = za - 0.07 * h;
    let r = 0.06 * h.min(2.0);
    b.rod(Body, [-0.35 * hw, yc, zh], [0.35 * hw, yc, zh], r);
    b.cuboid(
        Metal,
        [-0.5 * cs, yc - 0.3 * cs, zh],
        [0.5 * cs, yc + 0.3 * cs, za],
    );
    let c = 0.12 * hw.min(hd);
    b.cuboid(Body, [-c, yc - c, zh - r - 0.08 * h], [c, yc + c, zh - r]);
    b.cuboid(
        Light,
        [-0.7 * c, yc - 0.7 * c, zh - r - 0.082 * h],
        [0.7 * c, yc + 0.7 * c, zh - r - 0.08 * h],
    );
    // Handles either side of the collimator.
    for sx in [-1.0, 1.0] {
        b.rod(
            Handle,
            [sx * c, yc, zh - r - 0.04 * h],
            [sx * 1.6 * c, yc, zh - r - 0.04 * h],
            0.012,
        );
    }
}

/// A time machine: a brass sled (two runners curling up at the front under a wooden deck), a
/// red velvet seat on it facing forward, a brass control pillar before the seat with levers
/// and a crystal on top, a rail round the deck's back corners, and the great brass disc
/// standing upright behind the seat.
pub fn time_machine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The disc: as large as the box allows, its top at the box's top, behind the seat.
    let r = (0.95 * hw).min(0.42 * h);
    let zc = h - r - 0.01 * h;
    let yd = -0.8 * hd;
    let t = 0.03 * hd.max(0.5);
    b.rod(Metal, [0.0, yd - t, zc], [0.0, yd + t, zc], r);
    b.rod(
        Glass,
        [0.0, yd + t, zc],
        [0.0, yd + t + 0.005, zc],
        0.75 * r,
    );
    for k in 0..8 {
        let a = k as f64 / 8.0 * TAU;
        b.rod(
            Handle,
            [0.0, yd + t + 0.01, zc],
            [0.72 * r * a.cos(), yd + t + 0.01, zc + 0.72 * r * a.sin()],
            0.012 * r.max(0.5),
        );
    }
    b.rod(Light, [0.0, yd + t, zc], [0.0, yd + t + 0.04, zc], 0.1 * r);
    // The disc's two standards down to the deck.
    let zd = 0.07 * h;
    for sx in [-1.0, 1.0] {
        b.rod(
            Metal,
            [sx * 0.5 * r, yd, zd],
            [sx * 0.3 * r, yd, zc],
            0.02 * h.max(1.0),
        );
    }
    // The sled: runners curling up at the front, the deck on them.
    let rx = 0.8 * hw;
    for sx in [-1.0, 1.0] {
        let x = sx * rx;
        b.polyline(
            Metal,
            &[
                [x, -0.95 * hd, 0.015 * h],
                [x, 0.75 * hd, 0.015 * h],
                [x, 0.9 * hd, 0.03 * h],
                [x, 0.97 * hd, 0.07 * h],
            ],
            0.015 * h,
        );
        for y in [-0.6 * hd, 0.5 * hd] {
            b.rod(Metal, [x, y, 0.015 * h], [x, y, zd], 0.01 * h);
        }
    }
    b.cuboid(
        Top,
        [-0.9 * hw, -0.95 * hd, zd],
        [0.9 * hw, 0.8 * hd, zd + 0.02 * h],
    );
    // The seat on the deck, facing forward: a base, the velvet cushion, a buttoned back, arms.
    let z0 = zd + 0.02 * h;
    let (sw, ys) = (0.4 * hw, -0.15 * hd);
    let zs = z0 + 0.15 * h.min(3.0);
    b.cuboid(
        Frame,
        [-sw, ys - 0.3 * hd, z0],
        [sw, ys + 0.3 * hd, zs - 0.03],
    );
    b.cuboid(
        Upholstery,
        [-sw, ys - 0.3 * hd, zs - 0.03],
        [sw, ys + 0.3 * hd, zs + 0.04],
    );
    b.cuboid(
        Upholstery,
        [-sw, ys - 0.36 * hd, zs],
        [sw, ys - 0.26 * hd, zs + 0.5],
    );
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Frame,
            [sx * sw - 0.04, ys - 0.3 * hd, zs],
            [sx * sw + 0.04, ys + 0.3 * hd, zs + 0.2],
        );
    }
    // The control pillar before the seat: a brass column, a sloping panel with dials, levers
    // and a crystal.
    let yp = 0.55 * hd;
    let zp = zs + 0.35;
    b.cylinder(Metal, [0.0, yp, z0], 0.06 * hw.max(0.5), zp - z0);
    b.slab(
        Body,
        [0.0, yp, zp],
        [0.3 * hw, 0.1 * hd.max(0.5), 0.02],
        super::parts::rot_x(-0.5),
    );
    for k in 0..3 {
        let x = (k as f64 - 1.0) * 0.18 * hw;
        b.rod(
            Canvas,
            [x, yp - 0.02, zp + 0.03],
            [x, yp - 0.02, zp + 0.035],
            0.03,
        );
    }
    for sx in [-1.0, 1.0] {
        let base = [sx * 0.2 * hw, yp + 0.04, zp + 0.02];
        let top = [sx * 0.22 * hw, yp - 0.02, zp + 0.25];
        b.rod(Metal, base, top, 0.01);
        b.ellipsoid(Light, top, [0.025, 0.025, 0.025]);
    }
    b.ellipsoid(Light, [0.0, yp, zp + 0.1], [0.05, 0.05, 0.07]);
    // A rail round the deck's back corners.
    let zr = zd + 0.3 * h.min(3.0);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.88 * hw;
        b.polyline(
            Metal,
            &[
                [x, -0.2 * hd, zd],
                [x, -0.2 * hd, zr],
                [x, -0.9 * hd, zr],
                [x, -0.9 * hd, zd],
            ],
            0.012,
        );
    }
}
