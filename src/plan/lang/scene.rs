//! The scene a request names: the earliest scene name that is no part of an object's name, the
//! scene a generic place word stands for ("a lecture hall", "a wizard's laboratory"), and what
//! makes the place not the template's own ("a haunted ballroom", "a pirate ship's hold").
use super::objects::object_matcher;
use super::place::place_phrase;
use super::{
    alternation, is_function_word, is_known_word, is_verb, number_of, plurals, word_list, Reading,
};
use crate::plan::kb::KnowledgeBase;
use regex::Regex;
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// Reads the scene of `t` into `r` (its index and span, and `not_literal`); masks its name, the
/// room size words of two words ("a box room") and the phrase of the place the text is about.
pub(super) fn read_scene(
    kb: &KnowledgeBase,
    t: &str,
    r: &mut Reading,
    masked: &mut Vec<(usize, usize)>,
) {
    // Scene: the earliest scene name (the longest at that position) that is not part of a
    // longer object name ("office" in "an office chair").
    let (scene_re, scene_of) = scene_matcher(kb);
    let (obj_re0, _) = object_matcher(kb);
    let objects: Vec<(usize, usize)> = obj_re0.find_iter(t).map(|m| (m.start(), m.end())).collect();
    // "a poker room with three card tables and a bar": past the opening noun phrase, a name
    // that is also an object's, said as one item ("a bar"), is that object, not the scene.
    let contents = [" with ", ": "]
        .iter()
        .filter_map(|d| t.find(d))
        .min()
        .filter(|&i| i > 0);
    let found: Vec<regex::Match> = scene_re.find_iter(t).collect();
    let shared = |name: &str| {
        word_list("shared_rooms")
            .iter()
            .any(|w| w.replace('_', " ") == name)
    };
    // Whether the scene name `m` names the place: no part of a longer object's name, no item
    // of the contents, no place word another noun makes another place.
    let names_place = |m: &regex::Match| {
        let inside_object = objects
            .iter()
            .any(|&(s, e)| s <= m.start() && m.end() <= e && e - s > m.end() - m.start());
        let item = contents.is_some_and(|c| m.start() > c)
            && kb.object(m.as_str()).is_some()
            && ["a", "an", "one"].contains(&t[..m.start()].split_whitespace().last().unwrap_or(""));
        // "an ice cream parlour", "a tattoo parlour": a place word that a noun before it makes
        // another place (`kb/words.txt`: qualified_places) names no scene; "a cosy parlour",
        // "grandma's parlour" is the sitting room.
        let qualified = word_list("qualified_places").contains(&m.as_str()) && {
            let w = t[..m.start()].split_whitespace().last().unwrap_or("");
            !(w.is_empty()
                || is_function_word(w)
                || is_known_word(w)
                || w.ends_with("'s")
                || crate::plan::offline::style_word(w).is_some())
        };
        // "a green velvet sofa": a colour word that is also a place's name ("a village
        // green") said before another word describes what follows, names no place
        let colour = crate::plan::colours::COLOURS
            .iter()
            .any(|(c, _)| *c == m.as_str())
            && t[m.end()..]
                .strip_prefix(' ')
                .and_then(|rest| rest.split(|c: char| !c.is_alphanumeric()).next())
                .is_some_and(|w| !w.is_empty() && !is_function_word(w) && !is_verb(w));
        !inside_object && !item && !qualified && !colour
    };
    for (k, m) in found.iter().enumerate() {
        // An owner's place ("the dentist's") said before a room any place has ("a dentist's
        // waiting room") only qualifies that room.
        if m.as_str().ends_with("'s")
            && found
                .get(k + 1)
                .is_some_and(|n| n.start() == m.end() + 1 && shared(n.as_str()))
        {
            continue;
        }
        // "a town hall meeting room", "a museum cafe": a place's name right before another
        // place's name qualifies it; the last noun is the place ("a library reading room", two
        // names of one place, is that place).
        let next = found
            .get(k + 1)
            .filter(|n| n.start() == m.end() + 1 && names_place(n));
        // (a generic place word after it is its head: "a gallery hall" is a gallery)
        let head = next.filter(|n| word_list("place_heads").contains(&n.as_str()));
        if next.is_some_and(|n| scene_of[n.as_str()] != scene_of[m.as_str()])
            && head.is_none()
            && names_place(m)
        {
            continue;
        }
        if names_place(m) {
            // "a conference hall", "a lecture hall": a generic place word (`kb/words.txt`:
            // place_heads) after a word that starts another scene's name ("conference room")
            // is that other scene; a specific one keeps its meaning ("a tiny bedroom", "the
            // school library").
            let before = t[..m.start()].trim_end();
            let word = before.rsplit(' ').next().unwrap_or("");
            // So does an owner's place: "a wizard's laboratory" is the wizard's study, not a
            // school lab; "a child's bedroom" the child's room.
            let generic = word_list("place_heads").contains(&m.as_str())
                || (word.ends_with("'s") && !shared(m.as_str()));
            // (a size word of a room is none: "a narrow hall" is a hall, no narrowboat)
            let sized = [
                "room_tiny",
                "room_small",
                "room_large",
                "room_huge",
                "room_long",
            ]
            .iter()
            .any(|l| word_list(l).contains(&word));
            let modified = (generic && !word.is_empty() && !is_function_word(word) && !sized)
                .then(|| {
                    scene_of
                        .iter()
                        .filter(|(name, _)| {
                            name.strip_prefix(word)
                                .is_some_and(|rest| rest.starts_with(' '))
                        })
                        .map(|(_, &i)| i)
                        .next()
                })
                .flatten();
            // "a convention hall": a compound head (`kb/words.txt`: compound_heads) after a
            // noun that starts no scene's name is the place that head names in a compound
            let compound = compound_head(m.as_str())
                .filter(|_| modified.is_none() && noun_before(before).is_some())
                .and_then(|c| scene_of.get(&c).copied());
            let (mut i, start) = match modified.or(compound) {
                Some(i) => (i, before.len() - word.len()),
                None => (scene_of[m.as_str()], m.start()),
            };
            // "a classroom for toddlers" is the toddler classroom: a place for whom another
            // scene's name says it is for
            let mut end = m.end();
            if let Some(who) = t[end..].strip_prefix(" for ") {
                let w = who
                    .split(|c: char| !c.is_alphanumeric())
                    .next()
                    .unwrap_or("");
                let named = format!("{} {}", super::singular(w), m.as_str());
                if let Some(&k) = scene_of.get(&named).filter(|_| !w.is_empty()) {
                    (i, end) = (k, end + " for ".len() + w.len());
                }
            }
            // "a library reading room": another name of the same place right after it is
            // part of its name
            if let Some(n) = found.get(k + 1).filter(|n| {
                n.start() == end + 1 && scene_of.get(n.as_str()).is_some_and(|&j| j == i)
            }) {
                end = n.end();
            }
            if let Some(n) = head.filter(|n| n.start() == end + 1) {
                end = n.end();
            }
            r.scene = Some((i, start, end));
            // "a dance hall", "an exhibition hall": a compound head (a noun before it) names a
            // large place of the kind, unless the kind is such a place itself (an exam hall) or
            // the head alone names it (an entrance hall is a hallway)
            let last = t[start..end].rsplit(' ').next().unwrap_or("");
            let alone = scene_of.get(last);
            r.large_place = t[start..end].contains(' ')
                && compound_head(last).is_some()
                && compound_head(kb.scenes[i].name.rsplit(' ').next().unwrap_or("")).is_none()
                && alone != Some(&i);
            masked.push((start, end));
            break;
        }
    }

    // Room words of two words ("a box room") are the room's size, not objects.
    for l in ["room_tiny", "room_small", "room_large"] {
        for w in word_list(l).iter().filter(|w| w.contains('-')) {
            let phrase = w.replace('-', " ");
            for (i, _) in t.match_indices(&phrase) {
                masked.push((i, i + phrase.len()));
            }
        }
    }
    // The place the text is about when it is no scene the knowledge base knows ("a mermaid
    // grotto with ...") and what follows the scene's name ("the control room of a submarine").
    masked.extend(place_phrase(t, r.scene.map(|(_, s, e)| (s, e)), &objects));
    r.not_literal = r.scene.and_then(|(i, s, e)| {
        let sc = &kb.scenes[i];
        let own: Vec<&str> = std::iter::once(&sc.name)
            .chain(&sc.synonyms)
            .flat_map(|n| n.split(' '))
            .collect();
        not_literal(t, s, e, &own)
    });
}

