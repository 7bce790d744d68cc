//! What WordNet says of a noun the knowledge base lacks: its kind (the category its nearest
//! hypernym names, or a size class), whether a noun ending in "s" is singular ("dais"), and
//! irregular plurals. Data: `kb/wordnet.txt`, generated from WordNet 3.0 by
//! `scripts/wordnet_kinds.py`; and the English words one slip away from an object word, which
//! are never mended as slips (`kb/near_words.txt`, by `scripts/wordnet_near_words.py`).
use std::collections::{BTreeMap, BTreeSet};
use std::sync::OnceLock;

/// What a noun is a kind of.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Kind<'a> {
    /// A knowledge-base category ("chesterfield" -> "sofa").
    Category(&'a str),
    /// A size class: "small", "medium" or "large" ("owl" -> "small").
    Size(&'a str),
}

struct Lexicon {
    kinds: BTreeMap<&'static str, &'static str>,
    keep: BTreeSet<&'static str>,
    nouns: BTreeSet<&'static str>,
    people: BTreeSet<&'static str>,
    irregular: BTreeMap<&'static str, &'static str>,
}

fn lexicon() -> &'static Lexicon {
    static L: OnceLock<Lexicon> = OnceLock::new();
    L.get_or_init(|| {
        let mut l = Lexicon {
            kinds: BTreeMap::new(),
            keep: BTreeSet::new(),
            nouns: BTreeSet::new(),
            people: BTreeSet::new(),
            irregular: BTreeMap::new(),
        };
        for line in include_str!("kb/wordnet.txt").lines() {
            let Some((tag, rest)) = line.split_once(' ') else {
                continue;
            };
            let pair = rest.split_once(" | ").map(|(a, b)| (a.trim(), b.trim()));
            match (tag, pair) {
                ("kind", Some((w, k))) => {
                    l.kinds.insert(w, k);
                }
                ("irregular", Some((p, s))) => {
                    l.irregular.insert(p, s);
                }
                ("keep", None) => {
                    l.keep.insert(rest.trim());
                }
                ("noun", None) => {
                    l.nouns.insert(rest.trim());
                }
                ("person", None) => {
                    l.people.insert(rest.trim());
                }
                _ => {}
            }
        }
        l
    })
}

/// The kind of `noun` (singular, lower case), if WordNet gives one.
pub fn kind(noun: &str) -> Option<Kind<'static>> {
    let k = lexicon().kinds.get(noun)?;
    Some(match k.strip_prefix("size ") {
        Some(class) => Kind::Size(class),
        None => Kind::Category(k),
    })
}

/// Whether `w` is a noun and never an adjective in WordNet ("tape", "information", "hamster";
/// not "little", "stone", "wooden"): said before an unknown head noun, it names its kind.
pub fn is_noun(w: &str) -> bool {
    let l = lexicon();
    l.nouns.contains(w) || l.kinds.contains_key(w)
}

/// Whether `w` (singular, lower case) is a noun in use whose first sense is a person
/// ("teacher", "mechanic"): an object word before it names whom the person works with.
pub fn is_person(w: &str) -> bool {
    lexicon().people.contains(w)
}

/// Whether `w` is an English word (WordNet 3.0, any part of speech) one slip away from a word
/// of the object names ("arced", "barrels", "orange"): a word said on purpose, not a slip.
pub fn is_near_word(w: &str) -> bool {
    static WORDS: OnceLock<BTreeSet<&'static str>> = OnceLock::new();
    WORDS
        .get_or_init(|| {
            include_str!("kb/near_words.txt")
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .collect()
        })
        .contains(w)
}

/// The singular WordNet knows for `w`: itself for a singular noun ending in "s" ("dais"), the
/// base of an irregular plural ("mice" -> "mouse"); `None` when rules decide.
pub fn known_singular(w: &str) -> Option<&'static str> {
    let l = lexicon();
    l.keep
        .get(w)
        .copied()
        .or_else(|| l.irregular.get(w).copied())
}

/// The knowledge-base category a name the knowledge base lacks is a kind of: its head noun's
/// category ("captain chair" is a chair), else the category WordNet gives its head noun
/// ("chesterfield" is a sofa). `None` for a known name, or when neither says.
pub fn kind_category(name: &str) -> Option<&'static str> {
    let kb = super::kb::KnowledgeBase::builtin();
    if kb.object(name).is_some() {
        return None;
    }
    let head = name.rsplit(' ').next()?;
    if let Some(o) = kb.object(head) {
        return Some(o.category.as_str());
    }
    match kind(head)? {
        Kind::Category(c) => kb.object(c).map(|o| o.category.as_str()),
        Kind::Size(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unknown_name_is_a_kind_of_its_head_or_of_what_wordnet_says() {
        // none of these nouns is in kb/objects.txt
        for (name, want) in [
            ("grandmother chair", Some("chair")),
            ("escritoire", Some("desk")),
            ("divan", Some("sofa")),
            ("fauteuil", Some("armchair")),
            ("owl", None),
            ("sofa", None),
        ] {
            let kb = crate::plan::kb::KnowledgeBase::builtin();
            if want.is_some() {
                assert!(
                    kb.object(name).is_none(),
                    "`{name}` is in the knowledge base"
                );
            }
            let got = kind_category(name);
            match want {
                Some(w) => assert_eq!(
                    got.map(|c| kb.object(c).map(|o| o.category.as_str())),
                    Some(kb.object(w).map(|o| o.category.as_str())),
                    "{name}"
                ),
                None => assert_eq!(got, None, "{name}"),
            }
        }
    }
}
