//! One seeded attempt: the placement order, each instance's best pose, the fallback when none
//! is free.
use super::score::is_group;
use super::{Pose, Problem, WALL_MARGIN};
use crate::plan::check::{penetration, wall_distances, Box2};
use crate::plan::spec::{Anchor, Layout, PlacedBy, PlacedObject, RelationKind, Room, SceneSpec};
use rand::Rng;
use std::collections::VecDeque;

/// Placement order: a CENTER thing that nothing relates to first (a dance floor keeps the
/// middle), then breadth-first from the most connected instance of each component (ties:
/// wall-anchored, then larger), OVER subjects after their support.
pub(super) fn order(prob: &Problem, rng: &mut impl Rng) -> Vec<usize> {
    let n = prob.inst.len();
    // How much an instance holds others in place: being placed by a partner (a nightstand at
    // its bed, a coffee table in front of its sofa) and a support's load (a lamp on that
    // nightstand) do not count, so a partner is placed before what is placed by it; on ties,
    // what no partner places goes first.
    let placed_by = |rel: RelationKind| {
        is_group(rel)
            || matches!(
                rel,
                RelationKind::Front
                    | RelationKind::Behind
                    | RelationKind::Left
                    | RelationKind::Right
                    | RelationKind::Next
            )
    };
    let key = |i: usize| {
        let a = &prob.inst[i];
        // (a counter staff stand behind takes its wall as a wall thing does)
        let wall =
            (matches!(a.anchor, Anchor::Side | Anchor::Corner) || prob.staff[i] > 0.0) as u32;
        let area = a.size[0] * a.size[1];
        let holds = prob.rels[i]
            .iter()
            .filter(|&&(rel, _, subject)| {
                if subject {
                    !placed_by(rel)
                } else {
                    rel != RelationKind::Over
                }
            })
            .count();
        let free = !prob.rels[i]
            .iter()
            .any(|&(rel, _, subject)| subject && placed_by(rel));
        if prob.largest_first {
            return (false, 0, false, 0, (area * 1000.0) as u64);
        }
        // a thing the middle is kept for and nothing else places (a dance floor) takes it first
        let middle = a.anchor == Anchor::Center && prob.rels[i].is_empty();
        (middle, holds, free, wall, (area * 1000.0) as u64)
    };
    let mut done = vec![false; n];
    let mut out = vec![];
    loop {
        let start = (0..n)
            .filter(|&i| !done[i])
            .max_by_key(|&i| (key(i), std::cmp::Reverse(i)));
        let Some(start) = start else { break };
        let mut q = VecDeque::from([start]);
        done[start] = true;
        while let Some(i) = q.pop_front() {
            out.push(i);
            let mut next: Vec<usize> = prob.rels[i]
                .iter()
                .map(|r| r.1)
                .filter(|&j| !done[j])
                .collect();
            next.sort();
            next.dedup();
            // Ties broken by the key, then at random (restarts see different orders).
            // (One random draw per entry: a key drawn afresh at each comparison is no order.)
            let mut keyed: Vec<_> = next
                .into_iter()
                .map(|j| (std::cmp::Reverse(key(j)), rng.gen::<u32>(), j))
                .collect();
            keyed.sort();
            for (_, _, j) in keyed {
                done[j] = true;
                q.push_back(j);
            }
        }
    }
    // OVER subjects after their supports, and what a thing places after it when it waits for
    // its support (banners behind a throne after the throne on its dais).
    let mut rank = vec![0; n];
    for (k, &i) in out.iter().enumerate() {
        rank[i] = k;
    }
    // (where the two wait for each other, a thing on a support placed by another thing, only
    // supports are waited for)
    let mut fixed: Vec<usize> = vec![];
    let mut waiting: Vec<usize> = out;
    let mut placers = true;
    for _ in 0..2 * n + 2 {
        let mut rest = vec![];
        for &i in &waiting {
            let ready = prob.rels[i].iter().all(|&(rel, j, subject)| {
                let waits = subject
                    && (rel == RelationKind::Over
                        || (placers && placed_by(rel) && rank[j] < rank[i]));
                !waits || fixed.contains(&j)
            }) && prob.above[i].is_none_or(|j| fixed.contains(&j));
            if ready {
                fixed.push(i);
            } else {
                rest.push(i);
            }
        }
        if rest.len() == waiting.len() && placers && !rest.is_empty() {
            placers = false;
        } else if rest.is_empty() || rest.len() == waiting.len() {
            fixed.extend(rest);
            break;
        }
        waiting = rest;
    }
    fixed
}

