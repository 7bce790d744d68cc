//! A navigation mesh of the walkable floor: the room minus every obstacle footprint inflated by
//! the agent's radius (and minus a band of that radius along the walls), rasterised
//! conservatively on a square grid (a cell is walkable only when no inflated footprint touches
//! any part of it, by a separating-axis test) and triangulated two triangles a cell with shared
//! vertices, so neighbouring cells share edges (a connected mesh path finders accept as it is).
//! Obstacles no taller than the agent's step (rugs) or starting above its head do not cut it.
//! World frame (z up, metres; the room centred on the origin).
use std::collections::{HashMap, VecDeque};

/// The agent the mesh is built for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Agent {
    /// Metres kept clear around the agent's centre.
    pub radius: f64,
    /// Metres: obstacles starting higher than this are walked under.
    pub height: f64,
    /// Metres: obstacles no taller than this are stepped over.
    pub climb: f64,
}

impl Default for Agent {
    fn default() -> Agent {
        Agent {
            radius: 0.25,
            height: 1.8,
            climb: 0.3,
        }
    }
}

/// An oriented box standing on or above the floor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Obstacle {
    /// Footprint centre (x, y).
    pub centre: [f64; 2],
    /// Half extents along the box's own x and y.
    pub half: [f64; 2],
    /// Degrees, counter-clockwise about +z.
    pub yaw: f64,
    /// Bottom and top heights.
    pub z: [f64; 2],
}

impl Obstacle {
    /// Whether it blocks an agent walking on the floor.
    pub fn blocks(&self, a: &Agent) -> bool {
        self.z[0] < a.height && self.z[1] > a.climb
    }

    /// The part of this object an agent walking on the floor runs into, or `None` when it blocks
    /// nothing. An object no taller than the agent blocks with its whole footprint (when it
    /// [`blocks`](Self::blocks) at all). One reaching above the agent's head blocks only with
    /// what lies between the agent's step and its head: a patio umbrella's pole, not its canopy;
    /// a tree's trunk and the low boughs of its crown. That part is measured on `parts`, the
    /// object's surface samples in its own frame (x, y after the yaw is undone, relative to
    /// [`centre`](Self::centre); z above the object's bottom), each with its radius: the
    /// footprint of the samples whose centre lies in that band, grown by their radii and kept
    /// within the object's own. With no samples the whole footprint blocks; with samples but none
    /// in the band (all above the head or below the step), nothing does.
    pub fn walked_into(&self, agent: &Agent, parts: &[([f64; 3], f64)]) -> Option<Obstacle> {
        if !self.blocks(agent) {
            return None;
        }
        if self.z[1] <= agent.height || parts.is_empty() {
            return Some(*self);
        }
        let band = agent.climb..agent.height;
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for (p, r) in parts {
            if band.contains(&(self.z[0] + p[2])) {
                for a in 0..2 {
                    lo[a] = lo[a].min((p[a] - r).max(-self.half[a]));
                    hi[a] = hi[a].max((p[a] + r).min(self.half[a]));
                }
            }
        }
        if lo[0] > hi[0] || lo[1] > hi[1] {
            return None;
        }
        let mid = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
        let (s, c) = self.yaw.to_radians().sin_cos();
        Some(Obstacle {
            centre: [
                self.centre[0] + c * mid[0] - s * mid[1],
                self.centre[1] + s * mid[0] + c * mid[1],
            ],
            half: [(hi[0] - lo[0]) / 2.0, (hi[1] - lo[1]) / 2.0],
            yaw: self.yaw,
            z: [self.z[0], agent.height.min(self.z[1])],
        })
    }

    /// Whether the point (x, y) lies inside the footprint grown by `margin`.
    pub fn contains(&self, p: [f64; 2], margin: f64) -> bool {
        let (s, c) = self.yaw.to_radians().sin_cos();
        let d = [p[0] - self.centre[0], p[1] - self.centre[1]];
        let u = c * d[0] + s * d[1];
        let v = -s * d[0] + c * d[1];
        u.abs() <= self.half[0] + margin && v.abs() <= self.half[1] + margin
    }

    /// Whether the axis-aligned square of centre `p` and half side `h` overlaps the footprint
    /// grown by `margin` on every side (separating axes: the square's two, the box's two).
    fn overlaps_square(&self, p: [f64; 2], h: f64, margin: f64) -> bool {
        let (s, c) = self.yaw.to_radians().sin_cos();
        let (hx, hy) = (self.half[0] + margin, self.half[1] + margin);
        let d = [self.centre[0] - p[0], self.centre[1] - p[1]];
        // Box axes u = (c, s), v = (-s, c).
        let box_on_x = hx * c.abs() + hy * s.abs();
        let box_on_y = hx * s.abs() + hy * c.abs();
        if d[0].abs() > h + box_on_x || d[1].abs() > h + box_on_y {
            return false;
        }
        let sq_on_u = h * (c.abs() + s.abs());
        let du = c * d[0] + s * d[1];
        let dv = -s * d[0] + c * d[1];
        du.abs() <= hx + sq_on_u && dv.abs() <= hy + sq_on_u
    }
}

