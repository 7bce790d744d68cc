//! Things asked in rows ("four rows of six desks", "twelve desks in three rows", "a row of five
//! treadmills"): one block of aligned rows, every instance turned the same way, toward the front
//! of the room. What the rows face (their OPPOSITE or ROW partner, else the first category of
//! kb/fronts.txt the scene holds: a stage, altar, screen, board) stands at the front wall
//! (a passage before it when something more telling is there: a lectern before the board),
//! centred before them, with the fronts.txt things more telling than it that the scene holds
//! (a stage below the screen); the front band is deep enough that the ends of the first row
//! see them within 38° of straight ahead. Row 0 is nearest the front; a row holds `ceil(n / rows)` instances or
//! one fewer (every row is used), side by side; rows of four or more, or of long things (pews,
//! benches), are split by a centre aisle. The block keeps a free band at the front for what the
//! rows face, a walkway behind, and every door's clear zone; rows asked by or facing a window
//! face a wall with one.
use super::spacing::{PASSAGE, ROW_WALK, SEAT_GAP};
use super::{yaw_facing, Pose, Problem};
use crate::plan::check::{penetration, Box2};
use crate::plan::spec::{Anchor, OpeningKind, RelationKind, SceneSpec, Wall};

/// Free depth kept in front of the first row (for the board, screen or stage and its view).
const FRONT: f64 = 1.8;
/// The least front depth a tight room may keep.
const FRONT_MIN: f64 = 1.0;
/// The front depth of a row asked by a window with nothing at its front (a row of flower
/// buckets by the window): close to the wall, well inside the window anchor's reach
/// (`check::WINDOW_DISTANCE`, 1 m), rather than the board's band a front keeps.
const BY_WINDOW: f64 = 0.3;
/// Things at least this long (m) stand in rows of two, split by the aisle, when the rows are
/// not asked (pews, benches).
const LONG: f64 = 1.5;
/// The centre aisle of rows of four or more.
const AISLE: f64 = 1.0;
/// The widest angle (degrees) off straight ahead at which a seat at the end of the first
/// row sees the nearest point of what stands at the front (the fidelity corpus judges
/// "facing" within 40 degrees).
const SIGHT: f64 = 38.0;

/// The shape of one category's block: instances, rows, columns, pitch across and along.
struct Block {
    n: usize,
    rows: usize,
    cols: usize,
    size: [f64; 2],
    gap_x: f64,
    gap_y: f64,
    aisle: f64,
    /// Depth of the seats at the back of the last row (AT_BACK: a pupil's chair), 0 when none.
    seat_back: f64,
    /// Free depth in front of the first row: [`FRONT`], or what the rows face and its view,
    /// and deep enough that the ends of a wide row still see the front (0.55 x its width).
    front: f64,
    /// The width of what the rows face (0 when nothing).
    target_width: f64,
    /// What stands at the front, centred before the rows, the most telling first: the
    /// target and the fronts.txt categories before it that the scene holds (a stage, then
    /// the screen above it), each with how far before the front wall it stands: 0; for a floor
    /// target that is not the most telling (a lectern before a board) a passage before the
    /// others and before what stands BEFORE them; more by the depth of what stands BEHIND it.
    at_front: Vec<(String, f64)>,
}

/// kb/fronts.txt: what rows face, most telling first.
pub(crate) fn fronts() -> impl Iterator<Item = &'static str> {
    include_str!("../kb/fronts.txt")
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
}

impl Block {
    fn width(&self) -> f64 {
        self.cols as f64 * self.size[0] + (self.cols - 1) as f64 * self.gap_x + self.aisle
    }

    /// Depth from the first row's front to the back of the last row's seats.
    fn depth(&self) -> f64 {
        self.rows as f64 * self.size[1] + (self.rows - 1) as f64 * self.gap_y + self.seat_back
    }

    /// Room [across, along] the block needs: walkways at both sides and behind, the front band.
    fn needs(&self) -> [f64; 2] {
        [
            (self.width() + 2.0 * PASSAGE).max(self.target_width + 0.4),
            self.depth() + self.front + PASSAGE,
        ]
    }

