//! Waiting chairs stand along a wall, backs to it, facing the room (a pharmacy's, a salon's,
//! a studio's), where the scene says nothing of them: not scattered mid-floor.
mod common;
use common::placed::{all, lay, SEEDS};
use dreamscene::plan::check::anchor_holds;
use dreamscene::plan::spec::Anchor;

#[test]
fn waiting_chairs_line_the_walls() {
    for (prompt, n) in [
        ("a pharmacy with four waiting chairs and a counter", 4),
        (
            "a tattoo studio with one tattoo chair and three waiting chairs",
            3,
        ),
        (
            "a nail salon with two manicure tables and four waiting chairs",
            4,
        ),
    ] {
        for seed in SEEDS {
            let (l, spec) = lay(prompt, seed);
            let chairs = all(&l, "waiting chair");
            assert_eq!(chairs.len(), n, "{prompt}");
            for c in chairs {
                assert!(
                    anchor_holds(c, Anchor::Side, spec.scene_type, l.room.size),
                    "{prompt} seed {seed}: {} at {:?} yaw {}",
                    c.id,
                    c.position,
                    c.yaw
                );
            }
        }
    }
}
