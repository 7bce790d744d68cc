//! Seats the text turns to what the place's audience faces: "a media room with two sofas facing
//! a big screen", "four rows of folding chairs facing the stage". The scene's default seats set
//! facing that same thing (a home theater's theater seats OPPOSITE its screen, a hall's stacking
//! chairs in ROWs before its stage) are the audience the named seats already are, so they go
//! instead of adding to them; named seats in rows ("rows of chairs" in a church) are the
//! audience whatever they face, in place of the defaults of the audience's role (its pews). Named
//! seats are never removed, nor defaults facing anything else.
use super::Draft;
use crate::plan::lang;
use crate::plan::spec::RelationKind::{self, Front, Opposite, Row};

/// The relations that set a seat facing something in front of it.
fn faces(k: RelationKind) -> bool {
    matches!(k, Front | Opposite | Row)
}

/// Removes the default seats that face what a named seat is said to face, and with named seats
/// in rows every default seat set facing something in rows or opposite it.
pub(super) fn named_audience(d: &mut Draft) {
    let Some(scene) = d.scene else { return };
    let Draft {
        r,
        cats,
        counts,
        named,
        notes,
        ..
    } = d;
    for (i, (m, seat)) in r.mentions.iter().zip(cats.iter()).enumerate() {
        if m.negated || m.reference || !lang::is_seat(seat) {
            continue;
        }
        let said: Vec<(RelationKind, &String)> = r
            .relations
            .iter()
            .filter(|&&(s, k, _)| s == i && faces(k))
            .filter_map(|&(_, k, o)| Some((k, cats.get(o)?)))
            .collect();
        // seats in rows are an audience whatever they face ("rows of benches facing a
        // whiteboard" in a lecture hall whose seats face its screen)
        let rows = m.rows > 0 || m.in_rows || said.iter().any(|(k, _)| *k == Row);
        let gone: Vec<(String, String)> = scene
            .relations
            .iter()
            .filter(|k| faces(k.relation) && k.subject != *seat)
            .filter(|k| lang::is_seat(&k.subject) && !named.contains(&k.subject))
            .filter(|k| {
                said.iter().any(|(_, t)| **t == k.object)
                    || (rows
                        && (matches!(k.relation, Row | Opposite)
                            || crate::plan::roles::role_of(&k.subject)
                                == Some(crate::plan::roles::AUDIENCE)))
            })
            .map(|k| (k.subject.clone(), k.object.clone()))
            .collect();
        for (g, target) in gone {
            if counts.remove(&g).is_some() {
                notes.push(format!(
                    "default {g} left out: the named {seat} turned to the {target} takes its place"
                ));
            }
        }
    }
}
