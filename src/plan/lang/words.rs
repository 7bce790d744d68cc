//! The words of a request: the word lists of `kb/words.txt`, numbers, negators, plurals and
//! singulars, the tokens of a text and whether it is English at all.
use super::objects::object_matcher;
use super::scene::scene_matcher;
use super::KnowledgeBase;
use regex::Regex;
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// Words that never describe an object: articles, pronouns, prepositions, conjunctions,
/// auxiliaries, quantifiers and the words of placement phrases.
pub(super) fn function() -> &'static [&'static str] {
    word_list("function")
}

/// Verbs people use in requests; never part of a description.
pub(super) fn verbs() -> &'static [&'static str] {
    word_list("verbs")
}

/// Nouns that name no object to place (parts of the room, people, the mood).
pub(super) fn not_objects() -> &'static [&'static str] {
    word_list("not_objects")
}

/// Number words.
pub(super) const NUMBERS: &[(&str, u32)] = &[
    ("zero", 0),
    ("no", 0),
    ("one", 1),
    ("a", 1),
    ("an", 1),
    ("single", 1),
    ("two", 2),
    ("three", 3),
    ("four", 4),
    ("five", 5),
    ("six", 6),
    ("seven", 7),
    ("eight", 8),
    ("nine", 9),
    ("ten", 10),
    ("eleven", 11),
    ("twelve", 12),
    ("thirteen", 13),
    ("fourteen", 14),
    ("fifteen", 15),
    ("sixteen", 16),
    ("seventeen", 17),
    ("eighteen", 18),
    ("nineteen", 19),
    ("twenty", 20),
    ("thirty", 30),
    ("forty", 40),
    ("fifty", 50),
    ("sixty", 60),
    ("seventy", 70),
    ("eighty", 80),
    ("ninety", 90),
    ("dozen", 12),
    ("both", 2),
    ("couple", 2),
    ("pair", 2),
    ("pairs", 2),
    ("several", 3),
    // "a handful of stools": a few more than "a few"
    ("handful", 5),
    ("few", 3),
    ("some", 2),
    ("many", 6),
];

/// Words that switch negation on for the noun phrase after them.
pub(super) const NEGATORS: &[&str] = &[
    "no",
    "without",
    "except",
    "excluding",
    "minus",
    "zero",
    "not",
    "neither",
    "nor",
];

/// Words that name a heap of what follows "of" ("a hoard of gold": `kb/words.txt`, quantities).
pub(super) fn quantities() -> &'static [&'static str] {
    word_list("quantities")
}

/// How many people one of a category holds when its plural without a count means one thing
/// ("bunk beds" are one bunk bed, two beds one above the other: `kb/words.txt`, plural_one);
/// `None` for other categories.
pub fn plural_means_one(category: &str) -> Option<u32> {
    let key = category.replace(' ', "_");
    word_list("plural_one").iter().find_map(|e| {
        let (c, n) = e.split_once('=')?;
        (c == key).then(|| n.parse().ok()).flatten()
    })
}

/// English words that almost every request uses; a long text with none of them is not English.
pub(super) fn english() -> &'static [&'static str] {
    word_list("english")
}

/// A word list of `kb/words.txt`.
pub(super) fn word_list(name: &str) -> &'static [&'static str] {
    static LISTS: OnceLock<BTreeMap<&'static str, Vec<&'static str>>> = OnceLock::new();
    let lists = LISTS.get_or_init(|| {
        include_str!("../kb/words.txt")
            .lines()
            .filter(|l| !l.starts_with('#'))
            .filter_map(|l| l.split_once(':'))
            .map(|(k, v)| (k.trim(), v.split_whitespace().collect()))
            .collect()
    });
    lists.get(name).map(Vec::as_slice).unwrap_or(&[])
}

/// The categories an object part word belongs to ("fire" -> fireplace, fire pit, ...:
/// `kb/words.txt`, parts), if it is one.
pub fn part_owners(w: &str) -> Option<Vec<String>> {
    word_list("parts").iter().find_map(|e| {
        let (word, owners) = e.split_once('=')?;
        (word == w).then(|| owners.split(',').map(|c| c.replace('_', " ")).collect())
    })
}

