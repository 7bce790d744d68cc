//! The sizing stage of the offline planner: each named object's size (stated, scaled by its size
//! words, or for an unknown object from its head noun, WordNet or a size class) and the room's
//! (stated, else chosen to fit the furniture, scaled by "small" or "large").
use super::Draft;
use crate::plan::capacity::room_for;
use crate::plan::kb::KnowledgeBase;
use crate::plan::lang;
use crate::plan::spec::{Room, SceneSpec, SceneType};
use std::collections::BTreeSet;

/// The sizes the mentions give: an unknown object's (with a note), a stated one, or one scaled
/// by size words; records what the text names and its adjectives.
pub(super) fn mention_sizes(d: &mut Draft) {
    let (kb, scene, scene_type) = (d.kb, d.scene, d.scene_type);
    let Draft {
        r,
        cats,
        named,
        adjectives,
        sizes,
        unknown,
        notes,
        ..
    } = d;
    for (i, (m, cat)) in r.mentions.iter().zip(cats.iter()).enumerate() {
        if m.negated || m.reference {
            continue;
        }
        // "a basket of towels" in a laundry room is its laundry basket, which the knowledge
        // base has
        if !m.known && !unknown.contains_key(cat) && kb.object(cat).is_none() {
            // "the instructor's mat" in a yoga studio: sized as the scene's own mats
            let own = scene.and_then(|s| {
                let head = cat.rsplit(' ').next()?;
                let (c, _) = s
                    .objects
                    .iter()
                    .find(|(c, _)| c.rsplit(' ').next() == Some(head))?;
                Some((kb.object(c)?.size, format!("sized as a {c}")))
            });
            let (mut size, mut how) = own.unwrap_or_else(|| unknown_size(kb, cat));
            // "a cup of tea on the side table": a small thing the text puts on another is
            // a thing of its top, a hand's size, not a small piece of furniture
            let on = r
                .relations
                .iter()
                .find(|&&(s, rel, _)| s == i && rel == crate::plan::spec::RelationKind::Over)
                .and_then(|&(_, _, o)| kb.object(&r.mentions.get(o)?.category));
            if let Some(o) = on.filter(|o| o.size[2] < 1.5) {
                let top = o.size[0].min(o.size[1]);
                let side = (0.4 * top).clamp(0.1, TABLETOP[0]);
                size = [side, side, TABLETOP[1]];
                how = format!(
                    "sized as a small thing on a {} {}",
                    o.category,
                    fmt_size(size)
                );
            }
            notes.push(format!("`{cat}` is not in the knowledge base: kept, {how}"));
            unknown.insert(cat.clone(), size);
        }
        named.insert(cat.clone());
        if !m.adjectives.is_empty() {
            adjectives.insert(cat.clone(), m.adjectives.clone());
        }
        // a thing of outdoor scale in a room: its indoor size, scaled from there
        let indoor = (scene_type == SceneType::Indoor)
            .then(|| crate::plan::gcp::classes::Placements::builtin().indoor_size(cat))
            .flatten();
        let base = indoor
            .or(kb.object(cat).map(|o| o.size))
            .or(unknown.get(cat).copied());
        if let Some(mut size) = base {
            if m.size != [0.0; 3] {
                // A stated width keeps the shape's proportions in depth only when both are given.
                for (v, stated) in size.iter_mut().zip(m.size) {
                    if stated > 0.0 {
                        *v = stated;
                    }
                }
                sizes.insert(cat.clone(), size);
            } else if m.known {
                // "a huge viewscreen", "a tiny desk": the size words of kb/words.txt scale it.
                // "a big table for ten": the seats it is laid for set its footprint
                // (kb/seating.txt), whatever words of size are said of it
                let laid_for = r.seats_for.iter().any(|&(t, _)| t == i);
                let f: f64 = m
                    .adjectives
                    .iter()
                    .filter(|_| !laid_for)
                    .filter_map(|a| lang::object_scale(a))
                    .product();
                // a word the category's own description has ("small round cafe table") is
                // already in its size
                let described = kb.object(cat).map(|o| o.description.as_str()).unwrap_or("");
                let g: f64 = m
                    .adjectives
                    .iter()
                    .filter(|a| !laid_for && !described.split(' ').any(|w| w == a.as_str()))
                    .filter_map(|a| lang::object_footprint(a))
                    .product();
                // "a long table", "a tall bookcase": its longer side, its height
                let said = |by: fn(&str) -> Option<f64>| -> f64 {
                    m.adjectives
                        .iter()
                        .filter(|a| !described.split(' ').any(|w| w == a.as_str()))
                        .filter_map(|a| by(a))
                        .product()
                };
                let l = if laid_for {
                    1.0
                } else {
                    said(lang::object_length)
                };
                let h = said(lang::object_height);
                if f != 1.0 || g != 1.0 || l != 1.0 || h != 1.0 {
                    let longer = if size[0] >= size[1] { 0 } else { 1 };
                    for (k, v) in size.iter_mut().enumerate() {
                        let s = match k {
                            2 => f * h,
                            _ if k == longer => f * g * l,
                            _ => f * g,
                        };
                        *v = (*v * s * 100.0).round() / 100.0;
                    }
                    sizes.insert(cat.clone(), size);
                }
            }
        }
    }
}

