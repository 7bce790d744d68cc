//! Four-legged animals look like the one named: each is drawn from its row of the animal table
//! (`src/shape/kb/animals.txt`), checked on its surface samples at its knowledge-base size and a
//! stretched one: a giraffe's head stands far above its back, a camel has a hump, an elephant
//! a trunk reaching the ground ahead of its front legs, a pig is low with its back level with
//! its head, a zebra is striped in two colours and a sheep's face is darker than its fleece; a
//! spring rider is a horse on a coil, a dinosaur skeleton bones on a plinth. Host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, sized, within, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{animal_rows, archetype_of, build, Role, ShapeOptions};
use dreamscene::splat::cloud::SH_C0;

/// Samples of `category` at `size`, turned so its length runs along y (head at +y).
fn along_y(category: &str, size: [f64; 3]) -> Samples {
    let s = drawn(category, size, 5);
    if size[0] > size[1] {
        s.into_iter()
            .map(|(p, r)| ([-p[1], p[0], p[2]], r))
            .collect()
    } else {
        s
    }
}

/// The highest sample over the third of the length at `third` (0 rear, 1 middle, 2 front), as a
/// fraction of the height.
fn top_of_third(s: &Samples, size: [f64; 3], third: usize) -> f64 {
    let t = third as f64 / 3.0;
    top_between(s, size, t, t + 1.0 / 3.0)
}

/// The highest sample between fractions `a` and `b` of the length from the rear, as a fraction
/// of the height.
fn top_between(s: &Samples, size: [f64; 3], a: f64, b: f64) -> f64 {
    let len = size[0].max(size[1]);
    let pts = within(&all(s), |p| {
        (a * len..b * len).contains(&(p[1] + len / 2.0))
    });
    range(&pts, 2).1 / size[2]
}

#[test]
fn every_quadruped_category_has_a_row_and_every_row_parses() {
    let (rows, bad) = animal_rows();
    assert!(
        bad.is_empty(),
        "animals.txt lines that do not parse: {bad:#?}"
    );
    let kb = KnowledgeBase::builtin();
    for r in rows.iter().filter(|r| **r != "default") {
        assert_eq!(archetype_of(r), "quadruped", "animals.txt row `{r}`");
    }
    let missing: Vec<&str> = kb
        .objects
        .iter()
        .filter(|o| o.archetype == "quadruped" && !rows.contains(&o.category.as_str()))
        .map(|o| o.category.as_str())
        .collect();
    assert!(missing.is_empty(), "quadrupeds without a row: {missing:?}");
}

#[test]
fn a_giraffes_head_stands_far_above_its_back_and_a_pigs_back_is_level_with_its_head() {
    for size in sized("giraffe", [1.2, 0.9, 1.1]) {
        let s = along_y("giraffe", size);
        let (back, head) = (top_of_third(&s, size, 0), top_of_third(&s, size, 2));
        assert!(
            back < 0.7 && head > 0.97,
            "giraffe {size:?}: back {back:.2}, head {head:.2}"
        );
    }
    for size in sized("horse", [1.1, 0.9, 1.1]) {
        let s = along_y("horse", size);
        let back = top_of_third(&s, size, 0);
        assert!((0.7..0.9).contains(&back), "horse {size:?}: back {back:.2}");
    }
    for size in sized("pig", [1.2, 1.2, 0.9]) {
        let s = along_y("pig", size);
        let back = top_of_third(&s, size, 0);
        assert!(back > 0.92, "pig {size:?}: back {back:.2}");
    }
}

#[test]
fn a_camel_has_a_hump_and_a_horse_none() {
    let hump = |c: &str, size| {
        let s = along_y(c, size);
        top_between(&s, size, 0.3, 0.55) - top_between(&s, size, 0.0, 0.15)
    };
    for size in sized("camel", [1.2, 0.9, 1.1]) {
        let d = hump("camel", size);
        assert!(d > 0.15, "camel {size:?}: middle over rear {d:.2}");
    }
    for c in ["horse", "donkey", "zebra"] {
        let size = sized(c, [1.0; 3])[0];
        assert!(hump(c, size) < 0.1, "{c}: a hump");
    }
}

#[test]
fn an_elephant_has_a_trunk_to_the_ground_ahead_of_its_legs_and_ears_out_wide() {
    // Something low (under a quarter of the height) in the front tenth of the length, on
    // the middle line: a trunk. A horse's head and legs leave that empty.
    let trunk = |c: &str, size: [f64; 3]| {
        let s = along_y(c, size);
        let (len, across) = (size[0].max(size[1]), size[0].min(size[1]));
        within(&all(&s), |p| {
            p[1] > 0.3 * len && p[2] < 0.25 * size[2] && p[0].abs() < 0.15 * across
        })
        .len()
    };
    for size in sized("elephant", [1.1, 0.9, 1.1]) {
        assert!(trunk("elephant", size) > 20, "elephant {size:?}: no trunk");
        let s = along_y("elephant", size);
        let head = within(&all(&s), |p| p[2] > 0.6 * size[2] && p[1] > 0.15 * size[1]);
        let (x0, x1) = range(&head, 0);
        assert!(
            x1 - x0 > 0.75 * size[0],
            "elephant {size:?}: ears {:.2}",
            x1 - x0
        );
    }
    for c in ["horse", "cow", "camel"] {
        let size = sized(c, [1.0; 3])[0];
        assert_eq!(trunk(c, size), 0, "{c}: a trunk");
    }
}

