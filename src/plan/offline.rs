//! The offline planner: free text to a SceneSpec from the built-in knowledge base. It finds the
//! scene type (and its synonyms), the objects the prompt names with their counts and adjectives,
//! the room size, placement phrases, and style words carried into every description; the scene
//! type's default furniture fills in the rest. An unknown scene type still gives a room with the
//! objects the prompt names.
use super::gcp::choose_room;
use super::kb::{KnowledgeBase, ObjectKind};
use super::spec::{
    Anchor, ObjectSpec, Relation, RelationKind, Room, SceneSpec, SceneType, MAX_NUMBER,
};
use regex::Regex;
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// Style words carried into every description when the prompt uses them.
const STYLES: &[&str] = &[
    "modern",
    "minimalist",
    "minimal",
    "scandinavian",
    "nordic",
    "rustic",
    "industrial",
    "mid-century",
    "bohemian",
    "boho",
    "vintage",
    "retro",
    "cozy",
    "cosy",
    "luxurious",
    "luxury",
    "japanese",
    "zen",
    "victorian",
    "baroque",
    "gothic",
    "medieval",
    "futuristic",
    "sci-fi",
    "cyberpunk",
    "art deco",
    "coastal",
    "tropical",
    "farmhouse",
    "traditional",
    "contemporary",
    "elegant",
    "colorful",
    "colourful",
    "pastel",
    "dark",
    "bright",
    "sunny",
    "wooden",
    "classic",
    "mediterranean",
    "moroccan",
    "french",
    "english",
    "cottage",
    "steampunk",
    "fantasy",
    "festive",
];

/// Words that are neither count nor adjective.
const FILLER: &[&str] = &[
    "a", "an", "the", "some", "of", "pair", "couple", "few", "several", "with", "and", "in", "on",
    "at", "its", "their", "his", "her", "my", "our", "there", "is", "are", "has", "have", "lots",
    "many", "plus", "also", "to", "for", "by", "from", "this", "that", "room", "one",
];

const NUMBERS: &[(&str, u32)] = &[
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
    ("dozen", 12),
    ("several", 3),
    ("few", 3),
    ("some", 2),
    ("couple", 2),
    ("pair", 2),
    ("many", 4),
    ("both", 2),
];

/// An object the prompt names.
#[derive(Debug, Clone)]
struct Mention {
    start: usize,
    end: usize,
    category: String,
    count: Option<u32>,
    adjectives: Vec<String>,
    /// "the sofa": a reference to an object named before, not a new one.
    definite: bool,
}

fn plural(name: &str) -> Vec<String> {
    let mut v = vec![format!("{name}s"), format!("{name}es")];
    if let Some(stem) = name.strip_suffix('y') {
        v.push(format!("{stem}ies"));
    }
    if let Some(stem) = name.strip_suffix('f') {
        v.push(format!("{stem}ves"));
    }
    if let Some(stem) = name.strip_suffix("fe") {
        v.push(format!("{stem}ves"));
    }
    v
}

/// Regex matching any object name or plural, longest first, with the name table.
fn object_matcher(kb: &KnowledgeBase) -> &'static (Regex, BTreeMap<String, String>) {
    static M: OnceLock<(Regex, BTreeMap<String, String>)> = OnceLock::new();
    M.get_or_init(|| {
        let mut table = BTreeMap::new();
        for (name, o) in kb.names() {
            table.insert(name.to_string(), o.category.clone());
            for p in plural(name) {
                table.entry(p).or_insert_with(|| o.category.clone());
            }
        }
        (alternation(table.keys()), table)
    })
}

/// Regex matching any scene name or synonym (longest first), with the scene index of each name.
fn scene_matcher(kb: &KnowledgeBase) -> &'static (Regex, BTreeMap<String, usize>) {
    static M: OnceLock<(Regex, BTreeMap<String, usize>)> = OnceLock::new();
    M.get_or_init(|| {
        let mut table = BTreeMap::new();
        for (i, s) in kb.scenes.iter().enumerate() {
            for name in std::iter::once(&s.name).chain(&s.synonyms) {
                table.entry(name.clone()).or_insert(i);
            }
        }
        (alternation(table.keys()), table)
    })
}

