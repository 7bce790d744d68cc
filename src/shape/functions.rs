//! Function classes: what each knowledge-base category is for and which classes each archetype
//! can show, read from `kb/category_functions.txt` and `kb/archetype_functions.txt`. The shape
//! prior draws a category with an archetype of its own function; `tests/shape.rs` checks it.
use std::collections::BTreeMap;

const CATEGORY_FUNCTIONS: &str = include_str!("kb/category_functions.txt");
const ARCHETYPE_FUNCTIONS: &str = include_str!("kb/archetype_functions.txt");

/// The rows `key | value` of a table, comments and blank lines skipped.
fn rows(text: &'static str) -> impl Iterator<Item = (&'static str, &'static str)> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter_map(|l| l.split_once('|'))
        .map(|(k, v)| (k.trim(), v.trim()))
}

/// Category → function class.
pub fn category_functions() -> BTreeMap<&'static str, &'static str> {
    rows(CATEGORY_FUNCTIONS).collect()
}

/// Archetype → the function classes it can show.
pub fn archetype_functions() -> BTreeMap<&'static str, Vec<&'static str>> {
    rows(ARCHETYPE_FUNCTIONS)
        .map(|(a, f)| (a, f.split(',').map(str::trim).collect()))
        .collect()
}

/// The function class of `category` (lower-case name as the knowledge base spells it).
pub fn function_of(category: &str) -> Option<&'static str> {
    rows(CATEGORY_FUNCTIONS)
        .find(|(c, _)| *c == category)
        .map(|(_, f)| f)
}
