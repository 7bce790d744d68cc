//! Layouts of everyday kitchen, workshop and nursery things people name that had no drawing
//! of their own: a cutting board (a wooden board with a handle hole and a knife on it), a pot
//! rack (a rail hung on chains with pans on hooks), a sawhorse (a beam on splayed legs), a
//! baby gate (a low frame of close bars with a latched door) and a step stool (two treads, the
//! lower one in front). The front faces +y; each stays inside its size box.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A cutting board: a thick wooden board with a juice groove round its top, a handle at its
/// right end with a hole through it, and a knife lying on it.
pub fn cutting_board(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.75 * h;
    let xh = hw - 0.22 * hw;
    b.cuboid(Top, [-hw, -hd, 0.0], [xh, hd, zt]);
    // the handle: a narrower tab with a hole through it
    b.cuboid(Top, [xh, -0.45 * hd, 0.0], [hw, 0.45 * hd, zt]);
    b.cylinder(
        Interior,
        [0.5 * (xh + hw), 0.0, zt],
        0.2 * hd.min(hw - xh),
        0.002,
    );
    // the groove round the top
    let g = 0.08 * hd;
    for (lo, hi) in [
        ([-hw + g, -hd + g, zt], [xh - g, -hd + 1.4 * g, zt + 0.002]),
        ([-hw + g, hd - 1.4 * g, zt], [xh - g, hd - g, zt + 0.002]),
        ([-hw + g, -hd + g, zt], [-hw + 1.4 * g, hd - g, zt + 0.002]),
        ([xh - 1.4 * g, -hd + g, zt], [xh - g, hd - g, zt + 0.002]),
    ] {
        b.cuboid(Interior, lo, hi);
    }
    // a knife on it: the blade along x, its handle towards the right
    let yk = -0.3 * hd;
    b.cuboid(
        Metal,
        [-0.7 * hw, yk - 0.1 * hd, zt],
        [0.05 * hw, yk + 0.1 * hd, h - 0.1 * h],
    );
    b.cuboid(
        Handle,
        [0.05 * hw, yk - 0.08 * hd, zt],
        [0.45 * hw, yk + 0.08 * hd, h],
    );
}

/// A pot rack hung from the ceiling: four chains from its top corners down to an iron rail
/// frame, hooks along the long rails, saucepans and frying pans hanging from them.
pub fn pot_rack(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zr = 0.62 * h;
    let r = 0.012;
    let (x, y) = (hw - r, hd - r);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.rod(
                Frame,
                [sx * x, sy * y, zr],
                [sx * 0.9 * x, sy * 0.9 * y, h],
                0.006,
            );
        }
    }
    b.polyline(
        Frame,
        &[
            [-x, -y, zr],
            [x, -y, zr],
            [x, y, zr],
            [-x, y, zr],
            [-x, -y, zr],
        ],
        r,
    );
    b.rod(Frame, [-x, 0.0, zr], [x, 0.0, zr], r);
    // the pans: along each long rail, saucepans and frying pans in turn
    let n = ((b.w / 0.28).floor() as usize).max(2);
    let pitch = 2.0 * x / n as f64;
    let top = zr - 0.05;
    for (row, sy) in [-1.0, 1.0].into_iter().enumerate() {
        for k in 0..n {
            let px = -x + (k as f64 + 0.5) * pitch;
            let py = sy * y;
            b.rod(Metal, [px, py, zr], [px, py, top], 0.004);
            if (k + row) % 2 == 0 {
                // a saucepan hung by its long handle: the handle up, the pan below it
                let pr = (0.4 * pitch).min(0.9 * hd).min(0.12);
                let zp = (top - 0.16).max(0.05 * h);
                b.rod(Handle, [px, py, top], [px, py, zp + 0.02], 0.008);
                let cy = py - sy * pr;
                b.cylinder(Pot, [px, cy, zp - 1.2 * pr], pr, 1.2 * pr);
            } else {
                // a frying pan hung upright: its handle up from the rim, the round pan below
                let pr = (0.45 * pitch).min(0.9 * hd).min(0.14);
                let zc = (top - 0.12 - pr).max(pr);
                b.rod(Handle, [px, py, top], [px, py, zc + pr], 0.008);
                b.rod(Pot, [px, py - 0.02, zc], [px, py + 0.02, zc], pr);
            }
        }
    }
}

