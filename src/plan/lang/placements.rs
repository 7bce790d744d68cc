//! Placement phrases of a request: relations between the objects it names ("faces", "around",
//! "on either side of", "at the foot of", "between ... and ...") and anchors ("along the wall",
//! "in the corner", "in the middle").
use super::{is_adjective, re, Mention, Reading};
use crate::plan::spec::{Anchor, RelationKind};

/// A phrase that puts a thing against the walls ("along every wall", "on both sides", "against
/// the back wall", "wall-mounted").
pub(super) const SIDE_PHRASE: &str = r"\b(?:against|along|by|on|lining|lined up along|up against|down|around|round) (?:one|a|the|each|both|all|every|either|two|three|four|opposite)(?: the| four)? (?:(?:(?:back|front|far|end|side|rear|left|right|other|main|opposite|near|long) )?walls?|sides?|hull|edges?|perimeter|parapet|railings?)\b|\bwall-mounted\b|\bagainst the (?:walls?|hull)\b|\balong the (?:walls?|hull)\b";

/// Relation and anchor phrases between the mentions.
pub(super) fn read_placements(r: &mut Reading) {
    let t = r.text.clone();
    let clause_start = |pos: usize| {
        t[..pos]
            .rfind(['.', ';', '!', '?'])
            .map(|i| i + 1)
            .unwrap_or(0)
    };
    let last_in = |ms: &[Mention], from: usize, to: usize| -> Option<usize> {
        ms.iter()
            .enumerate()
            .rev()
            .find(|(_, m)| m.end <= to && m.start >= from && !m.negated)
            .map(|(i, _)| i)
    };
    // "Where do I put the piano? By the window, next to the bookshelf.": an answer that names
    // nothing before its placement phrase is said of the thing its question asked about
    let asked_about = |ms: &[Mention], cs: usize| -> Option<usize> {
        let q = cs.checked_sub(1).filter(|&q| t[q..].starts_with('?'))?;
        last_in(ms, clause_start(q), q)
    };
    let subject_before = |ms: &[Mention], pos: usize| -> Option<usize> {
        let cs = clause_start(pos);
        let s = last_in(ms, cs, pos).or_else(|| asked_about(ms, cs))?;
        Some(with_head(ms, &t, s, pos).unwrap_or(s))
    };
    let named_after = |ms: &[Mention], pos: usize| -> Option<usize> {
        ms.iter()
            .enumerate()
            .find(|(_, m)| {
                m.start >= pos
                    && !m.negated
                    && t[pos..m.start].split_whitespace().all(|w| {
                        is_adjective(w)
                            || super::number(w).is_some()
                            || ["the", "a", "an", "its", "their", "each", "every"].contains(&w)
                    })
            })
            .map(|(i, _)| i)
    };
    let objects_after = |ms: &[Mention], pos: usize| -> Vec<usize> {
        let them = referents(ms, &t, pos);
        if them.is_empty() {
            named_after(ms, pos).into_iter().collect()
        } else {
            them
        }
    };
    let mut used: Vec<(usize, usize)> = vec![];
    let phrases: &[(&str, Option<RelationKind>)] = &[
        (
            r"\b(?:on )?(?:either|both|each) sides? of\b",
            Some(RelationKind::Flank),
        ),
        (r"\bflank(?:s|ed|ing)?\b", Some(RelationKind::Flank)),
        (r"\bat the (?:foot|end) of\b", Some(RelationKind::Front)),
        (r"\bat the head of\b", Some(RelationKind::Behind)),
        (r"\bin front of\b", Some(RelationKind::Front)),
        (r"\b(?:to the left of|left of)\b", Some(RelationKind::Left)),
        (
            r"\b(?:to the right of|right of)\b",
            Some(RelationKind::Right),
        ),
        (
            r"\b(?:on top of|on|atop|upon|sitting on|standing on|resting on)\b",
            Some(RelationKind::Over),
        ),
        (
            r"\b(?:under|beneath|below|underneath)\b",
            Some(RelationKind::Under),
        ),
        (
            r"\b(?:around|round|surrounding|encircling|circling)\b",
            Some(RelationKind::Around),
        ),
        (
            r"\b(?:at|pulled up to|tucked under)\b",
            Some(RelationKind::At),
        ),
        (
            r"\b(?:next to|beside|alongside|along|near|close to|by|between)\b",
            Some(RelationKind::Next),
        ),
        (
            r"\b(?:opposite(?: to| of)?|across from|faces|facing|face|looking at|pointed at|towards|toward)\b",
            Some(RelationKind::Opposite),
        ),
        (r"\b(?:behind|in back of)\b", Some(RelationKind::Behind)),
        // "a painting above the piano": over it (a thing hung on the wall keeps its wall, one
        // hung from the ceiling its ceiling: "a chandelier hanging over the table")
        (
            r"\b(?:(?:hanging|hung|suspended) )?(?:(?:right|just|directly) )?(?:above|over)\b",
            Some(RelationKind::Over),
        ),
    ];
    let anchor_phrases: &[(&str, Anchor)] = &[
        (
            r"\b(?:facing|faces|face|looking out(?: of)?|looking at|looks out(?: of)?|turned to(?:wards?)?|towards?) (?:the |a |one of the )?(?:big |large |bay |front |tall |wide )?windows?\b",
            Anchor::FaceWindow,
        ),
        (
            r"\b(?:by|near|under|beneath|below|beside|next to|in front of|at|close to|against|in|to|up to|over to|along|lining) (?:the |a |one of the )?(?:big |large |bay |front |tall |wide |shop |display )?windows?\b",
            Anchor::Window,
        ),
        (
            r"\b(?:facing|faces|face|looking at|looks at|turned to(?:wards?)?|towards?) (?:the )?(?:(?:front |main |entrance |back )?door(?:way)?|(?:front |main )?(?:entrance|entryway)(?: door)?)\b",
            Anchor::FaceDoor,
        ),
        (
            r"\b(?:by|near|beside|next to|at|close to|inside|behind|to|up to|over to) (?:the )?(?:(?:front |main |entrance |back )?door(?:way)?|(?:front |main )?(?:entrance|entryway)(?: door)?)\b",
            Anchor::Door,
        ),
        (
            r"\b(?:centered|centred|in the (?:center|centre|middle)(?: of the room)?)\b",
            Anchor::Center,
        ),
        (SIDE_PHRASE, Anchor::Side),
        (
            r"\b(?:in|into|to) (?:the|a|one|each|every|all|two|three|four|opposite)(?: the)? corners?\b",
            Anchor::Corner,
        ),
    ];
    for (p, a) in anchor_phrases {
        for m in re(p).find_iter(&t) {
            // "along one side of it", "in the corner of the bar": a part of an object, no wall
            if t[m.end()..].starts_with(" of ")
                && !t[m.end()..].starts_with(" of the room")
                && *a != Anchor::Center
            {
                continue;
            }
            // "on the side table": the words name an object, no wall
            if r.mentions
                .iter()
                .any(|x| x.start < m.end() && m.start() < x.end)
            {
                continue;
            }
            // "in the middle of the back wall": at a wall, not in the room's middle
            let a = if *a == Anchor::Center
                && re(r"^ of (?:the |one |a |that )?(?:\w+ )?wall\b").is_match(&t[m.end()..])
            {
                &Anchor::Side
            } else {
                a
            };
            if let Some(s) = subject_before(&r.mentions, m.start()) {
                r.anchors.push((s, *a));
                if *a == Anchor::Side && hangs_on_wall(&t[..m.start()], m.as_str()) {
                    r.hung.push(s);
                }
                if *a == Anchor::Side && one_wall(m.as_str()) {
                    r.one_wall.push(s);
                }
                used.push((m.start(), m.end()));
            } else if r
                .scene
                .is_some_and(|(_, _, end)| end <= m.start() && t[end..m.start()].trim().is_empty())
            {
                // "a reading nook by the window": said of the place, right after its name
                r.place_anchor.get_or_insert(*a);
                used.push((m.start(), m.end()));
            }
        }
    }
    // "two sofas facing each other": a pair turned to one another (one mention, both ends)
    for m in re(r"\b(?:facing|face|faces|opposite|across from) (?:each other|one another)\b")
        .find_iter(&t)
    {
        let Some(s) = subject_before(&r.mentions, m.start()) else {
            continue;
        };
        let pair = r.mentions[s].count.map_or(r.mentions[s].plural, |n| n == 2);
        if pair {
            r.relations.push((s, RelationKind::Opposite, s));
        }
        used.push((m.start(), m.end()));
    }
    for (p, rel) in phrases {
        let Some(rel) = rel else { continue };
        for m in re(p).find_iter(&t) {
            if used.iter().any(|&(s, e)| m.start() < e && s < m.end()) {
                continue;
            }
            if m.as_str().ends_with("over") && counts_after(&t[m.end()..]) {
                // "over 20 chairs", "over a dozen tables": more than, not above
                continue;
            }
            let Some(s) = subject_before(&r.mentions, m.start()) else {
                continue;
            };
            let mut os = objects_after(&r.mentions, m.end());
            // "two tables, a vase on each", "four benches, a sink at each": what each of them
            // is, the thing the subject is said per instance of
            if os.is_empty()
                && re(r"^ (?:each|every one|each one)\b(?: of them\b)?").is_match(&t[m.end()..])
            {
                os.extend(r.mentions[s].each_of);
            }
            let Some(&o) = os.first() else {
                continue;
            };
            // "a sink at each bench": at it is beside it for what is not a seat
            let rel = if *rel == RelationKind::At && !super::is_seat(&r.mentions[s].category) {
                &RelationKind::Next
            } else {
                rel
            };
            used.push((m.start(), m.end()));
            // "a printer on the desk next to the computer": a thing that stands on surfaces is
            // a neighbour of the thing placed there, not of its support
            let s = placed_on(&r.mentions, &t, s, m.start())
                .filter(|_| stands_on_surfaces(&r.mentions[o].category))
                .unwrap_or(s);
            // "a nightstand with a lamp on it beside each bed": after "on it" the phrase is
            // said of what "it" is
            let s = said_of_pronoun(&r.mentions, &t, s, m.start()).unwrap_or(s);
            for &o in &os {
                if r.mentions[s].category != r.mentions[o].category {
                    r.relations.push((s, *rel, o));
                }
            }
            // "a stage with a sofa and a lamp on it": what is said together before a pronoun
            // is placed there as one, back to the thing the pronoun names
            // (said with that thing: "a coffee table and a rug under it" puts only the rug)
            let pronoun = re(r"^ (?:it|them)\b").is_match(&t[m.end()..]);
            if let (true, [o]) = (pronoun, os.as_slice()) {
                let mut j = s;
                while j > o + 1
                    && joined(&t, &r.mentions[j - 1], &r.mentions[j])
                    && !r.mentions[j - 1].negated
                {
                    j -= 1;
                }
                let with = t
                    .get(r.mentions[*o].end..r.mentions[j].start)
                    .is_some_and(|w| re(r"\b(?:with|has|having|holding|holds)\b").is_match(w));
                if j == o + 1 && j < s && with {
                    for k in j..s {
                        if r.mentions[k].category != r.mentions[*o].category {
                            r.relations.push((k, *rel, *o));
                        }
                    }
                }
            }
            if m.as_str() == "between" {
                // "between the sofa and the armchair": next to both
                if let Some(o2) = r.mentions.get(o + 1) {
                    if t[r.mentions[o].end..o2.start].trim().starts_with("and") {
                        r.relations.push((s, RelationKind::Next, o + 1));
                    }
                }
            }
        }
    }
}

