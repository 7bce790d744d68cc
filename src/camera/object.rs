//! Cameras around one object, as the authors' object trainer draws them: random orbits (radius,
//! polar angle, azimuth and field of view ranges, widened progressively), look-at jitter, the
//! view-direction classes of the view-dependent prompts, rings of reconstruction views, spheres
//! for the filtering score and turntables. Distances are in units of the object's size: the
//! authors' objects are normalised to about a unit cube, so every radius is multiplied by
//! [`ObjectFrame::scale`]. Never imports `ash`.
use super::Camera;
use rand::Rng;
use rand_distr::{Distribution, StandardNormal};

/// Where the object is and how large: its box `size` ([width, depth, height] in metres) rests on
/// z = 0 centred on the z axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectFrame {
    pub size: [f64; 3],
}

/// Half-diagonal of the authors' unit object (a unit cube).
const UNIT_RADIUS: f64 = 0.866;

impl ObjectFrame {
    /// The point cameras look at: the box centre.
    pub fn centre(&self) -> [f64; 3] {
        [0.0, 0.0, 0.5 * self.size[2]]
    }

    /// How much larger than the authors' unit object this one is (half-diagonal ratio).
    pub fn scale(&self) -> f64 {
        let [w, d, h] = self.size;
        (0.5 * (w * w + d * d + h * h).sqrt() / UNIT_RADIUS).max(1e-3)
    }

    /// The authors' `default_radius` (3.5) at this object's scale: the extent for learning rates.
    pub fn extent(&self) -> f64 {
        3.5 * self.scale()
    }
}

/// Ranges of the random object cameras (the authors' defaults).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrbitRanges {
    pub radius: (f64, f64),
    /// Polar angle from +z, degrees.
    pub theta: (f64, f64),
    /// Azimuth from +y (the object's front), degrees.
    pub phi: (f64, f64),
    /// Horizontal field of view, radians.
    pub fov: (f64, f64),
}

impl Default for OrbitRanges {
    fn default() -> Self {
        OrbitRanges {
            radius: (5.2, 5.5),
            theta: (45.0, 105.0),
            phi: (-180.0, 180.0),
            fov: (0.32, 0.60),
        }
    }
}

impl OrbitRanges {
    /// The ranges at `step`: widened every 500 steps from step 500 (closer cameras, wider
    /// choice of fields of view), as the authors' object trainer does.
    pub fn at_step(&self, step: u32) -> OrbitRanges {
        let mut r = *self;
        for _ in 0..(step / 500) {
            r.fov = ((r.fov.0 * 0.75).max(0.16), (r.fov.1 * 1.1).min(0.60));
            r.radius = ((r.radius.0 * 0.95).max(3.5), (r.radius.1 * 0.95).max(5.0));
        }
        r
    }
}

/// One sampled view: the camera and the angles its prompt depends on.
#[derive(Debug, Clone)]
pub struct OrbitView {
    pub camera: Camera,
    /// Azimuth in degrees, 0 in front (+y), in [−180, 180].
    pub azimuth: f64,
    /// Polar angle minus 90°: negative above the object.
    pub elevation: f64,
}

fn sph(r: f64, theta_deg: f64, phi_deg: f64) -> [f64; 3] {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    [r * t.sin() * p.sin(), r * t.sin() * p.cos(), r * t.cos()]
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// A camera at spherical coordinates around the frame's centre, square `res`, horizontal field of
/// view `fov`; `jitter` adds the authors' pose noise (centre ±0.025, target σ 0.05, up σ 0.01,
/// all at the object's scale).
#[allow(
    clippy::too_many_arguments,
    reason = "the authors' orbit parameters, one argument each"
)]
pub fn orbit_camera(
    frame: &ObjectFrame,
    radius: f64,
    theta: f64,
    phi: f64,
    fov: f64,
    res: u32,
    jitter: Option<&mut dyn rand::RngCore>,
) -> Camera {
    let k = frame.scale();
    let c = frame.centre();
    let mut eye = add(c, sph(radius * k, theta, phi));
    let mut target = c;
    let mut up = [0.0, 0.0, 1.0];
    if let Some(rng) = jitter {
        for a in 0..3 {
            eye[a] += rng.gen_range(-0.025..0.025) * k;
            let n: f64 = StandardNormal.sample(rng);
            target[a] += 0.05 * k * n;
            let n: f64 = StandardNormal.sample(rng);
            up[a] += 0.01 * n;
        }
    }
    // Square images: the horizontal and vertical fields of view agree.
    Camera::look_at(eye, target, up, res, res, fov)
}

