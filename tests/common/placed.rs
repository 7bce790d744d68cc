//! Plan-and-lay-out helpers the placement tests share: a prompt planned offline and laid out
//! on a seed, checked valid, and its placed things found by category.
use dreamscene::plan::check::{validity_problems, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject, SceneSpec};

/// The seeds a layout test runs.
pub const SEEDS: std::ops::Range<u64> = 0..3;

/// `prompt` planned offline and laid out on `seed`, with no validity problem.
pub fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    let problems = validity_problems(&l, &plan.spec);
    assert!(problems.is_empty(), "{prompt} seed {seed}: {problems:?}");
    (l, plan.spec)
}

/// The placed things of `category`.
pub fn all<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category)
        .collect()
}

/// Whether `a` stands on `b`: its centre over b's footprint, its bottom on b's top.
pub fn stands_on(a: &PlacedObject, b: &PlacedObject) -> bool {
    let bb = Box2::of(b);
    let q = bb.local([a.position[0], a.position[1]]);
    q[0].abs() <= bb.half[0] + 1e-6
        && q[1].abs() <= bb.half[1] + 1e-6
        && (a.position[2] - (b.position[2] + b.size[2])).abs() < 0.05
}
