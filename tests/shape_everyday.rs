//! Everyday household and garden things that had no object: the reader took a paper towel
//! holder for a beach towel and a knife block for a plain block, planned a doormat as a 0.9 m
//! box and a tricycle 1.6 m tall, and drew an air purifier, a clothesline and a hose reel as
//! plain boxes. Each is now its own category at a fitting size, drawn as what it is.
//! Plan-only and host-only.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
mod reading;
use common::samples::{all, drawn, of, range, sized, within, Samples};
use dreamscene::shape::{archetype_of, Role};
use reading::{keys, plan};

fn at(category: &str, size: [f64; 3]) -> Samples {
    drawn(category, size, 6)
}

#[test]
fn everyday_things_are_read_as_what_they_are_at_their_size() {
    for (prompt, category, not, max_h) in [
        (
            "a tidy kitchen with a paper towel holder by the sink",
            "paper towel holder",
            "beach towel",
            0.5,
        ),
        (
            "a kitchen counter with a knife block and a kettle",
            "knife block",
            "block",
            0.5,
        ),
        (
            "a front porch with a doormat and two chairs",
            "doormat",
            "mat",
            0.05,
        ),
        (
            "a nursery with an air purifier in the corner",
            "air purifier",
            "purifier",
            1.0,
        ),
        (
            "a child's garden with a red tricycle",
            "tricycle",
            "bicycle",
            0.8,
        ),
        (
            "a back garden with a washing line full of laundry",
            "clothesline",
            "box",
            2.2,
        ),
        (
            "a garden with a hose reel next to the shed",
            "hose reel",
            "reel",
            0.8,
        ),
    ] {
        let s = plan(prompt);
        let o = s.objects.get(category);
        assert!(o.is_some(), "{prompt}: {:?}", keys(&s));
        assert!(
            !s.objects.contains_key(not),
            "{prompt}: {not} in {:?}",
            keys(&s)
        );
        let h = o.unwrap().size[2];
        assert!(h <= max_h, "{prompt}: {category} {h} m tall");
    }
}

#[test]
fn a_tricycle_has_a_big_front_wheel_and_two_small_back_ones() {
    for size in sized("tricycle", [1.2, 1.3, 1.1]) {
        let s = at("tricycle", size);
        let hd = size[1] / 2.0;
        let tyres = of(&s, Role::Tyre);
        let front = within(&tyres, |p| p[1] > 0.2 * hd);
        let back = within(&tyres, |p| p[1] < -0.2 * hd);
        assert!(
            range(&front, 2).1 > 1.3 * range(&back, 2).1,
            "{size:?}: wheels alike"
        );
        // two back wheels apart, one front wheel in the middle
        assert!(back.iter().any(|p| p[0] > 0.3 * size[0] / 2.0), "{size:?}");
        assert!(back.iter().any(|p| p[0] < -0.3 * size[0] / 2.0), "{size:?}");
        assert!(
            front.iter().all(|p| p[0].abs() < 0.2 * size[0] / 2.0),
            "{size:?}"
        );
    }
    assert_eq!(archetype_of("trike"), "tricycle");
}

#[test]
fn a_clothesline_hangs_washing_between_two_posts() {
    for size in sized("clothesline", [1.3, 1.0, 1.1]) {
        let s = at("clothesline", size);
        let (hw, h) = (size[0] / 2.0, size[2]);
        let washing = of(&s, Role::Books);
        assert!(washing.len() > 100, "{size:?}: no washing");
        assert!(
            range(&washing, 2).0 > 0.3 * h,
            "{size:?}: washing on the ground"
        );
        let feet = within(&of(&s, Role::Frame), |p| p[2] < 0.02);
        assert!(
            feet.iter().all(|p| p[0].abs() > 0.8 * hw),
            "{size:?}: posts not at the ends"
        );
    }
    assert_eq!(archetype_of("washing line"), "clothesline");
}

#[test]
fn small_kitchen_and_garden_things_have_their_telling_parts() {
    // an air purifier: a grille round a tall tower
    let size = sized("air purifier", [1.0, 1.0, 1.0])[0];
    let s = at("air purifier", size);
    let grille = of(&s, Role::Interior);
    assert!(
        range(&grille, 2).1 - range(&grille, 2).0 > 0.4 * size[2],
        "purifier grille"
    );
    // a knife block: handles standing out of its top
    let size = sized("knife block", [1.0, 1.0, 1.0])[0];
    let s = at("knife block", size);
    assert!(
        range(&of(&s, Role::Handle), 2).1 > 0.9 * size[2],
        "knife handles"
    );
    // a paper towel holder: a roll round a post
    let size = sized("paper towel holder", [1.0, 1.0, 1.0])[0];
    let s = at("paper towel holder", size);
    let roll = of(&s, Role::Canvas);
    assert!(
        range(&roll, 2).1 - range(&roll, 2).0 > 0.7 * size[2],
        "towel roll"
    );
    // a hose reel: the coiled hose on a drum up off the ground
    let size = sized("hose reel", [1.0, 1.0, 1.0])[0];
    let s = at("hose reel", size);
    let coil = within(&of(&s, Role::Pot), |p| p[2] > 0.2 * size[2]);
    assert!(coil.len() > 100, "hose coil");
    assert!(!all(&s).is_empty());
}
