//! Counts that compose across noun phrases: distributive phrases ("four tables with two chairs
//! each", "a laptop on every desk", "three tables, each with a lamp and a vase", "a bench down
//! each side"), seats of a table ("a table for six", "eight tables, each laid for four") and rows
//! ("six rows of ten seats", "two rows of recliners, three in each row"). A mention after
//! "each" or "every" refers back to an object already named, never a new one.
use super::{number_of, re, Mention, Reading};
use crate::plan::spec::Anchor;

/// Placement words that put a thing said of each window at that window ("beneath each one").
const WINDOW_PLACES: &[&str] = &[
    "under", "beneath", "below", "by", "near", "beside", "next", "front", "at", "before",
];

/// How many of a thing "each side" and its kin stand for.
const PARTS: &[(&str, u32)] = &[("side", 2), ("end", 2), ("corner", 4), ("wall", 4)];

/// The mention a later "each"/"every" phrase distributes over: the nearest mention before `pos`
/// that names several things (a count above one or a plural), of another category than `not`.
fn distributor(r: &Reading, pos: usize, not: &str) -> Option<usize> {
    r.mentions
        .iter()
        .enumerate()
        .rev()
        .find(|(_, m)| {
            m.end <= pos
                && !m.negated
                && !m.reference
                && m.category != not
                && (m.count.is_some_and(|n| n > 1) || (m.plural && m.count.is_none()))
        })
        .map(|(i, _)| i)
}

/// The first named mention of the category of mention `i` (what "each umbrella" refers to).
fn referent(r: &Reading, i: usize) -> usize {
    let cat = &r.mentions[i].category;
    r.mentions
        .iter()
        .position(|m| &m.category == cat && !m.reference && !m.negated)
        .unwrap_or(i)
}

/// Multiplier of a part phrase ("each side" = 2) at the start of `s`.
fn part(s: &str) -> Option<u32> {
    let w = s.split_whitespace().next()?;
    let w = w.trim_matches(|c: char| !c.is_alphabetic());
    PARTS
        .iter()
        .find(|(p, _)| *p == w || format!("{p}s") == w)
        .map(|&(_, n)| n)
}

/// "a plant in each corner", "a clock on each wall": corners something stands in and walls are
/// the room's, never the thing named just before ("a stool at each corner" of a table is the
/// table's).
fn rooms_part(lead: &str, what: &str) -> bool {
    let what = what.trim_end_matches('s');
    what == "wall" || what == "corner" && lead.split_whitespace().last() == Some("in")
}

/// A countable part of the room that "each" can be about (`kb/words.txt`: features).
fn is_feature(w: &str) -> bool {
    let sg = super::singular(w);
    super::word_list("features").contains(&sg.as_str())
}

/// The last "N (adjectives) features" of `before` ("three big windows"): its end, N and the
/// feature's noun; only of that feature when `of` is given.
fn feature_count<'a>(before: &'a str, of: Option<&str>) -> Option<(usize, u32, &'a str)> {
    let mut words: Vec<(usize, &str)> = vec![];
    let mut pos = 0;
    for w in before.split(' ') {
        let core = w.trim_matches(|c: char| !c.is_alphanumeric() && c != '\'' && c != '-');
        words.push((pos + w.len(), core));
        pos += w.len() + 1;
    }
    let mut last = None;
    for (i, &(_, w)) in words.iter().enumerate() {
        let Some(n) = number_of(w).filter(|&n| n >= 2) else {
            continue;
        };
        for &(end, noun) in words.iter().skip(i + 1).take(3) {
            let same = of.is_none_or(|o| super::singular(o) == super::singular(noun));
            if is_feature(noun) && same {
                last = Some((end, n, noun));
                break;
            }
            if !super::is_adjective(noun) {
                break;
            }
        }
    }
    last
}

/// "a picnic table under a gazebo and four chairs around the table": a definite bare noun
/// whose kind the text named before ("the table": a picnic table) refers to that object; it
/// is no new one.
fn definite_references(r: &mut Reading) {
    counted_references(r);
    owner_references(r);
    for k in 0..r.mentions.len() {
        let m = &r.mentions[k];
        // "the headmaster's desk" is a particular one of its own
        if !m.definite
            || m.count.is_some()
            || m.negated
            || m.owner.is_some()
            || m.text.contains(' ')
        {
            continue;
        }
        let head = super::singular(&m.text);
        let earlier = r.mentions[..k]
            .iter()
            .rev()
            .find(|o| {
                !o.negated
                    && !o.reference
                    && o.category != m.category
                    && o.category.rsplit(' ').next() == Some(head.as_str())
            })
            .map(|o| o.category.clone());
        if let Some(c) = earlier {
            let m = &mut r.mentions[k];
            m.category = c;
            m.reference = true;
        }
    }
}

