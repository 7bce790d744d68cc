//! What `edit add` is asked for when the description says where it goes: "a green armchair next
//! to the bookshelf" is an armchair placed NEXT to the scene's bookshelf (not a third
//! bookshelf), "a lamp on the desk" one OVER the desk, "a plant in the corner" one anchored in a
//! corner. The request reader of `plan` reads the description, so the same phrases mean the same
//! thing in a prompt and in an edit.
use crate::plan::kb::KnowledgeBase;
use crate::plan::spec::{Anchor, RelationKind};

/// An `add` description read whole.
#[derive(Debug, Clone, PartialEq)]
pub struct Wanted {
    /// The thing to add as said, without where it goes ("a green armchair").
    pub what: String,
    /// Where it goes relative to a thing of the scene: that thing as said ("the bookshelf", or
    /// its id when the description names one: "next to bookshelf2") and the relation.
    pub partner: Option<(String, RelationKind)>,
    /// Where it goes in the room ("in the corner", "by the window").
    pub anchor: Option<Anchor>,
}

/// Reads `description` (already without its count); `ids` are the scene's instances with their
/// categories, so that an id said in it ("next to bookshelf2") is that instance.
pub fn read(description: &str, ids: &[(String, String)]) -> Wanted {
    let kb = KnowledgeBase::builtin();
    // an id said in the description reads as its category's name, and is the partner if the
    // partner is of its category
    let lower = description.to_lowercase();
    let named = ids
        .iter()
        .filter(|(id, _)| {
            let id = id.to_lowercase();
            lower.match_indices(&id).any(|(at, _)| {
                let before = lower[..at].chars().next_back();
                let after = lower[at + id.len()..].chars().next();
                !before.is_some_and(char::is_alphanumeric)
                    && !after.is_some_and(char::is_alphanumeric)
            })
        })
        .max_by_key(|(id, _)| id.len());
    let text = match named {
        Some((id, cat)) => lower.replacen(&id.to_lowercase(), &format!("the {cat}"), 1),
        None => lower.clone(),
    };
    let r = crate::plan::lang::read(kb, &text);
    let whole = Wanted {
        what: description.trim().to_string(),
        partner: None,
        anchor: None,
    };
    let Some(first) = r.mentions.iter().position(|m| !m.negated) else {
        return whole;
    };
    let anchor = r.anchors.iter().find(|(i, _)| *i == first).map(|&(_, a)| a);
    let partner = r
        .relations
        .iter()
        .find(|(s, _, o)| *s == first && *o != first)
        .and_then(|&(_, kind, o)| {
            let m = r.mentions.get(o)?;
            let said = match named {
                Some((id, cat)) if *cat == m.category => id.clone(),
                _ => r.text.get(m.start..m.end)?.to_string(),
            };
            Some((said, kind))
        });
    if partner.is_none() && anchor.is_none() {
        return whole;
    }
    let m = &r.mentions[first];
    let what = r.text.get(..m.end).unwrap_or(&r.text).trim().to_string();
    Wanted {
        what,
        partner,
        anchor,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ids() -> Vec<(String, String)> {
        [
            ("bookshelf1", "bookshelf"),
            ("bookshelf2", "bookshelf"),
            ("desk1", "desk"),
        ]
        .iter()
        .map(|(a, b)| (a.to_string(), b.to_string()))
        .collect()
    }

    fn read(description: &str) -> Wanted {
        super::read(description, &ids())
    }

    #[test]
    fn an_id_said_is_the_partner() {
        let w = read("a green armchair next to bookshelf2");
        assert_eq!(w.what, "a green armchair");
        assert_eq!(
            w.partner,
            Some(("bookshelf2".to_string(), RelationKind::Next))
        );
    }

    #[test]
    fn where_it_goes_is_read_apart_from_what_it_is() {
        let w = read("a green armchair next to the bookshelf");
        assert_eq!(w.what, "a green armchair");
        assert_eq!(
            w.partner.as_ref().map(|p| p.1),
            Some(RelationKind::Next),
            "{w:?}"
        );
        assert!(w.partner.unwrap().0.contains("bookshelf"));
        let w = read("a table lamp on the desk");
        assert_eq!(w.partner.map(|p| p.1), Some(RelationKind::Over));
        let w = read("a potted plant in the corner");
        assert_eq!(w.anchor, Some(Anchor::Corner), "{w:?}");
        assert_eq!(w.what, "a potted plant");
        let w = read("a red leather armchair");
        assert_eq!(w.what, "a red leather armchair");
        assert!(w.partner.is_none() && w.anchor.is_none());
    }
}
