//! Birds look like the one named: each is drawn from its row of the bird table
//! (`src/shape/kb/birds.txt`), checked on its surface samples at its knowledge-base size and a
//! stretched one: a flamingo stands on long bare legs, a swan's head rises far above its back,
//! a penguin stands upright with its pale breast to the front, an owl looks ahead with both
//! eyes under two ear tufts, a hen wears a comb on its crown, a duck is long and low; colour
//! words paint the whole bird, a second one its breast. Host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{all, drawn, of, range, sized, within, Samples};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{archetype_of, bird_rows, build, Role, ShapeOptions};
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
fn every_bird_category_has_a_row_and_every_row_parses() {
    let (rows, bad) = bird_rows();
    assert!(
        bad.is_empty(),
        "birds.txt lines that do not parse: {bad:#?}"
    );
    for r in rows.iter().filter(|r| **r != "default") {
        assert_eq!(archetype_of(r), "bird", "birds.txt row `{r}`");
    }
    let kb = KnowledgeBase::builtin();
    let missing: Vec<&str> = kb
        .objects
        .iter()
        .filter(|o| o.archetype == "bird" && !rows.contains(&o.category.as_str()))
        .map(|o| o.category.as_str())
        .collect();
    assert!(missing.is_empty(), "birds without a row: {missing:?}");
    for name in [
        "parrot", "hen", "rooster", "duck", "owl", "pigeon", "swan", "flamingo",
    ] {
        assert_eq!(archetype_of(name), "bird", "{name}");
    }
}

#[test]
fn a_flamingo_stands_on_long_bare_legs_and_a_duck_sits_low() {
    // Below 45% of its height a flamingo is only legs: a narrow, thin band of samples.
    for size in sized("flamingo", [1.2, 0.9, 1.1]) {
        let s = along_y("flamingo", size);
        let low = within(&all(&s), |p| p[2] > 0.08 * size[2] && p[2] < 0.45 * size[2]);
        assert!(!low.is_empty(), "flamingo {size:?}: no legs");
        let (y0, y1) = range(&low, 1);
        let len = size[0].max(size[1]);
        assert!(
            y1 - y0 < 0.2 * len,
            "flamingo {size:?}: legs {:.2} long",
            (y1 - y0) / len
        );
    }
    // A duck's body reaches down to a fifth of its height along most of its length.
    let size = sized("duck", [1.0; 3])[0];
    let s = along_y("duck", size);
    let low = within(&all(&s), |p| p[2] < 0.3 * size[2] && p[2] > 0.1 * size[2]);
    let (y0, y1) = range(&low, 1);
    assert!(
        y1 - y0 > 0.5 * size[1],
        "duck: belly {:.2} long",
        (y1 - y0) / size[1]
    );
}

#[test]
fn a_swans_head_rises_far_above_its_back() {
    for size in sized("swan", [1.2, 0.9, 1.1]) {
        let s = along_y("swan", size);
        let (back, head) = (
            top_between(&s, size, 0.0, 0.4),
            top_between(&s, size, 0.6, 1.0),
        );
        assert!(
            back < 0.6 && head > 0.95,
            "swan {size:?}: back {back:.2}, head {head:.2}"
        );
    }
}

#[test]
fn a_penguin_stands_upright_with_its_breast_to_the_front() {
    for size in sized("penguin", [1.1, 0.9, 1.1]) {
        let s = along_y("penguin", size);
        let mean_y = |pts: &[[f64; 3]]| pts.iter().map(|p| p[1]).sum::<f64>() / pts.len() as f64;
        let (breast, back) = (of(&s, Role::Cushion), of(&s, Role::Body));
        assert!(
            mean_y(&breast) > mean_y(&back) + 0.1 * size[1],
            "penguin {size:?}: breast {:.2}, back {:.2}",
            mean_y(&breast),
            mean_y(&back)
        );
        let (z0, z1) = range(&breast, 2);
        assert!(
            z1 - z0 > 0.5 * size[2],
            "penguin {size:?}: breast {:.2} tall",
            (z1 - z0) / size[2]
        );
    }
}

