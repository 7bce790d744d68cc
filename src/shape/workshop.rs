//! Layouts of workshop things: an anvil on its stump, a lathe, a drill press and a table saw.
//! The front faces +y, z up, the bottom face's centre at the origin.
use super::archetypes::{frame_along, Builder};
use super::materials::Role::*;
use super::parts::frustum_profile;

/// An anvil on a log stump: a flat face with a heel at -x and a tapering horn at +x, on a
/// narrow waist over a spreading foot.
pub fn anvil(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.55 * h;
    let r = hd.min(0.3 * hw);
    b.cylinder(Trunk, [0.0, 0.0, 0.0], r, top);
    b.cylinder(Top, [0.0, 0.0, top - 0.005], 0.97 * r, 0.005);
    let a = h - top;
    let face = (0.28 * b.d).min(0.9 * hd);
    let horn = 0.36 * b.w;
    let (x0, x1) = (-hw, hw - horn);
    // Foot, waist and the body under the face.
    b.cuboid(
        Metal,
        [-0.45 * hw, -0.95 * hd.min(r), top],
        [0.35 * hw, 0.95 * hd.min(r), top + 0.22 * a],
    );
    b.cuboid(
        Metal,
        [-0.3 * hw, -0.5 * face, top + 0.22 * a],
        [0.2 * hw, 0.5 * face, top + 0.6 * a],
    );
    b.cuboid(
        Metal,
        [x0 + 0.08 * b.w, -0.5 * face, top + 0.6 * a],
        [x1, 0.5 * face, h - 0.14 * a],
    );
    b.cuboid(Metal, [x0, -0.6 * face, h - 0.14 * a], [x1, 0.6 * face, h]);
    // The horn: a cone from the face's end, its top level with the face.
    let rh = 0.16 * a;
    b.revolved(
        Metal,
        0,
        [x1, 0.0, h - rh],
        frame_along([1.0, 0.0, 0.0]),
        1.0,
        frustum_profile(rh, 0.0, horn),
    );
}

/// A lathe: a long bed on two pedestal cabinets, a headstock with its chuck at the left, a
/// tailstock at the right, a workpiece between them and a carriage with a hand wheel.
pub fn lathe(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zb = 0.68 * h;
    let leg = 0.22 * b.w;
    for (x0, x1) in [(-hw, -hw + leg), (hw - 0.8 * leg, hw)] {
        b.cuboid(
            Body,
            [x0 + 0.02, -0.8 * hd, 0.0],
            [x1 - 0.02, 0.7 * hd, zb - 0.04],
        );
        b.cuboid(
            Door,
            [x0 + 0.05, 0.7 * hd, 0.08],
            [x1 - 0.05, 0.72 * hd, zb - 0.1],
        );
    }
    b.cuboid(Top, [-hw, -hd, zb - 0.04], [hw, 0.8 * hd, zb]);
    b.cuboid(
        Metal,
        [-hw + 0.05, -0.5 * hd, zb],
        [hw - 0.05, 0.2 * hd, zb + 0.08 * h],
    );
    let zs = 0.87 * h;
    // Headstock, chuck and its jaws.
    let head_x = -hw + 0.26 * b.w;
    b.cuboid(Body, [-hw, -0.7 * hd, zb], [head_x, 0.35 * hd, h]);
    let rc = 0.09 * h;
    b.revolved(
        Metal,
        0,
        [head_x, -0.15 * hd, zs],
        frame_along([1.0, 0.0, 0.0]),
        1.0,
        frustum_profile(rc, rc, 0.06 * b.w),
    );
    // Tailstock and its quill.
    let tail_x = hw - 0.16 * b.w;
    b.cuboid(
        Body,
        [tail_x, -0.5 * hd, zb + 0.08 * h],
        [hw - 0.04, 0.15 * hd, zs + 0.05 * h],
    );
    b.rod(
        Metal,
        [tail_x, -0.15 * hd, zs],
        [tail_x - 0.06 * b.w, -0.15 * hd, zs],
        0.025 * h,
    );
    // The workpiece between centres.
    b.rod(
        Trunk,
        [head_x + 0.06 * b.w, -0.15 * hd, zs],
        [tail_x - 0.06 * b.w, -0.15 * hd, zs],
        0.035 * h,
    );
    // The carriage with a tool post and an apron hand wheel at the front.
    let cx = 0.05 * b.w;
    b.cuboid(
        Body,
        [cx - 0.08 * b.w, -0.5 * hd, zb + 0.08 * h],
        [cx + 0.08 * b.w, 0.45 * hd, zb + 0.13 * h],
    );
    b.cuboid(
        Body,
        [cx - 0.07 * b.w, 0.25 * hd, zb - 0.1 * h],
        [cx + 0.07 * b.w, 0.45 * hd, zb + 0.08 * h],
    );
    b.cuboid(
        Metal,
        [cx - 0.03 * b.w, -0.05 * hd, zb + 0.13 * h],
        [cx + 0.03 * b.w, 0.15 * hd, zs - 0.04 * h],
    );
    b.revolved(
        Handle,
        0,
        [cx, 0.45 * hd, zb],
        frame_along([0.0, 1.0, 0.0]),
        1.0,
        frustum_profile(0.06 * h, 0.06 * h, 0.04 * hd),
    );
}

