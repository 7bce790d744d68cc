//! Light baked into a draft's environment when a scene is composed: ambient occlusion in the
//! room's creases (floor along the walls, wall foot and top, vertical corners), contact shadows of
//! the furniture on the floor and the walls behind it, a soft falloff of the ceiling light
//! towards the walls, a skirting line along the wall foot, and the openings drawn on the walls
//! (a door leaf in a frame; window panes brighter than the wall, with a frame and a sill).
//!
//! It works on the environment cloud and the current object boxes, so it is recomputed after
//! every edit (a moved sofa takes its shadow along) and `environment.ply` itself stays unlit.
//! Host-only and deterministic.
use crate::plan::spec::SceneType;
use crate::splat::cloud::SH_C0;
use crate::splat::Gaussians;
use serde::Deserialize;

/// An object's box in the world: bottom-face centre, size `[w, d, h]`, yaw in degrees.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LitBox {
    pub position: [f64; 3],
    pub size: [f64; 3],
    pub yaw: f64,
}

/// A door or window on a wall (ARCHITECTURE.md "Openings").
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct Opening {
    pub kind: String,
    pub wall: String,
    pub position: [f64; 3],
    pub width: f64,
    pub height: f64,
    /// A door's leaf colour from the scene's style ([`styled_openings`]); the drawn default
    /// when absent.
    #[serde(default)]
    pub leaf: Option<[f32; 3]>,
}

/// Colour of the skirting (linear RGB).
const SKIRTING: [f32; 3] = [0.95, 0.94, 0.91];
/// Skirting board height (metres).
const SKIRTING_H: f64 = 0.08;
/// Objects thinner than this lie on the floor (rugs, mats) and cast no contact shadow.
const FLAT: f64 = 0.05;
/// A contact shadow darkening a point by less than this is left out (a quarter of an 8-bit
/// level), so each object's shadow is a short list of the points near it.
const SHADOW_CUTOFF: f64 = 1e-3;

impl LitBox {
    /// Distance from `(x, y)` to the box's footprint (0 inside).
    fn footprint_distance(&self, x: f64, y: f64) -> f64 {
        let (s, c) = self.yaw.to_radians().sin_cos();
        let (dx, dy) = (x - self.position[0], y - self.position[1]);
        let (lx, ly) = (c * dx + s * dy, -s * dx + c * dy);
        let ox = (lx.abs() - 0.5 * self.size[0]).max(0.0);
        let oy = (ly.abs() - 0.5 * self.size[1]).max(0.0);
        ox.hypot(oy)
    }

    /// Distance from `p` to the box (0 inside).
    fn distance(&self, p: [f64; 3]) -> f64 {
        let d = self.footprint_distance(p[0], p[1]);
        let z0 = self.position[2];
        let oz = (z0 - p[2]).max(p[2] - (z0 + self.size[2])).max(0.0);
        d.hypot(oz)
    }

    /// How much the box darkens a floor point at footprint distance `d` (0: not at all).
    fn floor_shadow(&self, d: f64) -> f64 {
        let gap = self.position[2].max(0.0);
        let reach = 0.12 + 0.2 * self.size[2].min(1.5);
        0.5 * (-gap / 0.5).exp() * (-d / reach).exp()
    }

    /// How much the box darkens a wall point at distance `d` from it.
    fn wall_shadow(d: f64) -> f64 {
        0.3 * (-d / 0.25).exp()
    }
}

/// Which surface an environment Gaussian lies on.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Surface {
    /// Left as it is (outdoors: the sky).
    Unlit,
    Floor,
    Ceiling,
    /// A wall, with the name of its side and the horizontal coordinate along it.
    Wall(&'static str, f64),
}

fn surface(p: [f64; 3], room: [f64; 3]) -> Surface {
    let [hx, hy] = [0.5 * room[0], 0.5 * room[1]];
    // Walls and ceiling lie on or just outside the room box (pushed out by up to 2 cm); the
    // floor lies inside it at z = 0.
    let out_xy = (p[0].abs() - hx).max(p[1].abs() - hy);
    if p[2] >= room[2] - 1e-4 && out_xy < 0.0 {
        return Surface::Ceiling;
    }
    if out_xy < -1e-4 {
        return Surface::Floor;
    }
    let d = [
        (hx - p[0]).abs(),
        (hx + p[0]).abs(),
        (hy - p[1]).abs(),
        (hy + p[1]).abs(),
    ];
    let k = (0..4).min_by(|a, b| d[*a].total_cmp(&d[*b])).unwrap_or(0);
    wall_named(k, p)
}