#[test]
fn an_owl_looks_ahead_with_both_eyes_under_tufts_and_a_parrot_sideways() {
    for size in sized("owl", [1.2, 0.9, 1.1]) {
        let s = along_y("owl", size);
        let eyes = of(&s, Role::Light);
        assert!(!eyes.is_empty(), "owl {size:?}: no eyes");
        let front = eyes
            .iter()
            .filter(|p| p[1] > 0.25 * size[1].min(size[0]))
            .count();
        assert!(
            front * 2 > eyes.len(),
            "owl {size:?}: eyes not to the front"
        );
        for sx in [-1.0, 1.0] {
            let tuft = within(&all(&s), |p| {
                p[0] * sx > 0.1 * size[0] && p[2] > 0.93 * size[2]
            });
            assert!(!tuft.is_empty(), "owl {size:?}: no ear tuft at {sx}");
        }
    }
    let size = sized("parrot", [1.0; 3])[0];
    let s = along_y("parrot", size);
    let eyes = of(&s, Role::Interior);
    let (x0, x1) = range(&eyes, 0);
    assert!(
        x1 - x0 > 0.4 * size[0],
        "parrot: eyes {:.2} apart",
        (x1 - x0) / size[0]
    );
    assert!(of(&s, Role::Light).is_empty(), "a parrot has no owl's eyes");
}

#[test]
fn a_hen_wears_a_comb_on_its_crown_and_a_pigeon_none() {
    for size in sized("chicken", [1.2, 0.9, 1.1]) {
        let s = along_y("chicken", size);
        let comb = of(&s, Role::Skin);
        assert!(!comb.is_empty(), "hen {size:?}: no comb");
        assert!(
            range(&comb, 2).1 > 0.95 * size[2],
            "hen {size:?}: comb below the crown"
        );
    }
    let size = sized("pigeon", [1.0; 3])[0];
    assert!(of(&along_y("pigeon", size), Role::Skin).is_empty());
}

/// The mean colour of the Gaussians nearest the front of `category` drawn as `description`
/// (its breast), and of all of them.
fn colours(category: &str, description: &str) -> ([f32; 3], [f32; 3]) {
    let size = KnowledgeBase::builtin().object(category).unwrap().size;
    let g = build(category, size, description, &ShapeOptions::default()).unwrap();
    let rgb = |i: usize| {
        g.sh[i * 3..i * 3 + 3]
            .iter()
            .map(|c| 0.5 + SH_C0 as f32 * c)
            .collect::<Vec<_>>()
    };
    let mean = |idx: &[usize]| {
        let mut m = [0.0f32; 3];
        for &i in idx {
            for (k, v) in rgb(i).into_iter().enumerate() {
                m[k] += v / idx.len() as f32;
            }
        }
        m
    };
    let along = if size[0] > size[1] { 0 } else { 1 };
    let mid = size[2] as f32 * 0.5;
    let mut band: Vec<usize> = (0..g.means.len())
        .filter(|&i| (g.means[i][2] - mid).abs() < 0.2 * mid)
        .collect();
    // The most forward Gaussians of the band: the breast's surface.
    band.sort_by(|&i, &j| g.means[j][along].total_cmp(&g.means[i][along]));
    let front = &band[..40.min(band.len())];
    let every: Vec<usize> = (0..g.means.len()).collect();
    (mean(front), mean(&every))
}

#[test]
fn colour_words_paint_the_whole_bird_and_a_second_its_breast() {
    let (breast, _) = colours("chicken", "a white hen");
    assert!(
        breast.iter().all(|c| *c > 0.7),
        "a white hen's breast {breast:?}"
    );
    let (breast, whole) = colours("penguin", "a black and white penguin");
    assert!(breast.iter().all(|c| *c > 0.7), "penguin breast {breast:?}");
    assert!(whole.iter().sum::<f32>() < 1.8, "penguin {whole:?}");
}
