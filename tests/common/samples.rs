//! Surface samples of a drawn object, by role: the helpers the shape tests share.
use dreamscene::plan::kb::KnowledgeBase;
use dreamscene::shape::{parts, parts_mounted, Mount, Part, Role};
use rand::SeedableRng;

/// Surface samples with the role of the part each lies on.
pub type Samples = Vec<([f64; 3], Role)>;

/// `category`'s knowledge-base size and that size scaled by `k` and by `1 / k`: the three sizes
/// a shape test checks a drawing at.
pub fn sizes(category: &str, k: [f64; 3]) -> [[f64; 3]; 3] {
    let s = KnowledgeBase::builtin().object(category).unwrap().size;
    [
        s,
        [s[0] * k[0], s[1] * k[1], s[2] * k[2]],
        [s[0] / k[0], s[1] / k[1], s[2] / k[2]],
    ]
}

/// Surface samples of `category` drawn at `size` (sampling seed `seed`), those outside the size
/// box dropped as the shape prior drops them.
pub fn drawn(category: &str, size: [f64; 3], seed: u64) -> Samples {
    sampled(&parts(category, size).unwrap(), size, seed)
}

/// [`drawn`] as `description` shapes it and hung or stood as `mount` says.
pub fn drawn_mounted(
    category: &str,
    description: &str,
    size: [f64; 3],
    mount: Mount,
    seed: u64,
) -> Samples {
    sampled(
        &parts_mounted(category, size, description, mount).unwrap(),
        size,
        seed,
    )
}

fn sampled(parts: &[Part], size: [f64; 3], seed: u64) -> Samples {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let spacing = 0.004 * size.iter().cloned().fold(0.0, f64::max);
    let mut out = vec![];
    for p in parts {
        let mut s = vec![];
        p.prim.sample(spacing, &mut rng, &mut s);
        out.extend(s.iter().map(|s| (s.pos, p.role)));
    }
    let tol = 1e-6;
    out.retain(|(p, _)| {
        p[0].abs() <= size[0] / 2.0 + tol
            && p[1].abs() <= size[1] / 2.0 + tol
            && (-tol..=size[2] + tol).contains(&p[2])
    });
    out
}

/// `category`'s knowledge-base size and that size scaled by `k`.
pub fn sized(category: &str, k: [f64; 3]) -> [[f64; 3]; 2] {
    let s = KnowledgeBase::builtin().object(category).unwrap().size;
    [s, [s[0] * k[0], s[1] * k[1], s[2] * k[2]]]
}

/// Whether the samples `pts` of a face (x, z) are round: their bounding box's corners empty.
pub fn round(pts: &[[f64; 3]]) -> bool {
    let (x0, x1) = range(pts, 0);
    let (z0, z1) = range(pts, 2);
    let (xc, zc, rx, rz) = (
        0.5 * (x0 + x1),
        0.5 * (z0 + z1),
        0.5 * (x1 - x0),
        0.5 * (z1 - z0),
    );
    let corners = pts
        .iter()
        .filter(|p| (p[0] - xc).abs() > 0.8 * rx && (p[2] - zc).abs() > 0.8 * rz)
        .count();
    (rx / rz - 1.0).abs() < 0.15 && corners == 0
}

/// The sample positions of one role.
pub fn of(s: &[([f64; 3], Role)], role: Role) -> Vec<[f64; 3]> {
    s.iter()
        .filter(|(_, r)| *r == role)
        .map(|(p, _)| *p)
        .collect()
}

/// The points of `pts` that `keep` keeps.
pub fn within(pts: &[[f64; 3]], keep: impl Fn(&[f64; 3]) -> bool) -> Vec<[f64; 3]> {
    pts.iter().filter(|p| keep(p)).copied().collect()
}

/// Every sample's position.
pub fn all(s: &[([f64; 3], Role)]) -> Vec<[f64; 3]> {
    s.iter().map(|(p, _)| *p).collect()
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
