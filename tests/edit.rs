//! `dreamscene edit` on small scenes: a move renders as the object PLY under the new transform
//! (computed here independently), a colliding move is refused and changes nothing, undo restores
//! every file byte for byte, add places a new object free and next to the one asked, remove takes
//! its Gaussians out; with the oracle prior the floor where a removed object stood is
//! re-optimised to the reference, and restyling moves an object to a second reference with the
//! rest of the scene unchanged bit for bit.
#![allow(
    clippy::unwrap_used,
    reason = "helpers outside #[test] functions: a panic there fails the test at its line"
)]
mod common;
use common::edit;
#[allow(dead_code, reason = "this test uses some of the shared export helpers")]
mod export_support;
use dreamscene::camera::object::{orbit_camera, ObjectFrame};
use dreamscene::camera::{write_cameras, Camera};
use dreamscene::export::labels::write_labelled_scene;
use dreamscene::generate::scene::write_draft_scene;
use dreamscene::plan::check::{penetration, relation_holds, Box2};
use dreamscene::plan::gcp::{layout, LayoutOptions};
use dreamscene::plan::spec::{Layout, RelationKind, SceneSpec};
use dreamscene::scene::compose::merge;
use dreamscene::scene::dir::{compose_scene, light_draft, read_scene};
use dreamscene::splat::loss::psnr;
use dreamscene::splat::ply::{read_ply, write_ply};
use dreamscene::splat::raster::{GpuGaussians, Rasterizer};
use dreamscene::splat::Gaussians;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ds-edit-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A 3.6 x 3 x 2.4 m bedroom: bed against a wall, a nightstand next to it, a chair.
fn spec() -> SceneSpec {
    serde_json::from_str(
        r#"{"scene_type": "indoor", "scene_text": "a small bedroom",
            "room": {"size": [3.6, 3.0, 2.4]},
            "objects": {
              "bed": {"number": 1, "size": [1.4, 1.9, 0.6], "description": "A DSLR photo of a wooden bed"},
              "nightstand": {"number": 1, "size": [0.45, 0.4, 0.55], "description": "A DSLR photo of a white nightstand"},
              "chair": {"number": 1, "size": [0.45, 0.45, 0.85], "description": "A DSLR photo of a red chair"}},
            "anchors": {"bed1": "SIDE"},
            "relations": [{"subject": "nightstand1", "relation": "NEXT", "object": "bed1"}]}"#,
    )
    .unwrap()
}

/// A draft scene directory with one preview view (64²) of the whole room.
fn draft(name: &str) -> (PathBuf, Layout) {
    let spec = spec();
    let l = layout(&spec, LayoutOptions::seeded(2)).unwrap();
    let d = tmp(name);
    std::fs::write(d.join("spec.json"), serde_json::to_string(&spec).unwrap()).unwrap();
    l.write(&d.join("layout.json")).unwrap();
    write_draft_scene(&d, "a small bedroom", 0, &spec, &l, false, &mut |_| {}).unwrap();
    // Kept small: every k-th Gaussian, grown to cover the same surface.
    thin(&d.join("environment.ply"), 8);
    for cat in ["bed", "nightstand", "chair"] {
        thin(&d.join(format!("objects/{cat}.ply")), 15);
    }
    let s = read_scene(&d).unwrap();
    write_labelled_scene(&d, &s).unwrap();
    std::fs::create_dir_all(d.join("renders")).unwrap();
    let mut cam = Camera::look_at(
        [1.4, -1.2, 1.8],
        [-0.5, 0.5, 0.3],
        [0.0, 0.0, 1.0],
        64,
        64,
        1.2,
    );
    cam.img_name = "view".into();
    write_cameras(&d.join("renders/cameras.json"), &[cam]).unwrap();
    (d, l)
}

/// Keeps every `k`-th Gaussian of a PLY, each grown by √k on every axis.
fn thin(path: &Path, k: usize) {
    let g = read_ply(path).unwrap();
    let keep: Vec<bool> = (0..g.len()).map(|i| i % k == 0).collect();
    let mut t = dreamscene::generate::object::subset(&g, &keep);
    let grow = 0.5 * (k as f32).ln();
    for s in &mut t.scales {
        *s = s.map(|v| v + grow);
    }
    write_ply(path, &t).unwrap();
}

fn ok(o: &std::process::Output) -> String {
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "{err}");
    err
}

