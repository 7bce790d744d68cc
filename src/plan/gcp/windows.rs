//! Windows made for the things asked at one: a thing anchored WINDOW ("a desk under the
//! window") that the search could not stand at any window of the room, but that stands with a
//! wall at its back or side, gets a window in that wall before it, where the wall has room for
//! one (clear of the door and the other windows) and nothing placed covers it.
use super::openings::SILL;
use super::Problem;
use crate::plan::check::{at_window, penetration, wall_distances, window_zone, Box2};
use crate::plan::spec::{Anchor, Opening, OpeningKind, PlacedObject, Wall};

/// How near a wall (m) a thing stands for a window in that wall to be before it.
const NEAR_WALL: f64 = 0.3;
/// Wall kept between a made window and another opening of its wall (m).
const BETWEEN: f64 = 0.3;
/// The narrowest and widest window made (m), as `openings::generate` makes them.
const WIDTH: (f64, f64) = (0.6, 1.4);

impl Problem {
    /// The windows to add for the WINDOW things of `objects` that stand at none.
    pub(super) fn windows_for(&self, objects: &[PlacedObject]) -> Vec<Opening> {
        let mut made: Vec<Opening> = vec![];
        let boxes: Vec<Box2> = objects.iter().map(Box2::of).collect();
        for (o, b) in objects.iter().zip(&boxes) {
            if o.anchor != Anchor::Window {
                continue;
            }
            let all = || self.openings.iter().chain(&made);
            if all().any(|w| w.kind == OpeningKind::Window && at_window(b, w)) {
                continue;
            }
            let wd = wall_distances(b, self.room);
            let mut walls: Vec<usize> = (0..4).filter(|&k| wd[k] <= NEAR_WALL).collect();
            walls.sort_by(|&a, &c| wd[a].total_cmp(&wd[c]));
            let window = walls.into_iter().find_map(|k| {
                let w = self.window_at(k, b)?;
                let (lo, hi) = span(&w);
                let apart = all().filter(|x| x.wall == w.wall).all(|x| {
                    let (a, e) = span(x);
                    hi + BETWEEN <= a || e + BETWEEN <= lo
                });
                let zone = window_zone(&w);
                let uncovered = boxes.iter().all(|x| penetration(x, &zone) <= 0.0);
                (apart && uncovered).then_some(w)
            });
            made.extend(window);
        }
        made
    }

    /// A window in wall `k` ([-x, +x, -y, +y]) centred before footprint `b`, as wide as the
    /// footprint along the wall (within [`WIDTH`]); `None` when the wall is too short.
    fn window_at(&self, k: usize, b: &Box2) -> Option<Opening> {
        let [w, d, h] = self.room;
        let (wall, len) = match k {
            0 => (Wall::West, d),
            1 => (Wall::East, d),
            2 => (Wall::South, w),
            _ => (Wall::North, w),
        };
        let [x0, y0, x1, y1] = b.aabb();
        let (lo, hi) = if k < 2 { (y0, y1) } else { (x0, x1) };
        let width = (hi - lo).clamp(WIDTH.0, WIDTH.1);
        let reach = 0.5 * len - 0.5 * width - 0.15;
        if reach < 0.0 {
            return None;
        }
        let t = (0.5 * (lo + hi)).clamp(-reach, reach);
        let height = (h - SILL - 0.3).clamp(0.6, 1.3);
        let position = match wall {
            Wall::West => [-0.5 * w, t, SILL],
            Wall::East => [0.5 * w, t, SILL],
            Wall::South => [t, -0.5 * d, SILL],
            Wall::North => [t, 0.5 * d, SILL],
        };
        Some(Opening {
            kind: OpeningKind::Window,
            wall,
            position,
            width,
            height,
        })
    }
}

/// An opening's span along its wall (its two ends' coordinates along the wall's axis).
fn span(o: &Opening) -> (f64, f64) {
    let ((a0, a1), (e0, e1)) = {
        let (a, e) = o.span();
        ((a[0], a[1]), (e[0], e[1]))
    };
    let (a, e) = match o.wall {
        Wall::North | Wall::South => (a0, e0),
        Wall::East | Wall::West => (a1, e1),
    };
    (a.min(e), a.max(e))
}
