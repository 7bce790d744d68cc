//! Things that line the walls ("bookcases along every wall", "shelves along the walls", "a
//! corridor lined with lockers on both sides", "benches down both sides"): a plural the text
//! does not count is as many as the walls it names take, which only the room can say (the
//! planner counts them once it is sized). Read here: which mention lines how many walls.
use super::placements::SIDE_PHRASE;
use super::{re, Mention, Reading};
use crate::plan::spec::Anchor;

/// Most words between a thing and the wall phrase said of it ("bookcases crammed with books
/// along every wall").
const NEAR: usize = 5;

/// How many walls a phrase names: one ("along the back wall", "lining one wall"), two ("down
/// both sides", "along two walls", "on opposite walls") or every wall (0: "along the walls",
/// "along every wall", "lining the walls"). None where it names no run of walls: "on both
/// sides" alone is said of the thing named before (nightstands either side of a bed), and a
/// thing "wall-mounted" or "on the wall" is one thing on a wall.
fn walls_named(phrase: &str, lined: bool) -> Option<u32> {
    let words: Vec<&str> = phrase.split(|c: char| !c.is_alphanumeric()).collect();
    let has = |w: &str| words.contains(&w);
    let sides = has("side") || has("sides");
    // "paintings on the walls", "chairs by the wall": a few on them, not a run along them
    // (but a corridor "lined with lockers on both sides" has them down both)
    let on = (has("on") || has("by")) && !(lined && sides);
    if has("mounted") || has("hull") || on {
        return None;
    }
    if sides && !(lined || has("down") || has("lining")) {
        return None;
    }
    let two = ["both", "two", "opposite", "either"].iter().any(|w| has(w))
        || (sides && (has("each") || has("sides")));
    if two {
        return Some(2);
    }
    if sides {
        return Some(1);
    }
    // the edge of an open ground (a terrace's, a plaza's) runs round it unless one is named
    let edge = [
        "edge",
        "edges",
        "perimeter",
        "parapet",
        "railing",
        "railings",
    ]
    .iter()
    .any(|w| has(w));
    let one = [
        "one", "back", "front", "far", "near", "left", "right", "rear", "long",
    ];
    if edge && !one.iter().any(|w| has(w)) {
        return Some(0);
    }
    let many = has("walls")
        || ["every", "each", "all", "four", "three"]
            .iter()
            .any(|w| has(w));
    match many {
        true => Some(0),
        // "along the wall" said of a plural is a run along one wall
        false => Some(1),
    }
}

/// Whether a mention can be counted by the walls: a plural the text gives no number for, said
/// of no other instance ("chairs at each table" are counted by the tables), in one row at most
/// ("a row of lockers along the wall" is a run on it).
fn uncounted(r: &Reading, i: usize) -> bool {
    let m: &Mention = &r.mentions[i];
    m.plural
        && (m.count.is_none() || r.parts_counted.contains(&i))
        && !m.negated
        && !m.reference
        && m.each_of.is_none()
        && m.rows <= 1
}

/// Number of words in `s`.
fn words(s: &str) -> usize {
    s.split_whitespace().count()
}

/// Reads which mentions line the walls into `r.lining`, and anchors them to the walls.
pub(super) fn read_lining(r: &mut Reading) {
    let t = r.text.clone();
    // "a corridor lined with lockers", "walls lined with shelves": the things after it line
    // every wall, unless a wall phrase after them says which
    let mut lined: Vec<usize> = vec![];
    for m in re(r"\b(?:lined|lines|line) (?:with|by)\b").find_iter(&t) {
        // "shelves lined with jars": what lines a thing named just before is its contents
        let before = r
            .mentions
            .iter()
            .rfind(|x| x.end <= m.start())
            .is_some_and(|x| words(&t[x.end..m.start()]) <= 2);
        if before {
            continue;
        }
        let Some(i) = r
            .mentions
            .iter()
            .position(|x| x.start >= m.end() && words(&t[m.end()..x.start]) <= 3)
        else {
            continue;
        };
        if uncounted(r, i) {
            lined.push(i);
        }
    }
    let mut lining: Vec<(usize, u32)> = vec![];
    for m in re(SIDE_PHRASE).find_iter(&t) {
        // the nearest thing before the phrase in its clause, which the phrase anchored
        let Some(i) = r.mentions.iter().rposition(|x| x.end <= m.start()) else {
            continue;
        };
        let gap = &t[r.mentions[i].end..m.start()];
        if words(gap) > NEAR || gap.contains([',', '.', ';']) {
            continue;
        }
        let said_of = r.anchors.contains(&(i, Anchor::Side));
        if !said_of || !uncounted(r, i) {
            continue;
        }
        if let Some(n) = walls_named(m.as_str(), lined.contains(&i)) {
            lining.push((i, n));
        }
    }
    for i in lined {
        if !lining.iter().any(|&(j, _)| j == i) {
            lining.push((i, 0));
        }
        if !r.anchors.contains(&(i, Anchor::Side)) {
            r.anchors.push((i, Anchor::Side));
        }
    }
    // a row along a wall is the run on it, not a row standing in the room
    for &(i, _) in &lining {
        let m = &mut r.mentions[i];
        m.rows = 0;
        m.in_rows = false;
    }
    r.lining = lining;
}

#[cfg(test)]
mod tests {
    use super::walls_named;

    #[test]
    fn a_phrase_names_one_two_or_every_wall() {
        assert_eq!(walls_named("along every wall", false), Some(0));
        assert_eq!(walls_named("along the walls", false), Some(0));
        assert_eq!(walls_named("around all four walls", false), Some(0));
        assert_eq!(walls_named("against the back wall", false), Some(1));
        assert_eq!(walls_named("down both sides", false), Some(2));
        assert_eq!(walls_named("on both sides", true), Some(2));
        assert_eq!(walls_named("lining both sides", false), Some(2));
        assert_eq!(walls_named("along opposite walls", false), Some(2));
        // nightstands "on both sides" are either side of the bed, no run of walls
        assert_eq!(walls_named("on both sides", false), None);
        assert_eq!(walls_named("wall-mounted", false), None);
        assert_eq!(walls_named("on the walls", false), None);
        // an open ground's edge runs round it
        assert_eq!(walls_named("lining the edge", false), Some(0));
        assert_eq!(walls_named("around the perimeter", false), Some(0));
        assert_eq!(walls_named("along the back edge", false), Some(1));
    }
}
