//! The room a request describes: its stated size (the first dimensions no object took; an area
//! otherwise), "for N people", its size words ("a tiny bathroom") and "nothing else".
use super::{number_of, re, word_list, words_in, Mention, Reading};
use crate::plan::units::Dims;

/// The floor factor of a place named as a hall ("an exhibition hall"): twice the floor its
/// kind's furniture needs, the room of a place where a crowd gathers rather than a party.
const HALL_SCALE: f64 = 2.0;

/// The floor factor of a room called huge or vast: the floor of a hall.
const HUGE_SCALE: f64 = HALL_SCALE;

/// Reads the room's size, the people it is for, its scale and whether only what is named is
/// wanted from `t` into `r`; `masked` holds the dimensions objects took.
pub(super) fn read_room(t: &str, r: &mut Reading, masked: &[(usize, usize)], dims: &[Dims]) {
    // Room size: the first stated dims not used for an object; an area otherwise.
    for d in dims {
        if masked.iter().any(|&(s, e)| s == d.start && e == d.end) {
            continue;
        }
        if let Some(a) = d.area {
            if r.room.is_none() && a > 1.0 {
                r.room = Some(crate::plan::units::floor_from_area(a));
            }
        } else if r.room.is_none() && d.values.len() >= 2 {
            r.room = Some([d.values[0], d.values[1]]);
            r.room_unitless = d.unitless;
            if let Some(&h) = d.values.get(2) {
                r.room_height = Some(h);
            }
        }
    }

    // "for 24 students", "for eight people", "a dining room seating ten"
    let people = re(
        r"\b(?:for|seating|that seats|which seats|to seat) (\d+|[a-z]+)(?: (?:students|pupils|kids|children|people|persons|guests|diners|seats|employees|workers|players|customers|visitors))?(?:[ ,.;:!?]|$)",
    );
    for c in people.captures_iter(t) {
        let w = &c[1];
        if ![
            "a", "an", "no", "some", "many", "few", "several", "both", "couple", "pair", "one",
        ]
        .contains(&w)
        {
            if let Some(n) = number_of(w) {
                r.people = Some(n);
            }
        }
    }
    (r.scale, r.long) = room_scale(t, &r.mentions, r.scene.map(|(_, s, _)| s));
    // "a conference hall": a hall is large, unless the text says otherwise ("a small dance hall")
    // or counts what fills it ("a dining hall with three tables for eight": the room is sized
    // for what was counted)
    let counted = r.mentions.iter().any(|m| m.count.is_some_and(|n| n >= 2));
    if r.large_place && r.scale >= 1.0 && !counted {
        r.scale = r.scale.max(HALL_SCALE);
    }
    r.exclusive = re(r"\bnothing else\b|\b(?:only|just) (?:a|an|one|two|three|four|five|[0-9]+)\b")
        .is_match(t);
}

/// The room's size word ("a tiny bathroom", "a bedroom that's tiny", "quite cramped", "a box
/// room") as a factor on the floor area the furniture needs (`kb/words.txt`: room_tiny,
/// room_small, room_large, room_huge), and whether a word draws it out ("a long narrow hall":
/// room_long); a size word inside an object's noun phrase ("a small table") is the object's,
/// not the room's.
fn room_scale(t: &str, mentions: &[Mention], scene_start: Option<usize>) -> (f64, bool) {
    let words = words_in(t, 0, t.len());
    let mut scale: f64 = 1.0;
    let mut long = false;
    for (k, &(pos, w)) in words.iter().enumerate() {
        let two = words
            .get(k + 1)
            .map(|(_, n)| format!("{w} {n}"))
            .unwrap_or_default();
        let factor = if word_list("room_tiny").contains(&w)
            || word_list("room_tiny").contains(&two.replace(' ', "-").as_str())
        {
            0.35
        } else if word_list("room_small").contains(&w) {
            0.5
        } else if word_list("room_large").contains(&w) {
            1.35
        } else if word_list("room_huge").contains(&w) {
            HUGE_SCALE
        } else if word_list("room_long").contains(&w) {
            1.0
        } else {
            continue;
        };
        // "a garden with a treehouse": a word of an object's own name is that object's
        if mentions.iter().any(|m| m.start <= pos && pos < m.end) && scene_start != Some(pos) {
            continue;
        }
        // The noun this word describes: the next mention or scene name before punctuation.
        let rest: Vec<&(usize, &str)> = words[k + 1..]
            .iter()
            .take_while(|(_, x)| !matches!(*x, "," | "-" | "–"))
            .take(4)
            .collect();
        // The first noun after it decides: an object's ("a small table"), or the room's (the
        // scene's name, a place word: "a box room", "a tiny bedroom").
        let object = rest
            .iter()
            .find_map(|&&(p, x)| {
                if scene_start == Some(p) || word_list("place_heads").contains(&x) {
                    Some(false)
                } else if mentions.iter().any(|m| m.start == p) {
                    Some(
                        !mentions
                            .iter()
                            .any(|m| m.start == p && m.category.ends_with("room")),
                    )
                } else {
                    None
                }
            })
            .unwrap_or(false);
        // "a boxroom": the size word is the place's own name
        if object && scene_start != Some(pos) {
            continue;
        }
        long |= word_list("room_long").contains(&w);
        scale = if factor < 1.0 {
            scale.min(factor)
        } else {
            scale.max(factor)
        };
    }
    (scale, long)
}
