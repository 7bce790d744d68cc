//! Pairs the placement table makes before the search: a thing on a support its class does not
//! name rests on a neighbouring support it names (a bedside lamp said to be "on" the bed stands
//! on a nightstand by it), and a screen and a sofa-like seat that face nothing face each other
//! (kb/placement.txt's `faces` lines), at a viewing distance: in a room deeper than that, the
//! seat leaves its wall.
use super::classes::{base, Placements};
use super::WALL_MARGIN;
use crate::plan::spec::{Anchor, Relation, RelationKind, SceneSpec, SceneType};

/// Centre-to-centre distances of a seat and what it faces (OPPOSITE) that furnishers keep:
/// a sofa about 2-3 m from its TV (m).
pub(super) const VIEW_NEAR: f64 = 1.6;
pub(super) const VIEW_FAR: f64 = 3.2;
use std::collections::BTreeMap;

/// A thing OVER a support its placement class does not name, when a support it names stands
/// related to that one (a nightstand FLANKing the bed), moves onto the least loaded of those.
pub(super) fn to_named_neighbour(spec: &mut SceneSpec) {
    let table = Placements::builtin();
    let mut load: BTreeMap<String, usize> = BTreeMap::new();
    for r in &spec.relations {
        if r.relation == RelationKind::Over {
            *load.entry(r.object.clone()).or_default() += 1;
        }
    }
    for k in 0..spec.relations.len() {
        let r = &spec.relations[k];
        if r.relation != RelationKind::Over {
            continue;
        }
        let Some(p) = table.get(base(&r.subject)) else {
            continue;
        };
        let names = |id: &str| p.supports.iter().any(|s| s == base(id));
        if p.supports.is_empty() || names(&r.object) {
            continue;
        }
        let on = r.object.clone();
        let mut near: Vec<String> = spec
            .relations
            .iter()
            .filter(|q| q.relation != RelationKind::Over)
            .filter_map(|q| {
                if q.object == on {
                    Some(q.subject.clone())
                } else if q.subject == on {
                    Some(q.object.clone())
                } else {
                    None
                }
            })
            .filter(|id| names(id))
            .collect();
        near.sort();
        near.dedup();
        let Some(to) = near
            .into_iter()
            .min_by_key(|id| load.get(id).copied().unwrap_or(0))
        else {
            continue;
        };
        *load.entry(on).or_default() -= 1;
        *load.entry(to.clone()).or_default() += 1;
        spec.relations[k].object = to;
    }
}

/// Instance ids of the categories of `spec` named in `list`, in the list's order.
fn instances(spec: &SceneSpec, list: &[String]) -> Vec<String> {
    list.iter()
        .filter_map(|c| spec.objects.get(c).map(|o| (c, o.number)))
        .flat_map(|(c, n)| (1..=n).map(move |m| format!("{c}{m}")))
        .collect()
}

/// For each `faces` line of the table: a screen of the scene (or the stand it rests on) that
/// faces nothing and a seat of the line that faces nothing and is no member of a group (rows,
/// a table's seats) nor anchored at a window, face each other: the seat OPPOSITE the screen.
pub(super) fn face_screens(spec: &mut SceneSpec) {
    let opposite = |spec: &SceneSpec, id: &str| {
        spec.relations
            .iter()
            .any(|r| r.relation == RelationKind::Opposite && (r.subject == id || r.object == id))
    };
    for (seats, screens) in &Placements::builtin().faces {
        let seats = instances(spec, seats);
        for screen in instances(spec, screens) {
            // a screen on a stand is faced through its stand (the stand's front is the screen's)
            let target = spec
                .relations
                .iter()
                .find(|r| r.subject == screen && r.relation == RelationKind::Over)
                .map_or(screen.clone(), |r| r.object.clone());
            if opposite(spec, &screen) || opposite(spec, &target) {
                continue;
            }
            let free = seats.iter().find(|s| {
                !opposite(spec, s)
                    && !matches!(
                        spec.anchors.get(*s),
                        Some(Anchor::FaceWindow | Anchor::Window | Anchor::Door | Anchor::FaceDoor)
                    )
                    && !spec
                        .relations
                        .iter()
                        .any(|r| r.subject == **s && super::score::is_group(r.relation))
            });
            if let Some(seat) = free {
                spec.relations.push(Relation {
                    subject: seat.clone(),
                    relation: RelationKind::Opposite,
                    object: target,
                });
            }
        }
    }
}

