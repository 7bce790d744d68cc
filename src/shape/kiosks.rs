//! Standing machines a person uses at their front: an arcade cabinet (a marquee lit at the top,
//! a screen tilted back under it, a control panel jutting out with a joystick and buttons, a
//! coin door below, art along both sides, a service door at the back) and a cash machine (a
//! steel kiosk with a small hooded screen, a keypad on a sloping shelf, a card slot and a cash
//! slot, a coloured band at its top and no marquee, a vault door below).
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// An arcade cabinet facing +y.
pub fn arcade(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let side = (0.04 * hw).max(0.012);
    let yb = 0.15 * hd; // the screen's and the panel's back line
                        // The cabinet: a deep back box full height, a lower front under the panel.
                        // The side art and the service door lie on the panels, inside the size box.
    let (hw, hd) = (hw - 0.004, hd - 0.006);
    // The screen leans back from the panel's back line: the box above the panel is set back
    // behind it, closed by the side panels.
    let (s0, s1) = (0.6 * h, 0.82 * h);
    let lean: f64 = 0.3;
    let ys = yb - (s1 - s0 + 0.04) * lean.sin() - 0.01;
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, yb, 0.56 * h]);
    b.cuboid(Body, [-hw, -hd, 0.5 * h], [hw, ys, 0.96 * h]);
    b.cuboid(Body, [-hw, yb, 0.0], [hw, 0.55 * hd, 0.5 * h]);
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Body,
            [sx * (hw - side), ys, 0.5 * h],
            [sx * hw, yb, 0.96 * h],
        );
    }
    // Side art on both sides: a broad band sweeping up from the front.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw + 0.002);
        b.cuboid(
            Canvas,
            [x - 0.001, -0.7 * hd, 0.12 * h],
            [x + 0.001, 0.5 * hd, 0.45 * h],
        );
        b.cuboid(
            Canvas,
            [x - 0.001, -0.6 * hd, 0.45 * h],
            [x + 0.001, 0.1 * hd, 0.85 * h],
        );
    }
    // Coin door with two lit coin slots.
    let yf = 0.55 * hd;
    b.cuboid(
        Door,
        [-0.35 * hw, yf, 0.18 * h],
        [0.35 * hw, yf + 0.006, 0.36 * h],
    );
    for sx in [-1.0, 1.0] {
        let x = sx * 0.15 * hw;
        b.cuboid(
            Light,
            [x - 0.03 * hw, yf + 0.006, 0.3 * h],
            [x + 0.03 * hw, yf + 0.01, 0.33 * h],
        );
    }
    // The control panel, out past the lower front, sloping down towards the player.
    let (pz, pt) = (0.52 * h, 0.04 * h);
    let tilt = rot_x(-0.2);
    let pc = [0.0, 0.5 * (yb + hd), pz + pt];
    b.slab(Top, pc, [hw - side, 0.5 * (hd - yb), pt], tilt);
    let on_panel = |x: f64, y: f64| {
        [
            x,
            pc[1] + y * (hd - yb),
            pz + 2.0 * pt - 0.2 * y * (hd - yb),
        ]
    };
    let stick = on_panel(-0.45 * hw, 0.0);
    let knob = [stick[0], stick[1], stick[2] + 0.06 * h];
    b.rod(Metal, stick, knob, 0.012 * h.min(2.0));
    b.ellipsoid(Handle, knob, [0.025 * h; 3].map(|v: f64| v.min(0.05)));
    for (i, (x, y)) in [
        (0.05, 0.1),
        (0.25, 0.15),
        (0.45, 0.2),
        (0.15, -0.15),
        (0.35, -0.1),
        (0.55, -0.05),
    ]
    .iter()
    .enumerate()
    {
        let p = on_panel(x * hw, y * 1.0);
        let r = 0.06 * hw;
        let role = if i % 2 == 0 { Handle } else { Light };
        b.cylinder(role, [p[0], p[1], p[2] - 0.005], r, 0.015);
    }
    // The screen, tilted back under a bezel.
    let sc = [0.0, yb - 0.5 * (s1 - s0) * lean.sin(), 0.5 * (s0 + s1)];
    b.slab(
        Body,
        sc,
        [hw - side, 0.01, 0.5 * (s1 - s0) + 0.02],
        rot_x(lean),
    );
    let sc = [sc[0], sc[1] + 0.012, sc[2]];
    b.slab(
        Screen,
        sc,
        [0.8 * (hw - side), 0.003, 0.42 * (s1 - s0)],
        rot_x(lean),
    );
    // The marquee, lit, jutting forward over the screen.
    b.cuboid(Body, [-hw, yb, 0.84 * h], [hw, 0.45 * hd, 0.98 * h]);
    b.cuboid(
        Light,
        [-(hw - side), 0.45 * hd, 0.855 * h],
        [hw - side, 0.45 * hd + 0.004, 0.965 * h],
    );
    b.cuboid(Body, [-hw, -hd, 0.96 * h], [hw, 0.45 * hd, h]);
    // The service door at the back with vents over it.
    b.cuboid(
        Frame,
        [-0.7 * hw, -hd - 0.004, 0.1 * h],
        [0.7 * hw, -hd, 0.7 * h],
    );
    for k in 0..4 {
        let z = 0.76 * h + k as f64 * 0.03 * h;
        b.cuboid(
            Interior,
            [-0.5 * hw, -hd - 0.005, z],
            [0.5 * hw, -hd, z + 0.012 * h],
        );
    }
}

