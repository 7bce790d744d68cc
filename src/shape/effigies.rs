//! Layouts of figures that are not a person standing: a scarecrow (a cross of poles dressed in
//! a straw-stuffed shirt, straw at its cuffs and collar, a sacking head under a wide hat, the
//! pole bare below the shirt) and a statue (a figure on a moulded plinth, all of one stone).
//! Each faces +y and stays inside the size box.
use super::archetypes::Builder;
use super::materials::Role::*;

/// A scarecrow: an upright pole with a crossbar at the shoulders, a shirt over them (a body
/// and two sleeves along the bar; cloth, so "a straw scarecrow" keeps its shirt's colour),
/// straw tufts out of the cuffs, the collar and the hem, a sacking head with two dark eyes, a
/// wide-brimmed hat.
pub fn scarecrow(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let pr = (0.02 * h).clamp(0.02, 0.045);
    // The head's radius; the shoulders (the crossbar) leave room over them for the head and
    // its hat to reach the top.
    let hr = (0.075 * h).min(0.8 * hd).min(0.6 * hw);
    let zs = (h - 0.05 - 2.4 * hr).min(0.8 * h);
    b.cylinder(Trunk, [0.0, 0.0, 0.0], pr, zs + 0.05 + hr);
    b.rod(Trunk, [-hw, 0.0, zs], [hw, 0.0, zs], 0.8 * pr);
    // The shirt: a stuffed body hanging from the bar, its sleeves along it.
    let tw = (0.32 * hw).max(0.1);
    let td = (0.7 * hd).min(tw);
    let hem = 0.42 * h;
    b.ellipsoid(
        Duvet,
        [0.0, 0.0, 0.5 * (hem + zs)],
        [tw, td, 0.5 * (zs - hem) + 0.03],
    );
    let sr = (0.55 * td).min(0.07);
    let cuff = hw - 0.1 * hw;
    for sx in [-1.0, 1.0] {
        b.rod(
            Duvet,
            [sx * 0.6 * tw, 0.0, zs - 0.02],
            [sx * cuff, 0.0, zs],
            sr,
        );
        // Straw out of the cuff, hanging and splaying.
        for k in 0..4 {
            let dz = -0.04 * k as f64;
            b.rod(
                Cushion,
                [sx * cuff, 0.0, zs],
                [sx * (hw - 0.01), 0.02 * (k as f64 - 1.5), zs + dz - 0.03],
                0.012,
            );
        }
    }
    // Straw from the hem and round the collar.
    for k in 0..7 {
        let x = (k as f64 / 6.0 - 0.5) * 1.4 * tw;
        b.rod(
            Cushion,
            [x, 0.0, hem + 0.03],
            [1.1 * x, 0.3 * td, hem - 0.08],
            0.012,
        );
    }
    b.frustum(
        Cushion,
        [0.0, 0.0, zs + 0.01],
        0.5 * tw,
        0.5 * td,
        0.6,
        0.05,
    );
    // The head: a sack stuffed round, tied at the neck, two eyes; a hat with a wide brim.
    let zh = zs + 0.05 + hr;
    b.ellipsoid(Canvas, [0.0, 0.0, zh], [hr, 0.9 * hr, 1.05 * hr]);
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Interior,
            [sx * 0.35 * hr, 0.85 * hr, zh + 0.15 * hr],
            [0.14 * hr, 0.05 * hr, 0.14 * hr],
        );
    }
    let brim = (2.0 * hr).min(hw).min(hd);
    let zb = zh + 0.6 * hr;
    b.frustum(Top, [0.0, 0.0, zb], brim, brim, 1.0, 0.015);
    b.frustum(
        Top,
        [0.0, 0.0, zb],
        0.8 * hr,
        0.8 * hr,
        0.8,
        (h - zb).clamp(0.02, 0.8 * hr),
    );
}

/// A statue: a plinth with a moulded base and cap, and on it a standing figure with one arm
/// raised, every part in the stone's colour; its variant 1 stands at rest, arms at its sides.
pub fn statue(b: &mut Builder) {
    figure_on_plinth(b, b.variant.is_multiple_of(2));
}

/// A standing statue at rest: the figure of [`statue`] with both arms hanging at its sides
/// ("a standing statue").
pub fn standing_statue(b: &mut Builder) {
    figure_on_plinth(b, false);
}

