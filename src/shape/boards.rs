//! Tables drawn with the game played on them, not as a plain table: a chess table (an inlaid
//! board of light and dark squares with the two armies set up on their back ranks) and an air
//! hockey table (a white playfield inside raised rails, a goal slot at each end, a centre line,
//! two strikers and a puck, on a solid base). Sides across x; the front is +y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A chess table: a table whose top carries a board of 8 × 8 squares and its pieces.
pub fn chess_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pieces = (0.08 * h).clamp(0.03, 0.07);
    let zt = h - pieces;
    b.h = zt;
    super::furniture::table(b);
    b.h = h;
    let side = 0.8 * (2.0 * hw.min(hd));
    let sq = side / 8.0;
    for i in 0..8 {
        for j in 0..8 {
            let role = if (i + j) % 2 == 0 { Interior } else { Canvas };
            let (x0, y0) = (-side / 2.0 + i as f64 * sq, -side / 2.0 + j as f64 * sq);
            b.cuboid(role, [x0, y0, zt], [x0 + sq, y0 + sq, zt + 0.003]);
        }
    }
    // Pieces on the two back ranks of each side: pawns short, the back rank taller.
    for (rank, role) in [(0, Canvas), (1, Canvas), (6, Interior), (7, Interior)] {
        for file in 0..8 {
            let x = -side / 2.0 + (file as f64 + 0.5) * sq;
            let y = -side / 2.0 + (rank as f64 + 0.5) * sq;
            let tall = if rank == 1 || rank == 6 { 0.6 } else { 1.0 };
            b.frustum(
                role,
                [x, y, zt + 0.003],
                0.32 * sq,
                0.32 * sq,
                0.45,
                tall * (pieces - 0.004),
            );
        }
    }
}

/// An air hockey table: a solid base, a white playfield in raised rails with goal slots at the
/// ends (along x), a centre line, two strikers and a puck.
pub fn air_hockey_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let rail = 0.05;
    let zf = h - rail - 0.03;
    // The base: a cabinet under the field on a plinth of legs.
    b.cuboid(
        Body,
        [-hw + 0.05, -hd + 0.05, 0.35 * h],
        [hw - 0.05, hd - 0.05, zf],
    );
    b.legs(Frame, 0.08, 0.1, 0.0, 0.35 * h);
    b.cuboid(Canvas, [-hw, -hd, zf], [hw, hd, zf + 0.01]);
    // Rails round the field, broken by a goal slot at each end.
    let slot = 0.3 * hd;
    b.cuboid(Frame, [-hw, -hd, zf], [hw, -hd + rail, h]);
    b.cuboid(Frame, [-hw, hd - rail, zf], [hw, hd, h]);
    for sx in [-1.0, 1.0] {
        let x = sx * (hw - rail / 2.0);
        b.cuboid(Frame, [x - rail / 2.0, -hd, zf], [x + rail / 2.0, -slot, h]);
        b.cuboid(Frame, [x - rail / 2.0, slot, zf], [x + rail / 2.0, hd, h]);
        b.cuboid(
            Interior,
            [x - rail / 2.0, -slot, zf - 0.04],
            [x + rail / 2.0, slot, zf + 0.005],
        );
        // A striker on each half.
        b.frustum(
            Handle,
            [sx * 0.6 * hw, 0.0, zf + 0.01],
            0.05,
            0.05,
            0.5,
            0.05,
        );
    }
    b.cuboid(
        Handle,
        [-0.005, -hd + rail, zf + 0.01],
        [0.005, hd - rail, zf + 0.012],
    );
    b.cylinder(Interior, [0.15 * hw, 0.2 * hd, zf + 0.01], 0.03, 0.008);
}
