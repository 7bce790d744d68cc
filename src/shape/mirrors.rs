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
