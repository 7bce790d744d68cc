//! What a person calls a poor picture, measured from a view's camera and the layout boxes
//! (occlusion ignored): mostly bare wall or floor, a blocker close to the lens, a flat piece (a
//! mirror, painting, TV or whiteboard) seen edge-on, a near copy of an earlier view, and a
//! repeat of one (`repeat.rs`: the same things the same way, nothing new). The
//! render views are scored against these (`choose.rs`) and the framing figure counts them.
//! Host-only.
use super::repeat::{backdrop, heading, repeats, sparse, Look};
use super::views::{facing, frame_share, screen_box, FLAT};
use super::wall::bare_wall_share;
use super::{kind, ObjectBox, SceneBox};
use crate::camera::Camera;

/// A view whose objects' boxes cover less than this share of the frame is mostly bare wall or
/// floor (box silhouettes overstate what chairs and tables hide, so this is generous).
pub const BARE_COVER: f64 = 0.25;
/// A view more than this share of whose frame is wall with nothing before it (no object, door
/// or window; see [`bare_wall_share`]) is mostly bare wall, however much its boxes cover.
pub const BARE_WALL: f64 = 0.45;
/// A blocker: an object covering more than `BLOCKER_SHARE` of the frame whose footprint stands
/// nearer the camera than `BLOCKER_PER_SIZE` of its largest side (so it spans a wide angle),
/// and within `BLOCKER_NEAR` metres, with the room at least `BLOCKER_BEHIND` metres further
/// behind it (a lampshade before the sofa); unless it is seen whole (its silhouette inside the
/// frame) with its top below the eye: the eye looks over it (a bed seen whole from its foot).
pub const BLOCKER_SHARE: f64 = 0.05;
pub const BLOCKER_PER_SIZE: f64 = 0.9;
pub const BLOCKER_NEAR: f64 = 1.5;
pub const BLOCKER_BEHIND: f64 = 1.0;
/// An object is also a blocker, however far, when it stands at the frame's side like a column:
/// its silhouette cut by the frame's bottom edge and its left or right one, and rising through
/// at least this share of the frame's height.
pub const COLUMN_HEIGHT: f64 = 0.7;
/// A flat piece seen at more than this angle from its face (degrees) is seen edge-on: the
/// larger of the angle of the line of sight and that of the lens's axis, since a panel turned
/// from the image plane is drawn as a thin trapezoid even where the line of sight meets it
/// square (at the side of a wide lens).
pub const GRAZING_DEG: f64 = 65.0;
/// The limit for a mirror (a category named by the word, see `is_mirror`): the draft's
/// mirror reflects nothing, and its grey pane reads as a mirror only nearly face on.
pub const GRAZING_MIRROR_DEG: f64 = 45.0;
/// A flat piece: at most this deep (metres) and this share of its width and height.
const FLAT_DEPTH: f64 = 0.15;
const FLAT_RATIO: f64 = 0.25;
/// A flat piece counts when it covers more than this share of the frame.
const GRAZING_SHARE: f64 = 0.02;
/// A close-up of a wall: a view whose axis meets a wall (the ground's edge) within
/// `CLOSE_DEPTH` of the room's diagonal and more than `CLOSE_WALL` of whose frame is bare wall
/// (see [`looks_at_wall`]): one piece against the wall behind it, not a view into the room.
/// Counted by the framing figure beside the faults (not one of them: such a view still shows
/// what it frames).
pub const CLOSE_DEPTH: f64 = 0.4;
pub const CLOSE_WALL: f64 = 0.35;
/// Two views are near copies when they show this much the same (see [`alike`]).
pub const COPY: f64 = 0.6;

/// The faults of one view among a list.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ViewFaults {
    pub bare: bool,
    pub blocker: bool,
    pub grazing: bool,
    /// A near copy of an earlier view of the list.
    pub copy: bool,
    /// A repeat of an earlier view of the list ([`repeats`]): looking the same way, it shows
    /// little the earlier one did not.
    pub repeat: bool,
}

impl ViewFaults {
    /// True when the view has no fault.
    pub fn clean(&self) -> bool {
        !(self.poor() || self.repeat)
    }

