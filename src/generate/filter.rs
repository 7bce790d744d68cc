//! 3D Gaussian filtering: score every Gaussian by how much it contributes to a set of views (the
//! filtering-score kernel, in the paper's or the authors' form) and drop the lowest-scoring
//! fraction.
use crate::camera::Camera;
use crate::gpu::{Buffer, Context, Result};
use crate::splat::raster::GpuGaussians;
use crate::splat::raster::Rasterizer;
use crate::splat::score::{code_volume_weighting, ScoreRule, Scorer};

/// How to filter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilterConfig {
    pub rule: ScoreRule,
    /// Fraction of the Gaussians removed (the paper reports 66.1% in generation).
    pub fraction: f64,
    /// Views scored (the authors' code: 48 random directions on a sphere).
    pub views: usize,
}

impl Default for FilterConfig {
    fn default() -> Self {
        FilterConfig {
            rule: ScoreRule::Paper,
            fraction: 0.6,
            views: 48,
        }
    }
}

/// The score of every Gaussian of `g` summed over `cams` (white background). The code rule's
/// volume weighting `(V / V_ref)^0.1` is applied here.
pub fn scores(
    ctx: &Context,
    raster: &Rasterizer,
    g: &GpuGaussians,
    cams: &[Camera],
    rule: ScoreRule,
) -> Result<Vec<f32>> {
    let scorer = Scorer::new(ctx, false)?;
    let buf = Buffer::zeroed::<f32>(ctx, "filter scores", g.n as usize)?;
    for cam in cams {
        let frame = raster.forward(ctx, g, cam, [1.0; 3])?;
        scorer.accumulate(ctx, &frame, g, rule, &buf)?;
    }
    let s: Vec<f32> = buf.read(g.n as usize)?;
    Ok(match rule {
        ScoreRule::Paper => s,
        ScoreRule::Code => {
            let scales: Vec<[f32; 3]> = g.scales.read(g.n as usize)?;
            code_volume_weighting(&s, &scales, 0.1)
        }
    })
}

/// Which Gaussians to keep: all but the `fraction` with the lowest scores (ties at the
/// threshold go, as in the authors' `score <= threshold`; a Gaussian no view sees always goes).
pub fn keep_mask(scores: &[f32], fraction: f64) -> Vec<bool> {
    let n = scores.len();
    if n == 0 {
        return vec![];
    }
    let remove = ((fraction.clamp(0.0, 1.0) * n as f64).round() as usize).min(n);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| scores[a].total_cmp(&scores[b]).then(a.cmp(&b)));
    let mut keep = vec![true; n];
    for &i in &order[..remove] {
        keep[i] = false;
    }
    for (k, s) in keep.iter_mut().zip(scores) {
        if *s <= 0.0 || !s.is_finite() {
            *k = false;
        }
    }
    keep
}

#[cfg(test)]
mod tests {
    use super::keep_mask;

    #[test]
    fn keeps_the_highest_scores() {
        let k = keep_mask(&[0.5, 0.1, 0.9, 0.0, 0.3], 0.4);
        assert_eq!(k, vec![true, false, true, false, true]);
        // Unseen Gaussians go even when the fraction is smaller.
        assert_eq!(keep_mask(&[0.0, 1.0, 2.0], 0.0), vec![false, true, true]);
        assert!(keep_mask(&[], 0.5).is_empty());
    }
}
