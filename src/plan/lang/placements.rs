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
    let object_after = |ms: &[Mention], pos: usize| -> Option<usize> {
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
            r"\b(?:against|along|by|on|lining|lined up along|up against) (?:one|a|the|each|both|all|every|two|three|four|opposite) (?:walls?|sides?)\b|\bwall-mounted\b|\bagainst the walls?\b|\balong the walls?\b",
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
