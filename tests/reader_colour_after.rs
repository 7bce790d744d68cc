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

#[test]
fn things_in_each_corner_stand_in_the_rooms_corners() {
    // "in each corner" is the room's corners, not those of the thing named just before; the
    // reason quotes the phrase that gave the count
    for prompt in [
        "a den with a couch and a fern in each corner",
        "a study with a desk, a chair and a fern in each corner",
    ] {
        let p = plan_prompt(prompt).unwrap();
        let plant = p
            .understood
            .objects
            .iter()
            .find(|o| o.category == "fern")
            .unwrap_or_else(|| panic!("{prompt}: {:?}", p.understood.objects));
        assert_eq!(plant.count, 4, "{prompt}");
        assert!(
            !plant.why.contains("couch") && !plant.why.contains("chair"),
            "{prompt}: {}",
            plant.why
        );
    }
    // the corners of a table named just before are the table's
    let p = plan_prompt("a games room with a square table and a stool at each corner").unwrap();
    let stools = p.spec.objects.get("stool").map(|o| o.number);
    assert_eq!(stools, Some(4), "{:?}", p.spec.objects.keys());
}