/// A sawhorse: a wooden beam along x at the top, a pair of legs splayed front and back at
/// each end under it, a brace across each pair and a shelf rail between the pairs.
pub fn sawhorse(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let bt = 0.12 * h.min(1.0);
    let bd = (0.18 * hd).max(0.04);
    b.cuboid(Top, [-hw, -bd, h - bt], [hw, bd, h]);
    let s = 0.025;
    let xe = 0.8 * hw;
    for sx in [-1.0, 1.0] {
        let x = sx * xe;
        for sy in [-1.0, 1.0] {
            b.rod(
                Frame,
                [x, sy * 0.5 * bd, h - bt],
                [x, sy * (hd - s), 0.0],
                s,
            );
        }
        let zb = 0.35 * h;
        let yb = bd + (hd - s - bd) * (1.0 - zb / (h - bt)) * 0.95;
        b.cuboid(Frame, [x - s, -yb, zb - 0.03], [x + s, yb, zb + 0.03]);
    }
    b.cuboid(
        Frame,
        [-xe, -0.02, 0.35 * h - 0.03],
        [xe, 0.02, 0.35 * h + 0.03],
    );
}

/// A baby gate: a low white frame with close upright bars (too narrow for a child to pass), a
/// door in its middle with a latch on top, and pressure knobs at the sides that hold it in a
/// doorway or at the top of the stairs.
pub fn baby_gate(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let f = 0.02;
    let t = (0.5 * hd).min(0.015);
    b.cuboid(Frame, [-hw + 0.04, -t, 0.0], [hw - 0.04, t, f]);
    b.cuboid(Frame, [-hw + 0.04, -t, h - f], [hw - 0.04, t, h]);
    for sx in [-1.0, 1.0] {
        let x0 = sx * (hw - 0.04);
        b.cuboid(
            Frame,
            [x0.min(x0 - sx * f), -t, 0.0],
            [x0.max(x0 - sx * f), t, h],
        );
        // pressure knobs top and bottom out to the doorway's sides
        for z in [0.15 * h, 0.85 * h] {
            b.rod(Handle, [x0, 0.0, z], [sx * hw, 0.0, z], 0.02);
        }
    }
    // the door's stiles in the middle
    let dw = 0.3 * hw;
    for x in [-dw, dw] {
        b.cuboid(Frame, [x - 0.5 * f, -t, f], [x + 0.5 * f, t, h - f]);
    }
    // close upright bars
    let gap = 0.06;
    let x0 = -hw + 0.04 + f;
    let n = ((2.0 * (hw - 0.04 - f)) / gap).floor() as usize;
    for k in 1..n {
        let x = x0 + k as f64 * gap;
        b.rod(Frame, [x, 0.0, f], [x, 0.0, h - f], 0.006);
    }
    // the latch on top of the door
    b.cuboid(
        Handle,
        [dw - 0.05, -1.6 * t, h - 2.5 * f],
        [dw + 0.02, 1.6 * t, h + 0.0],
    );
}

/// A step stool: two side frames, a lower tread at the front and an upper one behind and
/// above it, each with a grip strip, and a brace across the back.
pub fn step_stool(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.025 * (h / 0.5).clamp(0.6, 1.6);
    let z1 = 0.5 * h;
    let sides = 0.04;
    for sx in [-1.0, 1.0] {
        let (x0, x1) = if sx < 0.0 {
            (-hw, -hw + sides)
        } else {
            (hw - sides, hw)
        };
        // the side frame: a tall back leg, a short front leg, rails between
        b.cuboid(Body, [x0, -hd, 0.0], [x1, -hd + 0.06, h]);
        b.cuboid(Body, [x0, hd - 0.06, 0.0], [x1, hd, z1]);
        b.cuboid(Body, [x0, 0.0 - 0.03, 0.0], [x1, 0.0 + 0.03, h]);
        b.cuboid(Body, [x0, -hd, z1 - t], [x1, hd, z1]);
        b.cuboid(Body, [x0, -hd, h - t], [x1, 0.03, h]);
    }
    let (x0, x1) = (-hw + sides, hw - sides);
    b.cuboid(Top, [x0, 0.0, z1 - t], [x1, hd, z1]);
    b.cuboid(Top, [x0, -hd, h - t], [x1, 0.0, h]);
    for (y0, y1, z) in [(0.1 * hd, 0.9 * hd, z1), (-0.9 * hd, -0.1 * hd, h)] {
        let mut y = y0;
        while y + 0.02 <= y1 {
            b.cuboid(Tyre, [x0 + 0.02, y, z - 0.002], [x1 - 0.02, y + 0.015, z]);
            y += 0.035;
        }
    }
    b.cuboid(Body, [x0, -hd, 0.1 * h], [x1, -hd + 0.03, 0.16 * h]);
}
