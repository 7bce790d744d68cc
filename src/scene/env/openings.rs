//! Doors and windows drawn on a draft's walls: what colour a point of a wall takes near an
//! opening (a door leaf with panels and a handle in a frame; window panes split by glazing bars,
//! a frame and a sill), and the opening's own surfels, laid on a regular grid aligned with its
//! edges a few millimetres in front of the wall, so its outline is straight whatever the jitter
//! of the wall's Gaussians behind it. Host-only.
use super::light::Opening;
use crate::splat::cloud::SH_C0;
use crate::splat::Gaussians;

/// Colours of the drawn openings (linear RGB); a door's leaf is its scene's when known.
const DOOR_LEAF: [f32; 3] = [0.62, 0.46, 0.30];
const FRAME: [f32; 3] = [0.93, 0.92, 0.89];
const PANE: [f32; 3] = [0.86, 0.93, 1.0];
const SILL: [f32; 3] = [0.97, 0.96, 0.94];
const HANDLE: [f32; 3] = [0.75, 0.72, 0.62];
/// Frame width around openings (metres).
pub const FRAME_W: f64 = 0.06;
/// Spacing of an opening's surfels (metres): finer than the wall's 2.6 cm.
const SPACING: f64 = 0.012;
/// How far in front of the wall plane (into the room) the surfels lie: in front of every wall
/// Gaussian (those are pushed outwards).
const INSET: f64 = 0.003;

/// +1 or −1: which way "right" runs along a wall seen from inside the room (the handle side).
fn side_sign(side: &str) -> f64 {
    match side {
        "north" | "west" => -1.0,
        _ => 1.0,
    }
}

/// The centre of `o` along its wall (y on the east and west walls, x on the others).
fn along(o: &Opening) -> f64 {
    if matches!(o.wall.as_str(), "east" | "west") {
        o.position[1]
    } else {
        o.position[0]
    }
}

/// The colour of the point at `u` along wall `side` and height `z` where opening `o` (on that
/// wall) covers it, and whether it lies inside the opening (not its frame or sill); `None`
/// outside the opening and its frame.
pub fn paint(o: &Opening, side: &str, u: f64, z: f64) -> Option<([f32; 3], bool)> {
    let oc = along(o);
    let (du, z0, z1) = ((u - oc).abs(), o.position[2], o.position[2] + o.height);
    let hw = 0.5 * o.width;
    if du > hw + FRAME_W || z < z0 - FRAME_W.min(z0) || z > z1 + FRAME_W {
        return None;
    }
    let inside = du <= hw && z >= z0 && z <= z1;
    let rgb = if !inside {
        if o.kind == "window" && z < z0 {
            SILL
        } else {
            FRAME
        }
    } else if o.kind == "door" {
        let leaf = o.leaf.unwrap_or(DOOR_LEAF);
        // A leaf with two recessed panels and a handle.
        let panel = du < hw - 0.1
            && ((z > z0 + 0.15 && z < z0 + 0.45 * o.height)
                || (z > z0 + 0.55 * o.height && z < z1 - 0.15));
        let handle =
            (u - oc - 0.35 * o.width * side_sign(side)).abs() < 0.03 && (z - z0 - 1.0).abs() < 0.03;
        if handle {
            HANDLE
        } else if panel {
            leaf.map(|c| c * 0.88)
        } else {
            leaf
        }
    } else {
        // Panes split by a cross of glazing bars.
        let bar = (u - oc).abs() < 0.025 || (z - 0.5 * (z0 + z1)).abs() < 0.025;
        if bar {
            FRAME
        } else {
            PANE
        }
    };
    Some((rgb, inside))
}

/// The surfels of `o` on a room of `room` size: a regular grid over the opening and its frame,
/// coloured by [`paint`] (unlit), with the wall's normal. Empty for an unknown wall.
pub fn surfels(o: &Opening, room: [f64; 3]) -> Gaussians {
    let mut g = Gaussians {
        sh_degree: 0,
        ..Default::default()
    };
    let [hx, hy] = [0.5 * room[0], 0.5 * room[1]];
    // Where the wall plane lies (x fixed on the east and west walls, y on the others) and its
    // inward normal.
    let (x_fixed, at, normal) = match o.wall.as_str() {
        "east" => (true, hx - INSET, [-1.0, 0.0, 0.0]),
        "west" => (true, -hx + INSET, [1.0, 0.0, 0.0]),
        "north" => (false, hy - INSET, [0.0, -1.0, 0.0]),
        "south" => (false, -hy + INSET, [0.0, 1.0, 0.0]),
        _ => return g,
    };
    let plane = |u: f64, z: f64| if x_fixed { [at, u, z] } else { [u, at, z] };
    let oc = along(o);
    let (u0, u1) = (oc - 0.5 * o.width - FRAME_W, oc + 0.5 * o.width + FRAME_W);
    let z0 = (o.position[2] - FRAME_W).max(0.0);
    let z1 = (o.position[2] + o.height + FRAME_W).min(room[2]);
    if !(u1 > u0 && z1 > z0) {
        return g;
    }
    // Whole cells: the outermost samples sit half a cell inside the outline.
    let nu = ((u1 - u0) / SPACING).ceil().max(1.0) as usize;
    let nz = ((z1 - z0) / SPACING).ceil().max(1.0) as usize;
    let (du, dz) = ((u1 - u0) / nu as f64, (z1 - z0) / nz as f64);
    let rot = super::quat_z_to(normal);
    let t = 0.6 * du.max(dz);
    let scale = [t.ln() as f32, t.ln() as f32, (0.15 * t).ln() as f32];
    let logit = (0.97f64 / 0.03).ln() as f32;
    for i in 0..nu {
        let u = u0 + (i as f64 + 0.5) * du;
        for j in 0..nz {
            let z = z0 + (j as f64 + 0.5) * dz;
            let Some((rgb, _)) = paint(o, &o.wall, u, z) else {
                continue;
            };
            g.means.push(plane(u, z).map(|v| v as f32));
            g.scales.push(scale);
            g.rotations.push(rot);
            g.opacities.push(logit);
            g.sh.extend(rgb.map(|c| ((c as f64 - 0.5) / SH_C0) as f32));
        }
    }
    g
}
