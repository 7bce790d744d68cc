//! What the planner understood of a request: each object with its count and why it is there
//! (named, a default of the scene, or inferred from a phrase), and the words it did not use.
//! `plan` and `generate` print it; spec.json records it under `understood`.
use super::lang::{self, Reading};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// One category of the plan.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Because {
    pub category: String,
    pub count: u32,
    /// "named", "default for a bedroom", "inferred from \"a table for six\"".
    pub why: String,
}

/// The plan's objects with their reasons, and the words of the request it did not use.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Understood {
    pub objects: Vec<Because>,
    pub unused: Vec<String>,
}

impl Understood {
    /// One line per object, then the unused words: what `plan` and `generate` print.
    pub fn lines(&self) -> Vec<String> {
        let mut out: Vec<String> = self
            .objects
            .iter()
            .map(|b| format!("{} {}: {}", b.count, b.category, b.why))
            .collect();
        if !self.unused.is_empty() {
            out.push(format!(
                "not used: {}",
                self.unused
                    .iter()
                    .map(|w| format!("\"{w}\""))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
        out
    }
}

/// Why `category` is in the plan: an inferred reason wins, then named, then the scene's default.
pub fn why(
    category: &str,
    inferred: &BTreeMap<String, String>,
    named: &std::collections::BTreeSet<String>,
    scene: Option<&str>,
    is_default: bool,
) -> String {
    if let Some(p) = inferred.get(category) {
        format!("inferred from \"{p}\"")
    } else if named.contains(category) {
        "named".into()
    } else if is_default {
        match scene {
            Some(s) => format!("default for {} {s}", article(s)),
            None => "default".into(),
        }
    } else {
        "added to complete the scene".into()
    }
}

fn article(s: &str) -> &'static str {
    match s.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => "an",
        _ => "a",
    }
}

/// The words of mention `i` as the text says them, with its count ("two chairs").
pub fn phrase(r: &Reading, i: usize) -> String {
    let m = &r.mentions[i];
    let before = r.text[..m.start].trim_end();
    // the determiner or number and the adjectives right before the noun
    let words: Vec<&str> = before.split(' ').collect();
    let mut take = 0;
    for w in words.iter().rev().take(4) {
        let w = w.trim_matches(|c: char| !c.is_alphanumeric() && c != '\'' && c != '-');
        if w.is_empty() || (lang::is_function_word(w) && !is_determiner(w)) || lang::is_verb(w) {
            break;
        }
        take += 1;
        if is_determiner(w) || w.parse::<u32>().is_ok() {
            break;
        }
    }
    let lead = words[words.len() - take..].join(" ");
    let s = format!("{lead} {}", &r.text[m.start..m.end]);
    s.trim().to_string()
}

fn is_determiner(w: &str) -> bool {
    [
        "a", "an", "the", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
        "twelve", "dozen", "couple", "pair", "several", "few", "some", "each", "every",
    ]
    .contains(&w)
}

/// "a table for six": from the table's mention to the number after "for".
pub fn seats_phrase(r: &Reading, table: usize) -> String {
    let m = &r.mentions[table];
    let rest = &r.text[m.end..];
    let tail: String = match rest.find(" for ") {
        Some(k) if k < 24 => rest[..k + 5]
            .chars()
            .chain(
                rest[k + 5..]
                    .split([' ', ',', '.', ';'])
                    .next()
                    .unwrap_or("")
                    .chars(),
            )
            .collect(),
        _ => String::new(),
    };
    format!("{}{tail}", phrase(r, table))
}

/// "two chairs at each table": from the first of the two mentions to the end of the other.
pub fn span_phrase(r: &Reading, a: usize, b: usize) -> String {
    let (x, y) = (a.min(b), a.max(b));
    let start = r.mentions[x].end.saturating_sub(phrase(r, x).len());
    let end = r.mentions[y].end;
    if end > start && end - start <= 80 {
        r.text[start..end].trim().to_string()
    } else {
        phrase(r, a)
    }
}

/// Words of the request that no part of the plan used: not in the scene's name or an object's
/// noun phrase, and no function word, verb, number, style, size, area or placement word.
pub fn unused_words(r: &Reading, styles: &[String]) -> Vec<String> {
    let mut spans: Vec<(usize, usize)> = r.mentions.iter().map(|m| (m.start, m.end)).collect();
    if let Some((_, s, e)) = r.scene {
        spans.push((s, e));
    }
    spans.extend(r.contents.iter().map(|&(_, _, s, e)| (s, e)));
    spans.extend(r.settings.iter().copied());
    spans.extend(r.described.iter().copied());
    // "3 by 4 metres", "12 x 10 ft": a size phrase is read whole, its unit too
    spans.extend(
        crate::plan::units::find_dims(&r.text)
            .iter()
            .map(|d| (d.start, d.end)),
    );
    let adjectives: Vec<&str> = r
        .mentions
        .iter()
        .flat_map(|m| m.adjectives.iter().map(String::as_str))
        .collect();
    // "take out the tv", "leave out the rug": the words of a remover of two words are used
    let bare: Vec<&str> = r
        .text
        .split(' ')
        .map(|w| w.trim_matches(|c: char| !c.is_alphanumeric()))
        .collect();
    let removes = |k: usize| {
        let pair = |a: usize| {
            bare.get(a + 1)
                .is_some_and(|b| lang::is_remover(&format!("{}_{b}", bare[a])))
        };
        pair(k) || (k > 0 && pair(k - 1))
    };
    let mut out: Vec<String> = vec![];
    let mut pos = 0;
    for (k, raw) in r.text.split(' ').enumerate() {
        let here = pos;
        pos += raw.len() + 1;
        let w = raw.trim_matches(|c: char| !c.is_alphanumeric() && c != '\'' && c != '-');
        let w = w.trim_end_matches("'s").trim_end_matches('\'');
        if w.len() < 2
            || !lang::is_adjective(w)
            || spans.iter().any(|&(s, e)| here < e && s < here + raw.len())
            || adjectives.contains(&w)
            || styles.iter().any(|s| s == w)
            || super::offline::style_word(w).is_some()
            || lang::is_known_word(w)
            // a word of the ground ("a rooftop terrace") sets where the place is, and the
            // environment draws it (a rooftop's parapet)
            || lang::is_ground(w)
            || removes(k)
            || out.iter().any(|x| x == w)
        {
            continue;
        }
        out.push(w.to_string());
    }
    out
}

/// "for 24 students": the words of the text that give `people`. The word after the number is
/// kept only when it names who the seats are for ("students", "people"): a function word, a
/// verb, a number or a word after a comma starts the next part of the request ("for eight, a
/// sideboard", "for eight with a bench").
pub fn people_phrase(text: &str, people: u32) -> String {
    let words: Vec<&str> = text.split_whitespace().collect();
    let bare = |w: &str| {
        w.trim_matches(|c: char| !c.is_alphanumeric() && c != '\'' && c != '-')
            .to_lowercase()
    };
    for (k, w) in words.iter().enumerate() {
        let Some(n) = words.get(k + 1) else { break };
        if bare(w) != "for" || lang::number(&bare(n)) != Some(people) {
            continue;
        }
        let number = bare(n);
        let closed = n.ends_with([',', '.', ';', ':', '!', '?', ')']);
        let tail = words.get(k + 2).map(|t| bare(t)).unwrap_or_default();
        let noun = !closed && lang::is_adjective(&tail) && lang::number(&tail).is_none();
        return if noun {
            format!("for {number} {tail}")
        } else {
            format!("for {number}")
        };
    }
    format!("for {people}")
}