    /// Local (across, along) centre of instance `k`; along grows toward the front.
    fn slot(&self, k: usize) -> [f64; 2] {
        // every row used: the first n % rows rows hold one more than the others
        let (base, extra) = (self.n / self.rows, self.n % self.rows);
        let (row, col) = if k < extra * (base + 1) {
            (k / (base + 1), k % (base + 1))
        } else {
            let k = k - extra * (base + 1);
            (extra + k / base, k % base)
        };
        let aisle = if col >= self.cols.div_ceil(2) {
            self.aisle
        } else {
            0.0
        };
        let x = -0.5 * self.width()
            + 0.5 * self.size[0]
            + col as f64 * (self.size[0] + self.gap_x)
            + aisle;
        let y = 0.5 * self.depth() - 0.5 * self.size[1] - row as f64 * (self.size[1] + self.gap_y);
        [x, y]
    }
}

/// The block of category `cat` (`None` when it is not in rows or has fewer than two).
fn block(spec: &SceneSpec, cat: &str) -> Option<Block> {
    let o = spec.objects.get(cat)?;
    let n = o.number as usize;
    if n < 2 {
        return None;
    }
    // rows asked, else rows of about 1.5 times as many as there are rows when every instance
    // is in ROW before the same front (a classroom's desks)
    let in_row = (1..=n).all(|k| {
        let id = format!("{cat}{k}");
        spec.relations
            .iter()
            .any(|r| r.relation == RelationKind::Row && r.subject == id)
    });
    let rows = match o.rows {
        // long things (pews, benches): one a side of the centre aisle
        0 if in_row && o.size[0] >= LONG => n.div_ceil(2),
        0 if in_row => n.div_ceil((1.5 * n as f64).sqrt().ceil() as usize),
        0 => return None,
        r => (r as usize).min(n),
    };
    let cols = n.div_ceil(rows);
    // a seat drawn up to each (a chair at a desk, stools at a bench) needs room between rows:
    // the seat's depth and a passage behind it
    let seat_depth = spec
        .relations
        .iter()
        .filter(|r| {
            matches!(
                r.relation,
                RelationKind::At | RelationKind::Around | RelationKind::AtBack
            ) && base(&r.object) == cat
        })
        .filter_map(|r| spec.objects.get(base(&r.subject)))
        .map(|s| s.size[1])
        .fold(None, |m: Option<f64>, d| Some(m.map_or(d, |m| m.max(d))));
    let seat_back = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::AtBack && base(&r.object) == cat)
        .filter_map(|r| spec.objects.get(base(&r.subject)))
        .map(|s| s.size[1] + SEAT_GAP)
        .fold(0.0, f64::max);
    // what the rows face (a stage, a screen) and a metre to see it from
    let target = spec
        .relations
        .iter()
        .filter(|r| matches!(r.relation, RelationKind::Opposite | RelationKind::Row))
        .filter(|r| base(&r.subject) == cat)
        .map(|r| base(&r.object).to_string())
        .next()
        .or_else(|| {
            fronts()
                .find(|f| *f != cat && spec.objects.contains_key(*f))
                .map(str::to_string)
        });
    // what else stands at the front with it: the fronts.txt categories the scene holds that
    // are more telling than it (a stage below a screen), the most telling first; a target
    // fronts.txt does not list (a piano the chairs face) is the front alone, and the scene's
    // board hangs elsewhere
    let listed = target.as_deref().is_none_or(|t| fronts().any(|f| f == t));
    let mut at_front: Vec<String> = fronts()
        .filter(|f| listed && *f != cat && spec.objects.contains_key(*f))
        .take_while(|f| Some(*f) != target.as_deref())
        .map(str::to_string)
        .collect();
    at_front.extend(target.clone());
    let front = at_front
        .iter()
        .filter_map(|t| spec.objects.get(t))
        .map(|t| t.size[0].min(t.size[1]) + 1.0)
        .fold(FRONT, f64::max);
    // what stands BEFORE the front things (a teacher's desk before the board, its chair
    // between) and a passage before the first row
    let before = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Before)
        .filter(|r| at_front.iter().any(|t| t == base(&r.object)))
        .filter_map(|r| {
            Some((
                spec.objects.get(base(&r.object))?,
                spec.objects.get(base(&r.subject))?,
            ))
        })
        .map(|(t, s)| t.size[1] + crate::plan::check::BEFORE_GAP.0 + 0.1 + s.size[1] + PASSAGE)
        .fold(0.0, f64::max);
    let front = front.max(before);
    let target_width = target
        .as_deref()
        .and_then(|t| spec.objects.get(t))
        .map(|t| t.size[0])
        .unwrap_or(0.0);
    let s = [o.size[0], o.size[1]];
    let mut b = Block {
        at_front: vec![],
        target_width,
        front,
        n,
        rows,
        cols,
        seat_back,
        size: s,
        gap_x: (0.25 * s[0]).clamp(0.08, 0.5),
        gap_y: if let Some(depth) = seat_depth {
            (depth + SEAT_GAP + PASSAGE).max(1.1)
        } else {
            (0.7 * s[1]).clamp(ROW_WALK, 1.0)
        },
        aisle: if cols >= 4 || (cols >= 2 && s[0] >= LONG) {
            AISLE
        } else {
            0.0
        },
    };
    b.front = b.front.max(0.55 * b.width());
    // the ends of the first row see what stands at the front within SIGHT of straight ahead;
    // a target on the floor that is not the most telling front thing (a lectern before a
    // board) stands a passage before it, and before what stands BEFORE it (a teacher's desk)
    let table = super::classes::Placements::builtin();
    let hung = |c: &str| matches!(table.class(c), super::classes::Class::OnWall(_));
    // the depth of the front things at the wall before the target, and a passage before them
    let at_wall = at_front
        .iter()
        .filter(|c| Some(*c) != target.as_ref())
        .filter_map(|c| spec.objects.get(c))
        .map(|t| t.size[1] + PASSAGE)
        .fold(0.0, f64::max);
    let mut placed_at = vec![];
    for (k, name) in at_front.into_iter().enumerate() {
        // (a target that stands on another thing, an altar on a platform, is set there)
        let on_other = spec
            .relations
            .iter()
            .any(|r| r.relation == RelationKind::Over && base(&r.subject) == name);
        let from_wall = if k > 0 && Some(&name) == target.as_ref() && !hung(&name) && !on_other {
            before.max(at_wall)
        } else {
            0.0
        };
        // what stands BEHIND it (candle stands behind an altar) stands between it and the wall
        let behind = spec
            .relations
            .iter()
            .filter(|r| r.relation == RelationKind::Behind && base(&r.object) == name)
            .filter_map(|r| spec.objects.get(base(&r.subject)))
            .map(|s| s.size[1] + super::compose::FRONT_LEGROOM + 0.05)
            .fold(0.0, f64::max);
        let from_wall = from_wall + if hung(&name) { 0.0 } else { behind };
        let Some(t) = spec.objects.get(&name) else {
            continue;
        };
        placed_at.push((name, from_wall));
        let lateral = (0.5 * b.width() - 0.5 * t.size[0]).max(0.0);
        b.front = b
            .front
            .max(from_wall + t.size[1] + (lateral / SIGHT.to_radians().tan()).max(1.0));
    }
    b.at_front = placed_at;
    Some(b)
}

