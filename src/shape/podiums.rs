//! Layouts of things people stand on or stand at, once drawn as plain boxes or cabinets: a stage
//! (a low wide platform with a dark deck, a lipped front edge, a skirt round its face and a
//! flight of steps let into one end of its front), a display pedestal (a slim plinth with a
//! stepped base moulding, panelled faces and a capping moulding under its top) and a host stand (a slim podium
//! on a plinth with a sloped writing top towards the host, a reading lamp and a menu pocket at
//! its side, an open shelf behind). The front faces +y; each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// How many risers a flight up to `h` takes (each at most 20 cm, at least two).
pub fn risers(h: f64) -> usize {
    ((h / 0.2).ceil() as usize).max(2)
}

/// A stage: a platform with a dark deck, a lighter lip along its front edge and a skirt hanging
/// round its face and sides, a flight of steps let into a notch at the right end of its front.
pub fn stage(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let n = risers(h);
    let tread = (0.28f64).min(0.3 * b.d / (n - 1) as f64);
    let yf = hd - tread * (n - 1) as f64;
    let sw = (0.25 * b.w).clamp(0.6, 1.2).min(0.5 * b.w);
    let (x0, x1) = (hw - 0.08 * b.w - sw, hw - 0.08 * b.w);
    let deck = (0.05 * h).clamp(0.02, 0.05);
    let skirt = 0.012;
    // The platform in three blocks round the notch: left of it, behind it, right of it.
    for (xa, xb, y1) in [(-hw, x0, hd), (x0, x1, yf), (x1, hw, hd)] {
        b.cuboid(Body, [xa, -hd, 0.0], [xb, y1 - skirt, h - deck]);
        b.cuboid(Top, [xa, -hd, h - deck], [xb, y1, h]);
        b.cuboid(
            Frame,
            [xa, y1 - 0.06, h - deck - 0.005],
            [xb, y1, h + 0.002],
        );
        b.cuboid(Canvas, [xa, y1 - skirt, 0.0], [xb, y1, h - deck - 0.01]);
    }
    for sx in [-1.0, 1.0] {
        let x = sx * hw;
        b.cuboid(
            Canvas,
            [x.min(x - sx * skirt), -hd, 0.0],
            [x.max(x - sx * skirt), hd, h - deck - 0.01],
        );
    }
    // The steps: one block per tread, each from the floor up, filling the notch.
    let rise = h / n as f64;
    for k in 0..n - 1 {
        let z = rise * (k + 1) as f64;
        let y1 = hd - tread * k as f64;
        b.cuboid(Body, [x0, yf, 0.0], [x1, y1, z - 0.015]);
        b.cuboid(Top, [x0, yf, z - 0.015], [x1, y1, z]);
        // A light nosing strip along each tread's edge.
        b.cuboid(Handle, [x0, y1 - 0.04, z], [x1, y1, z + 0.003]);
    }
}

/// A display pedestal: a base of two stepped mouldings, a slim shaft with a fielded panel on
/// each face and a shadow line under a two-step capping moulding, and the flat top.
pub fn pedestal(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tier = (0.05 * h).clamp(0.03, 0.08);
    let shaft = 0.72;
    let step = |b: &mut Builder, z0: f64, z1: f64, k: f64| {
        b.cuboid(Body, [-k * hw, -k * hd, z0], [k * hw, k * hd, z1]);
    };
    step(b, 0.0, tier, 1.0);
    step(b, tier, 2.0 * tier, 0.92);
    step(b, 2.0 * tier, h - 2.5 * tier, shaft);
    // A fielded panel on each face of the shaft, a little proud of it and a shade apart.
    let (px, py) = (shaft * hw, shaft * hd);
    let (z0, z1) = (3.0 * tier, h - 3.5 * tier);
    for s in [-1.0, 1.0] {
        let y = s * py;
        b.cuboid(
            Frame,
            [-0.75 * px, y.min(y + s * 0.004), z0],
            [0.75 * px, y.max(y + s * 0.004), z1],
        );
        let x = s * px;
        b.cuboid(
            Frame,
            [x.min(x + s * 0.004), -0.75 * py, z0],
            [x.max(x + s * 0.004), 0.75 * py, z1],
        );
    }
    // A dark shadow line where the shaft meets the capping.
    b.cuboid(
        Interior,
        [-(shaft + 0.01) * hw, -(shaft + 0.01) * hd, h - 2.5 * tier],
        [(shaft + 0.01) * hw, (shaft + 0.01) * hd, h - 2.2 * tier],
    );
    step(b, h - 2.2 * tier, h - 1.2 * tier, 0.92);
    b.cuboid(Top, [-hw, -hd, h - 1.2 * tier], [hw, hd, h]);
}

