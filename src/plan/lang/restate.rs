//! A later count of the same thing that restates the earlier one ("four chairs. Actually make it
//! six chairs", "change that to six chairs"): the request wants that many, not both added up.
//! The words that say so are `kb/words.txt`, restaters (`_` between the words of one).
use super::{number_of, word_list, words_in, Reading};

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
    bare_restated_counts(r);
}

/// "B: Table for eight? A: Yes, table for eight under the chandelier": a thing named in a question
/// and named again in the sentence after it (its answer) is one thing, the answer's, which takes
/// the question's count and seats where it says none; "B: A rug? A: No rug." / "A: No." wants
/// none.
pub(super) fn answered_questions(r: &mut Reading) {
    let t = r.text.clone();
    let ends = |from: usize| t[from..].find(['.', '!', '?']).map(|k| from + k);
    for i in 0..r.mentions.len() {
        let m = &r.mentions[i];
        if m.negated || m.reference {
            continue;
        }
        let Some(q) = ends(m.end).filter(|&q| t[q..].starts_with('?')) else {
            continue;
        };
        let next_end = ends(q + 1).unwrap_or(t.len());
        // the answer without its speaker's label ("a: no.")
        let answer = t[q + 1..next_end].trim();
        let answer = answer
            .split_once(':')
            .filter(|(who, _)| who.split_whitespace().count() == 1)
            .map_or(answer, |(_, a)| a.trim());
        let said_again = (i + 1..r.mentions.len()).find(|&j| {
            let o = &r.mentions[j];
            o.start > q && o.end <= next_end && o.category == m.category && !o.reference
        });
        let Some(j) = said_again else {
            let no = answer.split([',', ' ', '!']).next() == Some("no")
                && !r.mentions.iter().any(|o| o.start > q && o.end <= next_end);
            if no {
                r.mentions[i].negated = true;
            }
            continue;
        };
        if r.mentions[j].negated {
            r.mentions[i].negated = true;
            continue;
        }
        if r.mentions[j].count.is_none() {
            r.mentions[j].count = r.mentions[i].count;
        }
        if let Some(&(_, n)) = r.seats_for.iter().find(|s| s.0 == i) {
            if !r.seats_for.iter().any(|s| s.0 == j) {
                r.seats_for.push((j, n));
            }
        }
        r.seats_for.retain(|s| s.0 != i);
        let m = &mut r.mentions[i];
        m.count = None;
        m.reference = true;
    }
}

/// "four chairs. Actually make it six.": a restater whose number ends its clause, with no noun
/// after it, gives that number to the last counted thing named before it.
fn bare_restated_counts(r: &mut Reading) {
    let t = r.text.clone();
    let all = words_in(&t, 0, t.len());
    for (k, &(pos, w)) in all.iter().enumerate() {
        let Some(n) = number_of(w).filter(|&n| n > 1) else {
            continue;
        };
        let end = pos + w.len();
        // the number ends its clause: punctuation right after it, or the end of the text
        let closes = t[end..].is_empty() || t[end..].starts_with([',', '.', ';', '!', '?']);
        let from = all[k.saturating_sub(4)..k].first().map_or(pos, |x| x.0);
        if !closes
            || r.mentions.iter().any(|m| m.start <= pos && pos < m.end)
            || !restates(&t, from, pos)
        {
            continue;
        }
        if let Some(m) = r.mentions.iter_mut().rev().find(|m| {
            m.end <= pos && m.count.is_some() && !m.negated && !m.reference && m.each_of.is_none()
        }) {
            m.count = Some(n);
        }
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

    #[test]
    fn a_bare_restated_number_counts_the_last_counted_thing() {
        let kb = crate::plan::kb::KnowledgeBase::builtin();
        let r = super::super::read(
            kb,
            "a dining room with a table and four chairs. actually make it six.",
        );
        let chairs = r.mentions.iter().find(|m| m.text == "chairs").unwrap();
        assert_eq!(chairs.count, Some(6));
        let r = super::super::read(kb, "a dining room with a table for six and four chairs");
        let chairs = r.mentions.iter().find(|m| m.text == "chairs").unwrap();
        assert_eq!(chairs.count, Some(4));
    }
}
