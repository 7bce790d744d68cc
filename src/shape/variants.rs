//! The variant table (`kb/variants.txt`): how many variants an archetype is drawn in (a
//! poster's print, a painting's subject, a statue's pose), so that several of one category in
//! a scene need not look the same. An archetype the table does not list has one.
use std::sync::OnceLock;

type Table = super::rows::RowTable<u32>;

fn table() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| super::rows::read(include_str!("kb/variants.txt"), parse))
}

fn parse(f: &str) -> Result<u32, String> {
    match f.trim().parse::<u32>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!("`{}` is not a count of variants", f.trim())),
    }
}

/// How many variants `archetype` is drawn in (1 when it has none).
pub fn count(archetype: &str) -> u32 {
    table()
        .rows
        .iter()
        .find(|(a, _)| a == archetype)
        .map_or(1, |(_, n)| *n)
}

/// The table's rows (archetype, count) and its lines that did not read (for the tests).
pub fn rows() -> (Vec<(String, u32)>, Vec<String>) {
    let t = table();
    (t.rows.clone(), t.bad.clone())
}
