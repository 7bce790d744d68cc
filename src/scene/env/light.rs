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
}

/// Colours of the drawn openings and the skirting (linear RGB).
const DOOR_LEAF: [f32; 3] = [0.62, 0.46, 0.30];
const FRAME: [f32; 3] = [0.93, 0.92, 0.89];
const PANE: [f32; 3] = [0.86, 0.93, 1.0];
const SKIRTING: [f32; 3] = [0.95, 0.94, 0.91];
/// Skirting board height (metres).
const SKIRTING_H: f64 = 0.08;
/// Frame width around openings (metres).
const FRAME_W: f64 = 0.06;

/// Objects thinner than this lie on the floor (rugs, mats) and cast no contact shadow.
const FLAT: f64 = 0.05;

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
}

/// Which surface an environment Gaussian lies on.
enum Surface {
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
    match k {
        0 => Surface::Wall("east", p[1]),
        1 => Surface::Wall("west", p[1]),
        2 => Surface::Wall("north", p[0]),
        _ => Surface::Wall("south", p[0]),
    }
}

/// Bakes light into the environment cloud `env` of a draft (see the module doc). Outdoors only
/// the ground gets contact shadows.
pub fn bake_light(
    env: &mut Gaussians,
    scene_type: SceneType,
    room: [f64; 3],
    boxes: &[LitBox],
    openings: &[Opening],
) {
    let k3 = env.coeffs() * 3;
    let [hx, hy] = [0.5 * room[0], 0.5 * room[1]];
    let solid: Vec<&LitBox> = boxes.iter().filter(|b| b.size[2] > FLAT).collect();
    let indoor = scene_type == SceneType::Indoor;
    for i in 0..env.len() {
        let p = env.means[i].map(|v| v as f64);
        let mut paint: Option<[f32; 3]> = None;
        let mut k = 1.0f64;
        let s = if indoor {
            surface(p, room)
        } else if p[2].abs() < 0.03 {
            Surface::Floor
        } else {
            continue;
        };
        match s {
            Surface::Floor => {
                if indoor {
                    let dw = (hx - p[0].abs()).min(hy - p[1].abs()).max(0.0);
                    k *= 1.0 - 0.22 * (-dw / 0.25).exp();
                    // The ceiling light falls off towards the walls.
                    let r2 = (p[0] / hx).powi(2).max((p[1] / hy).powi(2));
                    k *= 1.0 - 0.1 * r2;
                }
                for b in &solid {
                    let d = b.footprint_distance(p[0], p[1]);
                    let gap = b.position[2].max(0.0);
                    let reach = 0.12 + 0.2 * b.size[2].min(1.5);
                    let strength = 0.5 * (-gap / 0.5).exp();
                    k *= 1.0 - strength * (-d / reach).exp();
                }
            }
            Surface::Ceiling => {
                let dw = (hx - p[0].abs()).min(hy - p[1].abs()).max(0.0);
                k *= 1.0 - 0.15 * (-dw / 0.3).exp();
            }
            Surface::Wall(side, u) => {
                let z = p[2];
                k *= 1.0 - 0.25 * (-z / 0.2).exp();
                k *= 1.0 - 0.12 * (-(room[2] - z) / 0.25).exp();
                let along = if matches!(side, "east" | "west") {
                    hy
                } else {
                    hx
                };
                k *= 1.0 - 0.2 * (-(along - u.abs()).max(0.0) / 0.25).exp();
                for b in &solid {
                    k *= 1.0 - 0.3 * (-b.distance(p) / 0.25).exp();
                }
                if z < SKIRTING_H {
                    paint = Some(SKIRTING);
                }
                for o in openings.iter().filter(|o| o.wall == side) {
                    let oc = if matches!(side, "east" | "west") {
                        o.position[1]
                    } else {
                        o.position[0]
                    };
                    let (du, z0, z1) = ((u - oc).abs(), o.position[2], o.position[2] + o.height);
                    let hw = 0.5 * o.width;
                    if du > hw + FRAME_W || z < z0 - FRAME_W.min(z0) || z > z1 + FRAME_W {
                        continue;
                    }
                    let inside = du <= hw && z >= z0 && z <= z1;
                    paint = Some(if !inside {
                        FRAME
                    } else if o.kind == "door" {
                        // A leaf with two recessed panels and a handle.
                        let panel = du < hw - 0.1
                            && ((z > z0 + 0.15 && z < z0 + 0.45 * o.height)
                                || (z > z0 + 0.55 * o.height && z < z1 - 0.15));
                        let handle = (u - oc - 0.35 * o.width * side_sign(side)).abs() < 0.03
                            && (z - z0 - 1.0).abs() < 0.03;
                        if handle {
                            [0.75, 0.72, 0.62]
                        } else if panel {
                            DOOR_LEAF.map(|c| c * 0.88)
                        } else {
                            DOOR_LEAF
                        }
                    } else {
                        // Panes split by a cross of glazing bars.
                        let bar = (u - oc).abs() < 0.025 || (z - 0.5 * (z0 + z1)).abs() < 0.025;
                        if bar {
                            FRAME
                        } else {
                            PANE
                        }
                    });
                    if !inside && o.kind == "window" && z < z0 && z > z0 - FRAME_W {
                        // The sill: brighter and a little wider.
                        paint = Some([0.97, 0.96, 0.94]);
                    }
                    if inside {
                        k = k.max(0.97);
                    }
                }
            }
        }
        for ch in 0..3 {
            let j = i * k3 + ch;
            let c = match paint {
                Some(rgb) => rgb[ch] as f64 * (0.97 + 0.03 * ((i * 7919 % 101) as f64 / 100.0)),
                None => 0.5 + SH_C0 * env.sh[j] as f64,
            };
            env.sh[j] = (((c * k).clamp(0.0, 1.0) - 0.5) / SH_C0) as f32;
        }
    }
}

