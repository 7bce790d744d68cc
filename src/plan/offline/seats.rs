//! Seats at tables while counts are read: the seat category that goes round a table, how many
//! fit round one, the footprint of a table laid for N, and "a table for six" (the people the
//! text seats).
use super::Draft;
use crate::plan::kb::KnowledgeBase;
use crate::plan::spec::{ObjectSpec, SceneSpec, SceneType};
use std::collections::BTreeMap;

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
                    on_wall: None,
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
                on_wall: None,
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
/// A long table grows past the furnishers' line when its seats are wider than the 0.6 m of
/// edge a place takes there (fourteen office chairs need a longer boardroom table).
pub(super) fn table_laid(
    kb: &KnowledgeBase,
    table: &str,
    seat: &str,
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
    // one at each end from eight, the rest along the two long sides, each seat and a hand's
    // width of room beside it
    let seat_width = kb.object(seat).map_or(0.5, |s| s.size[0]);
    let ends = if per >= 8 { 2 } else { 0 };
    let along = per.saturating_sub(ends).div_ceil(2) as f64;
    let w = if round {
        w
    } else {
        w.max(along * (seat_width + 0.1))
    };
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
            let laid_for = |p: u32| table_laid(kb, table, &seat, adjectives, p);
            let list: Option<Vec<(u32, [f64; 3])>> =
                each.iter().map(|&p| Some((p, laid_for(p)?))).collect();
            match (mixed, list, laid_for(most), kb.object(table)) {
                (true, Some(list), Some(big), _) => {
                    sizes.insert(table.clone(), big);
                    laid.insert(table.clone(), (seat.clone(), list));
                }
                // a table laid for them is the size furnishers give a table for that many
                // (kb/seating.txt), smaller or larger than the usual one: eight do not squeeze
                // round a six-seater that the seat rules would fit them to
                (_, _, Some(size), Some(_)) => {
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

/// "A garden party for ten with a long table": the people a place is for, in a plan with no
/// seats at anything, sit at the table the text names (laid for them when it is the only one);
/// a plan that already seats someone keeps its seats, which `companions` scales.
pub(super) fn people_at_the_table(d: &mut Draft, people: Option<u32>) {
    use crate::plan::spec::RelationKind::{Around, At, AtBack, Circle};
    let Some(p) = people else { return };
    let kb = d.kb;
    let Draft {
        r,
        cats,
        counts,
        sizes,
        inferred,
        adjectives,
        ..
    } = d;
    let probe = bare_spec(
        counts
            .keys()
            .map(|c| {
                let o = ObjectSpec {
                    number: 1,
                    size: [1.0, 1.0, 1.0],
                    description: String::new(),
                    rows: 0,
                    sizes: vec![],
                    on_wall: None,
                };
                (c.clone(), o)
            })
            .collect(),
    );
    let seated = counts.keys().any(|c| {
        crate::plan::groups::group_of(&probe, c)
            .is_some_and(|(k, _)| matches!(k, Around | At | AtBack | Circle))
    });
    if seated {
        return;
    }
    let table = r
        .mentions
        .iter()
        .zip(cats.iter())
        .filter(|(m, c)| !m.negated && !m.reference && counts.contains_key(*c))
        .find_map(|(_, t)| {
            let seat = seat_for(t, counts)?;
            let around = crate::plan::groups::relation_between(&seat, t) == Some(Around);
            around.then(|| (t.clone(), seat))
        });
    let Some((table, seat)) = table else { return };
    if counts[&table] == 1 && !sizes.contains_key(&table) {
        if let Some(size) = table_laid(kb, &table, &seat, adjectives, p) {
            sizes.insert(table.clone(), size);
        }
    }
    counts.insert(seat.clone(), p);
    inferred
        .entry(seat)
        .or_insert_with(|| crate::plan::understood::people_phrase(&r.text, p));
}

/// Companions follow what the text sets: "12 desks" get 12 chairs, "for 24 students" (`people`)
/// 24 seats, "20 chairs" the tables they need.
/// A spec of just these objects, with no room, anchors or relations: what the group rules
/// (seats at a table) are asked about while counts are read.
/// The seats of the tables other than `table` that the text names with no seats said (`said`:
/// those with their seats said) and that `seat` sits at (a head table beside round tables laid for eight).
pub(super) fn other_tables_seats(
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
