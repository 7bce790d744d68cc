//! Layouts of coin-operated amusement machines, each its own silhouette rather than one lit
//! cabinet: a jukebox (a cabinet under a rounded arch edged with coloured light tubes, a record
//! behind its window, a row of selector keys over a speaker grille), a pinball machine (a
//! sloped playfield under glass on four legs, a tall backbox at its far end), a slot machine
//! (a cabinet with three reels in a window, a button deck, a tray and a lever at its side) and
//! a popcorn machine (a glass box heaped with popcorn, a kettle hanging in it, on a red cart
//! with wheels). The player stands at the front (+y); everything stays inside the size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{rot_x, IDENTITY};
use std::f64::consts::PI;

/// Points of an arc of radius `r` about `(0, y, zc)` in the x-z plane, from angle `a0` to `a1`
/// (radians from +x, counter-clockwise towards +z), `n` segments.
fn arc(r: f64, y: f64, zc: f64, (a0, a1): (f64, f64), n: usize) -> Vec<[f64; 3]> {
    (0..=n)
        .map(|i| {
            let a = a0 + (a1 - a0) * i as f64 / n as f64;
            [r * a.cos(), y, zc + r * a.sin()]
        })
        .collect()
}

/// A jukebox: a cabinet whose top is a half round arch, coloured light tubes running up its
/// front edges and round the arch, a record standing behind the glass window under the arch,
/// a strip of selector keys, a speaker grille below; vents at the back.
pub fn jukebox(b: &mut Builder) {
    let (hw, hd0, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The cabinet's front stands back from the size box so its tubes and keys stay inside.
    let hd = hd0 - 0.04;
    let (g, yt) = (0.01, hd + 0.005);
    // The arch's centre: its round top touches the top of the size box.
    let zc = h - hw;
    b.cuboid(Body, [-hw, -hd0, 0.0], [hw, hd, zc]);
    b.rod(Body, [0.0, -hd0, zc], [0.0, hd, zc], hw);
    b.cuboid(Frame, [-hw, -hd0, 0.0], [hw, hd + 0.02, 0.06]);
    // Light tubes: up each front edge and round the arch, outer red, inner amber.
    for (role, inset, r) in [(Upholstery, 0.03, 0.03), (Light, 0.09, 0.025)] {
        let ri = hw - inset;
        let mut pts = vec![[ri, yt, 0.1 * h]];
        pts.extend(arc(ri, yt, zc, (0.0, PI), 16));
        pts.push([-ri, yt, 0.1 * h]);
        b.polyline(role, &pts, r);
    }
    // The window under the arch (a round-topped pane of dark glass), a record standing behind
    // it with its label, a blue tube framing it.
    let rw = hw - 0.16;
    let zw = zc - rw;
    b.cuboid(Interior, [-rw, hd, zw], [rw, hd + g, zc]);
    b.rod(Interior, [0.0, hd, zc], [0.0, hd + g, zc], rw);
    let rr = (0.6 * rw).min(0.2);
    let zr = zc - 0.1 * rw;
    b.rod(BlackKeys, [0.0, hd + g, zr], [0.0, hd + g + 0.004, zr], rr);
    b.rod(
        Cushion,
        [0.0, hd + g + 0.004, zr],
        [0.0, hd + g + 0.008, zr],
        0.35 * rr,
    );
    b.polyline(Seat, &arc(rw + 0.02, yt, zc, (0.0, PI), 12), 0.015);
    // Selector keys on a chrome strip, then the speaker grille.
    let zk = zw - 0.08 * h;
    b.cuboid(Metal, [-rw, hd, zk], [rw, hd + g, zw - 0.01]);
    let n = 10;
    for i in 0..n {
        let x = -rw + (i as f64 + 0.5) * 2.0 * rw / n as f64;
        b.cuboid(
            Keys,
            [x - 0.015, hd + g, zk + 0.02],
            [x + 0.015, hd + 2.0 * g, zw - 0.03],
        );
    }
    let (zg0, zg1) = (0.12 * h, zk - 0.04);
    b.cuboid(Interior, [-rw, hd, zg0], [rw, hd + g, zg1]);
    for i in 0..7 {
        let x = -rw + (i as f64 + 0.5) * 2.0 * rw / 7.0;
        b.cuboid(
            Metal,
            [x - 0.006, hd + g, zg0],
            [x + 0.006, hd + 2.0 * g, zg1],
        );
    }
    // The back: vent slots in a service panel.
    for i in 0..5 {
        let z = 0.3 * h + i as f64 * 0.06 * h;
        b.cuboid(
            Interior,
            [-0.6 * hw, -hd0, z],
            [0.6 * hw, -hd0 + g, z + 0.02 * h],
        );
    }
}

/// A pinball machine: a cabinet on four legs whose glass-covered playfield slopes up away from
/// the player, bumpers and flippers on it, a tall backbox with a lit backglass at the far end,
/// a coin door and a plunger at the front.
pub fn pinball(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let leg = 0.045;
    let zl = (0.42 * h).min(0.8);
    let (zf, zb) = (zl + 0.2, zl + 0.3); // cabinet top at the front and at the back
    let box_d = (0.16 * b.d).clamp(0.12, 0.25);
    let y_back = -hd + box_d;
    // Legs at the corners of the cabinet.
    for sx in [-1.0, 1.0] {
        for y in [hd - 0.06, y_back + 0.04] {
            let x = sx * (hw - 0.06);
            b.cuboid(
                Metal,
                [x - leg / 2.0, y - leg / 2.0, 0.0],
                [x + leg / 2.0, y + leg / 2.0, zl],
            );
        }
    }
    // The cabinet: a wedge, low at the front, drawn as a box up to the front height and a
    // sloped slab over it.
    let len = hd - y_back;
    let slope = ((zb - zf) / len).atan();
    b.cuboid(Body, [-hw, y_back, zl], [hw, hd, zf - 0.02]);
    let ym = 0.5 * (hd + y_back);
    let zm = 0.5 * (zf + zb);
    b.slab(
        Body,
        [0.0, ym, zm - 0.06],
        [hw, 0.5 * len / slope.cos(), 0.06],
        rot_x(-slope),
    );
    // The playfield under its glass, bumpers and flippers on it.
    let top = |y: f64| zf + (hd - y) * (zb - zf) / len;
    let inner = hw - 0.04;
    b.slab(
        Canvas,
        [0.0, ym, zm + 0.003],
        [inner, 0.48 * len / slope.cos(), 0.004],
        rot_x(-slope),
    );
    for (fx, fy) in [(-0.35, 0.35), (0.35, 0.35), (0.0, 0.55), (0.0, 0.2)] {
        let y = hd - fy * len;
        b.cylinder(Upholstery, [fx * inner, y, top(y)], 0.045, 0.05);
    }
    for sx in [-1.0, 1.0] {
        let y = hd - 0.1 * len;
        b.rod(
            Handle,
            [sx * 0.35 * inner, y + 0.03, top(y) + 0.02],
            [sx * 0.08 * inner, y - 0.02, top(y) + 0.02],
            0.015,
        );
    }
    b.slab(
        Pane,
        [0.0, ym, zm + 0.05],
        [inner, 0.48 * len / slope.cos(), 0.003],
        rot_x(-slope),
    );
    for sx in [-1.0, 1.0] {
        b.slab(
            Metal,
            [sx * (hw - 0.015), ym, zm + 0.03],
            [0.015, 0.5 * len / slope.cos(), 0.03],
            rot_x(-slope),
        );
    }
    // The backbox: a tall box at the far end, its lit backglass facing the player.
    let zb0 = zb - 0.05;
    b.cuboid(Body, [-hw, -hd, zb0], [hw, y_back, h]);
    b.cuboid(Top, [-hw, -hd, h - 0.03], [hw, y_back + 0.01, h]);
    b.cuboid(
        Light,
        [-hw + 0.05, y_back, zb0 + 0.12 * (h - zb0)],
        [hw - 0.05, y_back + 0.01, h - 0.08 * (h - zb0)],
    );
    b.cuboid(
        Interior,
        [-0.4 * hw, y_back + 0.01, zb0 + 0.05],
        [0.4 * hw, y_back + 0.015, zb0 + 0.1 * (h - zb0)],
    );
    b.cuboid(Body, [-hw, -hd + 0.02, zb - 0.3], [hw, y_back, zb0]);
    // The front: coin door, the plunger at the right and flipper buttons on the sides.
    b.cuboid(
        Metal,
        [-0.35 * hw, hd, zl + 0.03],
        [0.35 * hw, hd + 0.01, zf - 0.06],
    );
    b.rod(
        Handle,
        [0.7 * hw, hd, zf - 0.07],
        [0.7 * hw, hd + 0.06, zf - 0.07],
        0.012,
    );
    for sx in [-1.0, 1.0] {
        b.rod(
            Light,
            [sx * hw, hd - 0.12, zf - 0.07],
            [sx * (hw + 0.01), hd - 0.12, zf - 0.07],
            0.02,
        );
    }
}

/// A slot machine: a cabinet on a plinth with a lit topper, three reels side by side in a
/// window, a sloping button deck, a lit belly panel, a coin tray at the bottom and a lever
/// with a ball knob at its right side.
pub fn slot_machine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let g = 0.012;
    let lever = (0.12 * b.w).clamp(0.05, 0.09);
    let cw = hw - lever; // the cabinet's half width, the lever beside it
    let x0 = -hw;
    let cx = x0 + cw; // the cabinet's centre line
    let (hd, y1) = (hd - 2.0 * g, hd - g);
    let zp = 0.05 * h;
    b.cuboid(Frame, [x0, -hd, 0.0], [x0 + 2.0 * cw, hd, zp]);
    b.cuboid(
        Body,
        [x0, -hd, zp],
        [x0 + 2.0 * cw, hd - 0.05 * b.d, h - 0.12 * h],
    );
    b.cuboid(Body, [x0, -hd, zp], [x0 + 2.0 * cw, hd, 0.5 * h]);
    // The topper: a lit sign crowning the cabinet.
    b.cuboid(
        Light,
        [x0 + 0.04, -hd + 0.05, h - 0.12 * h],
        [x0 + 2.0 * cw - 0.04, hd - 0.05 * b.d, h],
    );
    // The reel window: three reels (drums turning about x) with a symbol each, in a frame.
    let (zr0, zr1) = (0.6 * h, 0.78 * h);
    let yw = hd - 0.05 * b.d;
    // A dark recess behind the reels and a chrome bezel round it, proud of the reels' faces.
    let (xa0, xa1) = (x0 + 0.04, x0 + 2.0 * cw - 0.04);
    b.cuboid(Interior, [xa0, yw, zr0], [xa1, yw + 0.003, zr1]);
    for (lo, hi) in [
        ([xa0, yw, zr0 - 0.025], [xa1, yw + 2.5 * g, zr0]),
        ([xa0, yw, zr1], [xa1, yw + 2.5 * g, zr1 + 0.025]),
        ([xa0, yw, zr0], [xa0 + 0.04, yw + 2.5 * g, zr1]),
        ([xa1 - 0.04, yw, zr0], [xa1, yw + 2.5 * g, zr1]),
    ] {
        b.cuboid(Metal, lo, hi);
    }
    let rw = (2.0 * cw - 0.16) / 3.0;
    let rr = 0.5 * (zr1 - zr0);
    for i in 0..3 {
        let xa = x0 + 0.08 + i as f64 * rw;
        let zc = 0.5 * (zr0 + zr1);
        b.rod(
            Canvas,
            [xa + 0.015, yw - rr + 2.0 * g, zc],
            [xa + rw - 0.015, yw - rr + 2.0 * g, zc],
            rr,
        );
        let xm = xa + 0.5 * rw;
        b.ellipsoid(
            Upholstery,
            [xm, yw + 2.0 * g, zc],
            [0.22 * rw, 0.006, 0.3 * rr],
        );
    }
    // The button deck: a ledge at waist height with buttons; the lit belly panel below.
    let zd = 0.5 * h;
    b.cuboid(Top, [x0, hd - 0.02, zd - 0.03], [x0 + 2.0 * cw, y1, zd]);
    for i in 0..4 {
        let x = x0 + 0.08 + (i as f64 + 0.5) * (2.0 * cw - 0.16) / 4.0;
        b.cuboid(
            Keys,
            [x - 0.025, y1 - 0.06, zd],
            [x + 0.025, y1 - 0.02, zd + 0.015],
        );
    }
    b.cuboid(
        Light,
        [x0 + 0.06, hd, 0.28 * h],
        [x0 + 2.0 * cw - 0.06, y1, zd - 0.06],
    );
    // The coin tray: a steel trough at the bottom of the front.
    let zt = 0.12 * h;
    b.cuboid(
        Interior,
        [cx - 0.6 * cw, hd, zt],
        [cx + 0.6 * cw, hd + 0.003, zt + 0.09],
    );
    b.cuboid(
        Metal,
        [cx - 0.6 * cw, hd, zt],
        [cx + 0.6 * cw, y1, zt + 0.03],
    );
    // The lever on the right side: a pivot box, an arm up and a red ball.
    let xl = x0 + 2.0 * cw;
    let zl = 0.6 * h;
    b.cuboid(
        Metal,
        [xl, -0.06, zl - 0.06],
        [xl + 0.3 * lever, 0.06, zl + 0.06],
    );
    let top = [hw - 0.4 * lever, 0.0, (zl + 0.22 * h).min(h - 0.06)];
    b.rod(Metal, [xl + 0.3 * lever, 0.0, zl], top, 0.015);
    let kr = (0.4 * lever).min(0.045);
    b.ellipsoid(Handle, [top[0], 0.0, top[2]], [kr, kr, kr]);
}

