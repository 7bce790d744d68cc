//! Place names written with a slip ("a dinning room", "a livng room"): a name of several words
//! of which one word is one edit away from the scene name's word (a letter left out, added,
//! or two swapped) is that name. Only words of five letters or more are mended, never a letter
//! changed for another (that makes other words: "a glass room" is no classroom), and only words
//! no table and no lexicon knows, so that what the text says on purpose stays.
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
        && crate::plan::lexicon::kind(w).is_none()
        && crate::plan::lexicon::kind(&super::singular(w)).is_none()
        && !super::words::is_known_word(w)
        && crate::plan::offline::style_word(w).is_none()
        && super::object_scale(w).is_none()
        && super::object_footprint(w).is_none()
        && !super::words::is_function_word(w)
}