/// Every file of the directory (history/ and dot-directories aside) with its bytes.
fn snapshot(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(dir).unwrap().to_string_lossy().to_string();
            if rel.starts_with("history") || rel.starts_with('.') {
                continue;
            }
            if p.is_dir() {
                stack.push(p);
            } else {
                out.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    out
}

fn instance(dir: &Path, id: &str) -> dreamscene::scene::dir::SceneObject {
    read_scene(dir)
        .unwrap()
        .objects
        .into_iter()
        .find(|o| o.id == id)
        .unwrap()
}

/// The test's own placement (uniform positive scale, SH degree 0): means by Rz·s·p + t,
/// rotations by the yaw quaternion, log-scales shifted by ln s.
fn place_here(g: &Gaussians, yaw: f64, s: f64, t: [f64; 3]) -> Gaussians {
    assert_eq!(g.sh_degree, 0, "the fixture is SH degree 0");
    let (sn, cs) = yaw.to_radians().sin_cos();
    let (hs, hc) = (0.5 * yaw.to_radians()).sin_cos();
    let mut out = g.clone();
    for i in 0..g.len() {
        let p = g.means[i].map(f64::from);
        out.means[i] = [
            (s * (cs * p[0] - sn * p[1]) + t[0]) as f32,
            (s * (sn * p[0] + cs * p[1]) + t[1]) as f32,
            (s * p[2] + t[2]) as f32,
        ];
        let q = g.rotations[i].map(f64::from);
        let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
        let [w, x, y, z] = q.map(|v| v / n);
        // (hc, 0, 0, hs) ⊗ (w, x, y, z)
        out.rotations[i] = [
            hc * w - hs * z,
            hc * x - hs * y,
            hc * y + hs * x,
            hc * z + hs * w,
        ]
        .map(|v| v as f32);
        out.scales[i] = g.scales[i].map(|v| (v as f64 + s.ln()) as f32);
    }
    out
}

/// Cloud `g` without the Gaussians `range`, with `insert` in their place.
fn splice(g: &Gaussians, range: std::ops::Range<usize>, insert: &Gaussians) -> Gaussians {
    let keep = |r: std::ops::Range<usize>| {
        let mask: Vec<bool> = (0..g.len()).map(|i| r.contains(&i)).collect();
        dreamscene::generate::object::subset(g, &mask)
    };
    merge(&[
        keep(0..range.start),
        insert.clone(),
        keep(range.end..g.len()),
    ])
}

fn render(
    ctx: &dreamscene::gpu::Context,
    g: &Gaussians,
    cam: &Camera,
) -> (Vec<[f32; 3]>, Vec<f32>) {
    let r = Rasterizer::new(ctx).unwrap();
    let out = r
        .forward(ctx, &GpuGaussians::upload(ctx, g).unwrap(), cam, [0.0; 3])
        .unwrap()
        .read()
        .unwrap();
    (out.color, out.transmittance)
}

/// The index range of instance `id` in the composed cloud (instances in scene.json order).
fn range_of(dir: &Path, id: &str) -> std::ops::Range<usize> {
    let s = read_scene(dir).unwrap();
    let mut start = 0;
    for o in &s.objects {
        let n = read_ply(&dir.join(&o.ply)).unwrap().len();
        if o.id == id {
            return start..start + n;
        }
        start += n;
    }
    panic!("no {id}")
}

/// PSNR over the pixels where `mask` is set.
fn masked_psnr(a: &[[f32; 3]], b: &[[f32; 3]], mask: &[bool]) -> f64 {
    let (mut se, mut n) = (0.0, 0usize);
    for i in (0..a.len()).filter(|&i| mask[i]) {
        for c in 0..3 {
            se += ((a[i][c] - b[i][c]) as f64).powi(2);
            n += 1;
        }
    }
    assert!(n > 0, "empty mask");
    10.0 * (1.0 / (se / n as f64).max(1e-12)).log10()
}

#[test]
fn move_renders_the_object_under_its_new_transform_refuses_collisions_and_undoes() {
    let ctx = common::gpu();
    let (d, l) = draft("move");
    let before = snapshot(&d);
    let chair0 = instance(&d, "chair1");
    let bed = l.objects.iter().find(|o| o.id == "bed1").unwrap();

    // Into the bed, and through a wall: refused, nothing changed.
    for args in [
        vec![
            "move".to_string(),
            "chair1".into(),
            "--to".into(),
            format!("{},{}", bed.position[0], bed.position[1]),
        ],
        vec!["move".into(), "chair1".into(), "--by".into(), "5,0".into()],
    ] {
        let a: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
        let o = edit(&d, &a);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success());
        assert!(err.starts_with("error: refused: chair1 would "), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(snapshot(&d) == before, "a refused move changed files");
        assert!(!d.join("history").exists() && !d.join(".edit").exists());
    }

    // A free pose (searched here with the layout's own boxes): shift, turn 30°, scale 1.1.
    let (yaw, s) = (chair0.yaw + 30.0, 1.1);
    let size = [0.45 * s, 0.45 * s, 0.85 * s];
    let others: Vec<Box2> = l
        .objects
        .iter()
        .filter(|o| o.id != "chair1")
        .map(Box2::of)
        .collect();
    let free = |x: f64, y: f64| {
        let b = Box2::new([x, y], yaw, [size[0], size[1]], 0.0, size[2]);
        let inside = b
            .corners()
            .iter()
            .all(|c| c[0].abs() < 1.7 && c[1].abs() < 1.4);
        inside && others.iter().all(|o| penetration(&b, o) < 0.0)
    };
    let mut target = None;
    'search: for r in 1..20 {
        for k in 0..16 {
            let a = k as f64 * std::f64::consts::TAU / 16.0;
            let (x, y) = (
                chair0.position[0] + 0.1 * r as f64 * a.cos(),
                chair0.position[1] + 0.1 * r as f64 * a.sin(),
            );
            if free(x, y) {
                target = Some([x, y]);
                break 'search;
            }
        }
    }
    let [x, y] = target.expect("a free pose for the chair");
    let o = edit(
        &d,
        &[
            "move",
            "chair1",
            "--to",
            &format!("{x},{y}"),
            "--rotate",
            "30",
            "--scale",
            "1.1",
        ],
    );
    ok(&o);
    let chair = instance(&d, "chair1");
    assert!((chair.position[0] - x).abs() < 1e-12 && (chair.yaw - yaw).abs() < 1e-9);
    assert!(d.join("history/0001/scene.ply").is_file());

    // The scene after the edit against the scene before with the chair's Gaussians replaced by
    // the chair PLY under the new transform (placed by this test), on the chair's pixels.
    let after = read_ply(&d.join("scene.ply")).unwrap();
    let old = {
        let p = tmp("move-old").join("scene.ply");
        std::fs::write(&p, &before["scene.ply"]).unwrap();
        read_ply(&p).unwrap()
    };
    let obj = read_ply(&d.join("objects/chair.ply")).unwrap();
    let mine = place_here(&obj, yaw, s, chair.position);
    let reference = splice(&old, range_of(&d, "chair1"), &mine);
    // A draft's environment is re-lit for the layout it is composed with (the chair's contact
    // shadow goes with it): the reference's environment is the unlit environment.ply lit for the
    // scene after the move, in place of the one lit for the scene before.
    let reference = {
        let s = read_scene(&d).unwrap();
        let clouds: BTreeMap<String, Gaussians> = s
            .objects
            .iter()
            .map(|o| (o.ply.clone(), read_ply(&d.join(&o.ply)).unwrap()))
            .collect();
        let mut env = read_ply(&d.join("environment.ply")).unwrap();
        light_draft(&s, &|rel| clouds.get(rel), &mut env);
        let n = reference.len();
        splice(&reference, n - env.len()..n, &env)
    };
    assert_eq!(after.len(), reference.len());
    let mut checked = 0;
    for k in 0..3 {
        let a = k as f64 * 2.1;
        let eye = [x + 1.6 * a.cos(), y + 1.6 * a.sin(), 1.5];
        if eye[0].abs() > 1.6 || eye[1].abs() > 1.3 {
            continue;
        }
        let cam = Camera::look_at(eye, [x, y, 0.4], [0.0, 0.0, 1.0], 96, 96, 1.0);
        let (_, alone_t) = render(&ctx, &mine, &cam);
        let mask: Vec<bool> = alone_t.iter().map(|t| *t < 0.5).collect();
        if mask.iter().filter(|m| **m).count() < 50 {
            continue;
        }
        let (ca, _) = render(&ctx, &after, &cam);
        let (cr, _) = render(&ctx, &reference, &cam);
        let (co, _) = render(&ctx, &old, &cam);
        let p = masked_psnr(&ca, &cr, &mask);
        let moved = masked_psnr(&ca, &co, &mask);
        println!(
            "move: {p:.1} dB against the independent placement ({moved:.1} dB against before)"
        );
        assert!(p >= 50.0, "{p:.1} dB");
        assert!(
            moved < 30.0,
            "the chair did not move on screen ({moved:.1} dB)"
        );
        checked += 1;
    }
    assert!(checked >= 1, "no view saw the chair");
    // The preview view was rendered from the new scene.
    assert!(d.join("renders/view.png").is_file());

    // Undo: every file as it was, byte for byte; the record gone.
    let o = edit(&d, &["undo"]);
    ok(&o);
    let now = snapshot(&d);
    assert_eq!(
        now.keys().collect::<Vec<_>>(),
        before.keys().collect::<Vec<_>>()
    );
    for (k, v) in &before {
        assert!(&now[k] == v, "{k} differs after undo");
    }
    assert!(!d.join("history/0001").exists());
    let o = edit(&d, &["undo"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("nothing to undo"));
}

#[test]
fn add_places_a_free_object_next_to_another_and_remove_takes_it_out() {
    let (d, _) = draft("add");
    let before = std::fs::read(d.join("scene.ply")).unwrap();
    let n0 = read_ply(&d.join("scene.ply")).unwrap().len();
    let o = edit(
        &d,
        &["add", "a tall floor lamp", "--near", "bed1", "--no-render"],
    );
    ok(&o);
    let s = read_scene(&d).unwrap();
    let lamp = s
        .objects
        .iter()
        .find(|o| o.id == "floor lamp1")
        .expect("added");
    let l: Layout =
        serde_json::from_str(&std::fs::read_to_string(d.join("layout.json")).unwrap()).unwrap();
    let lb = l.objects.iter().find(|o| o.id == "floor lamp1").unwrap();
    let bed = l.objects.iter().find(|o| o.id == "bed1").unwrap();
    assert!(
        relation_holds(lb, RelationKind::Next, bed),
        "not next to the bed"
    );
    for other in l.objects.iter().filter(|o| o.id != lb.id) {
        let p = penetration(&Box2::of(lb), &Box2::of(other));
        assert!(p <= 0.01, "overlaps {} by {p:.3} m", other.id);
    }
    let wd = dreamscene::plan::check::wall_distances(&Box2::of(lb), l.room.size);
    assert!(wd.iter().all(|w| *w >= -0.01), "outside the room: {wd:?}");
    // Its Gaussians are in scene.ply, placed as scene.json says.
    let scene = read_ply(&d.join("scene.ply")).unwrap();
    let obj = read_ply(&d.join(&lamp.ply)).unwrap();
    assert_eq!(scene.len(), n0 + obj.len());
    let mine = place_here(&obj, lamp.yaw, 1.0, lamp.position);
    let r = range_of(&d, "floor lamp1");
    for (a, b) in scene.means[r].iter().zip(&mine.means) {
        assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-5));
    }
    // Remove: its Gaussians gone (scene.ply is the composition before the add, byte for byte)
    // and its PLY removed (no other instance uses it).
    let o = edit(&d, &["remove", "floor lamp1", "--no-render"]);
    ok(&o);
    assert!(std::fs::read(d.join("scene.ply")).unwrap() == before);
    assert!(!d.join(&lamp.ply).exists());
    assert_eq!(read_scene(&d).unwrap().history.len(), 2);
    // An unknown category is a one-line error.
    let o = edit(&d, &["add", "a flux capacitor", "--no-render"]);
    assert!(!o.status.success());
    assert_eq!(String::from_utf8_lossy(&o.stderr).lines().count(), 1);
    // A count is that many edits, one instance each; undo takes back the last.
    let o = edit(&d, &["add", "two floor lamps", "--no-render"]);
    ok(&o);
    let s = read_scene(&d).unwrap();
    let lamps = |s: &dreamscene::scene::dir::SceneFile| {
        s.objects
            .iter()
            .filter(|o| o.category == "floor lamp")
            .count()
    };
    assert_eq!(lamps(&s), 2, "two lamps added");
    assert_eq!(s.history.len(), 4, "one edit a lamp");
    ok(&edit(&d, &["undo"]));
    assert_eq!(lamps(&read_scene(&d).unwrap()), 1, "undo takes back one");
}

