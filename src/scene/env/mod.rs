//! Environment initialisation (official code facts §6): an indoor room becomes a `cuboid` of
//! four walls and a ceiling just outside the room box plus a floor at z = 0; an outdoor scene a
//! `hemisphere` of sky around the ground area plus a ground disk. Host-only (no GPU): it only
//! builds [`Gaussians`].
//!
//! The Gaussians are flat surfels lying in their surface (scale along the normal a tenth of the
//! spacing, tangent scales 0.9 of it, so neighbours overlap and the draft walls look solid: at 0.6
//! the jittered grid left pinholes that read as a speckled stucco), laid
//! on a jittered grid (planes) or a Fibonacci / sunflower lattice (hemisphere, disk) so that there
//! are no holes, with SH degree 0 and a high opacity. Counts follow area: `density` Gaussians per
//! square metre, scaled down together when the total would pass `cap`. The authors use 400k per
//! wall and 300k for the floor (2.3M, random uniform points, opacity 0.1); a draft needs far fewer.
mod colours;
mod grounds;
mod light;
mod natural;
mod openings;
mod said_not;

pub use colours::{draft_colours, shade, EnvColours, Pattern};
pub use grounds::{sea_colour, shore_of, Shore, PARAPET_HEIGHT};
pub use light::{
    bake_light, openings_of, restyle_surface, styled_openings, DraftLight, LitBox, Opening,
};

use crate::plan::spec::SceneType;
use crate::splat::cloud::SH_C0;
use crate::splat::Gaussians;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// The environment's shape, as written in scene.json (`"cuboid"` / `"hemisphere"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum EnvKind {
    Cuboid,
    Hemisphere,
}

/// The initial environment: walls and ceiling or sky (`env`, trained in stage 1) and the floor or
/// ground (`floor`, trained in stage 2), both in world coordinates.
#[derive(Debug, Clone)]
pub struct Environment {
    pub kind: EnvKind,
    pub env: Gaussians,
    pub floor: Gaussians,
}

/// How many Gaussians and how they start.
#[derive(Debug, Clone, Copy)]
pub struct EnvOptions {
    /// Gaussians per square metre of surface.
    pub density: f64,
    /// Most Gaussians in all (env + floor); the density is lowered to fit.
    pub cap: usize,
    /// Initial opacity (0..1).
    pub opacity: f64,
    pub seed: u64,
}

/// Default density: 1,500 per m² (2.6 cm spacing) gives a 5 x 4 x 2.8 m room about 135k
/// Gaussians, solid at 512² from anywhere inside it.
pub const DEFAULT_DENSITY: f64 = 1500.0;
/// Default cap: 300k, about 13% of the authors' 2.3M; outdoor scenes (1,000s of m²) hit it.
pub const DEFAULT_CAP: usize = 300_000;

impl Default for EnvOptions {
    fn default() -> Self {
        EnvOptions {
            density: DEFAULT_DENSITY,
            cap: DEFAULT_CAP,
            opacity: 0.95,
            seed: 0,
        }
    }
}

/// How far the walls and ceiling are pushed outward: U(0, 2 cm), as the authors do.
pub const WALL_PUSH: f64 = 0.02;
/// Tangent scale of a surfel as a fraction of the point spacing (neighbours overlap).
const TANGENT_SCALE: f64 = 0.9;
/// Normal scale of a surfel as a fraction of the point spacing (flat).
const NORMAL_SCALE: f64 = 0.1;

/// The outdoor hemisphere radius as the authors compute it: the length of the box corner
/// `(W/2, D/2, H)`, i.e. the circumscribed radius of the ground area and sky height.
pub fn hemisphere_radius(room: [f64; 3]) -> f64 {
    (0.25 * room[0] * room[0] + 0.25 * room[1] * room[1] + room[2] * room[2]).sqrt()
}

/// Thickness of a rooftop's parapet (metres).
const PARAPET_THICKNESS: f64 = 0.2;