/// A host stand: a plinth, a slim body narrower than its top, a writing top sloping down
/// towards the host behind it with a lip at its low edge, a gooseneck lamp over it, a pocket of
/// menus at its side and an open shelf in its back.
pub fn hostess_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let plinth = (0.06 * h).min(0.07);
    let pocket = 0.16 * b.w;
    let xr = hw - pocket;
    let xc = -0.5 * pocket;
    let bw = 0.5 * (xr + hw) - 0.02;
    b.cuboid(Frame, [xc - bw, -hd, 0.0], [xc + bw, 0.9 * hd, plinth]);
    // The top's front edge is below the lamp's head, which stays within the height.
    let top_front = h - (0.1 * h).min(0.12);
    let top_back = top_front - 0.35 * b.d * 0.5;
    let body_top = top_back - 0.03;
    let (bx, by) = (0.88 * bw, 0.8 * hd);
    b.cuboid(Body, [xc - bx, -by, plinth], [xc + bx, by, body_top]);
    // The front board rises to the top's high front edge, hiding the slope from the guests.
    b.cuboid(
        Body,
        [xc - bx, by - 0.02, body_top],
        [xc + bx, by, top_front],
    );
    // A raised panel on the front and the open shelf behind.
    b.cuboid(
        Door,
        [xc - 0.75 * bx, by, plinth + 0.12 * h],
        [xc + 0.75 * bx, by + 0.012, body_top - 0.1 * h],
    );
    b.cuboid(
        Interior,
        [xc - 0.8 * bx, -by - 0.002, 0.45 * h],
        [xc + 0.8 * bx, -by + 0.12, body_top - 0.06],
    );
    b.cuboid(
        Top,
        [xc - 0.8 * bx, -by - 0.004, 0.6 * h],
        [xc + 0.8 * bx, -by + 0.12, 0.6 * h + 0.02],
    );
    // The sloped top: a slab tilted so its front edge is high and its back edge low.
    let (y0, y1) = (-hd, hd);
    let lean = ((top_front - top_back) / (y1 - y0)).atan();
    let th = 0.025;
    let zc = 0.5 * (top_front + top_back) - 0.5 * th / lean.cos();
    b.slab(
        Top,
        [xc, 0.0, zc],
        [bw, 0.5 * (y1 - y0) / lean.cos() - 0.01, 0.5 * th],
        rot_x(lean),
    );
    b.cuboid(
        Frame,
        [xc - bw, y0, top_back - 0.02],
        [xc + bw, y0 + 0.02, top_back + 0.03],
    );
    // The lamp: a stem from the back corner bending over the top to a small shade.
    let (lx, ly) = (xc - 0.8 * bw, -0.7 * hd);
    let head = [xc - 0.45 * bw, -0.1 * hd, h - 0.01];
    b.polyline(
        Metal,
        &[
            [lx, ly, top_back],
            [lx, ly, h - 0.01],
            [head[0], head[1], head[2]],
        ],
        0.006,
    );
    let shade = (0.15 * b.w).min(0.09);
    b.frustum(
        Shade,
        [head[0], head[1], head[2] - 0.6 * shade],
        0.6 * shade,
        0.6 * shade,
        0.5,
        0.6 * shade,
    );
    // The menu pocket on the right side, menus standing in it.
    let (pz0, pz1) = (0.45 * h, 0.75 * h);
    b.cuboid(Frame, [xc + bx, -0.5 * hd, pz0], [hw, 0.5 * hd, pz0 + 0.02]);
    b.cuboid(Frame, [hw - 0.012, -0.5 * hd, pz0], [hw, 0.5 * hd, pz1]);
    for k in 0..3 {
        let y = -0.4 * hd + k as f64 * 0.35 * hd;
        b.cuboid_v(
            Canvas,
            k,
            [xc + bx + 0.01, y, pz0 + 0.02],
            [hw - 0.015, y + 0.012, pz1 + 0.06],
        );
    }
}

