//! Place names written with a slip ("a dinning room", "a livng room"): a name of several words
//! of which one word is one edit away from the scene name's word (a letter left out, added,
//! or two swapped) is that name. Only words of five letters or more are mended, never a letter
//! changed for another (that makes other words: "a glass room" is no classroom), and only words
//! no table and no lexicon knows, so that what the text says on purpose stays. Object words are
//! mended by the same rules ("a tabel for six", "a cofee table"): a word one such edit away from
//! one word of the object names, and from no other, is that word, unless the edit is a letter
//! more or less at its end ("barre" is no barrel) and the next word does not complete an object's
//! name with it ("a coffe table" is a coffee table). An English word WordNet knows is never a slip.
use crate::plan::kb::KnowledgeBase;

/// `t` (normalised, single spaces) with each misspelt word of a scene name of several words
/// written as the name writes it.
pub(super) fn mend_place_names(kb: &KnowledgeBase, t: &str) -> String {
    let words: Vec<&str> = t.split(' ').collect();
    let core = |w: &str| -> (usize, usize) {
        // the word's letters, without punctuation around it
        let start = w.len() - w.trim_start_matches(|c: char| !c.is_alphanumeric()).len();
        let end = w.trim_end_matches(|c: char| !c.is_alphanumeric()).len();
        (start, end.max(start))
    };
    let mut out: Vec<String> = words.iter().map(|w| w.to_string()).collect();
    let names = kb
        .scenes
        .iter()
        .flat_map(|s| std::iter::once(&s.name).chain(&s.synonyms))
        .filter(|n| n.contains(' '));
    for name in names {
        let nw: Vec<&str> = name.split(' ').collect();
        if words.len() < nw.len() {
            continue;
        }
        for start in 0..=words.len() - nw.len() {
            let mut slip = None;
            let whole = nw.iter().enumerate().all(|(j, n)| {
                let w = words[start + j];
                let (a, b) = core(w);
                let w = &w[a..b];
                let last = j + 1 == nw.len();
                if w == *n || (last && super::words::plurals(n).iter().any(|p| p == w)) {
                    return true;
                }
                if slip.is_none() && mendable(kb, w, n) {
                    slip = Some(j);
                    return true;
                }
                false
            });
            if let (true, Some(j)) = (whole, slip) {
                let w = words[start + j];
                let (a, b) = core(w);
                out[start + j] = format!("{}{}{}", &w[..a], nw[j], &w[b..]);
            }
        }
    }
    out.join(" ")
}

/// `t` (normalised, single spaces) with each misspelt object word written as the knowledge
/// base's object names write it: "a tabel for six" is a table for six, "a cofee table" a coffee
/// table. A word is mended only when exactly one word of the names (or its plural) is a slip
/// away from it; a letter more or less at its end only when the word after it completes an
/// object's name with it ("a coffe table").
pub(super) fn mend_object_words(kb: &KnowledgeBase, t: &str) -> String {
    // every word of the names, short ones too: "carts" is carts (a cart), not a slip for "charts"
    let mut known: Vec<&str> = kb
        .objects
        .iter()
        .flat_map(|o| std::iter::once(&o.category).chain(&o.synonyms))
        .flat_map(|n| n.split(' '))
        .collect();
    known.sort_unstable();
    known.dedup();
    let vocabulary: Vec<&str> = known
        .iter()
        .copied()
        .filter(|w| w.chars().count() >= 5 && w.chars().all(char::is_alphabetic))
        .collect();
    let names: Vec<&str> = kb
        .objects
        .iter()
        .flat_map(|o| std::iter::once(&o.category).chain(&o.synonyms))
        .map(String::as_str)
        .collect();
    let words: Vec<&str> = t.split(' ').collect();
    words
        .iter()
        .enumerate()
        .map(|(k, &raw)| {
            // the next word, when the two may be one object's name ("a coffe table")
            let next = words
                .get(k + 1)
                .map(|n| n.trim_matches(|c: char| !c.is_alphanumeric()))
                .filter(|_| !raw.ends_with(|c: char| !c.is_alphanumeric()));
            let names_with = |form: &str| {
                next.is_some_and(|n| {
                    let two = [
                        format!("{form} {n}"),
                        format!("{form} {}", super::singular(n)),
                    ];
                    names.iter().any(|x| two.iter().any(|t| t == x))
                })
            };
            let start = raw.len() - raw.trim_start_matches(|c: char| !c.is_alphanumeric()).len();
            let end = raw
                .trim_end_matches(|c: char| !c.is_alphanumeric())
                .len()
                .max(start);
            let w = &raw[start..end];
            if w.chars().count() < 5
                || known.binary_search(&w).is_ok()
                || known.binary_search(&super::singular(w).as_str()).is_ok()
                || super::words::is_verb(w)
            {
                return raw.to_string();
            }
            let mut near = vocabulary.iter().flat_map(|n| {
                let plural = super::words::plurals(n);
                std::iter::once(n.to_string())
                    .chain(plural)
                    .filter(|form| {
                        mendable(kb, w, form)
                            && !inflected(w, form)
                            && (!end_slip(w, form) || names_with(form))
                    })
                    .take(1)
            });
            let Some(first) = near.next() else {
                return raw.to_string();
            };
            if near.any(|other| other != first) {
                return raw.to_string();
            }
            format!("{}{first}{}", &raw[..start], &raw[end..])
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Whether `w` is a word of English grammar made from something like `n` ("shaded" from
/// "shade", "angled" from "angle"): it ends as a verb or an adverb does and `n` does not. A
/// slip keeps the word's ending.
fn inflected(w: &str, n: &str) -> bool {
    ["ed", "ing", "ly", "est"]
        .iter()
        .any(|e| w.ends_with(e) && !n.ends_with(e))
}

/// Whether `w` is `n` with a letter more or less at its end: that makes other words ("barre"
/// is no barrel, "plaint" no plain), so only a slip inside a word or two letters swapped is
/// mended.
fn end_slip(w: &str, n: &str) -> bool {
    let (a, b) = if w.len() > n.len() { (w, n) } else { (n, w) };
    a.len() == b.len() + 1 && a.starts_with(b)
}

/// Whether `w` is `n` with one letter changed for another (same length, not two swapped).
fn substituted(w: &str, n: &str) -> bool {
    let (mut a, mut b): (Vec<char>, Vec<char>) = (w.chars().collect(), n.chars().collect());
    if a.len() != b.len() {
        return false;
    }
    a.sort_unstable();
    b.sort_unstable();
    a != b
}

/// Whether the text's word `w` is a slip for the name's word `n`.
fn mendable(kb: &KnowledgeBase, w: &str, n: &str) -> bool {
    n.chars().count() >= 5
        && w.chars().all(char::is_alphabetic)
        && strsim::damerau_levenshtein(w, n) == 1
        && !substituted(w, n)
        && kb.object(w).is_none()
        && kb.object(&super::singular(w)).is_none()
        && crate::plan::lexicon::kind(w).is_none()
        && !crate::plan::lexicon::is_near_word(w)
        && crate::plan::lexicon::kind(&super::singular(w)).is_none()
        // "railings" is a word of its own, no slip for "trailing"
        && !crate::plan::lexicon::is_noun(&super::singular(w))
        && !super::words::is_known_word(w)
        && crate::plan::offline::style_word(w).is_none()
        && super::object_scale(w).is_none()
        && super::object_footprint(w).is_none()
        && !super::words::is_function_word(w)
}
