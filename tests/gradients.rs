//! The f64 reference backward against central finite differences of the smooth reference forward
//! (no alpha skip, no early stop, no tile culling: a differentiable function of every parameter).
mod common;
use dreamscene::camera::Camera;
use dreamscene::splat::reference::{self, Cutoffs};
use dreamscene::splat::reference_grad;
use dreamscene::splat::Gaussians;
use rand::Rng;

fn camera(w: u32, h: u32) -> Camera {
    Camera::look_at(
        [0.3, -0.2, -0.5],
        [0.0, 0.0, 3.0],
        [0.0, -1.0, 0.0],
        w,
        h,
        60f64.to_radians(),
    )
}

/// A small scene away from the kinks the smooth mode keeps: opacities below the 0.99 clamp,
/// colours above the clamp at 0, one splat beyond the Jacobian's 1.3 x fov clamp.
fn scene(seed: u64, degree: u32) -> Gaussians {
    let mut rng = common::rng(seed);
    let mut g = Gaussians::random(
        &mut rng,
        10,
        [-0.8, -0.6, 2.0],
        [0.8, 0.6, 4.0],
        0.25,
        degree,
    );
    let k = g.coeffs();
    for i in 0..g.len() {
        g.sh[i * k * 3] = rng.gen_range(0.2..1.5);
        g.sh[i * k * 3 + 1] = rng.gen_range(0.2..1.5);
        g.sh[i * k * 3 + 2] = rng.gen_range(0.2..1.5);
    }
    // Far to the side: |x/z| beyond the clamp (about 0.75 here), large enough to reach the image.
    g.means[9] = [3.0, 0.2, 3.0];
    g.scales[9] = [(1.2f32).ln(), (0.8f32).ln(), (1.0f32).ln()];
    g
}

fn loss(g: &Gaussians, cam: &Camera, bg: [f64; 3], w: &[[f64; 3]]) -> f64 {
    let img = reference::render_with(g, cam, bg, Cutoffs::Smooth);
    img.color
        .iter()
        .zip(w)
        .map(|(c, w)| c[0] * w[0] + c[1] * w[1] + c[2] * w[2])
        .sum()
}

/// Central difference of the loss in one f32 parameter, divided by the step actually taken.
fn fd(
    g: &Gaussians,
    set: &dyn Fn(&mut Gaussians, f32),
    x: f32,
    f: &dyn Fn(&Gaussians) -> f64,
) -> f64 {
    let h = 1e-3f32 * x.abs().max(1.0);
    let (xp, xm) = (x + h, x - h);
    let mut gp = g.clone();
    set(&mut gp, xp);
    let mut gm = g.clone();
    set(&mut gm, xm);
    (f(&gp) - f(&gm)) / (xp as f64 - xm as f64)
}

#[test]
fn reference_gradients_match_finite_differences() {
    for degree in [0u32, 1, 3] {
        let g = scene(40 + degree as u64, degree);
        let cam = camera(40, 30);
        let bg = [0.3, 0.6, 0.1];
        let mut rng = common::rng(7);
        let wts: Vec<[f64; 3]> = (0..40 * 30)
            .map(|_| [0, 1, 2].map(|_| rng.gen_range(-1.0..1.0)))
            .collect();
        let (_, an) = reference_grad::backward(&g, &cam, bg, &wts, Cutoffs::Smooth);
        let f = |gg: &Gaussians| loss(gg, &cam, bg, &wts);
        let mut worst: f64 = 0.0;
        let mut biggest: f64 = 0.0;
        let mut check = |what: String, a: f64, num: f64| {
            let err = (a - num).abs() / (1e-3 + num.abs().max(a.abs()));
            biggest = biggest.max(num.abs());
            assert!(
                err < 2e-3,
                "degree {degree}, {what}: analytic {a:e}, finite difference {num:e}"
            );
            worst = worst.max(err);
        };
        let k = g.coeffs();
        for i in 0..g.len() {
            for c in 0..3 {
                let num = fd(&g, &|gg, v| gg.means[i][c] = v, g.means[i][c], &f);
                check(format!("mean[{i}][{c}]"), an.means[i][c], num);
                let num = fd(&g, &|gg, v| gg.scales[i][c] = v, g.scales[i][c], &f);
                check(format!("log scale[{i}][{c}]"), an.scales[i][c], num);
            }
            for c in 0..4 {
                let num = fd(&g, &|gg, v| gg.rotations[i][c] = v, g.rotations[i][c], &f);
                check(format!("rotation[{i}][{c}]"), an.rotations[i][c], num);
            }
            let num = fd(&g, &|gg, v| gg.opacities[i] = v, g.opacities[i], &f);
            check(format!("opacity[{i}]"), an.opacities[i], num);
            for e in 0..k * 3 {
                let j = i * k * 3 + e;
                let num = fd(&g, &|gg, v| gg.sh[j] = v, g.sh[j], &f);
                check(format!("sh[{i}][{}][{}]", e / 3, e % 3), an.sh[j], num);
            }
        }
        eprintln!("degree {degree}: worst relative error {worst:e}, largest gradient {biggest:e}");
        // The scene is not degenerate: gradients are far from zero.
        assert!(biggest > 1.0, "largest gradient {biggest}");
    }
}
