//! Seats the text sets out in rows ("twelve chairs in three rows facing the piano", "three rows
//! of five chairs facing a stage") are an audience's, not the seats drawn up to the scene's
//! default tables: the default tables they would sit at (a classroom's school desks, a
//! conference room's table) are left out, and nothing else changes. Named tables stay, and seats at tables the text names keep
//! them.
use super::Draft;
use crate::plan::spec::{ObjectSpec, RelationKind, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};

/// Removes the default tables whose only seats the text puts in rows; one note per table.
pub(super) fn seats_in_rows_leave_their_tables(d: &mut Draft) {
    let Draft {
        kb,
        r,
        scene,
        cats,
        scene_type,
        counts,
        defaults,
        named,
        explicit,
        notes,
        ..
    } = d;
    // the seat categories the text sets out in rows
    let rowed: BTreeSet<&String> = r
        .mentions
        .iter()
        .enumerate()
        .zip(cats.iter())
        .filter(|((k, m), _)| {
            !m.negated
                && !m.reference
                && (m.rows > 0
                    || m.in_rows
                    || r.relations
                        .iter()
                        .any(|(s, rel, _)| s == k && *rel == RelationKind::Row))
        })
        .map(|(_, c)| c)
        .filter(|c| named.contains(*c))
        .collect();
    if rowed.is_empty() {
        return;
    }
    // the tables the scene's defaults draw those seats up to
    let probe = SceneSpec {
        scene_type: *scene_type,
        scene_text: String::new(),
        room: None,
        objects: defaults
            .iter()
            .chain(counts.iter())
            .map(|(c, n)| {
                let o = ObjectSpec {
                    number: *n,
                    size: kb.object(c).map_or([0.7, 0.6, 0.9], |o| o.size),
                    description: String::new(),
                    rows: 0,
                    sizes: vec![],
                    on_wall: None,
                };
                (c.clone(), o)
            })
            .collect::<BTreeMap<_, _>>(),
        anchors: BTreeMap::new(),
        relations: vec![],
    };
    let mut gone = BTreeSet::new();
    for seat in rowed {
        // (seats round a table that is the place's own, a banquet's round tables, leave it
        // standing; a conference room's table goes when its chairs are set out in rows)
        use RelationKind::{Around, At, AtBack, Next};
        let Some((kind, table)) = crate::plan::groups::group_of(&probe, seat) else {
            continue;
        };
        let default_table = defaults.contains_key(&table)
            && !named.contains(&table)
            && !explicit.contains_key(&table);
        let own = scene.is_some_and(|sc| sc.own.contains(&table));
        let drawn_up = matches!(kind, At | AtBack) || (matches!(kind, Around | Next) && !own);
        if drawn_up && default_table {
            gone.insert(table);
        }
    }
    for t in gone {
        if counts.remove(&t).is_some() {
            notes.push(format!(
                "default {t} left out: the seats it would hold are set out in rows"
            ));
        }
    }
}
