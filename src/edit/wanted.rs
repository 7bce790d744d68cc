//! What `edit add` is asked for when the description says where it goes: "a green armchair next
//! to the bookshelf" is an armchair placed NEXT to the scene's bookshelf (not a third
//! bookshelf), "a lamp on the desk" one OVER the desk, "a plant in the corner" one anchored in a
//! corner; and what the thing is: "a desk lamp" is a lamp, on the scene's desk. The request
//! reader of `plan` reads the description, so the same phrases mean the same thing in a prompt
//! and in an edit.
use super::ops::Planned;
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

/// The instance a thing to add is named after and stands on: "a desk lamp" goes on the
/// scene's desk, when a desk can hold what `category` is (`kb/placement.txt`: supports) and
/// the scene has one. `what` is the thing as said; `ids` the scene's instances with their
/// categories (the first of the named category is chosen).
pub fn support_named(what: &str, category: &str, ids: &[(String, String)]) -> Option<String> {
    let supports = &crate::plan::gcp::classes::Placements::builtin()
        .get(category)?
        .supports;
    let said = format!(" {} ", what.to_lowercase());
    let kb = KnowledgeBase::builtin();
    ids.iter()
        .filter(|(_, c)| supports.contains(c))
        .find(|(_, c)| {
            kb.names()
                .filter(|(_, k)| k.category == *c)
                .any(|(name, _)| said.contains(&format!(" {name} ")))
        })
        .map(|(id, _)| id.clone())
}

/// Plans one object from `text` as the request reader of `plan` reads it: "a desk lamp" is a
/// lamp, "a bedroom dresser" a dresser (the place word names no object), as in a prompt. When
/// the reader names no one known object, the longest category name or synonym the text
/// contains (singular or plural).
pub fn plan_object(text: &str) -> super::Result<Planned> {
    let kb = KnowledgeBase::builtin();
    let description = if text.to_lowercase().starts_with("a dslr photo") {
        text.to_string()
    } else {
        format!(
            "A DSLR photo of {}",
            text.trim_start_matches(|c: char| c.is_whitespace())
        )
    };
    if let Some((category, size)) = read_object(text) {
        if let Some(kind) = kb.object(&category) {
            return Ok(Planned {
                category,
                size,
                anchor: kind.anchor,
                description,
            });
        }
    }
    let lower = text.to_lowercase();
    let words: Vec<&str> = lower
        .split(|c: char| !(c.is_alphanumeric() || c == '-'))
        .filter(|w| !w.is_empty())
        .collect();
    let joined = format!(" {} ", words.join(" "));
    let mut best: Option<(usize, &crate::plan::kb::ObjectKind)> = None;
    for (name, kind) in kb.names() {
        let forms = [name.to_string(), format!("{name}s"), format!("{name}es")];
        if forms.iter().any(|f| joined.contains(&format!(" {f} ")))
            && best.is_none_or(|b| name.len() > b.0)
        {
            best = Some((name.len(), kind));
        }
    }
    let Some((_, kind)) = best else {
        return Err(super::EditError::Bad(format!(
            "\"{text}\": no known object category in it (e.g. \"a floor lamp\", \"an armchair\")"
        )));
    };
    Ok(Planned {
        category: kind.category.clone(),
        size: kind.size,
        anchor: kind.anchor,
        description,
    })
}

/// The one object the offline planner reads `text` to name, with its planned size ("a tall
/// floor lamp"), if it names exactly one.
fn read_object(text: &str) -> Option<(String, [f64; 3])> {
    let p = crate::plan::offline::plan_prompt(text).ok()?;
    let named: Vec<&String> = p
        .named
        .iter()
        .filter(|c| p.spec.objects.contains_key(*c))
        .collect();
    let [c] = named[..] else {
        return None;
    };
    Some((c.clone(), p.spec.objects[c].size))
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

    #[test]
    fn a_thing_named_after_a_support_of_the_scene_stands_on_it() {
        assert_eq!(
            support_named("a desk lamp", "task lamp", &ids()),
            Some("desk1".to_string())
        );
        // no support named ("a floor lamp" stands on the floor), or none in the scene
        assert_eq!(support_named("a floor lamp", "floor lamp", &ids()), None);
        assert_eq!(support_named("a bedside lamp", "table lamp", &ids()), None);
        // the word is no support of what is added ("a desk chair" stands at it)
        assert_eq!(support_named("a desk chair", "office chair", &ids()), None);
    }

    #[test]
    fn the_thing_to_add_is_what_its_name_ends_in() {
        for (said, category) in [
            ("a desk lamp", "task lamp"),
            ("a brass desk lamp", "task lamp"),
            ("a floor lamp", "floor lamp"),
            ("a coffee table", "coffee table"),
            ("a table lamp", "table lamp"),
            ("a bedside table", "nightstand"),
            ("a bedroom dresser", "dresser"),
            ("a living room rug", "rug"),
        ] {
            let p = plan_object(said).expect("planned");
            assert_eq!(p.category, category, "{said}");
        }
    }
}
