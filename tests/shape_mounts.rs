//! The drawing follows the mount the layout gives: a thing hung on a wall has no legs, stand or
//! foot dangling under it (a round mirror on a bathroom wall was a cheval mirror on two legs in
//! the air, an office's whiteboard an easel on posts lifted onto the wall, a TV on the wall kept
//! its stand), a thing hung from the ceiling hangs from the top of its box (a tatami room's paper
//! lanterns were table lanterns, a globe on a black foot, floating under the ceiling), and a
//! standing one keeps its stand. The words still choose: "a whiteboard on wheels" stands on the
//! floor, "a standing mirror" is the standing kind. Shape- and plan-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
mod reading;
use common::samples::{all, drawn_mounted, of, range};
use dreamscene::plan::gcp::classes::{Class, Placements};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{archetype_of, form_rows, Mount, Role};
use reading::{keys, plan};

/// Slices the drawing's height is cut into to find a waist.
const SLICES: usize = 50;
/// Slices at the foot a foot plate may take before the legs or stem begin.
const FOOT: usize = 3;
/// A slice narrower than this share of the box's width holds only legs, posts or a stem.
const NARROW: f64 = 0.25;

/// The stretch (a share of the drawing's height) of narrow slices from its foot up, past a
/// thin foot plate: legs, posts or a stem holding up something wider. Zero for a thing wide
/// down to its lowest edge (a panel, a disc, a rack on its lowest board).
fn waist(category: &str, description: &str, size: [f64; 3], mount: Mount) -> f64 {
    let pts = all(&drawn_mounted(category, description, size, mount, 5));
    let (z0, z1) = range(&pts, 2);
    let hh = (z1 - z0).max(1e-9);
    let cells = 40;
    let mut cover = vec![vec![false; cells]; SLICES];
    for p in &pts {
        let k = (((p[2] - z0) / hh * SLICES as f64) as usize).min(SLICES - 1);
        let c = (((p[0] / size[0] + 0.5) * cells as f64) as usize).min(cells - 1);
        cover[k][c] = true;
    }
    let wide: Vec<bool> = cover
        .iter()
        .map(|r| r.iter().filter(|c| **c).count() as f64 / cells as f64 >= NARROW)
        .collect();
    // (a thin foot plate under the legs or stem is part of the stand)
    let Some(first) = wide.iter().position(|w| !*w).filter(|k| *k <= FOOT) else {
        return 0.0;
    };
    let best = wide[first..].iter().take_while(|w| !**w).count();
    best as f64 / SLICES as f64
}

/// How far below the top of its box a drawing's highest point lies (m).
fn gap_to_top(category: &str, size: [f64; 3], mount: Mount) -> f64 {
    let pts = all(&drawn_mounted(category, "", size, mount, 5));
    size[2] - range(&pts, 2).1
}

/// Descriptions a category can be drawn with: plain, and with each form word of its archetype
/// ("a round mirror", "an oval mirror").
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

/// A waist longer than this (a share of its height) is legs or a stand.
const LEGS: f64 = 0.08;

/// Wall things narrow at their foot by nature, not on legs: coats hang below their hooks' rail,
/// an oar hangs lengthwise out from the wall (its narrow side is across).
const HANG_DOWN: &[&str] = &["coat hooks", "oar"];

#[test]
fn a_thing_hung_on_a_wall_has_nothing_dangling_below_it() {
    let kb = KnowledgeBase::builtin();
    let table = Placements::builtin();
    let mut bad = vec![];
    for o in &kb.objects {
        // hung on a wall by its class, or by the scene (a TV with no stand, on the wall)
        let hangs = matches!(
            table.class(&o.category),
            Class::OnWall(_) | Class::OnSurface(Some(_))
        );
        if !hangs || HANG_DOWN.contains(&o.category.as_str()) {
            continue;
        }
        for d in descriptions(&o.category) {
            let w = waist(&o.category, &d, o.size, Mount::Wall);
            if w > LEGS {
                bad.push(format!("{} \"{d}\": {w:.2}", o.category));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "legs or a stand under a wall thing: {bad:?}"
    );
}

#[test]
fn a_thing_hung_from_the_ceiling_hangs_from_the_top_of_its_box() {
    let kb = KnowledgeBase::builtin();
    let mut bad = vec![];
    for o in &kb.objects {
        if Placements::builtin().class(&o.category) != Class::Ceiling {
            continue;
        }
        let gap = gap_to_top(&o.category, o.size, Mount::Ceiling);
        if gap > 0.005 {
            bad.push(format!("{}: {gap:.3} m below the ceiling", o.category));
        }
    }
    assert!(bad.is_empty(), "hung from nothing: {bad:?}");
    // The paper lantern hangs on a cord: narrow above its globe, wide at its foot.
    let size = kb.object("paper lantern").unwrap().size;
    let pts = all(&drawn_mounted("paper lantern", "", size, Mount::Ceiling, 5));
    let low = pts.iter().filter(|p| p[2] < 0.05 * size[2]).count();
    assert!(low > 0, "the globe is not at the foot of the box");
    let cord: Vec<_> = pts.iter().filter(|p| p[2] > 0.9 * size[2] - 0.03).collect();
    let (x0, x1) = cord
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p[0]), b.max(p[0])));
    assert!(
        x1 - x0 < 0.5 * size[0],
        "no cord: {:.2} m wide at the top",
        x1 - x0
    );
}