/// Whether a wall phrase (and the words before it) hangs a thing on a wall ("hanging on the
/// wall", "on the back wall", "mounted on one wall"), not stood against it ("against the wall",
/// "along the wall", "on both sides").
fn hangs_on_wall(before: &str, phrase: &str) -> bool {
    let last = |w: &str| w.rsplit(' ').next().unwrap_or("") == "wall" || w.ends_with(" walls");
    let hung_word =
        re(r"\b(?:hanging|hung|hangs|mounted|fixed|displayed|framed|pinned|nailed)\s*$");
    (phrase.starts_with("on ") && last(phrase))
        || (hung_word.is_match(before.trim_end()) && last(phrase))
}

/// Whether a wall phrase names one wall ("along the wall", "against the back wall", "lining
/// one wall"), not several ("along the walls", "on both walls") nor a hull or side.
fn one_wall(phrase: &str) -> bool {
    let words: Vec<&str> = phrase.split(|c: char| !c.is_alphanumeric()).collect();
    words.contains(&"wall")
        && !words.contains(&"mounted")
        && !words.iter().any(|w| {
            [
                "each", "both", "all", "every", "two", "three", "four", "opposite",
            ]
            .contains(w)
        })
}

/// Whether `rest` begins with a count ("20 chairs", "a dozen tables").
fn counts_after(rest: &str) -> bool {
    let mut w = rest.split_whitespace();
    match w.next() {
        Some("a" | "an") => matches!(w.next(), Some("dozen" | "hundred" | "couple" | "score")),
        Some(x) => super::number(x).is_some() || x == "dozen",
        None => false,
    }
}

