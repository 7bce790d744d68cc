//! Placement phrases of a request: relations between the objects it names ("faces", "around",
//! "on either side of", "at the foot of", "between ... and ...") and anchors ("along the wall",
//! "in the corner", "in the middle").
use super::{is_adjective, re, Mention, Reading};
use crate::plan::spec::{Anchor, RelationKind};

/// Relation and anchor phrases between the mentions.
pub(super) fn read_placements(r: &mut Reading) {
    let t = r.text.clone();
    let clause_start = |pos: usize| {
        t[..pos]
            .rfind(['.', ';', '!', '?'])
            .map(|i| i + 1)
            .unwrap_or(0)
    };
    let subject_before = |ms: &[Mention], pos: usize| -> Option<usize> {
        let cs = clause_start(pos);
        ms.iter()
            .enumerate()
            .rev()
            .find(|(_, m)| m.end <= pos && m.start >= cs && !m.negated)
            .map(|(i, _)| i)
    };
    let named_after = |ms: &[Mention], pos: usize| -> Option<usize> {
        ms.iter()
            .enumerate()
            .find(|(_, m)| {
                m.start >= pos
                    && !m.negated
                    && t[pos..m.start].split_whitespace().all(|w| {
                        is_adjective(w)
                            || [
                                "the", "a", "an", "its", "their", "each", "every", "one", "two",
                            ]
                            .contains(&w)
                    })
            })
            .map(|(i, _)| i)
    };
    let object_after = |ms: &[Mention], pos: usize| -> Option<usize> {
        referent(ms, &t, pos).or_else(|| named_after(ms, pos))
    };
    let mut used: Vec<(usize, usize)> = vec![];
    let phrases: &[(&str, Option<RelationKind>)] = &[
        (
            r"\b(?:on )?(?:either|both|each) sides? of\b",
            Some(RelationKind::Flank),
        ),
        (r"\bflank(?:s|ed|ing)?\b", Some(RelationKind::Flank)),
        (r"\bat the (?:foot|end) of\b", Some(RelationKind::Front)),
        (r"\bat the head of\b", Some(RelationKind::Behind)),
        (r"\bin front of\b", Some(RelationKind::Front)),
        (r"\b(?:to the left of|left of)\b", Some(RelationKind::Left)),
        (
            r"\b(?:to the right of|right of)\b",
            Some(RelationKind::Right),
        ),
        (
            r"\b(?:on top of|on|atop|upon|sitting on|standing on|resting on)\b",
            Some(RelationKind::Over),
        ),
        (
            r"\b(?:under|beneath|below|underneath)\b",
            Some(RelationKind::Under),
        ),
        (
            r"\b(?:around|round|surrounding|encircling|circling)\b",
            Some(RelationKind::Around),
        ),
        (
            r"\b(?:at|pulled up to|tucked under)\b",
            Some(RelationKind::At),
        ),
        (
            r"\b(?:next to|beside|alongside|near|close to|by|between)\b",
            Some(RelationKind::Next),
        ),
        (
            r"\b(?:opposite(?: to| of)?|across from|faces|facing|face|looking at|pointed at|towards|toward)\b",
            Some(RelationKind::Opposite),
        ),
        (r"\b(?:behind|in back of)\b", Some(RelationKind::Behind)),
        // "a painting above the piano": over it (a thing hung on the wall keeps its wall)
        (
            r"\b(?:above|right above|just above)\b",
            Some(RelationKind::Over),
        ),
    ];
    let anchor_phrases: &[(&str, Anchor)] = &[
        (
            r"\b(?:facing|faces|face|looking out(?: of)?|looking at|looks out(?: of)?|turned to(?:wards?)?|towards?) (?:the |a |one of the )?(?:big |large |bay |front |tall |wide )?windows?\b",
            Anchor::FaceWindow,
        ),
        (
            r"\b(?:by|near|under|beneath|below|beside|next to|in front of|at|close to|against|in) (?:the |a |one of the )?(?:big |large |bay |front |tall |wide )?windows?\b",
            Anchor::Window,
        ),
        (
            r"\b(?:by|near|beside|next to|at|close to|inside|behind) (?:the )?(?:front |main |entrance |back )?door(?:way)?\b",
            Anchor::Door,
        ),
        (
            r"\b(?:centered|centred|in the (?:center|centre|middle)(?: of the room)?)\b",
            Anchor::Center,
        ),
        (
            r"\b(?:against|along|by|on|lining|lined up along|up against) (?:one|a|the|each|both|all|every|two|three|four|opposite) (?:(?:(?:back|front|far|end|side|rear|left|right|other|main|opposite|near) )?walls?|sides?)\b|\bwall-mounted\b|\bagainst the walls?\b|\balong the walls?\b",
            Anchor::Side,
        ),
        (
            r"\bin (?:the|a|one|each|every|all|two|three|four|opposite)(?: the)? corners?\b",
            Anchor::Corner,
        ),
    ];
    for (p, a) in anchor_phrases {
        for m in re(p).find_iter(&t) {
            // "along one side of it", "in the corner of the bar": a part of an object, no wall
            if t[m.end()..].starts_with(" of ")
                && !t[m.end()..].starts_with(" of the room")
                && *a != Anchor::Center
            {
                continue;
            }
            if let Some(s) = subject_before(&r.mentions, m.start()) {
                r.anchors.push((s, *a));
                used.push((m.start(), m.end()));
            }
        }
    }
    for (p, rel) in phrases {
        let Some(rel) = rel else { continue };
        for m in re(p).find_iter(&t) {
            if used.iter().any(|&(s, e)| m.start() < e && s < m.end()) {
                continue;
            }
            let Some(s) = subject_before(&r.mentions, m.start()) else {
                continue;
            };
            let Some(o) = object_after(&r.mentions, m.end()) else {
                continue;
            };
            used.push((m.start(), m.end()));
            if r.mentions[s].category == r.mentions[o].category {
                continue;
            }
            r.relations.push((s, *rel, o));
            if m.as_str() == "between" {
                // "between the sofa and the armchair": next to both
                if let Some(o2) = r.mentions.get(o + 1) {
                    if t[r.mentions[o].end..o2.start].trim().starts_with("and") {
                        r.relations.push((s, RelationKind::Next, o + 1));
                    }
                }
            }
        }
    }
}

