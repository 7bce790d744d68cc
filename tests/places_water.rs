//! Places, water and colours drawn in scenes we did not write that did not read as what they
//! are, each checked on the plan, the environment's draft colours or an object's parts against
//! the old defect: a church, a throne room or a sports hall had a house's flat 2.8 m ceiling; a
//! dragon's lair was a small white room with windows; a tatami room had a dark plank floor; a
//! ship's deck was a sandy plane (boards too fine for the outdoor ground's point spacing) with
//! no rail; a pond was a raised tub with a rim, a koi pond had no fish; the sea read as a pool
//! with full-width lane ropes; "a wooden bridge" made every object of a park wooden (a wooden
//! stone fountain); a stone bench was wood-brown and an iron-bound chest iron-grey all over.
//! Host-only, plan and shape only (cheap in a debug build).
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
mod reading;
use common::samples::{drawn, of, range, sized, within};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{OpeningKind, SceneType};
use dreamscene::scene::env::{draft_colours, Pattern};
use dreamscene::shape::{archetype_of, build, Role, ShapeOptions};
use dreamscene::splat::cloud::SH_C0;
use reading::plan;

fn room(prompt: &str) -> [f64; 3] {
    plan(prompt).room.unwrap().size
}

#[test]
fn a_tall_place_has_a_tall_room_and_a_house_room_does_not() {
    for (prompt, least) in [
        ("a little stone chapel with six pews and an altar", 6.0),
        ("a cathedral with rows of pews and two statues", 6.0),
        ("a great hall with a throne and four suits of armour", 5.5),
        ("a school sports hall with two benches", 6.0),
        ("a cave with a treasure chest", 4.5),
    ] {
        let h = room(prompt)[2];
        assert!(h >= least, "{prompt}: {h} m high");
    }
    for prompt in [
        "a living room with a sofa and a coffee table",
        "a bedroom with a double bed",
    ] {
        let h = room(prompt)[2];
        assert!(h < 3.2, "{prompt}: {h} m high");
    }
    // a height the text gives wins
    let h = room("a chapel 6 by 8 by 4 metres with four pews")[2];
    assert!((h - 4.0).abs() < 0.05, "stated height: {h}");
}

#[test]
fn a_cave_is_a_big_dark_rock_room_without_windows() {
    for prompt in [
        "a dragon's lair with a pile of treasure chests",
        "a smugglers' cave with barrels and crates",
        "a cavern with a few rocks",
    ] {
        let p = plan_prompt(prompt).unwrap();
        let size = p.spec.room.as_ref().unwrap().size;
        assert!(size[0] * size[1] >= 80.0, "{prompt}: {size:?}");
        for seed in 0..3 {
            let l = layout(&p.spec, LayoutOptions::seeded(seed)).unwrap();
            assert!(
                l.openings.iter().all(|o| o.kind == OpeningKind::Door),
                "{prompt} seed {seed}: a window"
            );
        }
        let c = draft_colours(SceneType::Indoor, prompt);
        assert_eq!(c.wall_pattern, Pattern::Rock, "{prompt}");
        assert_eq!(c.ceiling_pattern, Pattern::Rock, "{prompt}");
        assert!(c.wall.iter().all(|v| *v < 0.5), "{prompt}: {:?}", c.wall);
    }
    // a room keeps its windows and its painted ceiling
    let l = layout(
        &plan("a bedroom with a bed and a wardrobe"),
        LayoutOptions::seeded(0),
    )
    .unwrap();
    assert!(l.openings.iter().any(|o| o.kind == OpeningKind::Window));
    let c = draft_colours(SceneType::Indoor, "a bedroom with a bed and a wardrobe");
    assert_eq!(c.ceiling_pattern, Pattern::Plain);
}

#[test]
fn a_tatami_room_has_mats_and_a_ship_deck_planks_inside_a_bulwark() {
    for prompt in [
        "a tatami room with a low table and floor cushions",
        "a japanese tea room with a tea table",
    ] {
        let c = draft_colours(SceneType::Indoor, prompt);
        assert_eq!(c.floor_pattern, Pattern::Tatami, "{prompt}");
    }
    for prompt in [
        "a pirate ship's deck with barrels and a cannon",
        "the deck of a pirate ship with crates",
    ] {
        let c = draft_colours(SceneType::Outdoor, prompt);
        assert_eq!(c.ground_pattern, Pattern::Planks, "{prompt}");
        assert!(c.parapet.is_some(), "{prompt}: no bulwark");
    }
    // planks read at the outdoor ground's spacing (7-8 cm): seams darker than the planks,
    // several seams across a few metres
    let base = [0.55, 0.40, 0.26];
    let row: Vec<f32> = (0..60)
        .map(|i| {
            dreamscene::scene::env::shade(base, Pattern::Planks, 0.3, i as f32 * 0.075, 0.5, 1)[0]
        })
        .collect();
    let dark = row.iter().filter(|v| **v < 0.3).count();
    assert!((5..30).contains(&dark), "{dark} dark points of 60");
}

