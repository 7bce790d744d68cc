//! Chairs the text sets out in rows are an audience: a meeting place's default table, which they
//! would have sat round, is left out, and no relation to it is left unsatisfied.
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;

#[test]
fn chairs_in_rows_leave_the_default_table_they_would_sit_round() {
    for (prompt, chairs) in [
        ("a meeting room with twenty chairs in rows", 20),
        ("a boardroom with 24 chairs in four rows of six", 24),
        (
            "a conference room where thirty chairs stand in rows before the screen",
            30,
        ),
    ] {
        let plan = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let spec = &plan.spec;
        let n = |c: &str| spec.objects.get(c).map_or(0, |o| o.number);
        assert_eq!(
            n("conference table"),
            0,
            "{prompt}: {:?}",
            spec.objects.keys()
        );
        let seats: u32 = spec
            .objects
            .iter()
            .filter(|(c, _)| c.ends_with("chair"))
            .map(|(_, o)| o.number)
            .sum();
        assert_eq!(seats, chairs, "{prompt}");
        for seed in 0..3 {
            let l = layout(spec, LayoutOptions::seeded(seed))
                .unwrap_or_else(|e| panic!("{prompt} (seed {seed}): {e}"));
            assert!(
                l.unsatisfied.is_empty(),
                "{prompt} (seed {seed}): {:?}",
                l.unsatisfied
            );
        }
    }
}
