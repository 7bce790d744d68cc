//! Environment init: the cuboid encloses the room without holes, the hemisphere and ground disk
//! sit where the authors put them, counts follow area under the cap, colours follow the words.
use dreamscene::plan::spec::SceneType;
use dreamscene::scene::env::{
    draft_colours, hemisphere_radius, init_environment, EnvKind, EnvOptions, Environment, Pattern,
    WALL_PUSH,
};
use dreamscene::splat::cloud::SH_C0;
use dreamscene::splat::Gaussians;

const ROOM: [f64; 3] = [5.0, 4.0, 2.8];

fn env(st: SceneType, room: [f64; 3], text: &str, opts: EnvOptions) -> Environment {
    init_environment(st, room, &draft_colours(st, text), &opts)
}

fn colours(g: &Gaussians) -> Vec<[f64; 3]> {
    g.sh.chunks(3)
        .map(|c| [0, 1, 2].map(|k| SH_C0 * c[k] as f64 + 0.5))
        .collect()
}

fn mean_colour(g: &Gaussians) -> [f64; 3] {
    let c = colours(g);
    [0, 1, 2].map(|k| c.iter().map(|x| x[k]).sum::<f64>() / c.len() as f64)
}

#[test]
fn cuboid_encloses_the_room_without_holes() {
    let e = env(
        SceneType::Indoor,
        ROOM,
        "a living room",
        EnvOptions::default(),
    );
    assert_eq!(e.kind, EnvKind::Cuboid);
    for g in [&e.env, &e.floor] {
        g.check().unwrap();
        assert_eq!(g.sh_degree, 0);
        assert!(
            g.opacities.iter().all(|&o| o > 2.0),
            "draft walls are opaque"
        );
        for s in &g.scales {
            assert!(s[2] < s[0] && s[2] < s[1], "flat surfels: {s:?}");
        }
    }
    let [w, d, h] = ROOM;
    // Every wall / ceiling Gaussian lies on one face, at most WALL_PUSH outside it.
    let mut faces = [0usize; 5];
    for m in &e.env.means {
        let m = m.map(|v| v as f64);
        let out = [
            -m[0] - 0.5 * w,
            m[0] - 0.5 * w,
            -m[1] - 0.5 * d,
            m[1] - 0.5 * d,
            m[2] - h,
        ];
        let (face, &o) = out
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .unwrap();
        assert!((-1e-4..=WALL_PUSH + 1e-4).contains(&o), "{m:?}");
        assert!(m[2] >= 0.0 && m[2] <= h + WALL_PUSH + 1e-4, "{m:?}");
        faces[face] += 1;
    }
    assert!(faces.iter().all(|&n| n > 10_000), "{faces:?}");
    // No holes: every 10 cm cell of the x = -W/2 wall and of the floor holds a Gaussian.
    let cells = |pts: Vec<(f64, f64)>, a: f64, b: f64| {
        let (na, nb) = ((a / 0.1) as usize, (b / 0.1) as usize);
        let mut hit = vec![false; na * nb];
        for (u, v) in pts {
            let (i, j) = ((u / 0.1) as usize, (v / 0.1) as usize);
            if i < na && j < nb {
                hit[j * na + i] = true;
            }
        }
        hit.iter().filter(|&&x| !x).count()
    };
    let wall: Vec<(f64, f64)> = e
        .env
        .means
        .iter()
        .filter(|m| (m[0] as f64) < -0.5 * w + 0.001 && (m[2] as f64) < h)
        .map(|m| (m[1] as f64 + 0.5 * d, m[2] as f64))
        .collect();
    assert_eq!(cells(wall, d, h), 0, "holes in the wall");
    let floor: Vec<(f64, f64)> = e
        .floor
        .means
        .iter()
        .map(|m| (m[0] as f64 + 0.5 * w, m[1] as f64 + 0.5 * d))
        .collect();
    assert_eq!(cells(floor, w, d), 0, "holes in the floor");
    for m in &e.floor.means {
        assert!((-0.005..=0.0).contains(&m[2]), "floor at z = 0: {m:?}");
        assert!((m[0] as f64).abs() <= 0.5 * w + WALL_PUSH + 1e-4);
        assert!((m[1] as f64).abs() <= 0.5 * d + WALL_PUSH + 1e-4);
    }
}