/// A plinth and a robed figure standing on it, its left arm hanging, its right one raised with
/// a torch when `raised`, else hanging as the left.
fn figure_on_plinth(b: &mut Builder, raised: bool) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zp = 0.22 * h; // the plinth's top
    b.cuboid(Top, [-hw, -hd, 0.0], [hw, hd, 0.04 * h]);
    b.cuboid(
        Body,
        [-0.85 * hw, -0.85 * hd, 0.0],
        [0.85 * hw, 0.85 * hd, zp - 0.03 * h],
    );
    b.cuboid(
        Top,
        [-0.95 * hw, -0.95 * hd, zp - 0.03 * h],
        [0.95 * hw, 0.95 * hd, zp],
    );
    // The figure, in proportion to the height left: a long robe to the plinth, a torso widening
    // to square shoulders, a neck, a head; one arm hanging at its side, the other raised.
    let fh = h - zp;
    let (fw, fd) = (0.75 * hw, 0.6 * hd);
    let at = |t: f64| zp + t * fh;
    let waist = at(0.5);
    let shoulder = at(0.79);
    // The robe: a skirt widening to its hem, folds running down it, toes under the hem.
    let skirt = (0.62 * fw).min(1.1 * fd);
    b.frustum(Body, [0.0, 0.0, zp], skirt, 0.8 * skirt, 0.72, waist - zp);
    for k in 0..7 {
        let a = -0.9 + 1.8 * k as f64 / 6.0;
        let (c, sn) = (a.sin(), a.cos());
        b.rod(
            Body,
            [c * skirt, sn * 0.8 * skirt, zp + 0.01],
            [c * 0.72 * skirt, sn * 0.58 * skirt, waist - 0.02 * fh],
            0.05 * skirt,
        );
    }
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Body,
            [sx * 0.3 * skirt, 0.8 * skirt, zp + 0.02 * fh],
            [0.22 * skirt, 0.3 * skirt, 0.025 * fh],
        );
    }
    // The torso: from the waist up to the shoulders, a sash across it.
    let sh = 0.62 * fw; // half the shoulders' width, to the arms' sockets
    b.frustum(
        Body,
        [0.0, 0.0, waist - 0.02 * fh],
        0.5 * fw,
        (0.42 * fw).min(0.8 * fd),
        1.3,
        shoulder - waist + 0.02 * fh,
    );
    b.rod(
        Top,
        [-0.5 * fw, 0.3 * fw, waist + 0.05 * fh],
        [0.55 * fw, 0.3 * fw, shoulder - 0.04 * fh],
        0.04 * fw,
    );
    let ar = (0.045 * fh).min(0.14 * fw);
    b.ellipsoid(
        Body,
        [0.0, 0.0, shoulder - 0.01 * fh],
        [sh + 0.5 * ar, (0.5 * fw).min(fd), 0.03 * fh],
    );
    for sx in [-1.0, 1.0] {
        b.ellipsoid(
            Body,
            [sx * sh, 0.0, shoulder - ar],
            [1.4 * ar, 1.3 * ar, 1.2 * ar],
        );
    }
    // One arm hangs at the side, a hand at the hip; the other too when it is not raised.
    let sides: &[f64] = if raised { &[-1.0] } else { &[-1.0, 1.0] };
    for &sx in sides {
        let elbow = [sx * (sh + 0.7 * ar), 0.0, at(0.6)];
        b.rod(Body, [sx * sh, 0.0, shoulder - ar], elbow, ar);
        b.rod(
            Body,
            elbow,
            [sx * (sh + 0.5 * ar), 0.25 * fw, at(0.46)],
            0.9 * ar,
        );
        b.ellipsoid(
            Body,
            [sx * (sh + 0.5 * ar), 0.25 * fw, at(0.43)],
            [0.9 * ar, 0.9 * ar, 1.3 * ar],
        );
    }
    if raised {
        raised_arm(b, sh, ar, shoulder, fh);
    }
    // The neck and the head, with hair gathered at the back and a nose to the front.
    let hr = (0.05 * fh).min(0.38 * fw);
    let neck = shoulder + 0.05 * fh;
    b.rod(
        Body,
        [0.0, 0.0, shoulder - 0.02 * fh],
        [0.0, 0.0, neck],
        0.55 * hr,
    );
    let zh = neck + 1.1 * hr;
    b.ellipsoid(Body, [0.0, 0.0, zh], [hr, 1.1 * hr, 1.3 * hr]);
    b.ellipsoid(
        Top,
        [0.0, -0.25 * hr, zh + 0.2 * hr],
        [1.08 * hr, 1.0 * hr, 1.2 * hr],
    );
    b.ellipsoid(Body, [0.0, 1.05 * hr, zh], [0.2 * hr, 0.2 * hr, 0.3 * hr]);
}

