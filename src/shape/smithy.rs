//! Layouts of fires, tools and small rigs: a blacksmith's forge (a brick hearth table with a
//! fire, a hood and flue over it and an anvil on its stump beside), a furnace (a squat metal
//! box with a glowing door and a flue), a two-burner camping stove with its lid and wind
//! shields up, a bench vise, a wedge stage monitor and a toy train set (a loop of track with a
//! little train). The front faces +y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x, rot_z};

/// A blacksmith's forge: a brick hearth table on the left with a fire pot of glowing coals, a
/// sheet-metal hood over it narrowing into a flue that rises to the top, and an anvil on its
/// stump on the right.
pub fn forge(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let xa = hw - 0.32 * b.w;
    let table = (0.6 * h).min(0.8);
    b.cuboid(Body, [-hw, -hd, 0.0], [xa - 0.04, hd, table]);
    b.cuboid(Top, [-hw, -hd, table], [xa - 0.04, hd, table + 0.04]);
    let xc = 0.5 * (-hw + xa - 0.04);
    let rf = 0.22 * (xa - 0.04 + hw);
    b.cylinder(Interior, [xc, 0.1 * hd, table + 0.04], rf, 0.02);
    b.ellipsoid(
        Light,
        [xc, 0.1 * hd, table + 0.06],
        [0.8 * rf, 0.8 * rf, 0.05],
    );
    // The hood: a frustum narrowing upwards from above the hearth, then the flue.
    let zh = table + 0.3 * (h - table);
    let hood = 0.45 * (h - table);
    let rh = (0.5 * (xa + hw) - 0.04).min(0.9 * hd);
    b.frustum(Metal, [xc, -0.15 * hd, zh], rh, 0.8 * hd, 0.3, hood);
    b.cylinder(
        Metal,
        [xc, -0.15 * hd, zh + hood - 0.01],
        0.28 * rh,
        h - zh - hood + 0.01,
    );
    for sx in [-1.0, 1.0] {
        let x = xc + sx * 0.8 * rh;
        b.rod(
            Metal,
            [x, -0.7 * hd, table + 0.04],
            [x, -0.7 * hd, zh + 0.02],
            0.015,
        );
    }
    // The anvil on its stump beside the hearth, drawn by the anvil's own layout at its own
    // proportions (a long face over a narrow waist), turned so its horn points forwards.
    let first = b.parts.len();
    let ah = (0.7 * h).min(0.85);
    let mut anvil = Builder {
        parts: vec![],
        w: (0.8 * b.d).min(0.9 * ah),
        d: (0.8 * (hw - xa)).min(0.45 * ah),
        h: ah,
        goods: None,
        animal: None,
        bird: None,
        variant: 0,
        mount: b.mount,
    };
    super::workshop::anvil(&mut anvil);
    b.parts.extend(anvil.parts);
    b.turn_from(first, rot_z(std::f64::consts::FRAC_PI_2));
    b.translate_from(first, [0.5 * (xa + hw), 0.1 * hd, 0.0]);
}

/// A furnace: a squat metal box on a plinth, a firebox door glowing at its front, a flue
/// rising from the back of its top.
pub fn furnace(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.62 * h;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.06 * h]);
    b.cuboid(
        Body,
        [-0.94 * hw, -0.94 * hd, 0.06 * h],
        [0.94 * hw, 0.94 * hd, top],
    );
    b.cuboid(Top, [-hw, -hd, top], [hw, hd, top + 0.04 * h]);
    // The firebox door, open on a glow, and an ash door below.
    let (dx, dz0, dz1) = (0.35 * hw, 0.28 * h, 0.5 * h);
    b.cuboid(
        Door,
        [-dx - 0.03, 0.94 * hd, dz0 - 0.03],
        [dx + 0.03, hd, dz1 + 0.03],
    );
    b.cuboid(Light, [-dx, hd - 0.004, dz0], [dx, hd, dz1]);
    b.cuboid(
        Interior,
        [-0.6 * dx, hd - 0.004, 0.1 * h],
        [0.6 * dx, hd, 0.2 * h],
    );
    b.cuboid(Handle, [dx, hd - 0.01, 0.38 * h], [dx + 0.08, hd, 0.4 * h]);
    // The flue.
    let r = (0.14 * b.w).min(0.3 * hd);
    b.cylinder(
        Metal,
        [0.0, -0.4 * hd, top + 0.04 * h],
        r,
        h - top - 0.04 * h,
    );
    b.cylinder(Metal, [0.0, -0.4 * hd, h - 0.05 * h], 1.2 * r, 0.03 * h);
}

