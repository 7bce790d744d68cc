//! The counts stage of the offline planner: what each mention counts (named, distributed over
//! "each" of another object, "a table for six"), and the companions that follow what the text
//! sets ("12 desks" get 12 chairs, "for 24 students" 24 seats, "20 chairs" the tables they
//! need), clamped to what one category may hold.
use super::Draft;
use crate::plan::kb::KnowledgeBase;
use crate::plan::lang;
use crate::plan::spec::{ObjectSpec, SceneSpec, SceneType, MAX_NUMBER};
use std::collections::{BTreeMap, BTreeSet};

/// The seat category that goes round `table`: one the plan already has, else the first of the
/// usual seats that the functional groups put at such a table.
pub(super) fn seat_for(table: &str, counts: &BTreeMap<String, u32>) -> Option<String> {
    const USUAL: &[&str] = &[
        "dining chair",
        "cafe chair",
        "patio chair",
        "office chair",
        "bar stool",
    ];
    let probe = |seat: &str| {
        let mut objects = BTreeMap::new();
        for c in [table, seat] {
            objects.insert(
                c.to_string(),
                ObjectSpec {
                    number: 1,
                    size: [1.0, 1.0, 1.0],
                    description: String::new(),
                    rows: 0,
                    sizes: vec![],
                },
            );
        }
        let spec = bare_spec(objects);
        crate::plan::groups::group_of(&spec, seat).is_some_and(|(_, t)| t == table)
    };
    counts
        .keys()
        .map(String::as_str)
        .chain(USUAL.iter().copied())
        .find(|s| *s != table && probe(s))
        .map(str::to_string)
}

