//! Which words of a scene text are said not to be there: "a rug instead of a carpet", "no
//! carpet", "without tiles", "wood rather than carpet", "not carpeted". A surface word said so
//! sets nothing (the floor of "a kids room with a rug instead of a carpet" is no carpet). Pure
//! text over the lower-case words of `plan::finish::words`.

/// Words that may stand between a negating word and what it negates ("no wall-to-wall carpet",
/// "instead of the carpet").
const BETWEEN: &[&str] = &["a", "an", "the", "any", "some", "its", "their"];

/// Whether word `i` of `w` is negated: "no", "not", "without", "instead of", "rather than" or
/// "except" before it, with only articles and words `describing` the same surface (colours,
/// materials: "no dark wall-to-wall carpet") between.
pub(super) fn negated(w: &[String], i: usize, describing: impl Fn(&str) -> bool) -> bool {
    let mut j = i;
    while j > 0 {
        j -= 1;
        let s = w[j].as_str();
        let prev = j.checked_sub(1).map(|k| w[k].as_str());
        match s {
            "no" | "not" | "without" | "except" | "never" => return true,
            "of" => return prev == Some("instead"),
            "than" => return prev == Some("rather"),
            _ if BETWEEN.contains(&s) || describing(s) => continue,
            _ => return false,
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::negated;

    fn at(text: &str, word: &str) -> bool {
        let w: Vec<String> = text.split(' ').map(str::to_string).collect();
        let i = w.iter().position(|x| x == word).expect("word in text");
        negated(&w, i, |s| ["wall-to-wall", "dark", "thick"].contains(&s))
    }

    #[test]
    fn instead_of_rather_than_no_and_without_negate_the_word_after_them() {
        assert!(at("a kids room with a rug instead of a carpet", "carpet"));
        assert!(at("a bedroom with no carpet", "carpet"));
        assert!(at("a study without any wall-to-wall carpet", "carpet"));
        assert!(at("a hall with wood rather than tiles", "tiles"));
        assert!(at("a nursery that is not carpeted", "carpeted"));
    }

    #[test]
    fn a_word_said_plainly_or_after_another_clause_is_not_negated() {
        assert!(!at("a bedroom with a thick carpet", "carpet"));
        assert!(!at("a kids room with a rug instead of a carpet", "rug"));
        assert!(!at("a hall with no chairs and a marble floor", "marble"));
        assert!(!at("a kitchen with tiles", "tiles"));
        assert!(!at("a room with no chairs tiled floor", "tiled"));
    }
}
