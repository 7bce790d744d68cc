//! Companions follow what the text sets: "12 desks" get 12 chairs, "for 24 students" 24 seats,
//! "20 chairs" the tables they need.
use super::Draft;
use crate::plan::lang;
use crate::plan::spec::{ObjectSpec, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};

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
                        on_wall: None,
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
                    on_wall: None,
                };
                (c.clone(), o)
            })
            .collect(),
        ..probe.clone()
    };
    for seat in &cats_now {
        // A rug under a table or a coffee table before a sofa is no companion to count by.
        use crate::plan::spec::RelationKind::{Front, Opposite, Under};
        let Some((mut kind, mut table)) = crate::plan::groups::group_of(&probe, seat) else {
            continue;
        };
        if matches!(kind, Under | Front | Opposite) {
            continue;
        }
        // A default seat whose own table is gone (the teacher's chair, once "the invigilator's
        // desk" took the teacher desk's place) is no seat of the others; one whose own table
        // is still there (the round tables of a reception that also names its top table) is
        // counted by it.
        if defaults.contains_key(seat) && !explicit.contains_key(seat) {
            let was = crate::plan::groups::group_of(&default_probe, seat);
            match was {
                Some((k, w)) if w != table && counts.contains_key(&w) => (kind, table) = (k, w),
                Some((_, w)) if w != table => continue,
                _ => {}
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
                // "christmas dinner for ten": a place of one table lays that one for them (up
                // to a dozen, as a home's table is); others take as many as they need
                let one = (defaults.get(&table) == Some(&1) && p <= 12)
                    .then(|| super::seats::table_laid(kb, &table, seat, adjectives, p))
                    .flatten();
                if let Some(size) = one {
                    sizes.insert(table.clone(), size);
                    counts.insert(table.clone(), 1);
                } else {
                    counts.insert(table.clone(), p.div_ceil(per.max(1)).max(1));
                }
                inferred.entry(table.clone()).or_insert(said);
            }
            continue;
        }
        // (each table takes no more than the defaults give one, or four: a big round table
        // that could take twelve is laid as the place lays it)
        if table_named && !seat_named {
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
            // and the seats of the other tables it sits at that the text names (the top
            // table's row beside the round tables)
            let besides =
                super::seats::other_tables_seats(kb, &table, seat, counts, explicit, sizes, &[]);
            let n = (counts[&table] * each + besides).saturating_sub(taken);
            counts.insert(seat.clone(), n);
            if let Some(i) = first_mention(&table).filter(|_| !named.contains(seat)) {
                inferred
                    .entry(seat.clone())
                    .or_insert_with(|| crate::plan::understood::phrase(r, i));
            }
            // a desk one person works at is named with its chair: a small room trims the
            // place's defaults, never the seat of a desk the text asks for
            if n > 0 && per == 1 && matches!(kind, At | AtBack) {
                named.insert(seat.clone());
            }
        } else if seat_named && !table_named && per < 12 {
            // six bar stools want a longer bar, not a second one
            let grown = crate::plan::groups::seats_per_grown(&probe, seat, &table).unwrap_or(per);
            let need = counts[seat].div_ceil(grown.max(1));
            let t = counts.get(&table).copied().unwrap_or(1);
            // "two barber chairs" in a salon whose defaults give each chair its station: the
            // stations, still as many as the defaults, follow the chairs the text counts, fewer
            // as well as more (not chairs said "at each" of something else)
            let paired = matches!(
                (defaults.get(seat), defaults.get(&table)),
                (Some(s), Some(dt)) if *dt > 0 && *s == dt * per && *dt == t
            );
            let counted = explicit.get(seat) == counts.get(seat)
                && !r
                    .mentions
                    .iter()
                    .zip(cats.iter())
                    .any(|(m, c)| c == seat && m.each_of.is_some());
            if need > t || (paired && counted && need < t) {
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