/// A drill press: a heavy foot, a round column at the back, a work table on an arm, and a head
/// with the motor behind, a belt cover on top, the chuck below and three feed handles.
pub fn drill_press(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let yc = -0.55 * hd;
    b.cuboid(Body, [-0.8 * hw, -hd, 0.0], [0.8 * hw, 0.7 * hd, 0.05 * h]);
    let rc = (0.16 * hw.min(hd)).max(0.03);
    b.cylinder(Metal, [0.0, yc, 0.05 * h], rc, 0.8 * h);
    // The table and its arm.
    let zt = 0.5 * h;
    b.cuboid(Body, [-0.06, yc, zt - 0.08], [0.06, 0.25 * hd, zt - 0.01]);
    b.cylinder(Top, [0.0, 0.25 * hd, zt - 0.03], 0.6 * hw.min(hd), 0.03);
    // The head.
    let (z0, z1) = (0.72 * h, 0.9 * h);
    b.cuboid(
        Body,
        [-0.5 * hw, yc - rc - 0.02, z0],
        [0.5 * hw, 0.45 * hd, z1],
    );
    b.cuboid(
        Top,
        [-0.55 * hw, yc - rc - 0.02, z1],
        [0.55 * hw, 0.5 * hd, h],
    );
    b.revolved(
        Body,
        0,
        [0.0, yc - rc - 0.02, 0.76 * h],
        frame_along([0.0, -1.0, 0.0]),
        1.0,
        frustum_profile(0.35 * hw, 0.35 * hw, (hd + yc - rc - 0.02).max(0.02)),
    );
    // The quill, the chuck and the bit.
    let yq = 0.25 * hd;
    b.cylinder(Metal, [0.0, yq, z0 - 0.06 * h], 0.03, 0.06 * h);
    b.frustum(Metal, [0.0, yq, z0 - 0.1 * h], 0.012, 0.012, 3.0, 0.04 * h);
    b.cylinder(Metal, [0.0, yq, z0 - 0.16 * h], 0.005, 0.06 * h);
    // Three feed handles from the head's right side.
    let hub = [0.5 * hw, 0.0, 0.8 * h];
    for k in 0..3 {
        let a = std::f64::consts::TAU * k as f64 / 3.0 + 0.3;
        let tip = [0.97 * hw, 0.5 * hd * a.cos(), hub[2] + 0.09 * h * a.sin()];
        b.rod(Handle, hub, tip, 0.008);
        b.ellipsoid(Handle, tip, [0.018, 0.018, 0.018]);
    }
}

/// A table saw: a cabinet base under a wide steel table, a round blade standing up through
/// it under a guard, a rip fence on its rail and a height wheel at the front.
pub fn table_saw(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rb = (0.25 * hd).min(0.15).min(0.12 * h);
    let zt = h - 1.05 * rb - 0.01;
    let t = 0.04;
    b.cuboid(
        Body,
        [-0.6 * hw, -0.6 * hd, 0.0],
        [0.6 * hw, 0.6 * hd, 0.06],
    );
    b.frustum(
        Body,
        [0.0, 0.0, 0.06],
        0.55 * hw,
        0.55 * hd,
        0.75,
        zt - t - 0.06,
    );
    b.cuboid(Top, [-hw, -hd + 0.06, zt - t], [hw, hd - 0.06, zt]);
    // The front rail the fence rides on.
    b.cuboid(Frame, [-hw, hd - 0.06, zt - 0.08], [hw, hd, zt - 0.02]);
    // The rip fence: a bar front to back.
    let xf = 0.3 * hw;
    b.cuboid(Frame, [xf, -hd + 0.06, zt], [xf + 0.05, hd, zt + 0.06]);
    // The blade standing up through the table and its guard.
    let xb = -0.15 * hw;
    b.revolved(
        Metal,
        0,
        [xb - 0.002, 0.0, zt - 0.15 * rb],
        frame_along([1.0, 0.0, 0.0]),
        1.0,
        frustum_profile(rb, rb, 0.004),
    );
    b.cuboid(
        Glass,
        [xb - 0.03, -1.1 * rb, zt + 0.9 * rb],
        [xb + 0.03, 1.1 * rb, zt + 1.0 * rb],
    );
    b.rod(
        Metal,
        [xb, -1.1 * rb, zt],
        [xb, -1.1 * rb, zt + 0.9 * rb],
        0.008,
    );
    // The height wheel on the cabinet's front.
    b.revolved(
        Handle,
        0,
        [0.0, 0.47 * hd, 0.5 * zt],
        frame_along([0.0, 1.0, 0.0]),
        1.0,
        frustum_profile(0.07, 0.07, 0.03),
    );
}
