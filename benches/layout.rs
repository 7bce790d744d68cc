//! GCP layout time for a 30-object room (a large open-plan living and dining room).
//! `cargo bench --bench layout`; under `cargo test` it runs once as a smoke test.
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{Anchor, ObjectSpec, Relation, RelationKind, SceneSpec, SceneType};
use std::collections::BTreeMap;

fn spec30() -> SceneSpec {
    let mut objects = BTreeMap::new();
    let mut anchors = BTreeMap::new();
    let items: [(&str, u32, [f64; 3], Anchor); 12] = [
        ("sofa", 2, [2.2, 0.95, 0.85], Anchor::Side),
        ("coffee table", 1, [1.1, 0.6, 0.45], Anchor::Center),
        ("armchair", 2, [0.85, 0.85, 0.9], Anchor::Others),
        ("dining table", 1, [1.8, 0.9, 0.75], Anchor::Others),
        ("dining chair", 6, [0.45, 0.5, 0.9], Anchor::Others),
        ("bookshelf", 2, [1.0, 0.35, 1.9], Anchor::Side),
        ("potted plant", 4, [0.5, 0.5, 1.2], Anchor::Corner),
        ("floor lamp", 3, [0.4, 0.4, 1.6], Anchor::Others),
        ("tv stand", 1, [1.6, 0.45, 0.55], Anchor::Side),
        ("tv", 1, [1.3, 0.08, 0.75], Anchor::Others),
        ("side table", 4, [0.5, 0.5, 0.55], Anchor::Others),
        ("rug", 3, [2.0, 1.4, 0.01], Anchor::Others),
    ];
    for (cat, n, size, a) in items {
        objects.insert(
            cat.to_string(),
            ObjectSpec {
                number: n,
                size,
                description: format!("A DSLR photo of a {cat}"),
                rows: 0,
                sizes: vec![],
                on_wall: None,
            },
        );
        for k in 1..=n {
            anchors.insert(format!("{cat}{k}"), a);
        }
    }
    let r = |s: &str, rel, o: &str| Relation {
        subject: s.into(),
        relation: rel,
        object: o.into(),
    };
    use RelationKind::*;
    let mut relations = vec![
        r("coffee table1", Front, "sofa1"),
        r("tv1", Over, "tv stand1"),
        r("tv stand1", Opposite, "sofa1"),
        r("armchair1", Left, "coffee table1"),
        r("armchair2", Right, "coffee table1"),
        r("rug1", Under, "coffee table1"),
        r("rug2", Under, "dining table1"),
        r("side table1", Next, "sofa1"),
        r("side table2", Next, "sofa2"),
        r("floor lamp1", Next, "armchair1"),
    ];
    for k in 1..=6 {
        relations.push(r(&format!("dining chair{k}"), Next, "dining table1"));
    }
    SceneSpec {
        scene_type: SceneType::Indoor,
        scene_text: "an open-plan living and dining room".into(),
        room: None,
        objects,
        anchors,
        relations,
    }
}

fn main() {
    let full = std::env::args().any(|a| a == "--bench");
    let spec = spec30();
    let n = spec.instances().len();
    let runs = if full { 10 } else { 1 };
    let mut times = vec![];
    let mut sat = 0;
    for seed in 0..runs {
        let t = std::time::Instant::now();
        let l = layout(&spec, LayoutOptions::seeded(seed)).expect("valid spec");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        sat += spec.relations.len() - l.unsatisfied.len();
    }
    times.sort_by(f64::total_cmp);
    println!(
        "layout {n} objects, {} relations: median {:.1} ms over {runs} seeds, {:.1}% relations satisfied",
        spec.relations.len(),
        times[times.len() / 2],
        100.0 * sat as f64 / (runs as usize * spec.relations.len()) as f64
    );
}