/// Surface areas (env, floor) in m²; `parapet`: outdoors, a parapet round the area.
fn areas(scene_type: SceneType, room: [f64; 3], parapet: bool) -> (f64, f64) {
    let [w, d, h] = room;
    match scene_type {
        SceneType::Indoor => (2.0 * (w + d) * h + w * d, w * d),
        SceneType::Outdoor => {
            let r = hemisphere_radius(room);
            let faces = 2.0 * PARAPET_HEIGHT + PARAPET_THICKNESS;
            // each side runs past the corners by the thickness and the push
            let run = 2.0 * (w + d) + 8.0 * (PARAPET_THICKNESS + WALL_PUSH);
            let wall = if parapet { run * faces } else { 0.0 };
            (
                2.0 * std::f64::consts::PI * r * r + wall,
                std::f64::consts::PI * r * r,
            )
        }
    }
}

/// The draft colours of a laid-out scene: the text's ([`draft_colours`]) and the sea past
/// the side of its ground the layout puts one along ([`shore_of`]).
pub fn scene_colours(layout: &crate::plan::spec::Layout, prompt: &str) -> EnvColours {
    EnvColours {
        shore: shore_of(layout),
        ..draft_colours(layout.scene_type, prompt)
    }
}

/// Builds the environment of a scene: a cuboid indoors, a hemisphere outdoors.
pub fn init_environment(
    scene_type: SceneType,
    room: [f64; 3],
    colours: &EnvColours,
    opts: &EnvOptions,
) -> Environment {
    let room = room.map(|v| if v.is_finite() { v.max(0.1) } else { 1.0 });
    let (a_env, a_floor) = areas(scene_type, room, colours.parapet.is_some());
    let density = opts
        .density
        .max(0.0)
        .min(opts.cap as f64 / (a_env + a_floor));
    let mut b = Builder::new(opts);
    let mut rng = ChaCha8Rng::seed_from_u64(opts.seed);
    match scene_type {
        SceneType::Indoor => {
            let [w, d, h] = room;
            let (hw, hd, m) = (0.5 * w, 0.5 * d, WALL_PUSH);
            // Walls span the floor-to-ceiling height and overlap at the corners by the push.
            let wall = |b: &mut Builder, rng: &mut ChaCha8Rng, axis: usize, sign: f64| {
                let (len, off) = if axis == 0 { (d, hw) } else { (w, hd) };
                let n = (density * len * h) as usize;
                b.plane(rng, n, [len + 2.0 * m, h], |u, v, push| {
                    let along = u - 0.5 * (len + 2.0 * m);
                    let pos = if axis == 0 {
                        [sign * (off + push), along, v]
                    } else {
                        [along, sign * (off + push), v]
                    };
                    let normal = if axis == 0 {
                        [sign, 0.0, 0.0]
                    } else {
                        [0.0, sign, 0.0]
                    };
                    (pos, normal, colours.wall, colours.wall_pattern)
                });
            };
            wall(&mut b, &mut rng, 0, -1.0);
            wall(&mut b, &mut rng, 0, 1.0);
            wall(&mut b, &mut rng, 1, -1.0);
            wall(&mut b, &mut rng, 1, 1.0);
            let n = (density * w * d) as usize;
            let span = [w + 2.0 * m, d + 2.0 * m];
            b.plane(&mut rng, n, span, |u, v, push| {
                let p = [u - hw - m, v - hd - m, h + push];
                (p, [0.0, 0.0, 1.0], colours.ceiling, colours.ceiling_pattern)
            });
            let env = b.take();
            // The floor sits at z = 0 (at most 4 mm below), under the walls' push.
            b.plane(&mut rng, n, span, |u, v, push| {
                let p = [u - hw - m, v - hd - m, -0.2 * push];
                (p, [0.0, 0.0, 1.0], colours.floor, colours.floor_pattern)
            });
            let floor = b.take();
            Environment {
                kind: EnvKind::Cuboid,
                env,
                floor,
            }
        }
        SceneType::Outdoor => {
            let r = hemisphere_radius(room);
            let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
            // Upper hemisphere, cos(polar) uniform in (0, 1) on a Fibonacci lattice; radius
            // jittered R * cbrt(U(0.95, 1.05)) as the authors.
            let a_sky = 2.0 * std::f64::consts::PI * r * r;
            let n = (density * a_sky) as usize;
            let spacing = (a_sky / n.max(1) as f64).sqrt();
            for i in 0..n {
                let z = (i as f64 + 0.5) / n as f64;
                let s = (1.0 - z * z).sqrt();
                let phi = i as f64 * golden;
                let dir = [s * phi.cos(), s * phi.sin(), z];
                let rad = r * rng.gen_range(0.95f64..1.05).cbrt();
                let horizon = [0, 1, 2].map(|k| (colours.sky[k] * 0.55 + 0.45) as f64);
                let t = z.sqrt();
                let c = [0, 1, 2].map(|k| horizon[k] + (colours.sky[k] as f64 - horizon[k]) * t);
                let speck: f32 = rng.gen();
                let c = shade(
                    c.map(|x| x as f32),
                    Pattern::Plain,
                    (phi * r) as f32,
                    (z * r) as f32,
                    speck,
                    opts.seed,
                );
                b.push(dir.map(|x| x * rad), dir, spacing, c);
            }
            if let Some(colour) = colours.parapet {
                parapet(&mut b, &mut rng, room, density, colour);
            }
            let env = b.take();
            // Ground disk of radius R on a sunflower lattice, z = U(-1 cm, 0).
            let n = (density * a_floor) as usize;
            let spacing = (a_floor / n.max(1) as f64).sqrt();
            for i in 0..n {
                let rr = r * ((i as f64 + 0.5) / n as f64).sqrt();
                let phi = i as f64 * golden;
                let jit = 0.3 * spacing;
                let x = rr * phi.cos() + rng.gen_range(-jit..jit);
                let y = rr * phi.sin() + rng.gen_range(-jit..jit);
                let z = -rng.gen_range(0.0..0.01);
                let speck: f32 = rng.gen();
                // the scene area's own ground, and around it the surround
                let inside =
                    x.abs() <= 0.5 * room[0] + WALL_PUSH && y.abs() <= 0.5 * room[1] + WALL_PUSH;
                let (base, pattern) = if inside {
                    (colours.ground, colours.ground_pattern)
                } else {
                    (colours.surround, colours.surround_pattern)
                };
                let mut c = shade(base, pattern, x as f32, y as f32, speck, opts.seed);
                // past a beach's water line, the sea out to the horizon
                if let Some((beyond, along)) = colours.shore.map(|s| s.beyond(x, y)) {
                    if beyond > 0.0 {
                        c = sea_colour(beyond, along);
                    }
                }
                b.push([x, y, z], [0.0, 0.0, 1.0], spacing, c);
            }
            let floor = b.take();
            Environment {
                kind: EnvKind::Hemisphere,
                env,
                floor,
            }
        }
    }
}

