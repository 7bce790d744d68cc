//! Foreground faults of a render view, one measure for the pick (which avoids them) and for the
//! tests (which count them): a view standing close to an object in its frame (a lampshade or a
//! chair back a step from the lens hides the room behind it), and an object before the view's
//! subject cut by the frame's bottom edge (the backs of the chairs at a dining table across the
//! foot of a view of the sideboard), and a mass at the frame's foot (any upright object, the
//! subject too, cut by the frame's bottom edge and filling much of the picture before the room
//! behind it: an armchair's back across a hotel lobby's view, a medical cart before the
//! operating table). Judged from the layout boxes alone. Host-only.
use super::super::faults::footprint_distance;
use super::super::views::{screen_box, FLAT};
use super::super::{ObjectBox, SceneBox};
use super::foreground;
use crate::camera::Camera;

/// A view stands close (the tests' count; the pick weighs the same distance, [`nearest`],
/// against the foreground distance, and past its fourth view takes one standing close only
/// where no other is left) when an object covering more than [`IN_FRAME`] of its frame stands
/// nearer than this (horizontal metres from the camera to its footprint); in a small room at
/// most the foreground distance ([`foreground`]), since nothing there stands further.
pub(super) const CLOSE: f64 = 1.4;
/// An object counts for the foreground faults when it covers more than this share of the frame.
pub(super) const IN_FRAME: f64 = 0.03;

/// The close distance of `scene` (see [`CLOSE`]).
pub(super) fn close(scene: &SceneBox) -> f64 {
    CLOSE.min(foreground(scene))
}

/// Horizontal distance from the camera to the nearest object covering more than [`IN_FRAME`]
/// of the frame, given each object's share of it and its footprint's distance from the camera
/// (infinite with none).
pub(super) fn nearest(shares: &[f64], dists: &[f64]) -> f64 {
    shares
        .iter()
        .zip(dists)
        .filter(|(s, _)| **s > IN_FRAME)
        .map(|(_, d)| *d)
        .fold(f64::INFINITY, f64::min)
}

/// True when `o` (its silhouette's box `rect`) stands upright in `cam`'s frame with its foot cut
/// by the frame's bottom edge: seen from so near that only its top half is in the picture.
pub(super) fn cut_at_foot(cam: &Camera, o: &ObjectBox, rect: Option<[f64; 4]>) -> bool {
    o.size[2] > FLAT && rect.is_some_and(|r| r[3] >= cam.height as f64 - 1.0)
}

/// The objects of `cam`'s view cut at their foot in its foreground: covering more than
/// [`IN_FRAME`] of the frame, nearer than the foreground distance ([`foreground`]), cut by the
/// frame's bottom edge ([`cut_at_foot`]), and not the view's `subject` (what the picture is of
/// may fill its foot). `boxes` are each object's share of the frame and silhouette's box,
/// `dists` its footprint's distance from the camera.
pub(super) fn cut_at_foot_objects(
    scene: &SceneBox,
    cam: &Camera,
    boxes: &[(f64, Option<[f64; 4]>)],
    dists: &[f64],
    subject: Option<usize>,
) -> Vec<usize> {
    let fg = foreground(scene);
    (0..scene.objects.len())
        .filter(|&k| {
            Some(k) != subject
                && boxes[k].0 > IN_FRAME
                && dists[k] < fg
                && cut_at_foot(cam, &scene.objects[k], boxes[k].1)
        })
        .collect()
}

/// A mass at the frame's foot covers more than this share of the frame: measured on the hotel
/// lobby's and the operating room's views, an armchair's back or a cart cut by the frame's
/// bottom covers 0.14–0.24 of a picture a person sees as blocked at the lens, while the sofa
/// or table a wide view is of, seen whole, covers at most 0.13 (and is not cut).
pub const MASS_SHARE: f64 = 0.12;
/// How much further (metres) the room behind a mass at the frame's foot stands: something else
/// in the frame at least this far behind it.
const MASS_BEHIND: f64 = 1.0;

/// The largest share of `cam`'s frame of a mass at its foot (see [`MASS_SHARE`]; 0 with none):
/// an upright object whose silhouette the frame's bottom edge cuts ([`cut_at_foot`]), with
/// another object in frame (over [`IN_FRAME`]) standing at least [`MASS_BEHIND`] further. Its
/// share counts whatever the view is aimed at or of: the picture is blocked at its foot
/// either way. `boxes` and `dists` as in [`cut_at_foot_objects`].
pub(in crate::camera::scene) fn foot_mass(
    scene: &SceneBox,
    cam: &Camera,
    boxes: &[(f64, Option<[f64; 4]>)],
    dists: &[f64],
) -> f64 {
    let behind = |k: usize| {
        (0..scene.objects.len())
            .any(|j| j != k && boxes[j].0 > IN_FRAME && dists[j] > dists[k] + MASS_BEHIND)
    };
    (0..scene.objects.len())
        .filter(|&k| {
            boxes[k].0 > IN_FRAME && cut_at_foot(cam, &scene.objects[k], boxes[k].1) && behind(k)
        })
        .map(|k| boxes[k].0)
        .fold(0.0, f64::max)
}

/// The largest share of `cam`'s frame of a mass at its foot ([`MASS_SHARE`], 0 with none).
pub fn foot_mass_share(scene: &SceneBox, cam: &Camera) -> f64 {
    let (boxes, dists) = seen(scene, cam);
    foot_mass(scene, cam, &boxes, &dists)
}

/// Each object's share of `cam`'s frame and its silhouette's box ([`screen_box`]), and its
/// footprint's horizontal distance from the camera: what the foreground faults are judged on.
pub(super) type Seen = (Vec<(f64, Option<[f64; 4]>)>, Vec<f64>);

/// What `cam` sees of `scene`'s objects for the foreground faults (see [`Seen`]).
pub(super) fn seen(scene: &SceneBox, cam: &Camera) -> Seen {
    let boxes = scene.objects.iter().map(|o| screen_box(cam, o)).collect();
    let dists = scene
        .objects
        .iter()
        .map(|o| footprint_distance(o, cam.position))
        .collect();
    (boxes, dists)
}

/// True when `cam` stands close to an object in its frame ([`CLOSE`], [`close`]).
#[cfg(test)]
pub(super) fn stands_close(scene: &SceneBox, cam: &Camera) -> bool {
    let (boxes, dists) = seen(scene, cam);
    let shares: Vec<f64> = boxes.iter().map(|b| b.0).collect();
    nearest(&shares, &dists) < close(scene)
}
