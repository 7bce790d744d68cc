//! The objects a request names: known names and synonyms (two names in a row are one object)
//! and unknown noun phrases after a determiner, as spans of the text. What each span says of its
//! object (adjectives, size, count, negation, owner) is read in `mentions`.
use super::{
    alternation, is_adjective, is_verb, not_objects, number_of, plurals, quantities, singular,
    word_list, words_in,
};
use crate::plan::kb::KnowledgeBase;
use crate::plan::units::Dims;
use regex::Regex;
use std::collections::BTreeMap;
use std::sync::OnceLock;

/// An object's span in the text: start, end, category (empty for an unknown object), plural.
pub(super) type Span = (usize, usize, String, bool);

/// Whether `w`, after a noun, is the verb of its clause ("a small bridge crosses the pond", "a
/// bridge spanning the pond", "an owl perched on the shelf"): a verb form that WordNet knows
/// no physical thing by, followed by a determiner (or, for a participle, a function word).
fn verb_after_noun(w: &str, next: Option<&str>) -> bool {
    const DETERMINERS: &[&str] = &[
        "the", "a", "an", "its", "their", "his", "her", "this", "that", "these", "those", "each",
        "every", "my", "our", "your",
    ];
    let Some(next) = next else {
        return false;
    };
    let thing = |n: &str| crate::plan::lexicon::kind(n).is_some();
    if thing(w) || thing(&singular(w)) {
        return false;
    }
    let participle = (w.ends_with("ing") || w.ends_with("ed")) && w.len() > 5;
    let third_person = w.ends_with('s') && !w.ends_with("ss") && w.len() > 3;
    DETERMINERS.contains(&next) && (participle || third_person)
        || participle
            && super::is_function_word(next)
            && !["and", "or", "nor", "but"].contains(&next)
}

/// Whether `p` lies inside one of `spans`.
pub(super) fn inside(p: usize, spans: &[(usize, usize)]) -> bool {
    spans.iter().any(|&(s, e)| p >= s && p < e)
}

/// The spans of the objects `t` names, in order and never overlapping; `scene` is the scene's
/// index and span, `masked` what is already explained.
/// Whether the object word of `span` is said of the person named right after it ("a piano
/// teacher's studio", "the bike mechanic", "guitar players"): a noun whose first sense is a
/// person (WordNet) and no object word itself.
pub(super) fn names_a_person(kb: &KnowledgeBase, t: &str, span: &Span) -> bool {
    let rest = &t[span.1..];
    if !rest.starts_with(' ') {
        return false;
    }
    let Some(next) = rest.split_whitespace().next() else {
        return false;
    };
    let next = next
        .strip_suffix("'s")
        .or_else(|| next.strip_suffix('\''))
        .unwrap_or(next);
    let one = singular(next);
    crate::plan::lexicon::is_person(&one) && kb.object(&one).is_none() && kb.object(next).is_none()
}

