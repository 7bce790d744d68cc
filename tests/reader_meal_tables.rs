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

/// A table "for N" is the size furnishers give a table for that many (kb/seating.txt), larger
/// than the usual six-seater for eight or ten, smaller for two or four: eight chairs were
/// squeezed round a 1.8 m table.
#[test]
fn a_table_for_n_is_sized_for_n() {
    let long = |prompt: &str| {
        let s = dreamscene::plan::offline::plan_prompt(prompt)
            .unwrap_or_else(|e| panic!("{prompt}: {e}"))
            .spec;
        let o = &s.objects["dining table"];
        o.size[0].max(o.size[1])
    };
    for (prompt, lo, hi) in [
        (
            "a family dining room with a table for eight and a dresser",
            2.1,
            2.5,
        ),
        (
            "a farmhouse kitchen, a big table for ten in the middle",
            2.5,
            3.0,
        ),
        ("a dining nook with a table for four", 1.0, 1.3),
        (
            "a little dining room with a table for two by the window",
            0.7,
            0.9,
        ),
    ] {
        let l = long(prompt);
        assert!((lo..=hi).contains(&l), "{prompt}: {l} m long");
    }
}
