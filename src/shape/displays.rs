//! Layouts of things that show printed matter face-out or upright: a magazine stand (a
//! newsstand rack of tiers stepping back as they rise, each a sloped ledge with magazines
//! leaning face-out on it) and a desktop file rack (a sorter of slanted slots stepping up to the
//! back, a folder standing in each). The front faces +y; backs at -y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_x;

/// How far a magazine leans back from upright on its ledge (radians, about 17°).
const LEAN: f64 = 0.3;

/// One magazine leaning back at [`LEAN`], its foot at `(x, y, z)`: the cover (a colour of the
/// goods palette by `v`), a pale masthead band across its top and a picture block below it.
pub(super) fn magazine(b: &mut Builder, v: u32, foot: [f64; 3], w: f64, h: f64) {
    let rot = rot_x(LEAN);
    let (s, c) = LEAN.sin_cos();
    let at = |t: f64, off: f64| {
        [
            foot[0],
            foot[1] - t * s + off * c,
            foot[2] + t * c + off * s,
        ]
    };
    b.slab_v(Books, v, at(0.5 * h, 0.0), [0.5 * w, 0.003, 0.5 * h], rot);
    b.slab(
        Canvas,
        at(0.87 * h, 0.004),
        [0.45 * w, 0.001, 0.07 * h],
        rot,
    );
    b.slab_v(
        Books,
        v + 3,
        at(0.45 * h, 0.004),
        [0.38 * w, 0.001, 0.25 * h],
        rot,
    );
}

/// A magazine stand: a back board and two side frames, tiers stepping back as they rise; each
/// tier a floor with a front lip and a sloped backer, magazines leaning face-out side by side.
pub fn magazine_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.02;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, -hd + t, h]);
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.06]);
    let tiers = ((h - 0.2) / 0.3).floor().clamp(2.0, 6.0) as usize;
    let pitch = (h - 0.1) / tiers as f64;
    let mh = (0.8 * pitch).min(0.3);
    let mw = (0.75 * mh).min(0.22);
    let reach = mh * LEAN.sin() + 0.04;
    let step = ((2.0 * hd - t - reach) / tiers as f64).max(0.0);
    let n = ((2.0 * hw - 2.0 * t) / (mw + 0.02)).floor().max(1.0) as usize;
    let gap = (2.0 * hw - 2.0 * t - n as f64 * mw) / (n as f64 + 1.0);
    for k in 0..tiers {
        let z = 0.06 + k as f64 * pitch;
        // The tier's front edge steps back as the tiers rise.
        let yf = hd - k as f64 * step;
        let yb = -hd + t;
        b.cuboid(Top, [-hw + t, yb, z], [hw - t, yf, z + 0.015]);
        b.cuboid(Frame, [-hw + t, yf - 0.012, z], [hw - t, yf, z + 0.05]);
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - t / 2.0);
            b.cuboid(
                Frame,
                [x - t / 2.0, yb, z],
                [x + t / 2.0, yf, z + pitch.min(0.12)],
            );
        }
        // The sloped backer the magazines rest on, rising from behind the lip.
        let foot = [0.0, yf - 0.03, z + 0.015];
        let (s, c) = LEAN.sin_cos();
        let bh = (mh * 0.9).min(pitch);
        b.slab(
            Frame,
            [0.0, foot[1] - 0.5 * bh * s - 0.006, foot[2] + 0.5 * bh * c],
            [hw - t, 0.006, 0.5 * bh],
            rot_x(LEAN),
        );
        for i in 0..n {
            let x = -hw + t + gap + i as f64 * (mw + gap) + 0.5 * mw;
            let v = ((k * 5 + i * 3) % 6) as u32;
            magazine(b, v, [x, foot[1] + 0.008, foot[2]], mw, mh);
        }
    }
    // Side frames: a post at the back, a rail down to the front foot.
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - t / 2.0);
        b.rod(Frame, [x, -hd + t, 0.0], [x, -hd + t, h], 0.012);
        b.rod(
            Frame,
            [x, hd - 0.01, 0.06],
            [x, -hd + t + step, h - 0.02],
            0.01,
        );
    }
}

/// A desktop file rack: a base tray, slanted dividers stepping up from front to back, a folder
/// or file standing in each slot, its papers' edges showing at the top.
pub fn file_sorter(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.006;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, 0.012]);
    let slots = ((b.d - 0.02) / 0.05).floor().clamp(3.0, 6.0) as usize;
    let pitch = (b.d - 0.02) / slots as f64;
    let lean = 0.12;
    for k in 0..=slots {
        // Dividers rise towards the back: the front one is lowest.
        let y = hd - 0.01 - k as f64 * pitch;
        let dh = h * (0.45 + 0.55 * k as f64 / slots as f64) - 0.012;
        let (s, c) = f64::sin_cos(lean);
        for sx in [-1.0, 1.0] {
            let x = sx * (hw - t);
            b.slab(
                Frame,
                [x, y - 0.5 * dh * s, 0.012 + 0.5 * dh * c],
                [t, 0.006, 0.5 * dh],
                rot_x(lean),
            );
        }
        b.slab(
            Frame,
            [0.0, y - 0.5 * (0.3 * dh) * s, 0.012 + 0.5 * 0.3 * dh * c],
            [hw - t, 0.003, 0.15 * dh],
            rot_x(lean),
        );
        if k == slots {
            break;
        }
        // A folder in the slot in front of this divider, a little lower than it.
        let fh = (0.9 * dh).max(0.05);
        let yf = y - 0.5 * pitch;
        let v = (k * 4 + 1) as u32;
        b.slab_v(
            Books,
            v,
            [0.0, yf - 0.5 * fh * s, 0.012 + 0.5 * fh * c],
            [hw - 2.5 * t, 0.004, 0.5 * fh],
            rot_x(lean),
        );
        b.slab(
            Canvas,
            [0.0, yf - fh * s + 0.004, 0.012 + fh * c + 0.008],
            [hw - 4.0 * t, 0.006, 0.01],
            rot_x(lean),
        );
    }
}
