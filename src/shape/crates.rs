//! Layouts of the real boxes, each still a box in outline but with the parts that say which
//! box it is: cardboard boxes (a stack of two, taped along their lid seams), a wooden crate
//! (boards with gaps between corner battens), a shipping container (a ribbed steel box with
//! corner castings and locking bars on its end doors), a hay bale (straw bound by two
//! twines) and a ballot box (see-through walls in a frame, slips inside, a slotted lid). The
//! front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// Cardboard boxes: a big box with a smaller one set on it a little askew, each with tape along
/// the seam between its lid flaps and down its ends.
pub fn cardboard_boxes(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let tape = |b: &mut Builder, x: [f64; 2], y: [f64; 2], z: [f64; 2]| {
        let t = 0.025f64.min(0.1 * (y[1] - y[0]));
        let yc = 0.5 * (y[0] + y[1]);
        b.cuboid(
            Handle,
            [x[0], yc - t, z[1] - 0.001],
            [x[1], yc + t, z[1] + 0.001],
        );
        for xe in [x[0], x[1]] {
            b.cuboid(
                Handle,
                [xe - 0.001, yc - t, z[1] - 0.25 * (z[1] - z[0])],
                [xe + 0.001, yc + t, z[1]],
            );
        }
    };
    let z1 = 0.55 * h;
    b.cuboid(
        Body,
        [-hw + 0.002, -hd + 0.002, 0.0],
        [hw - 0.002, hd - 0.002, z1],
    );
    tape(b, [-hw + 0.002, hw - 0.002], [-hd, hd], [0.0, z1 - 0.001]);
    let (sw, sd) = (0.6 * hw, 0.62 * hd);
    let first = b.parts.len();
    b.cuboid_v(Body, 1, [-sw, -sd, z1], [sw, sd, h - 0.002]);
    tape(b, [-sw, sw], [-sd, sd], [z1, h - 0.002]);
    b.translate_from(first, [-0.2 * hw, 0.15 * hd, 0.0]);
}

/// A wooden crate: boards round its sides with narrow gaps between them, battens up its
/// corners, and a lid of boards across the top.
pub fn crate_box(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = 0.018;
    b.cuboid(Interior, [-hw + t, -hd + t, 0.0], [hw - t, hd - t, h - t]);
    let n = ((h / 0.12).round() as usize).max(3);
    let pitch = h / n as f64;
    for k in 0..n {
        let (z0, z1) = (k as f64 * pitch + 0.006, (k + 1) as f64 * pitch - 0.006);
        let v = (k % 3) as u32;
        for (y0, x0) in [(-hd, -hw), (hd - t, hw - t)] {
            b.cuboid_v(Body, v, [-hw + t, y0, z0], [hw - t, y0 + t, z1]);
            b.cuboid_v(Body, v, [x0, -hd + t, z0], [x0 + t, hd - t, z1]);
        }
    }
    let bat = 0.05;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - bat / 2.0), sy * (hd - bat / 2.0));
            b.cuboid(
                Frame,
                [x - bat / 2.0, y - bat / 2.0, 0.0],
                [x + bat / 2.0, y + bat / 2.0, h],
            );
        }
    }
    let m = ((b.w / 0.12).round() as usize).max(3);
    let p = b.w / m as f64;
    for i in 0..m {
        let x0 = -hw + i as f64 * p;
        b.cuboid_v(
            Top,
            (i % 3) as u32,
            [x0 + 0.004, -hd, h - t],
            [x0 + p - 0.004, hd, h],
        );
    }
}

/// A shipping container: a steel box with vertical ribs pressed into its long sides, a ribbed
/// roof, corner castings, and two doors at its front end with four locking bars.
pub fn cargo_container(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let c = 0.16;
    let rib = 0.03;
    b.cuboid(Body, [-hw + rib, -hd, rib], [hw - rib, hd - 0.02, h - rib]);
    // Ribs along the long sides (which run along the longer axis).
    let along_y = b.d >= b.w;
    let len = if along_y { b.d } else { b.w };
    let n = ((len - 2.0 * c) / 0.28).floor() as usize;
    for i in 0..n {
        let f = -0.5 * len + c + (i as f64 + 0.5) * (len - 2.0 * c) / n as f64;
        for s in [-1.0, 1.0] {
            if along_y {
                let x0 = if s > 0.0 { hw - rib } else { -hw };
                b.cuboid(Body, [x0, f - 0.06, c], [x0 + rib, f + 0.06, h - c]);
            } else {
                let y0 = if s > 0.0 { hd - rib } else { -hd };
                b.cuboid(Body, [f - 0.06, y0, c], [f + 0.06, y0 + rib, h - c]);
            }
        }
    }
    // Frame: corner posts and top and bottom rails, castings at the corners.
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - 0.5 * c), sy * (hd - 0.5 * c));
            let p = 0.5 * c - 0.003;
            b.cuboid(Frame, [x - p, y - p, 0.0], [x + p, y + p, h]);
            for z in [0.0, h - c] {
                b.cuboid(
                    Metal,
                    [x - 0.5 * c, y - 0.5 * c, z],
                    [x + 0.5 * c, y + 0.5 * c, z + c],
                );
            }
        }
    }
    for z in [0.0, h - 0.6 * c] {
        b.cuboid(
            Frame,
            [-hw + c, -hd + c, z],
            [hw - c, hd - 0.02, z + 0.6 * c],
        );
    }
    // The doors at the +y end, split down the middle, each with two locking bars.
    b.cuboid(Door, [-hw + c, hd - 0.02, c], [-0.005, hd - 0.006, h - c]);
    b.cuboid(Door, [0.005, hd - 0.02, c], [hw - c, hd - 0.006, h - c]);
    for f in [-0.75, -0.3, 0.3, 0.75] {
        let x = f * (hw - c);
        b.cuboid(Handle, [x - 0.02, hd - 0.006, c], [x + 0.02, hd, h - c]);
    }
}

