//! Colours and materials said after an object's name ("the stool is teal", "a bench painted
//! mustard", "a futon in dark green", "make the wardrobe white") reach that object's
//! description (the shape prior colours from it) and are never reported unused; a colour that
//! names another thing ("a bench, orange cushions") stays with that thing.
use dreamscene::plan::offline::plan_prompt;

fn described(prompt: &str, category: &str) -> (String, Vec<String>) {
    let p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
    let o = p
        .spec
        .objects
        .get(category)
        .unwrap_or_else(|| panic!("{prompt}: no {category} in {:?}", p.spec.objects.keys()));
    (o.description.clone(), p.understood.unused)
}

#[test]
fn a_colour_said_after_the_name_describes_the_object() {
    for (prompt, category, words) in [
        (
            "a bedroom with a stool. The stool is teal.",
            "stool",
            &["teal"][..],
        ),
        (
            "a hallway with a bench painted mustard yellow",
            "bench",
            &["mustard", "yellow"],
        ),
        (
            "a studio flat with a futon in dark green and a lamp",
            "futon",
            &["dark", "green"],
        ),
        (
            "a dining room with a sideboard made of walnut",
            "sideboard",
            &["walnut"],
        ),
        (
            "User: a bedroom with a wardrobe and a bed. User: Make the wardrobe white.",
            "wardrobe",
            &["white"],
        ),
        (
            "a nursery with a rocking chair and a cot. Paint the cot pale pink, please.",
            "crib",
            &["pale", "pink"],
        ),
    ] {
        let (description, unused) = described(prompt, category);
        for w in words {
            assert!(
                description.split(' ').any(|x| x == *w),
                "{prompt}: {category} described as {description:?}"
            );
            assert!(
                !unused.iter().any(|u| u == w),
                "{prompt}: unused {unused:?}"
            );
        }
    }
}

#[test]
fn a_colour_of_the_next_thing_stays_with_it() {
    for (prompt, category, word) in [
        (
            "a porch with a bench, orange cushions and a plant",
            "bench",
            "orange",
        ),
        (
            "a study with a desk in the corner and a black chair",
            "desk",
            "black",
        ),
        ("a bedroom with a bed and a red rug", "bed", "red"),
    ] {
        let (description, _) = described(prompt, category);
        assert!(
            !description.split(' ').any(|x| x == word),
            "{prompt}: {category} described as {description:?}"
        );
    }
}

#[test]
fn another_name_of_the_place_and_a_thing_it_has_are_no_unknown_words() {
    // a second name of the same place right after the first is part of its name
    let p = plan_prompt("a library reading room with a globe and two armchairs").unwrap();
    assert!(
        !p.understood.unused.iter().any(|u| u == "reading"),
        "{:?}",
        p.understood.unused
    );
    // "a basket of socks" in a laundry room is its laundry basket, which the knowledge base has
    let p = plan_prompt("a laundry room with a basket of socks").unwrap();
    assert!(
        !p.notes
            .iter()
            .any(|n| n.contains("not in the knowledge base")),
        "{:?}",
        p.notes
    );
}
