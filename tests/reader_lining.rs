//! Things that line the walls: a plural the text gives no number for, said to stand along every
//! wall, along one or down both sides, or lining the place ("a corridor lined with lockers"), is
//! as many as those walls take in the room, not the two a bare plural stands for; a count the
//! text gives stays; "on both sides" of a bed, paintings "on the walls" and what lines a shelf
//! (its contents) are not linings. A size said before the place's name is the room's.
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{RelationKind, SceneSpec};

fn spec(prompt: &str) -> SceneSpec {
    plan_prompt(prompt)
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
        .spec
}

fn number(s: &SceneSpec, c: &str) -> u32 {
    s.objects.get(c).map_or(0, |o| o.number)
}

#[test]
fn a_lining_is_as_many_as_its_walls_take() {
    for (prompt, c, least) in [
        (
            "a gym changing room lined with lockers on both sides",
            "locker",
            4,
        ),
        (
            "a secondhand bookshop with bookcases along all four walls and a sofa",
            "bookshelf",
            6,
        ),
        (
            "a hospital corridor with chairs along one wall",
            "dining chair",
            5,
        ),
        (
            "a museum gallery with glass cases along the walls",
            "display case",
            4,
        ),
        (
            "a fire station with a row of lockers along the back wall and a fire engine",
            "locker",
            5,
        ),
    ] {
        let s = spec(prompt);
        let keys: Vec<&String> = s.objects.keys().collect();
        assert!(
            number(&s, c) >= least,
            "{prompt}: {} {c} in {keys:?}",
            number(&s, c)
        );
        // a row along the wall is a run on it, never a row standing in the room
        assert_eq!(s.objects[c].rows, 0, "{prompt}");
    }
}

#[test]
fn a_longer_room_takes_more() {
    let short = spec("a 6 m by 3 m corridor lined with lockers");
    let long = spec("a 14 m by 3 m corridor lined with lockers");
    assert!(
        number(&long, "locker") > number(&short, "locker") + 4,
        "{} then {}",
        number(&short, "locker"),
        number(&long, "locker")
    );
    // one wall takes about half of what both sides take
    let one = spec("a 12 m by 3 m corridor with lockers along one wall");
    let both = spec("a 12 m by 3 m corridor with lockers down both sides");
    let (a, b) = (number(&one, "locker"), number(&both, "locker"));
    assert!(a >= 5 && b >= 2 * a - 1 && b <= 2 * a + 1, "{a} then {b}");
    // one wall's run stands each beside the one before
    let runs = one
        .relations
        .iter()
        .filter(|r| r.relation == RelationKind::Next && r.subject.starts_with("locker"))
        .count();
    assert_eq!(runs as u32, a - 1);
}

#[test]
fn counts_given_and_other_phrases_are_not_linings() {
    for (prompt, c, n) in [
        (
            "a study with four bookcases along the walls",
            "bookshelf",
            4,
        ),
        (
            "a bedroom with matching nightstands on both sides of the bed",
            "nightstand",
            2,
        ),
        ("a hallway with paintings on the walls", "painting", 2),
        (
            "a master bedroom with nightstands on both sides",
            "nightstand",
            2,
        ),
    ] {
        let s = spec(prompt);
        assert_eq!(number(&s, c), n, "{prompt}");
    }
    // what lines a shelf is its contents: the shelves stay as said
    let s = spec("a pantry with shelves lined with jars");
    let shelves: u32 = s
        .objects
        .iter()
        .filter(|(k, _)| k.contains("shelf"))
        .map(|(_, o)| o.number)
        .sum();
    assert!(shelves <= 3, "{:?}", s.objects.keys());
}

#[test]
fn a_size_before_the_places_name_is_the_rooms() {
    // the size said before "corridor" is the corridor's, never the lockers' after it
    for prompt in [
        "a 12 m by 3 m corridor with lockers",
        "a 5 by 4 metre playroom with teddy bears",
    ] {
        let s = spec(prompt);
        let room = s.room.expect("a room").size;
        assert!(room[0] * room[1] <= 37.0, "{prompt}: {room:?}");
        for (c, o) in &s.objects {
            assert!(o.size[0] < 3.0, "{prompt}: {c} {:?}", o.size);
        }
    }
}
