//! The smallest room that takes a spec: grown in steps of 10% from what its footprints need
//! until the layout is valid.
use super::{choose_room, layout_in, LayoutOptions};
use crate::plan::spec::{Room, SceneSpec};

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