/// The counts the mentions give: negated and "no other" categories, counts distributed over the
/// instances of another object ("two chairs at each table"), a bare plural's default count.
pub(super) fn mention_counts(d: &mut Draft) {
    let kb = d.kb;
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
            Some(n) => {
                *explicit.entry(cat.clone()).or_default() += n;
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
            None if m.plural => {
                if !explicit.contains_key(cat) {
                    let d = defaults.get(cat).copied().unwrap_or(0).max(2);
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
    // Distributive counts multiply by the instances of what they distribute over.
    let mut spread: BTreeMap<String, u32> = BTreeMap::new();
    for (c, per, x) in &distributed {
        let over = counts.get(x).copied().unwrap_or(1).max(1);
        // ("eight chairs at each round table" and a head table: its party besides)
        let said: Vec<&String> = distributed.iter().map(|d| &d.2).collect();
        let besides = other_tables_seats(kb, x, c, counts, explicit, sizes, &said);
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

/// How many `seat`s go round a `table` of footprint `size`.
fn capacity(table: &str, seat: &str, size: [f64; 3]) -> Option<u32> {
    let objects = [(table, size), (seat, [0.5, 0.5, 0.9])]
        .into_iter()
        .map(|(c, size)| {
            let o = ObjectSpec {
                number: 1,
                size,
                description: String::new(),
                rows: 0,
                sizes: vec![],
            };
            (c.to_string(), o)
        })
        .collect();
    let spec = bare_spec(objects);
    crate::plan::groups::seats_per(&spec, seat, table)
}

/// The footprint of a `table` laid for `per` people (kb/seating.txt), its height kept: a round
/// one when its kind or the text says so. Only plain dining-like tables (a picnic table's size
/// holds its benches, a pool table seats nobody).
fn table_laid(
    kb: &KnowledgeBase,
    table: &str,
    adjectives: &BTreeMap<String, Vec<String>>,
    per: u32,
) -> Option<[f64; 3]> {
    let o = kb.object(table)?;
    let round = o.archetype == "round_table"
        || adjectives
            .get(table)
            .is_some_and(|a| a.iter().any(|w| w == "round"));
    if !(o.archetype == "table" || round) {
        return None;
    }
    let [w, d] = crate::plan::seating::table_for(per.max(1), round)?;
    Some([w, d, o.size[2]])
}

/// "A table for six": that many seats at each of those tables. The people the text seats
/// ("for 24 students"), unless a table's seats were given.
pub(super) fn seats_for(d: &mut Draft) -> Option<u32> {
    let kb = d.kb;
    let Draft {
        r,
        sizes,
        cats,
        counts,
        defaults,
        named,
        explicit,
        inferred,
        adjectives,
        laid,
        ..
    } = d;
    let mut seated = false;
    // "six tables for two and two tables for six": the seats of every such mention of one
    // table category add up
    for &(ti, per) in &r.seats_for {
        let table = &cats[ti];
        let Some(&tables) = counts.get(table) else {
            continue;
        };
        let Some(seat) = seat_for(table, counts) else {
            continue;
        };
        seated = true;
        inferred
            .entry(seat.clone())
            .or_insert_with(|| crate::plan::understood::seats_phrase(r, ti));
        let same: Vec<(usize, u32)> = r
            .seats_for
            .iter()
            .filter(|&&(tj, _)| cats[tj] == *table)
            .copied()
            .collect();
        if same.len() > 1 && same[0].0 != ti {
            continue;
        }
        // "desks for twelve people": things that seat one each, said in the plural with no
        // count, are as many as the people
        let m = &r.mentions[ti];
        let size = sizes
            .get(table)
            .copied()
            .or_else(|| kb.object(table).map(|o| o.size));
        let one_each = m.plural
            && m.count.is_none()
            && same.len() == 1
            && size.and_then(|z| capacity(table, &seat, z)) == Some(1);
        if one_each {
            counts.insert(table.clone(), per);
            explicit.insert(table.clone(), per);
        }
        let tables = if one_each { 1 } else { tables };
        let n = if same.len() > 1 {
            same.iter()
                .map(|&(tj, p)| p * r.mentions[tj].count.unwrap_or(tables).max(1))
                .sum()
        } else {
            per * tables.max(1)
        };
        // the seats of another table the text names that they also go to ("a head table and
        // ten round tables for eight": the head table's party besides the eighty)
        let said: Vec<&String> = r.seats_for.iter().map(|&(tj, _)| &cats[tj]).collect();
        let n = n + other_tables_seats(kb, table, &seat, counts, explicit, sizes, &said);
        // "tables for two": a table the size of one laid for two, not a long one; "six tables
        // for two and two tables for six": each table the size of its own seats, and the
        // seats said for it at it
        let most = same.iter().map(|&(_, p)| p).max().unwrap_or(per);
        let each: Vec<u32> = same
            .iter()
            .flat_map(|&(tj, p)| std::iter::repeat_n(p, r.mentions[tj].count.unwrap_or(1) as usize))
            .collect();
        let mixed = each.iter().any(|&p| p != most) && each.len() == tables as usize;
        if !sizes.contains_key(table) {
            let laid_for = |p: u32| table_laid(kb, table, adjectives, p);
            let list: Option<Vec<(u32, [f64; 3])>> =
                each.iter().map(|&p| Some((p, laid_for(p)?))).collect();
            match (mixed, list, laid_for(most), kb.object(table)) {
                (true, Some(list), Some(big), _) => {
                    sizes.insert(table.clone(), big);
                    laid.insert(table.clone(), (seat.clone(), list));
                }
                // a usual table that seats them keeps its size unless a smaller one is laid for them
                (_, _, Some(size), Some(o))
                    if size[0] * size[1] < o.size[0] * o.size[1]
                        || capacity(table, &seat, o.size).is_some_and(|c| c < most) =>
                {
                    sizes.insert(table.clone(), size);
                }
                _ => {}
            }
        }
        let total = if explicit.contains_key(&seat) && !defaults.contains_key(&seat) {
            explicit[&seat].max(n)
        } else {
            n
        };
        explicit.insert(seat.clone(), total);
        named.insert(seat.clone());
        counts.insert(seat, total);
    }
    if seated {
        None
    } else {
        r.people
    }
}

/// The seats of the tables other than `table` that the text names with no seats said (`said`:
/// those with their seats said) and that `seat` sits at (a head table beside round tables laid for eight).
fn other_tables_seats(
    kb: &KnowledgeBase,
    table: &str,
    seat: &str,
    counts: &BTreeMap<String, u32>,
    explicit: &BTreeMap<String, u32>,
    sizes: &BTreeMap<String, [f64; 3]>,
    said: &[&String],
) -> u32 {
    counts
        .iter()
        .filter(|&(t, _)| t != table && explicit.contains_key(t) && !said.contains(&t))
        .filter(|&(t, _)| seat_for(t, counts).as_deref() == Some(seat))
        .filter(|&(t, _)| {
            use crate::plan::spec::RelationKind::{Around, At, AtBack};
            matches!(
                crate::plan::groups::relation_between(seat, t),
                Some(Around | At | AtBack)
            )
        })
        .filter_map(|(t, &k)| {
            let size = sizes
                .get(t)
                .copied()
                .or_else(|| kb.object(t).map(|o| o.size))?;
            Some(k * capacity(t, seat, size)?)
        })
        .sum()
}

/// Companions follow what the text sets: "12 desks" get 12 chairs, "for 24 students" (`people`)
/// 24 seats, "20 chairs" the tables they need.
pub(super) fn companions(d: &mut Draft, people: Option<u32>) {
    let Draft {
        kb,
        r,
        cats,
        scene_type,
        counts,
        defaults,
        named,
        sizes,
        unknown,
        explicit,
        inferred,
        notes,
        adjectives,
        ..
    } = d;
    let scene_type = *scene_type;
    let first_mention = |c: &str| cats.iter().position(|x| x == c);
    let probe = SceneSpec {
        scene_type,
        scene_text: String::new(),
        room: None,
        objects: counts
            .iter()
            .map(|(c, n)| {
                let size = sizes
                    .get(c)
                    .copied()
                    .or_else(|| kb.object(c).map(|o| o.size))
                    .or_else(|| unknown.get(c).copied())
                    .unwrap_or([0.7, 0.6, 0.9]);
                (
                    c.clone(),
                    ObjectSpec {
                        number: *n,
                        size,
                        description: String::new(),
                        rows: 0,
                        sizes: vec![],
                    },
                )
            })
            .collect(),
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    let cats_now: Vec<String> = counts.keys().cloned().collect();
    let default_probe = SceneSpec {
        objects: defaults
            .iter()
            .map(|(c, n)| {
                let size = kb.object(c).map(|o| o.size).unwrap_or([0.7, 0.6, 0.9]);
                let o = ObjectSpec {
                    number: *n,
                    size,
                    description: String::new(),
                    rows: 0,
                    sizes: vec![],
                };
                (c.clone(), o)
            })
            .collect(),
        ..probe.clone()
    };
    for seat in &cats_now {
        // A rug under a table or a coffee table before a sofa is no companion to count by.
        use crate::plan::spec::RelationKind::{Front, Opposite, Under};
        let Some((kind, table)) = crate::plan::groups::group_of(&probe, seat) else {
            continue;
        };
        if matches!(kind, Under | Front | Opposite) {
            continue;
        }
        // A default seat whose own table is gone (the teacher's chair, once "the invigilator's
        // desk" took the teacher desk's place) is no seat of the others.
        if defaults.contains_key(seat) && !explicit.contains_key(seat) {
            let was = crate::plan::groups::group_of(&default_probe, seat).map(|g| g.1);
            if was.is_some_and(|w| w != table) {
                continue;
            }
        }
        let Some(per) = crate::plan::groups::seats_per(&probe, seat, &table) else {
            continue;
        };
        // "the laptop": a definite mention names it too
        let seat_named = explicit.contains_key(seat)
            || r.mentions
                .iter()
                .zip(cats.iter())
                .any(|(m, c)| c == seat && m.definite && !m.negated && !m.reference);
        // "along the counter": one particular table, however many seats it gets
        let one_said = r
            .mentions
            .iter()
            .zip(cats.iter())
            .any(|(m, c)| *c == table && m.definite && !m.plural && !m.negated && !m.reference);
        let table_named = explicit.contains_key(&table) || one_said;
        // "for 24 students" seats the scene's main seats (its most numerous seat category).
        let main_seat = cats_now
            .iter()
            .filter(|c| {
                use crate::plan::spec::RelationKind::{Around, At, AtBack, Circle};
                crate::plan::groups::group_of(&probe, c)
                    .is_some_and(|(k, _)| matches!(k, Around | At | AtBack | Circle))
            })
            .max_by_key(|c| {
                (
                    defaults.get(*c).copied().unwrap_or(0),
                    counts.get(*c).copied().unwrap_or(0),
                )
            });
        if let Some(p) = people.filter(|_| main_seat == Some(seat)) {
            let said = crate::plan::understood::people_phrase(&r.text, p);
            if !seat_named {
                counts.insert(seat.clone(), p);
                inferred.entry(seat.clone()).or_insert_with(|| said.clone());
            }
            if !table_named {
                counts.insert(table.clone(), p.div_ceil(per.max(1)).max(1));
                inferred.entry(table.clone()).or_insert(said);
            }
            continue;
        }
        if table_named && !seat_named && per < 12 {
            // Seats a table the way the scene's defaults do, within its capacity.
            let (ds, dt) = (defaults.get(seat).copied(), defaults.get(&table).copied());
            let mut each = match (ds, dt) {
                (Some(s), Some(t)) if t > 0 => s.div_ceil(t).min(per),
                _ => per.min(4),
            };
            // "a little table and chairs": a table said to be small seats two
            let small = adjectives.get(&table).is_some_and(|a| {
                a.iter().any(|w| {
                    lang::object_footprint(w).is_some_and(|f| f < 1.0)
                        || lang::object_scale(w).is_some_and(|f| f < 1.0)
                })
            });
            if small {
                each = each.min(2);
            }
            // seats of another kind the text puts at that table take their places ("a desk
            // and a gaming chair" has one chair); what stands on it takes no seat's place, but
            // the place of what fills the same slot on it ("a laptop on the desk" is its
            // computer: one group line of `kb/groups.txt`)
            use crate::plan::groups::{group_of_category, relation_between};
            use crate::plan::spec::RelationKind::{Around, At, AtBack, Circle};
            let seat_kind = |c: &str| {
                crate::plan::groups::group_of(&probe, c)
                    .filter(|(k, t)| *t == table && matches!(k, Around | At | AtBack | Circle))
                    .is_some()
            };
            let same_slot = |c: &str| {
                let line = group_of_category(c);
                line.is_some()
                    && line == group_of_category(seat)
                    && relation_between(c, &table) == relation_between(seat, &table)
            };
            let takes = |c: &str| {
                if seat_kind(seat) {
                    seat_kind(c)
                } else {
                    same_slot(c)
                }
            };
            // what the text names, "the laptop" too
            let said: BTreeSet<&String> = explicit
                .keys()
                .chain(
                    r.mentions
                        .iter()
                        .zip(cats.iter())
                        .filter(|(m, _)| m.definite && !m.negated && !m.reference)
                        .map(|(_, c)| c),
                )
                .collect();
            let taken: u32 = said
                .into_iter()
                .filter(|c| *c != seat && takes(c))
                .map(|c| counts.get(c).copied().unwrap_or(0))
                .sum();
            counts.insert(seat.clone(), (counts[&table] * each).saturating_sub(taken));
            if let Some(i) = first_mention(&table).filter(|_| !named.contains(seat)) {
                inferred
                    .entry(seat.clone())
                    .or_insert_with(|| crate::plan::understood::phrase(r, i));
            }
        } else if seat_named && !table_named && per < 12 {
            let need = counts[seat].div_ceil(per.max(1));
            let t = counts.get(&table).copied().unwrap_or(1);
            if need > t {
                counts.insert(table.clone(), need);
                if let Some(i) = first_mention(seat) {
                    inferred
                        .entry(table.clone())
                        .or_insert_with(|| crate::plan::understood::phrase(r, i));
                }
            }
        }
    }
    if people.is_some()
        && !counts
            .keys()
            .any(|c| crate::plan::groups::group_of(&probe, c).is_some())
    {
        notes.push("\"for N people\": this scene has no seats to scale; counts kept".into());
    }
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

/// A spec of just these objects, with no room, anchors or relations: what the group rules
/// (seats at a table) are asked about while counts are read.
fn bare_spec(objects: BTreeMap<String, ObjectSpec>) -> SceneSpec {
    SceneSpec {
        scene_type: SceneType::Indoor,
        scene_text: String::new(),
        room: None,
        objects,
        anchors: BTreeMap::new(),
        relations: vec![],
    }
}
