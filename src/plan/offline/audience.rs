//! Seats the text turns to what the place's audience faces: "a media room with two sofas facing
//! a big screen", "four rows of folding chairs facing the stage". The scene's default seats set
//! facing that same thing (a home theater's theater seats OPPOSITE its screen, a hall's stacking
//! chairs in ROWs before its stage) are the audience the named seats already are, so they go
//! instead of adding to them. Named seats are never removed, nor defaults facing anything else.
use super::Draft;
use crate::plan::lang;
use crate::plan::spec::RelationKind::{self, Front, Opposite, Row};

/// The relations that set a seat facing something in front of it.
fn faces(k: RelationKind) -> bool {
    matches!(k, Front | Opposite | Row)
}

/// Removes the default seats that face what a named seat is said to face.
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
    for &(s, kind, o) in &r.relations {
        let (Some(seat), Some(target)) = (cats.get(s), cats.get(o)) else {
            continue;
        };
        let m = &r.mentions[s];
        if !faces(kind) || m.negated || m.reference || !lang::is_seat(seat) {
            continue;
        }
        let gone: Vec<String> = scene
            .relations
            .iter()
            .filter(|k| k.object == *target && faces(k.relation) && k.subject != *seat)
            .filter(|k| lang::is_seat(&k.subject) && !named.contains(&k.subject))
            .map(|k| k.subject.clone())
            .collect();
        for g in gone {
            if counts.remove(&g).is_some() {
                notes.push(format!(
                    "default {g} left out: the named {seat} turned to the {target} takes its place"
                ));
            }
        }
    }
}
