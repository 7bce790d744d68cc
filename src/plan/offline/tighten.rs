//! An indoor room the planner chooses small ("a tiny kitchen", "quite cramped") has both sides
//! rounded up to the 10 cm, which can add most of a 10 cm strip along each: a cramped 11.9 m²
//! galley came out 3.9 x 3.1 = 12.1 m². The floor with one side a step shorter is taken instead
//! when the furniture still lays out as well in it (laid out, no piece more placed by fallback,
//! no relation more unsatisfied, on each of a few seeds), so a room never loses the room its
//! furniture needs to round a figure down.
use crate::plan::capacity::fit;
use crate::plan::gcp::{layout, LayoutOptions};
use crate::plan::spec::{Room, SceneSpec, SceneType, SpecError};
use std::collections::BTreeSet;

/// A side this short or shorter is kept as chosen: a tiny room is at the least a room of
/// its kind takes, not rounded up (metres).
const SHORT_SIDE: f64 = 2.4;

/// Seeds the two rooms are compared on.
const SEEDS: [u64; 2] = [0, 1];

/// How badly `spec` lays out in its room on `seed` (fallbacks, then unsatisfied relations), or
/// `None` when the layout refuses it.
fn cost(spec: &SceneSpec, seed: u64) -> Option<(usize, usize)> {
    let l = layout(spec, LayoutOptions::seeded(seed)).ok()?;
    let fallbacks = l
        .objects
        .iter()
        .filter(|o| o.placed_by == crate::plan::spec::PlacedBy::Fallback)
        .count();
    Some((fallbacks, l.unsatisfied.len()))
}

/// `fitted` (the spec in its rounded-up room, defaults trimmed; `unfitted` before trimming,
/// with its trimming notes `notes`) or, when one side a step shorter lays out as well, the
/// spec in that room with its own notes.
pub(super) fn tighten(
    unfitted: &SceneSpec,
    fitted: SceneSpec,
    notes: Vec<String>,
    named: &BTreeSet<String>,
    essential: &BTreeSet<String>,
    trim: bool,
) -> Result<(SceneSpec, Vec<String>), SpecError> {
    // (outdoors the "room" is ground, its rounding no room's size)
    let Some(room) = fitted
        .room
        .filter(|_| fitted.scene_type == SceneType::Indoor)
    else {
        return Ok((fitted, notes));
    };
    let [w, d, h] = room.size;
    let step = |v: f64| ((v - 0.1) * 10.0).round() / 10.0;
    // the shorter side first (the one the floor's area decided), then the longer
    let mut tries = vec![[w, step(d), h], [step(w), d, h]];
    if w < d {
        tries.reverse();
    }
    let Some(base) = SEEDS
        .iter()
        .map(|&s| cost(&fitted, s))
        .collect::<Option<Vec<_>>>()
    else {
        return Ok((fitted, notes));
    };
    for size in tries {
        if size[0].min(size[1]) < SHORT_SIDE - 1e-9 {
            continue;
        }
        // rows asked keep the width and depth their block needs (three rows of benches)
        let need = crate::plan::gcp::rows::room_for_rows(unfitted, [size[0], size[1]]);
        if need[0] > size[0] + 1e-9 || need[1] > size[1] + 1e-9 {
            continue;
        }
        let mut s = unfitted.clone();
        s.room = Some(Room { size });
        if s.objects
            .values()
            .any(|o| !crate::plan::capacity::fits(o.size, size))
        {
            continue;
        }
        let Ok(n) = fit(&mut s, named, essential, trim) else {
            continue;
        };
        // the same furniture: a tighter room that trims more is no tighter rounding
        if s.objects != fitted.objects {
            continue;
        }
        if SEEDS
            .iter()
            .zip(&base)
            .all(|(&seed, b)| cost(&s, seed).is_some_and(|c| c <= *b))
        {
            return Ok((s, n));
        }
    }
    Ok((fitted, notes))
}