/// The category of an instance id (`desk12` -> `desk`).
fn base(id: &str) -> &str {
    id.trim_end_matches(|c: char| c.is_ascii_digit())
}

/// The smallest [w, d] that holds every block of `spec` facing +y (a room chosen by floor area
/// alone can be too narrow for ten seats abreast) and every floor of tables.
pub fn room_for_rows(spec: &SceneSpec, base: [f64; 2]) -> [f64; 2] {
    let t = super::tables::room_for_tables(spec, base);
    let b = room_for_blocks(spec);
    [t[0].max(b[0]), t[1].max(b[1])]
}

/// The smallest [w, d] that holds every block of rows of `spec` facing +y, [0, 0] when none.
pub fn room_for_blocks(spec: &SceneSpec) -> [f64; 2] {
    let mut need = [0.0f64, 0.0f64];
    for cat in spec.objects.keys() {
        if let Some(b) = block(spec, cat) {
            let [a, l] = b.needs();
            need = [need[0].max(a), need[1].max(l)];
        }
    }
    need
}

impl Problem {
    /// Poses for every instance of every category in rows that `placed` leaves free, written
    /// into `placed` (the block of a category with an instance already placed is left alone),
    /// then the floors of tables with their seats (`tables.rs`).
    /// The front is the wall the block's rows face: tried in the order that leaves most room.
    /// Returns the front band of each block that faces something (from its first row to the
    /// front wall, as wide as the block) with the instances that belong there (the block and
    /// what stands at its front).
    pub(super) fn place_rows(
        &self,
        spec: &SceneSpec,
        placed: &mut [Option<Pose>],
    ) -> Vec<(Box2, Vec<usize>)> {
        let mut bands = vec![];
        for cat in spec.objects.keys() {
            let Some(b) = block(spec, cat) else { continue };
            let ids: Vec<usize> = (1..=b.n)
                .filter_map(|k| self.index.get(&format!("{cat}{k}")).copied())
                .collect();
            if ids.len() != b.n || ids.iter().any(|&i| placed[i].is_some()) {
                continue;
            }
            if let Some((poses, f)) = self.block_poses(&b, &ids, placed) {
                let first = poses
                    .iter()
                    .map(|p| p.c[0] * f[0] + p.c[1] * f[1])
                    .fold(f64::NEG_INFINITY, f64::max)
                    + 0.5 * b.size[1];
                for (&i, p) in ids.iter().zip(poses) {
                    placed[i] = Some(p);
                }
                let mut members = ids.clone();
                for (t, from_wall) in &b.at_front {
                    if let Some(&t) = self.index.get(&format!("{t}1")) {
                        self.place_front(t, f, *from_wall, placed);
                        members.push(t);
                    }
                }
                let along = 0.5
                    * if f[0] == 0.0 {
                        self.room[1]
                    } else {
                        self.room[0]
                    };
                let mid = 0.5 * (first + along);
                let band = Box2::new(
                    [mid * f[0], mid * f[1]],
                    yaw_facing(f),
                    [b.width(), (along - first).max(0.0)],
                    0.0,
                    self.room[2],
                );
                // (rows that face nothing, a shop's shelving, keep no view)
                if !b.at_front.is_empty() {
                    bands.push((band, members));
                }
            }
        }
        self.place_tables(spec, placed);
        bands
    }