/// A heap of popcorn: a dome of radii `r` standing on `base`.
fn heap(b: &mut Builder, base: [f64; 3], r: [f64; 3]) {
    let n = 8;
    let mut profile: Vec<[f64; 2]> = vec![[0.0, 0.0]];
    profile.extend((0..=n).map(|i| {
        let t = i as f64 / n as f64 * PI / 2.0;
        [r[0] * t.cos(), r[2] * t.sin()]
    }));
    b.revolved(Cushion, 0, base, IDENTITY, r[1] / r[0], profile);
}

/// A popcorn machine: a cart (a red cabinet on legs, two wheels at one end, a handle at the
/// other) carrying a glass box with red corner posts and roof, popcorn heaped inside and a
/// steel kettle hanging from the roof, a lit sign on top.
pub fn popcorn_machine(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let wr = (0.12 * h).min(0.9 * hd).min(0.18);
    let zc = (0.1 * h).max(wr + 0.02); // the cart's floor
    let zt = 0.52 * h; // its top
    let cw = hw - 0.06; // the cart's half width: its wheels stand beside it
                        // The cart: a cabinet with doors on its front, two legs at the front, a wheel on each
                        // side at the back.
    b.cuboid(Body, [-cw, -hd, zc], [cw, hd - 0.01, zt]);
    b.cuboid(
        Door,
        [-cw + 0.03, hd - 0.01, zc + 0.04],
        [cw - 0.03, hd, zt - 0.04],
    );
    b.cuboid(
        Interior,
        [-0.004, hd - 0.012, zc + 0.04],
        [0.004, hd, zt - 0.04],
    );
    let yw = -hd + wr;
    for sx in [-1.0, 1.0] {
        let x = sx * (cw - 0.04);
        b.cuboid(Frame, [x - 0.02, hd - 0.06, 0.0], [x + 0.02, hd - 0.02, zc]);
        b.rod(Tyre, [sx * cw, yw, wr], [sx * hw, yw, wr], wr);
        b.rod(
            Metal,
            [sx * (cw - 0.005), yw, wr],
            [sx * (hw + 0.002), yw, wr],
            0.4 * wr,
        );
    }
    b.cuboid(Top, [-cw, -hd, zt], [cw, hd, zt + 0.03]);
    // The glass box: corner posts, panes, a roof and a sign.
    let (zg0, zg1) = (zt + 0.03, 0.9 * h);
    let (gx, gy) = (cw - 0.02, hd - 0.02);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (gx - 0.015), sy * (gy - 0.015));
            b.cuboid(
                Body,
                [x - 0.015, y - 0.015, zg0],
                [x + 0.015, y + 0.015, zg1],
            );
        }
    }
    for (lo, hi) in [
        ([-gx, gy - 0.004, zg0], [gx, gy, zg1]),
        ([-gx, -gy, zg0], [gx, -gy + 0.004, zg1]),
        ([-gx, -gy, zg0], [-gx + 0.004, gy, zg1]),
        ([gx - 0.004, -gy, zg0], [gx, gy, zg1]),
    ] {
        b.cuboid(Pane, lo, hi);
    }
    b.cuboid(Body, [-cw, -hd, zg1], [cw, hd, zg1 + 0.03]);
    b.cuboid(Light, [-0.8 * cw, -0.004, zg1 + 0.03], [0.8 * cw, 0.004, h]);
    b.cuboid(Body, [-0.85 * cw, -0.01, h - 0.012], [0.85 * cw, 0.01, h]);
    // Popcorn heaped on the floor of the box, higher at the back.
    let gh = zg1 - zg0;
    for (fx, fy, rz) in [
        (-0.45, -0.45, 0.34),
        (0.45, -0.45, 0.3),
        (0.0, -0.3, 0.36),
        (-0.45, 0.4, 0.22),
        (0.45, 0.4, 0.2),
        (0.0, 0.45, 0.24),
    ] {
        heap(b, [fx * gx, fy * gy, zg0], [0.5 * gx, 0.5 * gy, rz * gh]);
    }
    b.cuboid(
        Cushion,
        [-gx + 0.01, -gy + 0.01, zg0],
        [gx - 0.01, gy - 0.01, zg0 + 0.1 * gh],
    );
    // The kettle hanging from the roof.
    let kr = 0.3 * gx.min(gy);
    b.rod(Metal, [0.0, 0.0, zg1], [0.0, 0.0, zg1 - 0.2 * gh], 0.01);
    b.frustum(
        Metal,
        [0.0, 0.0, zg1 - 0.2 * gh - 1.4 * kr],
        kr,
        kr,
        1.15,
        1.4 * kr,
    );
}
