//! Places read from what the text names and from the words that name them: curtains are things
//! (a window's pair, a ward bed's privacy curtain), a colour word is no place ("a green velvet
//! sofa" is no village green), a club named after what is played in it is no nightclub, a
//! station platform is outdoors, and a word naming a place (a warehouse, a spare room, a
//! departure gate) or a part that a named thing already is (a bus stop's shelter) is no object.
//! A room the text gave no size grows until its layout takes everything. Prompts of no corpus.
mod reading;
use dreamscene::plan::gcp::{layout_growing, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::SceneType;
use reading::{keys, number, plan};

#[test]
fn curtains_are_window_curtains_or_a_ward_beds_privacy_curtain() {
    let s = plan("a guest bedroom with heavy curtains and a reading chair");
    assert!(s.objects.contains_key("curtain"), "{:?}", keys(&s));
    let p = plan_prompt("a nursery with blackout curtains, a crib and a rocking chair").unwrap();
    assert!(
        p.spec.objects.contains_key("curtain"),
        "{:?}",
        keys(&p.spec)
    );
    assert!(
        !p.understood.unused.iter().any(|w| w.contains("curtain")),
        "{:?}",
        p.understood.unused
    );
    let s = plan("a recovery ward with eight beds, each with a locker and a curtain");
    assert_eq!(number(&s, "privacy curtain"), 8, "{:?}", keys(&s));
    assert_eq!(number(&s, "projector"), 0, "{:?}", keys(&s));
}

#[test]
fn a_nurses_station_and_a_charging_station_are_things_of_their_own() {
    let s = plan("a children's ward with five cots and a nurses' station by the door");
    assert_eq!(number(&s, "nurses station"), 1, "{:?}", keys(&s));
    assert!(!s.objects.contains_key("station"), "{:?}", keys(&s));
    let s = plan("a waiting area at a departure gate with ten chairs and a charging station");
    assert_eq!(number(&s, "charging station"), 1, "{:?}", keys(&s));
    assert!(
        !s.objects.contains_key("station") && !s.objects.contains_key("gate"),
        "{:?}",
        keys(&s)
    );
}

#[test]
fn a_colour_word_before_a_thing_names_no_place() {
    for prompt in [
        "a green leather armchair beside a stone fireplace and a tall bookcase",
        "a green velvet chaise facing a brick fireplace, a brass floor lamp on its right",
    ] {
        let s = plan(prompt);
        assert_eq!(s.scene_type, SceneType::Indoor, "{prompt}");
        for park in [
            "tree",
            "park bench",
            "fountain",
            "flower bed",
            "street lamp",
        ] {
            assert_eq!(number(&s, park), 0, "{prompt}: {:?}", keys(&s));
        }
    }
}

#[test]
fn a_club_named_for_its_game_is_no_nightclub() {
    for prompt in [
        "a backgammon club: three tables with boards, two chairs at each",
        "a book club with a round table, eight chairs and a bookcase",
    ] {
        let s = plan(prompt);
        for club in ["dance floor", "dj booth", "speaker"] {
            assert_eq!(number(&s, club), 0, "{prompt}: {:?}", keys(&s));
        }
        assert!(number(&s, "table") >= 1, "{prompt}: {:?}", keys(&s));
    }
    // a club with nothing before it is still the nightclub
    let s = plan("a club with a dance floor and a bar");
    assert_eq!(number(&s, "dance floor"), 1, "{:?}", keys(&s));
}

#[test]
fn a_station_platform_is_outdoors_and_no_stage() {
    for prompt in [
        "a railway platform with three benches, a vending machine and a clock",
        "a quiet station platform with two benches and a bin",
    ] {
        let s = plan(prompt);
        assert_eq!(s.scene_type, SceneType::Outdoor, "{prompt}");
        assert_eq!(number(&s, "stage"), 0, "{prompt}: {:?}", keys(&s));
        assert!(number(&s, "bench") >= 2, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_place_named_in_passing_is_no_object() {
    let s =
        plan("a studio apartment on the top floor of a converted warehouse, with a bed and a sofa");
    assert_eq!(number(&s, "warehouse"), 0, "{:?}", keys(&s));
    let s = plan("I have a spare room I want to make into a sewing room with a sewing table");
    assert_eq!(number(&s, "spare"), 0, "{:?}", keys(&s));
    assert_eq!(number(&s, "sewing table"), 1, "{:?}", keys(&s));
    let s = plan("a bus stop with a glass shelter, two benches and a bin");
    assert_eq!(number(&s, "shelter"), 0, "{:?}", keys(&s));
    assert_eq!(number(&s, "bus stop"), 1, "{:?}", keys(&s));
}

/// Plans `prompt` and lays it out the way `dreamscene plan` does when the text gives no size.
fn lays_out(prompt: &str, seed: u64) -> Result<[f64; 3], String> {
    let p = plan_prompt(prompt).map_err(|e| e.to_string())?;
    assert!(!p.room_stated, "{prompt}");
    let mut spec = p.spec;
    layout_growing(&mut spec, LayoutOptions::seeded(seed)).map_err(|e| e.to_string())?;
    Ok(spec.room.map_or([0.0; 3], |r| r.size))
}

#[test]
fn a_room_of_no_stated_size_grows_to_take_what_is_named() {
    let prompt =
        "turn the spare room into a small office with a desk, a bookshelf and a whiteboard";
    for seed in 0..3 {
        if let Err(e) = lays_out(prompt, seed) {
            panic!("{prompt} (seed {seed}): {e}");
        }
    }
}

#[test]
fn a_pair_facing_each_other_faces_one_another() {
    use dreamscene::plan::gcp::layout;
    use dreamscene::plan::spec::RelationKind;
    for (prompt, c) in [
        (
            "a snug with two sofas facing each other and a low table between them",
            "sofa",
        ),
        (
            "a reading room with two armchairs facing one another by the fire",
            "armchair",
        ),
        ("a shared study with two desks facing each other", "desk"),
    ] {
        let s = plan(prompt);
        let facing = |r: &&dreamscene::plan::spec::Relation| {
            r.relation == RelationKind::Opposite
                && r.subject == format!("{c}2")
                && r.object == format!("{c}1")
        };
        assert!(
            s.relations.iter().any(|r| facing(&r)),
            "{prompt}: {:?}",
            s.relations
        );
        // the layout turns a pair of sofas to each other (a pair of desks, each with its
        // chair, it does not yet manage)
        if c == "sofa" {
            for seed in 0..3 {
                let l = layout(&s, LayoutOptions::seeded(seed)).unwrap();
                let left = l.unsatisfied.iter().any(|r| facing(&r));
                assert!(!left, "{prompt} (seed {seed}): {:?}", l.unsatisfied);
            }
        }
    }
    // seats at a table face across it as the table has them, not as a pair of their own
    let s = plan("a card room: two tables, two chairs at each table facing each other");
    assert!(
        !s.relations
            .iter()
            .any(|r| r.relation == RelationKind::Opposite
                && r.subject.contains("chair")
                && r.object.contains("chair")),
        "{:?}",
        s.relations
    );
}
