//! Layouts of racks drawn for what they hold: a towel rail on the wall (a ladder of bars with a
//! towel over them), a wine rack (a lattice of cells, a bottle lying in each with its base to
//! the front), a pantry shelf (jars with lids, tins and packets) and a weapon rack (spears and
//! swords leaning in a frame). The front faces +y; the back stands at -y.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{frustum_profile, mat_mul, rot_z, IDENTITY, V3};
use super::Mount;

/// A closed body of revolution along `dir` from `base` (a bottle, a blade): the profile's
/// second coordinate runs along `dir`, its first is the radius; `ay` flattens the section and
/// `spin` turns it about `dir`.
#[allow(
    clippy::too_many_arguments,
    reason = "one call draws one oriented part"
)]
pub(super) fn along(
    b: &mut Builder,
    role: Role,
    variant: u32,
    base: V3,
    dir: V3,
    spin: f64,
    ay: f64,
    profile: Vec<[f64; 2]>,
) {
    let rot = mat_mul(&frame_along(dir), &rot_z(spin));
    b.revolved(role, variant, base, rot, ay, profile);
}

/// A towel rail on the wall: two upright tubes on wall brackets joined by a ladder of bars,
/// a bath towel folded over a bar near the top and a hand towel lower down, hanging in front.
pub fn towel_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.014;
    let y = -hd + 0.045;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - r);
        b.rod(Metal, [x, y, 0.0], [x, y, h], r);
        for z in [0.12 * h, 0.88 * h] {
            b.rod(Metal, [x, -hd, z], [x, y, z], 0.6 * r);
        }
    }
    // Bars in two groups, as on a heated rail: close pitch below, a gap for the towels above.
    let bars = ((h - 0.06) / 0.07).floor().max(3.0) as usize;
    for i in 0..bars {
        let z = 0.03 + (i as f64 + 0.5) * (h - 0.06) / bars as f64;
        b.rod(Metal, [-hw + r, y, z], [hw - r, y, z], 0.55 * r);
    }
    // A towel: a roll over the bar and two thin panels hanging either side of it.
    let towel = |b: &mut Builder, role: Role, z: f64, w: f64, drop: f64| {
        let t = 0.012;
        b.rod(role, [-w, y, z], [w, y, z], 2.2 * r);
        b.cuboid(role, [-w, y + 2.2 * r - t, z - drop], [w, y + 2.2 * r, z]);
        b.cuboid(
            role,
            [-w, y - 2.2 * r, z - 0.8 * drop],
            [w, y - 2.2 * r + t, z],
        );
    };
    towel(b, Canvas, 0.82 * h, 0.7 * (hw - r), 0.45 * h);
    towel(b, Cushion, 0.3 * h, 0.45 * (hw - r), 0.2 * h);
}

/// A wine bottle lying front to back, its base at `y0` and its neck's end `l` behind it.
fn bottle(b: &mut Builder, x: f64, z: f64, y0: f64, l: f64, r: f64, variant: u32) {
    let neck = 0.3 * r;
    let body = 0.62 * l;
    let shoulder = 0.14 * l;
    let profile = vec![
        [0.0, 0.0],
        [r, 0.0],
        [r, body],
        [neck, body + shoulder],
        [neck, l],
        [0.0, l],
    ];
    let role = if variant % 3 == 1 { BlackKeys } else { Glass };
    along(b, role, 0, [x, y0, z], [0.0, -1.0, 0.0], 0.0, 1.0, profile);
    // The punt: a dark hollow in the middle of the base.
    b.rod(Interior, [x, y0 + 0.002, z], [x, y0, z], 0.45 * r);
}

