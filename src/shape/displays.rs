//! Layouts of things that show printed matter face-out or upright: a magazine stand (a
//! newsstand rack of tiers stepping back as they rise, each a sloped ledge with magazines
//! leaning face-out on it), a desktop file rack (a sorter of slanted slots stepping up to the
//! back, a folder standing in each) and a salon hood dryer chair (an armchair with a dome hood
//! on a column over the sitter's head). The front faces +y; backs at -y.
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

/// A hood dryer chair: an armchair low in the size box, a chrome column rising behind its back
/// to an arm reaching forward, and the dryer's dome hood on the arm over where the sitter's head
/// is, its open rim tilted to face down and forward, dark inside, with a control dial on its side.
pub fn hood_dryer_chair(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let chair_h = (0.62 * h).min(0.95);
    let full = b.h;
    b.h = chair_h;
    super::furniture::armchair(b);
    b.h = full;
    // The column behind the back, on a round foot.
    let yc = -hd + 0.05;
    b.cylinder(Metal, [0.0, yc, 0.0], (0.3 * hw).min(0.14), 0.02);
    let top = h - 0.1;
    b.rod(Metal, [0.0, yc, 0.02], [0.0, yc, top], 0.025);
    // The hood: a dome of radius r, its rim tilted to face down and forward over the head.
    let r = (0.75 * hw).min(0.28).min(0.3 * h);
    let centre = [0.0, yc + r + 0.12, top - 0.3 * r];
    b.rod(Metal, [0.0, yc, top], [0.0, centre[1], top], 0.02);
    let dome = |rr: f64| {
        (0..=12)
            .map(|i| {
                let a = i as f64 / 12.0 * std::f64::consts::FRAC_PI_2;
                [rr * a.cos(), 1.1 * rr * a.sin()]
            })
            .collect::<Vec<_>>()
    };
    let tilt = rot_x(0.6);
    let base = [centre[0], centre[1], centre[2] - 0.5 * r];
    b.revolved(Body, 0, base, tilt, 1.0, dome(r));
    b.revolved(
        Interior,
        0,
        [base[0], base[1], base[2] - 0.004],
        tilt,
        1.0,
        dome(0.94 * r),
    );
    b.cylinder(Handle, [r + 0.005, base[1], base[2] + 0.3 * r], 0.03, 0.02);
}
