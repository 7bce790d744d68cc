//! A floor of tables with their seats (a restaurant's, a wedding's, a canteen's, a pub's): three
//! or more tables of one category, each with seats AROUND it, stand in a lattice with a passage
//! between the backs of their seats, the lattice's cells nearest the room's middle taken first,
//! clear of the walls' band, the doors' zones, what is placed and what stands in the middle (a
//! dance floor). Each table's seats are drawn up to its sides, the long sides first, spread
//! evenly along each side and turned to it. A floor that does not fit is left to the search.
use super::spacing::{PASSAGE, SEAT_GAP};
use super::{Pose, Problem};
use crate::plan::check::{penetration, Box2};
use crate::plan::spec::{Anchor, OpeningKind, RelationKind, SceneSpec};

/// Fewest tables of one category that make a floor of tables.
const MIN_TABLES: usize = 3;
/// Free band kept along the walls (m), widest first: things against a wall and a walkway, then
/// a walkway, then a tight room's last try.
const WALL_BANDS: [f64; 3] = [1.0, 0.7, 0.35];

/// One table's seats: (instance, side, position along the side).
type Seating = Vec<(usize, usize, f64)>;
/// Seats spread over a table's four sides: how many on each, and each seat's side in turn.
type SideSeats = ([usize; 4], Vec<usize>);

/// The [w, d] a room needs for the lattice of every floor of tables of `spec` (its cells,
/// those a CENTER thing takes with them, the walls' middle band), [0, 0] when there is none:
/// of the blocks that hold them, the one that grows a room of `base` ([w, d], what the rest of
/// its furniture needs) least.
pub fn room_for_tables(spec: &SceneSpec, room: [f64; 2]) -> [f64; 2] {
    let base = |id: &str| {
        id.trim_end_matches(|c: char| c.is_ascii_digit())
            .to_string()
    };
    let mut need = [0.0f64, 0.0f64];
    for (cat, o) in &spec.objects {
        let n = o.number as usize;
        if n < MIN_TABLES || o.rows > 0 {
            continue;
        }
        let seats: Vec<&str> = spec
            .relations
            .iter()
            .filter(|r| r.relation == RelationKind::Around && base(&r.object) == *cat)
            .map(|r| r.subject.as_str())
            .collect();
        if seats.is_empty() {
            continue;
        }
        let seat_sizes = || seats.iter().filter_map(|s| spec.objects.get(&base(s)));
        let deep = seat_sizes().map(|s| s.size[1]).fold(0.0, f64::max);
        let wide = seat_sizes().map(|s| s.size[0]).fold(0.0, f64::max);
        // the tables of each size (tables laid for two and for six), with their seats' share
        let mut groups: Vec<([f64; 3], usize)> = vec![];
        for k in 1..=o.number {
            let size = o.size_of(k);
            match groups.iter_mut().find(|(s, _)| *s == size) {
                Some(g) => g.1 += 1,
                None => groups.push((size, 1)),
            }
        }
        let pitches: Vec<([f64; 2], usize)> = groups
            .iter()
            .filter_map(|&(size, m)| {
                let at = |t: &str| {
                    spec.relations
                        .iter()
                        .filter(|r| r.relation == RelationKind::Around && r.object == t)
                        .count()
                };
                let per = (1..=o.number)
                    .filter(|&k| o.size_of(k) == size)
                    .map(|k| at(&format!("{cat}{k}")))
                    .max()
                    .unwrap_or(0)
                    .max(if groups.len() == 1 {
                        seats.len().div_ceil(n)
                    } else {
                        0
                    });
                let (count, _) = side_seats([size[0], size[1]], wide, per)?;
                // a seat's depth beyond the sides that have seats: the x pair (2, 3), the y pair (0, 1)
                let ring = [count[2] + count[3], count[0] + count[1]].map(|k| {
                    if k > 0 {
                        deep + SEAT_GAP
                    } else {
                        0.0
                    }
                });
                Some(([0, 1].map(|k| size[k] + 2.0 * ring[k] + PASSAGE), m))
            })
            .collect();
        let Some(&(pitch, _)) = pitches
            .iter()
            .max_by(|a, b| (a.0[0] * a.0[1]).total_cmp(&(b.0[0] * b.0[1])))
        else {
            continue;
        };
        // the side of a lone CENTER thing (a dance floor) with its passage, in either turn
        let middle: f64 = spec
            .objects
            .iter()
            .filter(|(c, _)| {
                spec.anchors.get(&format!("{c}1")) == Some(&Anchor::Center)
                    && !spec
                        .relations
                        .iter()
                        .any(|r| base(&r.subject) == **c || base(&r.object) == **c)
            })
            .map(|(_, m)| m.size[0].max(m.size[1]) + 2.0 * PASSAGE)
            .fold(0.0, f64::max);
        let block = if middle > 0.0 || pitches.len() < 2 {
            // tables of one size, or round a CENTER thing: the tables of every size in the
            // largest one's cells, in a near-square block round the cells it takes
            let area: f64 = pitches
                .iter()
                .map(|(p, m)| p[0] * p[1] * *m as f64)
                .sum::<f64>();
            let cells = (area / (pitch[0] * pitch[1])).ceil().max(1.0) as usize;
            let [nx, ny] = lattice_round(cells, pitch, middle);
            let band = 2.0 * WALL_BANDS[1] - PASSAGE;
            [nx as f64 * pitch[0] + band, ny as f64 * pitch[1] + band]
        } else {
            block_for(&pitches, room)
        };
        need = [need[0].max(block[0]), need[1].max(block[1])];
    }
    need
}

