//! Layouts of mirrors that are glass first: a mirror wall (a dance studio's or a gym's), a
//! row of full-height glass panels edge to edge, held by a thin metal edge trim and no wooden
//! frame. The front faces +y, the back against the wall at −y, the bottom face's centre at the
//! origin.
use super::archetypes::Builder;
use super::materials::Role::*;

/// Width of the metal trim round a mirror wall's edge (metres): an aluminium J-channel.
pub const MIRROR_WALL_EDGE: f64 = 0.015;
/// The widest glass panel of a mirror wall (metres); wider walls are several panels.
const PANEL: f64 = 1.2;
/// Width of the seam between two panels (metres): a hairline, drawn in the trim's metal.
const SEAM: f64 = 0.004;

/// A mirror wall: glass panels ([`Canvas`], silvered) across the whole face, thin metal seams
/// between them and a metal trim round the edge standing a few millimetres proud of the glass.
pub fn mirror_wall(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let e = MIRROR_WALL_EDGE.min(0.1 * b.w).min(0.1 * h);
    // The glass stands on a backing the depth of the box less the trim's lip.
    let lip = (0.3 * b.d).min(0.005);
    let face = hd - lip;
    b.cuboid(Canvas, [-hw + e, -hd, e], [hw - e, face, h - e]);
    // Trim: bottom, top, left, right.
    b.cuboid(Metal, [-hw, -hd, 0.0], [hw, hd, e]);
    b.cuboid(Metal, [-hw, -hd, h - e], [hw, hd, h]);
    b.cuboid(Metal, [-hw, -hd, e], [-hw + e, hd, h - e]);
    b.cuboid(Metal, [hw - e, -hd, e], [hw, hd, h - e]);
    // Seams between panels of at most PANEL width.
    let glass = b.w - 2.0 * e;
    let n = (glass / PANEL).ceil().max(1.0) as usize;
    for k in 1..n {
        let x = -hw + e + glass * k as f64 / n as f64;
        b.cuboid(
            Metal,
            [x - 0.5 * SEAM, face, e],
            [x + 0.5 * SEAM, face + 0.001, h - e],
        );
    }
}

/// Half the thickness of a sheen streak (metres): a film on the glass.
const SHEEN: f64 = 0.0008;

/// The sheen that makes glass read as a mirror: two light streaks slanting up to the right (as
/// seen from the room) across the glass (a broad one and a thin one beside it), in the glass's brighter shade
/// ([`Canvas`] variant 1), within the ellipse of semi-axes `rx` (across) and `rz` (up) centred
/// at `c` on the glass's front face (its normal +y, into the room).
pub fn sheen(b: &mut Builder, c: [f64; 3], rx: f64, rz: f64) {
    use super::parts::rot_y;
    let s = std::f64::consts::FRAC_1_SQRT_2;
    // in the unit disc: along (−1, 1)/√2, offset towards the upper left along (1, 1)/√2 (seen
    // from the room, the object's +x is on the viewer's left)
    for (off, wide) in [(0.28, 0.16), (0.02, 0.06)] {
        let half = 0.8 * (1.0_f64 - off * off).sqrt();
        let mid = [s * off, s * off];
        let ends =
            [-1.0, 1.0].map(|k| [(mid[0] - k * s * half) * rx, (mid[1] + k * s * half) * rz]);
        let (dx, dz) = (ends[1][0] - ends[0][0], ends[1][1] - ends[0][1]);
        let centre = [
            c[0] + 0.5 * (ends[0][0] + ends[1][0]),
            c[1] + SHEEN,
            c[2] + 0.5 * (ends[0][1] + ends[1][1]),
        ];
        // rot_y(−a) turns the local x axis to (cos a, 0, sin a)
        let a = dz.atan2(dx);
        let w = 0.5 * wide * rx.min(rz);
        b.slab_v(Canvas, 1, centre, [0.5 * dx.hypot(dz), SHEEN, w], rot_y(-a));
    }
}

#[cfg(test)]
mod tests {
    use super::super::archetypes::get;
    use super::super::materials::{Palette, Role};

    #[test]
    fn a_mirror_glass_is_brighter_than_its_frame_and_its_sheen_brighter_still() {
        for name in ["mirror", "round_mirror", "oval_mirror", "wall_mirror"] {
            let a = get(name);
            let p = Palette::new("", a.main, a.defaults);
            let lum = |c: [f32; 3]| c.iter().sum::<f32>() / 3.0;
            let (glass, sheen, frame) = (
                lum(p.colour(Role::Canvas, 0)),
                lum(p.colour(Role::Canvas, 1)),
                lum(p.colour(Role::Frame, 0)),
            );
            assert!(
                glass > 0.85 && sheen > glass + 0.05 && frame < glass - 0.2,
                "{name}: glass {glass:.2}, sheen {sheen:.2}, frame {frame:.2}"
            );
        }
    }
}
