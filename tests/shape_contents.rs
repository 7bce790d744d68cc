//! What a thing is said to hold, or what its place shows in it, is drawn: a vase of flowers was
//! an empty vase, a bookshop's round table of new releases a bare table, a bookshop's and a
//! museum's display cases were full of a bakery's pastries, and "an old dresser full of plates"
//! in a kitchen was a bedroom's chest of drawers. The planner writes the contents into the
//! description (what the text says, else the place's own: `src/plan/kb/holds.txt`), the shape
//! prior reads them (`src/shape/kb/contents.txt`). Shape- and plan-only, well under a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
mod reading;
use common::samples::{drawn_mounted, of, range};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{parts_mounted, said_goods, Goods, Mount, Primitive, Role};
use reading::{keys, plan};

fn size(category: &str) -> [f64; 3] {
    KnowledgeBase::builtin().object(category).unwrap().size
}

/// Goods samples (the [`Role::Books`] parts) of `category` drawn as `description` says.
fn goods(category: &str, description: &str) -> Vec<[f64; 3]> {
    of(
        &drawn_mounted(category, description, size(category), Mount::Stand, 3),
        Role::Books,
    )
}

/// How many goods parts of `category` as `description` says are round (urns, rings, blooms).
fn round_goods(category: &str, description: &str) -> usize {
    parts_mounted(category, size(category), description, Mount::Stand)
        .unwrap()
        .iter()
        .filter(|p| p.role == Role::Books && matches!(p.prim, Primitive::Revolved { .. }))
        .count()
}

#[test]
fn a_vase_of_flowers_holds_a_bouquet_and_an_empty_one_none() {
    let h = size("vase")[2];
    let full = goods("vase", "A DSLR photo of a ceramic vase full of tulips");
    assert!(
        full.iter().filter(|p| p[2] > 0.7 * h).count() > 50,
        "no blooms above the vase"
    );
    assert!(goods("vase", "A DSLR photo of an empty glass vase").is_empty());
}

#[test]
fn a_table_said_to_hold_books_has_them_on_its_top() {
    for category in ["round table", "dining table", "display table"] {
        let top_said = goods(
            category,
            &format!("A DSLR photo of a wooden {category} full of new releases"),
        );
        assert!(top_said.len() > 100, "{category}: no books on its top");
        let (lo, hi) = range(&top_said, 2);
        assert!(
            lo > 0.8 * size(category)[2] && hi <= size(category)[2] + 1e-6,
            "{category}: books from {lo:.2} to {hi:.2} m"
        );
        assert!(
            goods(category, &format!("A DSLR photo of a wooden {category}")).is_empty(),
            "{category}: goods on a table said to hold none"
        );
    }
}

#[test]
fn a_display_case_shows_what_it_is_said_to_hold() {
    let books = round_goods("display case", "a glass display case full of books");
    let art = round_goods("display case", "a glass display case full of artefacts");
    let jewels = round_goods("display case", "a glass display case full of rings");
    assert_eq!(books, 0, "books are drawn as spines, not rounds");
    assert!(art > 0 && jewels > 0, "artefacts {art}, jewels {jewels}");
    assert!(!goods("display case", "a glass display case full of books").is_empty());
}

#[test]
fn a_place_fills_its_display_cases_and_the_contents_choose_the_kind() {
    let desc = |prompt: &str, category: &str| {
        let s = plan(prompt);
        let o = s.objects.get(category);
        assert!(o.is_some(), "{prompt}: no {category} in {:?}", keys(&s));
        o.unwrap().description.clone()
    };
    for (prompt, category, held) in [
        (
            "a little secondhand bookshop with tall shelves and a display case",
            "display case",
            Goods::Books,
        ),
        (
            "a cosy bookstore with a round table of bestsellers near the window",
            "round table",
            Goods::Books,
        ),
        (
            "a small town museum with three display cases and some paintings",
            "display case",
            Goods::Artefacts,
        ),
        (
            "a breakfast nook with a table and a vase of tulips on it",
            "vase",
            Goods::Flowers,
        ),
    ] {
        let d = desc(prompt, category);
        assert_eq!(said_goods(&d), Some(held), "{prompt}: {category} \"{d}\"");
    }
    // what a dresser is said to hold chooses the kitchen's dresser, not the bedroom's
    for prompt in [
        "a cottage kitchen with a pine table and an old dresser full of plates",
        "a country kitchen with a dresser loaded with dishes against the wall",
    ] {
        let s = plan(prompt);
        assert!(
            s.objects.contains_key("kitchen dresser") && !s.objects.contains_key("dresser"),
            "{prompt}: {:?}",
            keys(&s)
        );
    }
    let s = plan("a bedroom with a double bed and a dresser full of clothes");
    assert!(s.objects.contains_key("dresser"), "{:?}", keys(&s));
}

/// A table said to hold books is covered in them, as a bookshop lays out its new releases:
/// books over most of its top to the edge (it had four small stacks in the middle of a round
/// table), some standing on end among the flat stacks.
#[test]
fn a_table_of_books_is_covered_in_them_some_standing() {
    for (category, description) in [
        ("round table", "a round wooden table piled with paperbacks"),
        ("dining table", "a long oak table covered with bestsellers"),
        ("display table", "a display table stocked with cookbooks"),
    ] {
        let s = size(category);
        let books = goods(category, description);
        // cover: cells of the top (its disc, for a round one) with a book over them
        let cells = 12;
        let (mut top, mut covered) = (0, 0);
        let r = 0.5 * s[0].min(s[1]);
        for i in 0..cells {
            for j in 0..cells {
                let x = -0.5 * s[0] + (i as f64 + 0.5) * s[0] / cells as f64;
                let y = -0.5 * s[1] + (j as f64 + 0.5) * s[1] / cells as f64;
                if category == "round table" && x.hypot(y) > 0.85 * r {
                    continue;
                }
                top += 1;
                let near = |p: &&[f64; 3]| {
                    (p[0] - x).abs() < 0.5 * s[0] / cells as f64
                        && (p[1] - y).abs() < 0.5 * s[1] / cells as f64
                };
                covered += books.iter().any(|p| near(&p)) as usize;
            }
        }
        let share = covered as f64 / top as f64;
        assert!(share > 0.6, "{category}: books over {share:.2} of its top");
        let standing = parts_mounted(category, s, description, Mount::Stand)
            .unwrap()
            .iter()
            .filter(|p| p.role == Role::Books)
            .filter(|p| matches!(p.prim, Primitive::Cuboid { rot, .. } if rot[2][2] < 0.999))
            .count();
        assert!(standing >= 2, "{category}: {standing} books standing");
    }
}
