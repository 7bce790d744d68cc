//! Which thing of a scene an on_surface thing stands on: the first of its supports in
//! `kb/placement.txt` that the scene holds, else a thing of the scene that fills the role of one
//! of them (`kb/roles.txt`: a librarian's desk is a work table as a desk is, a science bench a
//! lab work surface as a lab desk is) and is low enough to set things on. A printer in a lab of
//! science benches stands on a bench, not on the floor beside them.
use super::{Class, Placements};
use crate::plan::spec::SceneSpec;

/// The highest top a thing found by its role is set on (a bar counter, not a wardrobe).
const TOP_MAX: f64 = 1.2;

/// The category of `spec` that `category`'s supports name or stand in for, if any.
pub fn support_in<'a>(table: &Placements, category: &str, spec: &'a SceneSpec) -> Option<&'a str> {
    let p = table.get(category)?;
    if !matches!(p.class, Class::OnSurface(_)) {
        return None;
    }
    if let Some((c, _)) = p
        .supports
        .iter()
        .find_map(|s| spec.objects.get_key_value(s.as_str()))
    {
        return Some(c.as_str());
    }
    let roles: Vec<&str> = p
        .supports
        .iter()
        .filter_map(|s| crate::plan::roles::role_of(s))
        .collect();
    spec.objects
        .iter()
        .filter(|(c, o)| {
            *c != category && o.size[2] <= TOP_MAX && !matches!(table.class(c), Class::OnSurface(_))
        })
        .find(|(c, _)| crate::plan::roles::role_of(c).is_some_and(|r| roles.contains(&r)))
        .map(|(c, _)| c.as_str())
}

/// Every category of `spec` that `category`'s supports name, in the table's order of
/// preference, else the one [`support_in`] finds by its role (a thing goes on the next one
/// when the first ones' tops are taken).
pub fn supports_in<'a>(table: &Placements, category: &str, spec: &'a SceneSpec) -> Vec<&'a str> {
    let Some(p) = table.get(category) else {
        return vec![];
    };
    let listed: Vec<&'a str> = p
        .supports
        .iter()
        .filter_map(|s| {
            spec.objects
                .get_key_value(s.as_str())
                .map(|(c, _)| c.as_str())
        })
        .collect();
    if listed.is_empty() {
        support_in(table, category, spec).into_iter().collect()
    } else {
        listed
    }
}
