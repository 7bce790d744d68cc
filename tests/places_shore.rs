//! Outdoor places and garden buildings drawn from text we did not write that did not read as
//! what they are, each checked on the plan, the environment or an object's parts against the
//! old defect: the sea along a beach was a 16 x 6 m block on one side of the ground (a pool, a
//! canal) with sand all round it; a greenhouse and a potting shed had a house's white plaster
//! walls; a periscope was a thin pale pole shorter than the room with a small head.
//! Host-only, plan, environment and shape only (cheap in a debug build).
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{drawn, of, range, within};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedBy, SceneType};
use dreamscene::scene::env::{
    draft_colours, init_environment, scene_colours, shore_of, EnvOptions, Pattern,
};
use dreamscene::shape::Role;
use dreamscene::splat::cloud::SH_C0;

fn laid(prompt: &str, seed: u64) -> Layout {
    let p = plan_prompt(prompt).unwrap();
    layout(&p.spec, LayoutOptions::seeded(seed)).unwrap()
}

const SEASIDE: [&str; 4] = [
    "a sandy beach with two deckchairs, a windbreak and a rowing boat pulled up",
    "the seashore at noon with a picnic blanket, a cool box and three towels",
    "a little cove beach with a bonfire and a pair of sun loungers",
    "a beach by the ocean with five parasols and a snack kiosk",
];

#[test]
fn the_sea_runs_along_a_whole_side_and_nothing_stands_in_it() {
    for prompt in SEASIDE {
        for seed in 0..3 {
            let l = laid(prompt, seed);
            let sea = l
                .objects
                .iter()
                .find(|o| o.category == "sea")
                .unwrap_or_else(|| panic!("{prompt}: no sea"));
            let [w, d, _] = l.room.size;
            // along a long side (either side of a square ground), the whole of it, its back
            // at the edge, facing the land
            let across = sea.yaw.to_radians().cos().abs() > 0.99;
            let down = sea.yaw.to_radians().sin().abs() > 0.99;
            assert!(
                across || down && (w - d).abs() < 0.01,
                "{prompt} ({seed}): yaw {}",
                sea.yaw
            );
            // (a, b): the sea's axis along its side and the axis out to sea
            let (a, b) = if across { (0, 1) } else { (1, 0) };
            let (len, hd) = (l.room.size[a], 0.5 * l.room.size[b]);
            assert!(
                sea.size[0] >= len - 0.1,
                "{prompt} ({seed}): {:?} in {len}",
                sea.size
            );
            let back = sea.position[b].abs() + 0.5 * sea.size[1];
            assert!(
                (back - hd).abs() < 0.1,
                "{prompt} ({seed}): back at {back} of {hd}"
            );
            assert!(
                sea.position[a].abs() < 0.1,
                "{prompt} ({seed}): {:?}",
                sea.position
            );
            assert_ne!(
                sea.placed_by,
                PlacedBy::Fallback,
                "{prompt} ({seed}): a SIDE met"
            );
            // nothing stands in the water
            let front = sea.position[b].abs() - 0.5 * sea.size[1];
            let toward = sea.position[b].signum();
            for o in l.objects.iter().filter(|o| o.id != sea.id) {
                let r = 0.5 * o.size[0].max(o.size[1]);
                let y = o.position[b] * toward;
                assert!(
                    y - r < front + 0.05 && o.position[a].abs() <= 0.5 * l.room.size[a],
                    "{prompt} ({seed}): {} at {:?} in the sea (front {front})",
                    o.id,
                    o.position
                );
            }
        }
    }
}

#[test]
fn the_ground_past_the_sea_is_water_and_behind_the_beach_sand() {
    for prompt in SEASIDE {
        let l = laid(prompt, 0);
        let shore = shore_of(&l).unwrap_or_else(|| panic!("{prompt}: no shore"));
        assert_eq!(shore.axis, 1, "{prompt}");
        let c = scene_colours(&l, prompt);
        assert_eq!(c.shore, Some(shore), "{prompt}");
        let opts = EnvOptions {
            density: 40.0,
            ..EnvOptions::default()
        };
        let env = init_environment(SceneType::Outdoor, l.room.size, &c, &opts);
        let hd = 0.5 * l.room.size[1];
        let (mut sea, mut land) = ([0usize; 2], [0usize; 2]);
        for (m, dc) in env.floor.means.iter().zip(env.floor.sh.chunks(3)) {
            let rgb = [0, 1, 2].map(|k| 0.5 + SH_C0 * dc[k] as f64);
            let bluish = rgb[2] > rgb[0] + 0.1;
            let y = m[1] as f64 * shore.sign;
            // out past the sea's side, and on beyond the ground's ends along the shore
            if y > hd + 1.0 || (y > shore.edge + 3.0 && m[0].abs() as f64 > l.room.size[0]) {
                sea[usize::from(bluish)] += 1;
            } else if y < -hd - 1.0 {
                land[usize::from(bluish)] += 1;
            }
        }
        assert!(sea[1] > 20 * sea[0].max(1), "{prompt}: sea {sea:?}");
        assert!(land[0] > 20 * land[1].max(1), "{prompt}: land {land:?}");
    }
}

