//! The smallest room that takes a spec: grown in steps of 10% from what its footprints need
//! until the layout is valid; and the layout of a spec whose room is the planner's choice, in a
//! room grown until everything fits.
use super::{choose_room, layout, layout_in, LayoutOptions};
use crate::plan::spec::{Layout, Room, SceneSpec, SpecError};

/// Steps of 10% past the smallest room that [`layout_growing`] tries with the caller's seed
/// (the smallest room is found with seed 0).
const GROW_STEPS: usize = 4;

/// [`layout`] of `spec`, whose room the planner chose (the text stated no size): when the
/// objects do not all fit, the room grows (its proportions kept, never shrunk) to the smallest
/// room that takes them, then in steps of 10% until the layout with `opts` does, and `spec.room`
/// becomes the room used. A room that would have to grow past that is refused with the first
/// error. A room the user stated is never grown: lay it out with [`layout`].
pub fn layout_growing(spec: &mut SceneSpec, opts: LayoutOptions) -> Result<Layout, SpecError> {
    let first = match layout(spec, opts) {
        Err(e @ SpecError::DoesNotFit(_)) => e,
        other => return other,
    };
    let Some(planned) = spec.room else {
        return Err(first);
    };
    let smallest = smallest_room(spec);
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    let mut size = [0, 1, 2].map(|k| smallest.size[k].max(planned.size[k]));
    for _ in 0..=GROW_STEPS {
        if size == planned.size {
            size = [r(size[0] * 1.1), r(size[1] * 1.1), size[2]];
            continue;
        }
        let mut grown = spec.clone();
        grown.room = Some(Room { size });
        if let Ok(l) = layout(&grown, opts) {
            *spec = grown;
            return Ok(l);
        }
        size = [r(size[0] * 1.1), r(size[1] * 1.1), size[2]];
    }
    Err(first)
}

/// "a, b and 3 more" followed by `verb`.
pub(super) fn join_names(names: &[String], verb: &str) -> String {
    let shown: Vec<&str> = names.iter().take(5).map(String::as_str).collect();
    let more = names.len().saturating_sub(5);
    let mut s = shown.join(", ");
    if more > 0 {
        s.push_str(&format!(" and {more} more"));
    }
    format!("{s} {verb}")
}

/// The smallest room, in steps of 10% of the spec's room (its proportions kept; the chosen
/// room when it has none), in which every instance is placed validly.
pub fn smallest_room(spec: &SceneSpec) -> Room {
    let inst = spec.instances();
    let base = spec
        .room
        .unwrap_or_else(|| choose_room(&inst, spec.scene_type));
    // Start from what the footprints and the largest piece need, then grow.
    let area: f64 = inst.iter().map(|i| i.size[0] * i.size[1]).sum();
    let longest = inst
        .iter()
        .map(|i| i.size[0].max(i.size[1]))
        .fold(0.0, f64::max);
    let shortest = inst
        .iter()
        .map(|i| i.size[0].min(i.size[1]))
        .fold(0.0, f64::max);
    let tallest = inst.iter().map(|i| i.size[2]).fold(0.0, f64::max);
    let (bw, bd) = (base.size[0], base.size[1]);
    let mut f = (area / (0.6 * bw * bd)).sqrt();
    let (long_side, short_side) = (bw.max(bd), bw.min(bd));
    f = f
        .max(longest / long_side)
        .max(shortest / short_side)
        .max(0.2);
    let h = base.size[2].max(tallest + 0.1);
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    let opts = LayoutOptions {
        seed: 0,
        restarts: 2,
    };
    for _ in 0..30 {
        let room = Room {
            size: [r(bw * f), r(bd * f), r(h)],
        };
        let fits_all = spec
            .objects
            .values()
            .all(|o| crate::plan::capacity::fits(o.size, room.size));
        if fits_all {
            let l = layout_in(spec, room, opts);
            if crate::plan::check::validity_problems(&l, spec).is_empty() {
                return room;
            }
        }
        f *= 1.1;
    }
    choose_room(&inst, spec.scene_type)
}
