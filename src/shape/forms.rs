//! Form words: "a round mirror", "an oval table", "a square ottoman" draw the archetype of that
//! form (`kb/forms.txt`), and the layouts of those forms. A form word counts only when it stands
//! before the category's name in the description, so "a vanity table with a round mirror" keeps
//! its table square.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, rot_x};
use super::Mount;
use std::f64::consts::FRAC_PI_2;

const FORMS: &str = include_str!("kb/forms.txt");

/// The rows of `kb/forms.txt`: (archetype, form words, archetype drawn).
pub fn rows() -> impl Iterator<Item = (&'static str, Vec<&'static str>, &'static str)> {
    FORMS
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter_map(|l| {
            let mut f = l.split('|').map(str::trim);
            let (a, w, d) = (f.next()?, f.next()?, f.next()?);
            Some((a, w.split(',').map(str::trim).collect(), d))
        })
}

/// The archetype drawn for `archetype` when `description` names a form of `category` (see the
/// module docs); `archetype` itself otherwise.
pub fn reshaped(archetype: &'static str, category: &str, description: &str) -> &'static str {
    let lower = description.to_lowercase();
    let words: Vec<&str> = lower
        .split(|c: char| !c.is_ascii_alphanumeric() && c != '-')
        .filter(|w| !w.is_empty())
        .collect();
    let head = category
        .rsplit(' ')
        .next()
        .unwrap_or(category)
        .to_lowercase();
    let plural = format!("{head}s");
    // Words before the category's head noun; without it, before the first "with".
    let end = words
        .iter()
        .position(|w| *w == head || *w == plural)
        .or_else(|| words.iter().position(|w| *w == "with"))
        .unwrap_or(words.len());
    let before = &words[..end];
    // The form word nearest the name decides ("a square table, no, a round table").
    before
        .iter()
        .rev()
        .find_map(|w| {
            rows()
                .find(|(a, forms, _)| *a == archetype && forms.contains(w))
                .map(|(_, _, d)| d)
        })
        .and_then(|d| super::archetypes::NAMES.iter().find(|n| **n == d).copied())
        .unwrap_or(archetype)
}

/// A disc (or an ellipse `az` times as tall) of radius `r` and thickness `t` facing +y, its back
/// at `c`.
fn disc(b: &mut Builder, role: super::materials::Role, c: [f64; 3], r: f64, az: f64, t: f64) {
    b.revolved(role, 0, c, rot_x(-FRAC_PI_2), az, frustum_profile(r, r, t));
}

/// A framed mirror of semi-axes `rx` (across) and `rz` (up) centred at height `zc`, on the back
/// plane of the box; standing, on two slim legs when it does not reach the floor (hung on a
/// wall or from the ceiling, it has none).
fn elliptic_mirror(b: &mut Builder, rx: f64, rz: f64, zc: f64) {
    let hd = b.d / 2.0;
    let t = (0.5 * b.d).min(0.03);
    disc(b, Frame, [0.0, -hd, zc], rx, rz / rx, t);
    let inset = (0.1 * rx).clamp(0.02, 0.05);
    let (ix, iz) = (rx - inset, rz - inset);
    disc(b, Canvas, [0.0, -hd + t, zc], ix, iz / ix, 0.003);
    super::mirrors::sheen(b, [0.0, -hd + t + 0.003, zc], ix, iz);
    if zc - rz > 0.05 && b.mount == Mount::Stand {
        // A cheval stand: two legs from the floor to the frame's sides, splayed feet.
        for sx in [-1.0, 1.0] {
            let x = sx * 0.75 * rx;
            b.rod(
                Frame,
                [x, -hd + 0.5 * t, 0.0],
                [x, -hd + 0.5 * t, zc],
                0.012,
            );
            b.cuboid(Frame, [x - 0.015, -hd, 0.0], [x + 0.015, hd, 0.02]);
        }
    }
}

/// A round mirror: a circle as wide as the box (or as tall, when it is lower than wide) at the
/// top of its box when it stands (on legs below it), in the middle of its box when it hangs.
pub fn round_mirror(b: &mut Builder) {
    let r = 0.5 * b.w.min(b.h);
    match b.mount {
        Mount::Stand => elliptic_mirror(b, r, r, b.h - r),
        Mount::Wall | Mount::Ceiling | Mount::Post(_) => {
            // hung on a leather strap from a peg: the disc at the foot of its box, the strap's
            // two ends meeting at the top
            let r = r.min(0.4 * b.h);
            elliptic_mirror(b, r, r, r);
            let (y, top) = (-b.d / 2.0 + 0.006, b.h - 0.01);
            for sx in [-1.0, 1.0] {
                b.rod(Upholstery, [sx * 0.6 * r, y, 1.8 * r], [0.0, y, top], 0.006);
            }
            b.cylinder(Metal, [0.0, -b.d / 2.0 + 0.012, top - 0.01], 0.012, 0.02);
        }
    }
}

/// An oval mirror filling its box's width and height (an upright ellipse).
pub fn oval_mirror(b: &mut Builder) {
    let (rx, rz) = (0.5 * b.w, 0.5 * b.h);
    elliptic_mirror(b, rx, rz, rz);
}

/// A flat elliptic rug of semi-axes `rx`, `ry`: a border ring round its field.
fn elliptic_rug(b: &mut Builder, rx: f64, ry: f64) {
    let h = b.h;
    let bw = (0.08 * rx.min(ry)).min(0.12);
    b.frustum(Cushion, [0.0, 0.0, 0.0], rx, ry, 1.0, 0.6 * h);
    b.frustum(Upholstery, [0.0, 0.0, 0.0], rx - bw, ry - bw, 1.0, h);
}

/// A round rug: a circle as wide as the box's shorter side.
pub fn round_rug(b: &mut Builder) {
    let r = 0.5 * b.w.min(b.d);
    elliptic_rug(b, r, r);
}

/// An oval rug filling its box.
pub fn oval_rug(b: &mut Builder) {
    elliptic_rug(b, 0.5 * b.w, 0.5 * b.d);
}

/// An oval table: an elliptic top filling the box on two pedestals along its length.
pub fn oval_table(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let t = (0.05 * h).clamp(0.025, 0.05);
    b.frustum(Top, [0.0, 0.0, h - t], hw, hd, 1.0, t);
    let m = hw.min(hd);
    let (long_x, off) = (b.w >= b.d, 0.45 * (hw.max(hd) - m));
    for s in [-1.0, 1.0] {
        let c = if long_x {
            [s * off, 0.0]
        } else {
            [0.0, s * off]
        };
        let r = (0.1 * m).max(0.025);
        b.cylinder(Frame, [c[0], c[1], 0.04], r, h - t - 0.04);
        b.frustum(Frame, [c[0], c[1], 0.0], 0.5 * m, 0.5 * m, 0.45, 0.05);
    }
}

/// A square ottoman: an upholstered block with a piped top edge and a tufted top on short feet.
pub fn square_ottoman(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let feet = (0.12 * h).min(0.05);
    b.legs(Frame, 0.04, 0.02, 0.0, feet);
    b.cuboid(Upholstery, [-hw, -hd, feet], [hw, hd, h - 0.03]);
    b.cuboid(
        Cushion,
        [-hw + 0.01, -hd + 0.01, h - 0.03],
        [hw - 0.01, hd - 0.01, h],
    );
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            b.cylinder(
                Frame,
                [sx * 0.25 * b.w, sy * 0.25 * b.d, h - 0.001],
                0.012,
                0.001,
            );
        }
    }
}