fn wall_named(k: usize, p: [f64; 3]) -> Surface {
    match k {
        0 => Surface::Wall("east", p[1]),
        1 => Surface::Wall("west", p[1]),
        2 => Surface::Wall("north", p[0]),
        _ => Surface::Wall("south", p[0]),
    }
}

/// The skirting of walls drawn as `env`'s `surface` says: plain painted walls (the same colour
/// all over) have a white skirting board; walls of logs, boards, brick, tiles, glass or rock
/// (a patterned surface, its colour varying from point to point) have none: their foot only
/// darkens into the crease.
fn skirting_of(env: &Gaussians, surface: &[Surface]) -> Option<[f32; 3]> {
    let stride = 3 * env.coeffs();
    let (mut sum, mut sum2, mut count) = (0.0f64, 0.0f64, 0usize);
    for (i, s) in surface.iter().enumerate().take(env.len()) {
        if !matches!(s, Surface::Wall(..)) {
            continue;
        }
        let dc = &env.sh[i * stride..i * stride + 3];
        let rgb = dc.iter().map(|&c| SH_C0 * f64::from(c) + 0.5);
        let y: f64 = rgb.zip([0.2126, 0.7152, 0.0722]).map(|(c, w)| c * w).sum();
        (sum, sum2, count) = (sum + y, sum2 + y * y, count + 1);
    }
    if count == 0 {
        return Some(SKIRTING);
    }
    let mean = sum / count as f64;
    let spread = (sum2 / count as f64 - mean * mean).max(0.0).sqrt();
    (spread <= PLAIN_WALL * mean.max(1e-6)).then_some(SKIRTING)
}

/// The most a plain painted wall's luminance varies from point to point, as a share of its
/// mean (a trace of speckle; boards, bricks and tiles vary by a tenth and more).
const PLAIN_WALL: f64 = 0.04;

/// Bakes light into the environment cloud `env` of a draft (see the module doc); the openings'
/// own surfels are appended. Outdoors only the ground gets contact shadows. A frame loop keeps
/// a [`DraftLight`] instead, which re-computes only the shadows of objects that moved.
pub fn bake_light(
    env: &mut Gaussians,
    scene_type: SceneType,
    room: [f64; 3],
    boxes: &[LitBox],
    openings: &[Opening],
) {
    let mut light = DraftLight::new(std::mem::take(env), scene_type, room, openings);
    *env = light.lit(boxes);
}

/// A draft environment's light split in two: what the room gives (creases, the ceiling light's
/// falloff, the skirting and the openings), computed once, and each object's contact shadow,
/// kept with the box that cast it and re-computed only when that box changes, so a timeline
/// that moves a few objects re-lights only around them.
#[derive(Debug, Clone)]
pub struct DraftLight {
    /// The unlit environment with the openings' surfels appended.
    env: Gaussians,
    surface: Vec<Surface>,
    /// The room's light factor, the least factor (inside openings) and the painted colour.
    room_k: Vec<f64>,
    least_k: Vec<f64>,
    paint: Vec<Option<[f32; 3]>>,
    floor: Vec<u32>,
    walls: Vec<u32>,
    /// Per object: the box and the darkening factor of each point its shadow reaches.
    shadows: Vec<Shadow>,
}

/// The box an object's shadow was cast from and the darkening factor of each point it reaches.
type Shadow = (Option<LitBox>, Vec<(u32, f64)>);