/// The room: as stated, else chosen to fit `spec` (scaled by "small" / "large"); a size without
/// a unit gets a note.
pub(super) fn room(d: &mut Draft, spec: &SceneSpec) -> Room {
    let Draft {
        r,
        scene,
        scene_type,
        named,
        notes,
        ..
    } = d;
    let scene_type = *scene_type;
    // a tall place's kind (a church, a barn, a cave) sets its height, a house's room is 2.8 m
    let kind_height = scene
        .filter(|_| scene_type == SceneType::Indoor)
        .and_then(|s| s.height);
    let height: f64 = match scene_type {
        SceneType::Indoor => kind_height.unwrap_or(2.8),
        SceneType::Outdoor => 10.0,
    };
    let stated = r.room;
    let room = match stated {
        Some([w, d]) => {
            let tallest = spec
                .instances()
                .iter()
                .map(|i| i.size[2])
                .fold(0.0, f64::max);
            let h = r.room_height.unwrap_or(height.max(tallest + 0.3));
            Room {
                size: [
                    crate::plan::units::cm(w),
                    crate::plan::units::cm(d),
                    crate::plan::units::cm(h),
                ],
            }
        }
        None => {
            let mut room = room_for(spec, scene_type);
            room.size[2] = room.size[2].max(kind_height.unwrap_or(0.0));
            if let Some(floor) = scene.and_then(|s| s.floor) {
                room.size = kind_floor(spec, named, floor, r.scale, room.size);
            } else if r.scale < 1.0 {
                // what the text names and what the place cannot do without (its bed) set it;
                // with nothing named, the scene's furniture
                let essential = scene
                    .filter(|_| named.iter().any(|c| spec.objects.contains_key(c)))
                    .map_or(&[][..], |s| &s.essential[..]);
                let kept: BTreeSet<String> = named
                    .iter()
                    .chain(essential)
                    .filter(|c| spec.objects.contains_key(*c))
                    .cloned()
                    .collect();
                room.size = small_room(spec, &kept, room.size, r.scale, scene_type);
            } else if r.scale > 1.0 {
                let s = r.scale.sqrt();
                for k in 0..2 {
                    room.size[k] = (room.size[k] * s * 10.0).ceil() / 10.0;
                }
            }
            if r.long {
                room.size = drawn_out(room.size);
            }
            // things asked in rows: wide and deep enough for the block and its front
            // (floors of tables grow it only: the lattice keeps the walls' band for the rest)
            let up = |n: f64| (n * 10.0).ceil() / 10.0;
            let need =
                crate::plan::gcp::tables::room_for_tables(spec, [room.size[0], room.size[1]]);
            for (v, n) in room.size.iter_mut().zip(need) {
                *v = v.max(up(n));
            }
            let need = crate::plan::gcp::rows::room_for_blocks(spec).map(up);
            room.size = rows_room(room.size, need);
            room
        }
    };
    if r.room_unitless {
        notes.push(format!(
            "room size {} x {} has no unit: read as metres",
            room.size[0], room.size[1]
        ));
    }
    room
}

