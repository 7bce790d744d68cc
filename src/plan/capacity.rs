//! Capacity: how much furniture a room takes. Default furniture (what the scene type adds on
//! its own) is trimmed until the floor footprint is within [`TRIM_OCCUPANCY`] of the floor and
//! every piece fits the room; objects the user named are never dropped: when one cannot fit,
//! planning stops with an error naming it and the smallest room that would take it.
use super::gcp::{choose_room, smallest_room};
use super::spec::{Instance, RelationKind, Room, SceneSpec, SceneType, SpecError};
use std::collections::BTreeSet;

mod blocks;
pub(crate) use blocks::scale_blocks;

/// Largest share of the floor that footprints may cover once default furniture is trimmed:
/// Holodeck's floor capacity ratio (0.4) plus a little, as named pieces may exceed it.
pub const TRIM_OCCUPANCY: f64 = 0.45;

/// Floor a trimmed indoor room keeps free whatever its size, m²: room to stand at each piece
/// and a path from the door (a 0.8 m path across a 2.5 m room, and as much again to stand and
/// turn). In a tiny room this, not [`TRIM_OCCUPANCY`], decides how much furniture stays.
pub const FREE_FLOOR: f64 = 3.0;

/// Objects that decorate rather than furnish: trimmed first.
const DECOR: &[&str] = &[
    "potted plant",
    "floor lamp",
    "table lamp",
    "rug",
    "vase",
    "statue",
    "globe",
    "magazine rack",
    "umbrella stand",
    "trash can",
    "planter",
    "candle stand",
    "painting",
    "full length mirror",
    "speaker",
    "pedestal",
    "cardboard box",
    "laundry basket",
    "bean bag",
    "ottoman",
    "side table",
];

/// Room to use round each footprint when sizing a room for furniture in use (a chair pulled
/// out, a walk past a desk), metres added to width and depth.
pub const USE_MARGIN: f64 = 0.2;

/// A room that fits the instances of `spec` in use: [`choose_room`] on footprints grown by
/// [`USE_MARGIN`] (flat things and things standing on others too, a slight overestimate). A seat
/// round a table is pulled out into the table's own room: its bare footprint is all it adds (a
/// stool at an island or a chair at a desk keeps its own, as the counter or desk has no room
/// round it). A table with more seats round it than its long sides take has seats at its ends
/// too: its length counts them (a long table for ten is its length and two chairs long).
pub fn room_for(spec: &SceneSpec, scene: SceneType) -> Room {
    let around: Vec<(&str, &str)> = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Around && r.subject != r.object)
        .map(|r| (r.subject.as_str(), r.object.as_str()))
        .collect();
    let tucked: BTreeSet<&str> = around.iter().map(|&(s, _)| s).collect();
    let instances = spec.instances();
    let size_of = |id: &str| instances.iter().find(|i| i.id == id).map(|i| i.size);
    let grown: Vec<Instance> = instances
        .iter()
        .map(|i| {
            let mut g = i.clone();
            if !tucked.contains(i.id.as_str()) {
                g.size[0] += USE_MARGIN;
                g.size[1] += USE_MARGIN;
            }
            let seats: Vec<[f64; 3]> = around
                .iter()
                .filter(|&&(_, t)| t == i.id)
                .filter_map(|&(s, _)| size_of(s))
                .collect();
            let longer = usize::from(i.size[1] > i.size[0]);
            g.size[longer] += end_seats_length(i.size[longer], &seats);
            g
        })
        .collect();
    let mut room = choose_room(&grown, scene);
    room.size[2] = choose_room(&instances, scene).size[2];
    // a run asked along one wall: a wall long enough for it
    let run = (crate::plan::gcp::longest_run(spec) * 10.0).ceil() / 10.0;
    if run > room.size[0].max(room.size[1]) {
        room.size[0] = run;
    }
    room
}

/// What the seats at the ends of a table `length` long add to its length when the `seats`
/// round it are more than its two long sides take (a seat's width and 0.1 m each, as the layout
/// spreads them): a seat's depth and a hand's gap at each end; 0 when the sides take them all.
fn end_seats_length(length: f64, seats: &[[f64; 3]]) -> f64 {
    let wide = seats.iter().map(|s| s[0]).fold(0.0, f64::max);
    let deep = seats.iter().map(|s| s[1]).fold(0.0, f64::max);
    let side = ((length + 0.1) / (wide + 0.1)).floor().max(1.0) as usize;
    if seats.len() > 2 * side {
        2.0 * (deep + 0.05)
    } else {
        0.0
    }
}