pub(super) fn attempt_layout(
    prob: &Problem,
    spec: &SceneSpec,
    room: Room,
    seed: u64,
    rng: &mut rand_chacha::ChaCha8Rng,
    pinned: &[Option<Pose>],
) -> Layout {
    let n = prob.inst.len();
    let mut placed: Vec<Option<Pose>> = pinned.to_vec();
    let mut by: Vec<PlacedBy> = vec![PlacedBy::Constraint; n];
    // things hung from the ceiling last, where what stands below them puts them
    let (mut seq, hung): (Vec<usize>, Vec<usize>) = order(prob, rng)
        .into_iter()
        .partition(|&i| !prob.ceiling[i]);
    seq.extend(hung);
    for i in seq {
        if placed[i].is_some() {
            continue;
        }
        let boxes: Vec<Option<(Box2, [f64; 4])>> = placed
            .iter()
            .enumerate()
            .map(|(j, p)| {
                p.map(|p| {
                    let b = prob.boxed(j, &p);
                    (b, b.aabb())
                })
            })
            .collect();
        let hang = prob
            .ceiling_poses(i, &placed)
            .into_iter()
            .find(|p| prob.evaluate(i, p, &placed, &boxes, 0.0).0);
        if let Some(p) = hang {
            placed[i] = Some(p);
            continue;
        }
        let (group, cands) = prob.candidates(i, &placed);
        let mut best: Option<(f64, Pose, bool)> = None;
        let mut search = |poses: &[Pose], best: &mut Option<(f64, Pose, bool)>| {
            for p in poses {
                let (valid, ok, total, score) =
                    prob.evaluate(i, p, &placed, &boxes, rng.gen::<f64>() * 3.0);
                if valid && best.as_ref().is_none_or(|b| score > b.0) {
                    *best = Some((score, *p, ok == total));
                }
            }
        };
        search(&group, &mut best);
        if !best.as_ref().is_some_and(|b| b.2) {
            search(&cands, &mut best);
        }
        let (pose, all_ok) = match best {
            Some((_, p, ok)) => (p, ok),
            None => (fallback_pose(prob, i, &placed, rng), false),
        };
        placed[i] = Some(pose);
        if !all_ok {
            by[i] = PlacedBy::Fallback;
        }
    }
    let objects: Vec<PlacedObject> = prob
        .inst
        .iter()
        .enumerate()
        .map(|(i, inst)| {
            let p = placed[i].expect("every instance placed");
            let mut yaw = p.yaw % 360.0;
            if yaw > 180.0 {
                yaw -= 360.0;
            }
            if yaw <= -180.0 {
                yaw += 360.0;
            }
            PlacedObject {
                id: inst.id.clone(),
                category: inst.category.clone(),
                size: inst.size,
                position: [p.c[0], p.c[1], p.z],
                yaw,
                anchor: inst.anchor,
                placed_by: by[i],
            }
        })
        .collect();
    let unsatisfied = crate::plan::check::relations_unsatisfied(&objects, &spec.relations);
    Layout {
        scene_type: spec.scene_type,
        room,
        seed,
        objects,
        unsatisfied,
        unsatisfied_anchors: vec![],
        openings: vec![],
    }
}

/// The least-colliding pose inside the room when nothing is free (the room is overfull).
pub(super) fn fallback_pose(
    prob: &Problem,
    i: usize,
    placed: &[Option<Pose>],
    rng: &mut rand_chacha::ChaCha8Rng,
) -> Pose {
    let [w, d, _] = prob.room;
    let s = prob.inst[i].size;
    let mut best = (
        f64::INFINITY,
        Pose {
            c: [0.0, 0.0],
            yaw: 0.0,
            z: 0.0,
        },
    );
    // a thing hung on a wall stays on a wall, at its height
    let z = prob.hung[i].unwrap_or(0.0);
    let on_wall: Vec<Pose> = if prob.wall_hung[i] {
        prob.all_candidates(i, placed)
            .into_iter()
            .filter(|p| {
                let wd = wall_distances(&prob.boxed(i, p), prob.room);
                wd.iter().all(|&v| v >= -1e-9) && wd.iter().any(|&v| v <= WALL_MARGIN + 0.03)
            })
            .collect()
    } else {
        vec![]
    };
    let random = (0..2000).map(|_| {
        let yaw = [0.0, 90.0][rng.gen_range(0..2)];
        let (ex, ey) = if yaw == 0.0 {
            (s[0], s[1])
        } else {
            (s[1], s[0])
        };
        let x = rng.gen_range(-0.5 * (w - ex).max(0.0)..=0.5 * (w - ex).max(0.0));
        let y = rng.gen_range(-0.5 * (d - ey).max(0.0)..=0.5 * (d - ey).max(0.0));
        Pose { c: [x, y], yaw, z }
    });
    let poses: Vec<Pose> = if on_wall.is_empty() {
        random.collect()
    } else {
        on_wall
    };
    for p in poses {
        let b = prob.boxed(i, &p);
        let cost: f64 = placed
            .iter()
            .enumerate()
            .filter_map(|(j, q)| q.map(|q| (j, q)))
            .filter(|(j, _)| !prob.is_stacked(i, *j))
            .map(|(j, q)| penetration(&b, &prob.boxed(j, &q)).max(0.0))
            .sum::<f64>()
            + prob
                .zones
                .iter()
                .map(|z| penetration(&b, z).max(0.0))
                .sum::<f64>();
        if cost < best.0 {
            best = (cost, p);
        }
    }
    best.1
}
