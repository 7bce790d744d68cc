//! Roles that furniture fills (`kb/roles.txt`): a named object that fills a role replaces the
//! scene's default of that role instead of adding to it ("a single bed" in a bedroom is its bed),
//! a default that serves only what is absent goes (no TV, no TV stand), a default that holds only
//! what the text says is not there goes with it (no magazines, no magazine rack), and "nothing else" /
//! "just ..." keeps only what the text names.
use std::collections::{BTreeMap, BTreeSet};
use std::sync::OnceLock;

/// The role table: role name to categories, and "needs" lines: category to what it serves.
struct Roles {
    roles: Vec<(String, Vec<String>)>,
    needs: Vec<(String, Vec<String>)>,
    /// "holds" lines: a category to the things it is there to hold.
    holds: Vec<(String, Vec<String>)>,
    /// Names that say only the role of what they name ("shelving units").
    generic: Vec<String>,
    /// "has" lines: a category to the things it has as parts (a salon station's mirror).
    has: Vec<(String, Vec<String>)>,
}

fn roles() -> &'static Roles {
    static R: OnceLock<Roles> = OnceLock::new();
    R.get_or_init(|| {
        parse(
            include_str!("kb/roles.txt"),
            super::kb::KnowledgeBase::builtin(),
        )
        .expect("the built-in role table is valid (tested)")
    })
}

/// Reads a role table; every line must read and name categories of `kb`, or the error names
/// the line and the word.
fn parse(text: &str, kb: &super::kb::KnowledgeBase) -> Result<Roles, String> {
    let mut r = Roles {
        roles: vec![],
        needs: vec![],
        holds: vec![],
        generic: vec![],
        has: vec![],
    };
    for (ln, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let err = |m: String| format!("roles.txt line {}: {m}", ln + 1);
        let cols: Vec<&str> = line.split('|').map(str::trim).collect();
        let list = |s: &str| -> Result<Vec<String>, String> {
            s.split(',')
                .map(str::trim)
                .filter(|c| !c.is_empty())
                .map(|c| match kb.object(c) {
                    Some(o) if o.category == c => Ok(c.to_string()),
                    Some(o) => Err(err(format!("`{c}` is a name of `{}`", o.category))),
                    None => Err(err(format!("unknown object `{c}`"))),
                })
                .collect()
        };
        match cols.as_slice() {
            ["needs", cat, served] => {
                let cat = list(cat)?
                    .pop()
                    .ok_or_else(|| err("needs a category".into()))?;
                r.needs.push((cat, list(served)?));
            }
            ["holds", cat, held] => {
                let cat = list(cat)?
                    .pop()
                    .ok_or_else(|| err("holds a category".into()))?;
                r.holds.push((cat, list(held)?));
            }
            ["has", cat, parts] => {
                let cat = list(cat)?
                    .pop()
                    .ok_or_else(|| err("has a category".into()))?;
                r.has.push((cat, list(parts)?));
            }
            ["generic", names] => {
                for n in names.split(',').map(str::trim).filter(|n| !n.is_empty()) {
                    if kb.object(n).is_none() {
                        return Err(err(format!("unknown object name `{n}`")));
                    }
                    r.generic.push(n.to_string());
                }
            }
            [role, cats] if !matches!(*role, "needs" | "holds" | "has") => r.roles.push((role.to_string(), list(cats)?)),
            _ => {
                return Err(err(
                    "expected `role | categories`, `needs | category | categories`, `holds | category | categories`, `has | category | categories` or `generic | names`"
                        .into(),
                ))
            }
        }
    }
    Ok(r)
}

/// The role `category` fills, if any; a category the knowledge base lacks ("captain chair",
/// "child bed") fills the role of its head noun's category, else of its kind in WordNet ("a divan"
/// is the main seating).
pub fn role_of(category: &str) -> Option<&'static str> {
    let listed = |c: &str| {
        roles()
            .roles
            .iter()
            .find(|(_, cats)| cats.iter().any(|x| x == c))
            .map(|(r, _)| r.as_str())
    };
    listed(category).or_else(|| listed(super::lexicon::kind_category(category)?))
}

/// The role of the seats an audience sits on (a cinema's theater seats, a church's pews): seats
/// the text sets out in rows are that audience, in place of the defaults of this role.
pub const AUDIENCE: &str = "audience seating";

/// Whether `name` (an object name, singular) says only the role of what it names
/// (`kb/roles.txt`: generic): "a shelving unit" in a shop is its display shelf.
pub fn is_generic(name: &str) -> bool {
    roles().generic.iter().any(|n| n == name)
}

/// Whether `category` is there to hold `held` (`kb/roles.txt`: holds): a toy chest holds toys.
pub fn holds(category: &str, held: &str) -> bool {
    roles()
        .holds
        .iter()
        .any(|(c, h)| c == category && h.iter().any(|x| x == held))
}

/// Whether `category` has a `part` of its own (`kb/roles.txt`: has): a salon station's lit
/// mirror is the mirror a chair at it faces.
pub fn has_part(category: &str, part: &str) -> bool {
    roles()
        .has
        .iter()
        .any(|(c, parts)| c == category && parts.iter().any(|p| p == part))
}

/// Removes from `counts` the defaults (categories not in `named`) there only to hold what the
/// text says is not there: every category a default holds is in `negated` ("no magazines": no
/// magazine rack). One note per category removed.
pub fn without_what_they_hold(
    counts: &mut BTreeMap<String, u32>,
    named: &BTreeSet<String>,
    negated: &BTreeSet<String>,
) -> Vec<String> {
    let mut notes = vec![];
    for (c, held) in &roles().holds {
        if !named.contains(c)
            && held.iter().all(|h| negated.contains(h))
            && counts.remove(c).is_some()
        {
            notes.push(format!(
                "default {c} left out: what it holds ({}) is not wanted",
                held.join(", ")
            ));
        }
    }
    notes
}

