//! Seats the text gives each of a thing sit at that thing, as many at each as said, also where
//! no functional group seats them there ("six lab benches, each with two stools", "manicure
//! tables each with a chair on both sides", "each desk with a monitor and a chair"), and what
//! "each desk with" names comes once per desk. Plan and layout only; prompts of no corpus.
use dreamscene::plan::check::{gap, Box2};
use dreamscene::plan::gcp::{layout_growing, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject};

fn laid_out(prompt: &str, seed: u64) -> Layout {
    // (the room grows to take everything, as `plan` grows it)
    let mut p = plan_prompt(prompt).unwrap_or_else(|e| panic!("{prompt}: {e}"));
    layout_growing(&mut p.spec, LayoutOptions::seeded(seed))
        .unwrap_or_else(|e| panic!("{prompt}: {e}"))
}

fn named<'a>(l: &'a Layout, word: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        // (a word of its name, or the end of one: an armchair is a chair)
        .filter(|o| o.category.split(' ').any(|w| w.ends_with(word)))
        .collect()
}

/// Every host has `k` seats of its own within `within` m (a matching: no seat counts twice).
fn seated(prompt: &str, seed: u64, seat: &str, host: &str, k: usize, within: f64) {
    let l = laid_out(prompt, seed);
    let (seats, hosts) = (named(&l, seat), named(&l, host));
    assert!(!hosts.is_empty(), "{prompt}: no {host}");
    // slot h*k+j is host h's j-th seat; a seat may take a slot of a host within reach
    let near: Vec<Vec<usize>> = seats
        .iter()
        .map(|s| {
            (0..hosts.len() * k)
                .filter(|slot| gap(&Box2::of(s), &Box2::of(hosts[slot / k])) <= within)
                .collect()
        })
        .collect();
    fn augment(
        s: usize,
        near: &[Vec<usize>],
        seen: &mut [bool],
        slot_of: &mut [Option<usize>],
    ) -> bool {
        for &t in &near[s] {
            if !seen[t] {
                seen[t] = true;
                if slot_of[t].is_none_or(|o| augment(o, near, seen, slot_of)) {
                    slot_of[t] = Some(s);
                    return true;
                }
            }
        }
        false
    }
    let mut slot_of = vec![None; hosts.len() * k];
    for s in 0..seats.len() {
        augment(s, &near, &mut vec![false; hosts.len() * k], &mut slot_of);
    }
    for (h, o) in hosts.iter().enumerate() {
        let n = (0..k).filter(|j| slot_of[h * k + j].is_some()).count();
        assert!(
            n == k,
            "{prompt} (seed {seed}): {} has {n} {seat}s of its own within {within} m, want {k}: {:?}",
            o.id,
            seats.iter().chain(&hosts).map(|o| (&o.id, o.position, o.yaw)).collect::<Vec<_>>()
        );
    }
}

#[test]
fn seats_given_each_of_a_thing_sit_at_it() {
    for seed in [0, 5] {
        seated(
            "a woodwork classroom with eight workbenches, each with two stools",
            seed,
            "stool",
            "workbench",
            2,
            0.5,
        );
        seated(
            "a ceramics studio with five pottery wheels, each having a stool",
            seed,
            "stool",
            "wheel",
            1,
            0.5,
        );
        seated(
            "a nail bar with three manicure tables, each with a chair on both sides",
            seed,
            "chair",
            "table",
            2,
            0.5,
        );
        seated(
            "a language lab with ten desks, every desk has a headset and a chair",
            seed,
            "chair",
            "desk",
            1,
            0.5,
        );
        seated(
            "a small ward with three beds, each with a chair",
            seed,
            "chair",
            "bed",
            1,
            0.6,
        );
    }
}

#[test]
fn what_each_named_thing_has_comes_once_per_thing() {
    for (prompt, thing, n) in [
        (
            "a language lab with ten desks, every desk has a headset and a chair",
            "headset",
            10,
        ),
        (
            "a newsroom with twelve desks in three rows, each desk with a monitor and a phone",
            "monitor",
            12,
        ),
    ] {
        let l = laid_out(prompt, 0);
        let got = named(&l, thing).len();
        assert_eq!(got, n, "{prompt}: {got} {thing}s");
    }
}

#[test]
fn tables_of_n_seat_n_and_a_big_bed_has_its_bedside_tables() {
    for seed in [0, 2] {
        seated(
            "a church hall set out for a bingo night with five tables of six and a stage",
            seed,
            "chair",
            "table",
            6,
            0.5,
        );
        seated(
            "a guest suite with a king-size bed with a bedside table on each side and a wardrobe",
            seed,
            "nightstand",
            "bed",
            2,
            0.3,
        );
    }
}