/// A wine rack: a cabinet frame whose face is a lattice of square cells, with a bottle lying in
/// most cells, its base a dark round of glass just inside the cell's mouth.
pub fn wine_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.018;
    b.cuboid(Frame, [-hw, -hd, 0.0], [-hw + t, hd, h]);
    b.cuboid(Frame, [hw - t, -hd, 0.0], [hw, hd, h]);
    b.cuboid(Top, [-hw, -hd, h - t], [hw, hd, h]);
    b.cuboid(Frame, [-hw + t, -hd, 0.0], [hw - t, hd, 0.05]);
    b.cuboid(Interior, [-hw + t, -hd, 0.05], [hw - t, -hd + 0.006, h - t]);
    let (x0, x1, z0, z1) = (-hw + t, hw - t, 0.05, h - t);
    let cell = 0.1f64.min((x1 - x0) / 2.0);
    let nx = ((x1 - x0) / cell).floor().max(1.0) as usize;
    let nz = ((z1 - z0) / cell).floor().max(1.0) as usize;
    let (cx, cz) = ((x1 - x0) / nx as f64, (z1 - z0) / nz as f64);
    let lattice = 0.008;
    for i in 1..nx {
        let x = x0 + i as f64 * cx;
        b.cuboid(
            Frame,
            [x - lattice, -hd + 0.006, z0],
            [x + lattice, hd - 0.05, z1],
        );
    }
    for k in 1..nz {
        let z = z0 + k as f64 * cz;
        b.cuboid(
            Frame,
            [x0, -hd + 0.006, z - lattice],
            [x1, hd - 0.05, z + lattice],
        );
    }
    let r = (0.4 * cx.min(cz)).min(0.04);
    for i in 0..nx {
        for k in 0..nz {
            // A few cells stand empty, as in a rack in use.
            if (i * 7 + k * 5) % 6 == 2 {
                continue;
            }
            let x = x0 + (i as f64 + 0.5) * cx;
            let z = z0 + k as f64 * cz + lattice + r;
            let y0 = hd - 0.07;
            let l = (7.5 * r).min(y0 + hd - 0.01);
            bottle(b, x, z, y0, l, r, (i + 2 * k) as u32);
        }
    }
}

/// A closed cylinder of a product colour (`variant` picks it) standing on `base`.
fn tinted(b: &mut Builder, variant: u32, base: V3, r: f64, h: f64) {
    b.revolved(
        Books,
        variant,
        base,
        IDENTITY,
        1.0,
        frustum_profile(r, r, h),
    );
}

/// A pantry shelf: uprights and boards, each board carrying a row of stores: glass jars of
/// coloured food under metal lids, tins with labels and packets.
pub fn pantry_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.03;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - t / 2.0), sy * (hd - t / 2.0));
            b.cuboid(
                Frame,
                [x - t / 2.0, y - t / 2.0, 0.0],
                [x + t / 2.0, y + t / 2.0, h],
            );
        }
    }
    let boards = ((h / 0.38).round() as usize).clamp(3, 7);
    // standing, its lowest board is off the floor on the posts; hung on a wall, at its foot
    let z0 = if b.mount == Mount::Stand { 0.08 } else { 0.02 };
    let pitch = (h - z0 - 0.02) / (boards - 1) as f64;
    let mut n = 0u32;
    for k in 0..boards {
        let z = z0 + k as f64 * pitch;
        b.cuboid(Top, [-hw, -hd, z - 0.02], [hw, hd, z]);
        if k + 1 == boards {
            break;
        }
        let room = (pitch - 0.06).min(0.3);
        let mut x = -hw + t + 0.02;
        while x < hw - t - 0.08 {
            n += 1;
            let kind = (n * 7 + k as u32 * 3) % 5;
            let used = match kind {
                // A jar: see-through glass over its food, a metal lid.
                0..=2 => {
                    let r = 0.045;
                    let jh = room * (0.7 + 0.1 * kind as f64);
                    let c = [x + r, -0.2 * hd, z];
                    tinted(b, n, c, 0.92 * r, 0.85 * jh);
                    b.cylinder(Pane, c, r, 0.9 * jh);
                    b.cylinder(Metal, [c[0], c[1], z + 0.9 * jh], 1.05 * r, 0.1 * jh);
                    2.0 * r + 0.02
                }
                // A tin: metal ends round a paper label.
                3 => {
                    let r = 0.04;
                    let th = 0.5 * room;
                    for dy in [0.2 * hd, -0.2 * hd] {
                        let c = [x + r, dy, z];
                        b.cylinder(Metal, c, r, 0.12 * th);
                        tinted(b, n + 3, [c[0], c[1], z + 0.12 * th], r, 0.76 * th);
                        b.cylinder(Metal, [c[0], c[1], z + 0.88 * th], r, 0.12 * th);
                    }
                    2.0 * r + 0.02
                }
                // A packet standing on its end.
                _ => {
                    let w = 0.12;
                    b.cuboid_v(
                        Books,
                        n + 5,
                        [x, -0.6 * hd, z],
                        [x + w, 0.1 * hd, z + 0.85 * room],
                    );
                    w + 0.02
                }
            };
            x += used;
        }
    }
}

