//! Four-legged animals drawn from a row of the animal table (`animals.rs`): legs, a body (or a
//! fleece of lumps), a neck rising at the row's angle to a head tilted nose-down, eyes, ears,
//! horns, a tail, and where the row says a mane, a hump, a trunk and tusks, a snout; the coat's
//! pattern is `coats.rs`. The animal stands along the longer side of its footprint, head
//! towards +y (+x when wider than deep). It draws inside the planned size box.
use super::animals::{Animal, Ears, Horns, Tail};
use super::archetypes::{frame_along, Builder};
use super::materials::Role::{self, *};
use super::parts::{frustum_profile, mul, rot_x, rot_z, M3, V3};

/// The quadruped archetype: the builder's animal row, else the table's `default`.
pub fn quadruped(b: &mut Builder) {
    let a = b.animal.unwrap_or_else(super::animals::default_animal);
    draw(b, a);
}

/// Where an animal's body, neck and head lie (along y, head at +y), for the coat's pattern.
pub struct Plan {
    /// Body centre (y, z) and semi-axes (across, along, up).
    pub body: (f64, f64, V3),
    /// Neck base and top points and radii (base, top); `None` for no neck.
    pub neck: Option<(V3, V3, f64, f64)>,
    /// Leg feet (x, y) and radius.
    pub legs: (Vec<[f64; 2]>, f64),
    /// The top of the legs.
    pub leg_top: f64,
}

/// Draws `a` at the builder's size.
pub fn draw(b: &mut Builder, a: &Animal) {
    let first = b.parts.len();
    let along_x = b.w > b.d;
    let (w, d) = (b.w, b.d);
    if along_x {
        (b.w, b.d) = (d, w);
    }
    let plan = draw_along_y(b, a);
    super::coats::pattern(b, a, &plan);
    if along_x {
        (b.w, b.d) = (w, d);
        b.turn_from(first, rot_z(-std::f64::consts::FRAC_PI_2));
    }
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// A tapered rod from `a` to `b`, radius `r0` at `a` and `r1` at `b`.
pub fn taper(b: &mut Builder, role: Role, p: V3, q: V3, r0: f64, r1: f64) {
    let d = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-9);
    b.revolved(role, 0, p, frame_along(d), 1.0, frustum_profile(r0, r1, l));
}

