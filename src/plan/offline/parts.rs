//! Things named only as what seats face, where a planned thing has one as a part (kb/roles.txt:
//! has): "barber chairs facing mirrors" in a hair salon sit one at each styling station (the
//! seat's place at it, kb/groups.txt), and the mirrors the text asks for hang on the wall
//! above the stations, one above each, so each chair faces its mirror. Mirrors the text asks
//! for as things of their own ("and two mirrors") are left as they are.
use super::Draft;
use crate::plan::spec::{Relation, RelationKind, SceneSpec};

/// The relations by which a seat is said to face what it is used at.
const FACING: [RelationKind; 3] = [
    RelationKind::Opposite,
    RelationKind::Front,
    RelationKind::At,
];

/// The category of an instance id (`mirror2` -> `mirror`).
fn base(id: &str) -> &str {
    id.trim_end_matches(|c: char| c.is_ascii_digit())
}

/// Turns each "seat facing part" relation, where a planned category has the part and the seat
/// its place at that category, into the seat at an instance of that category (one seat a
/// station) and the part hung above it (one part a station when the text gives no count).
pub(super) fn seats_at_parts(d: &Draft, spec: &mut SceneSpec) {
    let mut pairs: Vec<(String, String, String, RelationKind)> = spec
        .relations
        .iter()
        .filter(|r| FACING.contains(&r.relation))
        .filter_map(|r| {
            let (seat, part) = (base(&r.subject), base(&r.object));
            let whole = spec
                .objects
                .keys()
                .find(|w| *w != part && crate::plan::roles::has_part(w, part))?;
            let g = crate::plan::groups::relation_between(seat, whole)?;
            Some((seat.to_string(), part.to_string(), whole.clone(), g))
        })
        .collect();
    pairs.sort();
    pairs.dedup();
    for (seat, part, whole, g) in pairs {
        let n_whole = spec.objects[&whole].number;
        let n_seat = spec.objects[&seat].number.min(n_whole);
        if !d.explicit.contains_key(&part) {
            set_number(spec, &part, n_seat.max(1));
        }
        let n_part = spec.objects[&part].number;
        // the seats at the stations face the parts there, by their place at the stations
        spec.relations.retain(|r| {
            let (s, o) = (base(&r.subject), base(&r.object));
            !(s == seat && (o == part || o == whole) && index(&r.subject) <= n_seat)
        });
        for k in 1..=n_seat {
            spec.relations.push(Relation {
                subject: format!("{seat}{k}"),
                relation: g,
                object: format!("{whole}{k}"),
            });
        }
        for k in 1..=n_part.min(n_whole) {
            spec.relations.push(Relation {
                subject: format!("{part}{k}"),
                relation: RelationKind::Over,
                object: format!("{whole}{k}"),
            });
        }
    }
}

/// Sets the number of `cat` to `n`: anchors for the instances added (as the first's), and
/// the anchors and relations of those gone removed.
fn set_number(spec: &mut SceneSpec, cat: &str, n: u32) {
    let Some(o) = spec.objects.get_mut(cat) else {
        return;
    };
    let had = o.number;
    o.number = n;
    if let Some(&a) = spec.anchors.get(&format!("{cat}1")) {
        for k in had + 1..=n {
            spec.anchors.insert(format!("{cat}{k}"), a);
        }
    }
    for k in n + 1..=had {
        spec.anchors.remove(&format!("{cat}{k}"));
    }
    spec.relations.retain(|r| {
        let gone = |id: &str| base(id) == cat && index(id) > n;
        !gone(&r.subject) && !gone(&r.object)
    });
}

/// The 1-based index of an instance id (`mirror2` -> 2).
fn index(id: &str) -> u32 {
    id[base(id).len()..].parse().unwrap_or(0)
}