/// The share of an object's Gaussians that are dark (mean below 0.3) and light (above 0.7).
fn dark_and_light(category: &str, description: &str) -> (f64, f64) {
    let size = KnowledgeBase::builtin().object(category).unwrap().size;
    let g = build(category, size, description, &ShapeOptions::default()).unwrap();
    let lum = |i: usize| {
        (0..3)
            .map(|c| SH_C0 * g.sh[i * 3 + c] as f64 + 0.5)
            .sum::<f64>()
            / 3.0
    };
    let n = g.len() as f64;
    let dark = (0..g.len()).filter(|i| lum(*i) < 0.3).count() as f64 / n;
    let light = (0..g.len()).filter(|i| lum(*i) > 0.7).count() as f64 / n;
    (dark, light)
}

#[test]
fn striped_and_patched_coats_show_two_colours_whatever_the_colour_word() {
    for (c, d) in [
        ("zebra", "black and white striped zebra"),
        ("zebra", "striped zebra"),
        ("cow", "black and white cow"),
        ("cow", "white cow with black patches"),
    ] {
        let (dark, light) = dark_and_light(c, d);
        assert!(
            dark > 0.1 && light > 0.1,
            "`{d}`: dark {dark:.2}, light {light:.2}"
        );
    }
    // A plain coat takes the colour word.
    let (_, white) = dark_and_light("horse", "white horse");
    let (_, brown) = dark_and_light("horse", "brown horse");
    assert!(
        white > 0.3 && brown < 0.05,
        "white horse {white:.2}, brown {brown:.2}"
    );
}

#[test]
fn two_coat_colours_go_on_in_the_animals_own_order() {
    // A zebra is white with black stripes whichever colour is named first; a cow's coat stays
    // white under its brown patches.
    for (c, d) in [
        ("zebra", "a black and white striped zebra"),
        ("zebra", "a white and black zebra"),
        ("zebra", "black-and-white striped zebra"),
        ("cow", "a brown and white spotted cow"),
    ] {
        // The light share is the row's own (white coat), not the pattern's.
        let (_, light) = dark_and_light(c, d);
        let (_, row) = dark_and_light(c, c);
        assert!(
            (light - row).abs() < 0.05,
            "`{d}`: coat not the light colour (light {light:.2}, the row's {row:.2})"
        );
    }
}

#[test]
fn a_sheep_is_a_round_fleece_with_a_dark_face_and_legs() {
    for size in sized("sheep", [1.2, 1.1, 0.9]) {
        let s = along_y("sheep", size);
        let skin = of(&s, Role::Skin);
        // The face at the front, the legs down to the ground.
        assert!(
            range(&skin, 1).1 > 0.35 * size[1],
            "sheep {size:?}: no dark face"
        );
        assert!(
            range(&skin, 2).0 < 0.01 * size[2],
            "sheep {size:?}: no dark legs"
        );
        // The fleece fills the width of the footprint.
        let fleece = of(&s, Role::Body);
        let (x0, x1) = range(&fleece, 0);
        assert!(
            x1 - x0 > 0.9 * size[0],
            "sheep {size:?}: fleece {:.2}",
            x1 - x0
        );
    }
    let (dark, _) = dark_and_light("sheep", "white woolly sheep");
    assert!(dark > 0.05, "a sheep's face and legs are dark: {dark:.2}");
}

#[test]
fn a_spring_rider_is_a_horse_on_a_coil_and_a_dinosaur_skeleton_is_bones_on_a_plinth() {
    for size in sized("spring rider", [1.2, 1.1, 1.2]) {
        let s = drawn("spring rider", size, 5);
        let coil = of(&s, Role::Metal);
        assert!(!coil.is_empty(), "spring rider {size:?}: no coil");
        assert!(
            range(&coil, 2).1 < 0.5 * size[2],
            "spring rider {size:?}: coil too high"
        );
        // Under the horse only the coil and its plate: a narrow waist.
        let waist = within(&all(&s), |p| p[2] > 0.15 * size[2] && p[2] < 0.3 * size[2]);
        let (y0, y1) = range(&waist, 1);
        assert!(
            y1 - y0 < 0.5 * size[1],
            "spring rider {size:?}: legs to the ground"
        );
        let body = of(&s, Role::Body);
        assert!(
            range(&body, 2).0 > 0.3 * size[2],
            "spring rider {size:?}: body low"
        );
    }
    for size in sized("dinosaur skeleton", [1.2, 1.0, 1.1]) {
        let s = drawn("dinosaur skeleton", size, 5);
        let plinth = of(&s, Role::Stone);
        assert!(
            range(&plinth, 2).1 < 0.1 * size[2],
            "{size:?}: no low plinth"
        );
        assert!(!of(&s, Role::Metal).is_empty(), "{size:?}: no posts");
        // Bones, not a body: seen from the side, the chest is mostly gaps between ribs.
        let len = size[0].max(size[1]);
        let bones = of(&s, Role::Body);
        let cell = 0.01 * len;
        let mut cells: Vec<(i64, i64)> = bones
            .iter()
            .filter(|p| p[2] > 0.35 * size[2] && p[2] < 0.6 * size[2])
            .filter(|p| p[0].abs().max(p[1].abs()) < 0.2 * len)
            .map(|p| {
                let along = if size[0] > size[1] { p[0] } else { p[1] };
                ((along / cell).floor() as i64, (p[2] / cell).floor() as i64)
            })
            .collect();
        cells.sort_unstable();
        cells.dedup();
        let total = (0.4 * len / cell) * (0.25 * size[2] / cell);
        let fill = cells.len() as f64 / total;
        assert!(
            fill > 0.05 && fill < 0.75,
            "{size:?}: chest side fill {fill:.2}"
        );
    }
}
