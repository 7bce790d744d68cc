//! Where the functional groups put a subject relative to its placed partner: a seat's slots
//! round a table or along a counter, a nightstand's place beside the bed's head, a ring round a
//! fire, rows before a board, a pupil's seat at the back of a desk turned to the board.
use super::{yaw_facing, Pose, Problem};
use crate::plan::check::Box2;
use crate::plan::spec::RelationKind;

impl Problem {
    /// Poses of a functional-group subject `i` (a seat at a table, a nightstand by a bed, ...)
    /// relative to its placed partner; `None` for the plain relations.
    pub(super) fn group_poses(
        &self,
        i: usize,
        rel: RelationKind,
        (j, pj): (usize, &Pose),
        bj: &Box2,
        placed: &[Option<Pose>],
    ) -> Option<Vec<Pose>> {
        let s = self.inst[i].size;
        let [hw, hd] = bj.half;
        let at = |lx: f64, ly: f64| {
            [
                bj.c[0] + lx * bj.ex[0] + ly * bj.ey[0],
                bj.c[1] + lx * bj.ex[1] + ly * bj.ey[1],
            ]
        };
        let mut out = vec![];
        // Evenly spaced slots along a side of length `len` for things `width` wide.
        let slots = |len: f64, width: f64| -> Vec<f64> {
            let k = ((len + 0.1) / (width + 0.1)).floor().max(1.0) as usize;
            (0..k)
                .map(|m| -0.5 * len + len * (m as f64 + 0.5) / k as f64)
                .collect()
        };
        match rel {
            RelationKind::Around => {
                // The partner's four sides, every seat turned to the table (at its right,
                // local +x, a seat faces -x: yaw + 90). People fill an oblong table's long
                // sides first, its ends only when the long sides cannot hold every seat at it,
                // and spread over the sides: the seats the table's sides take in turn
                // (`sides_of`), evenly along each side (four at a small square table: one a
                // side, centred); without such a spread, each side's slots.
                let seats = self.rels[j]
                    .iter()
                    .filter(|&&(rel, _, subject)| rel == RelationKind::Around && !subject)
                    .count();
                let (long, short) = (hw.max(hd), hw.min(hd));
                let ends_needed = long <= 1.2 * short || seats > 2 * slots(2.0 * long, s[0]).len();
                // (a seat much wider than a table's end, a bench, is left to the slots)
                let spread = self
                    .sides_of(j)
                    .1
                    .filter(|_| !(s[0] > 1.25 * 2.0 * short && s[0] > 0.8))
                    .map(|(count, _)| count);
                for (side, yaw_off) in [(0usize, 180.0), (1, 0.0), (2, 90.0), (3, -90.0)] {
                    let (len, half_across) = if side < 2 {
                        (2.0 * hw, hd)
                    } else {
                        (2.0 * hd, hw)
                    };
                    // (a side with planned seats offers its slots too, and its ends beside a
                    // lone centred seat, where a planned spot is taken or against a wall; the
                    // search's score keeps to the planned ones)
                    let along: Vec<f64> = match spread {
                        Some(count) if count[side] == 0 => continue,
                        Some(count) => (0..count[side])
                            .map(|m| len * ((m as f64 + 0.5) / count[side] as f64 - 0.5))
                            .chain(slots(len, s[0]))
                            .chain(if count[side] == 1 {
                                vec![-0.5 * len, 0.5 * len]
                            } else {
                                vec![]
                            })
                            .collect(),
                        // a seat much wider than a side (a bench at a table's end) sits on
                        // the long sides only
                        None if (!ends_needed && len < 2.0 * long - 1e-9)
                            || (s[0] > 1.25 * len && s[0] > 0.8) =>
                        {
                            continue
                        }
                        None => slots(len, s[0]),
                    };
                    for g in [0.05, 0.15] {
                        let off = half_across + g + 0.5 * s[1];
                        for &t in &along {
                            let c = match side {
                                0 => at(t, off),
                                1 => at(t, -off),
                                2 => at(off, t),
                                _ => at(-off, t),
                            };
                            out.push(Pose {
                                c,
                                yaw: pj.yaw + yaw_off,
                                z: 0.0,
                            });
                        }
                    }
                }
            }
            RelationKind::At => {
                // A row along the partner's front, facing it, in line with the seats already
                // at it (stools at a bar in one straight row).
                let mut gaps = vec![0.02, 0.1, 0.2];
                let mate = self.rels[j]
                    .iter()
                    .filter(|&&(rel, k, subject)| rel == RelationKind::At && !subject && k != i)
                    .find_map(|&(_, k, _)| placed[k].map(|q| (k, q)));
                if let Some((k, q)) = mate {
                    let d = [q.c[0] - bj.c[0], q.c[1] - bj.c[1]];
                    let g = d[0] * bj.ey[0] + d[1] * bj.ey[1] - hd - 0.5 * self.inst[k].size[1];
                    if (0.0..=0.3).contains(&g) {
                        gaps = vec![g];
                    }
                }
                for g in gaps {
                    for t in slots(2.0 * hw, s[0]) {
                        out.push(Pose {
                            c: at(t, hd + g + 0.5 * s[1]),
                            yaw: pj.yaw + 180.0,
                            z: 0.0,
                        });
                    }
                }
            }
            RelationKind::AtBack => {
                // Along the partner's back, turned as it is; a seat against the wall (a
                // head table's) in line with the wall.
                let wide = super::problem::AT_BACK_GAP;
                let gaps: &[f64] = if self.inst[i].anchor == crate::plan::spec::Anchor::Side {
                    &[wide]
                } else {
                    &[0.05, wide]
                };
                for &g in gaps {
                    for t in slots(2.0 * hw, s[0]) {
                        out.push(Pose {
                            c: at(t, -hd - g - 0.5 * s[1]),
                            yaw: pj.yaw,
                            z: 0.0,
                        });
                    }
                }
            }
            RelationKind::Before => {
                // Before the partner, turned as it is, a seat's room and more from it; centred
                // or toward one end.
                let (g0, g1) = crate::plan::check::BEFORE_GAP;
                let end = (hw - 0.5 * s[0]).max(0.0);
                for g in [g0 + 0.05, g0 + 0.2, g0 + 0.4, 0.5 * (g0 + g1)] {
                    for t in [0.0, -0.5 * end, 0.5 * end, -end, end] {
                        out.push(Pose {
                            c: at(t, hd + g + 0.5 * s[1]),
                            yaw: pj.yaw,
                            z: 0.0,
                        });
                    }
                }
            }
            RelationKind::Flank => {
                // Left and right of the head end, backs in line, turned as the partner.
                for side in [-1.0, 1.0] {
                    for g in [0.02, 0.08] {
                        out.push(Pose {
                            c: at(side * (hw + g + 0.5 * s[0]), -hd + 0.5 * s[1]),
                            yaw: pj.yaw,
                            z: 0.0,
                        });
                    }
                }
            }
            RelationKind::Circle => {
                // A ring round the centre, each member facing it: seats close in, big things
                // (tents) beyond them; spread evenly from the members already placed.
                out.extend(self.ring_poses(i, j, pj, placed));
                let ext = 0.5 * s[0].max(s[1]);
                for g in Self::ring_gaps(s) {
                    let r = hw.max(hd) + g + ext;
                    for k in 0..16 {
                        let a = k as f64 * std::f64::consts::TAU / 16.0;
                        let c = [pj.c[0] + r * a.cos(), pj.c[1] + r * a.sin()];
                        let yaw = yaw_facing([pj.c[0] - c[0], pj.c[1] - c[1]]);
                        out.push(Pose { c, yaw, z: 0.0 });
                    }
                }
            }
            RelationKind::Row => {
                // A lattice of rows in front of the partner, turned toward it.
                let pitch_x = s[0] + 0.5;
                let pitch_y = s[1] + 1.1;
                let [w, d, _] = self.room;
                let reach = w.max(d);
                let n_x = (reach / pitch_x).ceil() as i64;
                for row in 0..((reach / pitch_y).ceil() as i64) {
                    let ly = hd + 1.0 + 0.5 * s[1] + row as f64 * pitch_y;
                    for k in -n_x..=n_x {
                        out.push(Pose {
                            c: at(k as f64 * pitch_x, ly),
                            yaw: pj.yaw + 180.0,
                            z: 0.0,
                        });
                    }
                }
            }
            RelationKind::Under => {
                // Beneath the partner's footprint: centred, or one of a pair side by side
                // (loungers under a parasol), turned as it is or about.
                for lx in [0.0, -0.5 * s[0] - 0.05, 0.5 * s[0] + 0.05] {
                    for yaw in [pj.yaw, pj.yaw + 180.0] {
                        out.push(Pose {
                            c: at(lx, 0.0),
                            yaw,
                            z: 0.0,
                        });
                    }
                }
            }
            RelationKind::Over if self.used_from_front(i) => {
                // A thing someone sits or stands in front of (a computer with its chair) stands
                // at the front edge of its support, side by side with the others there.
                let ly = hd - 0.5 * s[1] - 0.02;
                for t in slots(2.0 * hw, s[0]) {
                    out.push(Pose {
                        c: at(t, ly),
                        yaw: pj.yaw,
                        z: bj.z1,
                    });
                }
            }
            _ => return None,
        }
        Some(out)
    }
}

