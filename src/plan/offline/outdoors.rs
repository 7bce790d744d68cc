//! Whether a request that names no known place is outdoors: by its place words (`kb/words.txt`,
//! outdoors: "a garden", "an allotment", "a rooftop"; indoors: "a grotto", "a cellar"), else by
//! what it names. A thing that the
//! knowledge base's outdoor places hold and no indoor place does (a shed, a tree, a swing set)
//! votes outdoors; one only indoor places hold (a sofa, a bed) votes indoors.
use super::super::kb::KnowledgeBase;
use super::super::lang::{self, Reading};
use super::super::spec::SceneType;

/// The scene type of a reading without a matched place (or whose place is only lent).
pub(super) fn unnamed_place_type(kb: &KnowledgeBase, r: &Reading) -> SceneType {
    // "open air" is one place word
    let text = r.text.replace("open air", "open-air");
    let words: Vec<&str> = text
        .split(|c: char| !(c.is_alphanumeric() || c == '-' || c == '\''))
        .filter(|w| !w.is_empty())
        .collect();
    // "a painting of a lake": a place a thing shows or looks out on is not where it stands;
    // "a mountain of cushions" is a heap
    let of = |k: usize| {
        let back: Vec<&str> = words[..k].iter().rev().take(2).copied().collect();
        back.first() == Some(&"of")
            || (back.get(1) == Some(&"of") && ["a", "an", "the"].contains(&back[0]))
            || words.get(k + 1) == Some(&"of")
    };
    if (0..words.len()).any(|k| lang::is_outdoor_place(words[k]) && !of(k)) {
        return SceneType::Outdoor;
    }
    // "a grotto with a waterfall": a place inside rock or a hull holds outdoor things indoors
    if words.iter().any(|w| lang::is_indoor_place(w)) {
        return SceneType::Indoor;
    }
    let mut vote = 0i32;
    for m in r.mentions.iter().filter(|m| m.known && !m.negated) {
        vote += home(kb, &m.category);
    }
    if vote > 0 {
        SceneType::Outdoor
    } else {
        SceneType::Indoor
    }
}

/// "an outdoor wedding ceremony", "a yoga class outdoors": an open-air word (`kb/words.txt`:
/// open_air) said of the place (in the phrase that names it, or right after its name) puts a
/// place that is a room by default out of doors; one said of a thing ("a kitchen with an
/// outdoor table") does not.
pub(super) fn said_open_air(r: &Reading) -> bool {
    let Some((_, s, e)) = r.scene else {
        return false;
    };
    let text = r.text.replace("open air", "open-air");
    let mut pos = 0;
    text.split(' ').any(|w| {
        let start = pos;
        pos += w.len() + 1;
        let w = w.trim_matches(|c: char| !(c.is_alphanumeric() || c == '-'));
        let of_place = (start < s && !text[start..s].contains([',', ':', ';'])) || start == e + 1;
        lang::is_open_air(w) && of_place
    })
}

/// "a wedding ceremony in a garden", "a yoga class on the beach": a place that is a room by
/// default, said right after its name to be in an outdoor place one stands in (`kb/words.txt`,
/// grounds, the head of the phrase: "in a garden shed" is in a shed), is out of doors.
pub(super) fn set_outdoors(r: &Reading) -> bool {
    let Some((_, s, e)) = r.scene else {
        return false;
    };
    // "a cabin in the forest": a building stays indoors wherever it stands
    let head = r.text[s..e].split_whitespace().last().unwrap_or("");
    if lang::is_building(head) {
        return false;
    }
    let after = regex::Regex::new(
        r"^\s*(?:in|at|on) (?:the |a |an )?(?:[a-z'-]+ )?([a-z'-]+)(?:\s*$|\s*[,.;:!?]|\s+(?:with|and|where|for|under|surrounded|full|at|on|by)\b)",
    )
    .expect("a valid pattern");
    r.text
        .get(e..)
        .is_some_and(|rest| after.captures(rest).is_some_and(|c| lang::is_ground(&c[1])))
}

/// +1 when only outdoor places of the knowledge base hold `category` by default, -1 when only
/// indoor ones do, 0 when both or neither.
fn home(kb: &KnowledgeBase, category: &str) -> i32 {
    let held = |t: SceneType| {
        kb.scenes
            .iter()
            .filter(|s| s.scene_type == t)
            .any(|s| s.objects.iter().any(|(c, _)| c == category))
    };
    match (held(SceneType::Outdoor), held(SceneType::Indoor)) {
        (true, false) => 1,
        (false, true) => -1,
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kind(text: &str) -> SceneType {
        let kb = KnowledgeBase::builtin();
        unnamed_place_type(kb, &lang::read(kb, text))
    }

    #[test]
    fn place_words_and_outdoor_things_make_a_scene_outdoors() {
        // place words of the list
        assert_eq!(
            kind("an orchard with five trees"),
            SceneType::Outdoor,
            "orchard"
        );
        assert_eq!(
            kind("a rooftop with two chairs"),
            SceneType::Outdoor,
            "rooftop"
        );
        // no place word: what it names
        assert_eq!(
            kind("a shed, two raised beds and a wheelbarrow"),
            SceneType::Outdoor,
            "garden things"
        );
        assert_eq!(
            kind("a sofa, a rug and a tv"),
            SceneType::Indoor,
            "living things"
        );
        assert_eq!(
            kind("a cave with a tree and a rock"),
            SceneType::Indoor,
            "a cave"
        );
        assert_eq!(kind("two chairs and a table"), SceneType::Indoor, "no vote");
    }
}