/// What `add` places is held up as the plan holds it up: a mirror and a wall clock hang on a
/// wall at their heights (their drawings with no foot down to the floor), a table lamp stands on
/// the nightstand, not on the floor.
#[test]
fn add_hangs_wall_things_and_puts_a_lamp_on_its_support() {
    let (d, _) = draft("add-mount");
    for (text, id) in [
        ("a mirror", "mirror1"),
        ("a wall clock", "wall clock1"),
        ("a table lamp", "table lamp1"),
    ] {
        ok(&edit(&d, &["add", text, "--no-render"]));
        let l: Layout =
            serde_json::from_str(&std::fs::read_to_string(d.join("layout.json")).unwrap()).unwrap();
        let o = l.objects.iter().find(|o| o.id == id).expect("added");
        let b = Box2::of(o);
        let wd = dreamscene::plan::check::wall_distances(&b, l.room.size);
        let r = range_of(&d, id);
        let scene = read_ply(&d.join("scene.ply")).unwrap();
        let low = scene.means[r].iter().map(|m| m[2]).fold(f32::MAX, f32::min);
        if id == "table lamp1" {
            let ns = l.objects.iter().find(|o| o.id == "nightstand1").unwrap();
            let nb = Box2::of(ns);
            let q = nb.local([o.position[0], o.position[1]]);
            assert!(
                (o.position[2] - ns.size[2]).abs() < 0.02
                    && q[0].abs() <= nb.half[0]
                    && q[1].abs() <= nb.half[1],
                "the lamp stands on the nightstand: {:?} (nightstand at {:?})",
                o.position,
                ns.position
            );
        } else {
            assert!(o.position[2] > 0.9, "{id} hangs: z = {}", o.position[2]);
            let near = wd.iter().cloned().fold(f64::MAX, f64::min);
            assert!(near < 0.05, "{id} on a wall: {wd:?}");
            assert!(low > 0.8, "{id}'s drawing reaches down to {low} m");
        }
    }
}

