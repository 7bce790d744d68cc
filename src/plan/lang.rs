//! Reading a scene request: noun phrases (a category with its own adjectives, never a verb or a
//! function word), counts (digits, number words, "a pair of", "a dozen"; 0 and "no" mean none),
//! negation ("no", "without", "except", carried over "or"), sizes with units (see `units`),
//! relation phrases ("faces", "around", "on either side of", "at the foot of", ...), anchor
//! phrases ("against the wall", "in the corner") and "for N students". Pure text processing:
//! what the words mean for a scene is decided by the offline planner.
use super::kb::KnowledgeBase;
use super::spec::{Anchor, RelationKind};
use super::units::{find_dims, find_lengths, Dims};

mod counts;
mod place;
mod placements;
use counts::read_counts;
use place::place_phrase;
use placements::read_placements;
use regex::Regex;
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// Words that never describe an object: articles, pronouns, prepositions, conjunctions,
/// auxiliaries, quantifiers and the words of placement phrases.
fn function() -> &'static [&'static str] {
    word_list("function")
}

/// Verbs people use in requests; never part of a description.
fn verbs() -> &'static [&'static str] {
    word_list("verbs")
}

/// Nouns that name no object to place (parts of the room, people, the mood).
fn not_objects() -> &'static [&'static str] {
    word_list("not_objects")
}

/// Number words.
const NUMBERS: &[(&str, u32)] = &[
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
    ("dozen", 12),
    ("both", 2),
    ("couple", 2),
    ("pair", 2),
    ("several", 3),
    ("few", 3),
    ("some", 2),
    ("many", 6),
];

/// Words that switch negation on for the noun phrase after them.
const NEGATORS: &[&str] = &[
    "no",
    "without",
    "except",
    "excluding",
    "minus",
    "zero",
    "not",
];

/// English words that almost every request uses; a long text with none of them is not English.
fn english() -> &'static [&'static str] {
    word_list("english")
}