/// A camping stove: a low case on the ground with two burners under pan grates, its lid
/// raised behind and wind shields folded up at both ends, a gas bottle on one side.
pub fn camp_stove(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let body = 0.3 * h;
    b.cuboid(Body, [-hw, -hd + 0.02, 0.0], [hw, hd, body]);
    b.cuboid(
        Interior,
        [-0.96 * hw, -hd + 0.03, body],
        [0.96 * hw, hd - 0.01, body + 0.003],
    );
    // The lid, raised behind, and the wind shields at the ends.
    b.cuboid(Body, [-hw, -hd, body], [hw, -hd + 0.02, h]);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.01);
        b.cuboid(
            Body,
            [x - 0.01, -hd + 0.02, body],
            [x + 0.01, 0.6 * hd, 0.75 * h],
        );
    }
    // Two burners with their grates.
    let r = (0.22 * hw).min(0.35 * hd);
    for sx in [-1.0, 1.0] {
        let x = sx * 0.5 * hw;
        b.cylinder(Metal, [x, 0.0, body], 0.5 * r, 0.02);
        b.cylinder(Light, [x, 0.0, body + 0.02], 0.35 * r, 0.006);
        for a in [0.0, std::f64::consts::FRAC_PI_2] {
            b.slab(Handle, [x, 0.0, body + 0.03], [r, 0.004, 0.004], rot_z(a));
        }
    }
    // Knobs on the front.
    for sx in [-1.0, 1.0] {
        b.revolved(
            Handle,
            0,
            [sx * 0.5 * hw, hd - 0.015, 0.5 * body],
            frame_along([0.0, 1.0, 0.0]),
            1.0,
            frustum_profile(0.015, 0.015, 0.015),
        );
    }
}

/// A bench vise: a base plate, a fixed jaw at the back, a sliding jaw in front on its slide, a
/// screw along the slide and a tommy bar through its end.
pub fn vise(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    b.cuboid(Body, [-0.7 * hw, -hd, 0.0], [0.7 * hw, 0.2 * hd, 0.1 * h]);
    b.cuboid(
        Body,
        [-0.25 * hw, -hd, 0.1 * h],
        [0.25 * hw, 0.5 * hd, 0.45 * h],
    );
    let jaw = |b: &mut Builder, y0: f64, y1: f64| {
        b.cuboid(Body, [-hw, y0, 0.45 * h], [hw, y1, 0.9 * h]);
        b.cuboid(Metal, [-hw, y0, 0.9 * h], [hw, y1, h]);
    };
    jaw(b, -hd, -0.5 * hd);
    jaw(b, -0.4 * hd, 0.0);
    b.cuboid(
        Body,
        [-0.3 * hw, 0.0, 0.3 * h],
        [0.3 * hw, 0.5 * hd, 0.7 * h],
    );
    b.rod(
        Metal,
        [0.0, 0.5 * hd, 0.5 * h],
        [0.0, 0.85 * hd, 0.5 * h],
        0.06 * h,
    );
    b.rod(
        Handle,
        [-0.8 * hw, 0.8 * hd, 0.5 * h],
        [0.8 * hw, 0.8 * hd, 0.5 * h],
        0.03 * h,
    );
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Handle,
            [sx * 0.8 * hw, 0.8 * hd, 0.5 * h],
            [0.05 * h, 0.05 * h, 0.05 * h],
        );
    }
}

