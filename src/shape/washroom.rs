//! Layouts of basins that stand or hang on their own: a wall urinal, a pedestal sink and a
//! baptismal font. The front faces +y, z up, the bottom face's centre at the origin; the back
//! of the first two is the wall (-y).
use super::archetypes::Builder;
use super::materials::Role::*;
use super::parts::IDENTITY;

/// A wall urinal: a tall rounded bowl hung on the wall with its open mouth facing forward,
/// a chrome flush pipe rising from its top and a trap below.
pub fn urinal(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let (z0, z1) = (0.22 * h, 0.9 * h);
    let zc = 0.5 * (z0 + z1);
    // The bowl: the front half of an upright ellipsoid, cut by the wall behind and open in
    // front, where the size box cuts it: through the mouth one sees the bowl's grey inside.
    let (rx, ry, rz) = (0.95 * hw, 1.15 * b.d, 0.5 * (z1 - z0));
    b.ellipsoid(Body, [0.0, -hd, zc], [rx, ry, rz]);
    // A flat back plate on the wall, the bowl's top edge.
    b.cuboid(Body, [-0.8 * hw, -hd, zc], [0.8 * hw, -hd + 0.2 * b.d, z1]);
    b.ellipsoid_rot(
        Canvas,
        0,
        [0.0, -hd + 0.45 * b.d, zc - 0.05 * rz],
        [0.6 * rx, 0.005, 0.62 * rz],
        IDENTITY,
    );
    b.ellipsoid_rot(
        Interior,
        0,
        [0.0, -hd + 0.47 * b.d, zc - 0.45 * rz],
        [0.12 * rx, 0.005, 0.06 * rz],
        IDENTITY,
    );
    // The flush pipe and its valve.
    let yp = -hd + 0.06;
    b.cylinder(Metal, [0.0, yp, z1 - 0.02], 0.02, h - z1 + 0.02 - 0.07 * h);
    b.ellipsoid(Metal, [0.0, yp, h - 0.05 * h], [0.04, 0.035, 0.05 * h]);
    b.rod(
        Metal,
        [0.0, yp, h - 0.05 * h],
        [0.0, yp + 0.1, h - 0.05 * h],
        0.008,
    );
    // The waste pipe from under the bowl down to the floor drain (the draft stands on the
    // floor: a hung shape would drop to it).
    b.cylinder(Metal, [0.0, -hd + 0.12, 0.0], 0.025, z0 + 0.02);
}

/// A pedestal sink: an oval basin with a flat rim and a low splashback on a column that
/// flares to the floor, a tap rising behind the bowl.
pub fn pedestal_sink(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let zt = 0.9 * h;
    let depth = 0.17 * h;
    // The column: a foot, a shaft waisted below the middle, a flared top under the basin.
    let rp = 0.3 * hw.min(hd);
    let yp = -0.2 * hd;
    b.frustum(Body, [0.0, yp, 0.0], 1.5 * rp, 1.5 * rp, 0.8, 0.06 * h);
    b.frustum(
        Body,
        [0.0, yp, 0.06 * h],
        1.2 * rp,
        1.2 * rp,
        0.75,
        0.24 * h,
    );
    b.frustum(
        Body,
        [0.0, yp, 0.3 * h],
        0.9 * rp,
        0.9 * rp,
        1.1,
        zt - depth - 0.3 * h,
    );
    b.frustum(Body, [0.0, yp, zt - depth], rp, rp, 1.6, 0.4 * depth);
    // The basin: a rounded bowl under a flat rim; the bowl's inside a lighter oval.
    let (rw, rd) = (0.98 * hw, 0.85 * hd);
    b.revolved(
        Body,
        0,
        [0.0, -0.1 * hd, zt - depth],
        IDENTITY,
        rd / rw,
        vec![
            [0.0, 0.0],
            [0.45 * rw, 0.0],
            [0.85 * rw, 0.4 * depth],
            [rw, depth],
            [0.0, depth],
        ],
    );
    b.frustum(
        Canvas,
        [0.0, 0.0, zt - 0.005],
        0.72 * rw,
        0.6 * rd,
        0.9,
        0.008,
    );
    b.cylinder(Interior, [0.0, 0.0, zt + 0.002], 0.035, 0.004);
    // The splashback and the tap.
    b.cuboid(Body, [-0.9 * hw, -hd, zt - 0.02], [0.9 * hw, -hd + 0.05, h]);
    let yt = -hd + 0.09;
    b.cylinder(Metal, [0.0, yt, zt], 0.018, 0.07 * h);
    b.rod(
        Metal,
        [0.0, yt, zt + 0.07 * h],
        [0.0, yt + 0.12, zt + 0.06 * h],
        0.012,
    );
    for sx in [-1.0, 1.0] {
        b.cylinder(Handle, [sx * 0.1, yt, zt], 0.016, 0.035);
    }
}

/// A baptismal font: a deep stone bowl holding water, on a stout column over a stepped base,
/// a moulding under the rim.
pub fn font(b: &mut Builder) {
    let (hw, hd, h) = (b.w / 2.0, b.d / 2.0, b.h);
    let r = hw.min(hd);
    let ay = hd / hw;
    // the stepped base: two discs, the upper narrower and taller
    for (radius, top) in [(0.85 * r, 0.06 * h), (0.65 * r, 0.12 * h)] {
        b.revolved(
            Top,
            0,
            [0.0, 0.0, 0.0],
            IDENTITY,
            ay,
            vec![[0.0, 0.0], [radius, 0.0], [radius, top], [0.0, top]],
        );
    }
    let zb = 0.55 * h;
    b.frustum(
        Body,
        [0.0, 0.0, 0.12 * h],
        0.38 * r,
        0.38 * r * ay,
        0.8,
        zb - 0.12 * h,
    );
    // The bowl: it widens from the column's top to the rim.
    b.revolved(
        Body,
        0,
        [0.0, 0.0, zb],
        IDENTITY,
        ay,
        vec![
            [0.0, 0.0],
            [0.4 * r, 0.0],
            [0.8 * r, 0.35 * (h - zb)],
            [0.97 * r, 0.85 * (h - zb)],
            [r, h - zb],
            [0.0, h - zb],
        ],
    );
    b.revolved(
        Top,
        0,
        [0.0, 0.0, zb + 0.3 * (h - zb)],
        IDENTITY,
        ay,
        vec![[0.77 * r, 0.0], [0.8 * r, 0.03 * h], [0.0, 0.03 * h]],
    );
    b.frustum(
        Top,
        [0.0, 0.0, h - 0.004],
        0.99 * r,
        0.99 * r * ay,
        1.0,
        0.004,
    );
    b.frustum(
        Water,
        [0.0, 0.0, h - 0.002],
        0.85 * r,
        0.85 * r * ay,
        1.0,
        0.002,
    );
}