#[test]
fn a_standing_thing_keeps_its_legs_or_stand() {
    for (category, description) in [
        ("makeup mirror", "a round makeup mirror"),
        ("mobile whiteboard", ""),
        ("paper lantern", ""),
    ] {
        let size = KnowledgeBase::builtin().object(category).unwrap().size;
        let w = waist(category, description, size, Mount::Stand);
        assert!(
            w > LEGS,
            "{category} \"{description}\" standing: waist {w:.2}"
        );
    }
    // a TV stands on its foot (metal at the floor of its box), and hung on a wall has none
    let size = KnowledgeBase::builtin().object("tv").unwrap().size;
    let foot = |mount| {
        let s = drawn_mounted("tv", "", size, mount, 5);
        of(&s, Role::Metal).iter().filter(|p| p[2] < 0.02).count()
    };
    assert!(foot(Mount::Stand) > 0, "a standing TV has no foot");
    assert_eq!(foot(Mount::Wall), 0, "a TV on the wall keeps its foot");
}

#[test]
fn the_old_defects_are_drawn_for_their_mount() {
    // (category, description as the planner writes it, mount)
    for (category, description) in [
        ("mirror", "A DSLR photo of a round mirror"),
        ("mirror", "A DSLR photo of an oval mirror"),
        ("whiteboard", "A DSLR photo of a whiteboard"),
        ("tv", "A DSLR photo of a large flat-screen television"),
        ("full length mirror", ""),
        ("blackboard", ""),
        ("projector screen", ""),
    ] {
        let size = KnowledgeBase::builtin().object(category).unwrap().size;
        let w = waist(category, description, size, Mount::Wall);
        assert!(
            w <= LEGS,
            "{category} \"{description}\" on a wall: waist {w:.2}"
        );
    }
}

/// The mount a category of a planned prompt is drawn with.
fn mount_in(prompt: &str, category: &str) -> Mount {
    let s = plan(prompt);
    assert!(
        s.objects.contains_key(category),
        "{prompt}: no {category} in {:?}",
        keys(&s)
    );
    Mount::in_scene(&s, category)
}

#[test]
fn the_scene_gives_the_mount_and_the_words_choose_the_kind() {
    for (prompt, category, mount) in [
        (
            "a small washroom with a basin, a toilet and a round mirror on the wall",
            "mirror",
            Mount::Wall,
        ),
        (
            "a start-up office with four desks and a whiteboard",
            "whiteboard",
            Mount::Wall,
        ),
        (
            "a seminar room with a whiteboard on wheels and ten chairs",
            "mobile whiteboard",
            Mount::Stand,
        ),
        (
            "a teacher's corner with a rolling whiteboard beside a desk",
            "mobile whiteboard",
            Mount::Stand,
        ),
        (
            "a guest bedroom with a double bed and a tv mounted on the wall",
            "tv",
            Mount::Wall,
        ),
        (
            "a den with a sofa and a tv on a tv stand",
            "tv",
            Mount::Stand,
        ),
        (
            "a dressing room with a cheval mirror beside the wardrobe",
            "standing mirror",
            Mount::Stand,
        ),
        (
            "a hotel corridor with a tall mirror on the wall",
            "full length mirror",
            Mount::Wall,
        ),
        (
            "a quiet teahouse with low tables and paper lanterns",
            "paper lantern",
            Mount::Ceiling,
        ),
    ] {
        assert_eq!(mount_in(prompt, category), mount, "{prompt}: {category}");
    }
    // "a whiteboard on wheels" is no wall whiteboard as well
    let s = plan("a seminar room with a whiteboard on wheels and ten chairs");
    assert!(!s.objects.contains_key("whiteboard"), "{:?}", keys(&s));
}