/// Exports instance `id` alone (`export --only`, scene frame, PLY) and reads it back.
fn export_only(dir: &Path, id: &str) -> (Gaussians, dreamscene::splat::ply::Labels) {
    let out = dir.with_extension("only.ply");
    let o = Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .arg("export")
        .arg(dir)
        .args(["--format", "ply", "--scene-frame", "--only", id, "--out"])
        .arg(&out)
        .output()
        .unwrap();
    ok(&o);
    let (g, l) = dreamscene::splat::ply::read_ply_labelled(&out).unwrap();
    (g, l.expect("the export keeps the labels"))
}

/// After an edit, scene.ply's labels and labels.json describe scene.json as it now is: instance
/// k is scene.json's k-th object with a block of its object PLY's size, and exporting one id
/// gives exactly that object's PLY under its transform (placed by this test).
fn labels_follow_scene_json(d: &Path) {
    let s = read_scene(d).unwrap();
    let (cloud, labels) = dreamscene::splat::ply::read_ply_labelled(&d.join("scene.ply")).unwrap();
    let labels = labels.expect("scene.ply keeps instance_id and semantic_id");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("labels.json")).unwrap()).unwrap();
    let listed = json["instances"].as_array().unwrap();
    assert_eq!(listed.len(), s.objects.len() + 1, "labels.json: {json}");
    let mut start = 0;
    for (k, o) in s.objects.iter().enumerate() {
        let n = read_ply(&d.join(&o.ply)).unwrap().len();
        let entry = &listed[k + 1];
        assert_eq!(
            entry["id"],
            o.id.as_str(),
            "labels.json lists the objects in order"
        );
        assert_eq!(entry["category"], o.category.as_str(), "{}: category", o.id);
        assert_eq!(entry["instance_id"], k + 1, "{}: instance id", o.id);
        assert_eq!(
            entry["gaussians"],
            serde_json::json!([start, n]),
            "{}",
            o.id
        );
        assert!(
            labels.instance[start..start + n]
                .iter()
                .all(|&i| usize::from(i) == k + 1),
            "{}: its block of scene.ply carries its instance id",
            o.id
        );
        start += n;
    }
    assert!(
        labels.instance[start..].iter().all(|&i| i == 0),
        "the environment is instance 0"
    );
    assert_eq!(labels.instance.len(), cloud.len(), "one label per Gaussian");
    for o in &s.objects {
        let (g, l) = export_only(d, &o.id);
        assert!(
            o.scale.iter().all(|v| (v - o.scale[0]).abs() < 1e-12),
            "{}: uniform scale",
            o.id
        );
        let mine = place_here(
            &read_ply(&d.join(&o.ply)).unwrap(),
            o.yaw,
            o.scale[0],
            o.position,
        );
        assert_eq!(g.len(), mine.len(), "{}", o.id);
        for (a, b) in g.means.iter().zip(&mine.means) {
            assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-5), "{}", o.id);
        }
        let k = s.objects.iter().position(|x| x.id == o.id).unwrap() + 1;
        assert!(
            l.instance.iter().all(|&i| usize::from(i) == k),
            "{}: export --only keeps its labels",
            o.id
        );
    }
}