/// A wedge stage monitor: a low box whose front slopes back to face a performer above it, a
/// dark grille over the slope and a handle recess on top.
pub fn stage_monitor(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The slope rises from the front foot (y = hd, z = 0.2 h) to the back top (y = -0.5 hd, z = h).
    let (ya, za, yb, zb) = (hd, 0.2 * h, -0.5 * hd, h);
    let a = (zb - za).atan2(ya - yb);
    let len = ((ya - yb).powi(2) + (zb - za).powi(2)).sqrt();
    let t = 0.02;
    // The solid behind the slope: a deep slab turned to lie along it, its back clipped by the
    // box, over a back block and a front foot.
    let c = [0.0, 0.5 * (ya + yb), 0.5 * (za + zb)];
    let depth = 0.5 * h;
    let n = [0.0, a.sin(), a.cos()];
    b.slab(
        Body,
        [0.0, c[1] - depth * n[1], c[2] - depth * n[2]],
        [hw, depth, 0.5 * len],
        rot_x(std::f64::consts::FRAC_PI_2 - a),
    );
    b.cuboid(Body, [-hw, -hd, 0.0], [hw, yb, h]);
    b.cuboid(Body, [-hw, yb, 0.0], [hw, hd, za]);
    // The grille on the slope, a little inside its edges.
    b.slab(
        Screen,
        [0.0, c[1] + 0.5 * t * n[1], c[2] + 0.5 * t * n[2]],
        [0.92 * hw, 0.5 * t, 0.45 * len],
        rot_x(std::f64::consts::FRAC_PI_2 - a),
    );
    b.cuboid(
        Interior,
        [-0.3 * hw, -0.9 * hd, h - 0.01],
        [0.3 * hw, -0.6 * hd, h],
    );
}

/// A toy train set: a loop of track (two rails on sleepers round a long oval) and a little
/// train of an engine and two wagons on its front straight.
pub fn train_set(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let g = (0.06 * b.d).clamp(0.02, 0.06);
    let ry = hd - g;
    let rx = hw - g;
    let straight = (rx - ry).max(0.0);
    // Points round the stadium: the straights along x, semicircular ends.
    let mut path = vec![];
    let n_arc = 16;
    for k in 0..=n_arc {
        let a = -std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / n_arc as f64;
        path.push([straight + ry * a.cos(), ry * a.sin()]);
    }
    for k in 0..=n_arc {
        let a = std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * k as f64 / n_arc as f64;
        path.push([-straight + ry * a.cos(), ry * a.sin()]);
    }
    path.push(path[0]);
    let rail = 0.012;
    for w in path.windows(2) {
        let (p, q) = (w[0], w[1]);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let l = (dx * dx + dy * dy).sqrt();
        if l < 1e-9 {
            continue;
        }
        let ang = dy.atan2(dx);
        // The track bed (sleepers' wood) and two grooves along it.
        let c = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])];
        b.slab(
            Top,
            [c[0], c[1], rail / 2.0],
            [0.5 * l + 0.004, g, rail / 2.0],
            rot_z(ang),
        );
        let (nx, ny) = (-dy / l, dx / l);
        for s in [-0.5, 0.5] {
            b.slab(
                Metal,
                [c[0] + s * g * nx, c[1] + s * g * ny, rail + 0.001],
                [0.5 * l + 0.004, 0.004, 0.002],
                rot_z(ang),
            );
        }
    }
    // The train on the front straight: an engine with a cab and a funnel, then two wagons.
    let car = (0.12 * b.w).min(0.15);
    let (cw, ch) = (0.8 * g, (h - rail).min(0.8 * car));
    let y = ry;
    let z = rail;
    let x0 = 0.2 * straight + car;
    b.cuboid(Body, [x0 - car, y - cw, z], [x0, y + cw, z + 0.6 * ch]);
    b.cuboid(Body, [x0 - 0.35 * car, y - cw, z], [x0, y + cw, z + ch]);
    b.cylinder(
        Interior,
        [x0 - 0.8 * car, y, z + 0.6 * ch],
        0.2 * cw,
        0.35 * ch,
    );
    for k in 1..3 {
        let x1 = x0 - k as f64 * 1.1 * car;
        b.cuboid_v(
            Door,
            k as u32,
            [x1 - car, y - cw, z],
            [x1 - 0.1 * car, y + cw, z + 0.55 * ch],
        );
    }
    for k in 0..3 {
        let x1 = x0 - k as f64 * 1.1 * car;
        for f in [0.25, 0.75] {
            b.rod(
                Tyre,
                [x1 - f * car, y - cw - 0.002, z + 0.12 * ch],
                [x1 - f * car, y + cw + 0.002, z + 0.12 * ch],
                0.12 * ch,
            );
        }
    }
}