/// Room kept beside what rows need when a side gives back area (m).
const ROWS_SLACK: f64 = 0.6;

/// The room `size` chosen by floor area made wide and deep enough for the blocks of rows
/// (`need`); when only one side must grow, the other gives back what keeps the floor area (the
/// rows already hold their share of it), down to what the rows need and [`ROWS_SLACK`] (a door
/// on the front wall still leaves the front thing its place): twelve yoga mats in three rows
/// were an 8.9 x 12.2 m studio, the square of their area drawn out to the rows' depth.
fn rows_room(size: [f64; 3], need: [f64; 2]) -> [f64; 3] {
    let area = size[0] * size[1];
    let mut out = [size[0].max(need[0]), size[1].max(need[1]), size[2]];
    for k in 0..2 {
        let o = 1 - k;
        if out[k] > size[k] && out[o] == size[o] {
            let keep = ((area / out[k]) * 10.0).ceil() / 10.0;
            out[o] = keep.max(need[o] + ROWS_SLACK).min(size[o]);
        }
    }
    out
}

/// Long side over short side of a room the text calls long or narrow (a hallway, a gallery):
/// plainly drawn out next to the 1.25 of a room sized for its furniture.
const LONG_RATIO: f64 = 2.5;

/// Short side of a room drawn out (metres): a corridor still walked past furniture on one side.
const LONG_MIN_SIDE: f64 = 1.6;

/// The floor `size` drawn out to [`LONG_RATIO`], its area kept (its short side never under
/// [`LONG_MIN_SIDE`]).
fn drawn_out(size: [f64; 3]) -> [f64; 3] {
    let area = size[0] * size[1];
    let d = (area / LONG_RATIO).sqrt().max(LONG_MIN_SIDE);
    let w = (area / d).max(d * LONG_RATIO);
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    [r(w), r(d), size[2]]
}

/// Scale below which the text called the room tiny, not just small ("tiny", "cramped").
pub(super) const TINY_SCALE: f64 = 0.45;

/// Height below which a thing is at floor level (metres): see [`small_room`].
const LOW: f64 = 0.3;

