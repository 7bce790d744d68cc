//! Photometric losses of 3DGS fitting on the host, with their gradients: L1, SSIM (11x11
//! Gaussian window, sigma 1.5, zero padding, as the 3DGS code computes it) and
//! `(1 - lambda) L1 + lambda (1 - SSIM)`. Images are row-major RGB in [0, 1].
use rayon::prelude::*;

const WINDOW: usize = 11;
const SIGMA: f64 = 1.5;
const C1: f64 = 0.01 * 0.01;
const C2: f64 = 0.03 * 0.03;

fn window() -> [f64; WINDOW] {
    let mut w = [0.0; WINDOW];
    let c = (WINDOW / 2) as f64;
    for (i, v) in w.iter_mut().enumerate() {
        *v = (-(i as f64 - c).powi(2) / (2.0 * SIGMA * SIGMA)).exp();
    }
    let s: f64 = w.iter().sum();
    w.map(|v| v / s)
}

/// Separable Gaussian filter with zero padding ("same" size).
fn blur(x: &[f64], w: usize, h: usize) -> Vec<f64> {
    let k = window();
    let r = WINDOW as isize / 2;
    let mut tmp = vec![0.0; w * h];
    tmp.par_chunks_mut(w).enumerate().for_each(|(y, row)| {
        for (xx, out) in row.iter_mut().enumerate() {
            let mut s = 0.0;
            for (j, kv) in k.iter().enumerate() {
                let sx = xx as isize + j as isize - r;
                if sx >= 0 && (sx as usize) < w {
                    s += kv * x[y * w + sx as usize];
                }
            }
            *out = s;
        }
    });
    let mut out = vec![0.0; w * h];
    out.par_chunks_mut(w).enumerate().for_each(|(y, row)| {
        for (xx, o) in row.iter_mut().enumerate() {
            let mut s = 0.0;
            for (j, kv) in k.iter().enumerate() {
                let sy = y as isize + j as isize - r;
                if sy >= 0 && (sy as usize) < h {
                    s += kv * tmp[sy as usize * w + xx];
                }
            }
            *o = s;
        }
    });
    out
}

/// Mean SSIM of one channel and, if asked, its gradient with respect to `x`.
fn ssim_channel(x: &[f64], y: &[f64], w: usize, h: usize, grad: bool) -> (f64, Vec<f64>) {
    let mux = blur(x, w, h);
    let muy = blur(y, w, h);
    let sq = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(p, q)| p * q).collect::<Vec<_>>();
    let exx = blur(&sq(x, x), w, h);
    let eyy = blur(&sq(y, y), w, h);
    let exy = blur(&sq(x, y), w, h);
    let n = w * h;
    let mut sum = 0.0;
    let (mut a, mut b, mut c) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for i in 0..n {
        let (mx, my) = (mux[i], muy[i]);
        let n1 = 2.0 * mx * my + C1;
        let n2 = 2.0 * (exy[i] - mx * my) + C2;
        let d1 = mx * mx + my * my + C1;
        let d2 = (exx[i] - mx * mx) + (eyy[i] - my * my) + C2;
        let s = n1 * n2 / (d1 * d2);
        sum += s;
        if grad {
            a[i] = 2.0 * my * n2 / (d1 * d2) - 2.0 * mx * s / d1 - 2.0 * n1 * my / (d1 * d2)
                + 2.0 * mx * s / d2;
            b[i] = -s / d2;
            c[i] = 2.0 * n1 / (d1 * d2);
        }
    }
    if !grad {
        return (sum / n as f64, vec![]);
    }
    // The filter is symmetric with zero padding, so it is its own adjoint.
    let (ga, gb, gc) = (blur(&a, w, h), blur(&b, w, h), blur(&c, w, h));
    let g = (0..n)
        .map(|i| (ga[i] + 2.0 * x[i] * gb[i] + y[i] * gc[i]) / n as f64)
        .collect();
    (sum / n as f64, g)
}

fn channels(img: &[[f32; 3]]) -> [Vec<f64>; 3] {
    [0, 1, 2].map(|c| img.iter().map(|p| p[c] as f64).collect())
}

