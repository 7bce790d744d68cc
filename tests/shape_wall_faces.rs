//! A thing hung on a wall shows its broad face to the room: seen from the front (its +y, the
//! wall's inward normal) its drawing covers much of its box's front, not a strip (a round mirror
//! whose disc stood edge-on to the room, its glass seen only from the side), and its face (a
//! mirror's glass, a picture's canvas, a TV's screen) is the first thing seen from the front
//! where it is, nothing of its own drawing in front of it. A mirror's glass carries a lighter
//! sheen. Shape-only, well under a second in release.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::drawn_mounted;
use dreamscene::plan::gcp::classes::{Class, Placements};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::materials::Role;
use dreamscene::shape::{archetype_of, form_rows, Mount};
use std::collections::BTreeMap;

/// Cells across and up the box's front the front view is cut into.
const CELLS: usize = 16;

/// The wall things: hung on a wall by their class, or by the scene (a TV with no stand).
fn wall_things() -> Vec<(String, [f64; 3])> {
    let table = Placements::builtin();
    KnowledgeBase::builtin()
        .objects
        .iter()
        .filter(|o| {
            matches!(
                table.class(&o.category),
                Class::OnWall(_) | Class::OnSurface(Some(_))
            )
        })
        .map(|o| (o.category.clone(), o.size))
        .collect()
}

/// Descriptions a category can be drawn with: plain, and with each form word of its archetype.
fn descriptions(category: &str) -> Vec<String> {
    let arch = archetype_of(category);
    let mut v = vec![String::new()];
    for (a, words, _) in form_rows() {
        if a == arch {
            v.extend(words.iter().map(|w| format!("a {w} {category}")));
        }
    }
    v
}

/// The front-view cell (across, up) of a point of a drawing in a box of `size`.
fn cell(p: &[f64; 3], size: [f64; 3]) -> (usize, usize) {
    let i = (((p[0] / size[0] + 0.5) * CELLS as f64) as usize).min(CELLS - 1);
    let k = ((p[2] / size[2] * CELLS as f64) as usize).min(CELLS - 1);
    (i, k)
}

/// The share of its box's front a wall thing's drawing covers seen from the front.
fn front_cover(s: &[([f64; 3], Role)], size: [f64; 3]) -> f64 {
    let mut seen = vec![false; CELLS * CELLS];
    for (p, _) in s {
        let (i, k) = cell(p, size);
        seen[k * CELLS + i] = true;
    }
    seen.iter().filter(|c| **c).count() as f64 / (CELLS * CELLS) as f64
}

/// Of the front-view cells where the drawing has its face (a screen, glass or canvas), the
/// share where the face is what is seen first from the front (no other part of it more than
/// [`PROUD`] further out: a clock's hands and a notice board's papers are); `None` when it has
/// no face.
fn face_seen(s: &[([f64; 3], Role)], size: [f64; 3]) -> Option<f64> {
    let face = |r: Role| matches!(r, Role::Screen | Role::Canvas);
    let mut front: BTreeMap<(usize, usize), (f64, f64)> = BTreeMap::new();
    for (p, r) in s {
        if *r == Role::Pane {
            continue; // see-through: a picture's glass shows the picture
        }
        let e = front.entry(cell(p, size)).or_insert((f64::MIN, f64::MIN));
        if face(*r) {
            e.0 = e.0.max(p[1]);
        } else {
            e.1 = e.1.max(p[1]);
        }
    }
    let cells: Vec<_> = front.values().filter(|(f, _)| *f > f64::MIN).collect();
    if cells.is_empty() {
        return None;
    }
    let first = cells.iter().filter(|(f, o)| *f >= *o - PROUD).count();
    Some(first as f64 / cells.len() as f64)
}

/// How far a thing's own small parts may stand proud of its face (m): a clock's hands, the
/// papers pinned on a board.
const PROUD: f64 = 0.015;
/// Least share of its box's front a wall thing covers seen from the front.
const COVER: f64 = 0.3;
/// Least share of its face seen first from the front.
const FACE: f64 = 0.7;

#[test]
fn a_wall_thing_shows_its_broad_face_to_the_room() {
    let mut bad = vec![];
    let mut checked = 0;
    for (category, size) in wall_things() {
        for d in descriptions(&category) {
            let s = drawn_mounted(&category, &d, size, Mount::Wall, 3);
            let cover = front_cover(&s, size);
            if cover < COVER {
                bad.push(format!("{category} \"{d}\": front covered {cover:.2}"));
            }
            if let Some(f) = face_seen(&s, size).filter(|f| *f < FACE) {
                bad.push(format!("{category} \"{d}\": face seen first {f:.2}"));
            }
            checked += 1;
        }
    }
    assert!(checked > 30, "only {checked} wall things");
    assert!(bad.is_empty(), "wall things turned from the room: {bad:?}");
}

#[test]
fn a_round_mirror_on_a_wall_faces_the_room_with_bright_glass_and_a_sheen() {
    for (category, d) in [
        ("mirror", "a round mirror"),
        ("mirror", "a round mirror on the wall"),
        ("mirror", "an oval bathroom mirror"),
        ("mirror", ""),
    ] {
        let size = KnowledgeBase::builtin().object(category).unwrap().size;
        let s = drawn_mounted(category, d, size, Mount::Wall, 3);
        let glass: Vec<_> = s.iter().filter(|(_, r)| *r == Role::Canvas).collect();
        assert!(!glass.is_empty(), "{category} \"{d}\": no glass");
        // the glass spreads across and up (a disc facing +y), and is thin along y
        let spread = |a: usize| {
            let (lo, hi) = glass.iter().fold((f64::MAX, f64::MIN), |(l, h), (p, _)| {
                (l.min(p[a]), h.max(p[a]))
            });
            hi - lo
        };
        assert!(
            spread(0) > 0.5 * size[0] && spread(2) > 0.3 * size[2] && spread(1) < 0.02,
            "{category} \"{d}\": glass spans {:.3} x {:.3} x {:.3} m",
            spread(0),
            spread(1),
            spread(2)
        );
        let f = face_seen(&s, size).unwrap();
        assert!(f > FACE, "{category} \"{d}\": glass seen first {f:.2}");
    }
    // the sheen: lighter streaks on the glass, in front of it
    let size = KnowledgeBase::builtin().object("mirror").unwrap().size;
    let parts =
        dreamscene::shape::parts_mounted("mirror", size, "a round mirror", Mount::Wall).unwrap();
    let sheen = parts
        .iter()
        .filter(|p| p.role == Role::Canvas && p.variant == 1)
        .count();
    assert!(sheen >= 2, "{sheen} sheen streaks");
}
