//! A later count of the same thing that restates the earlier one ("four chairs. Actually make it
//! six chairs", "change that to six chairs"): the request wants that many, not both added up.
//! The words that say so are `kb/words.txt`, restaters (`_` between the words of one).
use super::{word_list, Reading};

/// Whether the clause right before `at` (since the last full stop, semicolon or the mention
/// before, whichever is later) restates a count: it holds one of the restaters.
fn restates(t: &str, from: usize, at: usize) -> bool {
    let clause = &t[from..at];
    let clause = clause
        .rfind(['.', ';', '!', '?'])
        .map_or(clause, |k| &clause[k + 1..]);
    let words: Vec<&str> = clause
        .split(|c: char| !c.is_alphanumeric() && c != '\'')
        .filter(|w| !w.is_empty())
        .collect();
    word_list("restaters").iter().any(|r| {
        let phrase: Vec<&str> = r.split('_').collect();
        words.windows(phrase.len()).any(|w| w == phrase.as_slice())
    })
}

/// Gives each counted mention that restates an earlier counted one of its category its count to
/// the earlier one, and makes the later a reference to it (no new things).
pub(super) fn restated_counts(r: &mut Reading) {
    for i in 1..r.mentions.len() {
        let m = &r.mentions[i];
        let Some(n) = m
            .count
            .filter(|_| !m.negated && !m.reference && m.each_of.is_none())
        else {
            continue;
        };
        let from = r.mentions[i - 1].end;
        if !restates(&r.text, from, m.start) {
            continue;
        }
        let cat = m.category.clone();
        let Some(j) = (0..i).rev().find(|&j| {
            let o = &r.mentions[j];
            o.category == cat && !o.negated && !o.reference && o.each_of.is_none()
        }) else {
            continue;
        };
        r.mentions[j].count = Some(n);
        let m = &mut r.mentions[i];
        m.count = None;
        m.reference = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_restater_in_the_clause_before_restates() {
        let t = "a table and four chairs. actually make it six chairs";
        let at = t.rfind("six").unwrap();
        assert!(restates(t, t.find("four chairs").unwrap() + 11, at));
        let t = "four chairs by the desk and two chairs by the window";
        assert!(!restates(t, 11, t.find("two").unwrap()));
    }
}
