//! Things the text hangs on a wall that their kind stands on the floor or on a top, or that
//! the knowledge base does not know: "a guitar hanging on the wall", "a neon sign on the
//! wall", "a framed print on the wall", "tyres hanging on the wall", "a monitor on the wall". Such a thing hangs there (the spec's
//! `on_wall`) when it is something that can hang: not a support, a seat or a large piece, and
//! thin and light enough. Furniture said to be "on the back wall" stands against it as before.
use super::Draft;
use crate::plan::gcp::classes::{Class, Placements};
use crate::plan::spec::{SceneSpec, SceneType};

/// The height (m) of the middle of a thing hung on a wall: eye level.
const EYE: f64 = 1.5;
/// The largest height, depth (m) and footprint (m²) of a thing that hangs on a wall.
const MAX_HEIGHT: f64 = 1.6;
const MAX_DEPTH: f64 = 0.45;
const MAX_FOOTPRINT: f64 = 0.6;
/// The depth (m) an unknown thing hung on a wall is drawn with: flat against it.
const FLAT: f64 = 0.12;

/// Sets `on_wall` on the categories of `spec` that the text hangs on a wall and that hang.
pub(super) fn hang(d: &mut Draft, spec: &mut SceneSpec) {
    if d.scene_type != SceneType::Indoor {
        return;
    }
    let table = Placements::builtin();
    for &i in &d.r.hung {
        let (Some(m), Some(cat)) = (d.r.mentions.get(i), d.cats.get(i)) else {
            continue;
        };
        if m.negated || m.reference {
            continue;
        }
        let known = d.kb.object(cat).is_some();
        // (a thing that stands on a top, "a monitor on the wall showing the stage", hangs at
        // the height its kind hangs at where it has one)
        let (floor, mount) = match table.get(cat) {
            Some(p) => match p.class {
                Class::Floor | Class::AgainstWall => (true, None),
                Class::OnSurface(h) => (true, h),
                _ => (false, None),
            },
            None => (true, None),
        };
        if !floor || table.is_support(cat) || crate::plan::lang::is_seat(cat) {
            continue;
        }
        let Some(o) = spec.objects.get_mut(cat) else {
            continue;
        };
        let [w, dep, h] = o.size;
        let footprint = w * if known { dep } else { FLAT };
        if h > MAX_HEIGHT || (known && dep > MAX_DEPTH) || footprint > MAX_FOOTPRINT {
            continue;
        }
        if !known {
            o.size[1] = dep.min(FLAT);
            for s in &mut o.sizes {
                s[1] = s[1].min(FLAT);
            }
        }
        let bottom = mount.unwrap_or(((EYE - h / 2.0) * 100.0).round() / 100.0);
        o.on_wall = Some(bottom.max(0.3));
        d.notes.push(format!(
            "{cat}: hung on a wall as the text says, its bottom at {:.2} m",
            bottom.max(0.3)
        ));
    }
}
