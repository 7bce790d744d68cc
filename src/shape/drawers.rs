//! Layouts of drawer cases that are not bedroom dressers: a card catalogue (a grid of many small
//! drawers on a stand), a tool chest (many shallow full-width drawers under a lidded top, on
//! castors), a medical cart (a drawer trolley on castors with a rail round its top and a push
//! handle), a changing table (drawers under a padded top with raised edges and low guard
//! rails) and a jewellery armoire (a tall narrow chest of shallow drawers on legs, side doors
//! and a mirrored lid standing open). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A grid of `cols` × `rows` drawer fronts with pulls on the front face `y` between `x0..x1` and
/// `z0..z1`; `pull` is the pull's length as a share of a drawer's width.
fn drawer_grid(
    b: &mut Builder,
    x: [f64; 2],
    z: [f64; 2],
    y: f64,
    cols: usize,
    rows: usize,
    pull: f64,
) {
    let (cw, rh) = ((x[1] - x[0]) / cols as f64, (z[1] - z[0]) / rows as f64);
    let gap = (0.06 * cw.min(rh)).clamp(0.003, 0.008);
    for i in 0..cols {
        for j in 0..rows {
            let (xa, za) = (x[0] + i as f64 * cw, z[0] + j as f64 * rh);
            b.cuboid(
                Door,
                [xa + gap, y - 0.012, za + gap],
                [xa + cw - gap, y, za + rh - gap],
            );
            let (xc, zc) = (xa + 0.5 * cw, za + 0.5 * rh);
            let hl = 0.5 * pull * cw;
            let hz = (0.12 * rh).clamp(0.005, 0.012);
            b.cuboid(Handle, [xc - hl, y, zc - hz], [xc + hl, y + 0.012, zc + hz]);
        }
    }
}

/// Four castors under a case of half size `hw` × `hd`, each a wheel under a swivel block;
/// returns the height they lift the case to.
fn castors(b: &mut Builder, hw: f64, hd: f64) -> f64 {
    let r = 0.04;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - 0.06), sy * (hd - 0.06));
            b.rod(Tyre, [x - 0.015, y, r], [x + 0.015, y, r], r);
            b.cuboid(
                Metal,
                [x - 0.025, y - 0.025, 2.0 * r],
                [x + 0.025, y + 0.025, 2.0 * r + 0.03],
            );
        }
    }
    2.0 * r + 0.03
}

/// A card catalogue: a case on a low open stand, its front a grid of many small drawers, each
/// with a pull.
pub fn card_catalog(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let stand = 0.28 * h;
    b.legs(Frame, 0.05, 0.02, 0.0, stand);
    b.cuboid(
        Frame,
        [-hw + 0.02, -hd + 0.02, stand - 0.06],
        [hw - 0.02, hd - 0.02, stand],
    );
    b.cuboid(Body, [-hw, -hd, stand], [hw, hd - 0.012, h - 0.03]);
    b.cuboid(Top, [-hw, -hd, h - 0.03], [hw, hd, h]);
    let cols = ((b.w / 0.14).round() as usize).max(3);
    let rows = (((h - stand) / 0.11).round() as usize).max(4);
    let (x, z) = ([-hw + 0.03, hw - 0.03], [stand + 0.03, h - 0.05]);
    drawer_grid(b, x, z, hd - 0.012, cols, rows, 0.3);
}

/// A tool chest: a cabinet of many shallow drawers on castors, a deeper chest on top with a
/// lid, and a side handle.
pub fn tool_chest(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let z0 = castors(b, hw, hd);
    let split = 0.72 * h;
    b.cuboid(Body, [-hw + 0.04, -hd, z0], [hw - 0.04, hd - 0.012, split]);
    b.cuboid(
        Body,
        [-hw + 0.04, -hd, split + 0.01],
        [hw - 0.04, hd - 0.012, h - 0.04],
    );
    b.cuboid(Top, [-hw + 0.03, -hd, h - 0.04], [hw - 0.03, hd, h]);
    let rows = (((split - z0) / 0.08).round() as usize).max(5);
    drawer_grid(
        b,
        [-hw + 0.05, hw - 0.05],
        [z0 + 0.02, split - 0.01],
        hd - 0.012,
        1,
        rows,
        0.8,
    );
    drawer_grid(
        b,
        [-hw + 0.05, hw - 0.05],
        [split + 0.02, h - 0.05],
        hd - 0.012,
        2,
        2,
        0.6,
    );
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - 0.02);
        b.rod(
            Handle,
            [x, -0.6 * hd, 0.55 * h],
            [x, 0.6 * hd, 0.55 * h],
            0.012,
        );
    }
}

