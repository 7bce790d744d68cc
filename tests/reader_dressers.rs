//! A Welsh (kitchen) dresser is shelves of plates over a cupboard, not a bedroom's chest of
//! drawers: it is its own category, drawn as a dresser that holds crockery, and stands in for a
//! dining room's default china cabinet; a bedroom's dresser stays a chest of drawers.
mod common;
use common::placed::lay;
use dreamscene::shape::archetype_of;

#[test]
fn a_welsh_dresser_holds_plates_and_a_bedroom_dresser_drawers() {
    for prompt in [
        "a cottage dining room with a round table, four chairs and a welsh dresser",
        "a farmhouse kitchen with a pine dresser and a big table",
        "a breakfast room with a farmhouse dresser against the wall",
    ] {
        let (_, spec) = lay(prompt, 0);
        let keys: Vec<&String> = spec.objects.keys().collect();
        assert!(
            spec.objects.contains_key("kitchen dresser"),
            "{prompt}: {keys:?}"
        );
        assert!(
            !spec.objects.contains_key("dresser"),
            "{prompt}: a chest of drawers: {keys:?}"
        );
        assert!(
            !spec.objects.contains_key("china cabinet"),
            "{prompt}: two cabinets: {keys:?}"
        );
    }
    assert_eq!(
        archetype_of("kitchen dresser"),
        archetype_of("china cabinet")
    );
    assert_ne!(archetype_of("kitchen dresser"), archetype_of("dresser"));
    let (_, spec) = lay("a bedroom with a bed and a dresser", 0);
    assert!(spec.objects.contains_key("dresser"));
    assert!(!spec.objects.contains_key("kitchen dresser"));
}