/// Floor area the spec's instances cover: things standing on others and flat things (rugs,
/// mats) excepted.
pub fn floor_area(spec: &SceneSpec) -> f64 {
    let on_top: BTreeSet<&str> = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Over)
        .map(|r| r.subject.as_str())
        .collect();
    // what runs a whole side of the ground (the sea along a beach) is ground, not furniture
    spec.instances()
        .iter()
        .filter(|i| {
            !on_top.contains(i.id.as_str())
                && i.size[2] >= 0.05
                && !spans_ground(spec.scene_type, &i.category)
        })
        .map(|i| i.size[0] * i.size[1])
        .sum()
}

/// Whether `category` runs the whole length of a side of an outdoor ground (the sea along a
/// beach): its length is the ground's, so it is never too long for it.
fn spans_ground(scene: SceneType, category: &str) -> bool {
    scene == SceneType::Outdoor && super::gcp::classes::Placements::builtin().spans_side(category)
}

/// Whether a box of `size` fits in `room` in some quarter turn.
pub fn fits(size: [f64; 3], room: [f64; 3]) -> bool {
    let (a, b) = (size[0].max(size[1]), size[0].min(size[1]));
    let (w, d) = (room[0].max(room[1]), room[0].min(room[1]));
    a <= w + 1e-9 && b <= d + 1e-9 && size[2] <= room[2] + 1e-9
}

/// Removes the last instance of `cat` (or the category), with its anchors and relations.
/// Returns the instances that were related to it as subjects and now relate to nothing (a bar
/// stool at the island that went).
fn remove_one(spec: &mut SceneSpec, cat: &str) -> Vec<String> {
    let Some(o) = spec.objects.get_mut(cat) else {
        return vec![];
    };
    let id = format!("{cat}{}", o.number);
    if o.number > 1 {
        o.number -= 1;
    } else {
        spec.objects.remove(cat);
    }
    spec.anchors.remove(&id);
    let subjects: BTreeSet<String> = spec
        .relations
        .iter()
        .filter(|r| r.object == id && r.subject != id)
        .map(|r| r.subject.clone())
        .collect();
    spec.relations.retain(|r| r.subject != id && r.object != id);
    subjects
        .into_iter()
        .filter(|s| !spec.relations.iter().any(|r| r.subject == *s))
        .collect()
}

/// Share of the room's floor above which one piece counts as large when thinning: a 3 x 1.2 m
/// conference table in a 20 m² office is; a desk (1 m²) is not.
const LARGE_SHARE: f64 = 0.1;

/// The default category to thin next: what the place can do without before what it cannot,
/// decoration first, then furniture in no group, then a piece large for the room, then the one
/// whose instances cover the most floor; multiples lose one at a time. `None` when only named objects are left. Unless the room
/// is `crowded` (over its occupancy), only what the place can do without and what frees floor
/// (nothing standing on another piece or lying flat) is thinned: floor kept free for a room
/// the text names nothing for never costs a tiny office its desk.
pub(crate) fn next_to_trim(
    spec: &SceneSpec,
    named: &BTreeSet<String>,
    essential: &BTreeSet<String>,
    crowded: bool,
) -> Option<String> {
    let grouped: BTreeSet<String> = spec
        .relations
        .iter()
        .flat_map(|r| [base(&r.subject), base(&r.object)])
        .collect();
    let on_top: BTreeSet<String> = spec
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Over)
        .map(|r| base(&r.subject))
        .collect();
    // a single piece that takes a large share of the floor (a tiny office's conference
    // table) goes before one of many smaller ones: it frees the most room for the least loss
    let floor = spec.room.map_or(f64::INFINITY, |r| r.size[0] * r.size[1]);
    let key = |c: &str, o: &super::spec::ObjectSpec| {
        let large = o.size[0] * o.size[1] > LARGE_SHARE * floor;
        (
            !essential.contains(c) as u8,
            DECOR.contains(&c) as u8,
            !grouped.contains(c) as u8,
            if large { 2u8 } else { (o.number > 1) as u8 },
            o.number as f64 * o.size[0] * o.size[1],
        )
    };
    spec.objects
        .iter()
        .filter(|(c, _)| !named.contains(*c) && (crowded || !essential.contains(*c)))
        .filter(|(c, o)| crowded || !on_top.contains(c.as_str()) && o.size[2] >= 0.05)
        .max_by(|(ca, a), (cb, b)| {
            let (ka, kb) = (key(ca, a), key(cb, b));
            ka.0.cmp(&kb.0)
                .then(ka.1.cmp(&kb.1))
                .then(ka.2.cmp(&kb.2))
                .then(ka.3.cmp(&kb.3))
                .then(ka.4.total_cmp(&kb.4))
        })
        .map(|(c, _)| c.clone())
}