/// The right arm raised overhead from the shoulder at `shoulder`, holding a torch whose flame
/// reaches the top.
fn raised_arm(b: &mut Builder, sh: f64, ar: f64, shoulder: f64, fh: f64) {
    let h = b.h;
    let up_elbow = [sh + 1.5 * ar, 0.0, shoulder + 0.1 * fh];
    b.rod(Body, [sh, 0.0, shoulder - ar], up_elbow, ar);
    let hand = [sh + 1.2 * ar, 0.0, h - 0.12 * fh];
    b.rod(Body, up_elbow, hand, 0.9 * ar);
    b.ellipsoid(Body, hand, [1.1 * ar, 1.1 * ar, 1.2 * ar]);
    b.frustum(
        Top,
        [hand[0], 0.0, hand[2]],
        0.9 * ar,
        0.9 * ar,
        1.8,
        0.07 * fh,
    );
    b.ellipsoid(
        Top,
        [hand[0], 0.0, h - 0.035 * fh],
        [1.5 * ar, 1.5 * ar, 0.035 * fh],
    );
}

/// A seated statue on a plinth: a block throne, the figure sitting upright on it, its thighs
/// level and shins down to the plinth, hands resting on its knees, its head over square
/// shoulders ("a seated statue", "an enthroned figure").
pub fn seated_statue(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zp = 0.2 * h; // the plinth's top
    b.cuboid(Top, [-hw, -hd, 0.0], [hw, hd, 0.04 * h]);
    b.cuboid(
        Body,
        [-0.85 * hw, -0.85 * hd, 0.0],
        [0.85 * hw, 0.85 * hd, zp],
    );
    let fh = h - zp;
    let at = |t: f64| zp + t * fh;
    let (fw, fd) = (0.7 * hw, 0.85 * hd);
    // The throne: a block seat at the back half, a back rising behind the figure.
    let seat = at(0.34);
    let back = -0.8 * fd;
    b.cuboid(Top, [-0.8 * fw, back, zp], [0.8 * fw, 0.05 * fd, seat]);
    b.cuboid(
        Top,
        [-0.8 * fw, back, seat],
        [0.8 * fw, back + 0.18 * fd, at(0.72)],
    );
    // Thighs forward from the hips, shins down to the plinth, feet on it.
    let lr = (0.16 * fw).min(0.09 * fh);
    let knee_y = 0.65 * fd;
    for sx in [-1.0, 1.0] {
        let x = sx * 0.3 * fw;
        let hip = [x, -0.25 * fd, seat + lr];
        let knee = [x, knee_y, seat + lr];
        b.rod(Body, hip, knee, lr);
        b.ellipsoid(Body, knee, [lr, lr, lr]);
        b.rod(Body, knee, [x, knee_y, zp + 0.5 * lr], 0.85 * lr);
        b.ellipsoid(
            Body,
            [x, knee_y + 0.5 * lr, zp + 0.4 * lr],
            [0.8 * lr, 1.6 * lr, 0.4 * lr],
        );
    }
    // The torso upright over the hips, shoulders, arms down to the hands on the knees.
    let shoulder = at(0.8);
    b.frustum(
        Body,
        [0.0, -0.3 * fd, seat],
        0.5 * fw,
        0.35 * fd,
        1.15,
        shoulder - seat,
    );
    let sh = 0.62 * fw;
    let ar = 0.75 * lr;
    for sx in [-1.0, 1.0] {
        let top = [sx * sh, -0.3 * fd, shoulder - ar];
        let elbow = [sx * (sh + 0.3 * ar), -0.1 * fd, at(0.52)];
        let hand = [sx * 0.32 * fw, 0.6 * knee_y, seat + 2.2 * lr];
        b.ellipsoid(Body, top, [1.4 * ar, 1.3 * ar, 1.2 * ar]);
        b.rod(Body, top, elbow, ar);
        b.rod(Body, elbow, hand, 0.9 * ar);
        b.ellipsoid(Body, hand, [ar, 1.2 * ar, 0.8 * ar]);
    }
    let hr = (0.075 * fh).min(0.4 * fw);
    let neck = shoulder + 0.05 * fh;
    b.rod(
        Body,
        [0.0, -0.3 * fd, shoulder - 0.03 * fh],
        [0.0, -0.3 * fd, neck],
        0.55 * hr,
    );
    let zh = (neck + 1.1 * hr).min(h - 1.3 * hr);
    b.ellipsoid(Body, [0.0, -0.3 * fd, zh], [hr, 1.1 * hr, 1.3 * hr]);
    b.ellipsoid(
        Body,
        [0.0, -0.3 * fd + 1.05 * hr, zh],
        [0.2 * hr, 0.2 * hr, 0.3 * hr],
    );
}