/// Floor of a room the text calls small or tiny: what the named objects need in use (their
/// footprints with room to use them at half the floor, a little more when tiny; the longest
/// with a walkway), or with nothing named the scene's furniture room scaled by `scale`; never
/// below a small room's side. The defaults are then trimmed to fit by `capacity::fit`.
fn small_room(
    spec: &SceneSpec,
    named: &BTreeSet<String>,
    full: [f64; 3],
    scale: f64,
    scene_type: SceneType,
) -> [f64; 3] {
    let named_inst: Vec<_> = spec
        .instances()
        .into_iter()
        .filter(|i| named.contains(&i.category))
        .collect();
    let margin = crate::plan::capacity::USE_MARGIN;
    // The share of the floor the named furniture may take: more in a room called tiny.
    let occupancy = if scale < TINY_SCALE { 0.6 } else { 0.5 };
    // Only what stands on the floor takes floor (a mirror on the wall, a lamp on a table no).
    let on_floor = |c: &str| {
        use crate::plan::gcp::classes::{effective_class, Class};
        matches!(effective_class(spec, c), Class::Floor | Class::AgainstWall)
    };
    // A chair at a desk uses the desk's own room in front of it.
    let tucked = |c: &str| {
        use crate::plan::groups::{group_of, seats_per};
        matches!(group_of(spec, c), Some((crate::plan::spec::RelationKind::At | crate::plan::spec::RelationKind::AtBack, t)) if seats_per(spec, c, &t) == Some(1))
    };
    // A thing at floor level (a floor cushion, a mattress on the floor) is stepped onto: its
    // footprint is all it takes.
    let room_to_use = |h: f64| if h < LOW { 0.0 } else { margin };
    // In a room called tiny a thing against a wall is used from its front: its neighbours in a
    // run along the wall (a sink beside a counter) share the room at its sides, half each (a
    // room only called small keeps it whole: its defaults still need their fronts clear).
    let walled = |c: &str| {
        use crate::plan::gcp::classes::{effective_class, Class};
        effective_class(spec, c) == Class::AgainstWall
    };
    let need: f64 = named_inst
        .iter()
        .filter(|i| i.size[2] >= 0.05 && on_floor(&i.category) && !tucked(&i.category))
        .map(|i| {
            let m = room_to_use(i.size[2]);
            let side = if scale < TINY_SCALE && walled(&i.category) {
                0.5 * m
            } else {
                m
            };
            (i.size[0] + side) * (i.size[1] + m)
        })
        .sum::<f64>()
        / occupancy;
    let longest = spec
        .instances()
        .iter()
        .filter(|i| named.contains(&i.category))
        .map(|i| i.size[0].max(i.size[1]))
        .fold(0.0, f64::max);
    let base_side: f64 = match scene_type {
        SceneType::Indoor if scale < TINY_SCALE => 1.8,
        SceneType::Indoor => 2.2,
        SceneType::Outdoor => 6.0,
    };
    // a named seat and the screen it faces: across the room at a viewing distance
    let view = crate::plan::gcp::viewing_side(spec, named);
    let min_side = base_side.max(longest + 0.4).max(view);
    // What the text names sets the floor; with nothing named, the scene's furniture scaled.
    let area = if named_inst.is_empty() {
        full[0] * full[1] * scale
    } else {
        need.min(full[0] * full[1])
    };
    let [w, d] = sides_within(area, min_side);
    [w, d, full[2]]
}

/// The floor of a place whose kind fixes it (`kb/scenes.txt`, seventh field: a balcony is
/// 3.6 x 1.8 m): scaled up by "large" (never down: the kind is already small), grown to what the
/// named objects need in use, its longest side never shorter than the longest of them with a
/// walkway. The defaults are then trimmed to fit by `capacity::fit`.
fn kind_floor(
    spec: &SceneSpec,
    named: &BTreeSet<String>,
    floor: [f64; 2],
    scale: f64,
    full: [f64; 3],
) -> [f64; 3] {
    let s = scale.max(1.0).sqrt();
    let [mut w, mut d] = floor.map(|v| v * s);
    let margin = crate::plan::capacity::USE_MARGIN;
    let named_inst: Vec<_> = spec
        .instances()
        .into_iter()
        .filter(|i| named.contains(&i.category) && i.size[2] >= 0.05)
        .collect();
    let need: f64 = named_inst
        .iter()
        .map(|i| (i.size[0] + margin) * (i.size[1] + margin))
        .sum::<f64>()
        / 0.5;
    if need > w * d {
        let k = (need / (w * d)).sqrt();
        (w, d) = (w * k, d * k);
    }
    let longest = named_inst
        .iter()
        .map(|i| i.size[0].max(i.size[1]))
        .fold(0.0, f64::max);
    w = w.max(longest + 0.4);
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    [r(w), r(d), full[2]]
}

/// Sides of a floor of `area` (a little longer than deep), each rounded up to the 10 cm and
/// never below `min_side`: the floor keeps at least the room its furniture needs.
fn sides_within(area: f64, min_side: f64) -> [f64; 2] {
    let w = (area * 1.25).sqrt().max(min_side);
    let d = (area / w).max(min_side);
    let r = |v: f64| (v * 10.0).ceil() / 10.0;
    [r(w), r(d)]
}