impl DraftLight {
    /// The room's light of `env` (unlit, world frame) for a room of `room` size with `openings`.
    pub fn new(
        mut env: Gaussians,
        scene_type: SceneType,
        room: [f64; 3],
        openings: &[Opening],
    ) -> DraftLight {
        let indoor = scene_type == SceneType::Indoor;
        let mut surface: Vec<Surface> = env
            .means
            .iter()
            .map(|m| {
                let p = m.map(|v| v as f64);
                if indoor {
                    surface(p, room)
                } else if p[2].abs() < 0.03 {
                    Surface::Floor
                } else {
                    Surface::Unlit
                }
            })
            .collect();
        if indoor {
            for o in openings {
                let k = ["east", "west", "north", "south"]
                    .iter()
                    .position(|w| *w == o.wall);
                let (Some(k), Ok(mut extra)) = (k, openings_surfels(o, room)) else {
                    continue;
                };
                surface.extend(
                    extra
                        .means
                        .iter()
                        .map(|m| wall_named(k, m.map(|v| v as f64))),
                );
                append(&mut env, &mut extra);
            }
        }
        let n = env.len();
        let skirting = skirting_of(&env, &surface);
        let (mut room_k, mut least_k, mut paint) = (vec![1.0; n], vec![0.0; n], vec![None; n]);
        let [hx, hy] = [0.5 * room[0], 0.5 * room[1]];
        let (mut floor, mut walls) = (vec![], vec![]);
        for i in 0..n {
            let p = env.means[i].map(|v| v as f64);
            let k = &mut room_k[i];
            match surface[i] {
                Surface::Unlit => {}
                Surface::Floor => {
                    floor.push(i as u32);
                    if indoor {
                        let dw = (hx - p[0].abs()).min(hy - p[1].abs()).max(0.0);
                        *k *= 1.0 - 0.22 * (-dw / 0.25).exp();
                        // The ceiling light falls off towards the walls.
                        let r2 = (p[0] / hx).powi(2).max((p[1] / hy).powi(2));
                        *k *= 1.0 - 0.1 * r2;
                    }
                }
                Surface::Ceiling => {
                    let dw = (hx - p[0].abs()).min(hy - p[1].abs()).max(0.0);
                    *k *= 1.0 - 0.15 * (-dw / 0.3).exp();
                }
                Surface::Wall(side, u) => {
                    walls.push(i as u32);
                    let z = p[2];
                    *k *= 1.0 - 0.25 * (-z / 0.2).exp();
                    *k *= 1.0 - 0.12 * (-(room[2] - z) / 0.25).exp();
                    let along = if matches!(side, "east" | "west") {
                        hy
                    } else {
                        hx
                    };
                    *k *= 1.0 - 0.2 * (-(along - u.abs()).max(0.0) / 0.25).exp();
                    if z < SKIRTING_H {
                        paint[i] = skirting;
                    }
                    for o in openings.iter().filter(|o| o.wall == side) {
                        if let Some((rgb, inside)) = super::openings::paint(o, side, u, z) {
                            paint[i] = Some(rgb);
                            if inside {
                                least_k[i] = 0.97;
                            }
                        }
                    }
                }
            }
        }
        DraftLight {
            env,
            surface,
            room_k,
            least_k,
            paint,
            floor,
            walls,
            shadows: vec![],
        }
    }

    /// How many objects' shadows were (re-)computed by the last [`DraftLight::lit`].
    pub fn shadows_len(&self) -> usize {
        self.shadows.len()
    }

    /// The lit environment for the objects' current `boxes` (one per object, in a fixed order):
    /// the shadow of a box equal to the one last given at its index is re-used.
    pub fn lit(&mut self, boxes: &[LitBox]) -> Gaussians {
        self.shadows.resize_with(boxes.len(), || (None, vec![]));
        for (b, (cached, factors)) in boxes.iter().zip(self.shadows.iter_mut()) {
            if cached.as_ref() != Some(b) {
                *factors = shadow(b, &self.env, &self.surface, &self.floor, &self.walls);
                *cached = Some(*b);
            }
        }
        let mut k = self.room_k.clone();
        for (_, factors) in &self.shadows {
            for &(i, f) in factors {
                k[i as usize] *= f;
            }
        }
        let mut out = self.env.clone();
        let k3 = out.coeffs() * 3;
        for (i, k) in k.iter().enumerate() {
            if self.surface[i] == Surface::Unlit {
                continue;
            }
            let k = k.max(self.least_k[i]);
            for ch in 0..3 {
                let j = i * k3 + ch;
                let c = match self.paint[i] {
                    Some(rgb) => rgb[ch] as f64 * (0.97 + 0.03 * ((i * 7919 % 101) as f64 / 100.0)),
                    None => 0.5 + SH_C0 * self.env.sh[j] as f64,
                };
                out.sh[j] = (((c * k).clamp(0.0, 1.0) - 0.5) / SH_C0) as f32;
            }
        }
        out
    }
}

/// The contact shadow of box `b`: the darkening factor of each floor and wall point it reaches
/// by more than [`SHADOW_CUTOFF`]. Flat boxes (rugs) cast none.
fn shadow(
    b: &LitBox,
    env: &Gaussians,
    surface: &[Surface],
    floor: &[u32],
    walls: &[u32],
) -> Vec<(u32, f64)> {
    let mut out = vec![];
    if b.size[2] <= FLAT {
        return out;
    }
    for &i in floor {
        let p = env.means[i as usize];
        let s = b.floor_shadow(b.footprint_distance(p[0] as f64, p[1] as f64));
        if s >= SHADOW_CUTOFF {
            out.push((i, 1.0 - s));
        }
    }
    for &i in walls {
        if !matches!(surface[i as usize], Surface::Wall(..)) {
            continue;
        }
        let s = LitBox::wall_shadow(b.distance(env.means[i as usize].map(|v| v as f64)));
        if s >= SHADOW_CUTOFF {
            out.push((i, 1.0 - s));
        }
    }
    out
}

