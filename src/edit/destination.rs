//! Where a move sentence sends an instance when it names a place rather than a motion: "under
//! the window", "to the window", "next to the door", "into the corner", "against the wall". The
//! sentence is read by the request reader of `plan` (through [`super::wanted`], as `add` reads
//! "a plant in the corner"), so a place means the same thing in a prompt, an add and a move. The
//! instance is then placed by GCP at that anchor (or in the relation said to another instance),
//! every other instance pinned; its old relations are left to `move`, which brings the partners
//! along (the chair at a desk follows the desk).
use super::ops::{replace_partners, Pose};
use super::state::SceneState;
use super::wanted::{read, Wanted};
use super::{EditError, Result};
use crate::plan::spec::{Anchor, Relation};

/// A place a move sentence names, read for instance `id`.
#[derive(Debug, Clone, PartialEq)]
pub struct Destination {
    /// The room anchor said ("under the window": WINDOW).
    pub anchor: Option<Anchor>,
    /// The instance and relation said ("on the desk": desk1, OVER).
    pub partner: Option<(String, crate::plan::spec::RelationKind)>,
}

/// The place `text` sends `id` to, if it names one. The sentence is read as said ("move the
/// desk under the window") and, when it names no object, as said of the instance ("under the
/// window" of desk1 reads "the desk under the window").
pub fn destination(state: &SceneState, id: &str, text: &str) -> Option<Destination> {
    let cat = state.object(id).ok()?.category.clone();
    let ids = state.id_categories();
    let said = |w: &Wanted| {
        let partner = w.partner.as_ref().and_then(|(name, kind)| {
            let p = super::parse::resolve(name, &ids).ok()?;
            (p != id).then_some((p, *kind))
        });
        (w.anchor.is_some() || partner.is_some()).then_some(Destination {
            anchor: w.anchor,
            partner,
        })
    };
    said(&read(text, &ids)).or_else(|| said(&read(&format!("the {cat} {text}"), &ids)))
}

/// The pose GCP gives `id` at `to`, every other instance pinned where it stands; an error that
/// names the place when no free pose there keeps it.
pub fn place_at(state: &SceneState, id: &str, to: &Destination) -> Result<Pose> {
    // it goes free with its seats (the chair at a desk keeps its relation, so the desk is
    // placed with room for it); its other relations are left to `move`
    let seats = super::riders::seats(state, id);
    let mut free = state.clone();
    free.relations.retain(|r| {
        (r.subject != id && r.object != id) || (r.object == id && seats.contains(&r.subject))
    });
    if let Some(a) = to.anchor {
        free.anchors.insert(id.to_string(), a);
    }
    if let Some((p, kind)) = &to.partner {
        free.relations.push(Relation {
            subject: id.to_string(),
            relation: *kind,
            object: p.clone(),
        });
    }
    let scale = state.object(id)?.scale;
    let moving: Vec<String> = std::iter::once(id.to_string()).chain(seats).collect();
    replace_partners(&free, &moving, &[])?
        .into_iter()
        .find(|(p, _)| p == id)
        .map(|(_, pose)| Pose { scale, ..pose })
        .ok_or_else(|| {
            let place = match (&to.partner, to.anchor) {
                (Some((p, kind)), _) => format!("{kind:?} {p}"),
                (None, Some(a)) => format!("at {a:?}"),
                (None, None) => "there".into(),
            };
            EditError::Bad(format!(
                "no free pose for {id} {place} with the other objects where they stand"
            ))
        })
}
