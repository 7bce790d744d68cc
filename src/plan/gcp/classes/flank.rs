//! Flanking carried by supports: a thing that rests on a support and is asked on each side of
//! a piece on the floor ("a lamp on each side of the sofa") has its support stand flush beside
//! the piece, and rides on it.
use super::{base, effective_class, Class};
use crate::plan::spec::{Relation, RelationKind, SceneSpec};

/// A thing resting on a support that FLANKs a piece on the floor ("a lamp on each side of the
/// sofa": a table lamp on a side table) leaves the flanking to its support: the support stands
/// flush beside the piece and the thing rests on it. A support already flanking that piece, or
/// one the piece itself stands on (a vase beside the TV on its stand), leaves the relation as
/// it is.
pub(super) fn flank_with_support(spec: &mut SceneSpec, carried: &[(String, String)]) {
    for (id, sup) in carried {
        let flanked: Vec<String> = spec
            .relations
            .iter()
            .filter(|r| r.subject == *id && r.relation == RelationKind::Flank)
            .map(|r| r.object.clone())
            .collect();
        for piece in flanked {
            let shared = piece == *sup
                || spec.relations.iter().any(|r| {
                    r.relation == RelationKind::Over
                        && ((r.subject == piece && r.object == *sup)
                            || (r.subject == *sup && r.object == piece))
                });
            if shared
                || !matches!(
                    effective_class(spec, base(&piece)),
                    Class::Floor | Class::AgainstWall
                )
            {
                continue;
            }
            spec.relations.retain(|r| {
                !(r.subject == *id && r.relation == RelationKind::Flank && r.object == piece)
            });
            let already = spec.relations.iter().any(|r| {
                r.subject == *sup && r.relation == RelationKind::Flank && r.object == piece
            });
            if !already {
                // the support's looser tie to the piece (NEXT) gives way to the flanking
                spec.relations.retain(|r| {
                    !(r.subject == *sup && r.relation == RelationKind::Next && r.object == piece)
                });
                spec.relations.push(Relation {
                    subject: sup.clone(),
                    relation: RelationKind::Flank,
                    object: piece,
                });
            }
        }
    }
}
