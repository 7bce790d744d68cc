//! Collider geometry, world frame (z up): boxes, the 3-D convex hull of an object's opaque
//! Gaussians (the `quickhull` crate), and the room's walls with their door and window openings cut out
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

/// Grid steps (metres) the points of a hull are snapped to, finest first. quickhull 0.1 (as
/// parry3d 0.31, whose algorithm it follows) can return a mesh that is not convex for dense,
/// near-degenerate clouds (a plant's or a lamp shade's tens of thousands of Gaussians: points
/// 0.5-1.2 m outside faces in this project's drafts); the same clouds on a 1 cm grid give valid
/// hulls. A collider needs no finer detail, and every hull is checked before it is used.
pub const HULL_GRID: [f64; 3] = [0.01, 0.02, 0.04];

/// Twice the area (m²) below which a triangle's plane is not checked: 1 mm².
pub const SLIVER: f64 = 2e-6;

/// The convex hull of `points` in 3-D (quickhull's triangle mesh, outward faces), its vertices
/// on a grid of [`HULL_GRID`] (so within half a cell's diagonal of a point) and every point
/// within that of its inside; `None` when the points span no volume (fewer than four, or all on
/// one plane), a coordinate is not finite, or no grid gives a valid hull. Returns the hull and
/// the grid step it was made on.
pub fn convex_hull(points: &[[f64; 3]]) -> Option<(Mesh, f64)> {
    if points.len() < 4 || points.iter().flatten().any(|v| !v.is_finite()) {
        return None;
    }
    HULL_GRID
        .iter()
        .find_map(|&step| Some((hull_on_grid(points, step)?, step)))
}

/// [`convex_hull`] on one grid step, checked: outward faces, positive volume, every point of
/// the grid inside every face's plane (1 mm tolerance).
fn hull_on_grid(points: &[[f64; 3]], step: f64) -> Option<Mesh> {
    let mut cells: Vec<[i64; 3]> = points
        .iter()
        .map(|p| p.map(|v| (v / step).round() as i64))
        .collect();
    cells.sort_unstable();
    cells.dedup();
    if cells.len() < 4 {
        return None;
    }
    // quickhull works in f32: cells relative to their mean keep the precision where the shape
    // is (a room's coordinates are metres, an object's extent a few of them).
    let n = cells.len() as f64;
    let c = [0, 1, 2].map(|a| (cells.iter().map(|q| q[a] as f64).sum::<f64>() / n).round());
    let local: Vec<[f64; 3]> = cells
        .iter()
        .map(|q| [0, 1, 2].map(|a| (q[a] as f64 - c[a]) * step))
        .collect();
    let pts: Vec<glam::Vec3A> = local
        .iter()
        .map(|p| glam::Vec3A::new(p[0] as f32, p[1] as f32, p[2] as f32))
        .collect();
    let hull = quickhull::ConvexTriangleMesh::try_from_points(&pts, None).ok()?;
    let (vertices, triangles) = hull.into_parts();
    if triangles.len() < 4 {
        return None;
    }
    let mut m = Mesh {
        vertices: vertices
            .iter()
            .map(|v| [f64::from(v.x), f64::from(v.y), f64::from(v.z)])
            .collect(),
        triangles,
    };
    if !(m.volume() > 0.0 && m.holds(&local, 1e-3)) {
        return None;
    }
    for v in &mut m.vertices {
        *v = [0, 1, 2].map(|a| v[a] + c[a] * step);
    }
    Some(m)
}

impl Mesh {
    /// Whether every point lies inside every triangle's plane, within `tol` metres (slivers under
    /// 1 mm², whose plane f32 vertices leave undefined, are skipped).
    pub fn holds(&self, points: &[[f64; 3]], tol: f64) -> bool {
        self.triangles.iter().all(|t| {
            let (a, n) = self.face(t);
            let l = n.length();
            l < SLIVER
                || points
                    .iter()
                    .all(|p| n.dot(glam::DVec3::from(*p) - a) <= tol * l)
        })
    }

    /// Triangle `t`'s first vertex and its normal `(b − a) × (c − a)` (length twice its area).
    fn face(&self, t: &[u32; 3]) -> (glam::DVec3, glam::DVec3) {
        let [a, b, c] = t.map(|i| glam::DVec3::from(self.vertices[i as usize]));
        (a, (b - a).cross(c - a))
    }

