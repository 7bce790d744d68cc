//! A shape table of rows `name | features`: comments (`#`) and blank lines skipped, each line
//! parsed by the table's own parser, the lines that do not parse kept with why (for the tests);
//! rows found by name, the row `default` standing for what the table does not list.
use std::sync::OnceLock;

/// A table's parsed rows, in order, and its lines that did not parse.
pub(crate) struct RowTable<T> {
    pub rows: Vec<(String, T)>,
    pub bad: Vec<String>,
}

/// Reads `text` line by line with `parse` for the part after the `|`.
pub(crate) fn read<T>(text: &str, parse: fn(&str) -> Result<T, String>) -> RowTable<T> {
    let mut t = RowTable {
        rows: vec![],
        bad: vec![],
    };
    for line in text.lines().map(str::trim) {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        match line.split_once('|').map(|(n, f)| (n.trim(), parse(f))) {
            Some((name, Ok(a))) => t.rows.push((name.to_string(), a)),
            Some((_, Err(e))) => t.bad.push(format!("{line}: {e}")),
            None => t.bad.push(format!("{line}: no `|`")),
        }
    }
    t
}

impl<T> RowTable<T> {
    /// The row called `name`.
    pub fn row(&self, name: &str) -> Option<&T> {
        self.rows.iter().find(|(n, _)| n == name).map(|(_, a)| a)
    }

    /// Every row with its name (the `default` row among them).
    pub fn listed(&self) -> Vec<(&str, &T)> {
        self.rows.iter().map(|(n, a)| (n.as_str(), a)).collect()
    }
}

/// The row `default` of `table`, else `T::default()` (kept in `fallback`).
pub(crate) fn default_row<T: Default>(
    table: &'static RowTable<T>,
    fallback: &'static OnceLock<T>,
) -> &'static T {
    table
        .row("default")
        .unwrap_or_else(|| fallback.get_or_init(T::default))
}
