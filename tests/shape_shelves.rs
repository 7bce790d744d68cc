//! Shelves that hold what the place sells, and the stands of printed matter: a shop's shelf
//! shows its own goods (bread, packs, medicine boxes, toys, boxes…) in its own colours, never
//! book spines; a magazine stand shows covers face-out on sloped ledges; a file rack's slots
//! step up to the back; a hood dryer chair has its hood over the seat. Host-only, about a second.
#![allow(clippy::unwrap_used, reason = "tests")]
mod common;
use common::samples::{of, range};
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{
    archetype_of, build, goods_of, goods_rows, parts, Goods, Primitive, Role, ShapeOptions,
};
use dreamscene::splat::cloud::SH_C0;
use rand::SeedableRng;

fn size(category: &str) -> [f64; 3] {
    KnowledgeBase::builtin().object(category).unwrap().size
}

/// Book-like parts: upright boxes of the `Books` role, narrow and at least 2.5 times as tall
/// as wide and over 14 cm tall (a spine seen from the front; a basket's side wall is lower).
fn spines(category: &str) -> usize {
    parts(category, size(category))
        .unwrap()
        .iter()
        .filter(|p| p.role == Role::Books)
        .filter(|p| match &p.prim {
            Primitive::Cuboid { half, .. } => {
                half[0] < 0.03 && half[2] > 2.5 * half[0] && half[2] > 0.07
            }
            _ => false,
        })
        .count()
}

/// The share of a drafted object's Gaussians whose colour is a strong blue or purple (blue
/// well above red), as book spines and cloth bindings have and bread never does.
fn blue_share(category: &str, description: &str) -> f64 {
    let g = build(
        category,
        size(category),
        description,
        &ShapeOptions {
            gaussians: Some(20_000),
            seed: 3,
            variant: 0,
            mount: None,
        },
    )
    .unwrap();
    let rgb: Vec<[f64; 3]> =
        g.sh.chunks_exact(3)
            .map(|c| [0, 1, 2].map(|i| c[i] as f64 * SH_C0 + 0.5))
            .collect();
    rgb.iter().filter(|c| c[2] - c[0] > 0.15).count() as f64 / rgb.len() as f64
}

#[test]
fn the_goods_table_names_known_categories_and_kinds() {
    let (rows, bad) = goods_rows();
    assert!(
        bad.is_empty(),
        "shelf_goods.txt lines that do not parse: {bad:?}"
    );
    let kb = KnowledgeBase::builtin();
    for (c, _) in &rows {
        assert!(
            kb.object(c).is_some(),
            "shelf_goods.txt: `{c}` is no category"
        );
    }
    assert!(rows.len() >= 15, "{} rows", rows.len());
}

#[test]
fn shop_shelves_hold_their_goods_and_bookshelves_keep_books() {
    let shops = [
        ("bakery shelf", Goods::Loaves),
        ("display shelf", Goods::Groceries),
        ("pharmacy shelf", Goods::Medicine),
        ("toy shelf", Goods::Toys),
        ("storage shelf", Goods::Boxes),
        ("metal shelving", Goods::Boxes),
        ("potion shelf", Goods::Bottles),
        ("walk-in closet shelves", Goods::Clothes),
        ("cubby shelf", Goods::Baskets),
        ("cube shelf", Goods::Baskets),
        ("bowling ball rack", Goods::Balls),
    ];
    for (c, g) in shops {
        assert_eq!(goods_of(c), Some(g), "{c}");
        assert_eq!(spines(c), 0, "{c} ({}) shows book spines", archetype_of(c));
    }
    for c in ["bookshelf", "library shelf", "corner shelf"] {
        assert_eq!(goods_of(c), Some(Goods::Books), "{c}");
        assert!(spines(c) > 20, "{c}: {} spines", spines(c));
    }
    assert_eq!(goods_of("wall shelf"), Some(Goods::Books));
    // A shelf the table does not list holds what its archetype holds.
    assert_eq!(goods_of("pallet rack"), Some(Goods::Boxes));
}

#[test]
fn a_bakery_shelf_is_drawn_in_crust_colours_not_the_book_palette() {
    let bakery = blue_share("bakery shelf", "bakery shelf with bread");
    let books = blue_share("bookshelf", "tall wooden bookshelf filled with books");
    assert!(bakery < 0.005, "bakery shelf: {:.3} of it blue", bakery);
    assert!(books > 0.02, "bookshelf: {:.3} of it blue", books);
    // Each kind's goods have their own colours.
    for g in Goods::ALL.into_iter().filter(|g| *g != Goods::Books) {
        assert_ne!(g.palette(), Goods::Books.palette(), "{}", g.name());
    }
}

