//! A dialogue file (a JSON list of `{"role", "content"}`) to the text the planner reads: the
//! user turns (role matched case-insensitively: "user", "User", "USER", "human") joined as
//! sentences, each keeping its own closing punctuation and none doubled.
use serde::Deserialize;

/// One turn of a dialogue.
#[derive(Debug, Clone, Deserialize)]
pub struct Turn {
    pub role: String,
    pub content: String,
}

/// Whether `role` names the user.
pub fn is_user(role: &str) -> bool {
    let r = role.trim();
    r.eq_ignore_ascii_case("user") || r.eq_ignore_ascii_case("human")
}

/// The user turns joined: "I want a bedroom." + "Scandinavian, please" gives
/// "I want a bedroom. Scandinavian, please". `None` when there is no non-empty user turn.
pub fn user_text(turns: &[Turn]) -> Option<String> {
    let mut out = String::new();
    for t in turns.iter().filter(|t| is_user(&t.role)) {
        let c = t.content.trim();
        // Trailing separators of a turn are replaced by one full stop between turns.
        let c = c
            .trim_end_matches([',', ';', ':', '-', '–', '—'])
            .trim_end();
        if c.is_empty() {
            continue;
        }
        if !out.is_empty() {
            if !out.ends_with(['.', '!', '?']) {
                out.push('.');
            }
            out.push(' ');
        }
        out.push_str(c);
    }
    (!out.is_empty()).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn turn(role: &str, content: &str) -> Turn {
        Turn {
            role: role.into(),
            content: content.into(),
        }
    }

    #[test]
    fn turns_join_as_sentences_without_doubled_punctuation() {
        let t = [
            turn("user", "I want a bedroom."),
            turn("assistant", "Which style?"),
            turn("USER", "Scandinavian,"),
            turn("User", "  with a desk!  "),
            turn("Human", "and a rug"),
        ];
        assert_eq!(
            user_text(&t).unwrap(),
            "I want a bedroom. Scandinavian. with a desk! and a rug"
        );
        assert_eq!(user_text(&[turn("assistant", "hi")]), None);
        assert_eq!(user_text(&[turn("user", "  ")]), None);
    }
}
