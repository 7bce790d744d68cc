//! Places and kinds the reader infers: a fantastical version of a place keeps what its kind owns
//! and sheds the modern place's things, a place inside a template's outdoor place is indoors, a
//! potted tree is a potted plant, a named role at a table is no more of the same tables, and a
//! tiny room holds things at floor level without room to walk round them. Prompts of no corpus.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{SceneSpec, SceneType};

fn plan(prompt: &str) -> SceneSpec {
    match plan_prompt(prompt) {
        Ok(p) => p.spec,
        Err(e) => panic!("{prompt}: {e}"),
    }
}

fn number(spec: &SceneSpec, word: &str) -> u32 {
    spec.objects
        .iter()
        .filter(|(c, _)| c.contains(word))
        .map(|(_, o)| o.number)
        .sum()
}

#[test]
fn a_fantastical_place_keeps_what_its_kind_owns() {
    let s = plan("an enchanted ballroom with a harp and a golden clock");
    assert!(number(&s, "dance floor") == 1, "{:?}", s.objects.keys());
    assert!(number(&s, "table") >= 1, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "dj"), 0, "{:?}", s.objects.keys());
    let room = s.room.map_or(0.0, |r| r.size[0] * r.size[1]);
    assert!(room > 40.0, "a ballroom is large: {room} m²");
}

#[test]
fn a_place_inside_an_outdoor_template_is_indoors() {
    let s = plan("a pirate ship's hold with sacks of grain and a lantern");
    assert_eq!(s.scene_type, SceneType::Indoor);
    assert_eq!(
        number(&s, "cannon") + number(&s, "wheel"),
        0,
        "{:?}",
        s.objects.keys()
    );
    let s = plan("a pirate ship deck with a mast");
    assert_eq!(s.scene_type, SceneType::Outdoor);
}

#[test]
fn a_potted_tree_is_a_potted_plant() {
    let s = plan("an office with a desk and a potted palm in the corner");
    let (c, o) = s
        .objects
        .iter()
        .find(|(c, _)| c.contains("plant") || c.contains("palm"))
        .unwrap_or_else(|| panic!("{:?}", s.objects.keys()));
    assert!(o.size[2] < 2.0, "{c}: {:?}", o.size);
}

#[test]
fn a_named_role_at_a_table_is_no_more_of_the_same_tables() {
    let s = plan("a banquet with six round tables and a head table for the couple");
    let round: u32 = s
        .objects
        .iter()
        .filter(|(c, _)| c.contains("round"))
        .map(|(_, o)| o.number)
        .sum();
    assert_eq!(round, 6, "{:?}", s.objects.keys());
    assert_eq!(number(&s, "top table"), 1, "{:?}", s.objects.keys());
}

#[test]
fn a_tiny_room_fits_floor_level_things_without_room_round_them() {
    let s = plan("a tiny loft room with a floor mattress, two floor cushions and a clothes rail");
    let area = s.room.map_or(f64::MAX, |r| r.size[0] * r.size[1]);
    assert!(area <= 10.0, "{area} m²");
}