#[test]
fn labels_and_labels_json_follow_add_move_remove_and_undo() {
    let (d, l) = draft("labels");
    labels_follow_scene_json(&d);
    let before = snapshot(&d);
    ok(&edit(
        &d,
        &["add", "a tall floor lamp", "--near", "bed1", "--no-render"],
    ));
    labels_follow_scene_json(&d);
    // Removing an instance before others renumbers those after it.
    ok(&edit(&d, &["remove", "nightstand1", "--no-render"]));
    labels_follow_scene_json(&d);
    // The chair turned in place where it stands free of the others' boxes.
    let chair = l.objects.iter().find(|o| o.id == "chair1").unwrap();
    let turned = Box2::new(
        chair.position[..2].try_into().unwrap(),
        chair.yaw + 90.0,
        [0.45, 0.45],
        0.0,
        0.85,
    );
    assert!(l
        .objects
        .iter()
        .filter(|o| o.id != "chair1")
        .all(|o| penetration(&turned, &Box2::of(o)) < 0.0));
    ok(&edit(
        &d,
        &["move", "chair1", "--rotate", "90", "--no-render"],
    ));
    labels_follow_scene_json(&d);
    for _ in 0..3 {
        ok(&edit(&d, &["undo"]));
    }
    labels_follow_scene_json(&d);
    assert!(snapshot(&d) == before, "undo brought back other files");
}

/// The reference scene of the oracle tests: the draft with a checkered room.
fn reference(name: &str) -> (PathBuf, Layout) {
    let (d, l) = draft(name);
    let env = d.join("environment.ply");
    let mut g = read_ply(&env).unwrap();
    common::recolour(&mut g, |p, _| {
        let cell = (p[0] / 0.5).floor() + (p[1] / 0.5).floor() + (p[2] / 0.5).floor();
        if cell.rem_euclid(2.0) < 1.0 {
            [0.8, 0.3, 0.1]
        } else {
            [0.2, 0.4, 0.8]
        }
    });
    write_ply(&env, &g).unwrap();
    // The checkered room stands for a learnt scene, not a draft: no light is baked into it.
    let mut s = read_scene(&d).unwrap();
    s.prior = dreamscene::scene::dir::Prior {
        kind: "sd".into(),
        models: Some(d.display().to_string()),
    };
    dreamscene::scene::dir::write_scene(&d, &s).unwrap();
    write_labelled_scene(&d, &s).unwrap();
    (d, l)
}

/// A copy of the reference scene generated "with" the oracle prior of it.
fn oracle_copy(refdir: &Path, name: &str) -> PathBuf {
    let d = tmp(name);
    for f in ["spec.json", "layout.json", "environment.ply", "scene.ply"] {
        std::fs::copy(refdir.join(f), d.join(f)).unwrap();
    }
    std::fs::create_dir_all(d.join("objects")).unwrap();
    for e in std::fs::read_dir(refdir.join("objects")).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, d.join("objects").join(p.file_name().unwrap())).unwrap();
    }
    let mut s = read_scene(refdir).unwrap();
    s.prior = dreamscene::scene::dir::Prior {
        kind: "oracle".into(),
        models: Some(refdir.display().to_string()),
    };
    dreamscene::scene::dir::write_scene(&d, &s).unwrap();
    d
}

/// Views of footprint `b` from above, around it.
fn floor_views(b: &Box2) -> Vec<Camera> {
    (0..4)
        .map(|k| {
            let a = 0.4 + k as f64 * std::f64::consts::FRAC_PI_2;
            let eye = [b.c[0] + 0.7 * a.cos(), b.c[1] + 0.7 * a.sin(), 1.6];
            let eye = [eye[0].clamp(-1.6, 1.6), eye[1].clamp(-1.3, 1.3), eye[2]];
            Camera::look_at(eye, [b.c[0], b.c[1], 0.0], [0.0, 0.0, 1.0], 64, 64, 0.5)
        })
        .collect()
}

