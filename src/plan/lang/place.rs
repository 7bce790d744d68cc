//! The place a request is about, when its words are no object: "a mermaid grotto with a clam
//! shell" (an unknown place: the noun phrase that opens the text and introduces the contents),
//! "the control room of a submarine: ..." (what qualifies the scene's name). Spans of the
//! normalised text that the object reader must skip.
use super::{is_adjective, is_function_word, is_verb};

/// Where the opening noun phrase ends: the first word that introduces the contents.
const INTRODUCERS: &[&str] = &[
    ":",
    " with ",
    " - ",
    " – ",
    ", ",
    " where ",
    " full of ",
    " filled with ",
];

/// Spans of `t` that name the place rather than objects. `scene` is the span of the scene's
/// name, if the text has one; `objects` the spans of knowledge-base object names.
pub(super) fn place_phrase(
    t: &str,
    scene: Option<(usize, usize)>,
    objects: &[(usize, usize)],
) -> Vec<(usize, usize)> {
    let cut = |from: usize| {
        INTRODUCERS
            .iter()
            .filter_map(|d| t[from..].find(d).map(|i| (from + i, d.len())))
            .min()
    };
    let has_object = |s: usize, e: usize| objects.iter().any(|&(a, b)| a < e && s < b);
    let mut spans = vec![];
    if let Some((_, end)) = scene {
        // "the bridge of a starship: ...": "of" and its noun phrase qualify the scene's name.
        if t[end..].starts_with(" of ") {
            let from = end + 4;
            let to = cut(from).map(|(i, _)| i).unwrap_or(t.len());
            let words: Vec<&str> = t[from..to].split_whitespace().collect();
            let det = words
                .first()
                .is_some_and(|w| ["a", "an", "the", "my", "our", "his", "her"].contains(w));
            if det && words.len() <= 5 && words[1..].iter().all(|w| is_adjective(w)) {
                spans.push((from, to));
            }
        }
        return spans;
    }
    // No known scene: the opening noun phrase is the place when it names no known object and
    // the contents that follow it do.
    let Some((stop, len)) = cut(0) else {
        return spans;
    };
    // The contents: a known object, or another noun phrase with its determiner ("a small
    // waterfall"); "a harp with gold strings" is a harp.
    let rest = &t[stop + len..];
    let more = rest
        .split(|c: char| !c.is_alphanumeric() && c != '\'')
        .any(|w| super::number_of(w).is_some_and(|n| n > 0) || w == "some");
    if !(has_object(stop + len, t.len()) || more) || has_object(0, stop) {
        return spans;
    }
    let mut words: Vec<(usize, &str)> = vec![];
    let mut pos = 0;
    for w in t[..stop].split(' ') {
        if !w.is_empty() {
            words.push((pos, w));
        }
        pos += w.len() + 1;
    }
    // Request words and the determiner before the noun phrase ("I want a ...", "make me the ...").
    let lead = words
        .iter()
        .take_while(|(_, w)| is_verb(w) || is_function_word(w) || ["i", "me", "i'd"].contains(w))
        .count();
    let np = &words[lead..];
    let noun = |w: &str| is_adjective(w) || super::word_list("place_heads").contains(&w);
    if (1..=4).contains(&np.len()) && np.iter().all(|(_, w)| noun(w)) {
        let (s, _) = np[0];
        let (e, last) = np[np.len() - 1];
        spans.push((s, e + last.len()));
    }
    spans
}