/// The columns and rows of a centred lattice at `pitch` that hold `cells` tables round a thing
/// `middle` wide in the room's middle (0: none): without one, the near-square block; with one,
/// of the blocks whose cells clear of it (with their passage, as `place_tables` lays them)
/// are enough, the one with the shortest longer side, then the smallest.
fn lattice_round(cells: usize, pitch: [f64; 2], middle: f64) -> [usize; 2] {
    if middle <= 0.0 {
        let nx = (cells as f64).sqrt().ceil() as usize;
        return [nx, cells.div_ceil(nx)];
    }
    // centred cells along an axis whose seat rings reach into the middle thing's passage
    let blocked = |n: usize, p: f64| {
        (0..n)
            .filter(|&k| {
                let c = (k as f64 - 0.5 * (n as f64 - 1.0)) * p;
                c.abs() < 0.5 * middle + 0.5 * (p - PASSAGE) - 1e-9
            })
            .count()
    };
    let most = cells + 16;
    let mut best: Option<(f64, f64, [usize; 2])> = None;
    for nx in 1..=most {
        for ny in 1..=most {
            let free = nx * ny - blocked(nx, pitch[0]) * blocked(ny, pitch[1]);
            if free < cells {
                continue;
            }
            let (w, d) = (nx as f64 * pitch[0], ny as f64 * pitch[1]);
            let key = (w.max(d), w * d);
            if best.is_none_or(|(l, a, _)| key.0 < l - 1e-9 || (key.0 < l + 1e-9 && key.1 < a)) {
                best = Some((key.0, key.1, [nx, ny]));
            }
        }
    }
    best.map_or([cells, 1], |(_, _, n)| n)
}

/// The [w, d] of a room whose floor holds a block of table cells, `groups` of them at a pitch
/// each (tables of one size make one lattice), with the walls' middle band: the cells of every
/// group share the block's floor, each group's in whole rows of its own; of the blocks at least
/// one cell of each wide, the one that grows a room of `room` least, in either turn (the
/// lattice is laid in both).
fn block_for(groups: &[([f64; 2], usize)], room: [f64; 2]) -> [f64; 2] {
    let band = 2.0 * WALL_BANDS[1] - PASSAGE;
    let grown = |b: [f64; 2]| [room[0].max(b[0] + band), room[1].max(b[1] + band)];
    let mut best: Option<(f64, [f64; 2])> = None;
    for turn in [false, true] {
        let g: Vec<([f64; 2], usize)> = groups
            .iter()
            .map(|&(p, m)| (if turn { [p[1], p[0]] } else { p }, m))
            .collect();
        let widest = g.iter().map(|(p, _)| p[0]).fold(0.0, f64::max);
        // block widths: whole columns of some group's cells, or as wide as the room already is
        let widths = g
            .iter()
            .flat_map(|&(p, m)| (1..=m).map(move |k| k as f64 * p[0]))
            .chain([room[0] - band])
            .filter(|&bx| bx >= widest - 1e-9);
        for bx in widths {
            // the cells of every size share the block's rows; each size's lattice still needs
            // its whole rows
            // its whole rows; where sizes meet, the smaller keep half a passage more from the
            // larger's seats
            let meet = if g.len() > 1 { 0.5 * PASSAGE } else { 0.0 };
            let shared: f64 =
                g.iter().map(|&(p, m)| m as f64 * p[0] * p[1]).sum::<f64>() / bx + meet;
            let by = g
                .iter()
                .map(|&(p, m)| {
                    let across = ((bx + 1e-9) / p[0]).floor().max(1.0) as usize;
                    m.div_ceil(across) as f64 * p[1]
                })
                .fold(shared, f64::max);
            let r = grown([bx, by]);
            let a = r[0] * r[1];
            if best.is_none_or(|(b, _)| a < b - 1e-9) {
                best = Some((a, r));
            }
        }
    }
    best.map_or([0.0, 0.0], |(_, r)| r)
}