#[test]
fn oracle_remove_reoptimises_the_floor_where_the_object_stood() {
    let ctx = common::gpu();
    let (refdir, l) = reference("oracle-ref");
    let d = oracle_copy(&refdir, "oracle-remove");
    let stand = l.objects.iter().find(|o| o.id == "nightstand1").unwrap();
    let foot = Box2::of(stand);
    // The floor under the nightstand was never seen while it stood there: dark, unlearnt.
    let env_path = d.join("environment.ply");
    let mut env = read_ply(&env_path).unwrap();
    let grown = Box2 {
        half: [foot.half[0] + 0.05, foot.half[1] + 0.05],
        ..foot
    };
    common::recolour(&mut env, |p, c| {
        if p[2] < 0.05 && grown.contains([p[0] as f64, p[1] as f64]) {
            [0.05, 0.05, 0.05]
        } else {
            c
        }
    });
    write_ply(&env_path, &env).unwrap();
    let s = read_scene(&d).unwrap();
    write_labelled_scene(&d, &s).unwrap();

    // The answer: the reference room with the bed and the chair only.
    let truth = {
        let mut s = read_scene(&refdir).unwrap();
        s.objects.retain(|o| o.id != "nightstand1");
        compose_scene(&refdir, &s).unwrap()
    };
    let score = |dir: &Path| {
        let mut s = read_scene(dir).unwrap();
        s.objects.retain(|o| o.id != "nightstand1");
        let g = compose_scene(dir, &s).unwrap();
        let views = floor_views(&foot);
        views
            .iter()
            .map(|c| psnr(&render(&ctx, &g, c).0, &render(&ctx, &truth, c).0))
            .sum::<f64>()
            / views.len() as f64
    };
    let before = score(&d);
    let o = edit(
        &d,
        &[
            "remove",
            "nightstand1",
            "--iterations",
            "30",
            "--resolution",
            "64",
            "--no-render",
        ],
    );
    let err = ok(&o);
    assert!(err.contains("re-optimised with the oracle prior"), "{err}");
    let after = score(&d);
    println!("oracle remove: floor region {before:.2} -> {after:.2} dB");
    assert!(
        before < 22.0,
        "the damaged floor already scores {before:.2} dB"
    );
    assert!(
        after >= 22.0,
        "floor region {after:.2} dB (from {before:.2})"
    );
    // Far from the footprint the environment is unchanged bit for bit.
    let new_env = read_ply(&env_path).unwrap();
    let far = Box2 {
        half: [foot.half[0] + 0.35, foot.half[1] + 0.35],
        ..foot
    };
    let mut same = 0;
    for i in 0..env.len() {
        if !far.contains([env.means[i][0] as f64, env.means[i][1] as f64]) {
            assert_eq!(env.means[i], new_env.means[i]);
            assert_eq!(env.sh[i * 3..i * 3 + 3], new_env.sh[i * 3..i * 3 + 3]);
            same += 1;
        }
    }
    assert!(same > env.len() / 2);
}

#[test]
fn oracle_restyle_moves_the_object_to_the_second_reference_and_freezes_the_rest() {
    let ctx = common::gpu();
    let (refdir, _) = reference("restyle-ref");
    let d = oracle_copy(&refdir, "oracle-restyle");
    let obj_path = d.join("objects/nightstand.ply");
    let first = read_ply(&obj_path).unwrap();
    let mut second = first.clone();
    common::recolour(&mut second, |p, _| {
        if p[2] > 0.3 {
            [0.1, 0.3, 0.9]
        } else {
            [0.9, 0.6, 0.1]
        }
    });
    let second_path = tmp("second").join("nightstand_blue.ply");
    write_ply(&second_path, &second).unwrap();
    let env_before = std::fs::read(d.join("environment.ply")).unwrap();
    let bed_before = std::fs::read(d.join("objects/bed.ply")).unwrap();
    let scene_before = read_ply(&d.join("scene.ply")).unwrap();
    let o = edit(
        &d,
        &[
            "restyle",
            "nightstand1",
            "a blue and orange nightstand",
            "--edit-reference",
            second_path.to_str().unwrap(),
            "--iterations",
            "120",
            "--resolution",
            "64",
            "--no-render",
        ],
    );
    ok(&o);
    let edited = read_ply(&obj_path).unwrap();
    // Held-out views: a ring the training's random views are unlikely to repeat.
    let frame = ObjectFrame {
        size: [0.45, 0.4, 0.55],
    };
    let (mut to_first, mut to_second, mut start) = (0.0, 0.0, 0.0);
    let n = 6;
    for k in 0..n {
        let phi = -180.0 + 60.0 * k as f64 + 17.0;
        let cam = orbit_camera(&frame, 5.3, 70.0, phi, 0.5, 64, None);
        let r = |g: &Gaussians| render(&ctx, g, &cam).0;
        let e = r(&edited);
        to_first += psnr(&e, &r(&first)) / n as f64;
        to_second += psnr(&e, &r(&second)) / n as f64;
        start += psnr(&r(&first), &r(&second)) / n as f64;
    }
    println!(
        "oracle restyle: to the second reference {start:.2} -> {to_second:.2} dB (to the first {to_first:.2} dB)"
    );
    assert!(
        to_second >= 22.0,
        "{to_second:.2} dB to the second reference"
    );
    assert!(to_second > to_first);
    // The rest of the scene unchanged bit for bit.
    assert!(std::fs::read(d.join("environment.ply")).unwrap() == env_before);
    assert!(std::fs::read(d.join("objects/bed.ply")).unwrap() == bed_before);
    let scene_after = read_ply(&d.join("scene.ply")).unwrap();
    let r = range_of(&d, "nightstand1");
    assert_eq!(
        scene_after.len(),
        scene_before.len() - first.len() + edited.len()
    );
    let rest = |g: &Gaussians, n: usize| -> Vec<usize> {
        (0..r.start).chain(r.start + n..g.len()).collect()
    };
    let (ia, ib) = (
        rest(&scene_before, first.len()),
        rest(&scene_after, edited.len()),
    );
    assert_eq!(ia.len(), ib.len());
    for (i, j) in ia.into_iter().zip(ib) {
        assert_eq!(scene_before.means[i], scene_after.means[j]);
        assert_eq!(scene_before.scales[i], scene_after.scales[j]);
        assert_eq!(scene_before.opacities[i], scene_after.opacities[j]);
        assert_eq!(
            scene_before.sh[i * 3],
            scene_after.sh[j * scene_after.coeffs() * 3]
        );
    }
}

