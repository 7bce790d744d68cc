//! Doors and windows of an indoor room (ARCHITECTURE.md "Openings"): one door, 0.9 m wide,
//! near a corner of a seeded wall; a window centred on the wall opposite it and, at random, on
//! one side wall (two on a wall of 6 m or more), 0.9 m sill. A room whose sentence says it has
//! no windows gets none; one whose sentence counts its windows ("three big windows") gets that
//! many, the wall opposite the door first.
use crate::plan::spec::{Opening, OpeningKind, Wall};
use rand::Rng;

/// Door width and height (m).
pub const DOOR: [f64; 2] = [0.9, 2.1];
/// Window sill height (m).
pub const SILL: f64 = 0.9;

/// Whether `text` asks for a room without windows.
pub fn says_no_windows(text: &str) -> bool {
    let t = text.to_lowercase();
    [
        "no window",
        "windowless",
        "without windows",
        "without a window",
    ]
    .iter()
    .any(|p| t.contains(p))
}

/// How many windows `text` asks for: 0 when it asks for none ("a windowless room"), n when
/// it counts them ("three big windows", "4 windows": a number at most three words before
/// "windows"), `None` when it does not say.
pub fn asked_windows(text: &str) -> Option<u32> {
    if says_no_windows(text) {
        return Some(0);
    }
    const NUMBERS: [&str; 12] = [
        "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven",
        "twelve",
    ];
    let t = text.to_lowercase();
    let words: Vec<&str> = t
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    let number = |w: &str| {
        NUMBERS
            .iter()
            .position(|n| *n == w)
            .map(|k| k as u32 + 1)
            .or_else(|| w.parse::<u32>().ok().filter(|n| (1..=12).contains(n)))
    };
    let counted = words.iter().enumerate().find_map(|(k, w)| {
        if *w != "windows" {
            return None;
        }
        // the number and the adjectives between it and "windows" ("three big windows"), no
        // other phrase ("six chairs by the windows")
        const LINKS: [&str; 16] = [
            "the", "a", "an", "by", "near", "under", "beneath", "below", "at", "in", "of", "and",
            "with", "to", "beside", "facing",
        ];
        for back in 1..=3.min(k) {
            let w = words[k - back];
            if let Some(n) = number(w) {
                return Some(n);
            }
            if LINKS.contains(&w) {
                return None;
            }
        }
        None
    });
    counted.or_else(|| windowless_place(&t).then_some(0))
}

/// Length of `wall` in a room of size `room`.
fn length(wall: Wall, room: [f64; 3]) -> f64 {
    match wall {
        Wall::North | Wall::South => room[0],
        Wall::East | Wall::West => room[1],
    }
}

/// The point on `wall`'s inner face at `t` metres along it from its middle, at height `z`.
fn on_wall(wall: Wall, room: [f64; 3], t: f64, z: f64) -> [f64; 3] {
    let (hw, hd) = (0.5 * room[0], 0.5 * room[1]);
    match wall {
        Wall::North => [t, hd, z],
        Wall::South => [t, -hd, z],
        Wall::East => [hw, t, z],
        Wall::West => [-hw, t, z],
    }
}

fn opposite(w: Wall) -> Wall {
    match w {
        Wall::North => Wall::South,
        Wall::South => Wall::North,
        Wall::East => Wall::West,
        Wall::West => Wall::East,
    }
}

/// Whether the place `t` (lower case) opens with is of a kind without windows (`windowless` in
/// `kb/scenes.txt`: a cave, a cellar): its name or a synonym, whole words, among the words
/// naming the place (before "with", "where", a comma).
fn windowless_place(t: &str) -> bool {
    let head = t.split([',', ';', ':', '.']).next().unwrap_or("");
    let w: Vec<&str> = head
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    let end = w
        .iter()
        .position(|x| ["with", "where", "which", "that"].contains(x))
        .unwrap_or(w.len());
    let w = &w[..end];
    crate::plan::kb::KnowledgeBase::builtin()
        .scenes
        .iter()
        .filter(|s| !s.windows)
        .flat_map(|s| std::iter::once(&s.name).chain(&s.synonyms))
        .any(|name| {
            let n: Vec<&str> = name
                .split(|c: char| !c.is_alphanumeric())
                .filter(|w| !w.is_empty())
                .collect();
            !n.is_empty() && w.windows(n.len()).any(|x| x == &n[..])
        })
}