/// What makes the place named at `t[s..e]` (a scene's name) another place than the template:
/// a fantastical word before it in the opening phrase (`kb/words.txt`: fantastical) that is
/// not the template's own (`own`: the words of its names; a wizard study is a wizard's), or a
/// noun after it that the name only qualifies ("a pirate ship's hold", "a space station
/// galley").
fn not_literal(t: &str, s: usize, e: usize, own: &[&str]) -> Option<String> {
    let opening = t[..s]
        .rfind([':', ',', ';', '.'])
        .map(|i| i + 1)
        .unwrap_or(0);
    let fantastical = word_list("fantastical");
    if let Some(w) = t[opening..e]
        .split(|c: char| !c.is_alphanumeric() && c != '-')
        .find(|w| fantastical.contains(w) && !own.contains(w))
    {
        return Some(w.to_string());
    }
    let rest = &t[e..];
    let after = rest
        .strip_prefix("'s ")
        .or_else(|| rest.strip_prefix(' '))?;
    let next = after
        .split(|c: char| !c.is_alphanumeric())
        .next()
        .filter(|w| !w.is_empty())?;
    // the noun ends the opening phrase: the contents follow ("a space station galley with")
    let ends = after[next.len()..].is_empty()
        || [
            " with ",
            ":",
            ",",
            " -",
            " where ",
            " full of ",
            " filled with ",
        ]
        .iter()
        .any(|d| after[next.len()..].starts_with(d));
    if own.contains(&next) {
        // "a pirate ship's deck": the template's own place
        return None;
    }
    // "a barber's with four chairs": the owner's name with nothing after it is the shop
    let head = rest.starts_with("'s ") && !is_function_word(next)
        || (ends
            && !(is_function_word(next)
                || is_known_word(next)
                || is_verb(next)
                || number_of(next).is_some()));
    head.then(|| next.to_string())
}