#[test]
fn hemisphere_and_ground_disk_follow_the_authors_radius() {
    let room = [20.0, 20.0, 10.0];
    let e = env(SceneType::Outdoor, room, "a garden", EnvOptions::default());
    assert_eq!(e.kind, EnvKind::Hemisphere);
    let r = hemisphere_radius(room);
    assert!((r - 300f64.sqrt()).abs() < 1e-9);
    for m in &e.env.means {
        let d = m.iter().map(|v| (*v as f64).powi(2)).sum::<f64>().sqrt();
        assert!(d > 0.98 * r && d < 1.02 * r && m[2] >= 0.0, "{m:?}");
    }
    for m in &e.floor.means {
        assert!(((m[0] as f64).hypot(m[1] as f64)) < r + 0.1 && (-0.01..=0.0).contains(&m[2]));
    }
    let green = mean_colour(&e.floor);
    assert!(
        green[1] > green[0] && green[1] > green[2],
        "grass: {green:?}"
    );
    let sky = mean_colour(&e.env);
    assert!(sky[2] > sky[0], "blue sky: {sky:?}");
}

#[test]
fn counts_follow_area_and_respect_the_cap() {
    let total = |e: &Environment| e.env.len() + e.floor.len();
    let big = EnvOptions {
        cap: 10_000_000,
        ..Default::default()
    };
    let small = total(&env(SceneType::Indoor, ROOM, "a room", big));
    let large = total(&env(SceneType::Indoor, [10.0, 8.0, 2.8], "a room", big));
    // Areas 90.4 and 260.8 m².
    let ratio = large as f64 / small as f64;
    assert!(
        (ratio / (260.8 / 90.4) - 1.0).abs() < 0.05,
        "{small} {large}"
    );
    let draft = total(&env(
        SceneType::Indoor,
        ROOM,
        "a room",
        EnvOptions::default(),
    ));
    assert!((100_000..=200_000).contains(&draft), "{draft}");
    for (st, room) in [
        (SceneType::Indoor, [12.0, 10.0, 3.5]),
        (SceneType::Outdoor, [20.0, 20.0, 10.0]),
    ] {
        let capped = EnvOptions {
            cap: 20_000,
            ..Default::default()
        };
        let n = total(&env(st, room, "", capped));
        assert!((18_000..=20_000).contains(&n), "{st:?}: {n}");
        let n = total(&env(st, room, "", EnvOptions::default()));
        assert!(n <= EnvOptions::default().cap, "{st:?}: {n}");
    }
    let half = EnvOptions {
        density: 750.0,
        ..Default::default()
    };
    let n = total(&env(SceneType::Indoor, ROOM, "a room", half));
    assert!(
        (n as f64 / draft as f64 - 0.5).abs() < 0.03,
        "{n} vs {draft}"
    );
}

#[test]
fn colours_follow_surface_words() {
    let c = |t: &str| draft_colours(SceneType::Indoor, t);
    let o = |t: &str| draft_colours(SceneType::Outdoor, t);
    let wood = c("a study with a wooden floor");
    let marble = c("a study with a marble floor");
    assert_eq!(wood.floor_pattern, Pattern::Boards);
    assert_eq!(marble.floor_pattern, Pattern::Marble);
    assert_ne!(wood.floor, marble.floor);
    let dark = c("a bedroom with a dark oak floor");
    let light = c("a bedroom with an oak floor");
    assert!(dark.floor.iter().sum::<f32>() < 0.8 * light.floor.iter().sum::<f32>());
    assert_eq!(c("a bathroom").floor_pattern, Pattern::Tiles);
    assert_eq!(
        c("a kitchen with a wooden table").floor_pattern,
        Pattern::Tiles
    );
    assert_eq!(
        c("a bar with white brick walls").wall_pattern,
        Pattern::Bricks
    );
    assert_eq!(c("a bar with white brick walls").wall, [0.92, 0.92, 0.90]);
    assert_eq!(c("a living room").floor_pattern, Pattern::Boards);
    assert_eq!(
        c("an office with grey carpet").floor_pattern,
        Pattern::Speckled
    );
    let beach = o("a sunny beach");
    assert!(
        beach.ground[0] > 0.7 && beach.ground[2] < 0.6,
        "{:?}",
        beach.ground
    );
    assert!(o("a garden").ground[1] > o("a garden").ground[0]);
    assert!(o("a snowy park").ground.iter().all(|&v| v > 0.9));
    assert_eq!(o("a street").ground_pattern, Pattern::Speckled);
    assert_eq!(
        o("a market square with cobblestone ground").ground_pattern,
        Pattern::Cobbles
    );
    assert!(o("a park at sunset").sky[0] > o("a park").sky[0]);
}

/// A material word that is part of an object's name names the object, not the floor: a lawn
/// mower in a garage leaves its floor as it was, while the word alone still sets the ground.
#[test]
fn a_material_word_inside_an_object_name_leaves_the_floor_alone() {
    let c = |t: &str| draft_colours(SceneType::Indoor, t);
    let garage = c("a garage with a car");
    for t in [
        "a garage with a car and a lawn mower",
        "a garage with two lawn mowers and a workbench",
        "a teh garage with a car, a lawn mower and shelvs full of boxes",
    ] {
        let f = c(t);
        assert_eq!(
            (f.floor, f.floor_pattern),
            (garage.floor, garage.floor_pattern),
            "{t}"
        );
    }
    // the word on its own still speaks of the ground
    assert_eq!(c("a sunroom with a lawn").floor_pattern, Pattern::Mottled);
    assert!(c("a sunroom with a lawn").floor[1] > c("a sunroom with a lawn").floor[0]);
}