/// "a dragon's lair with a dragon", "a horse's stable with a horse": the owner a place is named
/// after, when the text names one of its kind again, is that one; it is no second one.
fn owner_references(r: &mut Reading) {
    let t = r.text.clone();
    for k in 0..r.mentions.len() {
        let m = &r.mentions[k];
        let owner = ["'s ", "' "].iter().any(|p| t[m.end..].starts_with(p))
            || t[..m.end].ends_with("'s")
            || t[..m.end].ends_with('\'');
        if !owner || m.negated || m.count.is_some_and(|n| n != 1) || m.reference {
            continue;
        }
        let again = r.mentions[k + 1..]
            .iter()
            .any(|o| !o.negated && o.category == m.category);
        if again {
            r.mentions[k].reference = true;
        }
    }
}

/// "two armchairs and a lamp between the two armchairs", "... between both armchairs": a
/// counted definite noun phrase of a kind the text named before, no more of them than were
/// named, refers to those; it is no new group.
fn counted_references(r: &mut Reading) {
    for k in 0..r.mentions.len() {
        let m = &r.mentions[k];
        let Some(n) = m.count.filter(|&n| n > 0 && m.definite && !m.negated) else {
            continue;
        };
        let named = r.mentions[..k].iter().any(|o| {
            let many = o.count.map_or(o.plural, |c| c >= n);
            !o.negated && !o.reference && o.category == m.category && many
        });
        if named {
            let m = &mut r.mentions[k];
            m.count = None;
            m.reference = true;
        }
    }
}

/// Reads the distributive counts, seats and rows of `r` (after its mentions).
/// The mention a rows phrase at `start..end` of `t` sets out: the one just after it ("rows of
/// chairs", `after`) or just before it ("chairs in rows"); none when it is negated or already
/// has its rows.
fn rowed_mention<'a>(
    r: &'a mut Reading,
    t: &str,
    start: usize,
    end: usize,
    after: bool,
) -> Option<&'a mut Mention> {
    let i = if after {
        r.mentions
            .iter()
            .position(|m| m.start >= end && t[end..m.start].split_whitespace().count() <= 2)
    } else {
        r.mentions
            .iter()
            .rposition(|m| m.end <= start && t[m.end..start].split_whitespace().count() <= 3)
    }?;
    let m = &mut r.mentions[i];
    (m.rows == 0 && !m.negated).then_some(m)
}

