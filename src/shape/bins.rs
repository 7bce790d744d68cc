//! Layouts of open and lidded containers of their own function: a pedal bin (a body under a
//! domed lid hinged at the back, a pedal at the front foot) and an umbrella stand (an open tube
//! with the furled umbrellas' canopies and crook handles standing out of it). The front faces +y.
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::{frustum_profile, IDENTITY};
use super::racks::along;

/// A pedal bin: a round body on a dark foot ring, a rolled rim, a shallow domed lid with its
/// hinge at the back, and a pedal sticking out at the front foot.
pub fn trash_can(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.84 * hw.min(hd);
    let lid = 0.1 * h;
    let body = h - lid;
    b.cylinder(Tyre, [0.0, 0.0, 0.0], 0.97 * r, 0.03);
    b.frustum(
        Body,
        [0.0, 0.0, 0.03],
        0.96 * r,
        0.96 * r,
        1.0 / 0.96,
        body - 0.05,
    );
    b.revolved(
        Metal,
        0,
        [0.0, 0.0, body - 0.02],
        IDENTITY,
        1.0,
        frustum_profile(1.02 * r, 1.02 * r, 0.02),
    );
    // The lid: a low cap rising to a flat top, with a seam where it meets the rim.
    b.revolved(
        Top,
        0,
        [0.0, 0.0, body],
        IDENTITY,
        1.0,
        vec![
            [0.0, 0.0],
            [1.02 * r, 0.0],
            [1.0 * r, 0.3 * lid],
            [0.8 * r, 0.85 * lid],
            [0.5 * r, lid],
            [0.0, lid],
        ],
    );
    b.rod(
        Handle,
        [-0.3 * r, -r - 0.01, body - 0.005],
        [0.3 * r, -r - 0.01, body - 0.005],
        0.012,
    );
    // The pedal: a bar from the foot out to a tread at the front.
    b.cuboid(Handle, [-0.25 * r, r - 0.02, 0.03], [0.25 * r, hd, 0.055]);
    b.cuboid(Metal, [-0.3 * r, hd - 0.04, 0.035], [0.3 * r, hd, 0.06]);
}

/// An umbrella stand: an open tube with a rim and a dark inside, and three furled umbrellas
/// leaning in it, their canopies and crook handles standing out above the rim.
pub fn umbrella_stand(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = 0.9 * hw.min(hd);
    let tube = 0.68 * h;
    let wall = 0.012;
    b.revolved(
        Body,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        vec![[0.0, 0.0], [r, 0.0], [r, tube], [r - wall, tube]],
    );
    b.revolved(
        Interior,
        0,
        [0.0, 0.0, 0.0],
        IDENTITY,
        1.0,
        vec![[r - wall, tube], [r - wall, 0.02], [0.0, 0.02]],
    );
    // Three umbrellas standing on their tips, leaning out from the middle.
    for (k, a) in [0.3f64, 2.4, 4.4].into_iter().enumerate() {
        let (s, c) = a.sin_cos();
        let lean = 0.09;
        let tip = [0.35 * r * c, 0.35 * r * s, 0.02];
        let u = {
            let v = [lean * c, lean * s, 1.0];
            let l = (v[0] * v[0] + v[1] * v[1] + 1.0).sqrt();
            v.map(|q| q / l)
        };
        let at = |t: f64| [0, 1, 2].map(|i| tip[i] + u[i] * t);
        let canopy = tube + 0.12 * h - 0.02 * k as f64;
        let rc = (0.3 * r).min(0.035);
        along(
            b,
            Books,
            k as u32,
            tip,
            u,
            0.0,
            1.0,
            vec![
                [0.0, 0.0],
                [0.5 * rc, 0.1 * canopy],
                [rc, 0.55 * canopy],
                [0.8 * rc, canopy],
                [0.0, canopy + 0.01],
            ],
        );
        // The shaft above the canopy, then a crook curling back over the middle.
        let top = h - 0.075 - 0.03 * k as f64;
        let shaft_end = at((top - tip[2]) / u[2]);
        b.rod(Metal, at(canopy), shaft_end, 0.006);
        let rh = 0.035;
        let (ix, iy) = (-c, -s);
        let mut pts = vec![];
        for j in 0..=6 {
            let th = std::f64::consts::PI * j as f64 / 6.0;
            pts.push([
                shaft_end[0] + rh * (1.0 - th.cos()) * ix,
                shaft_end[1] + rh * (1.0 - th.cos()) * iy,
                shaft_end[2] + rh * th.sin(),
            ]);
        }
        pts.push([pts[6][0], pts[6][1], pts[6][2] - 0.03]);
        b.polyline(Handle, &pts, 0.011);
    }
}
