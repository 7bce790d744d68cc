//! One row said along one wall ("six washing machines in a row along one wall") is a run
//! standing against that wall, each beside the one before, not a block of rows out in the
//! room with a band kept before it, in a room with a wall long enough for it. Prompts of no
//! corpus.
use dreamscene::plan::check::{relations_unsatisfied, validity_problems, wall_distances, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;

#[test]
fn a_row_said_along_one_wall_stands_against_it() {
    for (prompt, what, n) in [
        (
            "a home gym with four treadmills in a row along one wall",
            "treadmill",
            4,
        ),
        (
            "a utility room, three washing machines in a row against the back wall",
            "washing machine",
            3,
        ),
        // a room sized by floor area alone has no wall for nine: the room takes the run
        (
            "a dentist's waiting room, a row of nine chairs along one wall, a fish tank",
            "waiting chair",
            9,
        ),
    ] {
        let plan = plan_prompt(prompt).expect(prompt);
        let l = layout(&plan.spec, LayoutOptions::seeded(0)).expect(prompt);
        assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
        let room = l.room.size;
        let row: Vec<_> = l.objects.iter().filter(|o| o.category == what).collect();
        assert_eq!(row.len(), n, "{prompt}");
        for o in &row {
            let near = wall_distances(&Box2::of(o), room)
                .into_iter()
                .fold(f64::INFINITY, f64::min);
            assert!(near < 0.15, "{prompt}: {} is {near:.2} m off a wall", o.id);
        }
        // along one wall: all at one distance across it
        let (xs, ys): (Vec<f64>, Vec<f64>) =
            row.iter().map(|o| (o.position[0], o.position[1])).unzip();
        let spread = |v: &[f64]| {
            v.iter().cloned().fold(f64::MIN, f64::max) - v.iter().cloned().fold(f64::MAX, f64::min)
        };
        assert!(
            spread(&xs).min(spread(&ys)) < 0.05,
            "{prompt}: {xs:?} {ys:?}"
        );
        let left = relations_unsatisfied(&l.objects, &plan.spec.relations);
        assert!(
            left.iter().all(|r| !r.subject.starts_with(what)),
            "{prompt}: {left:?}"
        );
    }
}