/// A clinical place (named so by its kind or by the words naming the place) has a pale vinyl
/// floor whatever its kind's own floor, unless the text names another; places that are not
/// clinical keep theirs, even when they hold something medical.
#[test]
fn clinical_places_have_vinyl_floors() {
    let c = |t: &str| draft_colours(SceneType::Indoor, t);
    for t in [
        "an operating room",
        "a surgical suite with two carts",
        "a dental clinic",
        "a hospital room with a window",
        "a doctor's waiting room",
        "a vet clinic with a scale",
    ] {
        let f = c(t);
        assert_eq!(f.floor_pattern, Pattern::Speckled, "{t}");
        assert!(
            f.floor.iter().all(|&v| v > 0.7) && (f.floor[0] - f.floor[2]).abs() < 0.08,
            "{t}: a pale grey floor, not wood: {:?}",
            f.floor
        );
    }
    assert_eq!(
        c("an operating room with an oak floor").floor_pattern,
        Pattern::Boards
    );
    for t in [
        "a restaurant",
        "an exam hall",
        "a waiting room",
        "a living room",
        "a garage with a medical cart",
        "a kid's bedroom with a toy doctor kit and a bunk bed",
    ] {
        assert_ne!(c(t).floor, c("an operating room").floor, "{t}");
    }
}

/// A door's leaf follows the scene: its kind, its style words, and what it says of its doors;
/// a colour word of another noun leaves the door alone.
#[test]
fn door_leaves_follow_the_scene_not_always_wood() {
    let d = |t: &str| draft_colours(SceneType::Indoor, t).door;
    let lum = |c: [f32; 3]| c.iter().sum::<f32>() / 3.0;
    let wood = d("a living room");
    assert!(
        wood[0] > wood[2] + 0.15,
        "a living room's door is wood: {wood:?}"
    );
    assert!(
        lum(d("a hospital room")) > 0.85,
        "painted white: {:?}",
        d("a hospital room")
    );
    let metal = d("a spaceship bridge with a captain's chair");
    assert!((metal[0] - metal[2]).abs() < 0.05, "bare metal: {metal:?}");
    assert!(
        lum(d("a rustic kitchen")) < 0.3,
        "rustic: {:?}",
        d("a rustic kitchen")
    );
    assert!(
        lum(d("a modern study")) > 0.85,
        "modern: {:?}",
        d("a modern study")
    );
    let red = d("a bedroom with a red door");
    assert!(red[0] > 2.0 * red[1], "a red door: {red:?}");
    assert_eq!(
        d("a bedroom with a red sofa"),
        d("a bedroom"),
        "the sofa's red"
    );
    let dark = d("a kitchen with dark oak doors");
    assert!(
        lum(dark) < 0.7 * lum(d("a kitchen with oak doors")),
        "{dark:?}"
    );
}

#[test]
fn floors_are_patterned_and_deterministic_per_seed() {
    let opts = |seed| EnvOptions {
        seed,
        ..Default::default()
    };
    let a = env(SceneType::Indoor, ROOM, "a living room", opts(1));
    let b = env(SceneType::Indoor, ROOM, "a living room", opts(1));
    let c = env(SceneType::Indoor, ROOM, "a living room", opts(2));
    assert_eq!(a.env, b.env);
    assert_eq!(a.floor, b.floor);
    assert_ne!(a.floor.means, c.floor.means);
    // The wooden floor is not flat-coloured: brightness varies by more than 10% (boards, seams).
    let lum: Vec<f64> = colours(&a.floor)
        .iter()
        .map(|c| c.iter().sum::<f64>())
        .collect();
    let mean = lum.iter().sum::<f64>() / lum.len() as f64;
    let sd = (lum.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / lum.len() as f64).sqrt();
    assert!(sd / mean > 0.1, "floor brightness sd/mean {}", sd / mean);
}