/// The category a plant of `archetype` said with `word` is ("potted" palm -> potted plant:
/// `kb/words.txt`, potted), if `word` puts such a plant in a pot.
pub fn potted(word: &str, archetype: &str) -> Option<String> {
    let list = word_list("potted");
    if !list.contains(&archetype) {
        return None;
    }
    list.iter().find_map(|e| {
        let (w, c) = e.split_once('=')?;
        (w == word).then(|| c.replace('_', " "))
    })
}

/// Whether `w` names a place inside something ("a pirate ship's hold": `kb/words.txt`, indoors).
pub fn is_indoor_place(w: &str) -> bool {
    word_list("indoors").contains(&w)
}

/// Whether `w` names an outdoor place that no scene template is (`kb/words.txt`, outdoors: "an
/// allotment", "a rooftop").
pub fn is_outdoor_place(w: &str) -> bool {
    word_list("outdoors").contains(&w)
}

/// Whether `w` names an outdoor place one stands in (`kb/words.txt`, grounds: "a garden",
/// "the beach").
pub fn is_ground(w: &str) -> bool {
    word_list("grounds").contains(&w)
}

/// Whether `w` heads the name of a building one is inside (`kb/words.txt`, buildings: "a
/// cabin", "a chapel"), indoors wherever it stands.
pub fn is_building(w: &str) -> bool {
    word_list("buildings").contains(&w)
}

/// Whether `w` puts a place out of doors (`kb/words.txt`, open_air: "outdoor", "open-air").
pub fn is_open_air(w: &str) -> bool {
    word_list("open_air").contains(&w)
}

/// Whether `w` takes a named thing away (`kb/words.txt`, removers: "drop", "take_out").
pub fn is_remover(w: &str) -> bool {
    word_list("removers").contains(&w)
}

/// A word the reader knows as something other than an object: a part of the room, an area,
/// an arrangement, people, a room size word, the weather or mood of the scene or a common
/// English word of requests.
pub fn is_known_word(w: &str) -> bool {
    let sg = singular(w);
    [
        "not_objects",
        "weather",
        "room_tiny",
        "room_small",
        "room_large",
        "room_huge",
        "english",
        "removers",
    ]
    .iter()
    .any(|l| word_list(l).contains(&w) || word_list(l).contains(&sg.as_str()))
}

/// The factor a size word scales an object by ("huge" 1.6, "tiny" 0.55: `kb/words.txt`,
/// object_scale), if it is one.
pub fn object_scale(w: &str) -> Option<f64> {
    factor("object_scale", w)
}

/// The factor a plain size word scales an object's footprint by, its height kept ("a small
/// table" is narrower, not lower: `kb/words.txt`, object_footprint), if it is one.
pub fn object_footprint(w: &str) -> Option<f64> {
    factor("object_footprint", w)
}

/// The factor a length word scales an object's longer side by ("a long table" 1.5:
/// `kb/words.txt`, object_length), if it is one.
pub fn object_length(w: &str) -> Option<f64> {
    factor("object_length", w)
}

/// The factor a height word scales an object's height by ("a tall bookcase" 1.3, "a low
/// table" 0.75: `kb/words.txt`, object_height), if it is one.
pub fn object_height(w: &str) -> Option<f64> {
    factor("object_height", w)
}

pub(super) fn factor(list: &str, w: &str) -> Option<f64> {
    word_list(list).iter().find_map(|e| {
        let (word, f) = e.split_once('=')?;
        (word == w).then(|| f.parse().ok()).flatten()
    })
}

/// A head noun that a scene's defaults specialise (`kb/words.txt`: specialised): "desks" in a
/// classroom are its school desks.
pub fn is_specialised(head: &str) -> bool {
    word_list("specialised").contains(&head)
}

/// Whether a bare count of `head` takes in every kind of it the place has (`kb/words.txt`,
/// counted_whole): "ten chairs" are all the chairs.
pub fn counts_whole(head: &str) -> bool {
    word_list("counted_whole").contains(&head)
}

/// Whether `w` names a seat as generally as can be (`kb/words.txt`, generic_seats: "seat").
pub fn is_generic_seat(w: &str) -> bool {
    word_list("generic_seats").contains(&w)
}

/// Whether `category` is a thing to sit on (`kb/words.txt`, seats: its head noun).
pub fn is_seat(category: &str) -> bool {
    let head = category.rsplit(' ').next().unwrap_or(category);
    word_list("seats").contains(&head)
}