/// Regex matching any style word.
fn style_matcher() -> &'static Regex {
    static M: OnceLock<Regex> = OnceLock::new();
    M.get_or_init(|| alternation(STYLES.iter()))
}

/// `\b(?:a|b|...)\b` over `names`, longest first so that the longest name wins at a position.
fn alternation<S: AsRef<str>>(names: impl Iterator<Item = S>) -> Regex {
    let mut names: Vec<String> = names.map(|n| regex::escape(n.as_ref())).collect();
    names.sort_by_key(|n| std::cmp::Reverse(n.len()));
    re(&format!(r"\b(?:{})\b", names.join("|")))
}

fn re(pattern: &str) -> Regex {
    Regex::new(pattern).expect("valid regex")
}

/// Room size stated in the prompt: "4m x 5m", "5 x 4 m", "5 by 4 metres", "20 square meters".
pub fn parse_room_size(text: &str) -> Option<[f64; 2]> {
    let t = text.to_lowercase();
    let unit = r"(?:m|meters?|metres?)";
    let dims = re(&format!(
        r"(\d+(?:\.\d+)?)\s*{unit}?\s*(?:x|×|by|\*)\s*(\d+(?:\.\d+)?)\s*{unit}\b"
    ));
    if let Some(c) = dims.captures(&t) {
        let w: f64 = c[1].parse().ok()?;
        let d: f64 = c[2].parse().ok()?;
        if w > 0.5 && d > 0.5 && w <= 500.0 && d <= 500.0 {
            return Some([w, d]);
        }
    }
    let area = re(r"(\d+(?:\.\d+)?)\s*(?:square\s*(?:meters?|metres?|m)|sq\.?\s*m|m2|m²)");
    if let Some(c) = area.captures(&t) {
        let a: f64 = c[1].parse().ok()?;
        if a > 1.0 && a <= 250_000.0 {
            let w = (a * 1.25).sqrt();
            let r = |v: f64| (v * 10.0).round() / 10.0;
            return Some([r(w), r(a / w)]);
        }
    }
    None
}

fn find_mentions(kb: &KnowledgeBase, t: &str) -> Vec<Mention> {
    let (re_obj, table) = object_matcher(kb);
    let mut out = vec![];
    for m in re_obj.find_iter(t) {
        let category = table[m.as_str()].clone();
        // Count and adjectives: up to five words before the noun, back to a clause boundary.
        let before = &t[..m.start()];
        let clause_start = before
            .rfind([',', '.', ';', ':', '(', ')'])
            .map(|i| i + 1)
            .unwrap_or(0);
        let prev_end = out.last().map(|p: &Mention| p.end).unwrap_or(0);
        let from = clause_start.max(prev_end);
        let words: Vec<&str> = t[from..m.start()].split_whitespace().collect();
        let words = &words[words.len().saturating_sub(6)..];
        // Only the words after the last joining word belong to this object.
        let cut = words
            .iter()
            .rposition(|w| ["and", "with", "plus", "has", "have", "is", "are"].contains(w))
            .map(|i| i + 1)
            .unwrap_or(0);
        let words = &words[cut..];
        let definite = words
            .last()
            .is_some_and(|w| ["the", "its", "their", "that", "this"].contains(w));
        let mut count = None;
        let mut adjectives = vec![];
        for w in words {
            if let Ok(n) = w.parse::<u32>() {
                count = Some(n);
                adjectives.clear();
            } else if let Some(&(_, n)) = NUMBERS.iter().find(|(k, _)| k == w) {
                if count.is_none() || *w != "a" {
                    count = Some(n);
                }
                adjectives.clear();
            } else if !FILLER.contains(w) {
                adjectives.push(w.to_string());
            }
        }
        // A plural without a number means more than one.
        if count.is_none() && kb.object(m.as_str()).is_none() {
            count = Some(2);
        }
        out.push(Mention {
            start: m.start(),
            end: m.end(),
            category,
            count,
            adjectives,
            definite,
        });
    }
    out
}

fn article(s: &str) -> &'static str {
    match s.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => "an",
        _ => "a",
    }
}

