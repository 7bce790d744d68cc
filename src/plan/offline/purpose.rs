//! Seats said to be for someone: "two armchairs for visitors", "a sofa for waiting customers".
//! A named seat for those a default seat of the scene is named for (the office's visitor
//! chairs, the salon's waiting chairs) takes that default's place instead of adding to it.
//! It never removes what the text names, nor a default that is no seat.
//!
//! A place "for eight" whose text already seats eight ("eight desks, each with an office
//! chair") has no default seats besides (an open-plan office's meeting chairs), nor the default
//! tables only those seats were at.
use super::Draft;
use crate::plan::lang;

/// Removes the default seats whose place a named seat "for" the same people takes.
pub(super) fn seats_for_someone(d: &mut Draft) {
    let Draft {
        kb,
        r,
        cats,
        counts,
        defaults,
        named,
        notes,
        ..
    } = d;
    let after =
        regex::Regex::new(r"^,? (?:meant |kept |set )?for (?:the |our |their |any )?([a-z]+)")
            .expect("valid regex");
    for (m, cat) in r.mentions.iter().zip(cats.iter()) {
        if m.negated || m.reference || !lang::is_seat(cat) {
            continue;
        }
        let Some(c) = after.captures(&r.text[m.end..]) else {
            continue;
        };
        let whom = lang::singular(&c[1]);
        // "visitor chair", or a name of it with that word ("guest chair" is a visitor chair)
        let for_them = |d: &str| {
            let head = d.rsplit(' ').next().unwrap_or(d);
            d.split(' ').next() == Some(whom.as_str())
                || kb
                    .object(&format!("{whom} {head}"))
                    .is_some_and(|o| o.category == d)
        };
        let gone: Vec<String> = defaults
            .keys()
            .filter(|d| *d != cat && d.contains(' ') && !named.contains(*d))
            .filter(|d| lang::is_seat(d) && for_them(d))
            .cloned()
            .collect();
        for g in gone {
            if counts.remove(&g).is_some() {
                notes.push(format!(
                    "default {g} left out: the named {cat} for {} takes its place",
                    &c[1]
                ));
            }
        }
    }
}

/// "an open-plan office for eight: eight desks, each with an office chair": the seats the text
/// counts are the `people` the place is for, so the scene's other default seats go, with the
/// default tables they leave without seats; those of the place's own or essential furniture
/// (a classroom's teacher's desk) stay.
pub(super) fn seats_for_all(d: &mut Draft, people: Option<u32>) {
    let Some(p) = people else { return };
    let Draft {
        scene,
        counts,
        defaults,
        named,
        explicit,
        notes,
        ..
    } = d;
    let kept = |c: &str| scene.is_some_and(|s| s.own.iter().chain(&s.essential).any(|k| k == c));
    let said: u32 = explicit
        .iter()
        .filter(|(c, _)| lang::is_seat(c) && named.contains(*c))
        .map(|(c, _)| counts.get(c).copied().unwrap_or(0))
        .sum();
    if said < p {
        return;
    }
    let at_kept = |c: &str| {
        crate::plan::groups::partners_of(c)
            .iter()
            .any(|t| counts.contains_key(*t) && (kept(t) || named.contains(*t)))
    };
    let gone: Vec<String> = defaults
        .keys()
        .filter(|c| counts.contains_key(*c) && !named.contains(*c) && !explicit.contains_key(*c))
        .filter(|c| lang::is_seat(c) && !kept(c) && !at_kept(c))
        .cloned()
        .collect();
    for c in &gone {
        counts.remove(c);
        notes.push(format!(
            "default {c} left out: the {said} seats the text names are the {p} the place is for"
        ));
    }
    // the default tables only those seats were at
    let tables: Vec<String> = gone
        .iter()
        .flat_map(|c| crate::plan::groups::group_of_category(c).unwrap_or_default())
        .map(|t| t.to_string())
        .filter(|t| counts.contains_key(t) && defaults.contains_key(t))
        .filter(|t| !named.contains(t) && !kept(t))
        .filter(|t| {
            !counts.keys().any(|s| {
                lang::is_seat(s)
                    && crate::plan::groups::group_of_category(s)
                        .is_some_and(|g| g.contains(&t.as_str()))
            })
        })
        .collect();
    for t in tables {
        if counts.remove(&t).is_some() {
            notes.push(format!("default {t} left out: no seat at it is left"));
        }
    }
}
