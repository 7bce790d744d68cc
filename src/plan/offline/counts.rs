//! The counts stage of the offline planner: what each mention counts (named, distributed over
//! "each" of another object, a bare plural's default), clamped to what one category may hold.
//! Seats at tables are in `seats`, companions of what the text sets in `companions`.
use super::Draft;
use crate::plan::lang;
use crate::plan::spec::MAX_NUMBER;
use std::collections::{BTreeMap, BTreeSet};

/// Things a place sets out in "rows of chairs" when neither the text nor the place's defaults
/// count them (a waiting room's rows are its eight default chairs): three rows of four, the
/// smallest block that reads as rows facing something.
const SEATS_IN_ROWS: u32 = 12;

/// The counts the mentions give: negated and "no other" categories, counts distributed over the
/// instances of another object ("two chairs at each table"), a bare plural's default count.
pub(super) fn mention_counts(d: &mut Draft) {
    let kb = d.kb;
    let one_of_few = references_to_defaults(d);
    let Draft {
        r,
        sizes,
        cats,
        counts,
        defaults,
        negated,
        others,
        explicit,
        inferred,
        notes,
        ..
    } = d;
    // "two chairs at each table": (category, per instance, category of the distributor).
    let mut distributed: Vec<(String, u32, String)> = vec![];
    for (mi, (m, cat)) in r.mentions.iter().zip(cats.iter()).enumerate() {
        if m.negated {
            if m.adjectives.iter().any(|a| a == "other") {
                // "no other beds": no default of that kind or role, the named ones stay
                others.insert(cat.clone());
            } else {
                negated.insert(cat.clone());
            }
            continue;
        }
        if m.reference {
            // "each umbrella": the umbrellas named before
            continue;
        }
        if let Some(x) = m.each_of {
            inferred
                .entry(cat.clone())
                .or_insert_with(|| crate::plan::understood::span_phrase(r, mi, x));
            distributed.push((cat.clone(), m.count.unwrap_or(1) * m.parts, cats[x].clone()));
            continue;
        }
        match m.count {
            // "two bunks one above the other": a bunk is one bed of a bunk bed
            Some(n)
                if lang::singular(m.text.rsplit(' ').next().unwrap_or("")) == "bunk"
                    && lang::plural_means_one(cat).is_some() =>
            {
                let holds = lang::plural_means_one(cat).unwrap_or(1).max(1);
                *explicit.entry(cat.clone()).or_default() += n.div_ceil(holds);
            }
            Some(n) => {
                *explicit.entry(cat.clone()).or_default() += n;
            }
            // "a small office with a lamp on the desk": the one desk of a room the text sizes
            // small is the desk it refers to (the place's several desks are a bigger room's);
            // so is "an office where the desk faces the window": the text sets the desk in the
            // room as the one it has
            None if m.definite
                && one_of_few.contains(cat)
                && (r.room.is_some()
                    || r.scale < 1.0
                    || r.anchors.iter().any(|&(s, _)| s == mi)) =>
            {
                counts.insert(cat.clone(), 1);
            }
            None if m.definite => {
                counts.entry(cat.clone()).or_insert(1);
            }
            None if m.plural && lang::plural_means_one(cat).is_some() => {
                // "bunk beds": one bunk bed; "bunk beds for four kids": what sleeps four
                let holds = lang::plural_means_one(cat).unwrap_or(1).max(1);
                let n = r.people.map_or(1, |p| p.div_ceil(holds).max(1));
                *explicit.entry(cat.clone()).or_default() += n;
            }
            // "two rows of lockers": rows said of a name that is singular in the knowledge base
            // (a "lockers" unit) are rows of several all the same; "a row of lockers" is the one
            None if m.plural || m.rows > 1 => {
                if !explicit.contains_key(cat) {
                    // "three rows of benches": a row is two or more things side by side
                    let d = defaults
                        .get(cat)
                        .copied()
                        .unwrap_or(0)
                        .max(2)
                        .max(2 * m.rows)
                        .max(match m.in_rows && !defaults.contains_key(cat) {
                            true => SEATS_IN_ROWS,
                            false => 0,
                        });
                    counts.insert(cat.clone(), d);
                }
            }
            None => {
                *explicit.entry(cat.clone()).or_default() += 1;
            }
        }
    }
    for (c, n) in explicit.iter() {
        counts.insert(c.clone(), *n);
    }
    // "six washing machines in a row along one wall": one row said along one wall is a run
    // standing against that wall (`relations`), not a block of rows in the room with a
    // band before it
    let one_wall = r.one_wall.clone();
    for (i, (m, cat)) in r.mentions.iter_mut().zip(cats.iter()).enumerate() {
        if one_wall.contains(&i) && m.rows <= 1 && !super::relations::hung(cat) {
            m.rows = 0;
            m.in_rows = false;
        }
    }
    // "rows of chairs": as many rows as make a block a little wider than deep
    for (m, cat) in r.mentions.iter_mut().zip(cats.iter()) {
        if m.in_rows && m.rows == 0 && !m.negated {
            let n = counts.get(cat).copied().unwrap_or(0);
            if n >= 4 {
                m.rows = ((n as f64 / 1.5).sqrt().round() as u32).clamp(2, n / 2);
            }
        }
    }
    // Distributive counts multiply by the instances of what they distribute over.
    let mut spread: BTreeMap<String, u32> = BTreeMap::new();
    for (c, per, x) in &distributed {
        let over = counts.get(x).copied().unwrap_or(1).max(1);
        // ("eight chairs at each round table" and a head table: its party besides)
        let said: Vec<&String> = distributed.iter().map(|d| &d.2).collect();
        let besides = super::seats::other_tables_seats(kb, x, c, counts, explicit, sizes, &said);
        *spread.entry(c.clone()).or_default() += per * over + besides;
    }
    for (c, n) in spread {
        let total = explicit.get(&c).copied().unwrap_or(0) + n;
        explicit.insert(c.clone(), total);
        counts.insert(c, total);
    }
    // "a study with a lamp on the desk": a bare noun names the scene's single default of that
    // noun (its floor lamp), read as the kind the text asks for.
    for (m, cat) in r.mentions.iter().zip(cats.iter()) {
        if m.negated
            || m.reference
            || m.plural
            || m.text.contains(' ')
            || m.count.is_some_and(|n| n > 1)
            || defaults.contains_key(cat)
        {
            continue;
        }
        let head = lang::singular(&m.text);
        let same: Vec<&String> = defaults
            .iter()
            .filter(|(c, n)| **n == 1 && c.rsplit(' ').next() == Some(head.as_str()))
            .map(|(c, _)| c)
            .collect();
        let [was] = same[..] else {
            continue;
        };
        if !cats.contains(was) && !explicit.contains_key(was) && counts.remove(was).is_some() {
            notes.push(format!(
                "default {was} left out: the named {cat} is the {head} asked for"
            ));
        }
    }
}

/// Categories the text names only by a definite singular ("a lamp on the desk") where the
/// place has several of them by default (an office's desks).
fn references_to_defaults(d: &Draft) -> BTreeSet<String> {
    let said_otherwise = |cat: &String| {
        d.r.mentions
            .iter()
            .zip(d.cats.iter())
            .any(|(m, c)| c == cat && !m.negated && !m.reference && !m.definite)
    };
    d.r.mentions
        .iter()
        .zip(d.cats.iter())
        .filter(|(m, _)| m.definite && !m.plural && m.count.is_none() && !m.negated)
        .map(|(_, c)| c)
        .filter(|c| d.defaults.get(*c).is_some_and(|n| *n > 1))
        .filter(|c| !said_otherwise(c))
        .cloned()
        .collect()
}

/// Clamps counts (a note names each) and drops what has none.
pub(super) fn clamp(d: &mut Draft) {
    let Draft { counts, notes, .. } = d;
    for (c, n) in counts.iter_mut() {
        if *n > MAX_NUMBER {
            notes.push(format!(
                "{n} {c}: more than {MAX_NUMBER} of one category is not planned; using {MAX_NUMBER}"
            ));
            *n = MAX_NUMBER;
        }
    }
    counts.retain(|_, n| *n > 0);
}