/// "computers on four benches", "a drill on each bench": a support the text names whose kind
/// holds nothing (a bench to sit on) is the kind of its noun that holds things (a lab or work
/// bench, `kb/objects.txt` names and `kb/placement.txt` supports): the one that holds the thing
/// placed first, then one whose name keeps the noun.
pub(super) fn supports_hold(kb: &crate::plan::kb::KnowledgeBase, r: &mut Reading) {
    use crate::plan::gcp::classes::Placements;
    let table = Placements::builtin();
    for &(si, rel, oi) in &r.relations {
        let (s, o) = (&r.mentions[si], &r.mentions[oi]);
        if rel != RelationKind::Over
            || !stands_on_surfaces(&s.category)
            || table.is_support(&o.category)
            || !o.known
        {
            continue;
        }
        let head = super::singular(o.text.rsplit(' ').next().unwrap_or(""));
        let holds = |c: &str| {
            let p = table.get(&s.category);
            (
                p.is_some_and(|p| p.supports.iter().any(|x| x == c)),
                table.is_support(c),
            )
        };
        let kind = kinds_named_by(kb, &head)
            .filter(|k| holds(&k.category).1)
            // the kind the thing placed stands on, then one its noun names ("science bench")
            .min_by_key(|k| {
                let own = k.category.rsplit(' ').next() == Some(head.as_str());
                (!holds(&k.category).0, !own)
            })
            .map(|k| k.category.clone());
        if let Some(c) = kind {
            let was = r.mentions[oi].category.clone();
            // every mention of that support ("on benches ... each bench")
            for m in r.mentions.iter_mut().filter(|m| m.category == was) {
                m.category = c.clone();
            }
        }
    }
}

