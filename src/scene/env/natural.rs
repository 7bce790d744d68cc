//! Surface patterns of particular places: a tatami room's mats, a cave's rock, a ship's deck
//! planks, a greenhouse's glazing. Evaluated at surface coordinates in metres, like the patterns of `colours.rs`.
use super::colours::{fbm, hash, Pattern};

/// Tatami mat size (m): a 90 x 180 cm mat, its long side along u.
const MAT: [f32; 2] = [1.8, 0.9];
/// Width of a mat's cloth border along each long side (m); wide enough for the draft spacing.
const MAT_BORDER: f32 = 0.045;
/// The borders' dark cloth.
const BORDER: [f32; 3] = [0.14, 0.13, 0.11];

/// Deck plank width and length (m), and the caulked seam between planks.
const PLANK: [f32; 2] = [0.32, 3.2];
const SEAM: f32 = 0.07;
/// Caulking: pitch-dark.
const CAULK: [f32; 3] = [0.12, 0.09, 0.07];

/// A greenhouse pane (across, up) and half its glazing bar's width (m); the bars' white paint.
const PANE: [f32; 2] = [0.7, 1.2];
const FRAME: f32 = 0.025;
const FRAME_PAINT: [f32; 3] = [0.93, 0.94, 0.92];

/// The colour of `base` under one of this module's patterns at (u, v); `speck` is this point's
/// own uniform random number in [0, 1).
pub(super) fn shade(
    base: [f32; 3],
    pattern: Pattern,
    u: f32,
    v: f32,
    speck: f32,
    seed: u64,
) -> [f32; 3] {
    let mut k = 1.0 + 0.05 * (speck - 0.5);
    let mut mix_to: Option<([f32; 3], f32)> = None;
    match pattern {
        Pattern::Tatami => {
            // rows of mats, each row's joints half a mat along from the last's
            let row = (v / MAT[1]).floor();
            let uu = u + 0.5 * MAT[0] * (row as i64 & 1) as f32;
            let col = (uu / MAT[0]).floor();
            let (fu, fv) = (uu - col * MAT[0], v - row * MAT[1]);
            // each mat a slightly different straw, a fine weave across it
            k *= 0.94 + 0.12 * hash(row as i64, col as i64, seed);
            k *= 1.0 + 0.05 * ((fu * 90.0).sin());
            if fv.min(MAT[1] - fv) < MAT_BORDER {
                mix_to = Some((BORDER, 0.9));
            } else if fu.min(MAT[0] - fu) < 0.012 {
                k *= 0.8;
            }
        }
        Pattern::Rock => {
            // masses of darker and lighter stone, and cracks where the noise crosses a level
            let n = fbm(u, v, 1.6, seed);
            k *= 0.75 + 0.5 * n + 0.12 * (fbm(u, v, 0.35, seed + 3) - 0.5) + 0.1 * (speck - 0.5);
            let crack = (fbm(u, v, 0.9, seed + 11) - 0.5).abs();
            if crack < 0.02 {
                k *= 0.5;
            }
        }
        Pattern::Planks => {
            let row = (v / PLANK[0]).floor();
            let off = hash(row as i64, 5, seed) * PLANK[1];
            let plank = ((u + off) / PLANK[1]).floor();
            let fv = v - row * PLANK[0];
            let fu = (u + off) - plank * PLANK[1];
            k *= 0.85 + 0.3 * hash(row as i64, plank as i64, seed);
            k *= 1.0 + 0.06 * (fbm(u, v, 0.5, seed) - 0.5);
            if fv < SEAM || fu < 0.5 * SEAM {
                mix_to = Some((CAULK, 0.85));
            }
        }
        Pattern::Panes => {
            // the glass: pale, the planting outside greener below, brighter sky above
            let t = (v / 2.0).clamp(0.0, 1.0);
            let through = [0.55 + 0.4 * t, 0.75 + 0.2 * t, 0.55 + 0.42 * t];
            let mut c = [0, 1, 2].map(|i| 0.5 * (base[i] + through[i]));
            k *= 1.0 + 0.04 * (fbm(u, v, 0.6, seed) - 0.5);
            let (fu, fv) = (u.rem_euclid(PANE[0]), v.rem_euclid(PANE[1]));
            if fu.min(PANE[0] - fu) < FRAME || fv.min(PANE[1] - fv) < FRAME {
                c = FRAME_PAINT;
            }
            return c.map(|x| (x * k).clamp(0.0, 1.0));
        }
        _ => {}
    }
    let mut c = base.map(|x| x * k);
    if let Some((to, t)) = mix_to {
        c = [0, 1, 2].map(|i| c[i] + (to[i] - c[i]) * t);
    }
    c.map(|x| x.clamp(0.0, 1.0))
}
