//! Things that rest on a support and are asked on each side of a piece ("a lamp on each side of
//! the sofa"): each stands on a support flush beside the piece, one a side, none placed by
//! fallback, on every seed.
use dreamscene::plan::check::{gap, validity_problems, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::PlacedBy;

#[test]
fn lamps_either_side_of_a_seat_stand_on_supports_flush_beside_it() {
    for (prompt, piece) in [
        (
            "a living room with a sofa, a lamp on each side of the sofa and a coffee table in front of it",
            "sofa1",
        ),
        (
            "a den with a couch and a table lamp on either side of it",
            "sofa1",
        ),
        ("a bedroom with a lamp on each side of the bed", "bed1"),
    ] {
        let spec = plan_prompt(prompt).expect("planned").spec;
        for seed in 0..3 {
            let l = layout(&spec, LayoutOptions::seeded(seed)).expect("laid out");
            assert!(validity_problems(&l, &spec).is_empty(), "{prompt}");
            let find = |id: &str| l.objects.iter().find(|o| o.id == id).expect(id);
            let p = Box2::of(find(piece));
            let lamps: Vec<_> = l
                .objects
                .iter()
                .filter(|o| o.category.contains("lamp") && o.category != "floor lamp")
                .collect();
            assert_eq!(lamps.len(), 2, "{prompt}");
            let mut sides = vec![];
            for lamp in lamps {
                assert_eq!(lamp.placed_by, PlacedBy::Constraint, "{prompt} seed {seed}: {}", lamp.id);
                assert!(lamp.position[2] > 0.3, "{prompt}: {} stands on the floor", lamp.id);
                let g = gap(&Box2::of(lamp), &p);
                assert!(g <= 0.5, "{prompt} seed {seed}: {} {g:.2} m from {piece}", lamp.id);
                sides.push(p.local([lamp.position[0], lamp.position[1]])[0].signum());
            }
            assert!(sides[0] != sides[1], "{prompt} seed {seed}: both lamps on one side");
        }
    }
}