fn describe(o: &ObjectKind, adjectives: &[String], styles: &[String]) -> String {
    let mut words: Vec<String> = styles.to_vec();
    if adjectives.is_empty() {
        words.push(o.description.clone());
    } else {
        words.extend(adjectives.iter().cloned());
        words.push(o.category.clone());
    }
    let body = words.join(" ");
    format!("A DSLR photo of {} {body}", article(&body))
}

/// Plans `prompt` offline. Never fails: an unknown scene gives a generic room with the objects
/// named (or a few basic pieces of furniture when none are).
pub fn plan_offline(prompt: &str) -> SceneSpec {
    let kb = KnowledgeBase::builtin();
    let t = prompt.to_lowercase().replace(['\n', '\t'], " ");
    // Scene type: the longest scene name or synonym in the text.
    let (scene_re, scene_of) = scene_matcher(kb);
    let scene = scene_re
        .find_iter(&t)
        .max_by_key(|m| m.as_str().len())
        .map(|m| &kb.scenes[scene_of[m.as_str()]]);
    let outdoor_words =
        re(r"\b(outdoor|outdoors|outside|open air|garden|yard|field|forest|street|beach|park)\b");
    let scene_type = scene
        .map(|s| s.scene_type)
        .unwrap_or(if outdoor_words.is_match(&t) {
            SceneType::Outdoor
        } else {
            SceneType::Indoor
        });
    let mentions = find_mentions(kb, &t);
    // Style words describe the whole scene unless they are one object's adjectives.
    let styles: Vec<String> = {
        let local = |w: &str| mentions.iter().any(|m| m.adjectives.iter().any(|a| a == w));
        let mut v: Vec<String> = vec![];
        for m in style_matcher().find_iter(&t) {
            let w = m.as_str().to_string();
            if !local(&w) && !v.contains(&w) {
                v.push(w);
            }
        }
        for m in re(r"\b[a-z]+-(?:inspired|style|styled|themed)\b").find_iter(&t) {
            if !local(m.as_str()) {
                v.push(m.as_str().to_string());
            }
        }
        v
    };

    // Objects: the scene's defaults, then what the prompt names (its counts and words win).
    let mut counts: BTreeMap<String, u32> = BTreeMap::new();
    let mut adjectives: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut anchors: BTreeMap<String, Anchor> = BTreeMap::new();
    if let Some(s) = scene {
        for (c, n) in &s.objects {
            counts.insert(c.clone(), *n);
        }
    }
    for m in &mentions {
        if m.definite && m.count.is_none() && counts.contains_key(&m.category) {
            continue;
        }
        let n = m.count.unwrap_or(1).clamp(1, MAX_NUMBER);
        counts.insert(m.category.clone(), n);
        if !m.adjectives.is_empty() {
            adjectives.insert(m.category.clone(), m.adjectives.clone());
        }
    }
    if counts.is_empty() {
        for (c, n) in [
            ("dining table", 1),
            ("dining chair", 2),
            ("bookshelf", 1),
            ("potted plant", 1),
        ] {
            counts.insert(c.to_string(), n);
        }
    }
    for c in counts.keys() {
        let o = kb
            .object(c)
            .expect("categories come from the knowledge base");
        anchors.insert(c.clone(), o.anchor);
    }
    if let Some(s) = scene {
        for (c, a) in &s.anchors {
            anchors.insert(c.clone(), *a);
        }
    }

    // Placement phrases: anchors and relations, subject = the nearest object named before.
    let mut relations: Vec<(String, RelationKind, String)> = vec![];
    let anchor_phrases = [
        (
            r"\b(?:centered|centred|in the (?:center|centre|middle))\b",
            Anchor::Center,
        ),
        (
            r"\b(?:against|along|by|on) (?:one|a|the|each) wall\b|\bagainst the wall\b|\bwall-mounted\b",
            Anchor::Side,
        ),
        (r"\bin (?:the|a|one|each) corner\b", Anchor::Corner),
    ];
    let nearest_before = |pos: usize| -> Option<&Mention> {
        let clause_start = t[..pos].rfind(['.', ';']).map(|i| i + 1).unwrap_or(0);
        mentions
            .iter()
            .rev()
            .find(|m| m.end <= pos && m.start >= clause_start)
    };
    for (p, a) in anchor_phrases {
        for m in re(p).find_iter(&t) {
            if let Some(subj) = nearest_before(m.start()) {
                anchors.insert(subj.category.clone(), a);
            }
        }
    }
    let rel_phrases = [
        (r"\bin front of\b", RelationKind::Front),
        (
            r"\b(?:next to|beside|alongside|near|close to)\b",
            RelationKind::Next,
        ),
        (
            r"\b(?:opposite(?: to| of)?|across from|facing)\b",
            RelationKind::Opposite,
        ),
        (r"\b(?:behind|in back of)\b", RelationKind::Behind),
        (r"\b(?:on top of|on|atop|upon)\b", RelationKind::Over),
        (
            r"\b(?:under|beneath|below|underneath)\b",
            RelationKind::Under,
        ),
        (r"\b(?:to the left of|left of)\b", RelationKind::Left),
        (r"\b(?:to the right of|right of)\b", RelationKind::Right),
    ];
    for (p, rel) in rel_phrases {
        for m in re(p).find_iter(&t) {
            let Some(subj) = nearest_before(m.start()) else {
                continue;
            };
            // The object: the first object named right after the phrase (within a few words).
            let Some(obj) = mentions
                .iter()
                .find(|o| o.start >= m.end() && o.start <= m.end() + 24)
            else {
                continue;
            };
            if subj.category != obj.category {
                relations.push((subj.category.clone(), rel, obj.category.clone()));
            }
        }
    }
    if scene_type == SceneType::Outdoor {
        for a in anchors.values_mut() {
            if *a == Anchor::Corner {
                *a = Anchor::Side;
            }
        }
    }

    // Build the spec: instances, anchors, relations (the prompt's replace a default between the
    // same pair), descriptions.
    let mut spec_objects = BTreeMap::new();
    for (c, n) in &counts {
        let o = kb.object(c).expect("known");
        spec_objects.insert(
            c.clone(),
            ObjectSpec {
                number: *n,
                size: o.size,
                description: describe(
                    o,
                    adjectives.get(c).map(Vec::as_slice).unwrap_or(&[]),
                    &styles,
                ),
            },
        );
    }
    let mut spec_anchors = BTreeMap::new();
    for (c, n) in &counts {
        for k in 1..=*n {
            spec_anchors.insert(format!("{c}{k}"), anchors[c]);
        }
    }
    let mut spec_relations: Vec<Relation> = vec![];
    let mut pairs = std::collections::BTreeSet::new();
    let mut push = |s: String, rel: RelationKind, o: String, out: &mut Vec<Relation>| {
        let key = (s.clone().min(o.clone()), s.clone().max(o.clone()));
        if pairs.insert(key) {
            out.push(Relation {
                subject: s,
                relation: rel,
                object: o,
            });
        }
    };
    for (s, rel, o) in &relations {
        push(format!("{s}1"), *rel, format!("{o}1"), &mut spec_relations);
    }
    if let Some(sc) = scene {
        for r in &sc.relations {
            let (Some(&ns), Some(&no)) = (counts.get(&r.subject), counts.get(&r.object)) else {
                continue;
            };
            let n = if r.every { ns } else { 1 };
            for k in 1..=n {
                let ko = if r.every && no == ns { k } else { 1 };
                push(
                    format!("{}{k}", r.subject),
                    r.relation,
                    format!("{}{ko}", r.object),
                    &mut spec_relations,
                );
            }
        }
    }
    let mut spec = SceneSpec {
        scene_type,
        scene_text: prompt.trim().to_string(),
        room: None,
        objects: spec_objects,
        anchors: spec_anchors,
        relations: spec_relations,
    };
    let height = match scene_type {
        SceneType::Indoor => 2.8,
        SceneType::Outdoor => 10.0,
    };
    let chosen = choose_room(&spec.instances(), scene_type);
    spec.room = Some(match parse_room_size(&t) {
        Some([w, d]) => Room {
            size: [w, d, chosen.size[2].max(height)],
        },
        None => chosen,
    });
    spec
}