/// The least room side that lets a seat of a `faces` line among `cats` face its screen (also
/// among them) across the room at the nearest viewing distance, both against walls: 0 when
/// `cats` hold no such pair (a loveseat and a TV: 1.6 m between centres, and their half-depths).
pub fn viewing_side(spec: &SceneSpec, cats: &std::collections::BTreeSet<String>) -> f64 {
    let depth = |c: &str| spec.objects.get(c).map(|o| o.size[1]);
    Placements::builtin()
        .faces
        .iter()
        .flat_map(|(seats, targets)| {
            seats
                .iter()
                .flat_map(move |s| targets.iter().map(move |t| (s, t)))
        })
        .filter(|(s, t)| cats.contains(*s) && cats.contains(*t))
        .filter_map(|(s, t)| Some(VIEW_NEAR + 0.5 * (depth(s)? + depth(t)?) + 2.0 * WALL_MARGIN))
        .fold(0.0, f64::max)
}

/// A seat of a `faces` line standing against a wall (SIDE) OPPOSITE a thing against a wall,
/// in an indoor room where the two would stand further apart than [`VIEW_FAR`] across even its
/// shorter side, leaves its wall (anchor OTHERS): it stands at a viewing distance from what it
/// faces, its back to the room (a sofa floated before its TV in a large living room).
pub(super) fn float_seats(spec: &mut SceneSpec, room: [f64; 3]) {
    if spec.scene_type != SceneType::Indoor {
        return;
    }
    let seats: Vec<&String> = Placements::builtin()
        .faces
        .iter()
        .flat_map(|(s, _)| s)
        .collect();
    let depth = |spec: &SceneSpec, id: &str| spec.size_of(id).map_or(0.0, |s| s[1]);
    let mut floated = vec![];
    for r in &spec.relations {
        if r.relation != RelationKind::Opposite {
            continue;
        }
        for (seat, other) in [(&r.subject, &r.object), (&r.object, &r.subject)] {
            let side = |id: &str| spec.anchors.get(id) == Some(&Anchor::Side);
            if !seats.iter().any(|c| *c == base(seat)) || !side(seat) || !side(other) {
                continue;
            }
            let apart = room[0].min(room[1])
                - 2.0 * WALL_MARGIN
                - 0.5 * (depth(spec, seat) + depth(spec, other));
            if apart > VIEW_FAR {
                floated.push(seat.clone());
            }
        }
    }
    for id in floated {
        spec.anchors.insert(id, Anchor::Others);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use super::super::classes::tests::spec;

    fn triples(s: &SceneSpec) -> Vec<(String, RelationKind, String)> {
        s.relations
            .iter()
            .map(|r| (r.subject.clone(), r.relation, r.object.clone()))
            .collect()
    }

    #[test]
    fn a_lamp_said_on_the_bed_stands_on_a_nightstand_by_it() {
        let mut s = spec(
            &["bed", "nightstand", "table lamp"],
            "",
            r#"{"subject":"table lamp1","relation":"OVER","object":"bed1"},
               {"subject":"nightstand1","relation":"FLANK","object":"bed1"}"#,
        );
        to_named_neighbour(&mut s);
        let t = triples(&s);
        assert!(
            t.contains(&(
                "table lamp1".into(),
                RelationKind::Over,
                "nightstand1".into()
            )),
            "{t:?}"
        );
        // with no named support by it, it stays where the sentence put it
        let mut s = spec(
            &["bed", "table lamp"],
            "",
            r#"{"subject":"table lamp1","relation":"OVER","object":"bed1"}"#,
        );
        to_named_neighbour(&mut s);
        assert_eq!(s.relations[0].object, "bed1");
    }

    #[test]
    fn a_sofa_and_a_screen_that_face_nothing_face_each_other() {
        let mut s = spec(&["sofa", "tv"], "", "");
        face_screens(&mut s);
        assert_eq!(
            triples(&s),
            [("sofa1".into(), RelationKind::Opposite, "tv1".into())]
        );
        // a TV on a stand is faced through the stand
        let mut s = spec(
            &["sofa", "tv", "tv stand"],
            "",
            r#"{"subject":"tv1","relation":"OVER","object":"tv stand1"}"#,
        );
        face_screens(&mut s);
        assert!(triples(&s).contains(&(
            "sofa1".into(),
            RelationKind::Opposite,
            "tv stand1".into()
        )));
        // a pair the sentence made is kept as it is
        let rel = r#"{"subject":"tv1","relation":"OPPOSITE","object":"armchair1"}"#;
        let mut s = spec(&["sofa", "tv", "armchair"], "", rel);
        face_screens(&mut s);
        assert_eq!(s.relations.len(), 1);
        // a sofa facing the window keeps it
        let mut s = spec(&["sofa", "tv"], r#""sofa1":"FACE_WINDOW""#, "");
        face_screens(&mut s);
        assert!(s.relations.is_empty());
    }
}