#[test]
fn a_lake_or_a_pool_stays_inside_the_ground_and_no_sea_without_one() {
    for prompt in [
        "a park with a lake, two benches and a willow tree",
        "a hotel pool area with six loungers and a swimming pool",
        "a garden with a pond and a bench",
    ] {
        for seed in 0..3 {
            let l = laid(prompt, seed);
            assert_eq!(shore_of(&l), None, "{prompt} ({seed})");
            for o in &l.objects {
                assert!(
                    o.size[0] < l.room.size[0] - 1.0,
                    "{prompt} ({seed}): {} spans {:?}",
                    o.id,
                    o.size
                );
            }
        }
    }
    // a bedroom by the sea is a room with a view, not a beach
    let p = plan_prompt("a bedroom by the sea with a double bed and a wardrobe").unwrap();
    assert_eq!(p.spec.scene_type, SceneType::Indoor);
    let l = layout(&p.spec, LayoutOptions::seeded(0)).unwrap();
    assert_eq!(shore_of(&l), None);
}

#[test]
fn a_greenhouse_is_glazed_and_a_shed_is_boarded() {
    let c = |t: &str| draft_colours(SceneType::Indoor, t);
    for t in [
        "a greenhouse full of tomato plants and a potting bench",
        "a victorian glasshouse with ferns on staging",
    ] {
        let g = c(t);
        assert_eq!(g.wall_pattern, Pattern::Panes, "{t}: glass walls");
        assert_eq!(g.ceiling_pattern, Pattern::Panes, "{t}: a glass roof");
        // bright glass with light bars, not white plaster
        let pane = dreamscene::scene::env::shade(g.wall, Pattern::Panes, 0.35, 0.6, 0.5, 1);
        let bar = dreamscene::scene::env::shade(g.wall, Pattern::Panes, 0.005, 0.6, 0.5, 1);
        assert!(pane[1] > pane[0], "{t}: greenish glass {pane:?}");
        assert!(
            bar[0] > pane[0] + 0.05,
            "{t}: a light frame bar {bar:?} vs {pane:?}"
        );
    }
    for t in [
        "a potting shed with a workbench and clay pots",
        "a cosy boathouse with two rowing boats",
        "a wooden sauna with two benches",
        "a log cabin in the woods with a wood stove",
        "a ski chalet with bunk beds",
    ] {
        let s = c(t);
        assert_eq!(s.wall_pattern, Pattern::Boards, "{t}: timber walls");
        assert!(s.wall[0] < 0.85, "{t}: not white {:?}", s.wall);
    }
    assert_eq!(c("a living room with a sofa").wall_pattern, Pattern::Plain);
}

#[test]
fn a_periscope_is_a_stout_tube_with_a_wide_head_and_handles_at_eye_height() {
    let size = [0.7, 0.5, 2.5];
    let s = drawn("periscope", size, 0);
    let tube = within(&of(&s, Role::Metal), |p| p[2] > 0.3 && p[2] < 0.8);
    let (x0, x1) = range(&tube, 0);
    assert!(x1 - x0 >= 0.12, "a stout tube: {:.2} m", x1 - x0);
    let (_, top) = range(&of(&s, Role::Metal), 2);
    assert!(top >= 0.95 * size[2], "up to the ceiling: {top:.2}");
    let head = of(&s, Role::Body);
    let (hx0, hx1) = range(&head, 0);
    let (hz0, hz1) = range(&head, 2);
    assert!(hx1 - hx0 >= 2.0 * (x1 - x0), "a head wider than the tube");
    assert!(
        hz0 > 1.0 && hz1 < 1.8,
        "the head at eye height: {hz0:.2}-{hz1:.2}"
    );
    let grips = of(&s, Role::Handle);
    let (gx0, gx1) = range(&grips, 0);
    assert!(
        gx1 - gx0 > 0.5,
        "handles out at both sides: {:.2}",
        gx1 - gx0
    );
}