/// A medical cart: a drawer trolley on castors, a rail round its top on short posts and a push
/// handle out at one end.
pub fn medical_cart(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.88 * h;
    let case_hw = hw - 0.06;
    let z0 = castors(b, case_hw, hd);
    b.cuboid(Body, [-case_hw, -hd, z0], [case_hw, hd - 0.012, top - 0.02]);
    b.cuboid(
        Top,
        [-case_hw - 0.01, -hd, top - 0.02],
        [case_hw + 0.01, hd, top],
    );
    let rows = (((top - z0) / 0.14).round() as usize).max(4);
    drawer_grid(
        b,
        [-case_hw + 0.02, case_hw - 0.02],
        [z0 + 0.02, top - 0.04],
        hd - 0.012,
        1,
        rows,
        0.6,
    );
    // The rail round three sides of the top.
    let (x, y, z) = (case_hw - 0.01, hd - 0.02, h - 0.01);
    for [px, py] in [[-x, -y], [x, -y], [x, y], [-x, y]] {
        b.rod(Metal, [px, py, top], [px, py, z], 0.008);
    }
    b.polyline(
        Metal,
        &[[-x, y, z], [-x, -y, z], [x, -y, z], [x, y, z]],
        0.008,
    );
    // The push handle, off the right end.
    for sy in [-1.0, 1.0] {
        b.rod(
            Handle,
            [case_hw, sy * 0.6 * hd, 0.8 * h],
            [hw - 0.015, sy * 0.6 * hd, 0.8 * h],
            0.012,
        );
    }
    b.rod(
        Handle,
        [hw - 0.015, -0.6 * hd, 0.8 * h],
        [hw - 0.015, 0.6 * hd, 0.8 * h],
        0.015,
    );
}

/// A changing table: a dresser of a few deep drawers, a padded changing mat on its top with
/// rolled raised edges, and low guard rails round the back and sides.
pub fn changing_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let top = 0.82 * h;
    b.legs(Frame, 0.04, 0.02, 0.0, 0.1);
    b.cuboid(Body, [-hw, -hd, 0.1], [hw, hd - 0.012, top - 0.025]);
    b.cuboid(Top, [-hw, -hd, top - 0.025], [hw, hd, top]);
    drawer_grid(
        b,
        [-hw + 0.02, hw - 0.02],
        [0.12, top - 0.04],
        hd - 0.012,
        1,
        3,
        0.25,
    );
    // Guard rails round the back and both ends.
    let g = 0.02;
    b.cuboid(Frame, [-hw, -hd, top], [hw, -hd + g, h]);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - g / 2.0);
        b.cuboid(Frame, [x - g / 2.0, -hd, top], [x + g / 2.0, hd, h]);
    }
    // The mat with its rolled edges raised along the sides.
    let (mx, my) = (hw - g - 0.01, hd - g - 0.01);
    let pad = 0.35 * (h - top);
    b.cuboid(Cushion, [-mx, -my, top], [mx, hd - 0.02, top + pad]);
    let r = 0.5 * (h - top - pad).min(0.12);
    for sy in [-1.0, 1.0] {
        let y = if sy < 0.0 { -my + r } else { hd - 0.02 - r };
        b.rod(Cushion, [-mx, y, top + pad], [mx, y, top + pad], r);
    }
}

/// A jewellery armoire: a tall narrow chest on four slender legs, its front a column of many
/// shallow drawers, a tall hinged door down each side (a necklace cabinet), and a lid on top
/// standing open with a mirror inside it.
pub fn jewelry_armoire(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let legs = 0.16 * h;
    let lid = (0.04 * h).min(0.04);
    // The lid stands open: it rises from the back edge, so the case ends below it by its
    // height as an upright.
    let top = h - 0.9 * b.d.min(0.35 * h);
    let door = 0.018;
    b.legs(Frame, 0.025, 0.02, 0.0, legs + 0.02);
    b.cuboid(
        Frame,
        [-hw + 0.01, -hd + 0.01, legs],
        [hw - 0.01, hd - 0.01, legs + 0.03],
    );
    let (cx, cy) = (hw - door, hd - 0.012);
    b.cuboid(Body, [-cx, -hd, legs + 0.03], [cx, cy, top - lid]);
    b.cuboid(Top, [-hw, -hd, top - lid], [hw, hd, top]);
    let rows = (((top - lid - legs) / 0.07).round() as usize).max(6);
    drawer_grid(
        b,
        [-cx + 0.02, cx - 0.02],
        [legs + 0.05, top - lid - 0.02],
        cy,
        1,
        rows,
        0.25,
    );
    // The side doors: tall leaves over the upper two thirds, each with a knob.
    let z0 = legs + 0.3 * (top - legs);
    for sx in [-1.0, 1.0] {
        let x = sx * cx;
        b.cuboid(
            Door,
            [x.min(x + sx * door), -hd + 0.02, z0],
            [x.max(x + sx * door), hd - 0.03, top - lid - 0.015],
        );
        let xk = sx * (hw + 0.008);
        b.cuboid(
            Handle,
            [xk - 0.008, 0.5 * hd, 0.5 * (z0 + top) - 0.012],
            [xk + 0.008, 0.5 * hd + 0.016, 0.5 * (z0 + top) + 0.012],
        );
    }
    // The open lid: its frame upright along the back edge, the mirror on its front face.
    let up = h - top;
    b.cuboid(Top, [-hw, -hd, top], [hw, -hd + lid, h]);
    b.cuboid(
        Glass,
        [-hw + 0.03, -hd + lid, top + 0.03],
        [hw - 0.03, -hd + lid + 0.004, top + up - 0.03],
    );
}