pub(super) fn read_counts(r: &mut Reading) {
    definite_references(r);
    let t = r.text.clone();
    // "each X" / "every X" / "per X": a reference to X.
    let each_before = re(r"\b(?:each|every|per)\s+(?:[a-z'-]+\s+){0,2}$");
    for k in 0..r.mentions.len() {
        let m = &r.mentions[k];
        let from = m.start.saturating_sub(30);
        let from = (from..=m.start)
            .find(|&i| t.is_char_boundary(i))
            .unwrap_or(m.start);
        if each_before.is_match(&t[from..m.start]) && m.count.is_none() && !m.negated {
            // the same category, or a kind of it named by the bare head noun ("two single
            // beds ... each bed")
            let bare = !m.text.contains(' ');
            let head = super::singular(&m.text);
            let earlier = r.mentions[..k]
                .iter()
                .filter(|o| !o.negated)
                .find(|o| {
                    o.category == m.category
                        || (bare && o.category.rsplit(' ').next() == Some(head.as_str()))
                })
                .map(|o| o.category.clone());
            let m = &mut r.mentions[k];
            m.reference = earlier.is_some();
            m.definite = true;
            if let Some(c) = earlier {
                m.category = c;
            }
        }
    }
    let each_of_the =
        re(r"\b(?:each|every|one|all) of (?:the|its|their|these|those)(?: [a-z0-9-]+)?$");
    let n = r.mentions.len();
    // "Y each", "Y apiece", "Y per X", "Y at each X", "Y beneath each one", "Y on each side".
    let tail_re = re(
        r"^[ ,]*(?:(?:[a-z'-]+ ){0,4}?)(?:(each|every|per|apiece|either|both)\b(?: (one|of them|(?:([a-z'-]+) )?(?:side|sides|end|ends|corner|corners|wall)))?)",
    );
    let each_has = re(r"^ (?:with|having|holding|has|gets|topped with)\b");
    for k in 0..n {
        let m = &r.mentions[k];
        if m.negated || m.reference || m.each_of.is_some() {
            continue;
        }
        let next = r.mentions.get(k + 1).map(|o| o.start).unwrap_or(t.len());
        let clause_end = t[m.end..]
            .find([',', ';', '.', '!', '?'])
            .map(|i| m.end + i)
            .unwrap_or(t.len());
        let tail = &t[m.end..next.min(clause_end + 1).max(m.end)];
        let Some(c) = tail_re.captures(tail) else {
            continue;
        };
        // Words between the noun and "each" are placement words, not a new clause.
        let lead = &tail[..c.get(1).map(|g| g.start()).unwrap_or(0)];
        if lead.contains(" with ") || lead.contains(" and ") || lead.split_whitespace().count() > 4
        {
            continue;
        }
        let word = c.get(1).map(|g| g.as_str()).unwrap_or("");
        // "two tables by the window each with 2 chairs": "each with" says what each of them
        // has (read below), not that there are this many of it for each of something else
        if word == "each"
            && c.get(2).is_none()
            && each_has.is_match(&tail[c.get(1).map_or(0, |g| g.end())..])
        {
            continue;
        }
        // "three booths next to each other", "two armchairs facing each other": reciprocal,
        // not distributive
        if word == "each" && tail[c.get(1).map_or(0, |g| g.end())..].starts_with(" other") {
            continue;
        }
        // "each long side": an adjective may describe the part, nothing else may stand there
        if c.get(3).is_some_and(|a| !super::is_adjective(a.as_str())) {
            continue;
        }
        let what = c.get(2).map(|g| match c.get(3) {
            Some(_) => g.as_str().rsplit(' ').next().unwrap_or(g.as_str()),
            None => g.as_str(),
        });
        // "either" / "both" count only sides and ends ("a chair either side of it")
        if matches!(word, "either" | "both") && what.and_then(part).is_none() {
            continue;
        }
        let after_each = c.get(0).map(|g| g.end()).unwrap_or(0);
        let cat = m.category.clone();
        if let Some(p) = what.and_then(part) {
            // "two cannons on each side": as many as the parts, times a named owner if any
            // ("a bench down each side of every table").
            let rest = &tail[after_each..];
            let of_at = m.end + after_each + (rest.len() - rest.trim_start().len()) + 3;
            let pronoun = re(r"^of (?:it|them|this|that)\b").is_match(rest.trim_start());
            let owner = if rest.trim_start().starts_with("of ") && !pronoun {
                // the owner is named right after "of" ("of every table"), never the thing
                // itself said again later ("a lamp on each nightstand")
                (k + 1..n)
                    .find(|&j| r.mentions[j].reference && r.mentions[j].start <= of_at + 25)
                    .map(|j| referent(r, j))
                    .filter(|&o| o != k)
            } else if k > 0
                && !t[r.mentions[k - 1].end..m.start].contains(['.', ';'])
                && !rooms_part(lead, what.unwrap_or(""))
            {
                // "a big table in the centre, a bench on each long side": the sides of the
                // thing just named
                Some(k - 1)
            } else {
                None
            };
            let m = &mut r.mentions[k];
            // "two armchairs either side of the fire": as many as the sides with "either" or
            // "both" is the pair, one a side ("an armchair on either side" is two)
            let one_a_side = matches!(word, "either" | "both") && m.count == Some(p);
            m.parts = if one_a_side { 1 } else { p };
            m.each_of = owner;
            if owner.is_none() {
                if m.count.is_none() && m.plural {
                    // "lockers down both sides": one or more a side, the walls may say more
                    r.parts_counted.push(k);
                }
                let m = &mut r.mentions[k];
                m.count = Some(m.count.unwrap_or(1) * m.parts);
                m.parts = 1;
            }
            continue;
        }
        // "three windows and a plant beneath each one": a counted part of the room (no object)
        // named nearer than any object is what "each" is about.
        let next_word = tail[after_each..]
            .split_whitespace()
            .next()
            .unwrap_or("")
            .trim_matches(|c: char| !c.is_alphabetic());
        if what.is_some_and(|w| w == "one" || w == "of them") || is_feature(next_word) {
            let near = distributor(r, m.start, &cat).map(|x| r.mentions[x].end);
            let named_feature = if is_feature(next_word) {
                feature_count(&t[..m.start], Some(next_word))
            } else {
                feature_count(&t[..m.start], None)
            };
            if let Some((_, f, noun)) =
                named_feature.filter(|&(e, _, _)| near.is_none_or(|n| e > n))
            {
                let m = &mut r.mentions[k];
                m.count = Some(m.count.unwrap_or(1) * f);
                // "a plant beneath each one" of the windows: each stands at a window
                let placed = lead.split_whitespace().any(|w| WINDOW_PLACES.contains(&w));
                if placed && super::singular(noun) == "window" {
                    r.anchors.push((k, Anchor::Window));
                }
                continue;
            }
        }
        let over = match (word, what) {
            ("per" | "each" | "every", None) if next <= m.end + tail.len() && k + 1 < n => {
                // "per table", "at each bench": the next mention, a reference
                let nm = &r.mentions[k + 1];
                let between = t[m.end..nm.start].trim_end();
                if between.ends_with(word) && nm.reference {
                    Some(referent(r, k + 1))
                } else if between.ends_with(word) && !nm.negated {
                    // "a tea set on each table" of a tea room: the tables it has, named here
                    Some(k + 1)
                } else if each_of_the.is_match(between) {
                    // "a lamp on each of the two nightstands": the nightstands, named here
                    Some(if nm.reference {
                        referent(r, k + 1)
                    } else {
                        k + 1
                    })
                } else if word == "each" || word == "apiece" {
                    distributor(r, m.start, &cat)
                } else {
                    None
                }
            }
            _ => distributor(r, m.start, &cat),
        };
        if let Some(x) = over {
            r.mentions[k].each_of = Some(x);
        }
    }
    // "X, each with Y and Z", "X, each sheltering a pair of Y", "X, each in front of a Y"
    // (only "with" and its kin own a definite Y, "each with its own lamp"; "each facing the
    // window" names one window).
    let each_clause = re(
        r"\beach (?:(with|having|holding|has|gets|topped with)|[a-z]+ing|in front of|under|beneath|beside|next to|by|behind|against|below|above|on top of|on)\b",
    );
    let own_group = re(
        r"^ (?:(?:next to|facing|beside|opposite) (?:each other|one another)|side by side|(?:along|against|on|by|at|in|into|near) (?:the|one|a) (?:[a-z]+ ){0,2}(?:wall|walls|corner|corners|door|doorway|entrance|window|windows|room))\b",
    );
    // "16 desks in four rows, each desk with a monitor and a chair", "every table has a lamp":
    // the thing named again after "each" owns what it has
    let each_named =
        re(r"\b(?:each|every) (?:[a-z'-]+ ){0,2}?(?:with|having|holding|has|gets|topped with)\b");
    let named_owner = |r: &Reading, c: regex::Match| {
        let i = r
            .mentions
            .iter()
            .position(|m| m.reference && m.start >= c.start() && m.end <= c.end() && !m.negated)?;
        let x = referent(r, i);
        (x != i).then_some(x)
    };
    let clauses: Vec<(regex::Match, bool, Option<usize>)> = each_clause
        .captures_iter(&t)
        .filter_map(|c| Some((c.get(0)?, c.get(1).is_none(), None)))
        .chain(
            each_named
                .find_iter(&t)
                .filter_map(|c| Some((c, false, Some(named_owner(r, c)?)))),
        )
        .collect();
    for (c, placed, owner) in clauses {
        let Some(x) = owner.or_else(|| distributor(r, c.start(), "")) else {
            continue;
        };
        let mut end = t[c.end()..]
            .find([',', ';', '.', '!', '?'])
            .map(|i| c.end() + i)
            .unwrap_or(t.len());
        // "desks each with a laptop and three phone booths along the east wall": a thing set
        // by the room's parts or among its own kind is a new item of the list, and so is all
        // that follows it
        if let Some(m) = r
            .mentions
            .iter()
            .find(|m| m.start >= c.end() && m.end <= end && own_group.is_match(&t[m.end..end]))
        {
            end = m.start;
        }
        for m in r.mentions.iter_mut() {
            if m.start >= c.end()
                && m.end <= end
                && !m.negated
                && !m.reference
                && m.each_of.is_none()
                && !(placed && m.definite)
            {
                m.each_of = Some(x);
            }
        }
    }
    // Seats of a table: "a table for six", "tables for two", "each laid for four", "that seats 8",
    // "eight tables of six" (of people: no noun follows the number)
    let seats = re(
        r"^[ ,]*(?:each )?(?:(?:that|which) )?(?:(?:is )?(?:laid|set|seating|seats|seat) )?(?:for |of )?([0-9]+|[a-z]+)\b",
    );
    let of_people = re(
        r"^ of [0-9a-z]+(?:\s*(?:[,.;:!?]|$)| (?:people|guests|diners|and|with|for|each|apiece|by|near|in|around|along|under)\b)",
    );
    for k in 0..n {
        let m = &r.mentions[k];
        if m.negated || m.reference {
            continue;
        }
        let tail = &t[m.end..t.len().min(m.end + 40)];
        let Some(c) = seats.captures(tail) else {
            continue;
        };
        let whole = c.get(0).map(|g| g.as_str()).unwrap_or("");
        let of = whole.contains("of ") && of_people.is_match(tail);
        if !(whole.contains("for ") || whole.contains("seat") || of) {
            continue;
        }
        if let Some(v) = number_of(&c[1]).filter(|&v| v >= 2) {
            r.seats_for.push((k, v));
        }
    }
    // Rows: "N rows of M Y", "Y in N rows of M", "N rows of Y, M in each row".
    let rows_of_m = re(r"\b([0-9]+|[a-z]+) (?:rows|lines|columns) of ([0-9]+|[a-z]+)\b");
    for c in rows_of_m.captures_iter(&t) {
        let (Some(a), Some(b)) = (number_of(&c[1]), number_of(&c[2])) else {
            continue;
        };
        if a < 2 {
            continue;
        }
        let end = c.get(0).map(|g| g.end()).unwrap_or(0);
        let start = c.get(0).map(|g| g.start()).unwrap_or(0);
        // the thing in rows: right after ("rows of ten seats"), else right before ("desks in ...")
        let after = r.mentions.iter().position(|m| {
            m.start >= end && t[end..m.start].split_whitespace().all(super::is_adjective)
        });
        let before = r
            .mentions
            .iter()
            .rposition(|m| m.end <= start && t[m.end..start].split_whitespace().count() <= 3);
        if let Some(i) = after.or(before) {
            let m = &mut r.mentions[i];
            if after.is_some() || m.count.is_none() {
                m.count = Some(a * b);
            }
            m.rows = a;
        }
    }
    let rows_then = re(
        r"\b([0-9]+|[a-z]+) (?:rows|lines) of [^,.;]*?[,;]? (?:with )?([0-9]+|[a-z]+) (?:in each|per|to a|in every|on each|each) (?:row|line)\b",
    );
    for c in rows_then.captures_iter(&t) {
        let (Some(a), Some(b)) = (number_of(&c[1]), number_of(&c[2])) else {
            continue;
        };
        let (s, e) = c.get(0).map(|g| (g.start(), g.end())).unwrap_or((0, 0));
        if let Some(m) = r
            .mentions
            .iter_mut()
            .find(|m| m.start >= s && m.end <= e && !m.negated)
        {
            m.count = Some(a * b);
            m.rows = a;
        }
    }
    // "ten pews, five each side of the aisle": two blocks side by side, five rows deep.
    let each_side =
        re(r"\b([0-9]+|[a-z]+) (?:on )?(?:each|either) side of the (?:aisle|nave|gangway)\b");
    for c in each_side.captures_iter(&t) {
        let Some(n) = number_of(&c[1]) else { continue };
        let start = c.get(0).map(|g| g.start()).unwrap_or(0);
        if let Some(m) = r
            .mentions
            .iter_mut()
            .rev()
            .find(|m| m.end <= start && t[m.end..start].split_whitespace().count() <= 3)
        {
            if m.rows == 0 && !m.negated {
                m.rows = n;
            }
        }
    }
    // Rows the text does not count: "rows of chairs", "chairs in rows".
    let rows_unsaid = re(r"\b(rows|lines) of\b|\bin (rows|lines)\b");
    for c in rows_unsaid.captures_iter(&t) {
        let (start, end) = c.get(0).map(|g| (g.start(), g.end())).unwrap_or((0, 0));
        let before = t[..start].split_whitespace().last().unwrap_or("");
        if number_of(before).is_some() || ["in", "into"].contains(&before) {
            continue;
        }
        if let Some(m) = rowed_mention(r, &t, start, end, c.get(1).is_some()) {
            m.in_rows = true;
        }
    }
    // Rows without a count of their own: "Y in N rows", "Y, two rows", "a row of Y", "Y in a row".
    let rows_only = re(r"\b(a|one|[0-9]+|[a-z]+) (?:single )?(?:rows?|lines?)\b( of)?");
    for c in rows_only.captures_iter(&t) {
        let n = match &c[1] {
            "a" | "one" => Some(1),
            w => number_of(w),
        };
        let Some(n) = n else { continue };
        let (start, end) = c.get(0).map(|g| (g.start(), g.end())).unwrap_or((0, 0));
        if let Some(m) = rowed_mention(r, &t, start, end, c.get(2).is_some()) {
            m.rows = n;
        }
    }
}
