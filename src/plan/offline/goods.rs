//! A shop named for what it sells ("an aquarium shop", "a piano store"): a generic shop's
//! display furniture (`kb/roles.txt`: shelving) gives way to the goods themselves, set out on
//! the floor and along the walls. Goods that stand on shelves or tables (lamps, vases) leave the
//! shop as it is. Only a scene whose matched name ends in a shop word is read this way; a
//! place with its own name ("a bike shop") is its own scene.
use super::Draft;
use crate::plan::gcp::classes::{Class, Placements};
use crate::plan::lang;

/// Words that name a place by what it sells when a thing's name comes before them.
const SHOP_WORDS: [&str; 3] = ["shop", "store", "showroom"];

/// Replaces the shop's display shelves with the goods its name says it sells.
pub(super) fn goods_on_show(d: &mut Draft) {
    let Some((_, start, end)) = d.r.scene else {
        return;
    };
    let said = &d.r.text[start..end];
    if !SHOP_WORDS.contains(&said.rsplit(' ').next().unwrap_or("")) {
        return;
    }
    let before: Vec<&str> = d.r.text[..start].split_whitespace().collect();
    // "a fish tank shop", "an aquarium shop": the longest thing's name right before
    let goods = (1..=2.min(before.len()))
        .rev()
        .filter_map(|k| {
            let name = before[before.len() - k..].join(" ");
            d.kb.object(&name)
                .or_else(|| d.kb.object(&lang::singular(&name)))
        })
        .next();
    let Some(goods) = goods else {
        return;
    };
    let table = Placements::builtin();
    if !matches!(
        table.class(&goods.category),
        Class::Floor | Class::AgainstWall
    ) {
        return;
    }
    let display: Vec<(String, u32)> = d
        .counts
        .iter()
        .filter(|(c, _)| crate::plan::roles::role_of(c) == Some("shelving"))
        .map(|(c, n)| (c.clone(), *n))
        .collect();
    if display.is_empty() {
        return;
    }
    let mut n = 0;
    for (c, k) in display {
        d.counts.remove(&c);
        d.defaults.remove(&c);
        n += k;
        d.notes.push(format!(
            "default {c} left out: the shop shows its {} instead",
            goods.category
        ));
    }
    let n = n.max(2);
    d.counts.entry(goods.category.clone()).or_insert(n);
    d.defaults.entry(goods.category.clone()).or_insert(n);
}