/// A weapon rack: a base with a slotted rail in front, a top rail with notches at the back
/// on two end posts; spears and staves lean in it with their heads above the top rail, swords
/// stand point down with their hilts up.
pub fn weapon_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.05;
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.cuboid(Frame, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, -hd + t, h]);
        b.cuboid(Frame, [x - t / 2.0, -hd, 0.0], [x + t / 2.0, hd, t]);
    }
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.04]);
    // The foot rail in front holding the weapons' ends, the top rail at the back.
    b.cuboid(Frame, [-hw, hd - 0.08, 0.04], [hw, hd, 0.12]);
    let z_top = 0.72 * h;
    b.cuboid(Frame, [-hw, -hd, z_top - 0.06], [hw, -hd + 0.07, z_top]);
    b.cuboid(
        Frame,
        [-hw, -hd, 0.45 * h],
        [hw, -hd + 0.04, 0.45 * h + 0.04],
    );
    let n = ((b.w - 2.0 * t) / 0.16).floor().clamp(3.0, 12.0) as usize;
    let pitch = (b.w - 2.0 * t) / n as f64;
    for i in 0..n {
        let x = -hw + t + (i as f64 + 0.5) * pitch;
        let foot = [x, hd - 0.1, 0.06];
        let rest = [x, -hd + 0.1, z_top];
        let d = [0.0, rest[1] - foot[1], rest[2] - foot[2]];
        let l = (d[1] * d[1] + d[2] * d[2]).sqrt();
        let u = [0.0, d[1] / l, d[2] / l];
        if i % 3 == 1 {
            // A sword: blade from the foot rail to a crossguard, then grip and pommel.
            let blade = 0.7 * l;
            along(
                b,
                Metal,
                0,
                foot,
                u,
                0.0,
                0.12,
                vec![[0.0, 0.0], [0.02, 0.08], [0.022, blade], [0.0, blade]],
            );
            let g = [0, 1, 2].map(|k| foot[k] + u[k] * blade);
            b.rod(
                Handle,
                [x - 0.09, g[1], g[2]],
                [x + 0.09, g[1], g[2]],
                0.012,
            );
            let grip = [0, 1, 2].map(|k| g[k] + u[k] * 0.16);
            b.rod(Trunk, g, grip, 0.016);
            b.ellipsoid(Handle, grip, [0.025, 0.025, 0.025]);
        } else {
            // A spear or staff: a long shaft through the top rail, a leaf blade on the spears.
            let len = (h - 0.1 - foot[2]) / u[2];
            let spear = i % 3 == 0;
            let shaft = if spear { len - 0.2 } else { len };
            let tip = [0, 1, 2].map(|k| foot[k] + u[k] * shaft);
            b.rod(Trunk, foot, tip, 0.015);
            if spear {
                along(
                    b,
                    Metal,
                    0,
                    tip,
                    u,
                    0.0,
                    0.2,
                    vec![[0.0, 0.0], [0.035, 0.07], [0.0, len - shaft]],
                );
            }
        }
    }
}