fn draw_along_y(b: &mut Builder, a: &Animal) -> Plan {
    let (ha, hl, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let points = a.points_role();
    let zb = a.legs * h;
    let zt = ((a.legs + a.body) * h).min(h);
    let (zc, rz) = (0.5 * (zb + zt), 0.5 * (zt - zb));
    let ra = (a.girth * ha).min(ha);
    // The head: its top at the full height, its front at the front (less room for tusks).
    let hlen = a.head.0 * hl;
    let hrz = (hlen * a.head.1).min(0.45 * h);
    let hra = hrz.min(0.5 * ha);
    let tilt = (0.6 * a.neck.0).min(40.0).to_radians();
    let rot: M3 = rot_x(-tilt);
    let reach = if a.tusks || a.trunk { 1.3 } else { 1.0 };
    let yh = hl - reach * hlen * tilt.cos() - 0.02 * hl;
    let zh = h - hrz * (1.0 + 0.3 * tilt.sin());
    let head_c = [0.0, yh, zh];
    let on_head = |p: V3| add(head_c, mul(&rot, [p[0] * hra, p[1] * hlen, p[2] * hrz]));
    // The tail end of the body leaves room for the tail's root.
    let yk = -hl + 0.04 * hl;
    let (yf, neck) = if a.neck.0 > 1.0 {
        let top = on_head([0.0, -0.6, -0.1]);
        let base_z = zt - 0.3 * rz;
        let dz = (top[2] - base_z).max(0.05 * h);
        let dy = dz / a.neck.0.to_radians().tan();
        let base_y = top[1] - dy;
        // The neck rises from a point 15 % of the body's length behind its front.
        let yf = ((base_y - 0.15 * yk) / 0.85)
            .min(yh - 0.3 * hlen)
            .max(yk + 0.5 * hl);
        let base_y = base_y.min(yf - 0.1 * (yf - yk));
        let nr = (a.neck.1 * ha).min(0.9 * rz).max(0.01);
        let nt = nr.min((0.55 * nr).max(0.8 * hrz.min(hra)));
        (yf, Some(([0.0, base_y, base_z], top, nr, nt)))
    } else {
        (yh - 0.35 * hlen, None)
    };
    let (yc, ry) = (0.5 * (yf + yk), 0.5 * (yf - yk));
    // Legs.
    let lr = (a.thick * ha).min(0.22 * ry).max(0.008);
    let feet: Vec<[f64; 2]> = [-1.0, 1.0]
        .iter()
        .flat_map(|sx| {
            let x = sx * (0.75 * ra - lr).max(lr);
            [[x, yk + 0.45 * ry], [x, yf - 0.35 * ry]]
        })
        .collect();
    let leg_role = if a.wool { points } else { Body };
    for f in &feet {
        b.frustum(leg_role, [f[0], f[1], 0.0], 0.85 * lr, 0.85 * lr, 1.35, zc);
        if a.pads {
            b.cylinder(Body, [f[0], f[1], 0.0], 1.1 * lr, 0.06 * h);
        } else {
            b.cylinder(Interior, [f[0], f[1], 0.0], 0.9 * lr, 0.035 * h);
        }
    }
    // Body: smooth, or a fleece of lumps over a smaller core.
    if a.wool {
        b.ellipsoid(Body, [0.0, yc, zc], [0.85 * ra, 0.9 * ry, 0.85 * rz]);
        let lump = 0.42 * ra.min(rz);
        for i in 0..5 {
            let t = -0.8 + 1.6 * i as f64 / 4.0;
            let s = (1.0 - t * t).sqrt();
            for u in [0.0_f64, 50.0, 90.0, 130.0, 180.0, 230.0, 310.0] {
                let u = u.to_radians();
                let c = [
                    (0.8 * ra - 0.5 * lump) * s * u.cos(),
                    yc + 0.85 * ry * t,
                    zc + (0.8 * rz - 0.5 * lump) * s * u.sin(),
                ];
                b.ellipsoid(Body, c, [lump, 1.2 * lump, lump]);
            }
        }
    } else {
        b.ellipsoid(Body, [0.0, yc, zc], [ra, ry, rz]);
    }
    if a.hump > 0.0 {
        let hz = (a.hump * h).min(h - zt - 0.005).max(0.0);
        b.ellipsoid(
            Body,
            [0.0, yc + 0.05 * ry, zt - 0.3 * rz],
            [0.65 * ra, 0.38 * ry, hz + 0.3 * rz],
        );
    }
    // Neck and mane.
    if let Some((nb, nt, r0, r1)) = neck {
        taper(b, Body, nb, nt, r0, r1);
        if a.mane {
            let up = |p: V3, r: f64| add(p, [0.0, -0.25 * r, 0.85 * r]);
            taper(b, Cushion, up(nb, r0), up(nt, r1), 0.3 * r0, 0.45 * r1);
        }
    }
    // Head, eyes, muzzle or snout.
    let head_role = if a.wool { points } else { Body };
    b.ellipsoid_rot(head_role, 0, head_c, [hra, hlen, hrz], rot);
    for sx in [-1.0, 1.0] {
        let e = 0.14 * hra.min(hrz);
        b.ellipsoid(Interior, on_head([sx * 0.85, 0.25, 0.3]), [e, e, e]);
    }
    if a.snout {
        let tip = on_head([0.0, 0.9, -0.1]);
        let r = 0.5 * hrz.min(hra);
        taper(
            b,
            points,
            tip,
            add(tip, mul(&rot, [0.0, 0.12 * hlen, 0.0])),
            r,
            r,
        );
        for sx in [-1.0, 1.0] {
            let n = add(tip, mul(&rot, [sx * 0.35 * r, 0.13 * hlen, 0.0]));
            b.ellipsoid(Interior, n, [0.15 * r, 0.05 * r, 0.2 * r]);
        }
    } else if a.points.is_some() && !a.wool {
        let c = on_head([0.0, 0.7, -0.15]);
        b.ellipsoid_rot(points, 0, c, [0.85 * hra, 0.35 * hlen, 0.75 * hrz], rot);
    }
    ears(b, a, &on_head, [hra, hlen, hrz], h, points);
    horns(b, a, &on_head, hrz);
    if a.trunk {
        let s = on_head([0.0, 0.75, -0.3]);
        let low = 0.12 * h;
        let drop = (s[2] - low).max(0.0);
        let pts = [
            s,
            add(s, [0.0, 0.12 * hlen, -0.35 * drop]),
            add(s, [0.0, 0.18 * hlen, -0.75 * drop]),
            add(s, [0.0, 0.3 * hlen, -drop]),
        ];
        let r = 0.45 * hra;
        for (i, w) in pts.windows(2).enumerate() {
            let k = i as f64 / 3.0;
            taper(
                b,
                Body,
                w[0],
                w[1],
                r * (1.0 - 0.3 * k),
                r * (0.7 - 0.3 * k / 1.0),
            );
        }
    }
    if a.tusks {
        for sx in [-1.0, 1.0] {
            let p = on_head([sx * 0.4, 0.55, -0.55]);
            let q = add(p, [0.0, 0.3 * hlen, -0.45 * hrz]);
            let t = add(q, [0.0, 0.25 * hlen, 0.1 * hrz]);
            let r = 0.1 * hra;
            taper(b, Frame, p, q, r, 0.8 * r);
            taper(b, Frame, q, t, 0.8 * r, 0.3 * r);
        }
    }
    tail(b, a, [0.0, yk + 0.06 * ry, zt - 0.25 * rz], h);
    Plan {
        body: (yc, zc, [ra, ry, rz]),
        neck,
        legs: (feet, lr),
        leg_top: zb,
    }
}

fn ears(b: &mut Builder, a: &Animal, on_head: &dyn Fn(V3) -> V3, r: V3, h: f64, points: Role) {
    let Some((kind, size)) = a.ears else { return };
    let es = size * h;
    let role = if a.wool { points } else { Body };
    for sx in [-1.0, 1.0] {
        let base = on_head([sx * 0.45, -0.55, 0.8]);
        match kind {
            Ears::Point | Ears::Long => {
                let c = add(base, [sx * 0.1 * es, -0.05 * es, 0.45 * es]);
                b.ellipsoid(role, c, [0.22 * es, 0.1 * es, 0.5 * es]);
            }
            Ears::Side => {
                let c = add(base, [sx * 0.5 * es, 0.0, -0.1 * es]);
                b.ellipsoid(role, c, [0.55 * es, 0.22 * es, 0.2 * es]);
            }
            Ears::Flap => {
                // Fanned out from the head's sides, the front edge furthest out.
                let c = add(
                    on_head([sx * 0.9, -0.5, 0.0]),
                    [sx * 0.2 * es, -0.15 * es, 0.0],
                );
                let fan = rot_z(-sx * 0.5);
                b.ellipsoid_rot(role, 0, c, [0.05 * es.min(r[0]), 0.4 * es, 0.5 * es], fan);
            }
        }
    }
}

fn horns(b: &mut Builder, a: &Animal, on_head: &dyn Fn(V3) -> V3, hrz: f64) {
    let Some(kind) = a.horns else { return };
    for sx in [-1.0, 1.0] {
        match kind {
            Horns::Side => {
                let p = on_head([sx * 0.55, -0.45, 0.75]);
                let l = 1.1 * hrz;
                let q = add(p, [sx * 0.6 * l, 0.0, 0.2 * l]);
                let t = add(q, [sx * 0.3 * l, 0.1 * l, 0.45 * l]);
                taper(b, Frame, p, q, 0.14 * l, 0.1 * l);
                taper(b, Frame, q, t, 0.1 * l, 0.03 * l);
            }
            Horns::Curved => {
                let p = on_head([sx * 0.3, -0.35, 0.85]);
                let l = 1.6 * hrz;
                let pts = [
                    p,
                    add(p, [sx * 0.05 * l, -0.25 * l, 0.55 * l]),
                    add(p, [sx * 0.12 * l, -0.7 * l, 0.7 * l]),
                    add(p, [sx * 0.15 * l, -l, 0.45 * l]),
                ];
                for (i, w) in pts.windows(2).enumerate() {
                    let r = 0.12 * l * (1.0 - 0.3 * i as f64);
                    taper(b, Frame, w[0], w[1], r, 0.7 * r);
                }
            }
            Horns::Ossicones => {
                let p = on_head([sx * 0.3, -0.45, 0.8]);
                let l = 0.9 * hrz;
                let t = add(p, [sx * 0.1 * l, -0.1 * l, l]);
                taper(b, Frame, p, t, 0.14 * l, 0.12 * l);
                b.ellipsoid(Cushion, t, [0.2 * l, 0.2 * l, 0.2 * l]);
            }
        }
    }
}

fn tail(b: &mut Builder, a: &Animal, root: V3, h: f64) {
    let Some((kind, len)) = a.tail else { return };
    let l = len * h;
    match kind {
        Tail::Brush => {
            let end = add(root, [0.0, -0.22 * l, -l]);
            taper(b, Cushion, root, end, 0.08 * l, 0.12 * l);
        }
        Tail::Tuft => {
            let end = add(root, [0.0, -0.12 * l, -l]);
            taper(b, Body, root, end, 0.04 * l, 0.025 * l);
            b.ellipsoid(
                Cushion,
                add(end, [0.0, 0.0, 0.08 * l]),
                [0.06 * l, 0.06 * l, 0.16 * l],
            );
        }
        Tail::Curl => {
            let r = 0.25 * l;
            let pts: Vec<V3> = (0..=8)
                .map(|i| {
                    let t = i as f64 / 8.0 * 1.6 * std::f64::consts::PI;
                    add(root, [0.0, -r + r * t.cos() - 0.2 * r * t, r * t.sin()])
                })
                .collect();
            b.polyline(Body, &pts, 0.1 * l);
        }
        Tail::Stub => {
            let c = add(root, [0.0, -0.3 * l, 0.15 * l]);
            b.ellipsoid(Body, c, [0.35 * l, 0.5 * l, 0.35 * l]);
        }
    }
}