/// A word list of `kb/words.txt`.
fn word_list(name: &str) -> &'static [&'static str] {
    static LISTS: OnceLock<BTreeMap<&'static str, Vec<&'static str>>> = OnceLock::new();
    let lists = LISTS.get_or_init(|| {
        include_str!("kb/words.txt")
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

/// A word the reader knows as something other than an object: a part of the room, an area,
/// an arrangement, people, a room size word or a common English word of requests.
pub fn is_known_word(w: &str) -> bool {
    let sg = singular(w);
    [
        "not_objects",
        "room_tiny",
        "room_small",
        "room_large",
        "english",
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

fn factor(list: &str, w: &str) -> Option<f64> {
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

/// An object the text names.
#[derive(Debug, Clone, PartialEq)]
pub struct Mention {
    pub start: usize,
    pub end: usize,
    /// The knowledge-base category, or the phrase itself for an unknown object.
    pub category: String,
    /// False for an unknown object (not in the knowledge base).
    pub known: bool,
    /// The matched words ("couches").
    pub text: String,
    pub count: Option<u32>,
    pub plural: bool,
    pub adjectives: Vec<String>,
    /// "the sofa": a reference to an object named before.
    pub definite: bool,
    pub negated: bool,
    /// Width, depth, height stated for it (metres; zero where not stated).
    pub size: [f64; 3],
    /// "each umbrella", "every desk": the object named before, not a new one.
    pub reference: bool,
    /// "two chairs at each table": the mention whose every instance gets `count` of these.
    pub each_of: Option<usize>,
    /// "a bench down each side of every table": parts of each instance (2 sides); 1 otherwise.
    pub parts: u32,
    /// "in four rows of six": the number of rows (0 when not in rows).
    pub rows: u32,
    /// "the invigilator's desk": the owner a particular object is named after.
    pub owner: Option<String>,
}

/// What a request says.
#[derive(Debug, Clone, Default)]
pub struct Reading {
    /// Lower-case normalised text the spans refer to.
    pub text: String,
    /// Scene index into the knowledge base and the span of its name.
    pub scene: Option<(usize, usize, usize)>,
    pub mentions: Vec<Mention>,
    /// Room floor [W, D] and height, metres.
    pub room: Option<[f64; 2]>,
    pub room_height: Option<f64>,
    /// The room's size was given without a unit and read as metres.
    pub room_unitless: bool,
    /// (subject mention, relation, object mention) indices into `mentions`.
    pub relations: Vec<(usize, RelationKind, usize)>,
    /// Anchors the text gives (mention index).
    pub anchors: Vec<(usize, Anchor)>,
    /// "for 24 students".
    pub people: Option<u32>,
    /// "just a bed and a chest, nothing else": only what the text names.
    pub exclusive: bool,
    /// "a table for six": (table mention, seats at each of its instances).
    pub seats_for: Vec<(usize, u32)>,
    /// "small" / "large" said of the scene.
    pub scale: f64,
    /// Nothing in the text looks like English.
    pub not_english: bool,
    /// The word that makes the scene's place not the template's own ("a haunted ballroom", "a
    /// pirate ship's hold", "a space station galley"): the template lends only its generic
    /// furniture.
    pub not_literal: Option<String>,
}

fn re(p: &str) -> Regex {
    Regex::new(p).expect("valid regex")
}

/// Lower case, typographic quotes and primes made plain, whitespace single.
pub fn normalise(text: &str) -> String {
    text.to_lowercase()
        .replace(['’', '‘', '`'], "'")
        .replace(['“', '”'], "\"")
        .replace('×', " x ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
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

/// "chairs for kids", "a little table and chairs for children": what a thing is for names its
/// kind when the knowledge base has that kind ("kids chair"), for the phrase's nouns joined by
/// "and" too.
fn for_whom(kb: &KnowledgeBase, r: &mut Reading) {
    let after = re(r"^ for (?:the |little )?(kids|kid|children|child|toddlers)\b");
    for k in 0..r.mentions.len() {
        let Some(c) = after.captures(&r.text[r.mentions[k].end..]) else {
            continue;
        };
        let whom = if c[1].starts_with("kid") {
            "kids"
        } else {
            "children's"
        };
        let mut j = k;
        loop {
            let m = &r.mentions[j];
            let head = singular(m.text.rsplit(' ').next().unwrap_or(""));
            if let Some(o) = kb.object(&format!("{whom} {head}")) {
                // named by its kind now: no bare noun for the scene to specialise
                let m = &mut r.mentions[j];
                m.category = o.category.clone();
                m.known = true;
                m.text = format!("{whom} {}", m.text);
            }
            if j == 0 || r.text[r.mentions[j - 1].end..r.mentions[j].start].trim() != "and" {
                break;
            }
            j -= 1;
        }
    }
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
    let head = rest.starts_with("'s ")
        || (ends
            && !(is_function_word(next)
                || is_known_word(next)
                || is_verb(next)
                || number_of(next).is_some()));
    head.then(|| next.to_string())
}

/// The singular of a plural English noun: WordNet's where it knows better than rules ("dais"
/// stays, "mice" is "mouse"), else by rule (best effort, for unknown nouns).
pub fn singular(w: &str) -> String {
    if let Some(sg) = super::lexicon::known_singular(w) {
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
    re(&format!(r"\b(?:{})\b", names.join("|")))
}

/// A regex over names and what each name means: (category, is plural).
type NameMatcher = (Regex, BTreeMap<String, (String, bool)>);

/// Object names (categories, synonyms and their plurals) to (category, is plural).
fn object_matcher(kb: &KnowledgeBase) -> &'static NameMatcher {
    static M: OnceLock<NameMatcher> = OnceLock::new();
    M.get_or_init(|| {
        let mut table = BTreeMap::new();
        for (name, o) in kb.names() {
            table.insert(name.to_string(), (o.category.clone(), false));
        }
        for (name, o) in kb.names() {
            for p in plurals(name) {
                table.entry(p).or_insert_with(|| (o.category.clone(), true));
            }
        }
        (alternation(table.keys()), table)
    })
}

/// Scene names and synonyms to the scene index.
fn scene_matcher(kb: &KnowledgeBase) -> &'static (Regex, BTreeMap<String, usize>) {
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

/// Words of `t[from..to]` with their byte offsets.
fn words_in(t: &str, from: usize, to: usize) -> Vec<(usize, &str)> {
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

fn number_of(w: &str) -> Option<u32> {
    if let Ok(n) = w.parse::<u32>() {
        return Some(n);
    }
    NUMBERS.iter().find(|(k, _)| *k == w).map(|&(_, n)| n)
}

/// Reads `text`.
pub fn read(kb: &KnowledgeBase, text: &str) -> Reading {
    let t = normalise(text);
    let mut r = Reading {
        text: t.clone(),
        scale: 1.0,
        ..Default::default()
    };
    // Spans already explained (sizes, scene name), so that their words are neither counts
    // nor adjectives.
    let mut masked: Vec<(usize, usize)> = vec![];
    let dims: Vec<Dims> = find_dims(&t);

    // Scene: the earliest scene name (the longest at that position) that is not part of a
    // longer object name ("office" in "an office chair").
    let (scene_re, scene_of) = scene_matcher(kb);
    let (obj_re0, _) = object_matcher(kb);
    let objects: Vec<(usize, usize)> = obj_re0
        .find_iter(&t)
        .map(|m| (m.start(), m.end()))
        .collect();
    // "a poker room with three card tables and a bar": past the opening noun phrase, a name
    // that is also an object's, said as one item ("a bar"), is that object, not the scene.
    let contents = [" with ", ": "]
        .iter()
        .filter_map(|d| t.find(d))
        .min()
        .filter(|&i| i > 0);
    for m in scene_re.find_iter(&t) {
        let inside_object = objects
            .iter()
            .any(|&(s, e)| s <= m.start() && m.end() <= e && e - s > m.end() - m.start());
        let item = contents.is_some_and(|c| m.start() > c)
            && kb.object(m.as_str()).is_some()
            && ["a", "an", "one"].contains(&t[..m.start()].split_whitespace().last().unwrap_or(""));
        if !inside_object && !item {
            // "a conference hall", "a lecture hall": a generic place word (`kb/words.txt`:
            // place_heads) after a word that starts another scene's name ("conference room")
            // is that other scene; a specific one keeps its meaning ("a tiny bedroom", "the
            // school library").
            let before = t[..m.start()].trim_end();
            let word = before.rsplit(' ').next().unwrap_or("");
            // So does an owner's place: "a wizard's laboratory" is the wizard's study, not a
            // school lab; "a child's bedroom" the child's room.
            let generic = word_list("place_heads").contains(&m.as_str()) || word.ends_with("'s");
            let modified = (generic && !word.is_empty() && !is_function_word(word))
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
            let (i, start) = match modified {
                Some(i) => (i, before.len() - word.len()),
                None => (scene_of[m.as_str()], m.start()),
            };
            r.scene = Some((i, start, m.end()));
            masked.push((start, m.end()));
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
    masked.extend(place_phrase(&t, r.scene.map(|(_, s, e)| (s, e)), &objects));
    r.not_literal = r.scene.and_then(|(i, s, e)| {
        let sc = &kb.scenes[i];
        let own: Vec<&str> = std::iter::once(&sc.name)
            .chain(&sc.synonyms)
            .flat_map(|n| n.split(' '))
            .collect();
        not_literal(&t, s, e, &own)
    });

    // Objects; two names in a row are one object named by the last ("a sectional sofa", "a
    // stone coffin", "a desk chair"), or by the first when both fill one role ("a two-seater
    // sofa").
    let (obj_re, table) = object_matcher(kb);
    let mut raw: Vec<(usize, usize, String, bool)> = vec![];
    for m in obj_re.find_iter(&t) {
        if masked.iter().any(|&(s, e)| m.start() < e && s < m.end()) {
            continue;
        }
        // "a computer lab", "a piano bar": a noun right before the scene's name names the kind
        // of scene, not an object in it.
        if r.scene.is_some_and(|(_, s, _)| {
            s > m.end() && t[m.end()..s].trim().is_empty() && !m.as_str().is_empty()
        }) {
            continue;
        }
        let (cat, plural) = table[m.as_str()].clone();
        if let Some(last) = raw.last_mut() {
            if t[last.1..m.start()].trim().is_empty() && (last.2 == cat || !last.3) {
                let one_role = super::roles::role_of(&last.2)
                    .is_some_and(|role| super::roles::role_of(&cat) == Some(role));
                if !one_role {
                    last.2 = cat;
                }
                last.1 = m.end();
                last.3 = plural;
                continue;
            }
        }
        raw.push((m.start(), m.end(), cat, plural));
    }
    // Unknown objects: an indefinite noun phrase ("a harp", "two easels") whose head noun the
    // knowledge base lacks.
    let all = words_in(&t, 0, t.len());
    let inside = |p: usize, spans: &[(usize, usize)]| spans.iter().any(|&(s, e)| p >= s && p < e);
    let mut k = 0;
    while k < all.len() {
        let (pos, w) = all[k];
        let det = number_of(w).is_some() && !["no", "zero", "both"].contains(&w)
            || ["another", "some"].contains(&w);
        if !det || inside(pos, &masked) || dims.iter().any(|d| pos >= d.start && pos < d.end) {
            k += 1;
            continue;
        }
        // Words after the determiner up to a function word, verb or punctuation; a participle
        // right after the determiner describes what follows ("a stuffed owl", "two carved masks").
        let mut j = k + 1;
        if j + 1 < all.len()
            && is_verb(all[j].1)
            && all[j].1.ends_with("ed")
            && is_adjective(all[j + 1].1)
        {
            j += 1;
        }
        while j < all.len()
            && is_adjective(all[j].1)
            && !inside(all[j].0, &masked)
            && !raw.iter().any(|o| all[j].0 >= o.0 && all[j].0 < o.1)
        {
            j += 1;
        }
        // A run cut short by a known object or the scene's name is their description.
        let known_next = j < all.len()
            && (raw.iter().any(|o| all[j].0 >= o.0 && all[j].0 < o.1) || inside(all[j].0, &masked));
        if j > k + 1 && !known_next {
            let head = all[j - 1].1;
            let ok = !head.ends_with("'s")
                && !head.ends_with('\'')
                && !not_objects().contains(&head)
                && !not_objects().contains(&singular(head).as_str())
                && super::offline::style_word(head).is_none()
                && head.len() > 2;
            if ok {
                let start = all[k + 1].0;
                let end = all[j - 1].0 + head.len();
                let plural = singular(head) != head;
                raw.push((start, end, String::new(), plural));
            }
        }
        k = j.max(k + 1);
    }
    raw.sort_by_key(|o| o.0);
    // Spans never overlap: a name inside a hyphenated word ("three-seat sofa") is read once.
    let mut end_so_far = 0;
    raw.retain(|o| {
        let keep = o.0 >= end_so_far;
        end_so_far = end_so_far.max(o.1);
        keep
    });

    let mut prev_end = 0usize;
    let mut prev_replaced = false;
    for (idx, (start, end, cat, plural)) in raw.iter().cloned().enumerate() {
        // Walk back from the noun: adjectives, then a count or determiner, then negation.
        let before = words_in(&t, prev_end, start);
        let mut adjectives: Vec<String> = vec![];
        let mut b = before.len();
        while b > 0 {
            let (pos, w) = before[b - 1];
            if inside(pos, &masked) || dims.iter().any(|d| pos >= d.start && pos < d.end) {
                break;
            }
            if is_adjective(w) {
                adjectives.insert(0, w.to_string());
                b -= 1;
            } else {
                break;
            }
        }
        // A stated size right before the noun (or its adjectives): "a 2.4 m table", "a 3 x 1 m rug".
        let mut size = [0.0; 3];
        let np_start = if b > 0 { before[b - 1].0 } else { start };
        for d in &dims {
            if d.end <= start && d.end + 24 >= np_start && d.start >= prev_end && d.area.is_none() {
                let between = &t[d.end..np_start.max(d.end)];
                if between
                    .split_whitespace()
                    .all(|w| is_adjective(w) || w == "long" || w == "wide")
                {
                    for (k, v) in d.values.iter().enumerate().take(3) {
                        size[k] = *v;
                    }
                    masked.push((d.start, d.end));
                }
            }
        }
        let lengths = find_lengths(&t[..start]);
        if size == [0.0; 3] {
            if let Some(&(ls, le, v)) = lengths.last() {
                let between: Vec<&str> = t[le..start].split_whitespace().collect();
                if ls >= prev_end
                    && between.len() <= 3
                    && between.iter().all(|w| {
                        is_adjective(w)
                            || is_verb(w)
                            || ["long", "wide", "tall", "high", "across"].contains(w)
                    })
                    && !dims.iter().any(|d| ls >= d.start && ls < d.end)
                {
                    if between.iter().any(|w| *w == "tall" || *w == "high") {
                        size[2] = v;
                    } else {
                        size[0] = v;
                    }
                    masked.push((ls, le));
                    adjectives.retain(|a| {
                        !["long", "wide", "tall", "high", "across"].contains(&a.as_str())
                    });
                }
            }
        }
        let mut count = None;
        let mut definite = false;
        let mut negated = false;
        let stop: Vec<&str> = before[..b].iter().map(|x| x.1).collect();
        let last = stop.last().copied();
        // "a table that seats six", "a tent which sleeps four": between a relative pronoun and
        // a number a noun's form is the verb of the thing before it, not an object.
        if last.is_some_and(|w| w == "that" || w == "which")
            && t[end..]
                .split_whitespace()
                .next()
                .map(|w| w.trim_matches(|c: char| !c.is_alphanumeric()))
                .and_then(number_of)
                .is_some()
        {
            continue;
        }
        let prev2 = if stop.len() >= 2 {
            Some(stop[stop.len() - 2])
        } else {
            None
        };
        let prev3 = if stop.len() >= 3 {
            Some(stop[stop.len() - 3])
        } else {
            None
        };
        // "a sofa bed instead of a bed", "a futon rather than the bed": the bed is not wanted.
        let back = |i: usize| stop.len().checked_sub(i).and_then(|k| stop.get(k)).copied();
        let instead = |at: usize| {
            back(at + 1) == Some("instead") && back(at) == Some("of")
                || back(at + 1) == Some("rather") && back(at) == Some("than")
        };
        let replaced =
            instead(1) || instead(2) && matches!(back(1), Some("a" | "an" | "the" | "any"));
        match last {
            _ if replaced => {
                negated = true;
            }
            Some(w)
                if [
                    "the", "its", "their", "this", "that", "these", "those", "my", "our", "your",
                    "his", "her",
                ]
                .contains(&w) =>
            {
                definite = true;
                if prev2.is_some_and(|p| NEGATORS.contains(&p)) {
                    negated = true;
                }
            }
            Some("of") => {
                // "a pair of", "a couple of", "a dozen", "two sets of", "lots of"
                if let Some(n) = prev2.and_then(number_of) {
                    count = Some(n);
                    if let Some(m) = prev3.and_then(number_of) {
                        if m > 1
                            && ["dozen", "pair", "couple", "sets", "set"]
                                .contains(&prev2.unwrap_or(""))
                        {
                            count = Some(m * n.max(1));
                        }
                    }
                } else if prev2.is_some_and(|p| ["sets", "set"].contains(&p)) {
                    count = prev3.and_then(number_of);
                } else if prev2.is_some_and(|p| ["lots", "plenty", "lot"].contains(&p)) {
                    count = Some(6);
                }
                if prev3.is_some_and(|p| NEGATORS.contains(&p)) {
                    negated = true;
                }
            }
            Some("other" | "more" | "additional" | "extra")
                if prev2.is_some_and(|p| NEGATORS.contains(&p)) =>
            {
                // "no other beds": none besides those named
                negated = true;
                adjectives.insert(0, "other".to_string());
            }
            Some("single") if prev2.and_then(number_of).is_some_and(|n| n > 1) => {
                // "30 single desks": the number counts, "single" describes
                count = prev2.and_then(number_of);
                adjectives.insert(0, "single".to_string());
            }
            Some(w) => {
                if let Some(n) = number_of(w) {
                    count = Some(n);
                    if n == 0 {
                        negated = true;
                    }
                    // "a dozen", "a couple"
                    if ["dozen", "couple", "pair"].contains(&w) {
                        count = Some(n);
                    }
                    if (w == "a" || w == "an" || w == "any")
                        && prev2.is_some_and(|p| NEGATORS.contains(&p))
                    {
                        negated = true;
                    }
                    if prev2.is_some_and(|p| NEGATORS.contains(&p)) && w != "a" && w != "an" {
                        // "without two chairs" is odd; treat as none
                        negated = true;
                    }
                } else if w == "any" || w == "more" {
                    negated = prev2.is_some_and(|p| NEGATORS.contains(&p) || p == "n't");
                } else if NEGATORS.contains(&w) {
                    negated = true;
                }
            }
            None => {}
        }
        if !negated && idx > 0 {
            // "no sofa, tv or rug" / "without a sofa or a tv": connectors only since a negated
            // one; what was replaced ("instead of a bed, a desk") passes nothing on.
            let prev_neg = r.mentions.last().is_some_and(|p| p.negated) && !prev_replaced;
            let only_connectors = stop
                .iter()
                .all(|w| ["or", "nor", ",", "a", "an", "any", "the"].contains(w));
            if prev_neg && only_connectors && !stop.is_empty() {
                negated = true;
            }
        }
        if negated {
            count = Some(0);
        }
        prev_replaced = replaced;
        let head_text = t[start..end].to_string();
        let (category, known) = if cat.is_empty() {
            // The head noun names the unknown object; the words before it describe it.
            let mut words: Vec<&str> = head_text.split(' ').collect();
            let head = singular(words.pop().unwrap_or(""));
            adjectives.extend(words.iter().map(|w| w.to_string()));
            (head, false)
        } else {
            (cat, true)
        };
        // "the invigilator's desk", "a captain's chair": a particular one of its kind, named
        // after its owner unless the knowledge base has that name.
        let owner = adjectives
            .last()
            .filter(|_| known)
            .and_then(|a| a.strip_suffix("'s").or_else(|| a.strip_suffix('\'')))
            .filter(|o| o.len() > 1)
            .map(str::to_string);
        let (category, known) = match &owner {
            Some(o) => {
                adjectives.pop();
                let head = singular(head_text.rsplit(' ').next().unwrap_or(""));
                let name = format!("{o} {head}");
                match kb.object(&name) {
                    Some(k) => (k.category.clone(), true),
                    None => (name, false),
                }
            }
            None => (category, known),
        };
        r.mentions.push(Mention {
            start,
            end,
            category,
            known,
            text: head_text,
            count,
            plural,
            adjectives,
            definite,
            negated,
            size,
            reference: false,
            each_of: None,
            parts: 1,
            rows: 0,
            owner,
        });
        prev_end = end;
    }

    // Room size: the first stated dims not used for an object; an area otherwise.
    for d in &dims {
        if masked.iter().any(|&(s, e)| s == d.start && e == d.end) {
            continue;
        }
        if let Some(a) = d.area {
            if r.room.is_none() && a > 1.0 {
                r.room = Some(super::units::floor_from_area(a));
            }
        } else if r.room.is_none() && d.values.len() >= 2 {
            r.room = Some([d.values[0], d.values[1]]);
            r.room_unitless = d.unitless;
            if let Some(&h) = d.values.get(2) {
                r.room_height = Some(h);
            }
        }
    }

    // "for 24 students", "for eight people"
    let people = re(
        r"\bfor (\d+|[a-z]+)(?: (?:students|pupils|kids|children|people|persons|guests|diners|seats|employees|workers|players|customers|visitors))?(?:[ ,.;!?]|$)",
    );
    for c in people.captures_iter(&t) {
        let w = &c[1];
        if ![
            "a", "an", "no", "some", "many", "few", "several", "both", "couple", "pair", "one",
        ]
        .contains(&w)
        {
            if let Some(n) = number_of(w) {
                r.people = Some(n);
            }
        }
    }
    r.scale = room_scale(&t, &r.mentions, r.scene.map(|(_, s, _)| s));
    r.exclusive = re(r"\bnothing else\b|\b(?:only|just) (?:a|an|one|two|three|four|five|[0-9]+)\b")
        .is_match(&t);
    for_whom(kb, &mut r);
    read_counts(&mut r);
    read_placements(&mut r);

    let words: Vec<&str> = t
        .split(|c: char| !c.is_alphanumeric() && c != '\'')
        .filter(|w| !w.is_empty())
        .collect();
    // Words an English reader knows: function words, request verbs, object and scene names.
    let (_, objects_by_name) = object_matcher(kb);
    let (_, scenes_by_name) = scene_matcher(kb);
    let known = words
        .iter()
        .filter(|w| {
            english().contains(w)
                || is_function_word(w)
                || is_verb(w)
                || number_of(w).is_some()
                || objects_by_name.contains_key(**w)
                || scenes_by_name.contains_key(**w)
        })
        .count();
    r.not_english = words.len() >= 3 && other_language(text, known, words.len());
    r
}

/// The room's size word ("a tiny bathroom", "a bedroom that's tiny", "quite cramped", "a box
/// room") as a factor on the floor area the furniture needs (`kb/words.txt`: room_tiny,
/// room_small, room_large); a size word inside an object's noun phrase ("a small table") is the
/// object's, not the room's.
fn room_scale(t: &str, mentions: &[Mention], scene_start: Option<usize>) -> f64 {
    let words = words_in(t, 0, t.len());
    let mut scale: f64 = 1.0;
    for (k, &(pos, w)) in words.iter().enumerate() {
        let two = words
            .get(k + 1)
            .map(|(_, n)| format!("{w} {n}"))
            .unwrap_or_default();
        let factor = if word_list("room_tiny").contains(&w)
            || word_list("room_tiny").contains(&two.replace(' ', "-").as_str())
        {
            0.35
        } else if word_list("room_small").contains(&w) {
            0.5
        } else if word_list("room_large").contains(&w) {
            1.35
        } else {
            continue;
        };
        // The noun this word describes: the next mention or scene name before punctuation.
        let rest: Vec<&(usize, &str)> = words[k + 1..]
            .iter()
            .take_while(|(_, x)| !matches!(*x, "," | "-" | "–"))
            .take(4)
            .collect();
        // The first noun after it decides: an object's ("a small table"), or the room's (the
        // scene's name, a place word: "a box room", "a tiny bedroom").
        let object = rest
            .iter()
            .find_map(|&&(p, x)| {
                if scene_start == Some(p) || word_list("place_heads").contains(&x) {
                    Some(false)
                } else if mentions.iter().any(|m| m.start == p) {
                    Some(
                        !mentions
                            .iter()
                            .any(|m| m.start == p && m.category.ends_with("room")),
                    )
                } else {
                    None
                }
            })
            .unwrap_or(false);
        if object {
            continue;
        }
        let _ = pos;
        scale = if factor < 1.0 {
            scale.min(factor)
        } else {
            scale.max(factor)
        };
    }
    scale
}

/// Whether `text` is written in another language than English: `whatlang`'s trigram detector
/// among the languages people most often write requests in, trusted only when it is confident
/// or few of the words are ones an English reader knows, and never when half of them are (a
/// short English list of nouns can look like anything to a trigram model).
fn other_language(text: &str, english_words: usize, words: usize) -> bool {
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
