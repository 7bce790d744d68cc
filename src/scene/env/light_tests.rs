//! Tests of the draft light: shadows and openings, the light cache against re-baking.
use super::super::openings::FRAME_W;
use super::*;

fn floor_and_wall() -> Gaussians {
    let mut g = Gaussians {
        sh_degree: 0,
        ..Default::default()
    };
    let grey = ((0.8 - 0.5) / SH_C0) as f32;
    for p in [
        [0.0, 0.0, 0.0],
        [1.8, 0.0, 0.0],
        [0.0, 2.005, 1.0],
        [1.3, 2.005, 1.2],
        [0.0, 2.005, 0.03],
        [1.5, 2.005, 0.1],
    ] {
        g.means.push(p);
        g.scales.push([-4.0; 3]);
        g.rotations.push([1.0, 0.0, 0.0, 0.0]);
        g.opacities.push(3.0);
        g.sh.extend([grey; 3]);
    }
    g
}

fn grey(g: &Gaussians, i: usize) -> f64 {
    0.5 + SH_C0 * g.sh[3 * i] as f64
}

#[test]
fn contact_shadow_falls_under_the_object_and_openings_are_drawn() {
    let mut g = floor_and_wall();
    let sofa = LitBox {
        position: [0.0, 0.0, 0.0],
        size: [2.0, 0.9, 0.8],
        yaw: 0.0,
    };
    let window = Opening {
        kind: "window".into(),
        wall: "north".into(),
        position: [1.0, 2.0, 0.9],
        width: 1.2,
        height: 1.2,
        leaf: None,
    };
    bake_light(
        &mut g,
        SceneType::Indoor,
        [5.0, 4.0, 2.8],
        &[sofa],
        std::slice::from_ref(&window),
    );
    // Under the sofa darker than the open floor; the open floor still near its colour.
    assert!(grey(&g, 0) < 0.6 * 0.8, "{}", grey(&g, 0));
    assert!(grey(&g, 1) > 0.85 * 0.8, "{}", grey(&g, 1));
    // The window pane is brighter than the plain wall beside it; the wall foot is skirting.
    assert!(
        grey(&g, 3) > grey(&g, 2),
        "{} vs {}",
        grey(&g, 3),
        grey(&g, 2)
    );
    assert!(
        grey(&g, 4) > grey(&g, 5),
        "{} vs {}",
        grey(&g, 4),
        grey(&g, 5)
    );
}

/// A 5 x 4 x 2.8 m room's floor and north wall on a jittered 5 cm grid, mid grey.
fn room_cloud() -> Gaussians {
    let mut g = Gaussians {
        sh_degree: 0,
        ..Default::default()
    };
    let grey = ((0.7 - 0.5) / SH_C0) as f32;
    let mut push = |p: [f32; 3]| {
        g.means.push(p);
        g.scales.push([-3.5; 3]);
        g.rotations.push([1.0, 0.0, 0.0, 0.0]);
        g.opacities.push(3.0);
        g.sh.extend([grey; 3]);
    };
    for i in 0..100 {
        for j in 0..80 {
            let jit = ((i * 31 + j * 17) % 7) as f32 * 0.004;
            push([
                -2.5 + 0.05 * i as f32 + jit,
                -2.0 + 0.05 * j as f32 + jit,
                0.0,
            ]);
        }
        for j in 0..56 {
            push([-2.5 + 0.05 * i as f32, 2.01, 0.05 * j as f32]);
        }
    }
    g
}

fn boxes(x: f64) -> Vec<LitBox> {
    vec![
        LitBox {
            position: [x, 0.5, 0.0],
            size: [2.0, 0.9, 0.8],
            yaw: 10.0,
        },
        LitBox {
            position: [-1.5, 1.6, 0.0],
            size: [0.8, 0.4, 1.9],
            yaw: 0.0,
        },
        LitBox {
            position: [0.0, 0.0, 0.0],
            size: [2.0, 1.4, 0.01],
            yaw: 0.0,
        },
    ]
}

#[test]
fn kept_light_gives_the_same_environment_as_baking_again() {
    let window = Opening {
        kind: "window".into(),
        wall: "north".into(),
        position: [1.0, 2.0, 0.9],
        width: 1.2,
        height: 1.2,
        leaf: None,
    };
    let room = [5.0, 4.0, 2.8];
    let openings = std::slice::from_ref(&window);
    let mut kept = DraftLight::new(room_cloud(), SceneType::Indoor, room, openings);
    let first = kept.lit(&boxes(0.0));
    // The sofa moves: only its shadow is cast again.
    let moved = kept.lit(&boxes(1.2));
    let mut fresh = room_cloud();
    bake_light(&mut fresh, SceneType::Indoor, room, &boxes(1.2), openings);
    assert_eq!(moved.means, fresh.means);
    assert_eq!(
        moved.sh, fresh.sh,
        "the kept light differs from baking again"
    );
    assert_ne!(first.sh, moved.sh, "the shadow did not move");
    // And back: the first frame again.
    assert_eq!(kept.lit(&boxes(0.0)).sh, first.sh);
}

