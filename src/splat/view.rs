//! Rendering a scene larger than one storage binding allows (a classroom of 48 desks and chairs
//! is 3.2 million Gaussians; the rasterizer's per-Gaussian projection record is 48 bytes, and
//! lavapipe binds 128 MiB): such a scene is rendered per view from the Gaussians that view can
//! see, and when even those are too many, from the ones that matter most.
use super::cloud::Gaussians;
use super::raster::GpuGaussians;
use crate::camera::Camera;
use crate::gpu::{Context, Result};

/// The most bytes the rasterizer keeps per Gaussian in one buffer (the projection record).
const PROJECTED_BYTES: u64 = 48;

/// How many Gaussians one render can take on `ctx`'s device.
pub fn max_gaussians(ctx: &Context, g: &Gaussians) -> usize {
    most_in(ctx.info().max_storage_buffer_range, g.sh_degree)
}

/// How many Gaussians of SH degree `sh_degree` one storage binding of `limit` bytes takes: its
/// largest per-Gaussian array is the projection record or the SH coefficients.
fn most_in(limit: u64, sh_degree: u32) -> usize {
    let per = PROJECTED_BYTES.max(super::cloud::sh_coeffs(sh_degree) as u64 * 12);
    (limit / per) as usize
}

/// Refuses to train `n` Gaussians of SH degree `sh_degree` at once on a device whose storage
/// bindings hold `limit` bytes, when one of their arrays would not fit: one clear error before
/// anything is uploaded, rather than a buffer's name in the middle of a stage.
pub fn check_trainable(n: usize, sh_degree: u32, limit: u64) -> Result<()> {
    let most = most_in(limit, sh_degree);
    if n > most {
        return Err(crate::gpu::GpuError::TooManyToTrain { n, most, limit });
    }
    Ok(())
}

/// The indices of the Gaussians `cam` may see: centre in front of it (less three of its
/// largest standard deviations) and its three-sigma disc within the image widened by a tenth.
/// When more than `max` remain, the `max` of most opacity times extent are kept (ties by index,
/// so the choice is deterministic).
pub fn visible(g: &Gaussians, cam: &Camera, max: usize) -> Vec<usize> {
    let (r, t) = cam.world_to_camera();
    let half_w = cam.width as f64 * 0.55;
    let half_h = cam.height as f64 * 0.55;
    let mut keep: Vec<usize> = (0..g.len())
        .filter(|&i| {
            let m = g.means[i].map(f64::from);
            let c = [0, 1, 2].map(|k| r[k][0] * m[0] + r[k][1] * m[1] + r[k][2] * m[2] + t[k]);
            let s = g.scales[i].iter().fold(f32::MIN, |a, &b| a.max(b));
            let rad = 3.0 * f64::from(s).exp();
            if c[2] + rad <= 0.0 {
                return false;
            }
            let z = c[2].max(1e-3);
            (c[0].abs() - rad) * cam.fx / z <= half_w && (c[1].abs() - rad) * cam.fy / z <= half_h
        })
        .collect();
    if keep.len() > max {
        let weight = |i: usize| {
            let o = 1.0 / (1.0 + (-f64::from(g.opacities[i])).exp());
            let s: f32 = g.scales[i].iter().sum();
            o * f64::from(s).exp()
        };
        keep.sort_by(|&a, &b| weight(b).total_cmp(&weight(a)).then(a.cmp(&b)));
        keep.truncate(max);
        keep.sort_unstable();
    }
    keep
}

/// The Gaussians at `idx`, in that order.
pub fn select(g: &Gaussians, idx: &[usize]) -> Gaussians {
    let k = super::cloud::sh_coeffs(g.sh_degree) * 3;
    Gaussians {
        means: idx.iter().map(|&i| g.means[i]).collect(),
        scales: idx.iter().map(|&i| g.scales[i]).collect(),
        rotations: idx.iter().map(|&i| g.rotations[i]).collect(),
        opacities: idx.iter().map(|&i| g.opacities[i]).collect(),
        sh: idx
            .iter()
            .flat_map(|&i| g.sh[i * k..(i + 1) * k].iter().copied())
            .collect(),
        sh_degree: g.sh_degree,
    }
}