    /// True when the picture itself is poor: mostly bare, a blocker at the lens, a panel
    /// edge-on, or a near copy (a repeat is no poor picture, only one too many).
    pub fn poor(&self) -> bool {
        self.bare || self.blocker || self.grazing || self.copy
    }
}

/// Horizontal distance from `p` to an object's footprint (0 inside).
pub(crate) fn footprint_distance(o: &ObjectBox, p: [f64; 3]) -> f64 {
    let (s, c) = o.yaw.to_radians().sin_cos();
    let (dx, dy) = (p[0] - o.position[0], p[1] - o.position[1]);
    let (lx, ly) = (c * dx + s * dy, -s * dx + c * dy);
    let ox = (lx.abs() - 0.5 * o.size[0]).max(0.0);
    let oy = (ly.abs() - 0.5 * o.size[1]).max(0.0);
    ox.hypot(oy)
}

/// True for a thin upright panel (a mirror, painting, TV, whiteboard): shallow against its
/// width and height.
pub fn is_panel(o: &ObjectBox) -> bool {
    o.size[2] > FLAT
        && o.size[1] <= FLAT_DEPTH
        && o.size[1] <= FLAT_RATIO * o.size[0].min(o.size[2])
}

/// The share of the frame of the panels that `cam` sees edge-on (beyond `GRAZING_DEG` from
/// their face or back), given each object's share of the frame.
pub fn grazing_share(scene: &SceneBox, cam: &Camera, shares: &[f64]) -> f64 {
    let (cos, mirror_cos) = (
        GRAZING_DEG.to_radians().cos(),
        GRAZING_MIRROR_DEG.to_radians().cos(),
    );
    // A point far behind the camera along its axis: the direction "seen along the axis".
    let axis = [0, 1].map(|i| cam.position[i] - 1e6 * cam.rotation[i][2]);
    scene
        .objects
        .iter()
        .zip(shares)
        .filter(|(o, s)| {
            let limit = if is_mirror(o) { mirror_cos } else { cos };
            let seen = facing(o, cam.position)
                .abs()
                .min(facing(o, [axis[0], axis[1], 0.0]).abs());
            **s > GRAZING_SHARE && is_panel(o) && seen < limit
        })
        .map(|(_, s)| *s)
        .sum()
}

/// True when `o`'s kind ([`kind`]) names a mirror (a mirror, a full length mirror, a mirror wall).
fn is_mirror(o: &ObjectBox) -> bool {
    // camera may not import shape (layering): a mirror is a category named by the word
    kind(o)
        .split_whitespace()
        .any(|w| w == "mirror" || w == "mirrors")
}

/// Horizontal distance from `cam` along its view direction to the room's (ground's) edge.
pub(crate) fn depth(scene: &SceneBox, cam: &Camera) -> f64 {
    let [hx, hy] = scene.half();
    let (fx, fy) = (cam.rotation[0][2], cam.rotation[1][2]);
    let n = fx.hypot(fy).max(1e-9);
    let reach = |p: f64, f: f64, h: f64| {
        if f.abs() < 1e-9 {
            f64::INFINITY
        } else {
            ((f.signum() * h - p) / f).max(0.0)
        }
    };
    let (dx, dy) = (fx / n, fy / n);
    reach(cam.position[0], dx, hx).min(reach(cam.position[1], dy, hy))
}

/// True when `cam` looks at a near wall with little before it (see `CLOSE_DEPTH`): a close-up
/// of one piece against its wall rather than a view into the room.
pub fn looks_at_wall(scene: &SceneBox, cam: &Camera) -> bool {
    let diagonal = scene.room[0].hypot(scene.room[1]);
    depth(scene, cam) < CLOSE_DEPTH * diagonal && bare_wall_share(scene, cam) > CLOSE_WALL
}

/// The largest share of the frame a blocker covers (see `BLOCKER_SHARE`, `COLUMN_HEIGHT`), 0 without one,
/// given each object's share of the frame. What it stands before is the room: another object
/// in frame, or the wall or ground edge the view looks at.
pub fn blocker_share(scene: &SceneBox, cam: &Camera, shares: &[f64]) -> f64 {
    blocker_of(scene, cam, shares).map_or(0.0, |k| shares[k])
}