/// Outdoors the scene area has its kind's own ground and what lies around it another (paving
/// inside a lawn, decking in the sea); a rooftop stands inside a parapet, over roofs.
#[test]
fn outdoor_grounds_have_an_area_a_surround_and_a_roof_parapet() {
    let o = |t: &str| draft_colours(SceneType::Outdoor, t);
    let patio = o("a patio with a table");
    assert_eq!(patio.ground_pattern, Pattern::Slabs, "paved patio");
    assert!(patio.surround[1] > patio.surround[0], "a lawn round it");
    assert_eq!(o("a park").ground, o("a park").surround, "one ground");
    assert!(o("a park").parapet.is_none(), "no parapet in a park");
    // what the text says of one ground all round covers it all
    let snowy = o("a beach with white sand");
    assert_eq!(snowy.ground, snowy.surround, "white sand all round");
    let deck = o("a patio with timber decking");
    assert_eq!(deck.ground_pattern, Pattern::Boards, "decking named");
    assert!(deck.surround[1] > deck.surround[0], "still a lawn round it");
    let roof = o("a rooftop terrace with two chairs");
    assert!(roof.parapet.is_some(), "a parapet round a rooftop");
    // a possessive still names the scene: a ship's deck is planks (wide enough to read at the
    // outdoor ground's spacing) with the sea round it
    for t in [
        "a pirate ship's deck with two cannons",
        "the deck of a pirate ship",
    ] {
        let ship = o(t);
        assert_eq!(
            ship.ground_pattern,
            Pattern::Planks,
            "{t}: a deck of planks"
        );
        assert!(
            ship.surround[2] > ship.surround[1] && ship.surround[1] > ship.surround[0],
            "{t}: the sea round it"
        );
    }
    let room = [8.0, 6.0, 5.0];
    let e = env(
        SceneType::Outdoor,
        room,
        "a rooftop terrace with two chairs",
        EnvOptions::default(),
    );
    // the sky's surfels lie at the hemisphere's radius; the parapet's well inside it
    let r = 0.9 * hemisphere_radius(room);
    let wall: Vec<&[f32; 3]> = e
        .env
        .means
        .iter()
        .filter(|m| m.iter().map(|v| f64::from(*v).powi(2)).sum::<f64>().sqrt() < r)
        .collect();
    assert!(
        wall.len() > 1000,
        "parapet surfels: {} near the ground",
        wall.len()
    );
    for m in &wall {
        let (x, y) = (m[0].abs() as f64, m[1].abs() as f64);
        let edge = (x - 0.5 * room[0]).max(y - 0.5 * room[1]);
        assert!(
            (0.0..0.3).contains(&edge) && f64::from(m[2]) <= 1.06,
            "parapet surfel off the area's edge: {m:?}"
        );
    }
    let total = e.env.len() + e.floor.len();
    assert!(total <= EnvOptions::default().cap, "{total} over the cap");
}

/// A floor material the text says is not there sets nothing: "a rug instead of a carpet" in a
/// kids room (whose floor is carpet by default) gives it plain boards; "no carpet", "without
/// tiles" likewise, while the word said plainly still sets the floor.
#[test]
fn a_floor_material_said_not_to_be_there_is_not_the_floor() {
    let c = |t: &str| draft_colours(SceneType::Indoor, t);
    for t in [
        "a kids room with a rug instead of a carpet",
        "a nursery with no carpet",
        "a kids room without wall-to-wall carpet",
    ] {
        assert_ne!(c(t).floor_pattern, Pattern::Speckled, "{t}");
    }
    assert_ne!(
        c("a kitchen with wood rather than tiles").floor_pattern,
        Pattern::Tiles
    );
    assert_eq!(
        c("a bedroom with a thick carpet").floor_pattern,
        Pattern::Speckled
    );
    assert_eq!(
        c("a kids room with a rug instead of a carpet").floor_pattern,
        Pattern::Boards
    );
}

/// A balcony is up on a building: a parapet round it, as round a rooftop.
#[test]
fn a_balcony_has_a_parapet() {
    let o = |t: &str| draft_colours(SceneType::Outdoor, t);
    assert!(o("a small balcony").parapet.is_some());
    assert!(o("a balcony with two chairs").parapet.is_some());
    assert!(o("a garden").parapet.is_none());
}

/// A scene said to be in a place of another kind takes that place's floor and walls: "a home
/// gym in the garage" is the garage's concrete and grey walls, not the gym's; a place named
/// only as what it holds ("a garage with a rowing machine") keeps its own look.
#[test]
fn the_place_a_scene_is_in_gives_its_surfaces() {
    let c = |t: &str| draft_colours(SceneType::Indoor, t);
    let garage = c("a garage with a car");
    for t in [
        "a small home gym in the garage",
        "a home gym in my garage",
        "a workout room inside the garage with a treadmill",
    ] {
        let f = c(t);
        assert_eq!((f.floor, f.wall), (garage.floor, garage.wall), "{t}");
    }
    // what a garage holds after "with" leaves the gym its own look
    let gym = c("a home gym");
    let f = c("a home gym with a treadmill in the garage");
    assert_eq!((f.floor, f.wall), (gym.floor, gym.wall));
}