/// Seeded openings of a room of size `room`, with `windows` windows when the sentence counts
/// them (see [`asked_windows`]; `None`: as many as the walls take).
pub fn generate(room: [f64; 3], windows: Option<u32>, rng: &mut impl Rng) -> Vec<Opening> {
    const WALLS: [Wall; 4] = [Wall::South, Wall::North, Wall::East, Wall::West];
    let mut out = vec![];
    let door_wall = WALLS[rng.gen_range(0..4)];
    let len = length(door_wall, room);
    let w = DOOR[0].min(0.6 * len);
    let h = DOOR[1].min(room[2] - 0.1);
    let reach = (0.5 * len - 0.5 * w - 0.15).max(0.0);
    let t = [-reach, reach, -0.5 * reach, 0.5 * reach][rng.gen_range(0..4)];
    out.push(Opening {
        kind: OpeningKind::Door,
        wall: door_wall,
        position: on_wall(door_wall, room, t, 0.0),
        width: w,
        height: h,
    });
    match windows {
        Some(0) => return out,
        Some(n) => {
            counted_windows(room, door_wall, n, rng, &mut out);
            return out;
        }
        None => {}
    }
    let mut walls = vec![opposite(door_wall)];
    let sides: Vec<Wall> = WALLS
        .iter()
        .copied()
        .filter(|&x| x != door_wall && x != opposite(door_wall))
        .collect();
    if rng.gen_bool(0.5) {
        walls.push(sides[rng.gen_range(0..sides.len())]);
    }
    let height = (room[2] - SILL - 0.3).clamp(0.6, 1.3);
    for wall in walls {
        let len = length(wall, room);
        if len < 2.0 {
            continue;
        }
        let n = if len >= 6.0 { 2 } else { 1 };
        let width = (0.3 * len / n as f64).clamp(0.6, 1.4);
        for k in 0..n {
            let t = len * (k as f64 + 0.5) / n as f64 - 0.5 * len;
            out.push(Opening {
                kind: OpeningKind::Window,
                wall,
                position: on_wall(wall, room, t, SILL),
                width,
                height,
            });
        }
    }
    out
}

/// `n` windows on the walls without the door, the one opposite it first, spread as evenly as
/// the walls take them (each window at most 1.4 m wide, 0.3 m of wall at least between them).
fn counted_windows(
    room: [f64; 3],
    door_wall: Wall,
    n: u32,
    rng: &mut impl Rng,
    out: &mut Vec<Opening>,
) {
    let mut sides: Vec<Wall> = [Wall::South, Wall::North, Wall::East, Wall::West]
        .into_iter()
        .filter(|&x| x != door_wall && x != opposite(door_wall))
        .collect();
    if rng.gen_bool(0.5) {
        sides.reverse();
    }
    let walls: Vec<Wall> = std::iter::once(opposite(door_wall))
        .chain(sides)
        .filter(|&w| length(w, room) >= 1.5)
        .collect();
    if walls.is_empty() {
        return;
    }
    let mut per = vec![0u32; walls.len()];
    for k in 0..n {
        per[k as usize % walls.len()] += 1;
    }
    let height = (room[2] - SILL - 0.3).clamp(0.6, 1.3);
    for (wall, m) in walls.into_iter().zip(per) {
        if m == 0 {
            continue;
        }
        let len = length(wall, room);
        let width = ((len - 0.3 * (m as f64 + 1.0)) / m as f64).clamp(0.4, 1.4);
        for k in 0..m {
            let t = len * (k as f64 + 0.5) / m as f64 - 0.5 * len;
            out.push(Opening {
                kind: OpeningKind::Window,
                wall,
                position: on_wall(wall, room, t, SILL),
                width,
                height,
            });
        }
    }
}