fn run_cli(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_dreamscene"))
        .args(args)
        .output()
        .unwrap()
}

/// The centre of the Gaussians of `g` whose index is in `range`.
fn centre(g: &Gaussians, range: std::ops::Range<usize>) -> [f64; 3] {
    let n = range.len() as f64;
    let mut c = [0.0; 3];
    for m in &g.means[range] {
        for k in 0..3 {
            c[k] += m[k] as f64 / n;
        }
    }
    c
}

/// An animated scene plays in `export --time`, `render --time` and `video`: the exported cloud
/// at a time is the scene composed with the keyed transform (the chair 0.6 m along its track, the
/// rest where it was), renders at two times differ, and a video from one fixed camera shows the
/// object moving from frame to frame over the timeline's length.
#[test]
fn an_animated_scene_plays_in_export_render_and_video() {
    let (dir, _) = draft("anim");
    let d = dir.to_str().unwrap();
    let before = instance(&dir, "chair1");
    ok(&edit(
        &dir,
        &[
            "animate",
            "chair1",
            "move left 0.6 m",
            "--seconds",
            "1",
            "--no-render",
        ],
    ));
    // The track ends 0.6 m from where it starts (to the chair's left, in the floor plane).
    let tl = read_scene(&dir).unwrap().timeline.expect("a timeline");
    assert!((tl.duration - 1.0).abs() < 1e-9, "{}", tl.duration);

    let range = range_of(&dir, "chair1");
    let export_at = |t: &str, name: &str| -> Gaussians {
        let out = dir.join(name);
        ok(&run_cli(&[
            "export",
            d,
            "--format",
            "ply",
            "--scene-frame",
            "--time",
            t,
            "--out",
            out.to_str().unwrap(),
        ]));
        read_ply(&out).unwrap()
    };
    let g0 = export_at("0", "t0.ply");
    let g1 = export_at("1", "t1.ply");
    let still = read_ply(&dir.join("scene.ply")).unwrap();
    assert_eq!(g0.len(), still.len());
    let (c0, c1, cs) = (
        centre(&g0, range.clone()),
        centre(&g1, range.clone()),
        centre(&still, range.clone()),
    );
    let dist = |a: [f64; 3], b: [f64; 3]| {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    };
    assert!(
        dist(c0, cs) < 1e-4,
        "t = 0 is the static pose: {c0:?} vs {cs:?}"
    );
    assert!(
        (dist(c0, c1) - 0.6).abs() < 0.02,
        "the chair moved {:.3} m, not 0.6 m",
        dist(c0, c1)
    );
    assert!((c1[2] - c0[2]).abs() < 1e-4, "the move stays on the floor");
    // Left of a chair at yaw ψ is (−cos ψ, −sin ψ).
    let yaw = before.yaw.to_radians();
    let along = (c1[0] - c0[0]) * -yaw.cos() + (c1[1] - c0[1]) * -yaw.sin();
    assert!(along > 0.55, "moved {along:.3} m to the chair's left");
    // Everything that is not the chair stays bit for bit.
    let others = |g: &Gaussians| -> Vec<[f32; 3]> {
        (0..g.len())
            .filter(|i| !range.contains(i))
            .map(|i| g.means[i])
            .collect()
    };
    assert!(others(&g1) == others(&still), "static parts moved");
    // Without --time the engine-ready glb keeps the motion: each instance's node holds its own
    // splats and collider, the navmesh is there, and chair1's node has an animation over the
    // timeline's frames, valid glTF (the validator also checks that the accessors' bounds are
    // their data), its translations the track's positions in glTF's y-up frame
    // ((x, y, z) -> (x, z, -y)).
    export_support::require_readers();
    let glb = dir.join("anim.glb");
    ok(&run_cli(&[
        "export",
        d,
        "--format",
        "glb",
        "--out",
        glb.to_str().unwrap(),
    ]));
    let bytes = std::fs::read(&glb).unwrap();
    export_support::assert_renamed_validates_clean(&bytes, &dir.join("anim-renamed.glb"));
    let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
    let nodes = doc["nodes"].as_array().unwrap();
    let chair = nodes
        .iter()
        .position(|n| n["name"] == "chair1")
        .expect("a chair1 node");
    let named = |n: &str| nodes.iter().position(|x| x["name"] == n);
    let children = |i: usize| -> Vec<String> {
        nodes[i]["children"]
            .as_array()
            .map(|c| {
                c.iter()
                    .map(|k| nodes[k.as_u64().unwrap() as usize]["name"].to_string())
                    .collect()
            })
            .unwrap_or_default()
    };
    let kids = children(chair);
    assert!(
        kids.iter().any(|k| k.contains("splats_chair1"))
            && kids.iter().any(|k| k.contains("collider_chair1")),
        "chair1's node holds its splats and collider: {kids:?}"
    );
    assert!(
        named("splats_environment").is_some(),
        "the environment's splats"
    );
    assert!(
        glb.with_extension("navmesh.obj").is_file(),
        "the navmesh OBJ is written beside the glb"
    );
    let anim = &doc["animations"][0];
    let channel = anim["channels"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["target"]["path"] == "translation")
        .unwrap();
    assert_eq!(channel["target"]["node"].as_u64(), Some(chair as u64));
    let sampler = &anim["samplers"][channel["sampler"].as_u64().unwrap() as usize];
    let input = &doc["accessors"][sampler["input"].as_u64().unwrap() as usize];
    assert_eq!(input["count"].as_u64(), Some(31), "1 s at 30 fps");
    let output = &doc["accessors"][sampler["output"].as_u64().unwrap() as usize];
    let bound = |k: &str, i: usize| output[k][i].as_f64().unwrap();
    let keys = &tl.tracks[0].keys;
    let (p0, p1) = (keys[0].position, keys[keys.len() - 1].position);
    for (i, (a, b)) in [(p0[0], p1[0]), (p0[2], p1[2]), (-p0[1], -p1[1])]
        .into_iter()
        .enumerate()
    {
        assert!(
            (bound("min", i) - a.min(b)).abs() < 1e-5,
            "min {i}: {output}"
        );
        assert!(
            (bound("max", i) - a.max(b)).abs() < 1e-5,
            "max {i}: {output}"
        );
    }

    // With --time the engine-ready glb is the scene still, as it stands then: no animation,
    // chair1's node at the track's last key (y up), the root saying the time.
    let posed = dir.join("posed.glb");
    ok(&run_cli(&[
        "export",
        d,
        "--format",
        "glb",
        "--time",
        "1",
        "--out",
        posed.to_str().unwrap(),
    ]));
    let bytes = std::fs::read(&posed).unwrap();
    export_support::assert_renamed_validates_clean(&bytes, &dir.join("posed-renamed.glb"));
    let json_len = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&bytes[20..20 + json_len]).unwrap();
    assert!(doc["animations"].is_null(), "a posed glb is still");
    let nodes = doc["nodes"].as_array().unwrap();
    let root = nodes.iter().find(|n| n["name"] == "dreamscene").unwrap();
    assert_eq!(root["extras"]["time_s"].as_f64(), Some(1.0));
    assert!(root["extras"]["animated"].is_null());
    let chair = nodes.iter().find(|n| n["name"] == "chair1").unwrap();
    let tr: Vec<f64> = chair["translation"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    for (i, want) in [p1[0], p1[2], -p1[1]].into_iter().enumerate() {
        assert!((tr[i] - want).abs() < 1e-4, "chair1 at t = 1: {tr:?}");
    }
    assert!(
        nodes.iter().any(|n| n["name"] == "collider_chair1"),
        "its collider"
    );
    let o = run_cli(&[
        "export",
        d,
        "--format",
        "glb",
        "--time",
        "-1",
        "--out",
        dir.join("never.glb").to_str().unwrap(),
    ]);
    assert!(!o.status.success() && !dir.join("never.glb").exists());

    // A time is refused for a single PLY, and a negative time anywhere.
    let o = run_cli(&[
        "export",
        dir.join("t0.ply").to_str().unwrap(),
        "--format",
        "ply",
        "--time",
        "0.5",
        "--out",
        dir.join("x.ply").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let o = run_cli(&[
        "render",
        d,
        "--trajectory",
        "orbit",
        "--time",
        "-1",
        "--out",
        d,
    ]);
    assert!(!o.status.success());

    // render --time from a camera that sees the chair's path: the two times differ.
    let mut cam = Camera::look_at(
        [-0.6, -0.9, 1.7],
        [1.5, -0.9, 0.3],
        [0.0, 0.0, 1.0],
        64,
        64,
        1.2,
    );
    cam.img_name = "view".into();
    let cams = dir.join("chair_view.json");
    write_cameras(&cams, std::slice::from_ref(&cam)).unwrap();
    for (t, sub) in [("0", "r0"), ("1", "r1")] {
        ok(&run_cli(&[
            "render",
            d,
            "--cameras",
            cams.to_str().unwrap(),
            "--time",
            t,
            "--out",
            dir.join(sub).to_str().unwrap(),
        ]));
    }
    let a = image::open(dir.join("r0/view.png")).unwrap().to_rgb8();
    let b = image::open(dir.join("r1/view.png")).unwrap().to_rgb8();
    let changed = a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count();
    assert!(
        changed > 20,
        "only {changed} pixels changed between t = 0 and t = 1"
    );

    // video from four copies of that camera at 4 fps: frames at t = 0, 0.25, 0.5, 0.75 differ
    // only by the motion.
    let four: Vec<Camera> = (0..4)
        .map(|i| {
            let mut c = cam.clone();
            c.id = i;
            c.img_name = format!("f{i}");
            c
        })
        .collect();
    let fixed = dir.join("fixed.json");
    write_cameras(&fixed, &four).unwrap();
    let gif = dir.join("anim.gif");
    let o = run_cli(&[
        "video",
        d,
        "--trajectory",
        fixed.to_str().unwrap(),
        "--fps",
        "4",
        "--out",
        gif.to_str().unwrap(),
    ]);
    let err = ok(&o);
    assert!(err.contains("timeline"), "{err}");
    use image::AnimationDecoder;
    let frames: Vec<image::RgbaImage> = image::codecs::gif::GifDecoder::new(
        std::io::BufReader::new(std::fs::File::open(&gif).unwrap()),
    )
    .unwrap()
    .into_frames()
    .map(|f| f.unwrap().into_buffer())
    .collect();
    assert_eq!(frames.len(), 4);
    for w in frames.windows(2) {
        let d = w[0]
            .pixels()
            .zip(w[1].pixels())
            .filter(|(p, q)| p != q)
            .count();
        assert!(d > 5, "consecutive frames differ in only {d} pixels");
    }
}