#[test]
fn shadows_left_out_below_the_cutoff_change_no_colour_level() {
    // Against the shadow of every box applied to every point, whatever its size.
    let room = [5.0, 4.0, 2.8];
    let env = room_cloud();
    let lit = DraftLight::new(env.clone(), SceneType::Indoor, room, &[]).lit(&boxes(0.3));
    let plain = DraftLight::new(env.clone(), SceneType::Indoor, room, &[]).lit(&[]);
    let solid: Vec<LitBox> = boxes(0.3)
        .into_iter()
        .filter(|b| b.size[2] > FLAT)
        .collect();
    let mut worst = 0.0f64;
    for i in 0..env.len() {
        let p = env.means[i].map(|v| v as f64);
        let mut k = 1.0;
        for b in &solid {
            k *= 1.0
                - if matches!(surface(p, room), Surface::Floor) {
                    b.floor_shadow(b.footprint_distance(p[0], p[1]))
                } else {
                    LitBox::wall_shadow(b.distance(p))
                };
        }
        let want = (0.5 + SH_C0 * plain.sh[3 * i] as f64) * k;
        let got = 0.5 + SH_C0 * lit.sh[3 * i] as f64;
        worst = worst.max((want - got).abs());
    }
    assert!(worst < 1.0 / 255.0, "worst difference {worst}");
}

#[test]
fn an_opening_is_drawn_by_its_own_straight_edged_surfels() {
    let door = Opening {
        kind: "door".into(),
        wall: "north".into(),
        position: [-0.5, 2.0, 0.0],
        width: 0.9,
        height: 2.1,
        leaf: None,
    };
    let g = super::super::openings::surfels(&door, [5.0, 4.0, 2.8]);
    assert!(g.len() > 5000, "{} surfels", g.len());
    // In front of the wall, and every row of the grid spans the same outline.
    let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
    let mut rows: std::collections::BTreeMap<i64, (f32, f32)> = Default::default();
    for m in &g.means {
        assert!(m[1] < 2.0 && m[1] > 1.99, "{m:?}");
        lo = lo.min(m[0]);
        hi = hi.max(m[0]);
        let r = rows
            .entry((m[2] * 1e4).round() as i64)
            .or_insert((f32::MAX, f32::MIN));
        *r = (r.0.min(m[0]), r.1.max(m[0]));
    }
    for (z, (a, b)) in rows {
        assert!(
            (a - lo).abs() < 1e-5 && (b - hi).abs() < 1e-5,
            "row {z}: {a}..{b}"
        );
    }
    let outline = 0.5 * 0.9 + FRAME_W;
    assert!(
        (lo as f64 - (-0.5 - outline)).abs() < 0.012
            && (hi as f64 - (-0.5 + outline)).abs() < 0.012
    );
}

/// Blue over red of the lit wall points of `env` between heights `z0` and `z1` (white is about
/// 1, a warm timber well under it, a pale blue paint over it).
fn wall_band(env: &Gaussians, room: [f64; 3], z0: f64, z1: f64) -> f64 {
    let (mut sum, mut n) = ([0.0; 3], 0);
    for (i, m) in env.means.iter().enumerate() {
        let p = m.map(f64::from);
        let at_wall = (0.5 * room[1] - p[1].abs()).abs() < 0.02;
        if at_wall && p[2] > z0 && p[2] < z1 && p[0].abs() < 0.3 * room[0] {
            for (k, s) in sum.iter_mut().enumerate() {
                *s += 0.5 + SH_C0 * f64::from(env.sh[3 * i + k]);
            }
            n += 1;
        }
    }
    assert!(n > 10, "{n} wall points");
    sum[2] / sum[0]
}

#[test]
fn a_painted_wall_has_a_white_skirting_and_a_log_wall_none() {
    let room = [5.0, 4.0, 2.8];
    let opts = super::super::EnvOptions {
        density: 900.0,
        ..Default::default()
    };
    let lit = |text: &str| {
        let c = super::super::draft_colours(SceneType::Indoor, text);
        let mut env = super::super::init_environment(SceneType::Indoor, room, &c, &opts).env;
        bake_light(&mut env, SceneType::Indoor, room, &[], &[]);
        let (foot, above) = (
            wall_band(&env, room, 0.0, 0.07),
            wall_band(&env, room, 0.15, 0.3),
        );
        (foot, above)
    };
    // pale blue paint above a white skirting board
    let (foot, above) = lit("a kids room with a bunk bed");
    assert!(
        above > 1.1 && (foot - 0.96).abs() < 0.05,
        "painted: foot {foot:.2}, above {above:.2}"
    );
    // logs and rock run down to the floor
    for text in ["a log cabin with a wood stove", "a cave with a campfire"] {
        let (foot, above) = lit(text);
        assert!(
            (foot - above).abs() < 0.1,
            "{text}: foot {foot:.2}, above {above:.2}"
        );
    }
}
