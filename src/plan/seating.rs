//! How big a table laid for a number of people is (`kb/seating.txt`): "a table for two" is a
//! small square one, "a table for eight" a long one, each table of a plan sized by the seats
//! said for it. Pure host code.
use std::sync::OnceLock;

/// One line of kb/seating.txt.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Laid {
    seats: u32,
    /// Width and depth of a long (or square) table.
    long: [f64; 2],
    /// Diameter of a round table.
    round: f64,
}

fn table() -> &'static [Laid] {
    static TABLE: OnceLock<Vec<Laid>> = OnceLock::new();
    TABLE.get_or_init(|| parse(include_str!("kb/seating.txt")).unwrap_or_default())
}

/// Reads a seating table: `seats | width depth | diameter` a line, seats rising; the error names
/// the line and what is wrong.
fn parse(text: &str) -> Result<Vec<Laid>, String> {
    let mut out: Vec<Laid> = vec![];
    for (ln, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let err = |m: &str| format!("seating.txt line {}: {m}", ln + 1);
        let f: Vec<&str> = line.split('|').map(str::trim).collect();
        let [seats, long, round] = f[..] else {
            return Err(err("expected `seats | width depth | diameter`"));
        };
        let metres = |s: &str| -> Result<Vec<f64>, String> {
            s.split_whitespace()
                .map(|v| match v.parse::<f64>() {
                    Ok(x) if x > 0.0 && x < 10.0 => Ok(x),
                    _ => Err(err(&format!("`{v}` is no size in metres"))),
                })
                .collect()
        };
        let seats: u32 = seats
            .parse()
            .map_err(|_| err(&format!("`{seats}` is no number of seats")))?;
        let (long, round) = (metres(long)?, metres(round)?);
        let (&[w, d], &[r]) = (long.as_slice(), round.as_slice()) else {
            return Err(err(
                "a long table has a width and a depth, a round one a diameter",
            ));
        };
        if out.last().is_some_and(|l| l.seats >= seats) {
            return Err(err("seats must rise from line to line"));
        }
        out.push(Laid {
            seats,
            long: [w, d],
            round: r,
        });
    }
    Ok(out)
}

/// The footprint `[width, depth]` of a table laid for `seats` people (`round`: a round one), or
/// `None` past the table's last line.
pub fn table_for(seats: u32, round: bool) -> Option<[f64; 2]> {
    let l = table().iter().find(|l| l.seats >= seats)?;
    Some(if round { [l.round; 2] } else { l.long })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_built_in_table_reads_and_grows_with_the_seats() {
        let t = parse(include_str!("kb/seating.txt")).unwrap();
        assert!(t.len() >= 4, "a line for two, four, six and eight");
        for w in t.windows(2) {
            let area = |l: &Laid| l.long[0] * l.long[1];
            assert!(
                area(&w[1]) > area(&w[0]) && w[1].round > w[0].round,
                "{w:?}"
            );
        }
        assert_eq!(table_for(2, false), Some([0.8, 0.8]));
        assert_eq!(table_for(5, false), table_for(6, false));
        assert!(table_for(2, true).unwrap()[0] < table_for(8, true).unwrap()[0]);
        assert_eq!(table_for(1000, false), None);
    }

    #[test]
    fn a_broken_seating_table_is_one_clear_line() {
        let e = parse("# x\n2 | 0.8 0.8 | 0.7\n4 | 1.2 | 1.0\n").unwrap_err();
        assert!(
            e.contains("line 3") && e.contains("width and a depth"),
            "{e}"
        );
        let e = parse("4 | 1.2 0.9 | 1.0\n2 | 0.8 0.8 | 0.7\n").unwrap_err();
        assert!(e.contains("line 2") && e.contains("rise"), "{e}");
        let e = parse("two | 0.8 0.8 | 0.7\n").unwrap_err();
        assert!(e.contains("`two`"), "{e}");
    }
}
