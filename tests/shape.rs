//! Procedural shape priors: every knowledge-base category builds inside its box, rests on the
//! floor, faces +y, covers its silhouette without holes, takes colours from words, and is
//! deterministic per seed. Host-only.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{
    archetype_names, archetype_of, build, colour_words, parts, parts::convex_hull,
    parts::hull_contains, Role, ShapeError, ShapeOptions,
};
use dreamscene::splat::cloud::SH_C0;
use dreamscene::splat::Gaussians;

fn colour(g: &Gaussians, i: usize) -> [f64; 3] {
    [0, 1, 2].map(|c| SH_C0 * g.sh[i * 3 + c] as f64 + 0.5)
}

fn mean_colour(g: &Gaussians) -> [f64; 3] {
    let mut m = [0.0; 3];
    for i in 0..g.len() {
        let c = colour(g, i);
        (0..3).for_each(|k| m[k] += c[k] / g.len() as f64);
    }
    m
}

/// Fraction of silhouette cells covered by Gaussian centres when looking along `axis`: cells are
/// ~2.5% of the box (at least 1.5 cm and twice the sample spacing), a cell is in the silhouette when its centre lies inside the
/// projection of some solid part (rings such as tyres are see-through), and covered when a centre projects into it.
fn coverage(category: &str, size: [f64; 3], g: &Gaussians, axis: usize) -> f64 {
    let (a, b) = match axis {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let lo = [-size[0] / 2.0, -size[1] / 2.0, 0.0];
    let ps = parts(category, size).unwrap();
    let area: f64 = ps.iter().map(|p| p.prim.area()).sum();
    let spacing = (area / g.len() as f64).sqrt();
    let cell = |k: usize| (0.025 * size[k]).max(0.015).max(2.0 * spacing);
    let (na, nb) = (
        (size[a] / cell(a)).ceil() as usize,
        (size[b] / cell(b)).ceil() as usize,
    );
    let (ca, cb) = (size[a] / na as f64, size[b] / nb as f64);
    let mut covered = vec![false; na * nb];
    for m in &g.means {
        let i = ((m[a] as f64 - lo[a]) / ca).floor() as isize;
        let j = ((m[b] as f64 - lo[b]) / cb).floor() as isize;
        if (0..na as isize).contains(&i) && (0..nb as isize).contains(&j) {
            covered[i as usize * nb + j as usize] = true;
        }
    }
    let hulls: Vec<Vec<[f64; 2]>> = ps
        .iter()
        .filter(|p| p.prim.solid())
        .map(|p| {
            convex_hull(
                &p.prim
                    .hull_points()
                    .iter()
                    .map(|q| [q[a], q[b]])
                    .collect::<Vec<_>>(),
            )
        })
        .collect();
    let (mut inside, mut hit) = (0usize, 0usize);
    for i in 0..na {
        for j in 0..nb {
            let p = [lo[a] + (i as f64 + 0.5) * ca, lo[b] + (j as f64 + 0.5) * cb];
            if hulls.iter().any(|h| hull_contains(h, p)) {
                inside += 1;
                hit += covered[i * nb + j] as usize;
            }
        }
    }
    assert!(inside > 0, "{category}: empty silhouette along axis {axis}");
    if std::env::var("SHAPE_DEBUG").is_ok_and(|c| c == category) {
        for j in (0..nb).rev() {
            let row: String = (0..na)
                .map(|i| {
                    let p = [lo[a] + (i as f64 + 0.5) * ca, lo[b] + (j as f64 + 0.5) * cb];
                    match (
                        hulls.iter().any(|h| hull_contains(h, p)),
                        covered[i * nb + j],
                    ) {
                        (true, true) => '#',
                        (true, false) => 'o',
                        (false, true) => '+',
                        _ => '.',
                    }
                })
                .collect();
            eprintln!("{row}");
        }
    }
    hit as f64 / inside as f64
}

#[test]
fn every_builtin_category_builds_inside_its_box_and_covers_its_silhouette() {
    let kb = KnowledgeBase::builtin();
    let opts = ShapeOptions {
        gaussians: None,
        seed: 1,
        variant: 0,
        mount: None,
    };
    let mut holes: Vec<String> = vec![];
    for o in &kb.objects {
        let g = build(&o.category, o.size, &o.description, &opts).unwrap();
        g.check().unwrap();
        assert_eq!(g.sh_degree, 0);
        assert!(g.len() > 20_000, "{}: {} Gaussians", o.category, g.len());
        let [hw, hd, h] = [o.size[0] / 2.0, o.size[1] / 2.0, o.size[2]];
        let mut min_z = f64::INFINITY;
        for m in &g.means {
            let m = m.map(|v| v as f64);
            assert!(
                m[0].abs() <= hw + 0.01 && m[1].abs() <= hd + 0.01 && m[2] <= h + 0.01,
                "{}: {m:?} outside {:?}",
                o.category,
                o.size
            );
            min_z = min_z.min(m[2]);
        }
        assert!(min_z.abs() < 0.01, "{}: lowest z {min_z}", o.category);
        for axis in 0..3 {
            let c = coverage(&o.category, o.size, &g, axis);
            if c < 0.95 {
                holes.push(format!("{}: {c:.3} covered along axis {axis}", o.category));
            }
        }
    }
    assert!(holes.is_empty(), "{holes:#?}");
}

#[test]
fn surfels_are_flat_opaque_and_aligned_with_the_surface() {
    let g = build("cabinet", [1.0, 0.45, 1.1], "", &ShapeOptions::default()).unwrap();
    for i in 0..g.len() {
        let s = g.scales[i];
        assert!(s[2] < s[0] - 1.0 && s[2] < s[1] - 1.0, "not flat: {s:?}");
        let o = 1.0 / (1.0 + (-g.opacities[i]).exp());
        assert!((0.9..=0.95).contains(&o), "opacity {o}");
        // The Gaussian's z axis (third column of its rotation) is a box face normal: one of ±x,
        // ±y, ±z, and the centre lies on that face side of the box.
        let [w, x, y, z] = g.rotations[i];
        let n = [
            2.0 * (x * z + w * y),
            2.0 * (y * z - w * x),
            1.0 - 2.0 * (x * x + y * y),
        ];
        let big = n.iter().map(|v| v.abs()).fold(0.0, f32::max);
        assert!(big > 0.999, "normal {n:?} is not axis-aligned");
    }
}

#[test]
fn default_count_follows_area_and_option_overrides_it() {
    let sofa = build("sofa", [2.1, 0.95, 0.85], "", &ShapeOptions::default()).unwrap();
    let lamp = build("floor lamp", [0.4, 0.4, 1.6], "", &ShapeOptions::default()).unwrap();
    assert!((30_000..=63_000).contains(&sofa.len()), "{}", sofa.len());
    assert!((28_000..=63_000).contains(&lamp.len()), "{}", lamp.len());
    assert!(sofa.len() > lamp.len());
    let opts = ShapeOptions {
        gaussians: Some(12_000),
        seed: 0,
        variant: 0,
        mount: None,
    };
    let n = build("sofa", [2.1, 0.95, 0.85], "", &opts).unwrap().len();
    assert!((10_800..=13_200).contains(&n), "{n}");
}

/// Mean y of the Gaussians in the top fifth of the object, as a fraction of its depth.
fn high_mass_y(category: &str, size: [f64; 3]) -> f64 {
    let g = build(category, size, "", &ShapeOptions::default()).unwrap();
    let high: Vec<f64> = g
        .means
        .iter()
        .filter(|m| m[2] as f64 > 0.8 * size[2])
        .map(|m| m[1] as f64)
        .collect();
    high.iter().sum::<f64>() / high.len() as f64 / size[1]
}

#[test]
fn seats_and_beds_have_their_backs_at_minus_y() {
    for cat in [
        "dining chair",
        "sofa",
        "armchair",
        "office chair",
        "bed",
        "park bench",
        "toilet",
    ] {
        let size = KnowledgeBase::builtin().object(cat).unwrap().size;
        let y = high_mass_y(cat, size);
        assert!(y < -0.25, "{cat}: top mass at y = {y:.2} of the depth");
    }
}

#[test]
fn fronts_doors_and_screens_face_plus_y() {
    let kb = KnowledgeBase::builtin();
    let mut checked = 0;
    for o in &kb.objects {
        let ps = parts(&o.category, o.size).unwrap();
        let centre_y = |p: &dreamscene::shape::Part| {
            let pts = p.prim.hull_points();
            pts.iter().map(|q| q[1]).sum::<f64>() / pts.len() as f64
        };
        for p in &ps {
            if matches!(p.role, Role::Door | Role::Screen | Role::Keys) {
                checked += 1;
                assert!(
                    centre_y(p) > -0.05 * o.size[1],
                    "{}: {:?} part at y {:.3}",
                    o.category,
                    p.role,
                    centre_y(p)
                );
            }
        }
        // A bookshelf's back panel is at the back, its books open to the front.
        if archetype_of(&o.category) == "shelf" {
            let back = ps.iter().find(|p| p.role == Role::Interior).unwrap();
            assert!(centre_y(back) < -0.4 * o.size[1], "{}", o.category);
        }
    }
    assert!(checked > 50, "{checked} fronts checked");
}

#[test]
fn colour_words_change_colours() {
    let size = [2.1, 0.95, 0.85];
    let opts = ShapeOptions::default();
    let red = mean_colour(&build("sofa", size, "red velvet sofa", &opts).unwrap());
    let navy = mean_colour(&build("sofa", size, "navy leather sofa", &opts).unwrap());
    assert!(red[0] > red[1] + 0.2 && red[0] > red[2] + 0.2, "{red:?}");
    assert!(navy[2] > navy[0] && navy[2] > navy[1], "{navy:?}");
    let plain = mean_colour(&build("sofa", size, "", &opts).unwrap());
    let light = mean_colour(&build("sofa", size, "light grey sofa", &opts).unwrap());
    let dark = mean_colour(&build("sofa", size, "dark grey sofa", &opts).unwrap());
    assert!(
        light[0] > plain[0] - 0.1 && light[0] > dark[0] + 0.2,
        "{light:?} {dark:?}"
    );
    // A material with a part word colours that part only.
    let oak = mean_colour(
        &build(
            "dining table",
            [1.8, 0.9, 0.75],
            "table with a marble top",
            &opts,
        )
        .unwrap(),
    );
    let wood =
        mean_colour(&build("dining table", [1.8, 0.9, 0.75], "wooden table", &opts).unwrap());
    assert!(oak[2] > wood[2] + 0.15, "{oak:?} {wood:?}");
    let words = colour_words("A pale blue linen armchair with walnut legs");
    assert_eq!(words.len(), 3);
    assert_eq!(words[0].phrase, "pale blue");
    assert_eq!(words[2].part, Some(Role::Frame));
}

/// A rock's lumps each take a shade of their own (hue shifts the light cannot make: it scales
/// all channels alike), a stone word recolours the rock, and a machine's name ("paper
/// shredder") is not read as the material it is made of.
#[test]
fn rock_lumps_differ_in_shade_and_names_are_not_materials() {
    let opts = ShapeOptions::default();
    let size = [1.2, 1.0, 0.8];
    let rock = build("rock", size, "a big rock", &opts).unwrap();
    let ratios: Vec<f64> = (0..rock.len())
        .map(|i| colour(&rock, i))
        .filter(|c| c[2] > 0.05)
        .map(|c| c[0] / c[2])
        .collect();
    let (lo, hi) = ratios
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), r| (l.min(*r), h.max(*r)));
    assert!(
        hi - lo > 0.08,
        "red/blue ratios of a rock span {lo:.3}..{hi:.3}"
    );
    let plain = mean_colour(&rock);
    let granite = mean_colour(&build("rock", size, "a granite boulder", &opts).unwrap());
    assert!(granite[0] < plain[0] - 0.05, "{granite:?} {plain:?}");
    let shredder =
        mean_colour(&build("paper shredder", [0.4, 0.3, 0.6], "a paper shredder", &opts).unwrap());
    assert!(shredder.iter().all(|c| *c < 0.5), "{shredder:?}");
}