/// A free-standing cash machine facing +y.
pub fn atm(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yf = 0.6 * hd; // the fascia's plane, set back under a hood
                       // The band of colour round the top lies on the body, inside the size box.
    let (hw, hd) = (hw - 0.004, hd - 0.004);
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, yf, h]);
    b.cuboid(Body, [-hw, yf, 0.0], [hw, hd, 0.45 * h]);
    // The hood over the fascia and the band of colour round the top.
    for sx in [-1.0, 1.0] {
        b.cuboid(
            Body,
            [sx * hw - 0.08 * hw, yf, 0.45 * h],
            [sx * hw, hd, 0.82 * h],
        );
    }
    b.cuboid(Top, [-hw, yf, 0.82 * h], [hw, hd, 0.86 * h]);
    b.cuboid(
        Canvas,
        [-hw - 0.003, -hd - 0.003, 0.86 * h],
        [hw + 0.003, hd + 0.003, h - 0.002],
    );
    // The fascia: dark, a small screen with keys either side.
    b.cuboid(
        Top,
        [-0.92 * hw, yf, 0.45 * h],
        [0.92 * hw, yf + 0.004, 0.82 * h],
    );
    let (sz0, sz1) = (0.62 * h, 0.77 * h);
    let sw = 0.38 * hw;
    b.cuboid(Screen, [-sw, yf + 0.004, sz0], [sw, yf + 0.008, sz1]);
    for sx in [-1.0, 1.0] {
        for k in 0..3 {
            let z = sz0 + (0.2 + 0.3 * k as f64) * (sz1 - sz0);
            let x = sx * (sw + 0.1 * hw);
            b.cuboid(
                Keys,
                [x - 0.05 * hw, yf + 0.004, z - 0.012 * h],
                [x + 0.05 * hw, yf + 0.012, z + 0.012 * h],
            );
        }
    }
    // The card slot with its lit bezel, right of the screen.
    let cx = 0.72 * hw;
    b.cuboid(
        Light,
        [cx - 0.1 * hw, yf + 0.004, 0.56 * h],
        [cx + 0.1 * hw, yf + 0.02, 0.6 * h],
    );
    b.cuboid(
        Interior,
        [cx - 0.07 * hw, yf + 0.02, 0.575 * h],
        [cx + 0.07 * hw, yf + 0.022, 0.585 * h],
    );
    // The keypad on a shelf sloping down towards the user.
    let shelf = [0.0, 0.5 * (yf + hd), 0.47 * h];
    b.slab(
        Top,
        shelf,
        [0.9 * hw, 0.5 * (hd - yf), 0.02 * h],
        rot_x(-0.25),
    );
    let kw = 0.07 * hw;
    for row in 0..4 {
        for col in 0..3 {
            let x = -0.35 * hw + (col as f64 - 1.0) * 2.6 * kw;
            let t = (row as f64 + 0.5) / 4.0;
            let y = yf + (0.15 + 0.7 * t) * (hd - yf);
            let z = 0.49 * h + 0.25 * (hd - yf) * (0.5 - t) * 0.5 + 0.005;
            b.cuboid(
                Keys,
                [x - kw, y - 0.35 * (hd - yf) / 4.0, z],
                [x + kw, y + 0.35 * (hd - yf) / 4.0, z + 0.008],
            );
        }
    }
    // The cash slot under the shelf, and the receipt slot beside the keypad.
    b.cuboid(
        Interior,
        [-0.4 * hw, hd, 0.38 * h],
        [0.4 * hw, hd + 0.003, 0.41 * h],
    );
    b.cuboid(
        Metal,
        [-0.46 * hw, hd, 0.36 * h],
        [0.46 * hw, hd + 0.002, 0.43 * h],
    );
    b.cuboid(
        Interior,
        [0.3 * hw, hd - 0.01, 0.5 * h],
        [0.6 * hw, hd + 0.002, 0.51 * h],
    );
    // The vault door below.
    b.cuboid(
        Door,
        [-0.8 * hw, hd, 0.05 * h],
        [0.8 * hw, hd + 0.005, 0.33 * h],
    );
    b.cuboid(
        Handle,
        [0.55 * hw, hd + 0.005, 0.17 * h],
        [0.65 * hw, hd + 0.02, 0.21 * h],
    );
}