/// The highest top (m) of a floor people walk on: a stage is, a table-high ping-pong table
/// or a king-size bed is not.
const WALKED_ON_TOP: f64 = 0.7;

/// Whether things of `category` are a floor people walk on, low and wide (a stage): what
/// stands on the floor stands on it as it is ("a sofa and a standard lamp on the stage").
fn walked_on(kb: &crate::plan::kb::KnowledgeBase, category: &str) -> bool {
    kb.object(category)
        .is_some_and(|k| k.size[0] * k.size[1] >= 4.0 && k.size[2] <= WALKED_ON_TOP)
}

/// The knowledge base's kinds whose name or a synonym ends in the noun `head` ("bench":
/// a bench, a science bench, a workbench's "work bench").
fn kinds_named_by<'a>(
    kb: &'a crate::plan::kb::KnowledgeBase,
    head: &'a str,
) -> impl Iterator<Item = &'a crate::plan::kb::ObjectKind> + 'a {
    kb.objects.iter().filter(move |k| {
        std::iter::once(&k.category)
            .chain(&k.synonyms)
            .any(|n| n.rsplit(' ').next() == Some(head))
    })
}

/// A floor-standing thing the text puts on a support ("reading lamps standing on every table")
/// is the kind of its noun that stands on surfaces, preferring one that names that support
/// (a table lamp), then one its own noun names; the text's size words keep applying.
pub(super) fn surface_kinds(kb: &crate::plan::kb::KnowledgeBase, r: &mut Reading) {
    use crate::plan::gcp::classes::{Class, Placements};
    let table = Placements::builtin();
    for &(si, rel, oi) in &r.relations {
        let (s, o) = (&r.mentions[si], &r.mentions[oi]);
        if rel != RelationKind::Over
            || !s.known
            || !matches!(table.class(&s.category), Class::Floor | Class::AgainstWall)
            || !table.is_support(&o.category)
            || walked_on(kb, &o.category)
        {
            continue;
        }
        let head = super::singular(s.text.rsplit(' ').next().unwrap_or(""));
        let on = |c: &str| {
            table
                .get(c)
                .is_some_and(|p| p.supports.contains(&o.category))
        };
        // "flower pots": a kind named by the noun only in another compound (a "tea pot") is
        // another thing; one the bare noun names ("lamp": a table lamp) is the same thing
        let compound = s.text.contains(' ');
        let same_thing = |k: &crate::plan::kb::ObjectKind| {
            !compound
                || std::iter::once(&k.category)
                    .chain(&k.synonyms)
                    .any(|n| n == &head || n.ends_with(&format!(" {}", s.text)))
        };
        let kind = kinds_named_by(kb, &head)
            .filter(|k| stands_on_surfaces(&k.category) && same_thing(k))
            .min_by_key(|k| {
                let own = k.category.rsplit(' ').next() == Some(head.as_str());
                (!on(&k.category), !own)
            })
            .map(|k| k.category.clone());
        if let Some(c) = kind {
            let m = &mut r.mentions[si];
            if c != m.category {
                m.said_as = Some(std::mem::replace(&mut m.category, c));
            }
        }
    }
}