/// The head noun a one-word category is a kind of (`kb/words.txt`, kinds): "armchair" is a
/// chair, so a bare "chair" in a living room is its armchair.
pub fn kind_of_compound(category: &str) -> Option<&'static str> {
    word_list("kinds").iter().find_map(|e| {
        let (c, head) = e.split_once('=')?;
        (c.replace('_', " ") == category).then_some(head)
    })
}

pub fn is_function_word(w: &str) -> bool {
    function().contains(&w)
}

pub fn is_verb(w: &str) -> bool {
    verbs().contains(&w)
}

/// A word that can describe an object: letters (with hyphens or apostrophes inside), not a
/// function word, verb, number or adverb.
pub fn is_adjective(w: &str) -> bool {
    !w.is_empty()
        && w.chars().next().is_some_and(|c| c.is_alphabetic())
        && w.chars()
            .all(|c| c.is_alphabetic() || c == '-' || c == '\'')
        && !is_function_word(w)
        && !is_verb(w)
        && !NUMBERS.iter().any(|(k, _)| *k == w)
        && !(w.ends_with("ly") && w.len() > 4 && w != "holy" && w != "curly")
}

/// Lower case, typographic quotes and primes made plain, whitespace single, "w/" and "w/o"
/// written out.
pub fn normalise(text: &str) -> String {
    text.to_lowercase()
        .replace(['’', '‘', '`'], "'")
        .replace(['“', '”'], "\"")
        .replace('×', " x ")
        .split_whitespace()
        .map(|w| {
            // "each w/ two chairs", "w/o a rug": the shorthand for "with" and "without"
            if w == "w/o" {
                "without".to_string()
            } else if let Some(rest) = w.strip_prefix("w/").filter(|r| !r.starts_with('/')) {
                if rest.is_empty() {
                    "with".to_string()
                } else {
                    format!("with {rest}")
                }
            } else {
                w.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// "a sideboard with a fruit bowl on top": on top of it (the thing the phrase is said with),
/// as the placement phrases read a pronoun; so is "a side table with her knitting on", an
/// "on" that ends its clause.
pub(super) fn on_top_of_it(t: &str) -> String {
    static RE: OnceLock<Regex> = OnceLock::new();
    static END: OnceLock<Regex> = OnceLock::new();
    let re = RE.get_or_init(|| Regex::new(r"\bon top\b( of\b)?").expect("valid regex"));
    let end = END.get_or_init(|| {
        Regex::new(r"\bwith ([^,.;:!?]{1,60}?) on *([,.;:!?]|$)").expect("valid regex")
    });
    let t = re.replace_all(t, |c: &regex::Captures| {
        if c.get(1).is_some() {
            c[0].to_string()
        } else {
            "on top of it".to_string()
        }
    });
    end.replace_all(&t, "with $1 on it$2").into_owned()
}

/// Numbers of two words written out ("twenty-four", "thirty two") as digits, so that they
/// count what follows as a number word does.
pub(super) fn compound_numbers(t: &str) -> String {
    static RE: OnceLock<Regex> = OnceLock::new();
    let re = RE.get_or_init(|| {
        Regex::new(r"\b(twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)[- ](one|two|three|four|five|six|seven|eight|nine)\b")
            .expect("valid regex")
    });
    re.replace_all(t, |c: &regex::Captures| {
        let n = number_of(&c[1]).unwrap_or(0) + number_of(&c[2]).unwrap_or(0);
        n.to_string()
    })
    .into_owned()
}

/// Numbers written as words inside a size ("five metres by four", "twelve feet by ten", "four
/// by three meters", "about ten square metres") as digits, so that the size reader takes them as
/// it takes "5 m by 4". A number word becomes digits only next to a length unit, or beside "by"/"x"
/// across from digits: "a table for six by the window" keeps its six.
pub(super) fn spelled_sizes(t: &str) -> String {
    static UNIT: OnceLock<Regex> = OnceLock::new();
    static AFTER: OnceLock<Regex> = OnceLock::new();
    static BEFORE: OnceLock<Regex> = OnceLock::new();
    let unit = UNIT.get_or_init(|| {
        Regex::new(r"\b([a-z]+)(\s+(?:square\s+|sq\.?\s*)?(?:met(?:er|re)s?|m|cm|centimet(?:er|re)s?|mm|millimet(?:er|re)s?|ft|feet|foot|inch|inches)\b)")
            .expect("valid regex")
    });
    let after = AFTER.get_or_init(|| {
        Regex::new(r"(\d(?:\.\d+)?\s*(?:[a-z]+\s+)?(?:by|x)\s+)([a-z]+)\b").expect("valid regex")
    });
    let before =
        BEFORE.get_or_init(|| Regex::new(r"\b([a-z]+)(\s+(?:by|x)\s+\d)").expect("valid regex"));
    let swap = |w: &str| numeral(w).map(|n| n.to_string());
    let t = unit.replace_all(t, |c: &regex::Captures| {
        swap(&c[1]).map_or_else(|| c[0].to_string(), |n| format!("{n}{}", &c[2]))
    });
    let t = before.replace_all(&t, |c: &regex::Captures| {
        swap(&c[1]).map_or_else(|| c[0].to_string(), |n| format!("{n}{}", &c[2]))
    });
    after
        .replace_all(&t, |c: &regex::Captures| {
            swap(&c[2]).map_or_else(|| c[0].to_string(), |n| format!("{}{n}", &c[1]))
        })
        .into_owned()
}

/// The number a numeral word says ("five", "twenty"): not the articles and quantifiers that
/// also count ("a", "several", "a pair").
fn numeral(w: &str) -> Option<u32> {
    const NOT_NUMERALS: &[&str] = &[
        "no", "a", "an", "single", "both", "couple", "pair", "pairs", "several", "handful", "few",
        "some", "many",
    ];
    if NOT_NUMERALS.contains(&w) || w.chars().any(|c| c.is_ascii_digit()) {
        return None;
    }
    number_of(w)
}

/// The knowledge base's category a misspelt noun means ("a wardobe" is a wardrobe): the one
/// category with a name of one word one edit away (a letter left out, added, changed, or two
/// swapped), when the word is long enough to tell ("shell" is no shelf, "broom" no brook) and is
/// no noun the lexicon knows.
pub(super) fn misspelt(kb: &KnowledgeBase, noun: &str) -> Option<String> {
    if noun.chars().count() < 6 || crate::plan::lexicon::kind(noun).is_some() {
        return None;
    }
    let mut near = kb
        .objects
        .iter()
        .filter(|o| {
            std::iter::once(&o.category)
                .chain(&o.synonyms)
                .any(|n| !n.contains(' ') && strsim::damerau_levenshtein(n, noun) == 1)
        })
        .map(|o| o.category.clone());
    let first = near.next()?;
    near.all(|c| c == first).then_some(first)
}

pub fn plurals(name: &str) -> Vec<String> {
    let mut v = vec![format!("{name}s"), format!("{name}es")];
    if let Some(stem) = name.strip_suffix('y') {
        v.push(format!("{stem}ies"));
    }
    if let Some(stem) = name.strip_suffix("fe") {
        v.push(format!("{stem}ves"));
    } else if let Some(stem) = name.strip_suffix('f') {
        v.push(format!("{stem}ves"));
    }
    if let Some(stem) = name.strip_suffix("man") {
        v.push(format!("{stem}men"));
    }
    if let Some(stem) = name.strip_suffix("ch") {
        v.push(format!("{stem}ches"));
    }
    v
}

/// The singular of a plural English noun: WordNet's where it knows better than rules ("dais"
/// stays, "mice" is "mouse"), else by rule (best effort, for unknown nouns).
pub fn singular(w: &str) -> String {
    if let Some(sg) = crate::plan::lexicon::known_singular(w) {
        return sg.to_string();
    }
    for (pl, sg) in [
        ("ies", "y"),
        ("ves", "f"),
        ("ches", "ch"),
        ("shes", "sh"),
        ("sses", "ss"),
        ("xes", "x"),
        ("men", "man"),
    ] {
        if let Some(stem) = w.strip_suffix(pl) {
            if stem.len() >= 2 {
                return format!("{stem}{sg}");
            }
        }
    }
    if w.ends_with('s') && !w.ends_with("ss") && !w.ends_with("us") && w.len() > 3 {
        return w[..w.len() - 1].to_string();
    }
    w.to_string()
}

/// `\b(?:a|b|...)\b` over `names`, longest first so that the longest name wins at a position.
pub fn alternation<S: AsRef<str>>(names: impl Iterator<Item = S>) -> Regex {
    let mut names: Vec<String> = names.map(|n| regex::escape(n.as_ref())).collect();
    names.sort_by_key(|n| std::cmp::Reverse(n.len()));
    super::re(&format!(r"\b(?:{})\b", names.join("|")))
}

/// Words of `t[from..to]` with their byte offsets.
pub(super) fn words_in(t: &str, from: usize, to: usize) -> Vec<(usize, &str)> {
    let mut out = vec![];
    let s = &t[from..to];
    let mut i = 0;
    for w in s.split(|c: char| c.is_whitespace()) {
        if !w.is_empty() {
            let pos = from + i;
            // punctuation is its own token
            let core = w.trim_matches(|c: char| ",.;:!?()[]{}".contains(c));
            let lead = w.len()
                - w.trim_start_matches(|c: char| ",.;:!?()[]{}".contains(c))
                    .len();
            if w.starts_with(|c: char| ",.;:!?()".contains(c)) {
                out.push((pos, ","));
            }
            if !core.is_empty() {
                out.push((pos + lead, core));
            }
            if w.ends_with(|c: char| ",.;:!?()".contains(c)) && !core.is_empty() {
                out.push((pos + w.len() - 1, ","));
            }
        }
        i += w.len() + 1;
    }
    out
}

/// The number a word says ("6", "six", "dozen"), if any.
pub fn number(w: &str) -> Option<u32> {
    number_of(w)
}

pub(super) fn number_of(w: &str) -> Option<u32> {
    if let Ok(n) = w.parse::<u32>() {
        return Some(n);
    }
    NUMBERS.iter().find(|(k, _)| *k == w).map(|&(_, n)| n)
}

/// Whether the request `text` (normalised: `t`) is in another language than English: see
/// [`other_language`].
pub(super) fn not_english(kb: &KnowledgeBase, text: &str, t: &str) -> bool {
    let words: Vec<&str> = t
        .split(|c: char| !c.is_alphanumeric() && c != '\'')
        .filter(|w| !w.is_empty())
        .collect();
    // Words an English reader knows: function words, request verbs, object and scene names,
    // the words of place names, the words of `kb/words.txt` (size words, areas, arrangements)
    // and the nouns of the
    // lexicon (WordNet's physical things: "a huge zeppelin").
    let (_, objects_by_name) = object_matcher(kb);
    let (_, scenes_by_name) = scene_matcher(kb);
    // The words of place names ("dental" and "clinic" of "a dental clinic").
    let place_words: std::collections::BTreeSet<&str> = kb
        .scenes
        .iter()
        .flat_map(|s| std::iter::once(&s.name).chain(&s.synonyms))
        .flat_map(|n| n.split(' '))
        .collect();
    let known = words
        .iter()
        .filter(|w| {
            english().contains(w)
                || is_function_word(w)
                || is_verb(w)
                || number_of(w).is_some()
                || objects_by_name.contains_key(**w)
                || scenes_by_name.contains_key(**w)
                || place_words.contains(**w)
                || is_known_word(w)
                || object_scale(w).is_some()
                || object_footprint(w).is_some()
                || crate::plan::lexicon::kind(&singular(w)).is_some()
        })
        .count();
    words.len() >= 3 && other_language(text, known, words.len())
}

/// Whether `text` is written in another language than English: `whatlang`'s trigram detector
/// among the languages people most often write requests in, trusted only when it is confident
/// or few of the words are ones an English reader knows, and never when half of them are (a
/// short English list of nouns can look like anything to a trigram model).
pub(super) fn other_language(text: &str, english_words: usize, words: usize) -> bool {
    use whatlang::{Detector, Lang};
    static DETECTOR: OnceLock<Detector> = OnceLock::new();
    let detector = DETECTOR.get_or_init(|| {
        Detector::with_allowlist(vec![
            Lang::Eng,
            Lang::Spa,
            Lang::Fra,
            Lang::Deu,
            Lang::Ita,
            Lang::Por,
            Lang::Nld,
            Lang::Pol,
            Lang::Swe,
            Lang::Dan,
            Lang::Tur,
            Lang::Rus,
            Lang::Cmn,
            Lang::Jpn,
        ])
    });
    let Some(info) = detector.detect(text) else {
        return false;
    };
    let share = english_words as f64 / words.max(1) as f64;
    info.lang() != Lang::Eng && (info.confidence() >= 0.3 || share < 0.34) && share < 0.5
}