/// The surfels of opening `o` (see `openings.rs`); an error for an unknown wall.
fn openings_surfels(o: &Opening, room: [f64; 3]) -> Result<Gaussians, ()> {
    let g = super::openings::surfels(o, room);
    if g.is_empty() {
        Err(())
    } else {
        Ok(g)
    }
}

/// Appends `extra` (SH degree 0) to `env` (the environment's degree; higher bands zero).
fn append(env: &mut Gaussians, extra: &mut Gaussians) {
    let k = env.coeffs();
    env.means.append(&mut extra.means);
    env.scales.append(&mut extra.scales);
    env.rotations.append(&mut extra.rotations);
    env.opacities.append(&mut extra.opacities);
    for rgb in extra.sh.chunks(3) {
        env.sh.extend_from_slice(rgb);
        env.sh.extend(std::iter::repeat_n(0.0, 3 * (k - 1)));
    }
}

/// The openings a scene.json or layout.json value carries under `openings` (none when absent or
/// not in the contract's form).
pub fn openings_of(v: Option<&serde_json::Value>) -> Vec<Opening> {
    v.and_then(|v| serde_json::from_value(v.clone()).ok())
        .unwrap_or_default()
}

/// The openings of a scene's `extra` with each door's leaf coloured from the scene's text (its
/// kind, style and door words, see [`super::draft_colours`]).
pub fn styled_openings(
    v: Option<&serde_json::Value>,
    scene_type: SceneType,
    prompt: &str,
) -> Vec<Opening> {
    let door = super::draft_colours(scene_type, prompt).door;
    let mut out = openings_of(v);
    for o in out.iter_mut().filter(|o| o.kind == "door") {
        o.leaf = Some(door);
    }
    out
}

/// Re-materialises the floor (`floor`) or the walls and ceiling of a draft environment from a
/// restyle description with the same rules as a new draft ("dark green carpet" gives a green
/// speckled carpet, not tinted planks). Floor Gaussians are those inside the room box near
/// z = 0; every other one is wall or ceiling (kept), so no strip along the floor keeps the old
/// colour.
/// `None` when the description names no colour or material of that surface.
pub fn restyle_surface(
    env: &Gaussians,
    scene_type: SceneType,
    room: [f64; 3],
    floor: bool,
    description: &str,
    seed: u64,
) -> Option<(Gaussians, String)> {
    let noun = if floor { "floor" } else { "walls" };
    let text = format!("{description} {noun}");
    let plain = super::draft_colours(scene_type, "");
    let c = super::draft_colours(scene_type, &text);
    let (base, pattern, was) = if floor {
        (c.floor, c.floor_pattern, (plain.floor, plain.floor_pattern))
    } else {
        (c.wall, c.wall_pattern, (plain.wall, plain.wall_pattern))
    };
    if (base, pattern) == was {
        return None;
    }
    let k3 = env.coeffs() * 3;
    let mut out = env.clone();
    let mut n = 0usize;
    for i in 0..env.len() {
        let p = env.means[i].map(|v| v as f64);
        let on_floor = match scene_type {
            SceneType::Indoor => matches!(surface(p, room), Surface::Floor),
            SceneType::Outdoor => p[2].abs() < 0.05,
        };
        // The ceiling keeps its white: a restyle names the walls.
        let ceiling =
            scene_type == SceneType::Indoor && matches!(surface(p, room), Surface::Ceiling);
        if on_floor != floor || ceiling {
            continue;
        }
        let (u, v) = if floor {
            (p[0], p[1])
        } else {
            (p[0] + p[1], p[2])
        };
        let speck = super::colours::hash(i as i64, 17, seed);
        let rgb = super::shade(base, pattern, u as f32, v as f32, speck, seed);
        for (ch, c) in rgb.iter().enumerate() {
            out.sh[i * k3 + ch] = ((*c as f64 - 0.5) / SH_C0) as f32;
        }
        n += 1;
    }
    Some((
        out,
        format!(
            "shape prior: {n} Gaussians of the {noun} re-materialised as ({:.2}, {:.2}, {:.2}) {pattern:?}",
            base[0], base[1], base[2]
        ),
    ))
}

#[cfg(test)]
#[path = "light_tests.rs"]
mod tests;
