//! A named table with its own seats is the place's meal table: picnic tables named in a beer
//! garden replace its default bench tables, and the benches that served only those go with
//! them (no loose benches pushed against tables that have their own); the place said alone keeps
//! its bench tables and benches.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneSpec;

fn spec(prompt: &str) -> SceneSpec {
    plan_prompt(prompt)
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
        .spec
}

fn number(s: &SceneSpec, c: &str) -> u32 {
    s.objects.get(c).map_or(0, |o| o.number)
}

#[test]
fn named_picnic_tables_replace_default_bench_tables_and_their_benches() {
    for (prompt, n) in [
        ("a biergarten with five picnic tables and a bar", 5),
        (
            "a beer garden under chestnut trees with eight picnic tables",
            8,
        ),
    ] {
        let s = spec(prompt);
        let keys: Vec<&String> = s.objects.keys().collect();
        assert_eq!(number(&s, "picnic table"), n, "{prompt}: {keys:?}");
        assert_eq!(number(&s, "bench table"), 0, "{prompt}: {keys:?}");
        assert_eq!(number(&s, "beer bench"), 0, "{prompt}: {keys:?}");
    }
    let s = spec("a sunny beer garden");
    assert!(number(&s, "bench table") > 0 && number(&s, "beer bench") > 0);
}