/// How `n` seats `wide` wide spread over the sides of a table `size` ([width, depth]): the
/// seats on each side and each seat's side in turn (`None` when there are none, or more than
/// the sides take). Sides: 0 front (+y), 1 back, 2 right (+x), 3 left; the long pair first,
/// each pair filled in turn up to what a side takes (a seat's width and 0.1 m); a square table's
/// four sides in turn.
fn side_seats(size: [f64; 2], wide: f64, n: usize) -> Option<SideSeats> {
    let [w, d] = size;
    if n == 0 {
        return None;
    }
    let takes = [w, w, d, d].map(|l| ((l + 0.1) / (wide + 0.1)).floor().max(1.0) as usize);
    let rounds: Vec<Vec<usize>> = if (w - d).abs() < 0.15 {
        vec![vec![0, 1, 2, 3]]
    } else if w > d {
        vec![vec![0, 1], vec![2, 3]]
    } else {
        vec![vec![2, 3], vec![0, 1]]
    };
    let mut count = [0usize; 4];
    let mut order: Vec<usize> = vec![];
    for sides in rounds {
        while order.len() < n {
            let before = order.len();
            for &s in &sides {
                if order.len() < n && count[s] < takes[s] {
                    count[s] += 1;
                    order.push(s);
                }
            }
            if order.len() == before {
                break;
            }
        }
    }
    (order.len() == n).then_some((count, order))
}

/// The lattices of cell centres along a room side `len` long that keep `band` free at both
/// walls, for cells `cell` long at `pitch`: centred, and shifted by quarters of a pitch.
fn lattice(len: f64, band: f64, cell: f64, pitch: f64) -> Vec<Vec<f64>> {
    let (lo, hi) = (
        -0.5 * len + band + 0.5 * cell,
        0.5 * len - band - 0.5 * cell,
    );
    if hi < lo {
        return vec![];
    }
    let n = ((hi - lo) / pitch).floor() as usize;
    let centred: Vec<f64> = (0..=n)
        .map(|k| (k as f64 - 0.5 * n as f64) * pitch)
        .collect();
    let mut out = vec![centred];
    for q in 0..4 {
        let start = lo + 0.25 * q as f64 * pitch;
        out.push(
            (0..=n + 1)
                .map(|k| start + k as f64 * pitch)
                .filter(|&x| x <= hi + 1e-9)
                .collect(),
        );
    }
    out
}