/// What the pronoun of "THING on it" right before `pos` refers to, when mention `thing` is
/// placed that way.
fn said_of_pronoun(ms: &[Mention], t: &str, thing: usize, pos: usize) -> Option<usize> {
    let end = ms.get(thing)?.end;
    let between = t.get(end..pos)?;
    let on_it = re(r"^ (?:on top of|on|atop|upon) (?:it|them) $");
    if !on_it.is_match(between) {
        return None;
    }
    let at = end + between.find(" it").or_else(|| between.find(" them"))?;
    referents(ms, t, at + 1).first().copied()
}

/// The thing a phrase at `pos` is said of when the mention before it, `thing`, is what that thing
/// is said with and a comma closes it: "eight round tables, each with four chairs, under a
/// pergola" puts the tables under it, "a desk with a lamp, by the window" the desk.
fn with_head(ms: &[Mention], t: &str, thing: usize, pos: usize) -> Option<usize> {
    // "tables with chairs, by the window"; "2 tables with 2 chairs each in the window": the
    // share word closes what each has, so the place is the tables'
    let between = t.get(ms.get(thing)?.end..pos)?.trim();
    let shared =
        matches!(between, "each" | "apiece" | "each," | "apiece,") && ms[thing].each_of.is_some();
    if between != "," && !shared {
        return None;
    }
    if shared {
        return ms[thing].each_of.filter(|&h| h < thing && !ms[h].negated);
    }
    let mut k = thing;
    while k > 0 && joined(t, &ms[k - 1], &ms[k]) {
        k -= 1;
    }
    let h = k.checked_sub(1)?;
    let with = re(r"^,?\s*(?:(?:each|all|both|every one)\s+)?(?:with|having|holding)\s[^,.;:!?]*$");
    (with.is_match(t.get(ms[h].end..ms[k].start)?) && !ms[h].negated).then_some(h)
}

/// The thing placed on mention `support` when the text reads "THING on the SUPPORT" right
/// before `pos` (the phrase that follows the support's noun phrase).
fn placed_on(ms: &[Mention], t: &str, support: usize, pos: usize) -> Option<usize> {
    let sup = ms.get(support)?;
    if !t.get(sup.end..pos)?.trim().is_empty() || support == 0 {
        return None;
    }
    let thing = &ms[support - 1];
    let on = re(
        r"^ (?:on top of|on|atop|upon|sitting on|standing on|resting on) (?:(?:the|a|an|its|their|one) )?$",
    );
    let before = t.get(thing.end..sup.start)?;
    // adjectives of the support belong to its mention already
    (on.is_match(before) && !thing.negated).then_some(support - 1)
}

/// Whether things of `category` stand on the top of other furniture (`kb/placement.txt`:
/// on_surface).
fn stands_on_surfaces(category: &str) -> bool {
    use crate::plan::gcp::classes::{Class, Placements};
    matches!(Placements::builtin().class(category), Class::OnSurface(_))
}