/// Whether a part is a box tilted back about x by `lo`..`hi` radians.
fn tilted(p: &dreamscene::shape::Part, lo: f64, hi: f64) -> bool {
    match &p.prim {
        // The box's up axis (third column) leans towards -y by the tilt.
        Primitive::Cuboid { rot, .. } => {
            let a = (-rot[1][2]).atan2(rot[2][2]);
            (lo..=hi).contains(&a)
        }
        _ => false,
    }
}

#[test]
fn a_magazine_stand_shows_covers_face_out_on_sloped_ledges() {
    let ps = parts("magazine stand", size("magazine stand")).unwrap();
    let covers: Vec<_> = ps
        .iter()
        .filter(|p| p.role == Role::Books && tilted(p, 0.15, 0.5))
        .filter(|p| matches!(&p.prim, Primitive::Cuboid { half, .. } if half[0] > 0.05 && half[2] > 0.05))
        .collect();
    assert!(covers.len() >= 8, "{} face-out covers", covers.len());
    let ledges = ps
        .iter()
        .filter(|p| p.role == Role::Frame && tilted(p, 0.15, 0.5))
        .count();
    assert!(ledges >= 3, "{ledges} sloped ledges");
    // Tiers step back as they rise: the highest cover stands behind the lowest.
    let at = |p: &&dreamscene::shape::Part| match &p.prim {
        Primitive::Cuboid { centre, .. } => *centre,
        _ => unreachable!(),
    };
    let low =
        covers.iter().map(at).fold(
            [0.0, 0.0, f64::INFINITY],
            |a, c| if c[2] < a[2] { c } else { a },
        );
    let high = covers
        .iter()
        .map(at)
        .fold([0.0, 0.0, f64::NEG_INFINITY], |a, c| {
            if c[2] > a[2] {
                c
            } else {
                a
            }
        });
    assert!(
        high[1] < low[1] - 0.05,
        "top tier at y {:.2}, bottom at {:.2}",
        high[1],
        low[1]
    );
    assert_eq!(archetype_of("newsstand rack"), "magazine_stand");
}

#[test]
fn a_file_rack_holds_folders_in_slots_rising_to_the_back() {
    let ps = parts("file rack", size("file rack")).unwrap();
    let folders: Vec<([f64; 3], [f64; 3])> = ps
        .iter()
        .filter(|p| p.role == Role::Books)
        .filter_map(|p| match &p.prim {
            Primitive::Cuboid { centre, half, .. } => Some((*centre, *half)),
            _ => None,
        })
        .collect();
    assert!(folders.len() >= 3, "{} folders", folders.len());
    let mut by_y = folders.clone();
    by_y.sort_by(|a, b| b.0[1].total_cmp(&a.0[1]));
    for w in by_y.windows(2) {
        assert!(
            w[1].0[2] + w[1].1[2] > w[0].0[2] + w[0].1[2],
            "a folder further back is not taller: {by_y:?}"
        );
    }
}

#[test]
fn a_hood_dryer_chair_has_its_hood_over_the_seat() {
    let s = size("hair dryer chair");
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let mut pts = vec![];
    for p in parts("hood dryer", s).unwrap() {
        let mut out = vec![];
        p.prim.sample(0.01, &mut rng, &mut out);
        pts.extend(out.iter().map(|o| (o.pos, p.role)));
    }
    let hood = of(&pts, Role::Body);
    let seat = [of(&pts, Role::Upholstery), of(&pts, Role::Cushion)].concat();
    assert!(!hood.is_empty() && !seat.is_empty());
    let (hood_lo, _) = range(&hood, 2);
    let (_, seat_hi) = range(&seat, 2);
    assert!(hood_lo > 0.9, "hood reaches down to {hood_lo:.2} m");
    assert!(
        seat_hi < hood_lo,
        "seat {seat_hi:.2} m, hood from {hood_lo:.2} m"
    );
    // Over the chair, in front of the column at its back.
    let (y0, y1) = range(&hood, 1);
    assert!(
        y0 > -s[1] / 2.0 && 0.5 * (y0 + y1) > -s[1] / 2.0 + 0.15,
        "hood y {y0:.2}..{y1:.2}"
    );
}
