//! Things named only as what others face or stand at, when a planned thing has one as a part:
//! "barber chairs facing mirrors" in a hair salon face its stations' lit mirrors, one chair at
//! each station, and no wall mirrors are added (`kb/roles.txt`: has).
use super::Draft;

/// Folds each such category into the planned category that has it as a part: its mentions
/// mean that category, and a relation to it becomes the seat's place at it where the seat has
/// one (a barber chair at its station).
pub(super) fn named_parts(d: &mut Draft) {
    let named: Vec<String> = d.named.iter().cloned().collect();
    for part in named {
        if d.explicit.contains_key(&part) || !d.counts.contains_key(&part) {
            continue;
        }
        let ms: Vec<usize> = (0..d.r.mentions.len())
            .filter(|&i| d.cats[i] == part && !d.r.mentions[i].negated)
            .collect();
        // named only as the object of relations, never as a thing of its own
        let only_object = !ms.is_empty()
            && ms.iter().all(|i| {
                d.r.relations.iter().any(|&(_, _, o)| o == *i)
                    && !d.r.relations.iter().any(|&(s, _, _)| s == *i)
            });
        if !only_object {
            continue;
        }
        let Some(whole) = d
            .counts
            .keys()
            .find(|c| **c != part && crate::plan::roles::has_part(c, &part))
            .cloned()
        else {
            continue;
        };
        d.counts.remove(&part);
        d.named.remove(&part);
        for &i in &ms {
            d.cats[i] = whole.clone();
        }
        for (s, rel, o) in d.r.relations.iter_mut() {
            if ms.contains(o) {
                if let Some(g) = crate::plan::groups::relation_between(&d.cats[*s], &whole) {
                    *rel = g;
                }
            }
        }
    }
}
