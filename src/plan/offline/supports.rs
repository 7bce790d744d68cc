//! Supports counted by what they hold: "ten computers on benches" (a plural support with no
//! count) gets as many benches as ten computers need, each with a person's working width.
use super::Draft;
use crate::plan::gcp::classes::{Class, Placements};
use crate::plan::spec::RelationKind;

/// The width along a support's front that one thing placed on it takes when a person uses it
/// there (a seat in front): about a person's elbow room at a work surface.
const WORK_WIDTH: f64 = 0.7;

/// Raises the count of every plural support the text gives no count ("on benches") to what the
/// things placed on it need: its width holds `max(thing's width, WORK_WIDTH)` per thing.
pub(super) fn plural_supports(d: &mut Draft) {
    let table = Placements::builtin();
    for (oi, m) in d.r.mentions.iter().enumerate() {
        if !m.plural || m.count.is_some() || m.definite || m.reference || m.negated {
            continue;
        }
        let sup = &d.cats[oi];
        let Some(width) = d.kb.object(sup).map(|o| o.size[0]) else {
            continue;
        };
        let mut held: Vec<&String> =
            d.r.relations
                .iter()
                .filter(|&&(_, rel, o)| o == oi && rel == RelationKind::Over)
                .map(|&(si, _, _)| &d.cats[si])
                .filter(|c| matches!(table.class(c), Class::OnSurface(_)))
                .collect();
        held.sort();
        held.dedup();
        let mut need = 0u32;
        for c in held {
            let n = d.counts.get(c).copied().unwrap_or(0);
            let w = d.kb.object(c).map_or(WORK_WIDTH, |o| o.size[0]);
            let per = (width / w.max(WORK_WIDTH)).floor().max(1.0) as u32;
            need += n.div_ceil(per);
        }
        if need > d.counts.get(sup).copied().unwrap_or(0) {
            d.counts.insert(sup.clone(), need);
            d.notes.push(format!(
                "{need} {sup}: as many as the things placed on them need"
            ));
        }
    }
}

/// Bare "tables" that hold something worked at ("computers on tables") are tables to work at:
/// the work table (`kb/roles.txt`) its things go on in `kb/groups.txt`, a desk, not the dining
/// tables bare tables otherwise are; a single table ("a laptop on the table" of a kitchen) and
/// the tables of a place with tables to sit at (a cafe's, a classroom's: its meal tables or
/// pupil places) stay tables.
pub(super) fn work_tables(d: &mut Draft) {
    own_supports(d);
    for &(si, rel, oi) in &d.r.relations {
        let Some(m) = d.r.mentions.get(oi) else {
            continue;
        };
        let bare = crate::plan::lang::singular(&m.text) == "table";
        // "a laptop on the table" in a kitchen is on its table; a place with tables to sit at
        // (a cafe's, a classroom's) has those
        let sit_at = d.defaults.keys().any(|c| {
            crate::plan::roles::role_of(c).is_some_and(|r| r == "meal table" || r == "pupil place")
        });
        if rel != RelationKind::Over || !bare || !m.plural || sit_at || si >= d.cats.len() {
            continue;
        }
        let desk = crate::plan::groups::group_of_category(&d.cats[si])
            .and_then(|objs| objs.first())
            .filter(|c| crate::plan::roles::role_of(c) == Some("work table"));
        if let (Some(desk), Some(c)) = (desk, d.cats.get_mut(oi)) {
            *c = desk.to_string();
        }
    }
}

/// "a sewing machine on a table" in a sewing room: a bare "table" that something is said to be
/// on is the scene's default table made for it (the first of its supports in
/// `kb/placement.txt` that the scene holds), not another table beside that one.
fn own_supports(d: &mut Draft) {
    let table = Placements::builtin();
    for &(si, rel, oi) in &d.r.relations {
        let (Some(m), Some(held)) = (d.r.mentions.get(oi), d.cats.get(si)) else {
            continue;
        };
        let head = crate::plan::lang::singular(&m.text);
        if rel != RelationKind::Over || head != "table" || m.negated || m.reference {
            continue;
        }
        let Some(p) = table.get(held) else { continue };
        let own = p
            .supports
            .iter()
            .find(|c| d.defaults.contains_key(*c) && c.rsplit(' ').next() == Some(head.as_str()));
        if let (Some(own), Some(c)) = (own, d.cats.get_mut(oi)) {
            *c = own.clone();
        }
    }
}

/// What is said per instance of a thing ("an office chair at each one" of the tables) follows
/// that thing's final count, when its count grew after the reading (as many desks as the
/// computers on them need): never fewer than the count per instance times the instances.
pub(super) fn per_instance(d: &mut Draft) {
    let mut want: std::collections::BTreeMap<String, u32> = Default::default();
    for (m, c) in d.r.mentions.iter().zip(&d.cats) {
        let Some(x) = m.each_of.filter(|_| !m.negated) else {
            continue;
        };
        let over = d.cats.get(x).and_then(|o| d.counts.get(o)).copied();
        *want.entry(c.clone()).or_default() += m.count.unwrap_or(1) * m.parts * over.unwrap_or(1);
    }
    for (c, n) in want {
        let now = d.counts.get(&c).copied().unwrap_or(0);
        if n > now && now > 0 {
            d.counts.insert(c.clone(), n);
            d.explicit.insert(c, n);
        }
    }
}