/// An instance id's category ("bar stool3" → "bar stool").
fn base(id: &str) -> String {
    id.trim_end_matches(|c: char| c.is_ascii_digit())
        .to_string()
}

/// Removes one instance of the default `c`, and with it every default (not essential) left
/// relating to nothing (the bar stools of an island that went); counts them in `dropped`.
pub(crate) fn trim_one(
    spec: &mut SceneSpec,
    c: &str,
    named: &BTreeSet<String>,
    essential: &BTreeSet<String>,
    dropped: &mut std::collections::BTreeMap<String, u32>,
) {
    let mut gone = vec![c.to_string()];
    while let Some(c) = gone.pop() {
        let orphans = remove_one(spec, &c);
        *dropped.entry(c).or_default() += 1;
        gone.extend(
            orphans
                .iter()
                .map(|id| base(id))
                .filter(|o| !named.contains(o) && !essential.contains(o)),
        );
    }
}

/// Trims default furniture of `spec` (its room set) to fit; `trim` also to the occupancy and the
/// free floor (a room the user stated or asked small), the `essential` defaults (what the place
/// cannot do without) last and only to the occupancy. Returns one note per trimmed category; an error when a named object is larger
/// than the room.
pub fn fit(
    spec: &mut SceneSpec,
    named: &BTreeSet<String>,
    essential: &BTreeSet<String>,
    trim: bool,
) -> Result<Vec<String>, SpecError> {
    let Some(room) = spec.room else {
        return Ok(vec![]);
    };
    let mut notes = vec![];
    let mut dropped: std::collections::BTreeMap<String, u32> = Default::default();
    // Larger than the room: defaults go, named objects are refused.
    let too_big: Vec<String> = spec
        .objects
        .iter()
        .filter(|(c, o)| !fits(o.size, room.size) && !spans_ground(spec.scene_type, c))
        .map(|(c, _)| c.clone())
        .collect();
    for c in too_big {
        if named.contains(&c) {
            let s = spec.objects[&c].size;
            let need = smallest_room(spec);
            return Err(SpecError::DoesNotFit(format!(
                "{c} ({} x {} x {} m) does not fit in the {} x {} x {} m room; the smallest room that takes what the prompt names is {} x {} x {} m",
                s[0], s[1], s[2], room.size[0], room.size[1], room.size[2],
                need.size[0], need.size[1], need.size[2]
            )));
        }
        let n = spec.objects[&c].number;
        for _ in 0..n {
            let _ = remove_one(spec, &c);
        }
        *dropped.entry(c).or_default() += n;
    }
    if trim {
        let floor = room.size[0] * room.size[1];
        let share = match spec.scene_type {
            SceneType::Indoor => TRIM_OCCUPANCY,
            SceneType::Outdoor => 0.3,
        };
        // a room the text names nothing for is the place's furniture room shrunk: its
        // defaults thin to leave floor free (a room sized for named things was sized for them)
        let nothing_named = !spec.objects.keys().any(|c| named.contains(c));
        let most = match spec.scene_type {
            SceneType::Indoor if nothing_named => (share * floor).min(floor - FREE_FLOOR),
            _ => share * floor,
        };
        while floor_area(spec) > most {
            let crowded = floor_area(spec) > share * floor;
            let Some(c) = next_to_trim(spec, named, essential, crowded) else {
                break;
            };
            trim_one(spec, &c, named, essential, &mut dropped);
        }
    }
    for (c, n) in dropped {
        notes.push(format!(
            "{n} default {c} left out to fit the {} x {} m room",
            room.size[0], room.size[1]
        ));
    }
    if spec.objects.is_empty() {
        return Err(SpecError::DoesNotFit(format!(
            "nothing fits in the {} x {} x {} m room",
            room.size[0], room.size[1], room.size[2]
        )));
    }
    Ok(notes)
}