/// A parapet round the `room`'s ground area, just outside it: an inner and an outer face and
/// a top on each side, `PARAPET_HEIGHT` tall.
fn parapet(b: &mut Builder, rng: &mut ChaCha8Rng, room: [f64; 3], density: f64, colour: [f32; 3]) {
    let (hw, hd, t) = (0.5 * room[0], 0.5 * room[1], PARAPET_THICKNESS);
    for (axis, sign) in [(0usize, -1.0f64), (0, 1.0), (1, -1.0), (1, 1.0)] {
        // each side runs past the corners by the thickness, so the corners close
        let (len, off) = if axis == 0 {
            (room[1] + 2.0 * (t + WALL_PUSH), hw + WALL_PUSH)
        } else {
            (room[0] + 2.0 * (t + WALL_PUSH), hd + WALL_PUSH)
        };
        let at = |along: f64, across: f64, z: f64| {
            if axis == 0 {
                [sign * across, along, z]
            } else {
                [along, sign * across, z]
            }
        };
        let out = if axis == 0 {
            [sign, 0.0, 0.0]
        } else {
            [0.0, sign, 0.0]
        };
        let inward = out.map(|v| -v);
        let face = (density * len * PARAPET_HEIGHT) as usize;
        for (across, normal) in [(off, inward), (off + t, out)] {
            b.plane(rng, face, [len, PARAPET_HEIGHT], |u, v, _| {
                (at(u - 0.5 * len, across, v), normal, colour, Pattern::Plain)
            });
        }
        let top = (density * len * t) as usize;
        b.plane(rng, top, [len, t], |u, v, _| {
            let p = at(u - 0.5 * len, off + v, PARAPET_HEIGHT);
            (p, [0.0, 0.0, 1.0], colour, Pattern::Plain)
        });
    }
}