pub(super) fn object_spans(
    kb: &KnowledgeBase,
    t: &str,
    scene: Option<(usize, usize, usize)>,
    masked: &[(usize, usize)],
    dims: &[Dims],
) -> Vec<Span> {
    // Objects; two names in a row are one object named by the last ("a sectional sofa", "a
    // stone coffin", "a desk chair"), or by the first when both fill one role ("a two-seater
    // sofa").
    let (obj_re, table) = object_matcher(kb);
    let mut raw: Vec<(usize, usize, String, bool)> = vec![];
    for m in obj_re.find_iter(t) {
        if masked.iter().any(|&(s, e)| m.start() < e && s < m.end()) {
            continue;
        }
        // "a computer lab", "a piano bar": a noun right before the scene's name names the kind
        // of scene, not an object in it.
        if scene.is_some_and(|(_, s, _)| {
            s > m.end() && t[m.end()..s].trim().is_empty() && !m.as_str().is_empty()
        }) {
            continue;
        }
        // "the bridge of a spaceship": the head noun of the scene's name, said of the place,
        // is the scene, not an object in it
        if scene.is_some_and(|(i, _, _)| {
            kb.scenes[i].name.rsplit(' ').next() == Some(super::singular(m.as_str()).as_str())
                && t[m.end()..].trim_start().starts_with("of ")
        }) {
            continue;
        }
        let (cat, plural) = table[m.as_str()].clone();
        if let Some(last) = raw.last_mut() {
            if t[last.1..m.start()].trim().is_empty() && (last.2 == cat || !last.3) {
                let one_role = crate::plan::roles::role_of(&last.2)
                    .is_some_and(|role| crate::plan::roles::role_of(&cat) == Some(role));
                // "a bench seat": a seat's name then a word as general as any seat
                let generic = word_list("generic_seats").contains(&m.as_str())
                    && last
                        .2
                        .rsplit(' ')
                        .next()
                        .is_some_and(|h| word_list("seats").contains(&h));
                if !one_role && !generic {
                    last.2 = cat;
                }
                last.1 = m.end();
                last.3 = plural;
                continue;
            }
        }
        raw.push((m.start(), m.end(), cat, plural));
    }
    let raw_known: Vec<(usize, usize)> = raw.iter().map(|o| (o.0, o.1)).collect();
    // Unknown objects: an indefinite noun phrase ("a harp", "two easels") whose head noun the
    // knowledge base lacks.
    let all = words_in(t, 0, t.len());
    let known_at = |p: usize| raw_known.iter().any(|o| p >= o.0 && p < o.1);
    // The end of the run of describing words from `j`, and whether a known object or the
    // scene's name cuts it short (the run is then their description).
    let run = |mut j: usize| {
        let first = j;
        while j < all.len()
            && is_adjective(all[j].1)
            && !inside(all[j].0, masked)
            && !known_at(all[j].0)
            && !(j > first && verb_after_noun(all[j].1, all.get(j + 1).map(|x| x.1)))
        {
            j += 1;
        }
        let cut = j < all.len() && (known_at(all[j].0) || inside(all[j].0, masked));
        (j, cut)
    };
    let mut k = 0;
    while k < all.len() {
        let (pos, w) = all[k];
        // "the cake on the table": a definite phrase the text puts on or by a thing it names
        // is a thing too, though not named before (checked once its words are known)
        // (and so is "my hamster cage on the desk", "her knitting on the side table", "a
        // changing table with nappies on it", "information panels on the walls": a phrase
        // after a possessive, or with no determiner after "with", "and" or a comma, that the
        // text puts on, by or under a thing it names, or hangs on a wall)
        let possessive = POSSESSIVES.contains(&w);
        let the = w == "the" || possessive;
        let bare = !the
            && is_adjective(w)
            && !known_at(pos)
            && (k == 0 || [",", "with", "and"].contains(&all[k - 1].1));
        let det = number_of(w).is_some() && !["no", "zero", "both"].contains(&w)
            || ["another", "some"].contains(&w)
            || the
            || bare;
        // "bunk beds for six campers", "a bedroom for my two boys", "a ballroom for a wedding
        // reception": whom or what a thing is for, not more things
        let after_for = |q: usize| {
            q > 0
                && (all[q - 1].1 == "for"
                    || q > 1 && POSSESSIVES.contains(&all[q - 1].1) && all[q - 2].1 == "for")
        };
        let for_whom = after_for(k);
        if !det
            || for_whom
            || inside(pos, masked)
            || dims.iter().any(|d| pos >= d.start && pos < d.end)
        {
            k += 1;
            continue;
        }
        // Words after the determiner up to a function word, verb or punctuation; a participle
        // right after the determiner describes what follows ("a stuffed owl", "two carved masks",
        // "a hanging scroll", "a sleeping dragon").
        let mut j = if bare { k } else { k + 1 };
        // "a couple of deckchairs", "a pair of easels", "a dozen crates": the count's words
        // come before the thing
        if !bare
            && all.get(j + 1).is_some_and(|x| x.1 == "of")
            && all
                .get(j)
                .is_some_and(|x| ["couple", "pair", "few", "dozen", "handful"].contains(&x.1))
        {
            j += 2;
        }
        let from0 = j;
        if j + 1 < all.len()
            && is_verb(all[j].1)
            && (all[j].1.ends_with("ed") || all[j].1.ends_with("ing"))
            && is_adjective(all[j + 1].1)
        {
            j += 1;
        }
        let (mut j, mut known_next) = run(j);
        let mut from = from0;
        // "a hoard of gold", "a heap of gold coins": a quantity word names the heap of what
        // follows "of" (`kb/words.txt`: quantities), one object of the words after it.
        if j > k + 1
            && !known_next
            && quantities().contains(&all[j - 1].1)
            && all.get(j).is_some_and(|x| x.1 == "of")
        {
            from = j + 1;
            (j, known_next) = run(from);
        }
        // "a craft corner", "a reading nook", "a spare room": words before an area word or a
        // room's generic name (`kb/words.txt`: place_heads) describe the place
        let area_next = all.get(j).is_some_and(|x| {
            not_objects().contains(&x.1)
                || not_objects().contains(&singular(x.1).as_str())
                || word_list("place_heads").contains(&singular(x.1).as_str())
        });
        let placed_by_known = || {
            let mut q = j;
            // "cereals and juice on it": the phrase it is listed with is placed with it
            if all.get(q).is_some_and(|x| x.1 == "and") {
                q += 1;
                while q < j + 5
                    && all
                        .get(q)
                        .is_some_and(|x| is_adjective(x.1) || x.1 == "the")
                {
                    q += 1;
                }
            }
            let on = all.get(q).is_some_and(|x| x.1 == "on");
            // "a fruit machine by the door", "dust extractor in the corner", "a kiln against
            // the wall": put by the door or a window, in a corner or the middle, at a wall
            let word = |p: usize| all.get(p).map_or("", |x| x.1);
            let by = match (word(q), word(q + 1)) {
                ("next", "to") => Some(q + 2),
                ("by" | "near" | "beside" | "against" | "along" | "in", _) => Some(q + 1),
                _ => None,
            };
            if let Some(p) = by {
                let p = if ["the", "a", "one", "each", "every"].contains(&word(p)) {
                    p + 1
                } else {
                    p
                };
                let p = if ["back", "far", "front", "side", "left", "right", "end"]
                    .contains(&word(p))
                {
                    p + 1
                } else {
                    p
                };
                let place = match word(q) {
                    "in" => ["corner", "corners", "middle", "centre", "center"].contains(&word(p)),
                    "against" | "along" => ["wall", "walls"].contains(&word(p)),
                    _ => ["door", "doors", "window", "windows", "entrance", "wall"]
                        .contains(&word(p)),
                };
                // "a dresser loaded with dishes against the wall", "a desk with drawers by
                // the window": a phrase said after "with" is what the thing before has, and
                // the place is said of that thing
                if place && !(bare && k > 0 && all[k - 1].1 == "with") {
                    return true;
                }
            }
            match all.get(q).map(|x| x.1) {
                Some("on" | "under" | "beside" | "atop" | "upon" | "near") => q += 1,
                Some("next") if all.get(q + 1).is_some_and(|x| x.1 == "to") => q += 2,
                _ => return false,
            }
            // "a side table with her knitting on": on the thing it is said with
            if on && all.get(q).is_none_or(|x| x.1 == ",") {
                return true;
            }
            if all.get(q).is_some_and(|x| {
                [
                    "the", "a", "an", "its", "their", "each", "every", "one", "our", "my",
                ]
                .contains(&x.1)
            }) {
                q += 1;
            }
            // "... on it", "... on the back wall", "... on the walls"
            let hung = |q: usize| {
                (q..(q + 3).min(all.len()))
                    .find(|&p| !is_adjective(all[p].1) || matches!(all[p].1, "wall" | "walls"))
                    .is_some_and(|p| matches!(all[p].1, "wall" | "walls"))
            };
            all.get(q)
                .is_some_and(|x| known_at(x.0) || ["it", "them"].contains(&x.1))
                || on && hung(q)
        };
        if j > from && !known_next && !area_next && (!(the || bare) || placed_by_known()) {
            let head = all[j - 1].1;
            let ok = !head.ends_with("'s")
                && !head.ends_with('\'')
                && !not_objects().contains(&head)
                && !not_objects().contains(&singular(head).as_str())
                && crate::plan::offline::style_word(head).is_none()
                // "an old brick warehouse": a place's name is where things are, not a thing
                && !super::setting::names_place(kb, &singular(head))
                && !names_part_of(kb, &singular(head), &raw)
                && head.len() > 2;
            if ok {
                let start = all[from].0;
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
    raw
}

/// Words that own what follows, as "the" does ("my hamster cage on the desk").
const POSSESSIVES: &[&str] = &["my", "our", "his", "her", "their", "your"];

/// Whether the unknown noun `head` is the last word of another name of a thing the text names
/// (`raw`): "a bus stop with a shelter" says again the bus stop, which is a bus shelter.
fn names_part_of(kb: &KnowledgeBase, head: &str, raw: &[Span]) -> bool {
    raw.iter().filter(|o| !o.2.is_empty()).any(|o| {
        kb.names().any(|(n, k)| {
            k.category == o.2 && n.contains(' ') && n.rsplit(' ').next() == Some(head)
        })
    })
}

/// Whether a name "X of Y" is said in the plural of its head X ("buckets of flowers" is several
/// flower buckets, where "a chest of drawers" is one).
fn plural_head(name: &str) -> bool {
    name.split_once(" of ")
        .is_some_and(|(h, _)| !h.contains(' ') && singular(h) != h)
}

/// A regex over names and what each name means: (category, is plural).
type NameMatcher = (Regex, BTreeMap<String, (String, bool)>);

/// Object names (categories, synonyms and their plurals) to (category, is plural).
pub(super) fn object_matcher(kb: &KnowledgeBase) -> &'static NameMatcher {
    static M: OnceLock<NameMatcher> = OnceLock::new();
    M.get_or_init(|| {
        let mut table = BTreeMap::new();
        for (name, o) in kb.names() {
            table.insert(name.to_string(), (o.category.clone(), plural_head(name)));
        }
        for (name, o) in kb.names() {
            for p in plurals(name) {
                table.entry(p).or_insert_with(|| (o.category.clone(), true));
            }
        }
        (alternation(table.keys()), table)
    })
}