/// Mean colour of a drawn object.
fn mean(category: &str, description: &str) -> [f64; 3] {
    let size = sized(category, [1.0, 1.0, 1.0])[0];
    let g = build(category, size, description, &ShapeOptions::default()).unwrap();
    let mut m = [0.0; 3];
    for i in 0..g.len() {
        for (k, v) in m.iter_mut().enumerate() {
            *v += (SH_C0 * g.sh[i * 3 + k] as f64 + 0.5) / g.len() as f64;
        }
    }
    m
}

#[test]
fn material_words_colour_what_they_name() {
    // a stone bench is grey stone, not the wood of a plain bench
    let stone = mean("stone bench", "a stone bench");
    let wood = mean("bench", "a bench");
    assert!((stone[0] - stone[2]).abs() < 0.08, "stone {stone:?}");
    assert!(wood[0] - wood[2] > 0.15, "wood {wood:?}");
    // an iron-bound chest is a wooden chest with iron straps, not iron all over
    let bound = mean("pirate chest", "an iron-bound pirate chest");
    assert!(bound[0] - bound[2] > 0.1, "iron-bound {bound:?}");
    let iron = mean("pirate chest", "an iron chest");
    assert!(iron[0] < bound[0] - 0.1, "iron {iron:?} bound {bound:?}");
    // a word of the place's object names is not the style of every object
    for prompt in [
        "a town square with a little wooden bridge over the canal, a fountain and two benches",
        "a garden with a wooden bridge across the stream and a stone lantern",
    ] {
        let s = plan(prompt);
        let kb = dreamscene::plan::kb::KnowledgeBase::builtin();
        for (c, o) in &s.objects {
            let own = kb.object(c).map_or("", |k| k.description.as_str());
            if c != "wooden bridge" && !own.contains("wooden") {
                assert!(
                    !o.description.contains("wooden"),
                    "{prompt}: {c}: {}",
                    o.description
                );
            }
        }
    }
    // a style word still describes the whole scene
    let s = plan("a rustic garden with a wooden bridge and a bench");
    assert!(
        s.objects
            .iter()
            .all(|(_, o)| o.description.contains("rustic")),
        "{:?}",
        s.objects
            .values()
            .map(|o| &o.description)
            .collect::<Vec<_>>()
    );
}

#[test]
fn a_pond_lies_in_the_ground_with_fish_in_it() {
    for name in ["pond", "koi pond", "lily pond"] {
        assert_ne!(archetype_of(name), "water", "{name}");
        for size in sized(name, [1.6, 0.7, 1.0]) {
            let s = drawn(name, size, 3);
            let water = of(&s, Role::Water);
            assert!(range(&water, 2).1 < 0.06, "{name} {size:?}: water raised");
            // no rim wall: the edging is low stones, the water reaches near the box's edge
            assert!(of(&s, Role::Top).is_empty(), "{name} {size:?}: a rim");
            let stones = of(&s, Role::Stone);
            assert!(!stones.is_empty(), "{name} {size:?}: no edging");
            assert!(range(&stones, 2).1 < 0.2, "{name} {size:?}: edging tall");
            assert!(range(&water, 0).1 > 0.3 * size[0], "{name} {size:?}");
        }
    }
    for name in ["pond", "koi pond"] {
        let size = sized(name, [1.0, 1.0, 1.0])[0];
        let s = drawn(name, size, 3);
        let fish = within(&of(&s, Role::Body), |p| p[2] < 0.08);
        assert!(fish.len() > 20, "{name}: no fish");
    }
    // pools and fountains stay basins
    for name in ["swimming pool", "fountain"] {
        assert_eq!(archetype_of(name), "water", "{name}");
    }
}

#[test]
fn the_sea_has_a_ragged_foam_line_and_broken_crests_not_lane_ropes() {
    for size in sized("sea", [1.5, 0.6, 1.0]) {
        let s = drawn("sea", size, 5);
        let (hw, hd) = (size[0] / 2.0, size[1] / 2.0);
        let foam = of(&s, Role::Canvas);
        // the foam line's front edge wavers along the shore
        let bins = 20;
        let mut front = vec![f64::NEG_INFINITY; bins];
        for p in within(&foam, |p| p[1] > 0.3 * hd) {
            let k = (((p[0] + hw) / size[0] * bins as f64) as usize).min(bins - 1);
            front[k] = front[k].max(p[1]);
        }
        let (lo, hi) = front
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                (l.min(*v), h.max(*v))
            });
        assert!(hi - lo > 0.02 * size[1], "{size:?}: a straight foam line");
        // out on the water the crests are broken: no row runs the full width
        let out = within(&foam, |p| p[1] < 0.0);
        assert!(!out.is_empty(), "{size:?}: no crests");
        let mut covered = vec![false; bins];
        for p in &out {
            covered[(((p[0] + hw) / size[0] * bins as f64) as usize).min(bins - 1)] = true;
        }
        let share = covered.iter().filter(|c| **c).count() as f64 / bins as f64;
        assert!(share < 1.0, "{size:?}: crests across the whole width");
        // a wet band between the sand and the water
        assert!(!of(&s, Role::Interior).is_empty(), "{size:?}: no wet sand");
    }
}
