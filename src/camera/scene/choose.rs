//! The render views: the pictures a user opens first (`renders/`), chosen by what they show.
//!
//! Candidates stand at eye height on loops along the room's walls (outdoors: the ground's edge,
//! the loops further apart on a wide ground; indoors also one with the back to the wall),
//! every valid viewpoint 0.25 m apart, each looking at
//! an object, a pair of neighbouring objects or the room centre at a gentle downward pitch
//! (steeper in a small room, where the furniture stands close), through a lens that widens in a
//! small room ([`view_fov`]); indoors each spot also turns on the spot to evenly spaced
//! directions (`sweep.rs`), so a room with one spot to stand on still has several pictures. Each candidate is measured from the
//! layout boxes alone (occlusion ignored, see [`view_stats`]); the views are then picked
//! greedily: first those that frame well ([`ViewStats::framed_well`], counting an object and
//! what rests on it as one piece, so a TV on its stand is no wide view, and a piece cut in half
//! by the frame's side as none, so a floor lamp at the edge of a TV stand's picture is no
//! second piece), each adding the most
//! objects not yet shown (an object seen from its front counts more than one seen from behind),
//! with a subject no other view has had (nor, less so, another of its kind), seen from its front
//! rather than its back, with no object close in the foreground (nor standing in the frame's
//! middle like a pillar: a floor lamp before the sofa, nor cut by the frame's bottom: chair
//! backs before the sideboard), and far (in place or direction) from the views already taken
//! (a near copy costs more than framing well gains). Past the first few views only clean views
//! that frame well are taken: a small room gets fewer pictures rather than near copies, repeats
//! of a corner already shown (`repeat.rs`), views past a wardrobe at the lens or close-ups of a
//! bed; and among them first those that see their subject from the front with no mass at the
//! frame's foot (`fore.rs`: an armchair's back across a hotel lobby's view). Host-only.
use super::faults::{blocker_share, footprint_distance, grazing_share, BARE_COVER};
use super::repeat::{backdrop, sparse};
use super::views::FLAT;
use super::views::{facing, hidden_share, in_frame, in_frame_within, view_stats, ViewStats};
use super::{camera, kind, valid_viewpoint, ObjectBox, SceneBox, ROOM_MARGIN, SCENE_FOV_X};
use crate::camera::Camera;
use crate::plan::spec::SceneType;

/// Steepest downward pitch of a render view (degrees).
const MAX_PITCH_DEG: f64 = 14.0;
/// The steepest pitch in a room [`SMALL_ROOM`] metres or less across: there the furniture
/// stands within 1–2 m, and looked at level from eye height it fills the frame's lower third
/// under a band of bare wall; a person looks down on it (as a photographer of a box room
/// does). Measured on the framing figure's small rooms: 14° left 35 of 160 views mostly bare,
/// 26° 18; steeper (34°) looks down on the floor more than into the room.
const SMALL_ROOM_PITCH_DEG: f64 = 26.0;
/// Spacing of the candidate positions along the walls (metres); wider on a large ground, so
/// there are at most [`MAX_LOOP_POINTS`] a loop.
const STEP: f64 = 0.25;
const MAX_LOOP_POINTS: f64 = 160.0;
/// An object in the frame nearer than this (horizontal metres from the camera to its footprint)
/// is foreground: a lampshade or chair back at that distance hides the room behind it, so a view
/// loses score the nearer it stands. In a small room it is at most [`FOREGROUND_PER_SIDE`] of
/// the room's short side, since nothing there stands further.
const FOREGROUND: f64 = 1.6;
const FOREGROUND_PER_SIDE: f64 = 0.4;
/// The widest lens of a render view (horizontal, radians; 77°, a real-estate photographer's wide
/// angle), used in a room [`SMALL_ROOM`] metres or less across; from [`LARGE_ROOM`] on the lens
/// is the scene cameras' [`SCENE_FOV_X`] (55°), and between the two it widens linearly.
const WIDE_FOV_X: f64 = 1.35;
const SMALL_ROOM: f64 = 3.0;
/// The lens of the views from a room's corners to its centre (horizontal, radians; 90°).
const FILL_FOV_X: f64 = std::f64::consts::FRAC_PI_2;
const LARGE_ROOM: f64 = 5.0;

/// Eye height of the render views: 1.5 m, lower in low rooms.
pub fn eye_height(scene: &SceneBox) -> f64 {
    let top = match scene.scene_type {
        SceneType::Indoor => scene.room[2],
        SceneType::Outdoor => scene.room[2].min(4.0),
    };
    1.5f64.min(0.55 * top).max(ROOM_MARGIN)
}