/// Mean SSIM over pixels and channels.
pub fn ssim(a: &[[f32; 3]], b: &[[f32; 3]], w: usize, h: usize) -> f64 {
    let (ca, cb) = (channels(a), channels(b));
    (0..3)
        .map(|c| ssim_channel(&ca[c], &cb[c], w, h, false).0)
        .sum::<f64>()
        / 3.0
}

/// Peak signal-to-noise ratio in dB for images in [0, 1].
pub fn psnr(a: &[[f32; 3]], b: &[[f32; 3]]) -> f64 {
    let mse: f64 = a
        .iter()
        .zip(b)
        .flat_map(|(p, q)| (0..3).map(move |c| (p[c] as f64 - q[c] as f64).powi(2)))
        .sum::<f64>()
        / (3 * a.len().max(1)) as f64;
    -10.0 * mse.max(1e-20).log10()
}

/// `(1 - lambda) L1 + lambda (1 - SSIM)` of `render` against `target`, and its gradient with
/// respect to the rendered colours (`[f32; 4]` per pixel, as the backward pass reads it).
pub fn l1_dssim(
    render: &[[f32; 3]],
    target: &[[f32; 3]],
    w: usize,
    h: usize,
    lambda: f64,
) -> (f64, Vec<[f32; 4]>) {
    assert_eq!(render.len(), w * h, "the render is not w x h");
    assert_eq!(target.len(), w * h, "the target is not w x h");
    let n3 = (3 * w * h) as f64;
    let (cr, ct) = (channels(render), channels(target));
    let mut l1 = 0.0;
    let mut grad = vec![[0.0f32; 4]; w * h];
    for c in 0..3 {
        for i in 0..w * h {
            let d = cr[c][i] - ct[c][i];
            l1 += d.abs();
            grad[i][c] = ((1.0 - lambda) * d.signum() / n3) as f32;
        }
    }
    let mut s = 0.0;
    if lambda > 0.0 {
        for c in 0..3 {
            let (sc, g) = ssim_channel(&cr[c], &ct[c], w, h, true);
            s += sc / 3.0;
            for i in 0..w * h {
                grad[i][c] -= (lambda * g[i] / 3.0) as f32;
            }
        }
    }
    let loss = (1.0 - lambda) * l1 / n3 + lambda * (1.0 - s);
    (loss, grad)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn ssim_of_identical_images_is_one_and_psnr_is_high() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let a: Vec<[f32; 3]> = (0..30 * 20)
            .map(|_| [rng.gen(), rng.gen(), rng.gen()])
            .collect();
        assert!((ssim(&a, &a, 30, 20) - 1.0).abs() < 1e-12);
        assert!(psnr(&a, &a) > 150.0);
        let b: Vec<[f32; 3]> = a.iter().map(|p| p.map(|v| v + 0.1)).collect();
        assert!((psnr(&a, &b) - 20.0).abs() < 1e-3, "{}", psnr(&a, &b));
    }

    #[test]
    fn loss_gradient_matches_finite_differences() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2);
        let (w, h) = (17, 13);
        let r: Vec<[f32; 3]> = (0..w * h)
            .map(|_| [rng.gen(), rng.gen(), rng.gen()])
            .collect();
        let t: Vec<[f32; 3]> = (0..w * h)
            .map(|_| [rng.gen(), rng.gen(), rng.gen()])
            .collect();
        let lambda = 0.2;
        let (_, g) = l1_dssim(&r, &t, w, h, lambda);
        for &i in &[0usize, 5, 40, 100, w * h - 1] {
            for c in 0..3 {
                let hstep = 1e-3f32;
                let mut rp = r.clone();
                rp[i][c] += hstep;
                let mut rm = r.clone();
                rm[i][c] -= hstep;
                let fd = (l1_dssim(&rp, &t, w, h, lambda).0 - l1_dssim(&rm, &t, w, h, lambda).0)
                    / (rp[i][c] as f64 - rm[i][c] as f64);
                let a = g[i][c] as f64;
                assert!(
                    (a - fd).abs() < 1e-4 * fd.abs().max(1e-3) + 1e-7,
                    "pixel {i} channel {c}: analytic {a:e}, finite difference {fd:e}"
                );
            }
        }
    }
}
