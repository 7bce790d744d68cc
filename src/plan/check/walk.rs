//! Walkable paths: an occupancy grid of the floor (10 cm cells) where a person, a disc of
//! [`AGENT_RADIUS`], may stand: inside the walls and clear of every footprint that rises above
//! [`STEP_HEIGHT`] from the floor (rugs and mats are walked on; things hung higher than
//! [`HEAD_HEIGHT`] are walked under). Breadth-first from each door's clear zone. A thing is
//! reached where it is used: a thing against a wall (a sofa, a wardrobe, a counter, a desk)
//! at its front, one longer than it is wide there (a bed) at its front or a long side, a thing
//! in the room (a chair, a table) at any side.
use super::{door_zone, Box2};
use crate::plan::gcp::classes::{Class, Placements};
use crate::plan::spec::{Layout, OpeningKind, PlacedObject, SceneType};
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

/// The sides of a thing a person uses it from.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Use {
    /// Any side (a chair, a table in the room).
    Any,
    /// Its front (a sofa, a wardrobe, a counter against a wall).
    Front,
    /// Its front or either long side (a bed).
    FrontOrSides,
}

/// How `o` is used: a thing of the against_wall class or with a front clearance, standing
/// against a wall of `room`, from its front (a bed also from its long sides); else any side
/// (a desk in a row, a sofa floated in the room).
fn use_of(o: &PlacedObject, room: [f64; 3]) -> Use {
    let table = Placements::builtin();
    let at_wall = super::wall_distances(&Box2::of(o), room)
        .iter()
        .any(|&d| d <= super::side_distance(SceneType::Indoor, room));
    if !at_wall {
        return Use::Any;
    }
    let against = table.class(&o.category) == Class::AgainstWall;
    if against && o.size[1] > 1.2 * o.size[0] {
        Use::FrontOrSides
    } else if against || table.front_clearance(&o.category).is_some() {
        Use::Front
    } else {
        Use::Any
    }
}

/// Whether a standing spot `p` is before a side of `b` that `u` uses it from (a person at a
/// front corner reaches the front: a sofa past the end of its coffee table).
fn on_used_side(b: &Box2, u: Use, p: [f64; 2]) -> bool {
    let l = b.local(p);
    let front = l[1] > b.half[1] && l[0].abs() <= b.half[0] + AGENT_RADIUS;
    let side = l[0].abs() > b.half[0] && l[1].abs() <= b.half[1];
    match u {
        Use::Any => true,
        Use::Front => front,
        Use::FrontOrSides => front || side,
    }
}

/// Ids of the floor objects of an indoor layout that a person coming in by a door cannot
/// reach where they are used: no standing spot within [`AGENT_RADIUS`] + one cell diagonal of
/// the footprint, before a side it is used from, is connected to a door's clear zone. Empty for
/// outdoor layouts and rooms without doors.
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
            let u = use_of(o, l.room.size);
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
            !(j0..=j1).any(|j| {
                (i0..=i1).any(|i| {
                    let p = centre(i, j);
                    seen[j * nx + i] && dist(&b, p) <= reach && on_used_side(&b, u, p)
                })
            })
        })
        .map(|o| o.id.clone())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::spec::{Anchor, Opening, PlacedBy, Room, Wall};

    fn thing(id: &str, category: &str, size: [f64; 3], at: [f64; 2], yaw: f64) -> PlacedObject {
        PlacedObject {
            id: id.into(),
            category: category.into(),
            size,
            position: [at[0], at[1], 0.0],
            yaw,
            anchor: Anchor::Others,
            placed_by: PlacedBy::Constraint,
        }
    }

    fn room(objects: Vec<PlacedObject>) -> Layout {
        Layout {
            scene_type: SceneType::Indoor,
            room: Room {
                size: [4.0, 4.0, 2.8],
            },
            seed: 0,
            objects,
            unsatisfied: vec![],
            unsatisfied_anchors: vec![],
            openings: vec![Opening {
                kind: OpeningKind::Door,
                wall: Wall::South,
                position: [0.0, -2.0, 0.0],
                width: 0.9,
                height: 2.1,
            }],
        }
    }

    #[test]
    fn a_walled_in_chair_and_a_blocked_wardrobe_front_are_out_of_reach() {
        // a wardrobe on the north wall, facing south, reached at its front
        let wardrobe = thing("wardrobe1", "wardrobe", [1.5, 0.6, 2.0], [0.0, 1.68], 180.0);
        assert!(
            unreachable(&room(vec![wardrobe.clone()])).is_empty(),
            "free"
        );
        // a bookcase pushed against its doors leaves its ends free but its front shut
        let shelf = thing(
            "bookshelf1",
            "bookshelf",
            [1.6, 0.35, 1.9],
            [0.0, 1.18],
            180.0,
        );
        assert_eq!(unreachable(&room(vec![wardrobe, shelf])), ["wardrobe1"]);
        // a chair in the north-west corner fenced by two bookcases
        let chair = thing(
            "armchair1",
            "armchair",
            [0.8, 0.8, 0.9],
            [-1.55, 1.55],
            180.0,
        );
        let east = thing(
            "bookshelf1",
            "bookshelf",
            [1.8, 0.35, 1.9],
            [-0.9, 1.1],
            90.0,
        );
        let south = thing(
            "bookshelf2",
            "bookshelf",
            [1.4, 0.35, 1.9],
            [-1.3, 0.9],
            0.0,
        );
        let lost = unreachable(&room(vec![chair.clone(), east, south]));
        assert!(lost.contains(&"armchair1".to_string()), "{lost:?}");
        assert!(unreachable(&room(vec![chair])).is_empty(), "free chair");
        // a bed reached from a long side although its foot is blocked
        let bed = thing("bed1", "bed", [1.6, 2.1, 1.0], [0.0, 0.93], 180.0);
        let chest = thing("dresser1", "dresser", [1.6, 0.5, 0.9], [0.0, -0.4], 180.0);
        assert!(unreachable(&room(vec![bed, chest])).is_empty(), "bed");
    }
}