/// Removes from `counts` the defaults (categories not in `named`) that a named object's role
/// replaces, those serving only absent things, and with `exclusive` every default. One note
/// per category removed.
pub fn apply(
    counts: &mut BTreeMap<String, u32>,
    named: &BTreeSet<String>,
    exclusive: bool,
) -> Vec<String> {
    let mut notes = vec![];
    if exclusive {
        let gone: Vec<String> = counts
            .keys()
            .filter(|c| !named.contains(*c))
            .cloned()
            .collect();
        for c in gone {
            counts.remove(&c);
            notes.push(format!(
                "default {c} left out: the text asks for nothing else"
            ));
        }
        return notes;
    }
    for (role, cats) in &roles().roles {
        let by = cats
            .iter()
            .find(|c| named.contains(*c))
            .or_else(|| named.iter().find(|c| role_of(c) == Some(role.as_str())));
        let Some(by) = by else {
            continue;
        };
        for c in cats {
            if !named.contains(c) && counts.remove(c).is_some() {
                notes.push(format!(
                    "default {c} left out: the named {by} is the {role}"
                ));
            }
        }
    }
    // Twice: a removal can leave another default serving nothing.
    for _ in 0..2 {
        for (c, served) in &roles().needs {
            if counts.contains_key(c)
                && !named.contains(c)
                && !served.iter().any(|s| counts.contains_key(s))
            {
                counts.remove(c);
                notes.push(format!(
                    "default {c} left out: nothing it serves ({}) is planned",
                    served.join(", ")
                ));
            }
        }
    }
    notes
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(defaults: &[(&str, u32)], named: &[&str]) -> BTreeMap<String, u32> {
        let mut counts: BTreeMap<String, u32> =
            defaults.iter().map(|(c, n)| (c.to_string(), *n)).collect();
        for c in named {
            counts.insert(c.to_string(), 1);
        }
        let named: BTreeSet<String> = named.iter().map(|c| c.to_string()).collect();
        apply(&mut counts, &named, false);
        counts
    }

    #[test]
    fn a_named_object_replaces_the_default_of_its_role() {
        let c = plan(&[("bed", 1), ("nightstand", 2)], &["single bed"]);
        assert!(!c.contains_key("bed"), "{c:?}");
        assert_eq!(c.get("nightstand"), Some(&2));
        let c = plan(&[("blackboard", 1)], &["whiteboard"]);
        assert!(!c.contains_key("blackboard"), "{c:?}");
    }

    #[test]
    fn an_unknown_object_fills_the_role_of_its_head_noun() {
        let c = plan(&[("bed", 1), ("nightstand", 2)], &["child bed"]);
        assert!(!c.contains_key("bed"), "{c:?}");
        // a known category is never read through its head ("coffee table" is no meal table)
        let c = plan(&[("dining table", 1)], &["coffee table"]);
        assert!(c.contains_key("dining table"), "{c:?}");
    }

    #[test]
    fn an_unknown_noun_fills_the_role_of_its_kind_in_wordnet() {
        // neither noun is in kb/objects.txt; WordNet says a divan is a sofa, an escritoire a desk
        let c = plan(&[("sofa", 1), ("coffee table", 1)], &["divan"]);
        assert!(!c.contains_key("sofa"), "{c:?}");
        assert!(c.contains_key("coffee table"), "{c:?}");
        let c = plan(&[("desk", 1), ("office chair", 1)], &["escritoire"]);
        assert!(!c.contains_key("desk"), "{c:?}");
        // an owl is a small thing to WordNet, no kind of furniture: it replaces nothing
        let c = plan(&[("sofa", 1)], &["owl"]);
        assert!(c.contains_key("sofa"), "{c:?}");
    }

    #[test]
    fn a_default_serving_nothing_goes() {
        let c = plan(&[("tv stand", 1), ("sofa", 1)], &[]);
        assert!(!c.contains_key("tv stand"), "{c:?}");
        let c = plan(&[("tv stand", 1), ("tv", 1)], &[]);
        assert!(c.contains_key("tv stand"), "{c:?}");
    }

    #[test]
    fn the_role_table_loads_and_a_broken_one_names_its_line() {
        assert!(
            roles().roles.len() >= 5 && !roles().needs.is_empty(),
            "the built-in role table has its rows"
        );
        let kb = crate::plan::kb::KnowledgeBase::builtin();
        let e = parse("# roles\nsleeping place | bed, cot bed", kb).err();
        assert_eq!(
            e.as_deref(),
            Some("roles.txt line 2: unknown object `cot bed`")
        );
        let e = parse("main seating | sofa, couch", kb).err();
        assert_eq!(
            e.as_deref(),
            Some("roles.txt line 1: `couch` is a name of `sofa`")
        );
        let e = parse("generic | shelving unit, shelving thingy", kb).err();
        assert_eq!(
            e.as_deref(),
            Some("roles.txt line 1: unknown object name `shelving thingy`")
        );
        assert!(is_generic("shelving unit") && !is_generic("bookcase"));
        let e = parse("needs | tv stand | tv\nneeds | tv stand", kb).err();
        assert!(
            e.as_deref()
                .is_some_and(|e| e.starts_with("roles.txt line 2: expected")),
            "{e:?}"
        );
    }
}