#[test]
fn deterministic_per_seed_and_seeds_differ() {
    let size = [0.45, 0.5, 0.9];
    let a = ShapeOptions {
        gaussians: None,
        seed: 7,
        variant: 0,
        mount: None,
    };
    let b = ShapeOptions {
        gaussians: None,
        seed: 8,
        variant: 0,
        mount: None,
    };
    let g1 = build("chair", size, "oak chair", &a).unwrap();
    let g2 = build("chair", size, "oak chair", &a).unwrap();
    let g3 = build("chair", size, "oak chair", &b).unwrap();
    assert_eq!(g1, g2);
    assert_ne!(g1.means, g3.means);
    assert_ne!(g1.sh, g3.sh);
}

#[test]
fn bad_sizes_and_counts_are_errors() {
    let o = ShapeOptions::default();
    for size in [
        [0.0, 1.0, 1.0],
        [1.0, -1.0, 1.0],
        [1.0, 1.0, f64::NAN],
        [f64::INFINITY, 1.0, 1.0],
    ] {
        assert!(matches!(
            build("sofa", size, "", &o),
            Err(ShapeError::BadSize(_))
        ));
    }
    let few = ShapeOptions {
        gaussians: Some(5),
        seed: 0,
        variant: 0,
        mount: None,
    };
    assert!(matches!(
        build("sofa", [1.0, 1.0, 1.0], "", &few),
        Err(ShapeError::BadCount(5))
    ));
}

