//! An answer planned elsewhere (the LLM's) conformed to the reading of the text, so that both
//! planners hold what the sentence says: counts the text sets ("a table for six", "two chairs
//! at each table"), nothing it excludes ("no TV"), and a named object in place of the default
//! of its role (`kb/roles.txt`: a named single bed is the bedroom's bed). Pure: no I/O.
use super::kb::KnowledgeBase;
use super::offline::Plan;
use super::spec::{Anchor, SceneSpec};
use std::collections::{BTreeMap, BTreeSet};

/// Sets the count of `category` in `spec` to `n` (0 removes it), with the anchors and
/// relations of the instances that go; new instances take the category's default anchor.
fn set_count(spec: &mut SceneSpec, category: &str, n: u32) {
    let Some(o) = spec.objects.get_mut(category) else {
        return;
    };
    let old = o.number;
    if n == 0 {
        spec.objects.remove(category);
    } else {
        o.number = n;
        o.rows = o.rows.min(n);
    }
    for k in n + 1..=old {
        let id = format!("{category}{k}");
        spec.anchors.remove(&id);
        spec.relations.retain(|r| r.subject != id && r.object != id);
    }
    let anchor = KnowledgeBase::builtin()
        .object(category)
        .map(|o| o.anchor)
        .unwrap_or(Anchor::Others);
    for k in old + 1..=n {
        spec.anchors.insert(format!("{category}{k}"), anchor);
    }
}

/// Conforms `spec` to `reading` (the offline plan of the same text); one note per change.
pub fn conform(spec: &mut SceneSpec, reading: &Plan) -> Vec<String> {
    let mut notes = vec![];
    // What the text excludes, and what fills the same role ("no bath": no tub of any kind).
    let roles: BTreeSet<&str> = reading
        .negated
        .iter()
        .filter_map(|c| super::roles::role_of(c))
        .collect();
    let excluded: Vec<String> = spec
        .objects
        .keys()
        .filter(|c| {
            reading.negated.contains(*c)
                || !reading.named.contains(*c)
                    && super::roles::role_of(c).is_some_and(|r| roles.contains(r))
        })
        .cloned()
        .collect();
    for c in excluded {
        set_count(spec, &c, 0);
        notes.push(format!(
            "the answer has `{c}`, which the prompt excludes: removed"
        ));
    }
    for c in &reading.named {
        let (Some(have), Some(want)) = (spec.objects.get(c), reading.spec.objects.get(c)) else {
            continue;
        };
        let (have, want, rows) = (have.number, want.number, want.rows);
        if have != want {
            set_count(spec, c, want);
            notes.push(format!(
                "the answer has {have} `{c}`, the prompt asks for {want}: using {want}"
            ));
        }
        if let Some(o) = spec.objects.get_mut(c) {
            o.rows = rows;
        }
    }
    let mut counts: BTreeMap<String, u32> = spec
        .objects
        .iter()
        .map(|(c, o)| (c.clone(), o.number))
        .collect();
    let named: BTreeSet<String> = reading
        .named
        .iter()
        .filter(|c| counts.contains_key(*c))
        .cloned()
        .collect();
    notes.extend(super::roles::apply(&mut counts, &named, reading.exclusive));
    let gone: Vec<String> = spec
        .objects
        .keys()
        .filter(|c| !counts.contains_key(*c))
        .cloned()
        .collect();
    for c in gone {
        set_count(spec, &c, 0);
    }
    notes
}
