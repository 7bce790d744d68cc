//! A parasol set over a table shelters the table's seats: they stand round the table under its
//! canopy (the canopy is no obstacle to them), every one of them, and no lounger is brought
//! under a parasol that is over a table. Prompts of no corpus.
use dreamscene::plan::check::{relations_unsatisfied, validity_problems};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::RelationKind;

#[test]
fn the_seats_at_a_table_under_a_parasol_all_stand_round_it() {
    for (prompt, seats) in [
        (
            "a garden terrace with an outdoor table, four chairs and a big parasol over the table",
            4,
        ),
        (
            "a roof terrace: a table and six chairs with a parasol over the table",
            6,
        ),
        (
            "back patio, table for six, umbrella over the table, a grill",
            6,
        ),
    ] {
        let plan = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let spec = &plan.spec;
        let over: Vec<_> = spec
            .relations
            .iter()
            .filter(|r| r.relation == RelationKind::Over && r.subject.contains("umbrella"))
            .collect();
        assert_eq!(over.len(), 1, "{prompt}: {:?}", spec.relations);
        let (parasol, table) = (&over[0].subject, &over[0].object);
        let at: Vec<&String> = spec
            .relations
            .iter()
            .filter(|r| &r.object == table && r.relation == RelationKind::Around)
            .map(|r| &r.subject)
            .collect();
        assert_eq!(at.len(), seats, "{prompt}: {:?}", spec.relations);
        // nothing but the table's seats goes under it
        for r in spec
            .relations
            .iter()
            .filter(|r| &r.object == parasol && r.relation == RelationKind::Under)
        {
            assert!(
                at.contains(&&r.subject),
                "{prompt}: {} under the parasol",
                r.subject
            );
        }
        for seed in [0, 1] {
            let l = layout(spec, LayoutOptions::seeded(seed)).expect("laid out");
            assert!(validity_problems(&l, spec).is_empty(), "{prompt}");
            let left: Vec<_> = relations_unsatisfied(&l.objects, &spec.relations)
                .into_iter()
                .filter(|r| r.object == *table)
                .collect();
            assert!(left.is_empty(), "{prompt} (seed {seed}): {left:?}");
        }
    }
}