/// Largest footprint side and height of a small unknown thing on a support (m).
const TABLETOP: [f64; 2] = [0.25, 0.25];

/// Size of an object the knowledge base lacks: from its head noun's category when it has one,
/// else from a size class named by its words.
fn unknown_size(kb: &KnowledgeBase, name: &str) -> ([f64; 3], String) {
    let words: Vec<&str> = name.split(' ').collect();
    for k in (0..words.len()).rev() {
        if let Some(o) = kb.object(words[k]) {
            return (o.size, format!("sized as a {}", o.category));
        }
    }
    // WordNet: "a divan" is a kind of sofa, "an owl" a small thing
    let head = words.last().copied().unwrap_or("");
    let kind = crate::plan::lexicon::kind(head);
    if let Some(crate::plan::lexicon::Kind::Category(c)) = kind {
        if let Some(o) = kb.object(c) {
            return (o.size, format!("sized as a {c}, its kind in WordNet"));
        }
    }
    let wn_class = match kind {
        Some(crate::plan::lexicon::Kind::Size(class)) => class,
        _ => "",
    };
    let has = |ws: &[&str]| words.iter().any(|w| ws.contains(w));
    let (size, class) = if has(&["small", "tiny", "little", "mini", "miniature"]) {
        ([0.35, 0.35, 0.4], "small")
    } else if has(&[
        "large", "big", "huge", "giant", "enormous", "massive", "tall",
    ]) {
        ([1.5, 1.0, 1.6], "large")
    } else if wn_class == "small" {
        ([0.35, 0.35, 0.4], "small")
    } else if wn_class == "large" {
        ([1.5, 1.0, 1.6], "large")
    } else {
        ([0.7, 0.6, 0.9], "medium")
    };
    (
        size,
        format!("sized as a {class} object {}", fmt_size(size)),
    )
}

fn fmt_size(s: [f64; 3]) -> String {
    format!("{} x {} x {} m", s[0], s[1], s[2])
}

#[cfg(test)]
mod tests {
    use super::rows_room;

    #[test]
    fn rows_that_deepen_a_room_narrow_it_to_keep_its_area() {
        // deeper for the rows: the width gives back the area, down to the rows' width
        let r = rows_room([8.9, 8.9, 2.8], [5.7, 12.2]);
        assert_eq!(r[1], 12.2);
        assert!(r[0] >= 5.7 && r[0] * r[1] <= 8.9 * 8.9 + 1.0, "{r:?}");
        assert!((r[0] - 6.5).abs() < 0.05, "{r:?}");
        assert!(r[0] >= 5.7 + super::ROWS_SLACK, "{r:?}");
        // never below what the rows need, with some room beside
        assert_eq!(
            rows_room([9.0, 8.0, 2.8], [7.5, 20.0])[0],
            7.5 + super::ROWS_SLACK
        );
        assert_eq!(rows_room([7.8, 8.0, 2.8], [7.5, 20.0])[0], 7.8);
        // both sides grow: nothing to give back
        assert_eq!(rows_room([5.0, 5.0, 2.8], [6.0, 7.0]), [6.0, 7.0, 2.8]);
        // the rows fit: unchanged
        assert_eq!(rows_room([6.0, 7.0, 2.8], [4.0, 5.0]), [6.0, 7.0, 2.8]);
        // wider for the rows: the depth gives back
        let r = rows_room([6.0, 6.0, 2.8], [9.0, 3.0]);
        assert_eq!(r[0], 9.0);
        assert!((r[1] - 4.0).abs() < 0.05, "{r:?}");
        let r = rows_room([6.0, 6.0, 2.8], [9.0, 3.8]);
        assert!((r[1] - 4.4).abs() < 0.05, "{r:?}");
    }
}