    /// Stands what the rows face (instance `t`) `from_wall` before the front wall (against it
    /// when 0), centred before the rows and turned to them, when it is free there; else the
    /// search places it.
    fn place_front(&self, t: usize, f: [f64; 2], from_wall: f64, placed: &mut [Option<Pose>]) {
        if placed[t].is_some() {
            return;
        }
        let [w, d, _] = self.room;
        let along = if f[0] == 0.0 { d } else { w };
        let s = self.inst[t].size;
        let v = 0.5 * along - 0.02 - from_wall - 0.5 * s[1];
        let p = Pose {
            c: [v * f[0], v * f[1]],
            yaw: yaw_facing([-f[0], -f[1]]),
            z: self.hung[t].unwrap_or(0.0),
        };
        if self.block_is_free(&[t], &[p], placed) {
            placed[t] = Some(p);
        }
    }

    /// The block's poses and the way its rows face, or `None` when no way fits.
    fn block_poses(
        &self,
        b: &Block,
        ids: &[usize],
        placed: &[Option<Pose>],
    ) -> Option<(Vec<Pose>, [f64; 2])> {
        let [w, d, _] = self.room;
        // rows asked by or facing a window face a wall with one, close to it
        let by_window = matches!(
            self.inst[ids[0]].anchor,
            Anchor::Window | Anchor::FaceWindow
        );
        // by a window (not facing one) with nothing at the front: against that wall
        let least = if self.inst[ids[0]].anchor == Anchor::Window && b.at_front.is_empty() {
            BY_WINDOW
        } else {
            FRONT_MIN
        };
        let mut tries: Vec<([f64; 2], bool, bool, bool, f64)> = vec![];
        for (f, wall) in [
            ([0.0, 1.0], Wall::North),
            ([0.0, -1.0], Wall::South),
            ([1.0, 0.0], Wall::East),
            ([-1.0, 0.0], Wall::West),
        ] {
            let (across, along) = if f[0] == 0.0 { (w, d) } else { (d, w) };
            let [na, nl] = b.needs();
            let slack = (across - na).min(along - nl + b.front - FRONT_MIN);
            let window = by_window
                && self
                    .openings
                    .iter()
                    .any(|o| o.kind == OpeningKind::Window && o.wall == wall);
            // the whole front band fits this way
            let full = along >= nl && across >= na;
            // a front wall without a window keeps the board or screen off it
            let blank = !self.openings.iter().any(|o| o.wall == wall);
            tries.push((f, window, full, blank, slack));
        }
        // a window first when asked, then a way with the whole front, then a blank front
        // wall, then the most room; ties keep the order (north first)
        tries.sort_by(|a, b| {
            b.1.cmp(&a.1)
                .then(b.2.cmp(&a.2))
                .then(b.3.cmp(&a.3))
                .then(b.4.total_cmp(&a.4))
        });
        for (f, window, _, _, slack) in tries {
            if slack < 0.0 {
                continue;
            }
            let (across, along) = if f[0] == 0.0 { (w, d) } else { (d, w) };
            let want = if window { least } else { b.front };
            let front = (along - b.depth() - PASSAGE).min(want).max(least);
            let rest = if window {
                0.0
            } else {
                along - b.depth() - PASSAGE - front
            };
            // the block's centre along the facing: behind the front band, the rest shared
            let v0 = 0.5 * along - front - 0.5 * rest.max(0.0) - 0.5 * b.depth();
            if b.width().max(b.target_width) > across {
                continue;
            }
            let e = [f[1], -f[0]];
            let yaw = yaw_facing(f);
            let poses: Vec<Pose> = (0..b.n)
                .map(|k| {
                    let [u, v] = b.slot(k);
                    let v = v + v0;
                    Pose {
                        c: [u * e[0] + v * f[0], u * e[1] + v * f[1]],
                        yaw,
                        z: 0.0,
                    }
                })
                .collect();
            if self.block_is_free(ids, &poses, placed) {
                return Some((poses, f));
            }
        }
        None
    }

