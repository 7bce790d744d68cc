//! Seats said to face a part of a planned thing ("barber chairs facing mirrors" in a salon) sit
//! one at each station that has it, turned to it, and the mirrors asked hang on the wall above
//! the stations (so the chairs face them); mirrors asked as things of their own stay.
use dreamscene::plan::check::{
    facing_footprint_error, gap, validity_problems, wall_distances, Box2,
};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject, SceneSpec};

const SEEDS: std::ops::Range<u64> = 0..3;

fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

fn all<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category)
        .collect()
}

#[test]
fn chairs_facing_mirrors_sit_at_the_stations_under_wall_mirrors() {
    for (prompt, n) in [
        ("a barbershop with two barber chairs facing mirrors", 2),
        ("a hair salon where four styling chairs face the mirrors", 4),
        (
            "a beauty salon with three salon chairs in front of mirrors on the wall",
            3,
        ),
    ] {
        for seed in SEEDS {
            let (l, _) = lay(prompt, seed);
            let chairs = all(&l, "barber chair");
            let stations = all(&l, "salon station");
            let mirrors = all(&l, "mirror");
            assert_eq!(chairs.len(), n, "{prompt}");
            assert!(stations.len() >= n, "{prompt}: {} stations", stations.len());
            assert!(!mirrors.is_empty(), "{prompt}: the mirrors asked are gone");
            let mut taken = vec![];
            for c in &chairs {
                let cb = Box2::of(c);
                let (j, g) = stations
                    .iter()
                    .enumerate()
                    .map(|(j, s)| (j, gap(&cb, &Box2::of(s))))
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .expect("a station");
                assert!(
                    g <= 0.3,
                    "{prompt} (seed {seed}): {} {g:.2} m from the nearest station",
                    c.id
                );
                assert!(
                    facing_footprint_error(&cb, &Box2::of(stations[j])) <= 30.0,
                    "{prompt} (seed {seed}): {} not turned to its station",
                    c.id
                );
                assert!(
                    !taken.contains(&j),
                    "{prompt} (seed {seed}): two chairs at one station"
                );
                taken.push(j);
            }
            // every mirror hangs on a wall, over a station with a chair at it
            for m in &mirrors {
                let mb = Box2::of(m);
                let on_wall = wall_distances(&mb, l.room.size).iter().any(|&d| d <= 0.2);
                assert!(
                    on_wall && m.position[2] >= 0.4,
                    "{prompt} (seed {seed}): {} not on a wall",
                    m.id
                );
                let over = taken.iter().any(|&j| {
                    let s = Box2::of(stations[j]);
                    s.local(mb.c)[0].abs() <= s.half[0] && gap(&mb, &s) <= 0.1
                });
                assert!(
                    over,
                    "{prompt} (seed {seed}): {} above no station with a chair",
                    m.id
                );
            }
        }
    }
}

#[test]
fn mirrors_asked_on_their_own_stay() {
    for (prompt, n) in [
        ("a hair salon with three barber chairs and two mirrors", 2),
        (
            "a barber shop with two barber chairs and a big mirror on the wall",
            1,
        ),
    ] {
        let p = plan_prompt(prompt).expect("planned");
        let got = p.spec.objects.get("mirror").map_or(0, |o| o.number);
        assert_eq!(got, n, "{prompt}");
    }
}
