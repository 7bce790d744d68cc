//! The place a scene is in, said after a locative ("a picnic spot in a park", "a tent at the
//! edge of a forest", "a café on a rooftop"): a place word there (`kb/words.txt`: outdoors and
//! indoors, or a one-word scene name or synonym of the knowledge base) names where the scene is,
//! never an object of it. Its words are read (the reader uses them) and masked, so that the place
//! becomes no unknown box. A word that is also an object's name ("a lamp in a tent") stays the
//! object, unless it is a landscape a room cannot hold (`outdoors` words: "a bedroom by the sea",
//! "a kitchen overlooking the lake", "a study with a view of the river"): there it is where the
//! room is.
use super::objects::inside;
use super::{is_adjective, is_function_word, word_list, words_in, Reading};
use crate::plan::kb::KnowledgeBase;

/// Prepositions that put the scene inside or at a place.
const LOCATIVES: &[&str] = &[
    "in",
    "at",
    "inside",
    "within",
    "on",
    "outside",
    "by",
    "near",
    "overlooking",
];

/// Nouns after which "of" says what the room looks out on ("a view of the sea").
const VIEWS: &[&str] = &["view", "views"];
const DETERMINERS: &[&str] = &["a", "an", "the", "some", "my", "our", "your", "their"];

/// Whether `w` names a place rather than a thing.
pub(super) fn names_place(kb: &KnowledgeBase, w: &str) -> bool {
    if kb.object(w).is_some() || kb.names().any(|(n, _)| n == w) {
        return false;
    }
    is_place_word(kb, w)
}

/// Whether `w` is a place word of `kb/words.txt` or a one-word scene name, an object's name or not.
fn is_place_word(kb: &KnowledgeBase, w: &str) -> bool {
    word_list("outdoors").contains(&w)
        || word_list("indoors").contains(&w)
        || kb
            .scenes
            .iter()
            .any(|s| s.name == w || s.synonyms.iter().any(|x| x == w))
}

/// Spans "in a park", "at the beach" of `t` outside `masked`: the locative, its determiner, the
/// words describing the place and the place word.
pub(super) fn read_settings(
    kb: &KnowledgeBase,
    t: &str,
    r: &mut Reading,
    masked: &mut Vec<(usize, usize)>,
) {
    let all = words_in(t, 0, t.len());
    // a room cannot hold a landscape: there an outdoor word that is also an object (the sea, a
    // lake) said after a locative is where the room is
    let indoor = r
        .scene
        .is_some_and(|(i, _, _)| kb.scenes[i].scene_type == crate::plan::spec::SceneType::Indoor);
    let landscape = |w: &str| indoor && word_list("outdoors").contains(&w);
    // "a bathroom with a sea view"
    for k in 0..all.len().saturating_sub(1) {
        let ((start, w), (pos, next)) = (all[k], all[k + 1]);
        if landscape(w) && VIEWS.contains(&next) && !inside(start, masked) {
            let span = (start, pos + next.len());
            r.settings.push(span);
            masked.push(span);
        }
    }
    for k in 0..all.len().saturating_sub(2) {
        let (start, w) = all[k];
        let view = w == "of" && k > 0 && VIEWS.contains(&all[k - 1].1);
        if !(LOCATIVES.contains(&w) || view) || !DETERMINERS.contains(&all[k + 1].1) {
            continue;
        }
        // describing words ("a quiet city park") up to the head
        let mut j = k + 2;
        while j + 1 < all.len()
            && is_adjective(all[j + 1].1)
            && !is_function_word(all[j + 1].1)
            && !inside(all[j + 1].0, masked)
            && j < k + 5
        {
            j += 1;
        }
        // the head is the last describing word before a function word or the end
        let (pos, head) = all[j];
        let ends = all
            .get(j + 1)
            .is_none_or(|x| is_function_word(x.1) || !is_adjective(x.1));
        // a place of two words ("at an airport gate"): its head alone may name a thing
        let two = (j > k + 2).then(|| format!("{} {}", all[j - 1].1, head));
        let place = names_place(kb, head)
            || two.is_some_and(|p| names_place(kb, &p))
            || (landscape(head) && is_place_word(kb, head));
        if ends && !inside(pos, masked) && place {
            let span = (start, pos + head.len());
            r.settings.push(span);
            masked.push(span);
        }
    }
}
