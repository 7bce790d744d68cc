//! Layouts of treatment recliners built on the dentist's couch of `salon.rs`: a patient chair (a
//! treatment recliner: the couch reclined on its pedestal with arm rests, a moulded shell behind
//! its back and a foot plate) and a tattoo chair (an adjustable padded bench: the couch laid
//! flatter, a long arm rest on a post at its right and a foot pedal on its base). The front faces
//! +y; backs at -y.
use super::archetypes::Builder;
use super::fittings::pad;
use super::materials::Role::*;
use super::salon::{couch, Couch};

/// The moulded shell behind a couch's back rest, `t` behind it, from the seat's back edge to
/// the back's top: what a recliner shows from behind instead of bare padding.
fn back_shell(b: &mut Builder, c: &Couch, t: f64) {
    let (dy, dz) = (c.top[0] - c.ys0, c.top[1] - c.zs);
    let l = (dy * dy + dz * dz).sqrt().max(1e-6);
    // The normal of the back that points behind and below it.
    let n = [dz / l, -dy / l];
    let n = if n[1] > 0.0 { [-n[0], -n[1]] } else { n };
    let off = |p: [f64; 2]| [p[0] + t * n[0], p[1] + t * n[1]];
    pad(
        b,
        Body,
        0.0,
        off([c.ys0, c.zs]),
        off(c.top),
        c.cw + 0.02,
        0.03,
    );
}

/// A patient chair: the treatment couch reclined 40° with its arm rests, a shell behind the
/// back and a foot plate under the end of the leg rest.
pub fn patient_chair(b: &mut Builder) {
    let hd = b.d / 2.0;
    let c = couch(b, 40.0);
    back_shell(b, &c, 0.07);
    pad(
        b,
        Body,
        0.0,
        [hd - 0.06, c.zs - 0.22],
        [hd - 0.02, c.zs - 0.32],
        0.8 * c.cw,
        0.03,
    );
}

/// A tattoo chair: the treatment couch laid almost flat (12°), a long padded arm rest on a post at
/// its right reaching forward past the seat, and a foot pedal on its base plate.
pub fn tattoo_chair(b: &mut Builder) {
    let hw = b.w / 2.0;
    let c = couch(b, 12.0);
    back_shell(b, &c, 0.07);
    let x = (c.cw + 0.05).min(hw - 0.06);
    let za = c.zs + 0.26;
    b.rod(
        Metal,
        [x, c.ys0 + 0.15, c.zs + 0.2],
        [x, c.ys0 + 0.15, za],
        0.02,
    );
    b.cuboid(
        Cushion,
        [x - 0.06, c.ys0 - 0.1, za],
        [x + 0.06, c.ys0 + 0.6, za + 0.06],
    );
    b.cuboid(Metal, [-0.08, 0.4, 0.0], [0.08, 0.55, 0.05]);
}