#[test]
fn archetypes_cover_the_knowledge_base_and_unknowns_default_to_box() {
    let names = archetype_names();
    assert!(names.len() >= 20, "{} archetypes", names.len());
    for o in &KnowledgeBase::builtin().objects {
        assert!(names.contains(&archetype_of(&o.category)), "{}", o.category);
    }
    assert_eq!(archetype_of("couch"), "sofa");
    assert_eq!(archetype_of("Bookcase"), "shelf");
    assert_eq!(archetype_of("flux capacitor"), "box");
    let g = build(
        "flux capacitor",
        [0.5, 0.5, 0.5],
        "",
        &ShapeOptions::default(),
    )
    .unwrap();
    assert!(!g.is_empty());
}

#[test]
fn every_category_maps_to_an_archetype_of_its_own_function() {
    use dreamscene::shape::functions::{archetype_functions, category_functions};
    let cats = category_functions();
    let archs = archetype_functions();
    // Every archetype says what it can show, and only archetypes that exist are listed.
    for a in archetype_names() {
        assert!(
            archs.contains_key(a),
            "archetype `{a}` has no row in archetype_functions.txt"
        );
    }
    for a in archs.keys() {
        assert!(
            archetype_names().contains(a),
            "archetype_functions.txt names `{a}`, no archetype"
        );
    }
    let mut wrong = vec![];
    for o in &KnowledgeBase::builtin().objects {
        let Some(f) = cats.get(o.category.as_str()) else {
            wrong.push(format!(
                "`{}` has no row in category_functions.txt",
                o.category
            ));
            continue;
        };
        let arch = archetype_of(&o.category);
        if !archs.get(arch).is_some_and(|fs| fs.contains(f)) {
            wrong.push(format!(
                "`{}` is for `{f}` but its archetype `{arch}` shows {:?}",
                o.category,
                archs.get(arch)
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "{} categories:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
    // Function classes no archetype shows are typos.
    for (c, f) in &cats {
        assert!(
            archs.values().any(|fs| fs.contains(f)),
            "`{c}`: no archetype shows `{f}`"
        );
    }
}

/// A form word before the category's name draws the archetype of that form; one that describes
/// something else, or none, keeps the category's own.
#[test]
fn form_words_before_the_name_change_the_form() {
    use dreamscene::shape::archetype_described;
    let cases = [
        (
            "full length mirror",
            "a round gilded mirror",
            "round_mirror",
        ),
        (
            "full length mirror",
            "an oval mirror by the door",
            "oval_mirror",
        ),
        ("rug", "a big round wool rug", "round_rug"),
        ("dining table", "an oval oak dining table", "oval_table"),
        ("round table", "a square table", "table"),
        ("ottoman", "a square leather ottoman", "square_ottoman"),
        // The form word describes the mirror, not the table.
        ("vanity table", "vanity table with a round mirror", "vanity"),
        ("rug", "a rug under a round table", "rug"),
        // A form the archetype has not: a round sofa stays a sofa.
        ("sofa", "a round sofa", "sofa"),
    ];
    for (category, description, want) in cases {
        assert_eq!(
            archetype_described(category, description),
            want,
            "{category}: {description}"
        );
    }
    // The form's parts are its own: a round mirror's glass is a disc, narrower at its top than
    // a rectangle's of the same box.
    let size = [0.6, 0.05, 0.6];
    let top_width = |d: &str| {
        let parts = dreamscene::shape::parts_described("full length mirror", size, d).unwrap();
        let mut pts = vec![];
        let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
        for p in parts {
            p.prim.sample(0.01, &mut rng, &mut pts);
        }
        let near_top: Vec<f64> = pts
            .iter()
            .filter(|s| s.pos[2] > 0.55)
            .map(|s| s.pos[0].abs())
            .collect();
        near_top.iter().fold(0.0f64, |a, v| a.max(*v))
    };
    assert!(
        top_width("a round mirror") < 0.8 * top_width("a mirror"),
        "a round mirror should narrow towards its top"
    );
}

/// An oval rug leaves its box's corners bare; the plain rug fills them.
#[test]
fn an_oval_rug_is_an_ellipse() {
    let size = [2.0, 1.4, 0.005];
    let corner = |d: &str| {
        let parts = dreamscene::shape::parts_described("rug", size, d).unwrap();
        let mut pts = vec![];
        let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
        for p in parts {
            p.prim.sample(0.02, &mut rng, &mut pts);
        }
        pts.iter()
            .filter(|s| s.pos[0].abs() > 0.8 && s.pos[1].abs() > 0.55)
            .count()
    };
    assert_eq!(
        corner("an oval rug"),
        0,
        "an oval rug reaches its box's corners"
    );
    assert!(corner("a rug") > 0, "a plain rug should fill its corners");
}
