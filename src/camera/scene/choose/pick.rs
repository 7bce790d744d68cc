//! The greedy pick of the render views among the scored candidates (see the parent module's
//! doc): what a view gains for the objects it newly shows and for framing well, and what it
//! loses for each fault a person sees in it. Host-only.
use super::super::faults::{BARE_COVER, BARE_WALL, COPY};
use super::super::repeat::{repeats, Look};
use super::super::views::MAX_OBJECT_SHARE;
use super::super::wall::bare_wall_share;
use super::super::{kind, SceneBox};
use super::{focal, foreground, Candidate, MASS_SHARE};
use crate::camera::scene::ViewStats;
use crate::camera::Camera;

/// How much a view seeing its subject from behind loses per share of the frame that subject
/// fills (see [`back_penalty`]).
const BACK_PER_SHARE: f64 = 12.0;
/// What a view loses for each fault a person sees in it (`faults.rs`): mostly bare, a blocker
/// at the lens, a panel seen edge-on, a near copy of a view already taken; and for a
/// foreground pillar in mid-frame (`stands_mid_frame`). Views below
/// [`BARE_COVER`] lose score steeply on top.
const POOR: f64 = 6.0;
/// What a view gains for framing well ([`ViewStats::framed_well`]): more than any one fault
/// loses, so a poor view that frames well is still taken before one that does not.
const GOOD: f64 = 24.0;
/// A blocker at the lens (`faults.rs`) costs this many [`POOR`]: it hides the room behind it
/// (a shelf's flank or a display case filling the frame's side), worse than a view that is a
/// little bare, yet less than framing well gains.
const BLOCKER_FAULTS: f64 = 2.0;
/// What a near copy of a view already taken loses on top of [`POOR`]: together more than
/// half of [`GOOD`], so a room with one spot to stand on turns to a new direction
/// (`sweep.rs`) rather than repeating a well framed picture.
const COPY_MORE: f64 = 9.0;
/// Up to this share of the frame bare wall costs a view nothing (a room's walls show above its
/// furniture in every picture taken at eye height); beyond it each share costs
/// [`WALL_PER_SHARE`].
const WALL_FREE: f64 = 0.3;
const WALL_PER_SHARE: f64 = 12.0;
/// The share of the views that see the focal object from its front, looking the way the room
/// looks (3 of 8).
const FOCAL_VIEWS: f64 = 0.375;

/// Asked for more views than this, a room gets after its first view only views that frame
/// well and are no near copy of a view taken, and past this many (a row of the contact sheet)
/// only clean ones ([`ViewFaults`](super::super::ViewFaults): not mostly bare, no blocker at
/// the lens, no panel edge-on, no repeat of a view taken (`repeat.rs`: the door and bookcase
/// corner of a living room seen again from a step aside) and no pillar in mid-frame; among
/// those, views seeing their subject from behind, with a mass at the frame's foot (an
/// armchair's back), standing close or with chair backs cut by its foot come last. A room
/// that cannot give the views asked for (a box room with one spot to stand on, a bedroom that
/// is mostly bed, a living room of one sofa group) gets fewer distinct pictures rather than
/// copies, repeats and close-ups. Asked for this many or fewer, a room gets them all.
pub(in crate::camera::scene) const ALWAYS: usize = 4;

/// How much two views show the same: over the objects, the shares of the frame both give an
/// object (the smaller), summed, over the larger of the two views' sums; times how alike their
/// directions are. 1 is the same picture; views of one group from opposite sides are 0.
fn content_alike(a: &Candidate, b: &Candidate) -> f64 {
    let cos = a.dir[0] * b.dir[0] + a.dir[1] * b.dir[1];
    if cos <= 0.0 {
        return 0.0;
    }
    // Both lists are in index order: merge them.
    let (mut both, mut j) = (0.0, 0);
    for &(k, x) in &a.shares {
        while j < b.shares.len() && b.shares[j].0 < k {
            j += 1;
        }
        if let Some(&(_, y)) = b.shares.get(j).filter(|s| s.0 == k) {
            both += x.min(y);
        }
    }
    both / a.total.max(b.total).max(1e-9) * cos
}

/// What a view loses for seeing its subject from behind: more the more of the frame the back
/// fills (a sofa's back across the foreground reads as a wall of upholstery; a small chair back
/// in a wide view does not).
fn back_penalty(stats: &ViewStats) -> f64 {
    let back = (-stats.facing).max(0.0);
    back * (2.0 + BACK_PER_SHARE * stats.largest)
}