/// Accumulates surfels into a [`Gaussians`].
struct Builder {
    g: Gaussians,
    logit: f32,
    seed: u64,
}

impl Builder {
    fn new(opts: &EnvOptions) -> Builder {
        let o = opts.opacity.clamp(1e-4, 1.0 - 1e-4);
        Builder {
            g: Gaussians::default(),
            logit: (o / (1.0 - o)).ln() as f32,
            seed: opts.seed,
        }
    }

    fn take(&mut self) -> Gaussians {
        std::mem::take(&mut self.g)
    }

    /// A surfel at `p` with normal `n`, point spacing `spacing` and colour `c`.
    fn push(&mut self, p: [f64; 3], n: [f64; 3], spacing: f64, c: [f32; 3]) {
        let g = &mut self.g;
        g.means.push(p.map(|x| x as f32));
        let t = (TANGENT_SCALE * spacing).ln() as f32;
        g.scales.push([t, t, (NORMAL_SCALE * spacing).ln() as f32]);
        g.rotations.push(quat_z_to(n));
        g.opacities.push(self.logit);
        g.sh.extend(c.map(|x| ((x as f64 - 0.5) / SH_C0) as f32));
    }

    /// About `n` surfels on a jittered grid over a `span[0] x span[1]` rectangle; `at(u, v, push)`
    /// maps surface coordinates (metres) and this point's outward push U(0, WALL_PUSH) to its
    /// position, normal, base colour and pattern. Never more than `n` points.
    fn plane<F>(&mut self, rng: &mut ChaCha8Rng, n: usize, span: [f64; 2], at: F)
    where
        F: Fn(f64, f64, f64) -> ([f64; 3], [f64; 3], [f32; 3], Pattern),
    {
        if n == 0 {
            return;
        }
        let s = (span[0] * span[1] / n as f64).sqrt();
        let nu = ((span[0] / s).floor() as usize).max(1);
        let nv = ((span[1] / s).floor() as usize).max(1).min(n / nu);
        let (du, dv) = (span[0] / nu as f64, span[1] / nv.max(1) as f64);
        for j in 0..nv {
            for i in 0..nu {
                let u = (i as f64 + 0.5 + rng.gen_range(-0.3..0.3)) * du;
                let v = (j as f64 + 0.5 + rng.gen_range(-0.3..0.3)) * dv;
                let push = rng.gen_range(0.0..WALL_PUSH);
                let (p, normal, base, pattern) = at(u, v, push);
                let speck: f32 = rng.gen();
                let c = shade(base, pattern, u as f32, v as f32, speck, self.seed);
                self.push(p, normal, du.max(dv), c);
            }
        }
    }
}

/// The unit quaternion (w, x, y, z) turning +z onto the unit vector `n` (any rotation about `n`
/// does: the surfel is round in its plane).
fn quat_z_to(n: [f64; 3]) -> [f32; 4] {
    if n[2] < -0.999_999 {
        return [0.0, 1.0, 0.0, 0.0];
    }
    let q = [1.0 + n[2], -n[1], n[0], 0.0];
    let l = q.iter().map(|v| v * v).sum::<f64>().sqrt();
    q.map(|v| (v / l) as f32)
}
