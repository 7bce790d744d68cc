//! Birds drawn from a row of the bird table (`birds.rs`): two legs on toes or webbed feet, a
//! body tilted at the row's angle, folded wings along its sides, a paler breast, a tail (fan,
//! long or short), a neck rising to a round head with eyes and a beak of the row's kind, and
//! where the row says an owl's face disc and ear tufts or a hen's comb and wattle. The bird is
//! drawn at its real proportions, head towards +y (+x when wider than deep), then stretched to
//! fill the planned size box, standing on its floor and centred on it.
use super::archetypes::Builder;
use super::beasts::taper;
use super::birds::{Beak, Bird, Tail};
use super::materials::Role::*;
use super::parts::{rot_x, rot_z, Part, Primitive, M3, V3};

/// The bird archetype: the builder's bird row, else the table's `default`.
pub fn bird(b: &mut Builder) {
    let row = b.bird.unwrap_or_else(super::birds::default_bird);
    let along_x = b.w > b.d;
    let (w, d) = if along_x { (b.d, b.w) } else { (b.w, b.d) };
    let mut own = Builder {
        parts: vec![],
        w,
        d,
        h: b.h,
        goods: None,
        animal: None,
        bird: None,
        variant: 0,
        mount: b.mount,
    };
    draw(&mut own, row);
    fit(&mut own.parts, [w, d, b.h]);
    let first = b.parts.len();
    b.parts.extend(own.parts);
    if along_x {
        b.turn_from(first, rot_z(-std::f64::consts::FRAC_PI_2));
    }
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn at(p: V3, k: f64, dir: V3) -> V3 {
    add(p, [k * dir[0], k * dir[1], k * dir[2]])
}

/// Stretches `parts` to fill `size` (x, y centred, resting on z = 0): positions scale by each
/// axis's own factor, each part's extents by the factor along its own axes (exact for parts
/// along the object's axes, close for tilted ones), so a bird planned taller or longer than its
/// real proportions still fills its box.
fn fit(parts: &mut [Part], size: [f64; 3]) {
    for _ in 0..2 {
        let (lo, hi) = bounds(parts);
        let k = [0, 1, 2].map(|i| size[i] / (hi[i] - lo[i]).max(1e-9));
        let shift = [
            -0.5 * (lo[0] + hi[0]) * k[0],
            -0.5 * (lo[1] + hi[1]) * k[1],
            -lo[2] * k[2],
        ];
        let along = |rot: &M3, col: usize| {
            (0..3)
                .map(|i| (rot[i][col] * k[i]).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        for p in parts.iter_mut() {
            match &mut p.prim {
                Primitive::Cuboid { centre, half, rot } => {
                    *centre = [0, 1, 2].map(|i| centre[i] * k[i] + shift[i]);
                    *half = [0, 1, 2].map(|c| half[c] * along(rot, c));
                }
                Primitive::Revolved {
                    origin,
                    rot,
                    ay,
                    profile,
                } => {
                    *origin = [0, 1, 2].map(|i| origin[i] * k[i] + shift[i]);
                    let (kx, ky, kz) = (along(rot, 0), along(rot, 1), along(rot, 2));
                    *ay *= ky / kx;
                    for q in profile.iter_mut() {
                        *q = [q[0] * kx, q[1] * kz];
                    }
                }
            }
        }
    }
}

/// The parts' bounds (low and high corners).
fn bounds(parts: &[Part]) -> (V3, V3) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in parts {
        for q in p.prim.hull_points() {
            for i in 0..3 {
                lo[i] = lo[i].min(q[i]);
                hi[i] = hi[i].max(q[i]);
            }
        }
    }
    (lo, hi)
}

/// Draws `a` at its real size, feet on z = 0 under the body's middle, head towards +y.
fn draw(b: &mut Builder, a: &Bird) {
    let t = a.tilt.to_radians();
    let [al, ap, ax] = a.body;
    // The body's axis (rear to breast) and the direction across it, up.
    let u = [0.0, t.cos(), t.sin()];
    let n = [0.0, -t.sin(), t.cos()];
    let low = ((al * t.sin()).powi(2) + (ap * t.cos()).powi(2)).sqrt();
    let c = [0.0, 0.0, a.legs + low];
    let rot = rot_x(t);
    b.ellipsoid_rot(Body, 0, c, [ax, al, ap], rot);
    // The breast: paler, forward and under.
    let breast = at(at(c, 0.22 * al, u), -0.22 * ap, n);
    b.ellipsoid_rot(Cushion, 0, breast, [0.86 * ax, 0.72 * al, 0.85 * ap], rot);
    // Folded wings along the sides, their tips past the rump.
    for sx in [-1.0, 1.0] {
        let wc = at(
            at(add(c, [sx * 0.72 * ax, 0.0, 0.0]), 0.12 * ap, n),
            -0.18 * al,
            u,
        );
        b.ellipsoid_rot(Frame, 0, wc, [0.34 * ax, 0.86 * al, 0.62 * ap], rot);
    }
    tail(b, a, c, u, n);
    legs(b, a, c, low);
    // The neck rises from the breast's top to the head.
    let nr = a.neck.0.to_radians();
    let nd = [0.0, nr.cos(), nr.sin()];
    let base = at(at(c, 0.72 * al, u), 0.3 * ap, n);
    let top = at(base, a.neck.1, nd);
    let r = a.head;
    let head = at(top, 0.45 * r, nd);
    if a.neck.1 > 0.0 {
        taper(b, Top, base, top, a.neck.2, a.neck.2.min(0.8 * r));
    } else {
        b.ellipsoid(Top, base, [a.neck.2, a.neck.2, a.neck.2]);
    }
    b.ellipsoid(Top, head, [r, 1.1 * r, r]);
    face(b, a, head);
}

/// Eyes, beak and the head's extras.
fn face(b: &mut Builder, a: &Bird, head: V3) {
    let r = a.head;
    let e = a.eye * r;
    if a.disc {
        // An owl's flat face: a pale disc, eyes side by side to the front.
        b.ellipsoid(
            Cushion,
            at(head, 0.5 * r, [0.0, 1.0, 0.0]),
            [0.9 * r, 0.6 * r, 0.85 * r],
        );
    }
    for sx in [-1.0, 1.0] {
        let p = if a.disc {
            add(head, [sx * 0.4 * r, 1.05 * r, 0.15 * r])
        } else {
            add(head, [sx * 0.82 * r, 0.45 * r, 0.2 * r])
        };
        if a.iris.is_some() {
            b.ellipsoid(Light, p, [1.5 * e, 1.5 * e, 1.5 * e]);
            b.ellipsoid(Interior, at(p, 0.9 * e, [sx * 0.3, 0.9, 0.0]), [0.8 * e; 3]);
        } else {
            b.ellipsoid(Interior, p, [e; 3]);
        }
    }
    if a.tufts {
        for sx in [-1.0, 1.0] {
            let p = add(head, [sx * 0.55 * r, 0.1 * r, 0.75 * r]);
            taper(
                b,
                Top,
                p,
                add(p, [sx * 0.2 * r, 0.0, 0.55 * r]),
                0.22 * r,
                0.03 * r,
            );
        }
    }
    let l = a.beak.1;
    let front = if a.disc { 1.05 * r } else { 0.95 * r };
    let root = add(head, [0.0, front - 0.15 * l, -0.15 * r]);
    match a.beak.0 {
        Beak::Cone => {
            let dir = [0.0, 0.98, -0.2];
            taper(b, Handle, root, at(root, l, dir), 0.32 * r, 0.03 * r);
        }
        Beak::Hook => {
            let mid = add(root, [0.0, 0.55 * l, 0.05 * l]);
            let tip = add(mid, [0.0, 0.3 * l, -0.6 * l]);
            taper(b, Handle, root, mid, 0.38 * r, 0.22 * r);
            taper(b, Handle, mid, tip, 0.22 * r, 0.03 * r);
        }
        Beak::Flat => {
            let c = add(root, [0.0, 0.5 * l, -0.1 * l]);
            b.ellipsoid_rot(Handle, 0, c, [0.42 * r, 0.55 * l, 0.16 * r], rot_x(-0.2));
        }
        Beak::Bent => {
            let mid = add(root, [0.0, 0.5 * l, -0.1 * l]);
            let tip = add(mid, [0.0, 0.15 * l, -0.55 * l]);
            taper(b, Handle, root, mid, 0.3 * r, 0.18 * r);
            taper(b, Handle, mid, tip, 0.18 * r, 0.05 * r);
        }
    }
    if a.comb {
        // Three lobes along the crown and a wattle under the beak.
        for k in 0..3 {
            let y = (0.45 - 0.4 * k as f64) * r;
            b.ellipsoid(
                Skin,
                add(head, [0.0, y, 0.95 * r]),
                [0.14 * r, 0.22 * r, 0.32 * r],
            );
        }
        b.ellipsoid(
            Skin,
            add(root, [0.0, 0.1 * l, -0.45 * r]),
            [0.14 * r, 0.18 * r, 0.3 * r],
        );
    }
}

/// The tail from the rump, its kind's shape.
fn tail(b: &mut Builder, a: &Bird, c: V3, u: V3, n: V3) {
    let (kind, len, rise) = a.tail;
    if len <= 0.0 {
        return;
    }
    let [al, ap, ax] = a.body;
    let t = a.tilt.to_radians() - rise.to_radians();
    // Backwards along the body's line, cocked up by the rise.
    let dir = [0.0, -t.cos(), -t.sin()];
    let root = at(at(c, -0.8 * al, u), 0.1 * ap, n);
    let mid = at(root, 0.5 * len, dir);
    let rot = rot_x(t);
    match kind {
        Tail::Fan => {
            // Tall feathers fanned up and back (a hen's tail).
            for (k, lift) in [0.0f64, 0.45, 0.9].iter().enumerate() {
                let tt = t - lift;
                let d = [0.0, -tt.cos(), -tt.sin()];
                let p = at(root, 0.5 * len, d);
                let w = 0.3 * ax * (1.0 - 0.15 * k as f64);
                b.ellipsoid_rot(Frame, 0, p, [w, 0.5 * len, 0.22 * len], rot_x(tt));
            }
        }
        Tail::Long => b.ellipsoid_rot(Frame, 0, mid, [0.38 * ax, 0.5 * len, 0.08 * len], rot),
        Tail::Short => b.ellipsoid_rot(Frame, 0, mid, [0.55 * ax, 0.5 * len, 0.18 * len], rot),
    }
}

/// Two legs under the body's middle, on toes or webbed feet.
fn legs(b: &mut Builder, a: &Bird, c: V3, low: f64) {
    let ax = a.body[2];
    let r = (0.07 * ax).max(0.004).min(0.25 * a.legs.max(0.01));
    let top = c[2] - 0.6 * low;
    let toe = (0.5 * ax).max(0.3 * a.legs.min(2.0 * ax));
    for sx in [-1.0, 1.0] {
        let x = sx * 0.35 * ax;
        b.rod(Metal, [x, 0.0, r], [x, 0.0, top], r);
        if a.webbed {
            b.ellipsoid(
                Metal,
                [x, 0.5 * toe, 0.5 * r],
                [0.45 * toe, 0.6 * toe, 0.5 * r],
            );
        } else {
            for k in [-1.0, 0.0, 1.0] {
                let end = [x + k * 0.45 * toe, 0.9 * toe - k.abs() * 0.2 * toe, 0.6 * r];
                b.rod(Metal, [x, 0.0, 0.6 * r], end, 0.6 * r);
            }
            b.rod(Metal, [x, 0.0, 0.6 * r], [x, -0.45 * toe, 0.6 * r], 0.6 * r);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each bird's knowledge-base size is the box its drawing fills at its real proportions,
    /// so a bird is drawn at its planned size and not shrunk inside a box of other proportions.
    #[test]
    fn every_birds_planned_size_fits_its_drawing() {
        let kb = crate::plan::kb::KnowledgeBase::builtin();
        let mut off = vec![];
        for (n, a) in super::super::birds::rows() {
            let Some(o) = kb.object(n) else { continue };
            let mut b = Builder {
                parts: vec![],
                w: 1.0,
                d: 1.0,
                h: 1.0,
                goods: None,
                animal: None,
                bird: None,
                variant: 0,
                mount: super::super::Mount::Stand,
            };
            draw(&mut b, a);
            let (lo, hi) = bounds(&b.parts);
            let [w, d] = if o.size[0] > o.size[1] {
                [o.size[1], o.size[0]]
            } else {
                [o.size[0], o.size[1]]
            };
            for (i, planned) in [w, d, o.size[2]].into_iter().enumerate() {
                let k = (hi[i] - lo[i]) / planned;
                if !(0.88..1.12).contains(&k) {
                    off.push(format!(
                        "{n}: axis {i} drawn {:.2} m, planned {planned}",
                        hi[i] - lo[i]
                    ));
                }
            }
        }
        assert!(off.is_empty(), "{off:#?}");
    }
}
