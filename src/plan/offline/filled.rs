//! What a thing is said to be full of chooses its kind: "an old dresser full of plates" is a
//! kitchen dresser (shelves of plates over a cupboard), not a bedroom's chest of drawers; "a
//! fridge full of drinks" is a drinks fridge. A mention that names only the head noun
//! ("dresser") becomes the compound of that head (`kitchen dresser`) whose name, synonyms or
//! description say what it holds and that is placed as the named kind is; one that names its
//! kind outright keeps it.
use super::Draft;
use crate::plan::lang::singular;

/// Re-reads the category of each mention said to be full of something.
pub(super) fn by_contents(d: &mut Draft) {
    for (i, what, ..) in d.r.contents.clone() {
        let (Some(m), Some(cat)) = (d.r.mentions.get(i), d.cats.get(i)) else {
            continue;
        };
        // only a noun said alone ("a dresser"), not a kind the text names ("a chest of drawers")
        let head = cat.rsplit(' ').next().unwrap_or(cat).to_string();
        if m.text.contains(' ') || m.negated {
            continue;
        }
        let Some(held) = what.rsplit(' ').next().map(singular) else {
            continue;
        };
        let says = |text: &str| {
            text.split(|c: char| !c.is_alphanumeric())
                .any(|w| !w.is_empty() && singular(&w.to_lowercase()) == held)
        };
        // a kind placed as the named one is (a wall shelf of jars stays on the wall: a pantry
        // shelf stands on the floor)
        let placements = crate::plan::gcp::classes::Placements::builtin();
        let placed = |c: &str| std::mem::discriminant(&placements.class(c));
        let other = d.kb.objects.iter().find(|o| {
            o.category != *cat
                && o.category.ends_with(&format!(" {head}"))
                && placed(&o.category) == placed(cat)
                && (says(&o.category) || says(&o.description) || o.synonyms.iter().any(|n| says(n)))
        });
        if let Some(o) = other {
            d.cats[i] = o.category.clone();
        }
    }
}
