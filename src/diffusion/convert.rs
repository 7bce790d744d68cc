//! Host-side conversions at the boundary of the models: f32 ↔ f16 (with `half`'s slice
//! conversions, which use the CPU's F16C instructions where it has them), the finiteness check of
//! outputs, and the image layout changes between the renderer (`h × w × 3`, [0, 1]) and the
//! autoencoder (`3 × h × w`, [−1, 1]). Each writes one allocation (or a buffer the caller keeps)
//! and splits large tensors into chunks that run in parallel; results are bit for bit those of
//! the element-wise definitions.
use half::f16;
use half::slice::HalfFloatSliceExt as _;
use rayon::prelude::*;

/// Elements one parallel task converts: large enough that a task's overhead is noise, small
/// enough that a 512² batch (3 MB a view) spreads over the cores.
const CHUNK: usize = 1 << 16;

/// Below this many elements a conversion runs on the calling thread: a UNet run's latents or
/// outputs (≤ 0.2 M values at 512²) take well under a millisecond, less than waking the pool costs
/// on a loaded machine.
const PARALLEL_FROM: usize = 1 << 18;

/// Whether work over `elements` values is worth the thread pool (a 512² view is; a UNet run's
/// latents or a 16² test render are not).
pub fn worth_parallel(elements: usize) -> bool {
    elements >= PARALLEL_FROM
}

/// `f` over matching chunks of `out` and `src`, in parallel when the tensor is large.
fn chunked<A: Send, B: Sync>(out: &mut [A], src: &[B], f: impl Fn(&mut [A], &[B]) + Sync) {
    if !worth_parallel(src.len()) {
        f(out, src);
    } else {
        out.par_chunks_mut(CHUNK)
            .zip(src.par_chunks(CHUNK))
            .for_each(|(o, s)| f(o, s));
    }
}

/// `src` rounded to f16 (round to nearest even, as `f16::from_f32`).
pub fn f32_to_f16(src: &[f32]) -> Vec<f16> {
    let mut out = vec![f16::ZERO; src.len()];
    chunked(&mut out, src, |o, s| o.convert_from_f32_slice(s));
    out
}

/// `src` widened to f32.
pub fn f16_to_f32(src: &[f16]) -> Vec<f32> {
    let mut out = vec![0.0f32; src.len()];
    chunked(&mut out, src, |o, s| s.convert_to_f32_slice(o));
    out
}

/// Whether every value is finite.
pub fn all_finite(v: &[f32]) -> bool {
    if !worth_parallel(v.len()) {
        return v.iter().all(|x| x.is_finite());
    }
    v.par_chunks(CHUNK).all(|c| c.iter().all(|x| x.is_finite()))
}

/// Renderer layout (`h × w × 3`, [0, 1]) → model layout (`3 × h × w`, [−1, 1]) into `out`
/// (`3 w h` values), bands of each colour plane in parallel.
pub fn hwc01_to_chw11_into(rgb: &[f32], w: usize, h: usize, out: &mut [f32]) {
    let np = (w * h).max(1);
    if !worth_parallel(3 * np) {
        for (c, plane) in out.chunks_mut(np).take(3).enumerate() {
            for (o, px) in plane.iter_mut().zip(rgb.chunks_exact(3)) {
                *o = 2.0 * px[c] - 1.0;
            }
        }
        return;
    }
    let band = CHUNK / 4;
    out.par_chunks_mut(np)
        .take(3)
        .enumerate()
        .for_each(|(c, plane)| {
            plane
                .par_chunks_mut(band)
                .enumerate()
                .for_each(|(k, part)| {
                    let px = rgb.chunks_exact(3).skip(k * band);
                    for (o, px) in part.iter_mut().zip(px) {
                        *o = 2.0 * px[c] - 1.0;
                    }
                });
        });
}

/// Model layout (`3 × h × w`, [−1, 1]) → renderer layout (`h × w × 3`, [0, 1], clamped), in
/// parallel over bands of rows.
pub fn chw11_to_hwc01(img: &[f32], w: usize, h: usize) -> Vec<f32> {
    let np = w * h;
    let mut out = vec![0.0f32; 3 * np];
    if img.len() < 3 * np {
        return out;
    }
    let (r, rest) = img.split_at(np);
    let (g, b) = rest.split_at(np);
    let band = w.max(1) * 16;
    let convert = |(k, px): (usize, &mut [f32])| {
        let at = k * band;
        for (i, p) in px.chunks_exact_mut(3).enumerate() {
            let j = at + i;
            for (o, v) in p.iter_mut().zip([r[j], g[j], b[j]]) {
                *o = ((v + 1.0) * 0.5).clamp(0.0, 1.0);
            }
        }
    };
    if worth_parallel(3 * np) {
        out.par_chunks_mut(3 * band).enumerate().for_each(convert);
    } else {
        out.chunks_mut(3 * band).enumerate().for_each(convert);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_match_the_element_wise_definitions() {
        // Past several chunks, with values that round differently in f16 and the edges.
        let n = PARALLEL_FROM + 3 * CHUNK + 17;
        let v: Vec<f32> = (0..n)
            .map(|i| ((i as f32) * 0.7311).sin() * 70_000.0 / (1.0 + (i % 97) as f32))
            .chain([f32::MAX, f32::MIN_POSITIVE, -0.0, 1e-8])
            .collect();
        let h = f32_to_f16(&v);
        assert!(h
            .iter()
            .zip(&v)
            .all(|(a, b)| a.to_bits() == f16::from_f32(*b).to_bits()));
        let back = f16_to_f32(&h);
        assert!(back
            .iter()
            .zip(&h)
            .all(|(a, b)| a.to_bits() == b.to_f32().to_bits()));
        assert!(all_finite(&v));
        let mut bad = v.clone();
        bad[2 * CHUNK + 5] = f32::NAN;
        assert!(!all_finite(&bad));
        assert!(!all_finite(&back), "f32::MAX overflows f16 to infinity");
        assert!(all_finite(&[]));
        // The calling thread's path for small tensors gives the same bits.
        let small = &v[..1000];
        assert_eq!(f32_to_f16(small), h[..1000].to_vec());
        assert_eq!(f16_to_f32(&h[..1000]), back[..1000].to_vec());
        assert!(!all_finite(&[1.0, f32::INFINITY]));
    }

    #[test]
    fn layouts_round_trip_as_the_pixel_formulas() {
        let (w, h) = (37, 21);
        let rgb: Vec<f32> = (0..w * h * 3)
            .map(|i| ((i * 7919) % 1000) as f32 / 999.0)
            .collect();
        let mut chw = vec![f32::NAN; 3 * w * h];
        hwc01_to_chw11_into(&rgb, w, h, &mut chw);
        for p in 0..w * h {
            for c in 0..3 {
                assert_eq!(chw[c * w * h + p], 2.0 * rgb[3 * p + c] - 1.0);
            }
        }
        // Out-of-range model values are clamped.
        chw[0] = 3.0;
        chw[w * h + 1] = -3.0;
        let px = chw11_to_hwc01(&chw, w, h);
        assert_eq!(px.len(), 3 * w * h);
        assert_eq!(px[0], 1.0);
        assert_eq!(px[4], 0.0);
        for p in 0..w * h {
            for c in 0..3 {
                let want = ((chw[c * w * h + p] + 1.0) * 0.5).clamp(0.0, 1.0);
                assert_eq!(px[3 * p + c], want);
            }
        }
    }
}