/// Whether the mention names more than one thing.
fn many(m: &Mention) -> bool {
    m.plural || m.count.is_some_and(|c| c > 1)
}

/// Whether the words between two mentions say the second is with the first ("a desk with a
/// computer", "a counter holding a till", "a shelf, a vase on it").
fn with_things(t: &str, a: &Mention, b: &Mention) -> bool {
    t.get(a.end..b.start).is_some_and(|between| {
        joined(t, a, b)
            || between.split(|c: char| !c.is_alphanumeric()).any(|w| {
                [
                    "with", "has", "have", "having", "holding", "holds", "topped",
                ]
                .contains(&w)
            })
    })
}

/// Whether only coordination lies between two mentions ("and", "or", commas, determiners).
fn joined(t: &str, a: &Mention, b: &Mention) -> bool {
    t.get(a.end..b.start).is_some_and(|between| {
        between
            .split(|c: char| !c.is_alphanumeric())
            .filter(|w| !w.is_empty())
            .all(|w| {
                ["and", "or", "a", "an", "the", "some"].contains(&w) || super::number(w).is_some()
            })
    })
}

/// The objects a pronoun or a part word right after `pos` refers to. "it" is the last object
/// named before the phrase's subject and the things said with it ("a desk with a computer and
/// a lamp on it": the desk), one thing ("three stools, an island and a bowl on it": the
/// island); "them" the nearest plural before the subject: a plural noun phrase, or singular
/// ones said together ("a washer and a dryer and a shelf above them": both). A part word of
/// `kb/words.txt` (parts) is the last object named that has such a part ("facing the fire"
/// faces the fireplace, "above the mantel" is above it).
fn referents(ms: &[Mention], t: &str, pos: usize) -> Vec<usize> {
    referents_of(ms, t, pos).unwrap_or_default()
}

fn referents_of(ms: &[Mention], t: &str, pos: usize) -> Option<Vec<usize>> {
    let rest = t.get(pos..)?;
    let mut words = rest
        .split(|c: char| !c.is_alphanumeric() && c != '\'' && c != '-')
        .filter(|w| !w.is_empty());
    let mut w = words.next()?;
    let before: Vec<usize> = (0..ms.len())
        .filter(|&i| ms[i].end <= pos && !ms[i].negated)
        .collect();
    if w == "it" {
        // the subject is the last mention before `pos`; the antecedent the one before it and
        // the things said with it, the first of them that is one thing
        let mut k = before.len().checked_sub(2)?;
        let last = k;
        while k > 0 && joined(t, &ms[before[k]], &ms[before[k + 1]]) {
            k -= 1;
        }
        // "a bridge over the pond and maple trees around it": the things said together are
        // said of the one before them only when they are said with it ("a desk with a lamp")
        if k < last && !with_things(t, &ms[before[k]], &ms[before[k + 1]]) {
            k += 1;
        }
        let one = (k..=last).find(|&j| !many(&ms[before[j]])).unwrap_or(k);
        return Some(vec![before[one]]);
    }
    if w == "them" {
        // before the subject: a plural, or a run of singulars said together
        let mut j = before.len().checked_sub(2)?;
        loop {
            if many(&ms[before[j]]) {
                return Some(vec![before[j]]);
            }
            let mut from = j;
            while from > 0
                && !many(&ms[before[from - 1]])
                && joined(t, &ms[before[from - 1]], &ms[before[from]])
            {
                from -= 1;
            }
            if from < j {
                return Some(before[from..=j].to_vec());
            }
            if j == 0 {
                return Some(vec![before[0]]);
            }
            j -= 1;
        }
    }
    while ["the", "a", "an", "its", "their"].contains(&w) {
        w = words.next()?;
    }
    // a word that is itself (part of) a named object is no part word
    let at = pos + rest.find(w)?;
    if ms.iter().any(|m| m.start <= at && at < m.end) {
        return None;
    }
    let owners = super::part_owners(w)?;
    (0..ms.len())
        .rev()
        .find(|&i| {
            ms[i].end <= pos && !ms[i].negated && owners.iter().any(|o| *o == ms[i].category)
        })
        .map(|i| vec![i])
}
