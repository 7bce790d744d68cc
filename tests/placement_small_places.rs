//! Small places seat fewer: a room the text calls small or tiny keeps the share of its default
//! rows and tables (a media room's theatre seats, a classroom's desks, a cafe's tables) that it
//! keeps of its floor, and is sized for them instead of being grown back to the full place's
//! size; seats the text counts keep their count.
use dreamscene::plan::check::validity_problems;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;

fn planned(prompt: &str) -> SceneSpec {
    plan_prompt(prompt).expect("planned").spec
}

fn count(spec: &SceneSpec, cat: &str) -> u32 {
    spec.objects.get(cat).map_or(0, |o| o.number)
}

fn floor(spec: &SceneSpec) -> f64 {
    let r = spec.room.expect("a room").size;
    r[0] * r[1]
}

#[test]
fn a_small_place_keeps_fewer_default_seats_and_a_smaller_floor() {
    for (full, small, tiny, cat) in [
        (
            "a media room",
            "a small media room",
            "a tiny media room",
            "theater seat",
        ),
        (
            "a classroom",
            "a small classroom",
            "a tiny classroom",
            "school desk",
        ),
        ("a cafe", "a small cafe", "a tiny cafe", "cafe table"),
    ] {
        let (f, s, t) = (planned(full), planned(small), planned(tiny));
        let (nf, ns, nt) = (count(&f, cat), count(&s, cat), count(&t, cat));
        assert!(
            nf > ns && ns >= nt && nt >= 1,
            "{cat}: {nf} in {full:?}, {ns} in {small:?}, {nt} in {tiny:?}"
        );
        assert!(
            floor(&f) > floor(&s) && floor(&s) >= floor(&t),
            "{full:?} {:.1} m², {small:?} {:.1} m², {tiny:?} {:.1} m²",
            floor(&f),
            floor(&s),
            floor(&t)
        );
        for (prompt, spec) in [(small, &s), (tiny, &t)] {
            for seed in 0..3 {
                let l = layout(spec, LayoutOptions::seeded(seed)).expect("laid out");
                assert!(
                    validity_problems(&l, spec).is_empty(),
                    "{prompt} seed {seed}"
                );
            }
        }
    }
}

#[test]
fn seats_the_text_counts_keep_their_count_in_a_small_place() {
    for (prompt, cat, n) in [
        (
            "a small media room with eight theater seats",
            "theater seat",
            8,
        ),
        ("a small classroom with six school desks", "school desk", 6),
    ] {
        let spec = planned(prompt);
        assert_eq!(count(&spec, cat), n, "{prompt}");
    }
}
