//! Tables laid for the people said: a table for fourteen is long enough for fourteen of the
//! place's own seats (office chairs are wider than the 0.6 m a furnisher gives a place), a long
//! table said in a place of round ones is long, and the round tables a reception names beside
//! its top table are seated as the place seats them. Prompts of no corpus.
use dreamscene::plan::check::{relations_unsatisfied, validity_problems};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, ObjectSpec, RelationKind, SceneSpec};

/// Plans and lays out `prompt`; the layout is valid and every seat stands where it is asked
/// (none pushed off its table).
fn lay(prompt: &str) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(0)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    let left = relations_unsatisfied(&l.objects, &plan.spec.relations);
    assert!(left.is_empty(), "{prompt}: {left:?}");
    (l, plan.spec)
}

/// The table categories of `spec` people sit at (not a side table).
fn tables(spec: &SceneSpec) -> Vec<(&String, &ObjectSpec)> {
    spec.objects
        .iter()
        .filter(|(c, _)| c.ends_with("table") && !c.contains("side"))
        .collect()
}

/// The seats standing at or around `table`'s instances.
fn seated(spec: &SceneSpec, table: impl Fn(&str) -> bool) -> usize {
    spec.relations
        .iter()
        .filter(|r| table(&r.object))
        .filter(|r| {
            matches!(
                r.relation,
                RelationKind::Around | RelationKind::At | RelationKind::AtBack
            )
        })
        .count()
}

#[test]
fn a_table_for_many_is_long_enough_for_the_places_seats() {
    for (prompt, people) in [
        ("a company boardroom with a table for 16", 16),
        ("a conference room, one big table for fourteen people", 14),
    ] {
        let (_, spec) = lay(prompt);
        let (table, o) = tables(&spec)[0];
        assert_eq!(
            seated(&spec, |t| t.starts_with(table.as_str())),
            people,
            "{prompt}"
        );
        assert!(o.size[0] >= 2.5 * o.size[1], "{prompt}: {:?}", o.size);
    }
}

#[test]
fn a_long_table_said_in_a_place_of_round_ones_is_long() {
    let (_, spec) = lay("a gala dinner hall with a single long table for 24 guests");
    let long: Vec<_> = spec
        .objects
        .iter()
        .filter(|(c, o)| c.contains("table") && o.size[0] >= 2.0 * o.size[1])
        .filter(|(c, _)| !c.contains("buffet"))
        .collect();
    assert_eq!(long.len(), 1, "{:?}", spec.objects);
    assert_eq!(long[0].1.number, 1);
    assert!(
        !spec.objects.keys().any(|c| c.starts_with("round")),
        "{:?}",
        spec.objects.keys()
    );
    assert_eq!(seated(&spec, |t| t.starts_with(long[0].0.as_str())), 24);
}

#[test]
fn round_tables_named_beside_a_top_table_are_seated_as_the_place_seats_them() {
    for (prompt, tables) in [
        ("a wedding breakfast: a top table and nine round tables", 9),
        ("an awards dinner with a head table and six round tables", 6),
    ] {
        let (_, spec) = lay(prompt);
        let round: u32 = spec
            .objects
            .iter()
            .filter(|(c, _)| c.starts_with("round"))
            .map(|(_, o)| o.number)
            .sum();
        assert_eq!(round, tables, "{prompt}: {:?}", spec.objects.keys());
        let at_round = seated(&spec, |t| t.starts_with("round"));
        assert!(at_round >= 6 * tables as usize, "{prompt}: {at_round}");
    }
}

#[test]
fn a_meal_for_a_party_at_home_lays_its_one_table_for_them() {
    for (prompt, people) in [
        ("thanksgiving dinner for eleven", 11),
        ("a supper party for 9", 9),
    ] {
        let (_, spec) = lay(prompt);
        let tables = tables(&spec);
        assert_eq!(tables.len(), 1, "{prompt}: {:?}", spec.objects.keys());
        assert_eq!(tables[0].1.number, 1, "{prompt}");
        assert_eq!(
            seated(&spec, |t| t.starts_with(tables[0].0.as_str())),
            people
        );
    }
}