/// What a view loses for the share of its frame that is bare wall ([`bare_wall_share`]): from
/// [`WALL_FREE`] on, steeply, and [`POOR`] on top past [`BARE_WALL`] (a fault).
fn wall_penalty(wall: f64) -> f64 {
    WALL_PER_SHARE * (wall - WALL_FREE).max(0.0) + if wall > BARE_WALL { POOR } else { 0.0 }
}

/// True when a view sees its subject from behind (its facing cosine below −0.5, as the framing
/// figure counts back views).
fn is_back(stats: &ViewStats) -> bool {
    stats.facing < -0.5
}

/// What `c` is, for telling repeats (`repeat.rs`).
fn look(c: &Candidate) -> Look<'_> {
    Look {
        dir: c.dir,
        shows: &c.shares,
        backdrop: c.backdrop,
    }
}

/// Greedy choice of `count` candidates (see the module doc).
pub(super) fn pick(scene: &SceneBox, cands: Vec<Candidate>, count: usize) -> Vec<Camera> {
    let n = scene.objects.len();
    // An object's weight grows with its size; the objects of one kind (five trees, eight
    // chairs) share theirs, so a view of a tent is not outweighed by views of trees.
    let weight: Vec<f64> = scene
        .objects
        .iter()
        .map(|o| {
            let same = scene.objects.iter().filter(|p| kind(p) == kind(o)).count();
            (o.size[0] * o.size[1] * o.size[2]).cbrt().max(0.1) / (same as f64).sqrt()
        })
        .collect();
    let fg = foreground(scene);
    let close = super::fore::close(scene);
    let diagonal = scene.room[0].hypot(scene.room[1]);
    let focal = focal(scene);
    // Views that look the way the room looks: the focal object in frame, seen from its front.
    let looks_ahead = |c: &Candidate| {
        focal
            .as_ref()
            .is_some_and(|(f, _)| c.shows[*f].is_some_and(|s| s > 0.5))
    };
    let focal_target = (FOCAL_VIEWS * count as f64).round() as usize;
    let mut focal_taken = 0;
    let mut seen = vec![0usize; n];
    let mut taken: Vec<usize> = vec![];
    let mut walls: Vec<Option<f64>> = vec![None; cands.len()];
    for _ in 0..count.min(cands.len()) {
        // Past [`ALWAYS`] views only clean ones are taken (see there).
        let strict = count > ALWAYS && taken.len() >= ALWAYS;
        // Each candidate's score before the bare wall it shows (costly to measure, so measured
        // only for the candidates that could still win, best first).
        let mut scores: Vec<(usize, f64, usize)> = vec![];
        for (i, c) in cands.iter().enumerate() {
            if taken.contains(&i) {
                continue;
            }
            // Seen from its front an object counts whole; from a side 0.6, from behind 0.2. What
            // faces the focal object counts whole from behind too: seen looking where it looks.
            let fresh: f64 = (0..n)
                .filter_map(|k| c.shows[k].map(|f| (k, f)))
                .map(|(k, f)| {
                    let f = match &focal {
                        Some((_, who)) if who[k] => f.abs(),
                        _ => f,
                    };
                    weight[k] * (0.6 + 0.4 * f) / (1.0 + 2.0 * seen[k] as f64)
                })
                .sum();
            let near = taken
                .iter()
                .map(|&j| {
                    let o = &cands[j];
                    let dp = (c.cam.position[0] - o.cam.position[0])
                        .hypot(c.cam.position[1] - o.cam.position[1]);
                    let cos = c.dir[0] * o.dir[0] + c.dir[1] * o.dir[1];
                    // Close in place and direction, or showing the same things the same way:
                    // a near copy of a view already taken.
                    let alike = content_alike(c, o);
                    let copy = if alike > COPY { 1.0 } else { 0.0 };
                    let alike = ((alike - 0.4) / 0.6).max(0.0);
                    (
                        ((1.0 - (dp / 1.5).min(1.0)) * cos.max(0.0)).max(alike),
                        copy,
                    )
                })
                .fold((0.0f64, 0.0f64), |a, b| (a.0.max(b.0), a.1.max(b.1)));
            let (near, copy) = near;
            // The same subject again, or another of its kind: the views should show the place,
            // not one piece of it from every side.
            let (same, alike) = c.stats.subject.map_or((0, 0), |s| {
                let subjects = taken.iter().filter_map(|&j| cands[j].stats.subject);
                subjects.fold((0, 0), |(a, b), t| {
                    if t == s {
                        (a + 1, b)
                    } else if kind(&scene.objects[t]) == kind(&scene.objects[s]) {
                        (a, b + 1)
                    } else {
                        (a, b)
                    }
                })
            });
            // Framing well counts pieces: a TV on its stand is one thing, not two.
            let good = if c.stats.framed_well() && c.pieces >= 2 && c.piece <= MAX_OBJECT_SHARE {
                GOOD
            } else {
                0.0
            };
            // What a person calls a poor picture (`faults.rs`) loses [`POOR`] a fault: a wide
            // view of the room from its edge is better than any of them.
            let flag = |b: bool| if b { 1.0 } else { 0.0 };
            let (bare, blocker, grazing) = (
                flag(c.stats.covered < BARE_COVER),
                flag(c.blocker > 0.0),
                flag(c.grazing > 0.0),
            );
            // A repeat of a view taken (`repeat.rs`: the same things, or the same corner, the
            // same way) and a pillar in mid-frame are faults a person sees in a set of views.
            let repeat = taken.iter().any(|&j| repeats(look(c), look(&cands[j])));
            let pillar = flag(c.pillar > 0.0);
            let refused = (count > ALWAYS && !taken.is_empty() && (copy > 0.0 || good == 0.0))
                || (strict && (bare + blocker + grazing + pillar > 0.0 || repeat));
            if refused {
                continue;
            }
            let largest = c.piece;
            let over = (largest - MAX_OBJECT_SHARE).max(0.0);
            let score = good + fresh + 0.2 * c.stats.in_view.min(8) as f64 + 2.0 * c.stats.covered
                - 6.0 * near
                - 5.0 * over
                - 3.0 * (largest - 0.2).max(0.0)
                - 6.0 * (fg - c.near).max(0.0)
                - if c.pillar > 0.0 {
                    2.0 * POOR + 10.0 * c.pillar
                } else {
                    0.0
                }
                - if c.cut > 0.0 {
                    POOR + 10.0 * c.cut
                } else {
                    0.0
                }
                - 3.0 * same as f64
                - if same >= 2 { POOR } else { 0.0 }
                - 1.0 * alike as f64
                - back_penalty(&c.stats)
                - 16.0 * (c.occluder - 0.05).max(0.0)
                - 20.0 * (BARE_COVER - c.stats.covered).max(0.0)
                - POOR * (bare + copy + BLOCKER_FAULTS * blocker + grazing)
                - COPY_MORE * copy
                - 10.0 * (c.blocker + c.grazing)
                + 4.0 * (c.reach / diagonal).min(0.6)
                + if focal_taken < focal_target && looks_ahead(c) {
                    3.0
                } else {
                    0.0
                };
            // Past [`ALWAYS`] a view seeing its subject from behind or with a mass at its foot
            // (`fore.rs`) is taken only where no view without them is left, one standing close
            // to what it frames only after those, and one with chair backs cut by the frame's
            // foot last.
            let tier = if strict {
                let soft = is_back(&c.stats) || c.mass > MASS_SHARE;
                4 * usize::from(c.cut > 0.0) + 2 * usize::from(c.near < close) + usize::from(soft)
            } else {
                0
            };
            scores.push((i, score, tier));
        }
        scores.sort_by(|a, b| b.1.total_cmp(&a.1));
        let mut best: Option<(usize, f64)> = None;
        for tier in 0..8 {
            for &(i, score, _) in scores.iter().filter(|s| s.2 == tier) {
                if best.is_some_and(|(_, s)| s >= score) {
                    break;
                }
                let wall = *walls[i].get_or_insert_with(|| bare_wall_share(scene, &cands[i].cam));
                if strict && wall > BARE_WALL {
                    continue;
                }
                let score = score - wall_penalty(wall);
                if best.is_none_or(|(_, s)| score > s) {
                    best = Some((i, score));
                }
            }
            if best.is_some() {
                break;
            }
        }
        let Some((i, _)) = best else { break };
        if looks_ahead(&cands[i]) {
            focal_taken += 1;
        }
        for (s, shown) in seen.iter_mut().zip(&cands[i].shows) {
            if shown.is_some() {
                *s += 1;
            }
        }
        taken.push(i);
    }
    let mut out: Vec<Camera> = taken.into_iter().map(|i| cands[i].cam.clone()).collect();
    for (i, c) in out.iter_mut().enumerate() {
        c.id = i as u32;
        c.img_name = format!("view_{i:04}");
    }
    out
}
