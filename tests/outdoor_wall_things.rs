//! Things hung on a wall where there is no wall: outdoors (a terrace, a garden, a market) the
//! layout puts string lights, a sign or a clock at their mounting height, and they floated
//! there with nothing under them. Outdoors they stand on posts from the ground; indoors they
//! still hang flat on their wall with nothing reaching down. And an open ground's edge is a run
//! its things line ("planters lining the edge" of a terrace), spaced as an open edge is.
//! Host-only: plan and shape only (cheap in a debug build).
#![allow(clippy::unwrap_used, reason = "tests")]
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Anchor, SceneType};
use dreamscene::shape::{build, Mount, ShapeOptions};

fn drawn(category: &str, size: [f64; 3], mount: Mount) -> Vec<[f32; 3]> {
    let opts = ShapeOptions {
        gaussians: Some(6000),
        seed: 1,
        variant: 0,
        mount: Some(mount),
    };
    build(category, size, "", &opts).unwrap().means
}

#[test]
fn outdoors_a_wall_thing_stands_on_posts_from_the_ground() {
    for (prompt, cat) in [
        (
            "a garden party with string lights and a long table",
            "string lights",
        ),
        (
            "a farmers market with a clock and four stalls",
            "wall clock",
        ),
        (
            "a backyard with a dartboard and a picnic table",
            "dartboard",
        ),
    ] {
        let p = plan_prompt(prompt).unwrap();
        assert_eq!(p.spec.scene_type, SceneType::Outdoor, "{prompt}");
        let mount = Mount::in_scene(&p.spec, cat);
        let Mount::Post(cm) = mount else {
            panic!("{prompt}: {cat} is {mount:?}, not on posts");
        };
        let l = layout(&p.spec, LayoutOptions::seeded(0)).unwrap();
        let o = l.objects.iter().find(|o| o.category == cat).unwrap();
        let foot = o.position[2] - 0.5 * o.size[2];
        let drop = f64::from(cm) / 100.0;
        assert!(
            (foot - drop).abs() < 0.05 || (o.position[2] - drop).abs() < 0.05,
            "{prompt}: {cat} hangs {drop} m up, laid at {:?}",
            o.position
        );
        let means = drawn(cat, o.size, mount);
        // the posts reach the ground, the drop below its own foot
        let low = means.iter().map(|m| m[2]).fold(f32::INFINITY, f32::min);
        assert!(
            (f64::from(low) + drop).abs() < 0.05,
            "{prompt}: lowest point {low} for a drop of {drop}"
        );
        // something at every height from the ground up to it (no gap in the air)
        let steps = (drop / 0.2).ceil() as usize;
        for k in 0..steps {
            let z = -drop + 0.2 * k as f64;
            assert!(
                means.iter().any(|m| (f64::from(m[2]) - z).abs() < 0.1),
                "{prompt}: nothing holds it up at {z:.2} m below its foot"
            );
        }
        // a wide thing is held at both ends, a narrow one in the middle
        let posts: Vec<f32> = means
            .iter()
            .filter(|m| f64::from(m[2]) < -0.5 * drop)
            .map(|m| m[0])
            .collect();
        let (x0, x1) = posts
            .iter()
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), x| {
                (a.min(*x), b.max(*x))
            });
        if o.size[0] > 1.2 {
            assert!(
                x0 < -0.4 * o.size[0] as f32 && x1 > 0.4 * o.size[0] as f32,
                "{prompt}: {x0}..{x1}"
            );
        } else {
            assert!(
                x0.abs() < 0.2 && x1.abs() < 0.2,
                "{prompt}: one post {x0}..{x1}"
            );
        }
    }
}

#[test]
fn indoors_a_wall_thing_hangs_with_nothing_reaching_down() {
    let p = plan_prompt("a kitchen with a clock on the wall").unwrap();
    assert_eq!(Mount::in_scene(&p.spec, "clock"), Mount::Wall);
    let means = drawn("clock", [0.35, 0.06, 0.35], Mount::Wall);
    let low = means.iter().map(|m| m[2]).fold(f32::INFINITY, f32::min);
    assert!(low > -0.01, "a hung clock reaches down to {low}");
}

#[test]
fn an_open_edge_is_lined_with_things_spaced_along_it() {
    let prompt = "a rooftop terrace with two bistro tables and planters lining the edge";
    let p = plan_prompt(prompt).unwrap();
    let n = p.spec.objects.get("planter").map_or(0, |o| o.number);
    assert!((6..=20).contains(&n), "{prompt}: {n} planters");
    let l = layout(&p.spec, LayoutOptions::seeded(0)).unwrap();
    let [w, d, _] = l.room.size;
    let near_edge = l
        .objects
        .iter()
        .filter(|o| o.category == "planter")
        .filter(|o| {
            let r = 0.5 * o.size[0].max(o.size[1]) + 0.3;
            0.5 * w - o.position[0].abs() < r || 0.5 * d - o.position[1].abs() < r
        })
        .count();
    assert_eq!(near_edge as u32, n, "{prompt}: every planter at the edge");
    assert!(p.spec.anchors.values().any(|a| *a == Anchor::Side));
    // the edge of a table is no wall: candles along it are not a lining
    let p = plan_prompt("a dining room with candles along the edge of the table").unwrap();
    let n = p.spec.objects.get("candle").map_or(0, |o| o.number);
    assert!(n <= 4, "{n} candles");
}
