//! The guided trainer's operations the generators rely on: a frozen index range keeps its
//! parameters bit for bit while the rest moves; raising the SH degree keeps the colours and adds
//! zero bands; retaining a mask keeps exactly those Gaussians.
mod common;
use dreamscene::camera::Camera;
use dreamscene::splat::train::{FitConfig, Trainer};
use dreamscene::splat::Gaussians;

fn scene() -> (Gaussians, Camera) {
    let mut rng = common::rng(5);
    let g = Gaussians::random(&mut rng, 400, [-1.0, -1.0, 3.0], [1.0, 1.0, 5.0], 0.08, 1);
    let cam = Camera::look_at([0.0; 3], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0], 48, 48, 1.0);
    (g, cam)
}

fn rows(g: &Gaussians, i: usize) -> Vec<f32> {
    let k3 = g.coeffs() * 3;
    let mut v = g.means[i].to_vec();
    v.extend(g.scales[i]);
    v.extend(g.rotations[i]);
    v.push(g.opacities[i]);
    v.extend(&g.sh[i * k3..(i + 1) * k3]);
    v
}

#[test]
fn frozen_range_keeps_its_parameters_while_the_rest_moves() {
    let ctx = common::gpu();
    let (g, cam) = scene();
    let mut t = Trainer::guided(
        &ctx,
        &g,
        FitConfig {
            densify: false,
            ..FitConfig::default()
        },
        1.0,
    )
    .unwrap();
    t.trainable = Some(100..300);
    for _ in 0..3 {
        let bv = t.render_view(&cam, [0.0; 3]).unwrap();
        // Pull every pixel toward white: every visible Gaussian gets a gradient.
        let grad: Vec<[f32; 3]> = bv.color.iter().map(|c| c.map(|v| v - 1.0)).collect();
        t.apply(&[bv], &[grad], None).unwrap();
    }
    let after = t.gaussians().unwrap();
    let moved = |i: usize| rows(&g, i) != rows(&after, i);
    assert!(
        (0..100).chain(300..400).all(|i| !moved(i)),
        "a frozen Gaussian moved"
    );
    let n = (100..300).filter(|&i| moved(i)).count();
    assert!(n > 100, "only {n} of 200 trainable Gaussians moved");
    ctx.check_validation().unwrap();
}

#[test]
fn sh_degree_raise_and_retain_keep_the_cloud() {
    let ctx = common::gpu();
    let (mut g, cam) = scene();
    g.sh_degree = 0;
    g.sh = (0..g.len() * 3).map(|i| (i % 7) as f32 * 0.1).collect();
    let mut t = Trainer::guided(&ctx, &g, FitConfig::default(), 1.0).unwrap();
    let before = t.render_view(&cam, [0.0; 3]).unwrap().color;
    t.set_sh_degree(2).unwrap();
    let up = t.gaussians().unwrap();
    assert_eq!((up.sh_degree, up.sh.len()), (2, g.len() * 27));
    for i in 0..g.len() {
        assert_eq!(&up.sh[i * 27..i * 27 + 3], &g.sh[i * 3..i * 3 + 3]);
        assert!(up.sh[i * 27 + 3..(i + 1) * 27].iter().all(|v| *v == 0.0));
    }
    assert_eq!(t.render_view(&cam, [0.0; 3]).unwrap().color, before);
    let keep: Vec<bool> = (0..g.len()).map(|i| i % 3 != 0).collect();
    t.retain(&keep).unwrap();
    let kept = t.gaussians().unwrap();
    let want: Vec<[f32; 3]> = (0..g.len())
        .filter(|&i| keep[i])
        .map(|i| g.means[i])
        .collect();
    assert_eq!(kept.means, want);
    ctx.check_validation().unwrap();
}
