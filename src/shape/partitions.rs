//! Layouts of free-standing partitions: a folding screen (a room divider or a privacy screen)
//! of hinged framed panels standing in a zigzag, each panel a frame round a fabric or paper
//! infill with a cross rail, hinges between the panels and short feet. The zigzag fills the
//! size box: its depth is how far the folds stand out. The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::rot_z;

/// A folding screen: three panels for a narrow box, four for a wide one, each turned
/// alternately to the left and right so the screen stands on its own.
pub fn folding_screen(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let n = if b.w > 1.3 { 4 } else { 3 };
    let t = 0.025;
    // Panel width L and fold angle a with n·L·cos a = w and L·sin a = d − t.
    let dx = b.w / n as f64;
    let dy = (b.d - t).max(0.0);
    let l = (dx * dx + dy * dy).sqrt();
    let a = dy.atan2(dx);
    let (zf, ztop) = (0.05, h);
    let frame = 0.035;
    for k in 0..n {
        // Panel k runs from its left edge to its right edge, alternately front to back.
        let x0 = -hw + k as f64 * dx;
        let (y0, y1) = if k % 2 == 0 {
            (-hd + t / 2.0, hd - t / 2.0)
        } else {
            (hd - t / 2.0, -hd + t / 2.0)
        };
        let (cx, cy) = (x0 + dx / 2.0, 0.5 * (y0 + y1));
        let yaw = if k % 2 == 0 { a } else { -a };
        let rot = rot_z(yaw);
        let at = |u: f64| [cx + u * yaw.cos(), cy + u * yaw.sin()];
        let half = l / 2.0;
        // The frame: two stiles, a top and a bottom rail, and a cross rail at a third.
        for u in [-half + frame / 2.0, half - frame / 2.0] {
            let p = at(u);
            b.slab(
                Frame,
                [p[0], p[1], 0.5 * (zf + ztop)],
                [frame / 2.0, t / 2.0, 0.5 * (ztop - zf)],
                rot,
            );
        }
        for (z, role) in [
            (zf + frame / 2.0, Frame),
            (ztop - frame / 2.0, Frame),
            (zf + 0.28 * (ztop - zf), Frame),
        ] {
            b.slab(role, [cx, cy, z], [half - frame, t / 2.0, frame / 2.0], rot);
        }
        // The infill: cloth above the cross rail, a panel below it.
        let z_mid = zf + 0.28 * (ztop - zf);
        b.slab(
            Canvas,
            [cx, cy, 0.5 * (z_mid + ztop)],
            [half - frame, 0.3 * t, 0.5 * (ztop - z_mid) - frame],
            rot,
        );
        b.slab(
            Upholstery,
            [cx, cy, 0.5 * (zf + z_mid)],
            [half - frame, 0.3 * t, 0.5 * (z_mid - zf) - frame],
            rot,
        );
        // Feet under both stiles.
        for u in [-half + frame, half - frame] {
            let p = at(u);
            b.cuboid(
                Frame,
                [p[0] - 0.02, p[1] - 0.02, 0.0],
                [p[0] + 0.02, p[1] + 0.02, zf],
            );
        }
        // Hinges at the fold to the next panel.
        if k + 1 < n {
            let p = at(half);
            for z in [zf + 0.15 * (ztop - zf), zf + 0.85 * (ztop - zf)] {
                b.rod(Metal, [p[0], p[1], z - 0.04], [p[0], p[1], z + 0.04], 0.012);
            }
        }
    }
}