/// `count` random training views at `step` (the ranges widened for the step).
pub fn random_views(
    frame: &ObjectFrame,
    ranges: &OrbitRanges,
    step: u32,
    count: usize,
    res: u32,
    rng: &mut impl Rng,
) -> Vec<OrbitView> {
    let r = ranges.at_step(step);
    (0..count)
        .map(|i| {
            let radius = rng.gen_range(r.radius.0..=r.radius.1);
            let theta = rng.gen_range(r.theta.0..=r.theta.1);
            let phi = rng.gen_range(r.phi.0..=r.phi.1);
            let fov = rng.gen_range(r.fov.0..=r.fov.1);
            let mut camera = orbit_camera(frame, radius, theta, phi, fov, res, Some(rng));
            camera.id = i as u32;
            camera.img_name = format!("train_{i}");
            OrbitView {
                camera,
                azimuth: phi,
                elevation: theta - 90.0,
            }
        })
        .collect()
}

/// `count` reconstruction views on the authors' four rings (polar 100°, 85°, 75°, 55° holding
/// 4 : 12 : 14 : 6 of the views, azimuths evenly spaced), radius 0.9 × 3.5, field of view 0.55.
pub fn ring_views(frame: &ObjectFrame, count: usize, res: u32) -> Vec<OrbitView> {
    const RINGS: [(f64, f64); 4] = [(100.0, 4.0), (85.0, 12.0), (75.0, 14.0), (55.0, 6.0)];
    let total: f64 = RINGS.iter().map(|r| r.1).sum();
    // Largest-remainder split of `count` over the rings.
    let mut n: Vec<usize> = RINGS
        .iter()
        .map(|r| (r.1 * count as f64 / total) as usize)
        .collect();
    let mut rest: Vec<(f64, usize)> = RINGS
        .iter()
        .enumerate()
        .map(|(i, r)| (r.1 * count as f64 / total - n[i] as f64, i))
        .collect();
    rest.sort_by(|a, b| b.0.total_cmp(&a.0));
    let missing = count - n.iter().sum::<usize>();
    for (_, i) in rest.into_iter().take(missing) {
        n[i] += 1;
    }
    let mut out = vec![];
    for (ring, &(theta, _)) in RINGS.iter().enumerate() {
        for j in 0..n[ring] {
            // Offset alternate rings by half a step so they do not line up.
            let phi = -180.0 + (j as f64 + 0.5 * (ring % 2) as f64) * 360.0 / n[ring] as f64;
            let mut camera = orbit_camera(frame, 3.15, theta, phi, 0.55, res, None);
            camera.id = out.len() as u32;
            camera.img_name = format!("recon_{:03}", out.len());
            out.push(OrbitView {
                camera,
                azimuth: phi,
                elevation: theta - 90.0,
            });
        }
    }
    out
}

/// `count` cameras on the sphere of radius 3.5 around the object, directions uniform (the
/// filtering score's views), field of view 0.55.
pub fn sphere_views(
    frame: &ObjectFrame,
    count: usize,
    res: u32,
    rng: &mut impl Rng,
) -> Vec<Camera> {
    (0..count)
        .map(|i| {
            let d: [f64; 3] = std::array::from_fn(|_| StandardNormal.sample(rng));
            let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-9);
            let theta = (d[2] / l).clamp(-1.0, 1.0).acos().to_degrees();
            let phi = d[0].atan2(d[1]).to_degrees();
            let mut c = orbit_camera(frame, 3.5, theta, phi, 0.55, res, None);
            c.id = i as u32;
            c.img_name = format!("score_{i:02}");
            c
        })
        .collect()
}

/// A turntable: `count` views at polar angle `theta` (degrees), starting in front.
pub fn turntable(frame: &ObjectFrame, count: usize, theta: f64, res: u32) -> Vec<Camera> {
    (0..count)
        .map(|i| {
            let phi = 360.0 * i as f64 / count.max(1) as f64;
            let mut c = orbit_camera(frame, 4.0, theta, phi, 0.55, res, None);
            c.id = i as u32;
            c.img_name = format!("turntable_{i:03}");
            c
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn cameras_look_at_the_object_and_fit_it() {
        let f = ObjectFrame {
            size: [2.0, 1.0, 0.8],
        };
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
        let views = random_views(&f, &OrbitRanges::default(), 0, 64, 64, &mut rng);
        for v in &views {
            let (r, t) = v.camera.world_to_camera();
            let c = f.centre();
            let z: f64 = (0..3).map(|a| r[2][a] * c[a]).sum::<f64>() + t[2];
            assert!(z > 2.0 * f.scale(), "centre in front of the camera: {z}");
            assert!((-180.0..=180.0).contains(&v.azimuth));
            assert!((-45.0..=15.0).contains(&v.elevation));
        }
        // Azimuth 0 looks at the front: the camera is on the +y side.
        let c = orbit_camera(&f, 5.0, 90.0, 0.0, 0.5, 32, None);
        assert!(c.position[1] > 4.0 * f.scale() && c.position[0].abs() < 1e-9);
        assert_eq!(ring_views(&f, 20, 32).len(), 20);
        assert_eq!(ring_views(&f, 36, 32).len(), 36);
        let w = OrbitRanges::default().at_step(1500);
        assert!((w.fov.0 - 0.16).abs() < 1e-9 && (w.radius.1 - 5.0).abs() < 1e-9);
    }
}