/// The index of the object that is the largest blocker of `cam`'s view (see
/// [`blocker_share`]), given each object's share of the frame.
pub fn blocker_of(scene: &SceneBox, cam: &Camera, shares: &[f64]) -> Option<usize> {
    let dists: Vec<f64> = scene
        .objects
        .iter()
        .map(|o| footprint_distance(o, cam.position))
        .collect();
    let seen = |k: usize| shares[k] > 0.02 && scene.objects[k].size[2] > FLAT;
    let far = (0..scene.objects.len())
        .filter(|&j| seen(j))
        .map(|j| dists[j])
        .fold(depth(scene, cam), f64::max);
    let (w, h) = (cam.width as f64, cam.height as f64);
    // A column at the frame's side: cut by its side and bottom edges and rising to the frame's
    // top part (a punching bag or a wardrobe's flank beside the lens).
    let column = |o: &ObjectBox| {
        screen_box(cam, o).1.is_some_and(|r| {
            (r[0] <= 1.0 || r[2] >= w - 1.0) && r[3] >= h - 1.0 && r[1] <= (1.0 - COLUMN_HEIGHT) * h
        })
    };
    // Seen whole and low: its silhouette inside the frame and its top below the eye. The eye
    // looks over it at the room (a bed seen whole from its foot), and the picture shows it
    // entire: it is the foreground of the picture, not something in its way.
    let whole_below_eye = |o: &ObjectBox| {
        o.position[2] + o.size[2] < cam.position[2]
            && screen_box(cam, o)
                .1
                .is_some_and(|r| r[0] > 1.0 && r[1] > 1.0 && r[2] < w - 1.0 && r[3] < h - 1.0)
    };
    (0..scene.objects.len())
        .filter(|&k| {
            let o = &scene.objects[k];
            let near = BLOCKER_NEAR.min(BLOCKER_PER_SIZE * o.size[0].max(o.size[1]).max(o.size[2]));
            seen(k)
                && shares[k] > BLOCKER_SHARE
                && far > dists[k] + BLOCKER_BEHIND
                && (dists[k] < near || column(o))
                && !whole_below_eye(o)
        })
        .max_by(|a, b| shares[*a].total_cmp(&shares[*b]))
}

/// How much two views show the same: over the objects, the smaller of the shares of the frame
/// the two give it, summed, over the larger of the views' summed shares; times the cosine
/// between their directions (0 when they look apart by 90° or more). 1 is the same picture.
pub fn alike(a: (&Camera, &[f64]), b: (&Camera, &[f64])) -> f64 {
    let fwd = |c: &Camera| [c.rotation[0][2], c.rotation[1][2]];
    let (da, db) = (fwd(a.0), fwd(b.0));
    let (na, nb) = (da[0].hypot(da[1]), db[0].hypot(db[1]));
    let cos = (da[0] * db[0] + da[1] * db[1]) / (na * nb).max(1e-9);
    if cos <= 0.0 {
        return 0.0;
    }
    let both: f64 = a.1.iter().zip(b.1).map(|(x, y)| x.min(*y)).sum();
    let (ta, tb): (f64, f64) = (a.1.iter().sum(), b.1.iter().sum());
    both / ta.max(tb).max(1e-9) * cos
}