/// A pulpit: a raised, enclosed wooden box at the front right of its footprint (a panelled
/// parapet waist high round a floor raised on a pedestal, a sloped reading ledge inside its
/// front with a cloth fall hanging over the front), reached by a flight of steps with a
/// handrail rising from the left to a gap in its left side.
pub fn pulpit(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The parapet stands about 1.05 m over the pulpit's floor.
    let zf = (h - 1.05).clamp(0.3 * h, 0.5 * h);
    let bw = b.d.min(0.55 * b.w);
    // Panels and the cloth stand proud of the walls, inside the size box.
    let (x0, x1) = (hw - bw, hw - 0.025);
    let (y0, y1) = (-hd + 0.015, hd - 0.025);
    let t = 0.05;
    // The pedestal, a moulded foot and a floor slab overhanging it.
    b.cuboid(
        Frame,
        [x0 + 0.06, y0 + 0.06, 0.0],
        [x1 - 0.06, y1 - 0.06, 0.08],
    );
    b.cuboid(
        Body,
        [x0 + 0.15, y0 + 0.15, 0.08],
        [x1 - 0.15, y1 - 0.15, zf - 0.08],
    );
    b.cuboid(Top, [x0, y0, zf - 0.08], [x1, y1, zf]);
    // The parapet: front, right and back walls whole, the left one cut for the stair's gap.
    let zt = h - 0.04;
    b.cuboid(Body, [x0, y1 - t, zf], [x1, y1, zt]);
    b.cuboid(Body, [x1 - t, y0, zf], [x1, y1, zt]);
    b.cuboid(Body, [x0, y0, zf], [x1, y0 + t, zt]);
    let gap = (0.6 * b.d).min(0.6);
    b.cuboid(Body, [x0, y0 + gap, zf], [x0 + t, y1, zt]);
    // A capping rail all round, proud of the walls.
    b.cuboid(
        Top,
        [x0 - 0.01, y1 - t - 0.01, zt],
        [x1 + 0.01, y1 + 0.01, h],
    );
    b.cuboid(
        Top,
        [x1 - t - 0.01, y0 - 0.01, zt],
        [x1 + 0.01, y1 + 0.01, h],
    );
    b.cuboid(
        Top,
        [x0 - 0.01, y0 - 0.01, zt],
        [x1 + 0.01, y0 + t + 0.01, h],
    );
    b.cuboid(
        Top,
        [x0 - 0.01, y0 + gap, zt],
        [x0 + t + 0.01, y1 + 0.01, h],
    );
    // Raised panels on the front (doors' role, facing +y) and the right side.
    let (pz0, pz1) = (zf + 0.12, zt - 0.12);
    let n = ((bw / 0.35).round() as usize).max(2);
    let pw = (bw - 0.08) / n as f64;
    for i in 0..n {
        let x = x0 + 0.04 + i as f64 * pw;
        b.cuboid(Door, [x + 0.03, y1, pz0], [x + pw - 0.03, y1 + 0.012, pz1]);
    }
    let m = ((b.d / 0.35).round() as usize).max(2);
    let pd = (b.d - 0.08) / m as f64;
    for i in 0..m {
        let y = y0 + 0.04 + i as f64 * pd;
        b.cuboid(Top, [x1, y + 0.03, pz0], [x1 + 0.012, y + pd - 0.03, pz1]);
    }
    // The reading ledge inside the front, sloping down towards the preacher, and a cloth fall
    // hanging from it over the middle of the front.
    let slope = 0.35f64;
    let ld = 0.32f64.min(0.4 * b.d);
    b.slab(
        Top,
        [
            0.5 * (x0 + x1),
            y1 - t - 0.5 * ld,
            h - 0.02 - 0.5 * ld * slope.sin(),
        ],
        [0.4 * bw, 0.5 * ld, 0.015],
        rot_x(slope),
    );
    let fw = (0.18 * bw).min(0.2);
    let xm = 0.5 * (x0 + x1);
    b.cuboid(
        Canvas,
        [xm - fw, y1 + 0.012, zt - 0.45],
        [xm + fw, y1 + 0.022, h],
    );
    // The steps, rising from the left towards the gap, under a handrail on newels.
    let run = x0 - (-hw);
    let k = risers(zf);
    let tread = run / k as f64;
    let (sy0, sy1) = (y0 + 0.05, y0 + gap - 0.02);
    for i in 0..k {
        let xs = -hw + i as f64 * tread;
        let z = zf * (i + 1) as f64 / k as f64;
        b.cuboid(Top, [xs, sy0, z - 0.03], [x0, sy1, z]);
        b.cuboid(Body, [xs, sy0, 0.0], [xs + 0.02, sy1, z - 0.03]);
    }
    b.cuboid(Body, [-hw, sy0, 0.0], [x0, sy0 + 0.03, 0.5 * zf]);
    let rail = 0.9f64.min(h - zf);
    let (ya, za, zb) = (sy1 - 0.02, zf / k as f64 + rail, zf + rail);
    b.rod(
        Frame,
        [-hw + 0.03, ya, zf / k as f64],
        [-hw + 0.03, ya, za],
        0.025,
    );
    b.rod(
        Frame,
        [x0 - 0.03, ya, zf],
        [x0 - 0.03, ya, zb.min(h)],
        0.025,
    );
    b.rod(
        Handle,
        [-hw + 0.03, ya, za],
        [x0 - 0.03, ya, zb.min(h)],
        0.02,
    );
}