/// A hay bale: a block of straw with slightly rounded edges, bound by two twines round it.
pub fn hay_bale(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let e = 0.03;
    let g = 0.004;
    b.cuboid(Body, [-hw + e, -hd + g, 0.0], [hw - e, hd - g, h - g]);
    b.cuboid(Body, [-hw, -hd + e, e], [hw, hd - e, h - e]);
    for f in [-0.45, 0.45] {
        let x = f * hw;
        b.cuboid(Handle, [x - 0.008, -hd, 0.0], [x + 0.008, -hd + 1.5 * g, h]);
        b.cuboid(Handle, [x - 0.008, hd - 1.5 * g, 0.0], [x + 0.008, hd, h]);
        b.cuboid(Handle, [x - 0.008, -hd, h - 1.5 * g], [x + 0.008, hd, h]);
    }
}

/// A ballot box: see-through walls in a dark frame, folded ballot papers lying inside, a white
/// label across front and back, a lid with a slot across it, and a seal at the front.
pub fn ballot_box(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let f = (0.06 * b.w.min(b.d)).clamp(0.008, 0.025);
    let lid = 0.12 * h;
    b.cuboid(Frame, [-hw, -hd, 0.0], [hw, hd, f]);
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - f / 2.0), sy * (hd - f / 2.0));
            b.cuboid(
                Frame,
                [x - f / 2.0, y - f / 2.0, 0.0],
                [x + f / 2.0, y + f / 2.0, h - lid],
            );
        }
    }
    b.cuboid(
        Pane,
        [-hw + f, -hd + 0.004, f],
        [hw - f, -hd + 0.007, h - lid],
    );
    b.cuboid(
        Pane,
        [-hw + f, hd - 0.007, f],
        [hw - f, hd - 0.004, h - lid],
    );
    b.cuboid(Pane, [-hw, -hd + f, f], [-hw + 0.003, hd - f, h - lid]);
    b.cuboid(Pane, [hw - 0.003, -hd + f, f], [hw, hd - f, h - lid]);
    // Ballot papers, a loose heap of folded slips on the floor of the box.
    for (k, (x, y, a)) in [
        (-0.4, -0.3, 0.3),
        (0.3, -0.2, -0.5),
        (-0.1, 0.35, 0.9),
        (0.45, 0.4, 0.1),
        (0.0, 0.0, -0.2),
    ]
    .into_iter()
    .enumerate()
    {
        let z = f + 0.012 * (k % 3) as f64;
        let (sw, sd) = (0.3 * hw, 0.2 * hd);
        let first = b.parts.len();
        b.cuboid_v(Books, k as u32, [-sw, -sd, z], [sw, sd, z + 0.008]);
        b.turn_from(first, super::parts::rot_z(a));
        b.translate_from(first, [x * (hw - f - sw), y * (hd - f - sd), 0.0]);
    }
    // A printed label across the front and back, the lid, its slot and the seal.
    for y in [-hd, hd - 0.003] {
        b.cuboid(
            Canvas,
            [-0.75 * hw, y, 0.3 * h],
            [0.75 * hw, y + 0.003, 0.72 * h],
        );
    }
    b.cuboid(Top, [-hw, -hd, h - lid], [hw, hd, h]);
    b.cuboid(
        Interior,
        [-0.5 * hw, -0.08 * hd, h - 0.002],
        [0.5 * hw, 0.08 * hd, h + 0.001],
    );
    b.cuboid(
        Handle,
        [-0.08 * hw, hd - 0.004, 0.74 * h],
        [0.08 * hw, hd, h - 0.3 * lid],
    );
}
