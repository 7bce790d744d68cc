//! Collider geometry, world frame (z up): boxes, a convex prism around an object's opaque
//! Gaussians, and the room's walls with their door and window openings cut out
//! (ARCHITECTURE.md, "Openings").
use serde_json::Value;

/// Wall thickness outside the room's inner faces, metres.
pub const WALL: f64 = 0.1;

/// A triangle soup with shared vertices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    pub vertices: Vec<[f64; 3]>,
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// Adds the axis-aligned box `lo..hi` (outward, counter-clockwise faces).
    pub fn add_box(&mut self, lo: [f64; 3], hi: [f64; 3]) {
        let b = self.vertices.len() as u32;
        for k in 0..8 {
            self.vertices.push([
                if k & 1 == 0 { lo[0] } else { hi[0] },
                if k & 2 == 0 { lo[1] } else { hi[1] },
                if k & 4 == 0 { lo[2] } else { hi[2] },
            ]);
        }
        // Faces -z, +z, -y, +y, -x, +x as quads of corner bits.
        for q in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            self.triangles.push([b + q[0], b + q[1], b + q[2]]);
            self.triangles.push([b + q[0], b + q[2], b + q[3]]);
        }
    }

    /// Bounding box `(lo, hi)`.
    pub fn bounds(&self) -> ([f64; 3], [f64; 3]) {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for v in &self.vertices {
            for a in 0..3 {
                lo[a] = lo[a].min(v[a]);
                hi[a] = hi[a].max(v[a]);
            }
        }
        (lo, hi)
    }
}

/// The convex prism over the 2-D convex hull of `points` (x, y), from `z0` to `z1`; `None`
/// when the points span no area.
pub fn hull_prism(points: &[[f64; 2]], z0: f64, z1: f64) -> Option<Mesh> {
    let hull = crate::util::convex_hull(points);
    if hull.len() < 3 {
        return None;
    }
    let n = hull.len() as u32;
    let mut m = Mesh::default();
    for z in [z0, z1] {
        m.vertices.extend(hull.iter().map(|p| [p[0], p[1], z]));
    }
    for k in 1..n - 1 {
        m.triangles.push([0, k + 1, k]); // bottom, facing down
        m.triangles.push([n, n + k, n + k + 1]); // top, facing up
    }
    for k in 0..n {
        let j = (k + 1) % n;
        m.triangles.push([k, j, n + j]);
        m.triangles.push([k, n + j, n + k]);
    }
    Some(m)
}

/// A door or window in a wall.
#[derive(Debug, Clone, PartialEq)]
pub struct Opening {
    pub kind: String,
    /// `north` (+y), `south`, `east` (+x) or `west`.
    pub wall: String,
    /// Bottom centre on the wall's inner face.
    pub position: [f64; 3],
    pub width: f64,
    pub height: f64,
}

/// The `openings` list of a scene.json or layout.json value (entries that do not parse are
/// skipped).
pub fn openings(v: &Value) -> Vec<Opening> {
    let num = |x: &Value| x.as_f64();
    v.get("openings")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
        .filter_map(|o| {
            let p = o.get("position")?.as_array()?;
            Some(Opening {
                kind: o.get("kind")?.as_str()?.to_string(),
                wall: o.get("wall")?.as_str()?.to_lowercase(),
                position: [num(p.first()?)?, num(p.get(1)?)?, num(p.get(2)?)?],
                width: num(o.get("width")?)?,
                height: num(o.get("height")?)?,
            })
        })
        .collect()
}

/// The four walls of a room `[W, D, H]` centred on the origin, each a slab [`WALL`] thick
/// outside the inner face, with `openings` cut out: `(side, mesh)`.
pub fn walls(room: [f64; 3], openings: &[Opening]) -> Vec<(&'static str, Mesh)> {
    let [w, d, h] = room.map(|v| v / 2.0);
    let t = WALL;
    let mut out = vec![];
    for side in ["north", "south", "east", "west"] {
        // Along-wall axis 0 (x) or 1 (y), its span, and the slab's span across.
        let (axis, span, across) = match side {
            "north" => (0, [-w - t, w + t], [d, d + t]),
            "south" => (0, [-w - t, w + t], [-d - t, -d]),
            "east" => (1, [-d, d], [w, w + t]),
            _ => (1, [-d, d], [-w - t, -w]),
        };
        let mut holes: Vec<[f64; 4]> = openings
            .iter()
            .filter(|o| o.wall == side)
            .map(|o| {
                let c = o.position[axis];
                let z0 = o.position[2].max(0.0);
                [
                    (c - o.width / 2.0).max(span[0]),
                    (c + o.width / 2.0).min(span[1]),
                    z0,
                    (z0 + o.height).min(2.0 * h),
                ]
            })
            .filter(|o| o[1] > o[0] && o[3] > o[2])
            .collect();
        holes.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let mut m = Mesh::default();
        let mut piece = |a: f64, b: f64, z0: f64, z1: f64| {
            if b - a > 1e-6 && z1 - z0 > 1e-6 {
                let (lo, hi) = if axis == 0 {
                    ([a, across[0], z0], [b, across[1], z1])
                } else {
                    ([across[0], a, z0], [across[1], b, z1])
                };
                m.add_box(lo, hi);
            }
        };
        let mut cursor = span[0];
        for o in &holes {
            let lo = o[0].max(cursor);
            piece(cursor, lo, 0.0, 2.0 * h);
            piece(lo, o[1], 0.0, o[2]);
            piece(lo, o[1], o[3], 2.0 * h);
            cursor = cursor.max(o[1]);
        }
        piece(cursor, span[1], 0.0, 2.0 * h);
        out.push((side, m));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hull_of_a_square_with_inner_points_is_its_corners() {
        let pts = [
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [0.5, 0.5],
            [0.2, 0.7],
        ];
        let m = hull_prism(&pts, 0.0, 2.0).expect("area");
        assert_eq!(m.vertices.len(), 8);
        assert_eq!(m.bounds(), ([0.0, 0.0, 0.0], [1.0, 1.0, 2.0]));
    }

    #[test]
    fn a_door_leaves_a_gap_and_a_lintel() {
        let door = Opening {
            kind: "door".into(),
            wall: "south".into(),
            position: [1.0, -2.0, 0.0],
            width: 0.9,
            height: 2.1,
        };
        let ws = walls([6.0, 4.0, 2.8], &[door]);
        let (_, south) = ws.iter().find(|w| w.0 == "south").expect("south");
        // Left piece, lintel, right piece: no box covers the door's middle below 2.1 m.
        assert_eq!(south.vertices.len(), 3 * 8);
        for b in south.vertices.chunks(8) {
            let (lo, hi) = Mesh {
                vertices: b.to_vec(),
                triangles: vec![],
            }
            .bounds();
            let covers_door = lo[0] < 1.0 && hi[0] > 1.0 && lo[2] < 1.0;
            assert!(!covers_door, "{lo:?} {hi:?}");
        }
        let (_, north) = ws.iter().find(|w| w.0 == "north").expect("north");
        assert_eq!(north.vertices.len(), 8);
    }
}