/// The walkable grid and its triangulation.
#[derive(Debug, Clone, PartialEq)]
pub struct NavMesh {
    pub agent: Agent,
    /// Cell side, metres.
    pub cell: f64,
    /// Corner of cell (0, 0): (-W/2, -D/2).
    pub origin: [f64; 2],
    pub nx: usize,
    pub ny: usize,
    /// Row-major (y outer), `nx * ny`.
    pub walkable: Vec<bool>,
    /// Vertices, world frame (z = 0).
    pub vertices: Vec<[f64; 3]>,
    /// Counter-clockwise seen from above.
    pub triangles: Vec<[u32; 3]>,
}

impl NavMesh {
    /// Builds the mesh of a `room` (W, D) floor centred on the origin with `obstacles`.
    pub fn build(room: [f64; 2], obstacles: &[Obstacle], agent: Agent, cell: f64) -> NavMesh {
        let nx = (room[0] / cell).floor().max(0.0) as usize;
        let ny = (room[1] / cell).floor().max(0.0) as usize;
        let origin = [-(nx as f64) * cell / 2.0, -(ny as f64) * cell / 2.0];
        let blocking: Vec<&Obstacle> = obstacles.iter().filter(|o| o.blocks(&agent)).collect();
        let (wx, wy) = (room[0] / 2.0 - agent.radius, room[1] / 2.0 - agent.radius);
        let h = cell / 2.0;
        let mut walkable = vec![false; nx * ny];
        for j in 0..ny {
            for i in 0..nx {
                let p = [
                    origin[0] + (i as f64 + 0.5) * cell,
                    origin[1] + (j as f64 + 0.5) * cell,
                ];
                let inside = p[0].abs() + h <= wx && p[1].abs() + h <= wy;
                walkable[j * nx + i] = inside
                    && !blocking
                        .iter()
                        .any(|o| o.overlaps_square(p, h, agent.radius));
            }
        }
        let mut m = NavMesh {
            agent,
            cell,
            origin,
            nx,
            ny,
            walkable,
            vertices: vec![],
            triangles: vec![],
        };
        m.triangulate();
        m
    }

    fn triangulate(&mut self) {
        let mut index: HashMap<(usize, usize), u32> = HashMap::new();
        let (cell, origin) = (self.cell, self.origin);
        let mut vertex = |i: usize, j: usize, verts: &mut Vec<[f64; 3]>| -> u32 {
            *index.entry((i, j)).or_insert_with(|| {
                verts.push([
                    origin[0] + i as f64 * cell,
                    origin[1] + j as f64 * cell,
                    0.0,
                ]);
                (verts.len() - 1) as u32
            })
        };
        let mut verts = vec![];
        let mut tris = vec![];
        for j in 0..self.ny {
            for i in 0..self.nx {
                if !self.walkable[j * self.nx + i] {
                    continue;
                }
                let a = vertex(i, j, &mut verts);
                let b = vertex(i + 1, j, &mut verts);
                let c = vertex(i + 1, j + 1, &mut verts);
                let d = vertex(i, j + 1, &mut verts);
                tris.push([a, b, c]);
                tris.push([a, c, d]);
            }
        }
        self.vertices = verts;
        self.triangles = tris;
    }

    /// Walkable area, square metres.
    pub fn area(&self) -> f64 {
        self.walkable.iter().filter(|w| **w).count() as f64 * self.cell * self.cell
    }

    /// The cell holding point (x, y), if inside the grid.
    pub fn cell_of(&self, p: [f64; 2]) -> Option<(usize, usize)> {
        let i = ((p[0] - self.origin[0]) / self.cell).floor();
        let j = ((p[1] - self.origin[1]) / self.cell).floor();
        (i >= 0.0 && j >= 0.0 && (i as usize) < self.nx && (j as usize) < self.ny)
            .then_some((i as usize, j as usize))
    }

    fn centre(&self, k: usize) -> [f64; 2] {
        [
            self.origin[0] + ((k % self.nx) as f64 + 0.5) * self.cell,
            self.origin[1] + ((k / self.nx) as f64 + 0.5) * self.cell,
        ]
    }

