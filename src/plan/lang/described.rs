//! Colour and material words said of an object after its name: "the armchair is red", "an
//! armchair painted red", "a sofa in navy blue", "make the armchair red". They join the
//! object's adjectives (so its description carries them, and the shape prior colours from it);
//! said of "the armchair", they join the mention that first named it.
use super::words::is_adjective;
use super::Reading;
use crate::plan::colours::{COLOURS, MATERIALS};

/// Words that link an object's name to a colour said after it.
const LINKS: &[&str] = &[
    "is",
    "are",
    "was",
    "were",
    "be",
    "in",
    "of",
    "all",
    "entirely",
    "painted",
    "coloured",
    "colored",
    "upholstered",
    "covered",
    "finished",
    "done",
    "made",
    "dyed",
    "lacquered",
    "stained",
];

/// Words that only shade a colour ("light blue", "dark wood").
const SHADES: &[&str] = &["light", "dark", "pale", "deep", "bright", "vivid", "soft"];

/// A colour or material name, or a word of one ("navy", "oak", "stainless").
pub(super) fn colour_or_material(w: &str) -> bool {
    COLOURS.iter().any(|c| c.0 == w) || MATERIALS.iter().any(|m| m.0.split(' ').any(|x| x == w))
}

/// Adds the colour and material words said after each mention to its adjectives (or, for "the
/// armchair", to the mention that named it first), and records the words read in
/// `r.described`.
pub(super) fn read_described(t: &str, r: &mut Reading) {
    for i in 0..r.mentions.len() {
        let m = &r.mentions[i];
        if m.negated {
            continue;
        }
        let until = r
            .mentions
            .get(i + 1)
            .map_or(t.len(), |n| n.start)
            .max(m.end);
        let Some((run, span)) = colour_after(t, m.end, until) else {
            continue;
        };
        // "an armchair. The armchair is red.": the armchair named first is red
        let owner = if m.definite {
            (0..i)
                .rev()
                .find(|&k| {
                    let p = &r.mentions[k];
                    !p.negated && !p.definite && p.category == m.category
                })
                .unwrap_or(i)
        } else {
            i
        };
        let adjectives = &mut r.mentions[owner].adjectives;
        for w in run {
            if !adjectives.contains(&w) {
                adjectives.push(w);
            }
        }
        r.described.push(span);
    }
}

/// The colour words said right after a name ending at `from` (before `until`), and the span
/// of the words read: linking words, then shades and colour or material words, then the end of
/// the clause (punctuation, the end, or a word that describes nothing, such as "and" or
/// "with"): "painted red", "in navy blue", "is red.", "red and".
fn colour_after(t: &str, from: usize, until: usize) -> Option<(Vec<String>, (usize, usize))> {
    let mut words: Vec<(usize, usize, &str)> = vec![];
    let mut pos = from;
    for raw in t[from..until].split(' ') {
        let start = pos;
        pos += raw.len() + 1;
        if raw.is_empty() {
            continue;
        }
        words.push((start, start + raw.len(), raw));
    }
    let bare = |w: &str| {
        w.trim_matches(|c: char| !c.is_alphanumeric() && c != '-')
            .to_string()
    };
    // the name's own phrase ends at punctuation: "a sofa, red rug" says nothing of the sofa
    if t[from..until].starts_with([',', '.', ';', ':', '!', '?']) {
        return None;
    }
    let mut k = 0;
    while k < words.len() && LINKS.contains(&bare(words[k].2).as_str()) {
        if words[k].2.ends_with([',', '.', ';', ':', '!', '?']) {
            return None;
        }
        k += 1;
    }
    let mut run: Vec<String> = vec![];
    let mut closed = false;
    while k < words.len() {
        let w = bare(words[k].2);
        let shade = SHADES.contains(&w.as_str());
        if !shade && !colour_or_material(&w) {
            break;
        }
        run.push(w);
        k += 1;
        if words[k - 1]
            .2
            .ends_with([',', '.', ';', ':', '!', '?', ')'])
        {
            closed = true;
            break;
        }
    }
    // shades alone, or a colour that goes on to name another thing ("a sofa in red velvet
    // cushions"), say nothing of this one
    if !run.iter().any(|w| colour_or_material(w)) {
        return None;
    }
    let ends = closed
        || words
            .get(k)
            .is_none_or(|&(_, _, w)| !is_adjective(&bare(w)));
    if !ends {
        return None;
    }
    Some((run, (words[0].0, words[k - 1].1)))
}

#[cfg(test)]
mod tests {
    use super::colour_after;

    fn after(t: &str, noun: &str) -> Option<Vec<String>> {
        let from = t.find(noun).expect("noun in text") + noun.len();
        colour_after(t, from, t.len()).map(|(run, _)| run)
    }

    #[test]
    fn colours_said_after_the_name_are_read_up_to_the_clause_end() {
        let v = |s: &[&str]| Some(s.iter().map(|x| x.to_string()).collect::<Vec<_>>());
        assert_eq!(
            after("a stool painted mint green", "stool"),
            v(&["mint", "green"])
        );
        assert_eq!(after("the stool is teal.", "stool"), v(&["teal"]));
        assert_eq!(
            after("a stool in dark oak with a rug", "stool"),
            v(&["dark", "oak"])
        );
        assert_eq!(after("paint the stool yellow", "stool"), v(&["yellow"]));
        assert_eq!(after("a stool, red rug", "stool"), None);
        assert_eq!(after("a stool in red velvet cushions", "stool"), None);
        assert_eq!(after("a stool in the corner", "stool"), None);
    }
}
