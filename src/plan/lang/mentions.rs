//! What a request says of each object it names: walking back from the noun, its adjectives,
//! stated size, count or determiner, definiteness, negation and owner ("the invigilator's
//! desk"); and whom a thing is for ("chairs for kids").
use super::objects::{inside, Span};
use super::re;
use super::{
    is_adjective, is_verb, number_of, quantities, singular, word_list, words_in, Mention, Reading,
    NEGATORS,
};
use crate::plan::kb::KnowledgeBase;
use crate::plan::units::{find_lengths, Dims};

/// Whether `w` negates the noun phrase after it: a negator ("no", "without", "neither") or a
/// verb that takes a thing away (`kb/words.txt`: removers, "drop the tv").
fn negates(w: &str) -> bool {
    NEGATORS.contains(&w) || word_list("removers").contains(&w)
}

/// Whether the two words before a determiner take the thing away ("get rid of the rug", "leave
/// out the tv": `kb/words.txt`, removers, joined by `_`).
fn removes(w1: Option<&str>, w2: Option<&str>) -> bool {
    let (Some(a), Some(b)) = (w1, w2) else {
        return false;
    };
    word_list("removers").contains(&format!("{a}_{b}").as_str())
}

/// The mentions of the object spans `raw` of `t`, walking back from each noun: adjectives, a
/// stated size (masked once used), then a count or determiner, then negation.
pub(super) fn read_mentions(
    kb: &KnowledgeBase,
    t: &str,
    r: &mut Reading,
    raw: &[Span],
    masked: &mut Vec<(usize, usize)>,
    dims: &[Dims],
) {
    let mut prev_end = 0usize;
    let mut prev_replaced = false;
    for (idx, (start, end, cat, plural)) in raw.iter().cloned().enumerate() {
        // Walk back from the noun: adjectives, then a count or determiner, then negation.
        let before = words_in(t, prev_end, start);
        let mut adjectives: Vec<String> = vec![];
        let mut b = before.len();
        while b > 0 {
            let (pos, w) = before[b - 1];
            if inside(pos, masked) || dims.iter().any(|d| pos >= d.start && pos < d.end) {
                break;
            }
            // "a 2 metre sofa", "a 65 inch tv": a unit after a number is a size, no adjective
            let unit = crate::plan::units::is_unit_word(w)
                && b >= 2
                && before[b - 2].1.parse::<f64>().is_ok();
            if is_adjective(w) && !unit {
                adjectives.insert(0, w.to_string());
                b -= 1;
            } else {
                break;
            }
        }
        // A stated size right before the noun (or its adjectives): "a 2.4 m table", "a 3 x 1 m rug".
        let mut size = [0.0; 3];
        // where the noun phrase begins: its first adjective, else the noun ("2m x 2m: mic"
        // has punctuation between, so the size is not the mic's)
        let np_start = before.get(b).map_or(start, |w| w.0);
        for d in dims {
            if d.end <= start && d.end + 24 >= np_start && d.start >= prev_end && d.area.is_none() {
                let between = &t[d.end..np_start.max(d.end)];
                // "a 12 m by 3 m corridor with lockers": the place's name between is what
                // the size is of
                let place_between = masked
                    .iter()
                    .any(|&(s, e)| s >= d.end && e <= np_start.max(d.end) && s < e);
                if !place_between
                    && between
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
        let mut stop: Vec<&str> = before[..b].iter().map(|x| x.1).collect();
        // "two 2 m sofas": the size between the count and the noun is no count
        if let [.., n, u] = stop[..] {
            if crate::plan::units::is_unit_word(u) && n.parse::<f64>().is_ok() {
                stop.truncate(stop.len() - 2);
            }
        }
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
        // what comes between is a determiner or a count ("instead of the two single beds")
        let filler = |w: Option<&str>| {
            w.is_some_and(|w| {
                matches!(
                    w,
                    "a" | "an" | "the" | "any" | "my" | "our" | "its" | "their"
                ) || number_of(w).is_some()
            })
        };
        let replaced = (1..=3).any(|k| instead(k) && (1..k).all(|i| filler(back(i))));
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
                // "drop the tv", "get rid of the rug"
                if prev2.is_some_and(negates) || removes(prev3, prev2) {
                    negated = true;
                }
            }
            // "so we can watch from bed", "to read in bed": a bare singular noun after a
            // preposition is the thing already there (or the place's own), said as an idiom
            // (not a unit after a number: "a 65 in tv")
            Some("from" | "in" | "into" | "to")
                if b == before.len()
                    && !plural
                    && !prev2
                        .is_some_and(|p| number_of(p).is_some() || p.parse::<f64>().is_ok()) =>
            {
                definite = true;
            }
            Some("of") => {
                // "a pair of", "a couple of", "a dozen", "two sets of", "lots of"
                let head = t[start..end].rsplit(' ').next().unwrap_or("");
                if prev2.is_some_and(|p| p == "pair" || p == "pairs")
                    && word_list("pair_nouns").contains(&head)
                {
                    // "two pairs of headphones": a pair is one thing
                    count = Some(prev3.and_then(number_of).unwrap_or(1).max(1));
                } else if let Some(n) = prev2.and_then(number_of) {
                    count = Some(n);
                    if let Some(m) = prev3.and_then(number_of) {
                        if m > 1
                            && ["dozen", "pair", "pairs", "couple", "sets", "set"]
                                .contains(&prev2.unwrap_or(""))
                        {
                            count = Some(m * n.max(1));
                        }
                    }
                } else if prev2.is_some_and(|p| ["sets", "set"].contains(&p)) {
                    count = prev3.and_then(number_of);
                } else if prev2.is_some_and(|p| ["lots", "plenty", "lot"].contains(&p)) {
                    count = Some(6);
                } else if prev2.is_some_and(|p| quantities().contains(&p)) {
                    // "a heap of gold coins" is one heap, "two piles of logs" two
                    count = prev3.and_then(number_of);
                }
                if prev3.is_some_and(negates) {
                    negated = true;
                }
            }
            Some("other" | "more" | "additional" | "extra") if prev2.is_some_and(negates) => {
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
                    // "the two armchairs", "both armchairs": a counted definite noun phrase
                    // (said again of things already named, see `counts::definite_references`)
                    definite = w == "both"
                        || prev2.is_some_and(|p| ["the", "these", "those"].contains(&p));
                    // "a dozen", "a couple"; "half a dozen"
                    if ["dozen", "couple", "pair"].contains(&w) {
                        count = Some(n);
                        if matches!(prev2, Some("a" | "an")) && prev3 == Some("half") {
                            count = Some(n / 2);
                        }
                    }
                    // "not a single chair", "not one"
                    if ["single", "one"].contains(&w)
                        && matches!(prev2, Some("a" | "an"))
                        && prev3.is_some_and(negates)
                    {
                        negated = true;
                    }
                    if (w == "a" || w == "an" || w == "any") && prev2.is_some_and(negates) {
                        negated = true;
                    }
                    if prev2.is_some_and(negates) && w != "a" && w != "an" {
                        // "without two chairs" is odd; treat as none
                        negated = true;
                    }
                } else if w == "any" || w == "more" {
                    negated = prev2.is_some_and(|p| negates(p) || p == "n't");
                } else if negates(w) {
                    negated = true;
                }
            }
            None => {}
        }
        if !negated && idx > 0 {
            // "no sofa, tv or rug" / "without a sofa or a tv": connectors only since a negated
            // one; what was replaced ("instead of a bed, a desk") passes nothing on.
            // A colon, semicolon, full stop or dash ends the list the negation governs
            // ("without a wardrobe: a single bed and a chair").
            let prev_neg = r.mentions.last().is_some_and(|p| p.negated)
                && !prev_replaced
                && !t[prev_end..start].contains([':', ';', '.', '!', '?'])
                && !t[prev_end..start].contains(" - ");
            let only_connectors = stop
                .iter()
                .all(|w| ["or", "nor", ",", "a", "an", "any", "the"].contains(w));
            // a comma alone carries the negation only in a list an "or" or "nor" ends ("no
            // rugs, curtains or lamps"); "no coffee table, sofa facing the telly" lists what
            // is there after what is not
            let or_said = |w: &&str| ["or", "nor"].contains(w);
            let clause = t[end..]
                .split([':', ';', '.', '!', '?'])
                .next()
                .unwrap_or("")
                .split(" - ")
                .next()
                .unwrap_or("");
            let list_ends_in_or = stop.iter().any(or_said)
                || clause
                    .split_whitespace()
                    .any(|w| or_said(&w.trim_matches(',')));
            if prev_neg && only_connectors && !stop.is_empty() && list_ends_in_or {
                negated = true;
            }
        }
        if negated {
            count = Some(0);
        }
        let after_replaced = prev_replaced;
        prev_replaced = replaced;
        let head_text = t[start..end].to_string();
        let (category, known) = if cat.is_empty() {
            // The head noun names the unknown object; the words before it describe it.
            let mut words: Vec<&str> = head_text.split(' ').collect();
            let head = singular(words.pop().unwrap_or(""));
            // "a tape dispenser", "information panels", "my hamster cage": a noun before the
            // head names the kind with it (a material or colour only describes it)
            let kind_word = words.last().copied().filter(|w| {
                crate::plan::lexicon::is_noun(w)
                    && !crate::plan::colours::MATERIALS.iter().any(|m| m.0 == *w)
                    && !crate::plan::colours::COLOURS.iter().any(|c| c.0 == *w)
            });
            if kind_word.is_some() {
                words.pop();
            }
            adjectives.extend(words.iter().map(|w| w.to_string()));
            match (super::words::misspelt(kb, &head), kind_word) {
                (Some(c), None) => (c, true),
                (_, Some(k)) => (format!("{k} {head}"), false),
                (None, None) => (head, false),
            }
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
        // "a rug instead of a carpet", "instead of a carpet, a rug": what replaces is the same
        // kind as what is replaced, so the words choose which one (its make or material); the
        // kind is wanted, once.
        let mut reference = false;
        // "no TV, it's not a sports bar", "this isn't a games room": what the place is not,
        // said of the place, takes away no thing of its
        let copula = |w: Option<&str>| {
            matches!(
                w,
                Some("it's" | "its" | "is" | "that's" | "thats" | "this's" | "was" | "'s")
            )
        };
        let is_not = matches!(last, Some("a" | "an"))
            && (back(2) == Some("not") && copula(back(3))
                || matches!(back(2), Some("isn't" | "isnt" | "wasn't" | "ain't")));
        if is_not && negated {
            (negated, count, reference) = (false, None, true);
        }
        if replaced
            && r.mentions
                .last()
                .is_some_and(|p| !p.negated && p.category == category)
        {
            (negated, count, reference) = (false, None, true);
        }
        if !negated && after_replaced {
            if let Some(p) = r
                .mentions
                .last_mut()
                .filter(|p| p.negated && p.category == category)
            {
                (p.negated, p.count, p.reference) = (false, None, true);
            }
        }
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
            reference,
            each_of: None,
            parts: 1,
            rows: 0,
            in_rows: false,
            owner,
            said_as: None,
        });
        prev_end = end;
    }
}

/// "chairs for kids", "a little table and chairs for children": what a thing is for names its
/// kind when the knowledge base has that kind ("kids chair"), for the phrase's nouns joined by
/// "and" too.
pub(super) fn for_whom(kb: &KnowledgeBase, r: &mut Reading) {
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

/// "a tiny tv room with ... a television on the wall": a noun that names the place it stands
/// before (`kb/words.txt`: place_heads, "room") is no object of its own when the text names
/// that thing again; the later mention is the one.
pub(super) fn place_names(r: &mut Reading) {
    let heads = word_list("place_heads");
    let names_place = |m: &Mention| {
        r.text[m.end..]
            .strip_prefix(' ')
            .and_then(|t| t.split(|c: char| !c.is_alphanumeric()).next())
            .is_some_and(|w| heads.contains(&w))
    };
    let gone: Vec<usize> = (0..r.mentions.len())
        .filter(|&i| {
            let m = &r.mentions[i];
            names_place(m)
                && r.mentions.iter().enumerate().any(|(j, o)| {
                    j != i && o.category == m.category && !o.negated && !names_place(o)
                })
        })
        .collect();
    for i in gone.into_iter().rev() {
        r.mentions.remove(i);
    }
}