impl Problem {
    /// Whether seat `i` at box `b` stands off the spots its table `t` (box `bt`) plans for its
    /// seats (`sides_of`: one a side, centred, at a small table for four); false when the
    /// table plans none.
    pub(super) fn off_planned_spot(&self, i: usize, b: &Box2, t: usize, bt: &Box2) -> bool {
        let Some((count, _)) = self.sides_of(t).1 else {
            return false;
        };
        let s = self.inst[i].size;
        let short = bt.half[0].min(bt.half[1]);
        if s[0] > 1.25 * 2.0 * short && s[0] > 0.8 {
            return false;
        }
        let l = bt.local(b.c);
        let [hw, hd] = bt.half;
        // the side it stands at, and where along it
        let (side, along, len) = if l[1].abs() - hd > l[0].abs() - hw {
            (if l[1] > 0.0 { 0 } else { 1 }, l[0], 2.0 * hw)
        } else {
            (if l[0] > 0.0 { 2 } else { 3 }, l[1], 2.0 * hd)
        };
        let n = count[side];
        !(0..n).any(|m| (len * ((m as f64 + 0.5) / n as f64 - 0.5) - along).abs() < 0.05)
    }

    /// Whether something is in FRONT of or AT instance `i` (a chair before a computer).
    fn used_from_front(&self, i: usize) -> bool {
        self.rels[i].iter().any(|&(rel, _, subject)| {
            !subject && matches!(rel, RelationKind::Front | RelationKind::At)
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::check::Box2;
    use crate::plan::gcp::{layout, LayoutOptions};
    use crate::plan::spec::SceneSpec;

    /// Where seat `s` sits at table `t`: on one of its long sides (true) or at an end.
    fn on_long_side(t: &Box2, s: &Box2) -> bool {
        let d = [s.c[0] - t.c[0], s.c[1] - t.c[1]];
        let along = d[0] * t.ex[0] + d[1] * t.ex[1];
        let across = d[0] * t.ey[0] + d[1] * t.ey[1];
        let long_x = t.half[0] >= t.half[1];
        (across.abs() > along.abs()) == long_x
    }

    #[test]
    fn seats_fill_an_oblong_tables_long_sides_before_its_ends() {
        let spec = |chairs: u32| -> SceneSpec {
            let rels: Vec<String> = (1..=chairs)
                .map(|k| {
                    format!(r#"{{"subject":"dining chair{k}","relation":"AROUND","object":"dining table1"}}"#)
                })
                .collect();
            let text = format!(
                r#"{{"scene_type":"indoor","scene_text":"t","room":{{"size":[5.0,4.0,2.8]}},
                "anchors":{{"dining table1":"CENTER"}},"objects":{{
                "dining table":{{"number":1,"size":[1.8,0.9,0.75],"description":"d"}},
                "dining chair":{{"number":{chairs},"size":[0.5,0.5,0.9],"description":"d"}}}},
                "relations":[{}]}}"#,
                rels.join(",")
            );
            serde_json::from_str(&text).expect("spec")
        };
        for (chairs, want_ends) in [(2u32, 0usize), (6, 0), (8, 2)] {
            for seed in 0..3 {
                let l = layout(&spec(chairs), LayoutOptions::seeded(seed)).expect("laid out");
                let get =
                    |id: &str| Box2::of(l.objects.iter().find(|o| o.id == id).expect("placed"));
                let t = get("dining table1");
                let ends = (1..=chairs)
                    .filter(|k| !on_long_side(&t, &get(&format!("dining chair{k}"))))
                    .count();
                assert!(
                    ends <= want_ends,
                    "{chairs} chairs, seed {seed}: {ends} at the ends (at most {want_ends})"
                );
            }
        }
    }

    #[test]
    fn four_seats_at_a_small_square_table_sit_one_a_side_centred() {
        let rels: Vec<String> = (1..=4)
            .map(|k| {
                format!(
                    r#"{{"subject":"cafe chair{k}","relation":"AROUND","object":"cafe table1"}}"#
                )
            })
            .collect();
        let text = format!(
            r#"{{"scene_type":"indoor","scene_text":"t","room":{{"size":[4.0,4.0,2.8]}},
            "objects":{{"cafe table":{{"number":1,"size":[1.2,1.2,0.75],"description":"d"}},
            "cafe chair":{{"number":4,"size":[0.45,0.5,0.85],"description":"d"}}}},
            "relations":[{}]}}"#,
            rels.join(",")
        );
        let spec: SceneSpec = serde_json::from_str(&text).expect("spec");
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).expect("laid out");
            let get = |id: &str| Box2::of(l.objects.iter().find(|o| o.id == id).expect("placed"));
            let t = get("cafe table1");
            let mut sides = vec![];
            for k in 1..=4 {
                let p = t.local(get(&format!("cafe chair{k}")).c);
                let (across, along) = if p[0].abs() > p[1].abs() {
                    (p[0], p[1])
                } else {
                    (p[1], p[0])
                };
                assert!(
                    along.abs() < 0.05,
                    "seed {seed}: chair{k} off centre by {along:.2}"
                );
                sides.push((p[0].abs() > p[1].abs(), across > 0.0));
            }
            sides.sort();
            sides.dedup();
            assert_eq!(sides.len(), 4, "seed {seed}: two seats on one side");
        }
    }
}
