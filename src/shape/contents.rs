//! What a description says a thing holds (`kb/contents.txt`): "a ceramic vase with flowers",
//! "a round wooden table full of new releases", "an old dresser full of plates". The planner
//! writes what the text says (or what the place shows: a bookshop's display case is full of
//! books) into the description; here it becomes the goods the drawing lays on the thing's
//! shelves, in its case or on its top, over the category's own (`kb/shelf_goods.txt`).
use super::goods::Goods;
use std::sync::OnceLock;

/// The phrases that introduce what a thing holds, longest first.
const FILLED: &[&str] = &[
    " full of ",
    " filled with ",
    " stocked with ",
    " packed with ",
    " crammed with ",
    " stuffed with ",
    " loaded with ",
    " piled with ",
    " covered with ",
    " laden with ",
    " with ",
];

/// At most this many words after the phrase are read ("full of old paperback books").
const MOST_WORDS: usize = 4;

/// (words, kind) rows of the table, longest words first.
fn table() -> &'static Vec<(String, Goods)> {
    static T: OnceLock<Vec<(String, Goods)>> = OnceLock::new();
    T.get_or_init(|| {
        let mut rows = vec![];
        for line in include_str!("kb/contents.txt").lines() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let Some((kind, words)) = line.split_once('|') else {
                continue;
            };
            let Some(g) = Goods::parse(kind) else {
                continue;
            };
            for w in words.split(',') {
                rows.push((w.trim().to_lowercase(), g));
            }
        }
        rows.sort_by_key(|(w, _)| std::cmp::Reverse(w.len()));
        rows
    })
}

/// The lines of the table whose kind does not parse or that lack a `|` (for the tests).
pub fn bad_lines() -> Vec<&'static str> {
    include_str!("kb/contents.txt")
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter(|l| {
            l.split_once('|')
                .and_then(|(k, _)| Goods::parse(k))
                .is_none()
        })
        .collect()
}

/// The goods `description` says its thing holds: the first goods word among the few words
/// after a filling phrase; `None` when it says none ("a dresser with brass handles").
pub fn said(description: &str) -> Option<Goods> {
    let d = format!(" {} ", description.to_lowercase());
    FILLED.iter().find_map(|f| {
        let mut from = 0;
        while let Some(i) = d[from..].find(f) {
            let rest = &d[from + i + f.len()..];
            let words: Vec<&str> = rest
                .split_whitespace()
                .map(|w| w.trim_matches(|c: char| !c.is_alphanumeric() && c != '-'))
                .take(MOST_WORDS)
                .collect();
            // "with a round mirror", "with shelves of plates": the words name a part, not
            // what it holds, unless a goods word comes before any other noun-like stop
            for k in 0..words.len() {
                let two = words.get(k + 1).map(|n| format!("{} {n}", words[k]));
                for cand in two.iter().map(String::as_str).chain([words[k]]) {
                    if let Some((_, g)) = table().iter().find(|(w, _)| w == cand) {
                        return Some(*g);
                    }
                }
                if STOPS.contains(&words[k]) {
                    break;
                }
            }
            from += i + f.len();
        }
        None
    })
}

/// Words after which the phrase no longer names what the thing holds ("with shelves of
/// plates over a cupboard": its shelves are a part; "with a lamp", "with brass handles").
const STOPS: &[&str] = &[
    "shelves", "shelf", "doors", "door", "drawers", "drawer", "handles", "legs", "and", "over",
    "on", "in", "under", "its", "their", "mirror", "lamp", "top",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_words_after_a_filling_phrase_name_the_goods() {
        assert_eq!(
            said("A DSLR photo of a ceramic vase with flowers"),
            Some(Goods::Flowers)
        );
        assert_eq!(
            said("A DSLR photo of a round wooden dining table full of new releases"),
            Some(Goods::Books)
        );
        assert_eq!(said("an old dresser full of plates"), Some(Goods::Plates));
        assert_eq!(said("a wooden dresser with brass handles"), None);
        assert_eq!(said("a vanity table with a round mirror"), None);
        assert_eq!(
            said("a wooden kitchen dresser with shelves of plates over a cupboard"),
            None
        );
        assert_eq!(said("a glass display case"), None);
        assert!(bad_lines().is_empty(), "{:?}", bad_lines());
    }
}