/// The horizontal field of view of the render views of `scene`: wider in a small room, where a
/// camera cannot step back far enough to frame more than one piece through the usual lens.
pub fn view_fov(scene: &SceneBox) -> f64 {
    match scene.scene_type {
        SceneType::Outdoor => SCENE_FOV_X,
        SceneType::Indoor => SCENE_FOV_X + smallness(scene) * (WIDE_FOV_X - SCENE_FOV_X),
    }
}

/// How small `scene` is for its views: 0 from [`LARGE_ROOM`] across on (and outdoors), 1 at
/// [`SMALL_ROOM`] or less, linear between.
fn smallness(scene: &SceneBox) -> f64 {
    match scene.scene_type {
        SceneType::Outdoor => 0.0,
        SceneType::Indoor => {
            let side = scene.room[0].min(scene.room[1]);
            ((LARGE_ROOM - side) / (LARGE_ROOM - SMALL_ROOM)).clamp(0.0, 1.0)
        }
    }
}

/// The steepest downward pitch of the render views of `scene` (degrees): [`MAX_PITCH_DEG`],
/// steeper in a small room up to [`SMALL_ROOM_PITCH_DEG`].
fn view_pitch(scene: &SceneBox) -> f64 {
    MAX_PITCH_DEG + smallness(scene) * (SMALL_ROOM_PITCH_DEG - MAX_PITCH_DEG)
}

/// The foreground distance of `scene` (see [`FOREGROUND`]).
fn foreground(scene: &SceneBox) -> f64 {
    match scene.scene_type {
        SceneType::Outdoor => FOREGROUND,
        SceneType::Indoor => FOREGROUND.min(FOREGROUND_PER_SIDE * scene.room[0].min(scene.room[1])),
    }
}

/// A nearer object covering more than this share of a larger one's silhouette hides it.
const HIDES: f64 = 0.2;

/// The volume of an object's box.
fn volume(o: &ObjectBox) -> f64 {
    o.size[0] * o.size[1] * o.size[2]
}

/// Half the width of a person standing to take a picture (metres): a render view's spot on the
/// floor is at least this far from every object standing on the floor, so no view is taken
/// from on top of a kitchen island or a bed.
const BODY: f64 = 0.2;
/// Objects whose bottom is at most this high stand on the floor (a wall-hung board does not).
const ON_FLOOR: f64 = 0.3;

/// True when a person can stand at `p`'s spot on the floor (see [`BODY`]).
fn stands(scene: &SceneBox, p: [f64; 3]) -> bool {
    !scene
        .objects
        .iter()
        .any(|o| o.size[2] > FLAT && o.position[2] <= ON_FLOOR && footprint_distance(o, p) < BODY)
}

/// An object that several others face (the board pupils' desks face, the TV a sofa faces, the
/// stage the audience faces) is the room's focal object: the one faced by the most, when at
/// least [`FOCAL_MIN`] face it. Something faces an object when the object's centre lies within
/// [`FOCAL_CONE_DEG`] of its front's direction.
const FOCAL_MIN: usize = 3;
const FOCAL_CONE_DEG: f64 = 35.0;
/// The focal object of `scene` (see [`FOCAL_MIN`]) and which objects face it.
pub(crate) fn focal(scene: &SceneBox) -> Option<(usize, Vec<bool>)> {
    let cone = FOCAL_CONE_DEG.to_radians().cos();
    let faces = |a: &ObjectBox, t: &ObjectBox| {
        let (s, c) = a.yaw.to_radians().sin_cos();
        let (dx, dy) = (t.position[0] - a.position[0], t.position[1] - a.position[1]);
        let d = dx.hypot(dy);
        d > 1e-6 && (-s * dx + c * dy) / d >= cone
    };
    let (best, n) = (0..scene.objects.len())
        .filter(|t| scene.objects[*t].size[2] > FLAT)
        .map(|t| {
            let o = &scene.objects[t];
            let n = scene
                .objects
                .iter()
                .filter(|a| a.id != o.id && kind(a) != kind(o) && a.size[2] > FLAT && faces(a, o))
                .count();
            (t, n)
        })
        .max_by_key(|(t, n)| (*n, usize::MAX - t))?;
    if n < FOCAL_MIN {
        return None;
    }
    let t = &scene.objects[best];
    let who = scene
        .objects
        .iter()
        .map(|a| a.id != t.id && kind(a) != kind(t) && faces(a, t))
        .collect();
    Some((best, who))
}

