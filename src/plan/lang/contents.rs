//! What an object is full of: "a bookcase full of books", "a fridge of drinks", "a basket
//! filled with yarn". The words after the object that name no object of their own say what it
//! holds: they describe it (its description says "full of books") and are used, not left over.
//! A thing the knowledge base knows after "of" ("a vase of flowers" where flowers are a
//! category) is a mention of its own and no content; nor is a number, a determiner or a place
//! ("a table of six", "the foot of the bed").
use super::{is_adjective, is_known_word, Reading};

/// The words that introduce what an object holds, longest first.
const FILLED: &[&str] = &[
    "full of",
    "filled with",
    "stocked with",
    "packed with",
    "crammed with",
    "stuffed with",
    "loaded with",
    "of",
];

/// At most this many words name the contents ("full of old paperback books").
const MOST_WORDS: usize = 3;

/// Finds each mention's contents: (mention index, the phrase as said, its span).
pub(super) fn read_contents(r: &mut Reading) {
    let t = r.text.clone();
    let starts: Vec<usize> = r.mentions.iter().map(|m| m.start).collect();
    let mut held_inside = vec![];
    for (i, m) in r.mentions.iter().enumerate() {
        if m.negated {
            continue;
        }
        let after = &t[m.end..];
        let Some((intro, rest)) = FILLED.iter().find_map(|w| {
            let s = after.strip_prefix(' ')?.strip_prefix(w)?;
            s.starts_with(' ').then_some((*w, &s[1..]))
        }) else {
            continue;
        };
        let from = t.len() - rest.len();
        // the noun phrase: words up to punctuation or a function word
        let mut end = from;
        let mut words = 0;
        for w in rest.split(' ') {
            let bare = w.trim_end_matches([',', '.', ';', ':', '!', '?']);
            if bare.is_empty() || !is_adjective(bare) || is_known_word(bare) || words == MOST_WORDS
            {
                break;
            }
            words += 1;
            end += bare.len();
            if bare.len() != w.len() {
                break;
            }
            end += 1;
        }
        let end = end.min(t.len()).max(from);
        let end = from + t[from..end].trim_end().len();
        // "a toy box full of toys": what the thing is there to hold (kb/roles.txt holds), said
        // after "full of" and not after a bare "of", is inside it, not a thing of its own
        if intro != "of" {
            let held = r.mentions.iter().position(|o| {
                o.start >= from
                    && t[from..o.start]
                        .split(' ')
                        .filter(|w| !w.is_empty())
                        .count()
                        <= MOST_WORDS
                    && !o.reference
                    && crate::plan::roles::holds(&m.category, &o.category)
            });
            if let Some(j) = held {
                held_inside.push((i, j, format!("{intro} {}", &t[from..r.mentions[j].end])));
                continue;
            }
        }
        if words == 0 || starts.iter().any(|&s| s >= from && s < end) {
            continue;
        }
        let span_start = m.end + 1;
        r.contents
            .push((i, format!("{intro} {}", &t[from..end]), span_start, end));
    }
    for (i, j, said) in held_inside {
        let end = r.mentions[j].end;
        r.mentions[j].reference = true;
        let span_start = r.mentions[i].end + 1;
        r.contents.push((i, said, span_start, end));
    }
}

#[cfg(test)]
mod tests {
    use crate::plan::kb::KnowledgeBase;

    fn contents(text: &str) -> Vec<String> {
        let r = super::super::read(KnowledgeBase::builtin(), text);
        r.contents.iter().map(|c| c.1.clone()).collect()
    }

    #[test]
    fn what_an_object_is_full_of_is_its_contents() {
        assert_eq!(contents("a bookcase full of books"), ["full of books"]);
        assert_eq!(
            contents("a kitchen with a fridge of drinks and a stove"),
            ["of drinks"]
        );
        assert_eq!(
            contents("a study with a shelf filled with old paperbacks, and a desk"),
            ["filled with old paperbacks"]
        );
    }

    /// What a thing is there to hold (kb/roles.txt holds), said after "full of", is inside it:
    /// no pile of toys beside the toy box; after a bare "of", or said on its own, it is a thing.
    #[test]
    fn what_a_container_holds_is_inside_it() {
        let kb = KnowledgeBase::builtin();
        let things = |text: &str| -> Vec<String> {
            let r = super::super::read(kb, text);
            r.mentions
                .iter()
                .filter(|m| !m.reference)
                .map(|m| m.category.clone())
                .collect()
        };
        for (text, inside) in [
            ("a nursery with a toy chest full of toys", "full of toys"),
            (
                "a kid's room with a toy box stuffed with soft toys and a bed",
                "stuffed with soft toys",
            ),
        ] {
            assert_eq!(contents(text), [inside], "{text}");
            let t = things(text);
            assert!(
                !t.iter().any(|c| c == "toys" || c == "teddy bear"),
                "{text}: {t:?}"
            );
            assert!(t.iter().any(|c| c == "toy chest"), "{text}: {t:?}");
        }
        // toys of their own, or after a bare "of", stay things
        for text in [
            "a playroom with a toy chest and toys on the rug",
            "a room with a toy box of toys",
        ] {
            let t = things(text);
            assert!(t.iter().any(|c| c == "toys"), "{text}: {t:?}");
        }
    }

    #[test]
    fn objects_numbers_and_places_after_of_are_no_contents() {
        assert!(contents("a living room with a vase of flowers").len() <= 1);
        assert!(contents("a dining room with a table of six").is_empty());
        assert!(contents("a bedroom with a rug at the foot of the bed").is_empty());
        assert!(contents("a kitchen with a pair of stools").is_empty());
    }
}