/// A scene's Gaussians on the device for one view after another: uploaded once when the whole
/// scene fits one render, else the part each view can see.
pub struct ViewSource<'a> {
    g: &'a Gaussians,
    max: usize,
    uploaded: Option<GpuGaussians>,
}

impl<'a> ViewSource<'a> {
    /// A source of `g` for `ctx`'s device.
    pub fn new(ctx: &Context, g: &'a Gaussians) -> ViewSource<'a> {
        ViewSource {
            g,
            max: max_gaussians(ctx, g),
            uploaded: None,
        }
    }

    /// Whether views are rendered from parts of the scene (it is too large for one render).
    pub fn split(&self) -> bool {
        self.g.len() > self.max
    }

    /// The Gaussians to render `cam` from.
    pub fn for_camera(&mut self, ctx: &Context, cam: &Camera) -> Result<&GpuGaussians> {
        let split = self.split();
        Ok(match (split, self.uploaded.take()) {
            (false, Some(whole)) => self.uploaded.insert(whole),
            (false, None) => self.uploaded.insert(GpuGaussians::upload(ctx, self.g)?),
            (true, _) => {
                let part = select(self.g, &visible(self.g, cam, self.max));
                self.uploaded.insert(GpuGaussians::upload(ctx, &part)?)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        // at the origin looking down +z (the world-to-camera rotation is the identity)
        Camera {
            id: 0,
            img_name: "v".into(),
            width: 100,
            height: 100,
            position: [0.0; 3],
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            fx: 100.0,
            fy: 100.0,
        }
    }

    fn cloud(means: &[[f32; 3]], opacity: &[f32]) -> Gaussians {
        Gaussians {
            means: means.to_vec(),
            scales: vec![[(0.01f32).ln(); 3]; means.len()],
            rotations: vec![[1.0, 0.0, 0.0, 0.0]; means.len()],
            opacities: opacity.to_vec(),
            sh: (0..means.len() * 3).map(|i| i as f32).collect(),
            sh_degree: 0,
        }
    }

    #[test]
    fn training_more_than_one_binding_holds_is_one_clear_error() {
        let limit: u64 = 128 << 20;
        // Degree 0: the 48-byte projection record bounds it.
        let most = (limit / 48) as usize;
        assert!(check_trainable(most, 0, limit).is_ok(), "{most} fit");
        let e = check_trainable(most + 1, 0, limit)
            .expect_err("one too many")
            .to_string();
        let says = [&(most + 1).to_string(), &most.to_string(), "128 MiB"];
        assert!(says.iter().all(|w| e.contains(w)), "{e}");
        // Degree 3: 16 coefficients of 3 colours, 192 bytes, bound it first.
        assert!(check_trainable(most / 4, 3, limit).is_ok(), "degree 3 fits");
        assert!(check_trainable(most / 4 + 1, 3, limit).is_err(), "degree 3");
    }

    #[test]
    fn keeps_what_the_view_sees_and_the_strongest_when_capped() {
        // in view; behind the camera; far to the side; in view near the edge; in view, faint
        let g = cloud(
            &[
                [0.0, 0.0, 2.0],
                [0.0, 0.0, -2.0],
                [5.0, 0.0, 1.0],
                [0.9, 0.9, 2.0],
                [0.1, 0.0, 3.0],
            ],
            &[2.0, 2.0, 2.0, 1.0, -3.0],
        );
        let cam = camera();
        assert_eq!(visible(&g, &cam, 10), vec![0, 3, 4], "the three in view");
        assert_eq!(visible(&g, &cam, 2), vec![0, 3], "the faint one goes first");
        let s = select(&g, &[3, 0]);
        assert_eq!(
            s.means,
            vec![[0.9, 0.9, 2.0], [0.0, 0.0, 2.0]],
            "order kept"
        );
        assert_eq!(s.sh, vec![9.0, 10.0, 11.0, 0.0, 1.0, 2.0], "colours follow");
        assert!(s.check().is_ok(), "a consistent cloud");
    }
}