/// The object a pronoun or a part word right after `pos` refers to: "it" / "them" is the last
/// object named before the phrase's subject ("a painting hanging above it"), a part word of
/// `kb/words.txt` (parts) the last object named that has such a part ("facing the fire" faces
/// the fireplace, "above the mantel" is above it).
fn referent(ms: &[Mention], t: &str, pos: usize) -> Option<usize> {
    let rest = t.get(pos..)?;
    let mut words = rest
        .split(|c: char| !c.is_alphanumeric() && c != '\'' && c != '-')
        .filter(|w| !w.is_empty());
    let mut w = words.next()?;
    if ["it", "them"].contains(&w) {
        // the subject is the last mention before `pos`; the antecedent the one before it and
        // the things said with it ("a desk with a computer and a lamp on it": the desk)
        let before: Vec<usize> = (0..ms.len())
            .filter(|&i| ms[i].end <= pos && !ms[i].negated)
            .collect();
        let mut k = before.len().checked_sub(2)?;
        while k > 0 {
            let between = t.get(ms[before[k]].end..ms[before[k + 1]].start)?;
            let joined = between
                .split(|c: char| !c.is_alphanumeric())
                .filter(|w| !w.is_empty())
                .all(|w| {
                    ["and", "or", "a", "an", "the", "some"].contains(&w)
                        || super::number(w).is_some()
                });
            if !joined {
                break;
            }
            k -= 1;
        }
        return before.get(k).copied();
    }
    while ["the", "a", "an", "its", "their"].contains(&w) {
        w = words.next()?;
    }
    // a word that is itself (part of) a named object is no part word
    let at = pos + rest.find(w)?;
    if ms.iter().any(|m| m.start <= at && at < m.end) {
        return None;
    }
    let owners = super::part_owners(w)?;
    (0..ms.len()).rev().find(|&i| {
        ms[i].end <= pos && !ms[i].negated && owners.iter().any(|o| *o == ms[i].category)
    })
}
