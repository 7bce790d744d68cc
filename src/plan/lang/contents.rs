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
        if words == 0 || starts.iter().any(|&s| s >= from && s < end) {
            continue;
        }
        let span_start = m.end + 1;
        r.contents
            .push((i, format!("{intro} {}", &t[from..end]), span_start, end));
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

    #[test]
    fn objects_numbers_and_places_after_of_are_no_contents() {
        assert!(contents("a living room with a vase of flowers").len() <= 1);
        assert!(contents("a dining room with a table of six").is_empty());
        assert!(contents("a bedroom with a rug at the foot of the bed").is_empty());
        assert!(contents("a kitchen with a pair of stools").is_empty());
    }
}