    /// The signed volume enclosed by the triangles (positive when they face outward).
    pub fn volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize]);
                (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0]))
                    / 6.0
            })
            .sum()
    }
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

    /// Every face's outward plane, `(normal, offset)` with `normal · p <= offset` inside
    /// (slivers left out).
    fn planes(m: &Mesh) -> Vec<([f64; 3], f64)> {
        m.triangles
            .iter()
            .map(|t| {
                let (a, n) = m.face(t);
                let l = n.length();
                let n = n / l;
                (l, (n.to_array(), n.dot(a)))
            })
            .filter(|(l, _)| *l >= SLIVER)
            .map(|(_, p)| p)
            .collect()
    }

    #[test]
    fn hull_of_a_box_with_inner_points_is_its_corners() {
        let mut pts = vec![];
        for k in 0..8 {
            pts.push([
                if k & 1 == 0 { -0.7 } else { 0.7 },
                if k & 2 == 0 { 1.2 } else { 2.0 },
                if k & 4 == 0 { 0.0 } else { 0.75 },
            ]);
        }
        pts.extend([[0.0, 1.5, 0.3], [0.5, 1.9, 0.7], [-0.69, 1.21, 0.01]]);
        let (m, step) = convex_hull(&pts).expect("volume");
        assert_eq!(step, 0.01);
        assert_eq!(m.vertices.len(), 8);
        assert_eq!(m.triangles.len(), 12);
        assert!(
            (m.volume() - 1.4 * 0.8 * 0.75).abs() < 1e-5,
            "{}",
            m.volume()
        );
        let (lo, hi) = m.bounds();
        for a in 0..3 {
            assert!((lo[a] - [-0.7, 1.2, 0.0][a]).abs() < 1e-6);
            assert!((hi[a] - [0.7, 2.0, 0.75][a]).abs() < 1e-6);
        }
        // Flat or too few points: no hull.
        assert!(convex_hull(&pts[..3]).is_none());
        let flat: Vec<[f64; 3]> = pts.iter().map(|p| [p[0], p[1], 0.0]).collect();
        assert!(convex_hull(&flat).is_none());
    }

    #[test]
    fn hull_of_random_points_holds_them_all_and_is_made_of_them() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        // A chair-like cloud: a seat slab and a thin back, off the origin as in a room.
        let pts: Vec<[f64; 3]> = (0..3000)
            .map(|i| {
                let (x, y, z) = if i % 3 == 0 {
                    (
                        rng.gen_range(-0.22..0.22),
                        rng.gen_range(0.18..0.22),
                        rng.gen_range(0.45..0.9),
                    )
                } else {
                    (
                        rng.gen_range(-0.22..0.22),
                        rng.gen_range(-0.22..0.22),
                        rng.gen_range(0.4..0.45),
                    )
                };
                [x + 1.3, y - 0.8, z]
            })
            .collect();
        let (m, step) = convex_hull(&pts).expect("volume");
        assert_eq!(step, 0.01);
        let ps = planes(&m);
        for p in &pts {
            for (n, d) in &ps {
                assert!(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] <= d + 0.009);
            }
        }
        // Vertices are grid points, each within half a cell's diagonal of an input point.
        for v in &m.vertices {
            let near = pts
                .iter()
                .any(|p| (0..3).map(|a| (p[a] - v[a]).powi(2)).sum::<f64>().sqrt() <= step * 0.87);
            assert!(near, "{v:?} is no input point");
        }
        // Tighter than the bounding box: the back leaves the upper front empty.
        let (lo, hi) = m.bounds();
        let bbox = (0..3).map(|a| hi[a] - lo[a]).product::<f64>();
        assert!(
            m.volume() > 0.0 && m.volume() < 0.8 * bbox,
            "{} vs {bbox}",
            m.volume()
        );
    }

    #[test]
    fn hull_of_a_lamp_is_convex_despite_its_rings_of_points() {
        // A pole and a shade: thousands of points on coplanar circles, the degenerate case.
        let mut pts = vec![];
        for i in 0..4000 {
            let a = i as f64 * 0.618_033_988_75 * std::f64::consts::TAU;
            let (r, z) = match i % 4 {
                0 => (0.2, 1.2),
                1 => (0.12, 1.5),
                2 => (0.015, 1.2 * (i as f64 / 4000.0)),
                _ => (0.14, 0.02),
            };
            pts.push([r * a.cos() - 0.9, r * a.sin() + 1.1, z]);
        }
        let (m, step) = convex_hull(&pts).expect("volume");
        let half_diagonal = step * 3f64.sqrt() / 2.0;
        assert!(m.holds(&pts, half_diagonal + 1e-6));
        assert!(m.volume() > 0.0);
        let (lo, hi) = m.bounds();
        assert!(
            (lo[2] - 0.0).abs() <= step && (hi[2] - 1.5).abs() <= step,
            "{lo:?} {hi:?}"
        );
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
