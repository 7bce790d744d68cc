//! Placement faults of round 20: rows face a front that kb/fronts.txt does not list (a piano)
//! and leave the default desks their seats would sit at; a thing of outdoor scale indoors (a
//! flagpole, a tree) takes its indoor size instead of raising the ceiling.
use dreamscene::plan::check::validity_problems;
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::offline::plan_prompt;
use dreamscene::plan::spec::{Layout, PlacedObject, SceneSpec};

/// Plans and lays out `prompt` (seed `seed`); the layout is valid.
fn lay(prompt: &str, seed: u64) -> (Layout, SceneSpec) {
    let plan = plan_prompt(prompt).expect("planned");
    let l = layout(&plan.spec, LayoutOptions::seeded(seed)).expect("laid out");
    assert!(validity_problems(&l, &plan.spec).is_empty(), "{prompt}");
    (l, plan.spec)
}

fn of<'a>(l: &'a Layout, category: &str) -> Vec<&'a PlacedObject> {
    l.objects
        .iter()
        .filter(|o| o.category == category)
        .collect()
}

/// Angle (degrees) between `o`'s facing and the way from its centre to the nearest point of
/// `t`'s footprint (how a person judges "facing" it).
fn facing_angle(o: &PlacedObject, t: &PlacedObject) -> f64 {
    let a = o.yaw.to_radians();
    let f = [-a.sin(), a.cos()];
    let (c, s) = (t.yaw.to_radians().cos(), t.yaw.to_radians().sin());
    let (hw, hd) = (0.5 * t.size[0], 0.5 * t.size[1]);
    // the target's footprint corners, then the nearest point on its outline
    let corners: Vec<[f64; 2]> = [[-hw, -hd], [hw, -hd], [hw, hd], [-hw, hd]]
        .iter()
        .map(|[x, y]| [t.position[0] + c * x - s * y, t.position[1] + s * x + c * y])
        .collect();
    let p = [o.position[0], o.position[1]];
    let mut best = (f64::INFINITY, [0.0, 0.0]);
    for k in 0..4 {
        let (a, b) = (corners[k], corners[(k + 1) % 4]);
        let v = [b[0] - a[0], b[1] - a[1]];
        let len = v[0] * v[0] + v[1] * v[1];
        let u = (((p[0] - a[0]) * v[0] + (p[1] - a[1]) * v[1]) / len).clamp(0.0, 1.0);
        let q = [a[0] + u * v[0], a[1] + u * v[1]];
        let d = (q[0] - p[0]).hypot(q[1] - p[1]);
        if d < best.0 {
            best = (d, q);
        }
    }
    let to = [best.1[0] - p[0], best.1[1] - p[1]];
    let n = to[0].hypot(to[1]).max(1e-9);
    ((f[0] * to[0] + f[1] * to[1]) / n)
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees()
}

#[test]
fn chairs_in_rows_face_a_piano_and_leave_the_default_desks() {
    for (prompt, n) in [
        (
            "a music classroom with a piano, a blackboard and twelve chairs in three rows facing the piano",
            12,
        ),
        (
            "a choir room with a piano and sixteen chairs in four rows facing the piano",
            16,
        ),
        (
            "a classroom with a harp and ten chairs in two rows facing the harp",
            10,
        ),
    ] {
        for seed in 0..3 {
            let (l, spec) = lay(prompt, seed);
            assert!(
                !spec.objects.contains_key("school desk"),
                "{prompt}: the chairs in rows are no desks' seats: {:?}",
                spec.objects.keys()
            );
            let front = l
                .objects
                .iter()
                .find(|o| o.category == "piano" || o.category == "harp")
                .expect("the front");
            let chairs = of(&l, "dining chair");
            assert_eq!(chairs.len(), n, "{prompt}");
            for c in chairs {
                let a = facing_angle(c, front);
                assert!(a <= 40.0, "{prompt} (seed {seed}): {} off by {a:.0}", c.id);
            }
        }
    }
    // desks the text names in rows stay
    let plan = plan_prompt("a classroom with twelve school desks in three rows and a blackboard")
        .expect("planned");
    assert_eq!(plan.spec.objects["school desk"].number, 12);
}

#[test]
fn a_thing_of_outdoor_scale_indoors_takes_its_indoor_size() {
    // the ceiling is the place's own (a hall is taller than a classroom), never the thing's
    for (prompt, place, cat) in [
        ("a school hall with a flagpole", "a school hall", "flagpole"),
        ("a classroom with a flagpole", "a classroom", "flagpole"),
        ("a living room with a tree", "a living room", "tree"),
        (
            "an office lobby with a palm tree",
            "an office lobby",
            "palm tree",
        ),
    ] {
        let (l, spec) = lay(prompt, 0);
        let own = lay(place, 0).0.room.size[2];
        assert!(
            l.room.size[2] <= own.max(2.8) + 1e-9,
            "{prompt}: {:?}",
            l.room.size
        );
        let h = spec.objects[cat].size[2];
        assert!(h < l.room.size[2], "{prompt}: {cat} {h} m");
    }
    // outdoors a flagpole keeps its height
    let plan = plan_prompt("a park with a flagpole").expect("planned");
    assert!(plan.spec.objects["flagpole"].size[2] >= 5.0);
}