/// +1 or −1: which way "right" runs along a wall seen from inside the room (the handle side).
fn side_sign(side: &str) -> f64 {
    match side {
        "north" | "west" => -1.0,
        _ => 1.0,
    }
}

/// The openings a scene.json or layout.json value carries under `openings` (none when absent or
/// not in the contract's form).
pub fn openings_of(v: Option<&serde_json::Value>) -> Vec<Opening> {
    v.and_then(|v| serde_json::from_value(v.clone()).ok())
        .unwrap_or_default()
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
mod tests {
    use super::*;

    fn floor_and_wall() -> Gaussians {
        let mut g = Gaussians {
            sh_degree: 0,
            ..Default::default()
        };
        let grey = ((0.8 - 0.5) / SH_C0) as f32;
        for p in [
            [0.0, 0.0, 0.0],
            [1.8, 0.0, 0.0],
            [0.0, 2.005, 1.0],
            [1.3, 2.005, 1.2],
            [0.0, 2.005, 0.03],
            [1.5, 2.005, 0.1],
        ] {
            g.means.push(p);
            g.scales.push([-4.0; 3]);
            g.rotations.push([1.0, 0.0, 0.0, 0.0]);
            g.opacities.push(3.0);
            g.sh.extend([grey; 3]);
        }
        g
    }

    fn grey(g: &Gaussians, i: usize) -> f64 {
        0.5 + SH_C0 * g.sh[3 * i] as f64
    }

    #[test]
    fn contact_shadow_falls_under_the_object_and_openings_are_drawn() {
        let mut g = floor_and_wall();
        let sofa = LitBox {
            position: [0.0, 0.0, 0.0],
            size: [2.0, 0.9, 0.8],
            yaw: 0.0,
        };
        let window = Opening {
            kind: "window".into(),
            wall: "north".into(),
            position: [1.0, 2.0, 0.9],
            width: 1.2,
            height: 1.2,
        };
        bake_light(
            &mut g,
            SceneType::Indoor,
            [5.0, 4.0, 2.8],
            &[sofa],
            std::slice::from_ref(&window),
        );
        // Under the sofa darker than the open floor; the open floor still near its colour.
        assert!(grey(&g, 0) < 0.6 * 0.8, "{}", grey(&g, 0));
        assert!(grey(&g, 1) > 0.85 * 0.8, "{}", grey(&g, 1));
        // The window pane is brighter than the plain wall beside it; the wall foot is skirting.
        assert!(
            grey(&g, 3) > grey(&g, 2),
            "{} vs {}",
            grey(&g, 3),
            grey(&g, 2)
        );
        assert!(
            grey(&g, 4) > grey(&g, 5),
            "{} vs {}",
            grey(&g, 4),
            grey(&g, 5)
        );
    }
}