impl Problem {
    /// Places every floor of tables of `spec` that fits, tables and seats, into `placed`.
    pub(super) fn place_tables(&self, spec: &SceneSpec, placed: &mut [Option<Pose>]) {
        for (cat, o) in &spec.objects {
            let n = o.number as usize;
            if n < MIN_TABLES || o.rows > 0 {
                continue;
            }
            let tables: Vec<usize> = (1..=n)
                .filter_map(|k| self.index.get(&format!("{cat}{k}")).copied())
                .collect();
            if tables.len() != n || !tables.iter().all(|&t| self.free_table(t, placed)) {
                continue;
            }
            // tables of one size make one lattice (tables laid for two, tables for six), the
            // largest first, nearest the middle
            let mut sizes: Vec<[f64; 3]> = vec![];
            for &t in &tables {
                if !sizes.contains(&self.inst[t].size) {
                    sizes.push(self.inst[t].size);
                }
            }
            sizes.sort_by(|a, b| (b[0] * b[1]).total_cmp(&(a[0] * a[1])));
            // tables of several sizes: when the larger ones nearest the middle leave the smaller
            // no lattice, the larger go to the edge of the floor instead
            let mut first: Option<Vec<Option<Pose>>> = None;
            for edge in [false, true] {
                if edge && sizes.len() < 2 {
                    break;
                }
                let mut trial = placed.to_vec();
                let mut mates: Vec<usize> = vec![];
                let mut all = true;
                for &size in &sizes {
                    let alike: Vec<usize> = tables
                        .iter()
                        .copied()
                        .filter(|&t| self.inst[t].size == size)
                        .collect();
                    let seatings = alike
                        .iter()
                        .map(|&t| self.seating(t))
                        .collect::<Option<Vec<Seating>>>();
                    let poses =
                        seatings.and_then(|s| self.floor_poses(&alike, &s, &trial, &mates, edge));
                    match poses {
                        Some(poses) => {
                            for (i, p) in poses {
                                trial[i] = Some(p);
                                mates.push(i);
                            }
                        }
                        None => all = false,
                    }
                }
                if all {
                    first = Some(trial);
                    break;
                }
                first.get_or_insert(trial);
            }
            if let Some(trial) = first {
                placed.copy_from_slice(&trial);
            }
        }
    }

    /// Whether table `t` is free to stand anywhere: not placed, in the room's open floor, the
    /// subject of no relation, and its seats not placed yet.
    fn free_table(&self, t: usize, placed: &[Option<Pose>]) -> bool {
        placed[t].is_none()
            && matches!(self.inst[t].anchor, Anchor::Others | Anchor::Center)
            && self.hung[t].is_none()
            && self.rels[t].iter().all(|&(rel, k, subject)| {
                !subject && (rel != RelationKind::Around || placed[k].is_none())
            })
    }

    /// The seats AROUND table `t` and how [`side_seats`] spreads them over its sides (`None`
    /// when it has none, or more than its sides take), each seat's side in turn.
    pub(super) fn sides_of(&self, t: usize) -> (Vec<usize>, Option<SideSeats>) {
        let seats: Vec<usize> = self.rels[t]
            .iter()
            .filter(|r| r.0 == RelationKind::Around && !r.2)
            .map(|r| r.1)
            .collect();
        let wide = seats
            .iter()
            .map(|&s| self.inst[s].size[0])
            .fold(0.0, f64::max);
        let [w, d, _] = self.inst[t].size;
        let spread = side_seats([w, d], wide, seats.len());
        (seats, spread)
    }

    /// The seats AROUND table `t` over its sides (`None` when it has none, or more than its
    /// sides take), as [`side_seats`] spreads them.
    fn seating(&self, t: usize) -> Option<Seating> {
        let (seats, spread) = self.sides_of(t);
        let (count, order) = spread?;
        let [w, d, _] = self.inst[t].size;
        let len = [w, w, d, d];
        let mut nth = [0usize; 4];
        Some(
            seats
                .iter()
                .zip(order)
                .map(|(&i, side)| {
                    let t = len[side] * ((nth[side] as f64 + 0.5) / count[side] as f64 - 0.5);
                    nth[side] += 1;
                    (i, side, t)
                })
                .collect(),
        )
    }