/// Valid points along the loop `inset` inside the room's (ground's) edge.
fn wall_loop(scene: &SceneBox, inset: f64, z: f64) -> Vec<[f64; 3]> {
    let [hx, hy] = scene.half();
    let (ax, ay) = ((hx - inset).max(0.05), (hy - inset).max(0.05));
    let per = 4.0 * (ax + ay);
    let n = ((per / STEP).min(MAX_LOOP_POINTS) as usize).max(8);
    (0..n)
        .map(|i| {
            let mut s = per * i as f64 / n as f64;
            let side = [2.0 * ax, 2.0 * ay, 2.0 * ax, 2.0 * ay];
            let mut k = 0;
            while k < 3 && s > side[k] {
                s -= side[k];
                k += 1;
            }
            match k {
                0 => [-ax + s, -ay, z],
                1 => [ax, -ay + s, z],
                2 => [ax - s, ay, z],
                _ => [-ax, ay - s, z],
            }
        })
        .filter(|p| valid_viewpoint(scene, *p) && stands(scene, *p))
        .collect()
}

/// One shot to measure: the eye, the spot it looks at, the target it aims at (its index in
/// the list of targets, 0 the room), the lens, and whether it is a turn on the spot
/// ([`sweep::turns`]).
type Shot = ([f64; 3], [f64; 3], usize, f64, bool);

/// One scored candidate.
struct Candidate {
    cam: Camera,
    stats: ViewStats,
    /// For each object: `None` when its centre is out of frame, else how much of its front the
    /// view sees ([`facing`]).
    shows: Vec<Option<f64>>,
    dir: [f64; 2],
    /// Horizontal distance to the nearest object covering part of the frame (metres,
    /// [`fore::nearest`]).
    near: f64,
    /// The largest share of the frame an object that is not looked at covers from in front of
    /// what is (a bush before the fountain, a lampshade before the sofa).
    occluder: f64,
    /// Horizontal distance from the camera to the spot it looks at (metres).
    reach: f64,
    /// The share of the frame of a blocker close to the lens and of panels seen edge-on
    /// ([`blocker_share`], [`grazing_share`]).
    blocker: f64,
    grazing: f64,
    /// The pieces in view and the largest share of the frame one covers ([`pieces`]).
    pieces: usize,
    piece: f64,
    /// The share of the frame of a foreground object standing in it like a pillar, before the
    /// room ([`stands_mid_frame`]): a floor lamp splitting the picture. Its box's share is
    /// small (a pole and a shade), what it does to the picture is not.
    pillar: f64,
    /// The largest share of the frame of a foreground object other than the subject that the
    /// frame's bottom edge cuts ([`fore::cut_at_foot_objects`]): the backs of the chairs at a
    /// dining table across the bottom of a view of the sideboard.
    cut: f64,
    /// The share of the frame of a mass at its foot ([`fore::foot_mass`]): an armchair's back
    /// or a cart cut by the frame's bottom edge before the room.
    mass: f64,
    /// What the view is named by, for telling repeats ([`backdrop`]).
    backdrop: Option<usize>,
    /// The objects in frame (index, share of the frame it covers), in index order, and the sum
    /// of their shares.
    shares: Vec<(usize, f64)>,
    total: f64,
}

