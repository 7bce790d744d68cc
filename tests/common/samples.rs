//! Surface samples of a drawn object, by role: the helpers the shape tests share.
use dreamscene::shape::Role;

/// The sample positions of one role.
pub fn of(s: &[([f64; 3], Role)], role: Role) -> Vec<[f64; 3]> {
    s.iter()
        .filter(|(_, r)| *r == role)
        .map(|(p, _)| *p)
        .collect()
}

/// The lowest and highest coordinate of `pts` along `axis`.
pub fn range(pts: &[[f64; 3]], axis: usize) -> (f64, f64) {
    pts.iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p[axis]), hi.max(p[axis]))
        })
}

/// Runs of occupied cells (of `cell` metres) along `axis`: separate panes, pipes, rods, wheels.
pub fn runs(pts: &[[f64; 3]], axis: usize, cell: f64) -> usize {
    let mut cells: Vec<i64> = pts
        .iter()
        .map(|p| (p[axis] / cell).floor() as i64)
        .collect();
    cells.sort_unstable();
    cells.dedup();
    1 + cells.windows(2).filter(|w| w[1] - w[0] > 1).count()
}