impl super::Problem {
    /// Candidate poses of instance `i` that its opening anchor asks for: along a window's wall
    /// in front of it (WINDOW), facing it from 0.3–1.5 m (FACE_WINDOW), beside a door's clear
    /// zone (DOOR), facing it from beyond its clear zone (FACE_DOOR; a desk whose seat faces the
    /// door stands there with its back to it, between the seat and the door). Empty for the
    /// other anchors.
    pub(super) fn opening_candidates(&self, i: usize) -> Vec<super::Pose> {
        use crate::plan::spec::Anchor;
        let anchor = if self.seat_faces_door(i) {
            Anchor::FaceDoor
        } else {
            self.inst[i].anchor
        };
        let kind = match anchor {
            Anchor::Window | Anchor::FaceWindow => OpeningKind::Window,
            Anchor::Door | Anchor::FaceDoor => OpeningKind::Door,
            _ => return vec![],
        };
        let s = self.inst[i].size;
        let z = self.hung[i].unwrap_or(0.0);
        // (a thing that stands with its back to a wall, a window seat or a sideboard, stands
        // under a window with its back to the window's wall, as one with a seat at it does)
        let seated = self.seated_at(i) || self.faced[i];
        let mut out = vec![];
        for o in self.openings.iter().filter(|o| o.kind == kind) {
            let n = o.wall.inward();
            let a = o.wall.along();
            let into = super::yaw_facing(n);
            let toward = into + 180.0;
            let base = [o.position[0], o.position[1]];
            let at = |along: f64, out_: f64| {
                [
                    base[0] + a[0] * along + n[0] * out_,
                    base[1] + a[1] * along + n[1] * out_,
                ]
            };
            match anchor {
                Anchor::Window => {
                    // a desk or table with a seat at it is used from its front: its back to
                    // the window, so the seat faces the window across it
                    let turns: &[(f64, f64)] = if seated {
                        &[(into, s[1])]
                    } else {
                        &[
                            (into, s[1]),
                            (toward, s[1]),
                            (into + 90.0, s[0]),
                            (into - 90.0, s[0]),
                        ]
                    };
                    for along in [0.0, -0.5 * o.width, 0.5 * o.width, -o.width, o.width] {
                        for &(yaw, depth) in turns {
                            // against the wall, a little off it, or just clear of the
                            // window's zone (a plant taller than the sill beneath it)
                            let clear = crate::plan::check::window_zone(o).half[1] * 2.0 + 0.02;
                            for gap in [0.02, 0.3, clear] {
                                out.push(super::Pose {
                                    c: at(along, gap + 0.5 * depth),
                                    yaw,
                                    z,
                                });
                            }
                        }
                    }
                }
                Anchor::FaceWindow => {
                    for along in [0.0, -0.3 * o.width, 0.3 * o.width] {
                        for gap in [0.3, 0.6, 1.0, 1.5] {
                            out.push(super::Pose {
                                c: at(along, gap + 0.5 * s[1]),
                                yaw: toward,
                                z,
                            });
                        }
                    }
                }
                Anchor::FaceDoor => {
                    // beyond the clear zone; a seated desk turned away, its seat behind it
                    let yaw = if seated { into } else { toward };
                    let clear = crate::plan::check::DOOR_CLEAR_DEPTH + 0.2;
                    for along in [0.0, -0.3 * o.width, 0.3 * o.width] {
                        for gap in [clear, clear + 0.5, clear + 1.0, clear + 1.5] {
                            out.push(super::Pose {
                                c: at(along, gap + 0.5 * s[1]),
                                yaw,
                                z,
                            });
                        }
                    }
                }
                _ => {
                    let side = 0.5 * o.width + 0.1 + 0.5 * s[0].max(s[1]);
                    for along in [-side, side, -side - 0.3, side + 0.3] {
                        for (yaw, depth) in [(into, s[1]), (into + 90.0, s[0]), (into - 90.0, s[0])]
                        {
                            out.push(super::Pose {
                                c: at(along, 0.02 + 0.5 * depth),
                                yaw,
                                z,
                            });
                        }
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn counted_windows_are_read_and_made() {
        assert_eq!(
            asked_windows("a sunroom with three big windows"),
            Some(3),
            "three big"
        );
        assert_eq!(
            asked_windows("a studio with 2 tall windows"),
            Some(2),
            "digits"
        );
        assert_eq!(asked_windows("a windowless cellar"), Some(0), "none");
        assert_eq!(
            asked_windows("a bedroom with a bed by the window"),
            None,
            "not counted"
        );
        assert_eq!(
            asked_windows("six chairs by the windows"),
            None,
            "chairs counted"
        );
        for seed in 0..8 {
            let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
            for n in [1, 3, 5] {
                let o = generate([4.3, 3.5, 2.8], Some(n), &mut rng);
                let wins: Vec<&Opening> =
                    o.iter().filter(|o| o.kind == OpeningKind::Window).collect();
                assert_eq!(wins.len(), n as usize, "windows made");
                let door = o
                    .iter()
                    .find(|o| o.kind == OpeningKind::Door)
                    .expect("door");
                assert!(
                    wins.iter().all(|w| w.wall != door.wall),
                    "a window on the door wall"
                );
                // no two windows of a wall overlap
                for a in &wins {
                    for b in &wins {
                        if !std::ptr::eq(*a, *b) && a.wall == b.wall {
                            let d = (a.position[0] - b.position[0]).abs()
                                + (a.position[1] - b.position[1]).abs();
                            assert!(d >= 0.5 * (a.width + b.width), "{a:?} {b:?}");
                        }
                    }
                }
            }
        }
    }
}
