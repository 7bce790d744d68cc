//! Seats said to be for someone: "two armchairs for visitors", "a sofa for waiting customers".
//! A named seat for those a default seat of the scene is named for (the office's visitor
//! chairs, the salon's waiting chairs) takes that default's place instead of adding to it.
//! It never removes what the text names, nor a default that is no seat.
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
