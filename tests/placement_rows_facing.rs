//! Things the text sets out in rows, all facing one thing ("twelve mats in three rows of four,
//! all facing the instructor's mat", "twenty chairs in four rows facing the lectern"): each row
//! faces it, as an audience does, not each thing its narrow front. Every one of them was
//! reported "unsatisfied" (OPPOSITE asks a thing to stand within the other's width, which only
//! the middle of a row can). Plan and layout only; prompts of no corpus.
use dreamscene::plan::check::relation_holds;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::RelationKind;

#[test]
fn rows_said_to_face_a_thing_face_it_as_rows() {
    for (prompt, rowed, target) in [
        (
            "a yoga room: ten yoga mats in two rows of five facing the teacher's mat",
            "yoga mat",
            "mat",
        ),
        (
            "a small lecture hall with sixteen chairs in four rows facing a lectern",
            "chair",
            "lectern",
        ),
        (
            "a village hall with benches in rows all facing the stage",
            "bench",
            "stage",
        ),
    ] {
        let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
        let rels: Vec<_> = p
            .spec
            .relations
            .iter()
            .filter(|r| r.subject.contains(rowed) && r.object.contains(target))
            .collect();
        assert!(rels.len() >= 4, "{prompt}: {:?}", p.spec.relations);
        assert!(
            rels.iter().all(|r| r.relation == RelationKind::Row),
            "{prompt}: {rels:?}"
        );
        for seed in 0..2 {
            let l = layout(&p.spec, LayoutOptions::seeded(seed)).unwrap();
            let find = |id: &str| l.objects.iter().find(|o| o.id == id).unwrap();
            for r in &rels {
                let (s, o) = (find(&r.subject), find(&r.object));
                assert!(
                    relation_holds(s, r.relation, o),
                    "{prompt} ({seed}): {} does not face {}",
                    s.id,
                    o.id
                );
            }
            assert!(
                !l.unsatisfied.iter().any(|u| u.subject.contains(rowed)),
                "{prompt} ({seed}): {:?}",
                l.unsatisfied
            );
        }
    }
}