    /// Inside the room, clear of door zones and of what is placed already.
    fn block_is_free(&self, ids: &[usize], poses: &[Pose], placed: &[Option<Pose>]) -> bool {
        let [w, d, _] = self.room;
        let others: Vec<Box2> = placed
            .iter()
            .enumerate()
            .filter_map(|(j, p)| p.map(|p| self.boxed(j, &p)))
            .collect();
        let doors: Vec<&Box2> = self
            .openings
            .iter()
            .zip(&self.zones)
            .filter(|(o, _)| o.kind == OpeningKind::Door)
            .map(|(_, z)| z)
            .collect();
        ids.iter().zip(poses).all(|(&i, p)| {
            let bx = self.boxed(i, p);
            let [x0, y0, x1, y1] = bx.aabb();
            let inside = x0 >= -0.5 * w && x1 <= 0.5 * w && y0 >= -0.5 * d && y1 <= 0.5 * d;
            inside
                && doors.iter().all(|z| penetration(&bx, z) <= 0.0)
                && others.iter().all(|o| penetration(&bx, o) <= 0.0)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(n: u32, rows: u32, size: [f64; 3]) -> SceneSpec {
        let text = format!(
            r#"{{"scene_type":"indoor","scene_text":"t","objects":{{"seat":{{"number":{n},"size":{size:?},"description":"d","rows":{rows}}}}}}}"#
        );
        serde_json::from_str(&text).expect("spec")
    }

    #[test]
    fn a_block_has_the_rows_asked_and_its_slots_do_not_overlap() {
        for (n, rows) in [(15, 3), (12, 5), (6, 1), (100, 10)] {
            let b = block(&spec(n, rows, [0.6, 0.6, 0.9]), "seat").expect("block");
            let slots: Vec<[f64; 2]> = (0..b.n).map(|k| b.slot(k)).collect();
            let mut ys: Vec<f64> = slots.iter().map(|s| s[1]).collect();
            ys.sort_by(f64::total_cmp);
            ys.dedup_by(|a, c| (*a - *c).abs() < 1e-9);
            assert_eq!(ys.len(), rows as usize, "{n} in {rows}");
            for (i, a) in slots.iter().enumerate() {
                for c in &slots[i + 1..] {
                    let apart = (a[0] - c[0]).abs() >= 0.6 || (a[1] - c[1]).abs() >= 0.6;
                    assert!(apart, "{n} in {rows}: {a:?} {c:?}");
                }
            }
        }
        assert!(block(&spec(4, 0, [0.6, 0.6, 0.9]), "seat").is_none());
    }
}