/// Up to `count` render views of `scene` chosen by what they show (see the module doc), named
/// `view_0000`…; every camera is a valid viewpoint. Asked for more than four, a
/// room that cannot give that many distinct, clean views that frame well gets fewer. An empty scene gets views of the room from
/// its edge towards the centre.
pub fn render_views(scene: &SceneBox, count: usize, width: u32, height: u32) -> Vec<Camera> {
    let eye = eye_height(scene);
    let fov = view_fov(scene);
    let mut positions = vec![];
    let short = scene.room[0].min(scene.room[1]);
    let (edge, apart) = match scene.scene_type {
        SceneType::Indoor => (ROOM_MARGIN + 0.05, 0.6),
        // On open ground the loops spread inwards with its size, so trees along the edge are
        // not always in the foreground.
        SceneType::Outdoor => (ROOM_MARGIN + 0.05 + 0.05 * short, (0.1 * short).max(0.6)),
    };
    for k in 0..3 {
        positions.extend(wall_loop(scene, edge + apart * k as f64, eye));
    }
    if scene.scene_type == SceneType::Indoor {
        // Stepping back to the wall: in a small room the few centimetres behind the first loop
        // take a second piece into the frame.
        positions.extend(wall_loop(scene, ROOM_MARGIN, eye));
    }
    if positions.is_empty() {
        positions.extend(super::nearest_valid(scene, [0.0, 0.0, eye]));
    }
    // Each target: the spot looked at and the objects it is the centre of.
    let mut targets: Vec<([f64; 3], Vec<usize>)> = vec![([0.0, 0.0, 0.0], vec![])];
    let centre = |o: &ObjectBox| {
        [
            o.position[0],
            o.position[1],
            o.position[2] + 0.5 * o.size[2],
        ]
    };
    for (i, a) in scene.objects.iter().enumerate() {
        targets.push((centre(a), vec![i]));
        for (j, b) in scene.objects.iter().enumerate().skip(i + 1) {
            let (ca, cb) = (centre(a), centre(b));
            if (ca[0] - cb[0]).hypot(ca[1] - cb[1]) < 3.0 {
                targets.push(([0, 1, 2].map(|k| 0.5 * (ca[k] + cb[k])), vec![i, j]));
            }
        }
    }
    thin_shots(&mut positions, &mut targets, scene.objects.len());
    let max_pitch = view_pitch(scene).to_radians().tan();
    // Every position looks at every target; the room's corners also look at its centre through
    // the widest lens: the views that fill in where a small room runs short of good ones.
    let mut shots: Vec<Shot> = positions
        .iter()
        .flat_map(|p| {
            let targets = &targets;
            (0..targets.len()).map(move |t| (*p, targets[t].0, t, fov, false))
        })
        .collect();
    // Each spot also turns on the spot (`sweep::turns`): where a small room has one or two
    // spots to stand on, another view from there is another direction, not a copy.
    shots.extend(sweep::turns(scene, &positions, fov));
    if scene.scene_type == SceneType::Indoor {
        let [hx, hy] = scene.half();
        for inset in [edge, edge + apart] {
            for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let p = [sx * (hx - inset), sy * (hy - inset), eye];
                if valid_viewpoint(scene, p) && stands(scene, p) {
                    shots.push((p, targets[0].0, 0, fov.max(FILL_FOV_X), false));
                }
            }
        }
    }
    let piece = pieces::piece_of(scene);
    let focal_object = focal(scene).map(|f| f.0);
    use rayon::prelude::*;
    let cands: Vec<Candidate> = shots
        .into_par_iter()
        .filter_map(|(p, t, ti, fov, turned)| {
            let (t, looked_at) = (&t, &targets[ti].1);
            let p = &p;
            let d = (t[0] - p[0]).hypot(t[1] - p[1]);
            if d < 0.8 {
                return None;
            }
            // Look at the target's spot, no steeper than MAX_PITCH_DEG, never upwards.
            let tz = t[2].max(eye - max_pitch * d).min(eye);
            let cam = camera(*p, [t[0], t[1], tz], [0.0, 0.0, 1.0], width, height, fov);
            let stats = view_stats(scene, &cam);
            // A turn is a view only where it frames the room ([`sweep`]).
            if turned && !(stats.framed_well() && stats.covered >= BARE_COVER) {
                return None;
            }
            let shows = scene
                .objects
                .iter()
                .map(|o| in_frame(&cam, o).then(|| facing(o, *p)))
                .collect();
            let dir = [(t[0] - p[0]) / d, (t[1] - p[1]) / d];
            // How close the nearest object in the frame stands: a foreground lampshade or chair
            // back hides the room even under the share limit.
            let (mut occluder, mut pillar) = (0.0f64, 0.0f64);
            let (boxes, dists) = fore::seen(scene, &cam);
            let shares: Vec<f64> = boxes.iter().map(|b| b.0).collect();
            for (k, o) in scene.objects.iter().enumerate() {
                let share = shares[k];
                if share <= 0.03 {
                    continue;
                }
                let dist = dists[k];
                if dist < PILLAR_NEAR
                    && stands_mid_frame(&cam, o, boxes[k].1, dist, &dists, &shares)
                {
                    pillar = pillar.max(share);
                }
                // What is looked at hides nothing, unless it is the near one of a pair, or it
                // stands before a larger object and hides much of it (a bush before the
                // fountain).
                if o.size[2] <= FLAT || dist >= d - 0.3 {
                    continue;
                }
                let hides_larger = || {
                    boxes[k].1.is_some_and(|r| {
                        scene.objects.iter().enumerate().any(|(j, q)| {
                            j != k
                                && shares[j] > 0.03
                                && dists[j] > dist + 0.5
                                && volume(q) > volume(o)
                                && boxes[j].1.is_some_and(|f| hidden_share(&r, &f) > HIDES)
                        })
                    })
                };
                let aimed = looked_at.contains(&k) && dist >= 0.5 * d && !hides_larger();
                if !aimed {
                    occluder = occluder.max(share);
                }
            }
            let near = fore::nearest(&shares, &dists);
            let cut = fore::cut_at_foot_objects(scene, &cam, &boxes, &dists, stats.subject)
                .into_iter()
                .map(|k| shares[k])
                .fold(0.0, f64::max);
            let mass = fore::foot_mass(scene, &cam, &boxes, &dists);
            let total = shares.iter().sum();
            let shown: Vec<bool> = scene
                .objects
                .iter()
                .map(|o| in_frame_within(&cam, o, pieces::SIDE_INSET))
                .collect();
            let (pieces, piece_share) = pieces::pieces_in_view(scene, &piece, &shown, &shares);
            let (blocker, grazing) = (
                blocker_share(scene, &cam, &shares),
                grazing_share(scene, &cam, &shares),
            );
            let backdrop = backdrop(scene, &cam, &sparse(&shares), focal_object);
            Some(Candidate {
                backdrop,
                pillar,
                cut,
                mass,
                pieces,
                piece: piece_share,
                blocker,
                grazing,
                shares: shares
                    .into_iter()
                    .enumerate()
                    .filter(|(_, s)| *s > 0.0)
                    .collect(),
                total,
                occluder,
                reach: d,
                near,
                cam,
                stats,
                shows,
                dir,
            })
        })
        .collect();
    pick::pick(scene, cands, count)
}

