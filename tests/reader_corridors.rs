//! A corridor is no home's entrance hall: a school's holds lockers, a notice board and a bench,
//! an office's or a hospital's benches and a notice board, none of them a console table, a shoe
//! rack, a coat rack or an umbrella stand, and each is long and narrow; an entrance hall and a
//! hallway keep their furniture.
mod common;
use common::placed::{all, lay};
use dreamscene::plan::check::anchor_holds;
use dreamscene::plan::spec::Anchor;

const HALL: [&str; 4] = ["console table", "shoe rack", "coat rack", "umbrella stand"];

#[test]
fn corridors_are_furnished_as_corridors() {
    for (prompt, wants) in [
        (
            "a school corridor with a water cooler",
            &["locker", "bulletin board"][..],
        ),
        ("a quiet school hallway at night", &["locker"][..]),
        ("an office corridor with a printer", &["bench"][..]),
        ("a hospital corridor", &["bench", "bulletin board"][..]),
        ("a narrow passage with a painting", &["bench"][..]),
    ] {
        let (l, spec) = lay(prompt, 0);
        let has = |c: &str| spec.objects.get(c).is_some_and(|o| o.number > 0);
        for c in wants {
            assert!(
                has(c),
                "{prompt}: no {c}: {:?}",
                spec.objects.keys().collect::<Vec<_>>()
            );
        }
        for c in HALL {
            assert!(!has(c), "{prompt}: an entrance hall's {c}");
        }
        let [w, d, _] = l.room.size;
        assert!(
            w.max(d) >= 2.5 * w.min(d),
            "{prompt}: {w:.1} x {d:.1} m is no corridor"
        );
        for b in all(&l, "bench") {
            assert!(
                anchor_holds(b, Anchor::Side, spec.scene_type, l.room.size),
                "{prompt}: {} stands out in the corridor",
                b.id
            );
        }
    }
    for prompt in ["an entrance hall with a staircase", "a hallway with a rug"] {
        let (_, spec) = lay(prompt, 0);
        assert!(
            HALL.iter()
                .filter(|c| spec.objects.contains_key(**c))
                .count()
                >= 3,
            "{prompt}: {:?}",
            spec.objects.keys().collect::<Vec<_>>()
        );
    }
}