    /// Poses of the tables and their seats in a lattice, or `None` when no lattice holds them:
    /// the cells nearest the middle (`edge`: farthest from it), a passage from the `mates` (the
    /// floor's tables and seats laid already).
    fn floor_poses(
        &self,
        tables: &[usize],
        seatings: &[Seating],
        placed: &[Option<Pose>],
        mates: &[usize],
        edge: bool,
    ) -> Option<Vec<(usize, Pose)>> {
        let [w, d, _] = self.room;
        let s = self.inst[tables[0]].size;
        let deep = seatings
            .iter()
            .flatten()
            .map(|&(i, _, _)| self.inst[i].size[1])
            .fold(0.0, f64::max);
        // seats at the left or right (x) and at the front or back (y) of some table
        let seated = |sides: [usize; 2]| {
            seatings
                .iter()
                .flatten()
                .any(|&(_, side, _)| sides.contains(&side))
        };
        let ring =
            [seated([2, 3]), seated([0, 1])].map(|on| if on { deep + SEAT_GAP } else { 0.0 });
        // the tables and seats of this floor laid already (the larger tables) keep a passage
        // from the new cells, as the cells of one lattice do from each other
        let others: Vec<Box2> = placed
            .iter()
            .enumerate()
            .filter_map(|(j, p)| {
                let mut b = self.boxed(j, p.as_ref()?);
                if mates.contains(&j) {
                    b.half = b.half.map(|h| h + 0.5 * PASSAGE);
                }
                Some(b)
            })
            .chain(self.middle_keep())
            .chain(
                self.openings
                    .iter()
                    .zip(&self.zones)
                    .filter(|(o, _)| o.kind == OpeningKind::Door)
                    .map(|(_, z)| *z),
            )
            .collect();
        for band in WALL_BANDS {
            // every turn and lattice phase; the one whose tables stand nearest the middle
            let mut best: Option<(f64, f64, Vec<[f64; 2]>)> = None;
            for yaw in [0.0, 90.0] {
                let ([fx, fy], [rx, ry]) = if yaw == 0.0 {
                    ([s[0], s[1]], ring)
                } else {
                    ([s[1], s[0]], [ring[1], ring[0]])
                };
                let cell = [fx + 2.0 * rx, fy + 2.0 * ry];
                let pitch = [cell[0] + PASSAGE, cell[1] + PASSAGE];
                let xs = lattice(w, band, cell[0], pitch[0]);
                let ys = lattice(d, band, cell[1], pitch[1]);
                for x in &xs {
                    for y in &ys {
                        let mut cells: Vec<[f64; 2]> = vec![];
                        for &a in x {
                            for &b in y {
                                let zone = Box2::new([a, b], 0.0, cell, 0.0, 2.0);
                                if others.iter().all(|o| penetration(&zone, o) <= 0.0) {
                                    cells.push([a, b]);
                                }
                            }
                        }
                        if cells.len() < tables.len() {
                            continue;
                        }
                        // the cells nearest the middle
                        let r = |c: &[f64; 2]| {
                            let r = (c[0] / w).hypot(c[1] / d);
                            if edge {
                                -r
                            } else {
                                r
                            }
                        };
                        cells.sort_by(|a, b| r(a).total_cmp(&r(b)).then(a[0].total_cmp(&b[0])));
                        cells.truncate(tables.len());
                        let spread: f64 = cells.iter().map(r).sum();
                        if best.as_ref().is_none_or(|b| spread < b.0 - 1e-9) {
                            best = Some((spread, yaw, cells));
                        }
                    }
                }
            }
            let Some((_, yaw, mut cells)) = best else {
                continue;
            };
            // in reading order
            cells.sort_by(|a, b| b[1].total_cmp(&a[1]).then(a[0].total_cmp(&b[0])));
            let mut out = vec![];
            for ((&t, seating), c) in tables.iter().zip(seatings).zip(cells) {
                let p = Pose { c, yaw, z: 0.0 };
                out.push((t, p));
                out.extend(self.seat_poses(t, &p, seating));
            }
            return Some(out);
        }
        None
    }

    /// The poses of a table's seats, each `SEAT_GAP` off its side and turned to the table.
    fn seat_poses(&self, t: usize, p: &Pose, seating: &Seating) -> Vec<(usize, Pose)> {
        let b = self.boxed(t, p);
        let [hw, hd] = b.half;
        seating
            .iter()
            .map(|&(i, side, along)| {
                let off = SEAT_GAP + 0.5 * self.inst[i].size[1];
                let [lx, ly] = match side {
                    0 => [along, hd + off],
                    1 => [along, -hd - off],
                    2 => [hw + off, along],
                    _ => [-hw - off, along],
                };
                let c = [
                    b.c[0] + lx * b.ex[0] + ly * b.ey[0],
                    b.c[1] + lx * b.ex[1] + ly * b.ey[1],
                ];
                // square to its side, facing across it (a seat near a long side's end
                // faces that side, not the table's nearest end)
                let yaw = p.yaw
                    + match side {
                        0 => 180.0,
                        1 => 0.0,
                        2 => 90.0,
                        _ => -90.0,
                    };
                (i, Pose { c, yaw, z: 0.0 })
            })
            .collect()
    }

