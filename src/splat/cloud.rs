//! A Gaussian cloud in the INRIA 3DGS parameterisation: raw (pre-activation) parameters.
use rand::Rng;

/// SH coefficients per colour channel for a degree.
pub fn sh_coeffs(degree: u32) -> usize {
    ((degree + 1) * (degree + 1)) as usize
}

/// Gaussians with raw parameters: `scales` are log-scales (activation exp), `opacities` logits
/// (activation sigmoid), `rotations` quaternions (w, x, y, z), normalised at use. `sh` holds
/// `sh_coeffs(sh_degree)` coefficients x 3 channels per Gaussian, laid out `[gaussian][coeff][rgb]`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Gaussians {
    pub means: Vec<[f32; 3]>,
    pub scales: Vec<[f32; 3]>,
    pub rotations: Vec<[f32; 4]>,
    pub opacities: Vec<f32>,
    pub sh: Vec<f32>,
    pub sh_degree: u32,
}

/// The zeroth SH basis constant: colour = C0 * dc + 0.5.
pub const SH_C0: f64 = 0.282_094_791_773_878_14;

impl Gaussians {
    /// Number of Gaussians.
    pub fn len(&self) -> usize {
        self.means.len()
    }

    /// True when there are none.
    pub fn is_empty(&self) -> bool {
        self.means.is_empty()
    }

    /// Coefficients per channel.
    pub fn coeffs(&self) -> usize {
        sh_coeffs(self.sh_degree)
    }

    /// Checks that all arrays agree in length.
    pub fn check(&self) -> Result<(), String> {
        let n = self.len();
        if self.scales.len() != n || self.rotations.len() != n || self.opacities.len() != n {
            return Err(format!(
                "inconsistent Gaussian arrays: {n} means, {} scales, {} rotations, {} opacities",
                self.scales.len(),
                self.rotations.len(),
                self.opacities.len()
            ));
        }
        if self.sh_degree > 3 {
            return Err(format!("SH degree {} (0 to 3 supported)", self.sh_degree));
        }
        if self.sh.len() != n * self.coeffs() * 3 {
            return Err(format!(
                "{} SH values for {n} Gaussians of degree {}",
                self.sh.len(),
                self.sh_degree
            ));
        }
        Ok(())
    }

    /// Random Gaussians with centres uniform in the box `[lo, hi]`, isotropic-ish scales around
    /// `scale`, random rotations, opacities in (0.1, 0.9) and random colours.
    pub fn random(
        rng: &mut impl Rng,
        n: usize,
        lo: [f32; 3],
        hi: [f32; 3],
        scale: f32,
        sh_degree: u32,
    ) -> Gaussians {
        let k = sh_coeffs(sh_degree);
        let mut g = Gaussians {
            sh_degree,
            ..Default::default()
        };
        for _ in 0..n {
            g.means
                .push([0, 1, 2].map(|i| rng.gen_range(lo[i]..=hi[i])));
            g.scales
                .push([0, 1, 2].map(|_| (scale * rng.gen_range(0.5f32..1.5)).ln()));
            let q = [0, 1, 2, 3].map(|_| rng.gen_range(-1.0f32..1.0));
            g.rotations.push(q);
            let o: f32 = rng.gen_range(0.1..0.9);
            g.opacities.push((o / (1.0 - o)).ln());
            for c in 0..k {
                for _ in 0..3 {
                    let v = if c == 0 {
                        rng.gen_range(-1.5f32..1.5)
                    } else {
                        rng.gen_range(-0.3f32..0.3)
                    };
                    g.sh.push(v);
                }
            }
        }
        g
    }
}
