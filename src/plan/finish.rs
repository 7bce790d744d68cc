//! The finish a kind of place gives its furniture (`kb/finishes.txt`): a clinical place (an
//! operating room, a dental clinic, a ward) is furnished in white steel that is wiped clean,
//! so the wooden cabinets and stools the knowledge base describes for a home are described as
//! white steel there. Which place a text names is read from the scene kind's name and the
//! words naming the place, never from what the place holds. Pure text; no drawing.

const FINISHES: &str = include_str!("kb/finishes.txt");

/// One row of `kb/finishes.txt`.
#[derive(Debug, Clone, PartialEq)]
pub struct Finish {
    /// The kind of place ("clinical").
    pub place: &'static str,
    /// Words that name such a place.
    pub words: Vec<&'static str>,
    /// Material words of a knowledge-base description the finish replaces.
    pub replaces: Vec<&'static str>,
    /// The finish's words ("white steel").
    pub finish: &'static str,
}

/// Every row of `kb/finishes.txt`.
pub fn finishes() -> Vec<Finish> {
    FINISHES
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter_map(|l| {
            let f: Vec<&str> = l.split('|').map(str::trim).collect();
            let list = |s: &'static str| s.split(',').map(str::trim).collect::<Vec<_>>();
            (f.len() == 4).then(|| Finish {
                place: f[0],
                words: list(f[1]),
                replaces: list(f[2]),
                finish: f[3],
            })
        })
        .collect()
}

/// Lower-case words of `text`; a possessive names its noun ("a vet's surgery", "a pirate
/// ship's deck").
pub(crate) fn words(text: &str) -> Vec<String> {
    text.to_lowercase()
        .split(|c: char| !(c.is_alphanumeric() || c == '-' || c == '\''))
        .map(|w| w.strip_suffix("'s").unwrap_or(w).trim_matches('\''))
        .filter(|w| !w.is_empty())
        .map(str::to_string)
        .collect()
}

/// The words naming the place: those before the first clause or "with"/"and" ("a dental clinic
/// with a chair" names a dental clinic; "a garage with a medical cart" a garage).
fn place_words(text: &str) -> Vec<String> {
    let head = text.split([',', ';', '.', ':']).next().unwrap_or("");
    words(head)
        .into_iter()
        .take_while(|w| !matches!(w.as_str(), "with" | "and" | "where" | "that" | "which"))
        .collect()
}

/// The finish of the place `text` names, whose scene kind is `kind` (if any).
pub fn place_finish(kind: Option<&str>, text: &str) -> Option<Finish> {
    let named: Vec<String> = kind
        .map(words)
        .unwrap_or_default()
        .into_iter()
        .chain(place_words(text))
        .collect();
    finishes()
        .into_iter()
        .find(|f| named.iter().any(|w| f.words.contains(&w.as_str())))
}

/// Whether the place `text` names (scene kind `kind`) is clinical.
pub fn clinical(kind: Option<&str>, text: &str) -> bool {
    place_finish(kind, text).is_some_and(|f| f.place == "clinical")
}

/// `description` with its material words replaced by `finish` (once, where the first stood);
/// unchanged when it names none of them.
pub fn refinish(description: &str, finish: &Finish) -> String {
    let mut out: Vec<&str> = vec![];
    let mut done = false;
    for w in description.split_whitespace() {
        if finish.replaces.contains(&w.to_lowercase().as_str()) {
            if !done {
                out.push(finish.finish);
                done = true;
            }
        } else {
            out.push(w);
        }
    }
    out.join(" ")
}