    /// What keeps the room's middle: a CENTER thing that relates to nothing (a dance floor),
    /// with a passage round it, in either turn (a cross).
    fn middle_keep(&self) -> Vec<Box2> {
        (0..self.inst.len())
            .filter(|&i| self.inst[i].anchor == Anchor::Center && self.rels[i].is_empty())
            .flat_map(|i| {
                let s = self.inst[i].size;
                let e = [s[0] + 2.0 * PASSAGE, s[1] + 2.0 * PASSAGE];
                [0.0, 90.0].map(|yaw| Box2::new([0.0, 0.0], yaw, e, 0.0, 2.0))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::check::{relations_unsatisfied, validity_problems};
    use crate::plan::gcp::{layout, LayoutOptions};
    use crate::plan::spec::SceneSpec;

    fn hall(tables: u32, size: [f64; 3], chairs: u32) -> SceneSpec {
        let rels: Vec<String> = (0..tables * chairs)
            .map(|k| {
                format!(
                    r#"{{"subject":"chair{}","relation":"AROUND","object":"table{}"}}"#,
                    k + 1,
                    k / chairs + 1
                )
            })
            .collect();
        let text = format!(
            r#"{{"scene_type":"indoor","scene_text":"t","objects":{{
            "table":{{"number":{tables},"size":{size:?},"description":"d"}},
            "chair":{{"number":{},"size":[0.45,0.5,0.9],"description":"d"}},
            "dance floor":{{"number":1,"size":[4.0,4.0,0.02],"description":"d"}}}},
            "anchors":{{"dance floor1":"CENTER"}},
            "relations":[{}]}}"#,
            tables * chairs,
            rels.join(",")
        );
        serde_json::from_str(&text).expect("spec")
    }

    #[test]
    fn every_table_of_a_floor_gets_all_its_seats_and_the_middle_stays_free() {
        for (tables, size, chairs) in [
            (10, [1.2, 1.2, 0.75], 8),
            (6, [1.8, 0.9, 0.75], 4),
            (5, [0.7, 0.7, 0.75], 2),
        ] {
            let spec = hall(tables, size, chairs);
            let l = layout(&spec, LayoutOptions::seeded(1)).expect("laid out");
            assert!(
                validity_problems(&l, &spec).is_empty(),
                "{tables} tables: {:?}",
                validity_problems(&l, &spec)
            );
            let left = relations_unsatisfied(&l.objects, &spec.relations);
            assert!(left.is_empty(), "{tables} tables: {left:?}");
            let floor = l
                .objects
                .iter()
                .find(|o| o.id == "dance floor1")
                .expect("dance floor");
            // CENTER: within a quarter of the room's shorter side of its centre
            let r = floor.position[0].hypot(floor.position[1]);
            let most = 0.25 * l.room.size[0].min(l.room.size[1]);
            assert!(
                r <= most,
                "{tables} tables: the dance floor is {r:.2} m off the middle"
            );
        }
    }
    #[test]
    fn a_room_sized_for_its_tables_round_a_dance_floor_seats_every_table() {
        // the room the estimate gives, no larger: every table and seat clear of the floor
        for (tables, chairs) in [(8, 8), (6, 6), (12, 8)] {
            let mut spec = hall(tables, [1.2, 1.2, 0.75], chairs);
            let need = super::room_for_tables(&spec, [3.0, 3.0]);
            let r = |v: f64| (v * 10.0).ceil() / 10.0;
            spec.room = Some(crate::plan::spec::Room {
                size: [r(need[0]), r(need[1]), 2.8],
            });
            let l = layout(&spec, LayoutOptions::seeded(0)).expect("laid out");
            let left = relations_unsatisfied(&l.objects, &spec.relations);
            assert!(
                left.is_empty(),
                "{tables} tables in {need:?}: {} seats left",
                left.len()
            );
        }
    }
}