/// The scene `word` names as the head of a compound place name ("a convention hall": a hall of
/// gatherings), when it is such a head (`kb/words.txt`: compound_heads, `head=scene`; plurals
/// too).
fn compound_head(word: &str) -> Option<String> {
    let w = super::singular(word);
    word_list("compound_heads").iter().find_map(|e| {
        let (head, scene) = e.split_once('=')?;
        (head == w).then(|| scene.replace('_', " "))
    })
}

/// The noun that ends `before` (the text before a place word), when it is one that makes a
/// compound with it ("convention" in "a convention hall"): not a function word, a size or
/// mood word, an owner ("grandma's"), a style, a word that only describes a place
/// (`kb/words.txt`: place_describers: "the main hall") or a participle ("a tiled hall").
fn noun_before(before: &str) -> Option<&str> {
    let w = before.split_whitespace().last()?;
    let describes = is_function_word(w)
        || is_known_word(w)
        || w.ends_with("'s")
        || w.ends_with("ed")
        || crate::plan::offline::style_word(w).is_some()
        || word_list("place_describers").contains(&w)
        || word_list("fantastical").contains(&w)
        || number_of(w).is_some()
        || super::described::colour_or_material(w);
    (!describes && w.chars().all(|c| c.is_alphabetic() || c == '-')).then_some(w)
}

/// Scene names and synonyms to the scene index.
pub(super) fn scene_matcher(kb: &KnowledgeBase) -> &'static (Regex, BTreeMap<String, usize>) {
    static M: OnceLock<(Regex, BTreeMap<String, usize>)> = OnceLock::new();
    M.get_or_init(|| {
        let mut table = BTreeMap::new();
        for (i, s) in kb.scenes.iter().enumerate() {
            for name in std::iter::once(&s.name).chain(&s.synonyms) {
                table.entry(name.clone()).or_insert(i);
                for p in plurals(name) {
                    table.entry(p).or_insert(i);
                }
            }
        }
        (alternation(table.keys()), table)
    })
}
