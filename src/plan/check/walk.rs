//! Walkable paths: an occupancy grid of the floor (10 cm cells) where a person, a disc of
//! [`AGENT_RADIUS`], may stand: inside the walls and clear of every footprint that rises above
//! [`STEP_HEIGHT`] from the floor (rugs and mats are walked on; things hung higher than
//! [`HEAD_HEIGHT`] are walked under). Breadth-first from each door's clear zone.
use super::{door_zone, Box2};
use crate::plan::spec::{Layout, OpeningKind};
use std::collections::VecDeque;

/// The walker's radius (m).
pub const AGENT_RADIUS: f64 = 0.3;
/// Things lower than this are walked over (m).
pub const STEP_HEIGHT: f64 = 0.05;
/// Things whose bottom is higher than this are walked under (m).
pub const HEAD_HEIGHT: f64 = 1.9;
const CELL: f64 = 0.1;

/// Distance from `p` to `b`'s footprint (0 inside).
fn dist(b: &Box2, p: [f64; 2]) -> f64 {
    let l = b.local(p);
    let dx = (l[0].abs() - b.half[0]).max(0.0);
    let dy = (l[1].abs() - b.half[1]).max(0.0);
    (dx * dx + dy * dy).sqrt()
}

/// Ids of the floor objects of an indoor layout that a person coming in by a door cannot
/// reach: no standing spot within [`AGENT_RADIUS`] + one cell diagonal of the footprint is
/// connected to a door's clear zone. Empty for outdoor layouts and rooms without doors.
pub fn unreachable(l: &Layout) -> Vec<String> {
    let doors: Vec<_> = l
        .openings
        .iter()
        .filter(|o| o.kind == OpeningKind::Door)
        .collect();
    if doors.is_empty() {
        return vec![];
    }
    let [w, d, _] = l.room.size;
    let (nx, ny) = ((w / CELL).floor() as usize, (d / CELL).floor() as usize);
    let centre = |i: usize, j: usize| {
        [
            -0.5 * w + (i as f64 + 0.5) * CELL,
            -0.5 * d + (j as f64 + 0.5) * CELL,
        ]
    };
    let obstacles: Vec<Box2> = l
        .objects
        .iter()
        .map(Box2::of)
        .filter(|b| b.z1 > STEP_HEIGHT && b.z0 < HEAD_HEIGHT)
        .collect();
    let free = |p: [f64; 2]| {
        p[0].abs() <= 0.5 * w - AGENT_RADIUS
            && p[1].abs() <= 0.5 * d - AGENT_RADIUS
            && obstacles.iter().all(|b| dist(b, p) > AGENT_RADIUS)
    };
    let mut open = vec![false; nx * ny];
    for j in 0..ny {
        for i in 0..nx {
            open[j * nx + i] = free(centre(i, j));
        }
    }
    let mut seen = vec![false; nx * ny];
    let mut q = VecDeque::new();
    for door in doors {
        let zone = door_zone(door);
        for j in 0..ny {
            for i in 0..nx {
                if open[j * nx + i] && zone.contains(centre(i, j)) && !seen[j * nx + i] {
                    seen[j * nx + i] = true;
                    q.push_back((i, j));
                }
            }
        }
    }
    while let Some((i, j)) = q.pop_front() {
        for (di, dj) in [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)] {
            let (a, b) = (i as i64 + di, j as i64 + dj);
            if a < 0 || b < 0 || a >= nx as i64 || b >= ny as i64 {
                continue;
            }
            let k = b as usize * nx + a as usize;
            if open[k] && !seen[k] {
                seen[k] = true;
                q.push_back((a as usize, b as usize));
            }
        }
    }
    let reach = AGENT_RADIUS + CELL * std::f64::consts::SQRT_2;
    l.objects
        .iter()
        .filter(|o| o.position[2] < STEP_HEIGHT && o.size[2] > STEP_HEIGHT)
        .filter(|o| {
            let b = Box2::of(o);
            let [x0, y0, x1, y1] = b.aabb();
            let cell = |v: f64, lo: f64, n: usize| {
                (((v - lo) / CELL).floor().max(0.0) as usize).min(n.saturating_sub(1))
            };
            let (i0, i1) = (
                cell(x0 - reach, -0.5 * w, nx),
                cell(x1 + reach, -0.5 * w, nx),
            );
            let (j0, j1) = (
                cell(y0 - reach, -0.5 * d, ny),
                cell(y1 + reach, -0.5 * d, ny),
            );
            !(j0..=j1)
                .any(|j| (i0..=i1).any(|i| seen[j * nx + i] && dist(&b, centre(i, j)) <= reach))
        })
        .map(|o| o.id.clone())
        .collect()
}
