//! Everyday requests nobody tuned on: seats said to be for someone take the place of the
//! scene's seats for them, a salon's stations follow the chairs the text counts, a noun that
//! names the room ("a tv room") is no second thing beside the one the text names, and places the
//! knowledge base lacked (a reading nook, a sauna, a harbour) are read as those places.
//! Prompts of no corpus.
mod reading;
use dreamscene::plan::spec::SceneType;
use reading::{keys, number, plan};

#[test]
fn seats_for_visitors_take_the_place_of_the_visitor_chairs() {
    for (prompt, seat, n) in [
        (
            "an office with a desk, a bookcase and two armchairs for visitors",
            "armchair",
            2,
        ),
        ("a study with a desk and a sofa for guests", "sofa", 1),
        (
            "an office with three desks and a bench for the visitors",
            "bench",
            1,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, seat), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "visitor"), 0, "{prompt}: {:?}", keys(&s));
    }
    // a seat for nobody the scene's seats are named for leaves them
    let s = plan("an office with a desk and a sofa for naps");
    assert!(number(&s, "visitor") > 0, "{:?}", keys(&s));
}

#[test]
fn a_seat_for_waiting_takes_the_place_of_the_waiting_chairs() {
    for prompt in [
        "a barbershop with two barber chairs, a mirror in front of each and a sofa for waiting",
        "a hair salon with four styling chairs and a bench for waiting customers",
        "a pharmacy with a counter, shelves and a couch for waiting",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "waiting"), 0, "{prompt}: {:?}", keys(&s));
    }
    // what is no seat keeps the waiting chairs
    let s = plan("a pharmacy with a counter and a water cooler for waiting customers");
    assert!(number(&s, "waiting chair") > 0, "{:?}", keys(&s));
}

#[test]
fn a_salons_stations_follow_the_chairs_the_text_counts() {
    for (prompt, n) in [
        ("a barbershop with two barber chairs", 2),
        ("a hair salon with one styling chair", 1),
        (
            "a barber shop with five barber chairs and a bench for waiting",
            5,
        ),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "barber chair"), n, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "salon station"), n, "{prompt}: {:?}", keys(&s));
    }
    // chairs said at each of something else leave the tables they need
    let s = plan("a call centre with sixteen computers on tables and an office chair at each one");
    assert_eq!(number(&s, "office chair"), 16, "{:?}", keys(&s));
}

#[test]
fn a_noun_naming_the_room_is_no_second_thing() {
    for (prompt, word) in [
        (
            "a tiny tv room with a loveseat, a television on the wall and a bookshelf",
            "tv",
        ),
        ("a piano room with a grand piano and a bench", "piano"),
        ("a tv room with a sofa and a flat screen tv", "tv"),
    ] {
        let s = plan(prompt);
        let n: u32 = s
            .objects
            .iter()
            .filter(|(c, _)| c.as_str() == word || c.ends_with(&format!(" {word}")))
            .map(|(_, o)| o.number)
            .sum();
        assert_eq!(n, 1, "{prompt}: {:?}", keys(&s));
    }
    // alone, the room's noun is still the thing
    let s = plan("a tv room with a sofa");
    assert_eq!(
        s.objects.get("tv").map(|o| o.number),
        Some(1),
        "{:?}",
        keys(&s)
    );
}

#[test]
fn a_reading_nook_is_a_place_with_one_seat() {
    for (prompt, seat) in [
        ("a cozy reading nook", "reading chair"),
        (
            "a reading nook by the window with a beanbag, a floor lamp and a pile of books",
            "bean bag",
        ),
        ("a little reading nook with an armchair", "armchair"),
    ] {
        let s = plan(prompt);
        assert!(s.objects.len() >= 3, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, seat), 1, "{prompt}: {:?}", keys(&s));
        let seats = number(&s, "chair") + number(&s, "bean bag") + number(&s, "sofa");
        assert_eq!(seats, 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "lamp"), 1, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_harbour_is_outdoors() {
    for prompt in [
        "a harbour with a lighthouse",
        "a small fishing harbor with three boats",
        "a marina with a wooden pier and some bollards",
    ] {
        let s = plan(prompt);
        assert_eq!(s.scene_type, SceneType::Outdoor, "{prompt}");
        assert!(number(&s, "boat") >= 1, "{prompt}: {:?}", keys(&s));
    }
    let s = plan("a small fishing harbor with three boats");
    assert_eq!(number(&s, "boat"), 3, "{:?}", keys(&s));
}

#[test]
fn a_sauna_has_its_benches_and_its_stove() {
    for (prompt, benches) in [
        ("a sauna with two wooden benches and a stove", 2),
        ("a small sauna", 2),
        ("a steam room with three benches", 3),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "bench"), benches, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "sauna stove"), 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "kitchen"), 0, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_telly_is_a_tv_and_a_livingroom_a_living_room() {
    for prompt in [
        "a livingroom with a sofa, an armchair and a telly on the wall",
        "a living room with a big telly",
        "a livingroom with a sofa",
    ] {
        let s = plan(prompt);
        assert_eq!(
            number(&s, "tv"),
            1 + number(&s, "tv stand"),
            "{prompt}: {:?}",
            keys(&s)
        );
        assert!(number(&s, "coffee table") == 1, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_tea_set_is_one_thing_on_its_table() {
    for prompt in [
        "a japanese tea house with a low table, four floor cushions around it and a tea set on the table",
        "a living room with a sofa and a teapot on the coffee table",
        "a kitchen with a table and a tea set on it",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "tea set"), 1, "{prompt}: {:?}", keys(&s));
        assert!(!s.objects.contains_key("tea"), "{prompt}: {:?}", keys(&s));
        let on = s.relations.iter().any(|r| {
            r.subject.starts_with("tea set") && format!("{:?}", r.relation) == "Over"
        });
        assert!(on, "{prompt}: {:?}", s.relations);
    }
}

#[test]
fn a_lobby_has_a_reception_desk() {
    for prompt in [
        "a hotel lobby with a reception desk, two sofas and a coffee table between them",
        "a hotel lobby",
        "a hotel lobby with a reception desk and a luggage cart",
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "reception desk"), 1, "{prompt}: {:?}", keys(&s));
    }
}

#[test]
fn a_photo_studio_has_its_backdrop_and_lights() {
    for (prompt, lights) in [
        (
            "a photo studio with a backdrop, two softbox lights and one stool in the middle",
            2,
        ),
        ("a photography studio", 2),
        ("a portrait studio with three studio lights and a chair", 3),
    ] {
        let s = plan(prompt);
        assert_eq!(number(&s, "backdrop"), 1, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "softbox"), lights, "{prompt}: {:?}", keys(&s));
        assert_eq!(number(&s, "easel"), 0, "{prompt}: {:?}", keys(&s));
    }
}