/// The faults of each of `cams` (a near copy and a repeat are judged against the views before
/// it).
pub fn view_faults(scene: &SceneBox, cams: &[Camera]) -> Vec<ViewFaults> {
    let shares: Vec<Vec<f64>> = cams
        .iter()
        .map(|c| scene.objects.iter().map(|o| frame_share(c, o)).collect())
        .collect();
    let shown: Vec<Vec<(usize, f64)>> = shares.iter().map(|s| sparse(s)).collect();
    let focal = super::choose::focal(scene).map(|f| f.0);
    cams.iter()
        .enumerate()
        .map(|(i, c)| {
            let s = &shares[i];
            let look = |j: usize| Look {
                dir: heading(&cams[j]),
                shows: &shown[j],
                backdrop: backdrop(scene, &cams[j], &shown[j], focal),
            };
            let covered: f64 = s.iter().sum();
            ViewFaults {
                bare: covered < BARE_COVER || bare_wall_share(scene, c) > BARE_WALL,
                blocker: blocker_share(scene, c, s) > 0.0,
                grazing: grazing_share(scene, c, s) > 0.0,
                copy: (0..i).any(|j| alike((c, s), (&cams[j], &shares[j])) > COPY),
                repeat: (0..i).any(|j| repeats(look(i), look(j))),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::scene::views::frame_share;
    use crate::camera::scene::views::tests::boxed;

    #[test]
    fn a_low_bed_seen_whole_is_no_blocker_and_cut_by_the_frame_it_is() {
        // "a tiny bedroom": its views from the bed's foot counted as blocked, the bed within
        // 1.5 m of the lens, though the picture shows the bed whole with the room over it.
        let scene = SceneBox {
            scene_type: crate::plan::spec::SceneType::Indoor,
            room: [4.0, 3.6, 2.8],
            objects: vec![boxed("bed1", 0.0, -0.5, [1.6, 2.1, 0.6])],
            openings: vec![],
        };
        let eye = [0.0, 1.4, 1.5];
        let look = |target: [f64; 3]| {
            let cam = crate::camera::scene::camera(eye, target, [0.0, 0.0, 1.0], 64, 64, 1.35);
            let shares: Vec<f64> = scene.objects.iter().map(|o| frame_share(&cam, o)).collect();
            assert!(shares[0] > BLOCKER_SHARE, "the bed fills {}", shares[0]);
            blocker_of(&scene, &cam, &shares)
        };
        // 0.85 m from its foot, looking down at its middle: seen whole, its top below the eye.
        assert_eq!(look([0.0, -0.5, 0.3]), None, "a bed seen whole");
        // Turned aside, the frame cuts the bed at its side: a mass at the lens.
        assert_eq!(look([-1.6, 0.2, 0.3]), Some(0), "a bed cut by the frame");
        // A bunk bed as tall as the eye at the same spot rises into the room behind it.
        let mut bunk = scene.clone();
        bunk.objects[0].size[2] = 1.6;
        let cam =
            crate::camera::scene::camera(eye, [0.0, -1.5, 0.8], [0.0, 0.0, 1.0], 64, 64, 1.35);
        let shares: Vec<f64> = bunk.objects.iter().map(|o| frame_share(&cam, o)).collect();
        assert_eq!(
            blocker_of(&bunk, &cam, &shares),
            Some(0),
            "a bunk bed at the lens"
        );
    }

    #[test]
    fn a_view_from_close_at_an_empty_wall_looks_at_it_and_one_across_the_room_does_not() {
        let scene = SceneBox {
            scene_type: crate::plan::spec::SceneType::Indoor,
            room: [5.0, 4.0, 2.8],
            objects: vec![boxed("tv stand1", 0.0, 1.75, [1.6, 0.45, 0.5])],
            openings: vec![],
        };
        let look = |eye: [f64; 3], at: [f64; 3]| {
            let cam = crate::camera::scene::camera(eye, at, [0.0, 0.0, 1.0], 64, 64, 0.96);
            looks_at_wall(&scene, &cam)
        };
        // 1.5 m from the north wall, at the stand before it: the wall fills the frame.
        assert!(
            look([0.0, 0.5, 1.5], [0.0, 1.75, 1.0]),
            "a close-up of the stand"
        );
        // From the south wall across the room at the same stand: it looks into the room.
        assert!(
            !look([0.0, -1.7, 1.5], [0.0, 1.75, 1.0]),
            "a view across the room"
        );
        // Close, but at the floor before the stand: little bare wall.
        assert!(
            !look([0.0, 0.5, 1.5], [0.0, 1.2, 0.0]),
            "a view down at the floor is no wall close-up"
        );
    }

    #[test]
    fn mirrors_are_known_by_their_name_word() {
        for id in [
            "mirror1",
            "full length mirror2",
            "mirror wall1",
            "magic mirror1",
        ] {
            assert!(
                is_mirror(&boxed(id, 0.0, 0.0, [1.0, 0.05, 1.5])),
                "{id} is a mirror"
            );
        }
        for id in ["painting1", "tv1", "mirrored cabinet1", "whiteboard3"] {
            assert!(
                !is_mirror(&boxed(id, 0.0, 0.0, [1.0, 0.05, 1.5])),
                "{id} is no mirror"
            );
        }
    }
}
