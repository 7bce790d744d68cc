//! Foreground faults of a render view, one measure for the pick (which avoids them) and for the
//! tests (which count them): a view standing close to an object in its frame (a lampshade or a
//! chair back a step from the lens hides the room behind it), and an object before the view's
//! subject cut by the frame's bottom edge (the backs of the chairs at a dining table across the
//! foot of a view of the sideboard). Judged from the layout boxes alone. Host-only.
use super::super::faults::footprint_distance;
use super::super::views::{screen_box, FLAT};
use super::super::{ObjectBox, SceneBox};
use super::foreground;
use crate::camera::Camera;

/// A view stands close (the tests' count; the pick weighs the same distance, [`nearest`],
/// against the foreground distance) when an object covering more than [`IN_FRAME`] of its frame stands
/// nearer than this (horizontal metres from the camera to its footprint); in a small room at
/// most the foreground distance ([`foreground`]), since nothing there stands further.
#[cfg(test)]
pub(super) const CLOSE: f64 = 1.4;
/// An object counts for the foreground faults when it covers more than this share of the frame.
pub(super) const IN_FRAME: f64 = 0.03;

/// The close distance of `scene` (see [`CLOSE`]).
#[cfg(test)]
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