/// The most object boxes (shots, a position looking at a target, times objects) scored for
/// one scene. A hall of a hundred chairs has a thousand pairs of neighbours and hundreds of spots
/// along its walls; beyond this, the pairs' targets are thinned to one a cell, then spots are
/// skipped evenly, so a large scene's views take seconds, not minutes. Rooms of everyday size
/// (25 objects, 60,000 shots) stay under it.
const MAX_BOX_SHOTS: usize = 1_500_000;
/// The cell (metres) in which thinned pair targets keep one.
const TARGET_CELL: f64 = 0.75;

fn thin_shots(
    positions: &mut Vec<[f64; 3]>,
    targets: &mut Vec<([f64; 3], Vec<usize>)>,
    objects: usize,
) {
    let max_shots = MAX_BOX_SHOTS / objects.max(1);
    if positions.len() * targets.len() <= max_shots {
        return;
    }
    let mut cells = std::collections::BTreeSet::new();
    targets.retain(|(t, objs)| {
        objs.len() < 2 || cells.insert([0, 1, 2].map(|k| (t[k] / TARGET_CELL).floor() as i64))
    });
    let stride = (positions.len() * targets.len()).div_ceil(max_shots);
    if stride > 1 {
        *positions = positions.iter().step_by(stride).copied().collect();
    }
}

/// True when `o` (its silhouette's box `rect`, `dist` metres away) stands inside `cam`'s frame
/// like a pillar: from the frame's lower part ([`PILLAR_FOOT`] of its height down) up past its
/// centre, cut by neither side (at a side it is a column, a blocker of `faults.rs`), narrower
/// than half the frame, with something in frame at least [`PILLAR_BEHIND`] further. The
/// caller asks this of objects within [`PILLAR_NEAR`] only.
fn stands_mid_frame(
    cam: &Camera,
    o: &ObjectBox,
    rect: Option<[f64; 4]>,
    dist: f64,
    dists: &[f64],
    shares: &[f64],
) -> bool {
    let (w, h) = (cam.width as f64, cam.height as f64);
    let Some(r) = rect else { return false };
    o.size[2] > FLAT
        && r[3] >= PILLAR_FOOT * h
        && r[1] < 0.5 * h
        && r[2] - r[0] < 0.5 * w
        && r[0] > 1.0
        && r[2] < w - 1.0
        && dists
            .iter()
            .zip(shares)
            .any(|(d, s)| *s > 0.03 && *d > dist + PILLAR_BEHIND)
}

/// How near (metres) a pillar stands: a floor lamp 2 m off still splits the picture it stands
/// in the middle of, past the foreground distance.
const PILLAR_NEAR: f64 = 2.5;
/// How low in the frame (share of its height from the top) a pillar's foot reaches.
const PILLAR_FOOT: f64 = 0.75;
/// How much further (metres) the room behind a pillar must stand.
const PILLAR_BEHIND: f64 = 1.0;

mod fore;
pub use fore::{foot_mass_share, MASS_SHARE};
mod pick;
mod pieces;
mod sweep;
#[cfg(test)]
mod tests;