    fn neighbours(&self, k: usize) -> impl Iterator<Item = usize> + '_ {
        let (i, j) = ((k % self.nx) as isize, (k / self.nx) as isize);
        [(1, 0), (-1, 0), (0, 1), (0, -1)]
            .into_iter()
            .map(move |(di, dj)| (i + di, j + dj))
            .filter(|&(a, b)| a >= 0 && b >= 0 && (a as usize) < self.nx && (b as usize) < self.ny)
            .map(|(a, b)| b as usize * self.nx + a as usize)
    }

    /// Cells reachable from cell `k` over walkable cells (4-neighbours): hops, or `None`.
    pub fn hops_from(&self, k: usize) -> Vec<Option<u32>> {
        let mut d = vec![None; self.walkable.len()];
        if !self.walkable.get(k).copied().unwrap_or(false) {
            return d;
        }
        d[k] = Some(0);
        let mut q = VecDeque::from([k]);
        while let Some(c) = q.pop_front() {
            let next = d[c].map_or(0, |v| v + 1);
            for n in self.neighbours(c).collect::<Vec<_>>() {
                if self.walkable[n] && d[n].is_none() {
                    d[n] = Some(next);
                    q.push_back(n);
                }
            }
        }
        d
    }

    /// Clearance of every cell: hops to the nearest non-walkable cell or the grid's edge.
    fn clearance(&self) -> Vec<u32> {
        let mut d = vec![u32::MAX; self.walkable.len()];
        let mut q = VecDeque::new();
        for (k, (dk, &walk)) in d.iter_mut().zip(&self.walkable).enumerate() {
            let (i, j) = (k % self.nx, k / self.nx);
            let edge = i == 0 || j == 0 || i + 1 == self.nx || j + 1 == self.ny;
            if !walk || edge {
                *dk = u32::from(walk);
                q.push_back(k);
            }
        }
        while let Some(c) = q.pop_front() {
            for n in self.neighbours(c).collect::<Vec<_>>() {
                if d[n] == u32::MAX {
                    d[n] = d[c] + 1;
                    q.push_back(n);
                }
            }
        }
        d
    }

    /// The cells of the largest 4-connected walkable region (the first found on ties).
    pub fn largest_region(&self) -> Vec<bool> {
        let mut seen = vec![false; self.walkable.len()];
        let mut best = vec![false; self.walkable.len()];
        let mut best_len = 0;
        for k in 0..self.walkable.len() {
            if !self.walkable[k] || seen[k] {
                continue;
            }
            let hops = self.hops_from(k);
            let region: Vec<usize> = (0..hops.len()).filter(|&c| hops[c].is_some()).collect();
            for &c in &region {
                seen[c] = true;
            }
            if region.len() > best_len {
                best_len = region.len();
                best = vec![false; self.walkable.len()];
                for &c in &region {
                    best[c] = true;
                }
            }
        }
        best
    }

    /// Up to `n` spawn points (world frame, on the floor) with what each is near, all on the
    /// largest walkable region: the cell of that region nearest each door's inside point first, then the most open cells (largest clearance,
    /// nearest the room's centre on ties) reachable from the first, at least a metre apart.
    pub fn spawn_points(&self, doors: &[[f64; 2]], n: usize) -> Vec<([f64; 3], &'static str)> {
        let cells: Vec<usize> = (0..self.walkable.len())
            .filter(|&k| self.walkable[k])
            .collect();
        if cells.is_empty() || n == 0 {
            return vec![];
        }
        let dist2 = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2);
        let clear = self.clearance();
        // Spawns stand on the largest walkable region: a pocket cut off by furniture beside the
        // door (behind a counter, between a bed and a wall) reaches nothing.
        let main = self.largest_region();
        let cells: Vec<usize> = cells.into_iter().filter(|&k| main[k]).collect();
        let mut picked: Vec<(usize, &'static str)> = vec![];
        for d in doors {
            let best = cells
                .iter()
                .copied()
                .min_by(|&a, &b| dist2(self.centre(a), *d).total_cmp(&dist2(self.centre(b), *d)));
            if let Some(b) = best {
                if !picked.iter().any(|p| p.0 == b) && picked.len() < n {
                    picked.push((b, "door"));
                }
            }
        }
        let mut open = cells.clone();
        open.sort_by(|&a, &b| {
            clear[b]
                .cmp(&clear[a])
                .then(dist2(self.centre(a), [0.0; 2]).total_cmp(&dist2(self.centre(b), [0.0; 2])))
        });
        let reach = picked.first().map(|p| self.hops_from(p.0));
        for k in open {
            if picked.len() >= n {
                break;
            }
            let reachable = reach.as_ref().is_none_or(|r| r[k].is_some());
            let apart = picked
                .iter()
                .all(|p| dist2(self.centre(p.0), self.centre(k)) >= 1.0);
            if reachable && apart {
                picked.push((k, "open floor"));
            }
        }
        picked
            .into_iter()
            .map(|(k, why)| {
                let c = self.centre(k);
                ([c[0], c[1], 0.0], why)
            })
            .collect()
    }

    /// Wavefront OBJ of the mesh in glTF's y-up frame (`(x, y, z)` world is `(x, z, -y)`), as
    /// Recast and most engines take it.
    pub fn to_obj(&self) -> String {
        let mut s = format!(
            "# dreamscene navmesh: y up, metres; agent radius {} m, height {} m, climb {} m, cell {} m\n",
            self.agent.radius, self.agent.height, self.agent.climb, self.cell
        );
        for v in &self.vertices {
            s += &format!("v {:.4} {:.4} {:.4}\n", v[0], v[2], -v[1]);
        }
        for t in &self.triangles {
            s += &format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
        }
        s
    }
}

#[cfg(test)]
mod tests;
