//! A four-poster canopy bed: the bed of `furniture.rs` with a headboard of its own height, a
//! turned post at each corner up to the full height, rails joining the posts' tops, a fabric
//! canopy over them with a valance round its edge, and drapes gathered at each post, so it
//! reads as a canopy bed from the front and from behind. The head is at -y.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A canopy bed: posts, rails, canopy, valance and drapes round an ordinary bed.
pub fn canopy_bed(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    // The bed itself, its headboard about 1.1 m high.
    let bed_h = 1.1_f64.min(0.55 * h);
    b.h = bed_h;
    super::furniture::bed(b);
    b.h = h;
    let p = 0.04;
    let top = 0.05;
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            let (x, y) = (sx * (hw - p), sy * (hd - p));
            b.cylinder(Frame, [x, y, 0.0], p, h - top);
            // A finial knob on each post.
            b.ellipsoid(Frame, [x, y, h - top], [1.4 * p, 1.4 * p, 1.2 * top]);
            // Drapes gathered at the post, from the canopy down to the floor.
            let (dx, dy) = (x - sx * 2.2 * p, y - sy * 2.2 * p);
            b.revolved(
                Canvas,
                0,
                [dx, dy, 0.05],
                super::parts::IDENTITY,
                1.0,
                vec![
                    [0.0, 0.0],
                    [0.07, 0.0],
                    [0.035, 0.45 * (h - 0.05)],
                    [0.05, 0.8 * (h - 0.05)],
                    [0.08, h - top - 0.15 - 0.05],
                    [0.0, h - top - 0.15 - 0.05],
                ],
            );
        }
    }
    // Rails along the top, the canopy over them and a valance hanging round its edge.
    let z = h - top - 0.06;
    b.cuboid(Frame, [-hw, -hd, z], [hw, -hd + 2.0 * p, z + 0.06]);
    b.cuboid(Frame, [-hw, hd - 2.0 * p, z], [hw, hd, z + 0.06]);
    b.cuboid(Frame, [-hw, -hd, z], [-hw + 2.0 * p, hd, z + 0.06]);
    b.cuboid(Frame, [hw - 2.0 * p, -hd, z], [hw, hd, z + 0.06]);
    b.cuboid(
        Canvas,
        [-hw + p, -hd + p, z + 0.06],
        [hw - p, hd - p, z + 0.07],
    );
    let v = 0.15_f64.min(0.1 * h);
    b.cuboid(Canvas, [-hw, -hd, z - v], [hw, -hd + 0.01, z + 0.04]);
    b.cuboid(Canvas, [-hw, hd - 0.01, z - v], [hw, hd, z + 0.04]);
    b.cuboid(Canvas, [-hw, -hd, z - v], [-hw + 0.01, hd, z + 0.04]);
    b.cuboid(Canvas, [hw - 0.01, -hd, z - v], [hw, hd, z + 0.04]);
}
