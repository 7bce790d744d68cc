//! The [`Builder`] that archetype layouts draw with: boxes, frustums, cylinders, rods, slabs,
//! ellipsoids and surfaces of revolution in the object frame, collected as parts; and
//! [`frame_along`], the rotation that points a part's axis along a direction.
use super::materials::Role;
use super::parts::{ellipsoid_profile, frustum_profile, Part, Primitive, IDENTITY, M3, V3};

/// Collects parts in the object frame for a size `[w, d, h]`.
pub struct Builder {
    pub parts: Vec<Part>,
    pub w: f64,
    pub d: f64,
    pub h: f64,
    /// What the category's shelves hold (`kb/shelf_goods.txt`); `None` where it has no row.
    pub goods: Option<super::goods::Goods>,
    /// The animal a quadruped is drawn as (`kb/animals.txt`); `None` for other categories.
    pub animal: Option<&'static super::animals::Animal>,
    /// The bird a bird is drawn as (`kb/birds.txt`); `None` for other categories.
    pub bird: Option<&'static super::birds::Bird>,
    /// Which of its archetype's variants to draw (`kb/variants.txt`: a poster's print, a
    /// statue's pose), below the archetype's count; 0 is its usual drawing.
    pub variant: u32,
    /// How it is held up: a wall thing draws no legs, a ceiling thing hangs on a cord.
    pub mount: super::Mount,
}

impl Builder {
    /// Half width and half depth.
    pub fn half(&self) -> (f64, f64) {
        (self.w / 2.0, self.d / 2.0)
    }

    /// Moves every part drawn since the first `first` parts by `by` (a body drawn centred,
    /// then set off-centre to leave room beside it).
    pub fn translate_from(&mut self, first: usize, by: V3) {
        for p in &mut self.parts[first..] {
            let c = match &mut p.prim {
                Primitive::Cuboid { centre, .. } => centre,
                Primitive::Revolved { origin, .. } => origin,
            };
            for (v, d) in c.iter_mut().zip(by) {
                *v += d;
            }
        }
    }

    /// Turns every part drawn since the first `first` parts by `m` about the origin (a part
    /// drawn along one axis, then set along another).
    pub fn turn_from(&mut self, first: usize, m: M3) {
        for p in &mut self.parts[first..] {
            let (c, r) = match &mut p.prim {
                Primitive::Cuboid { centre, rot, .. } => (centre, rot),
                Primitive::Revolved { origin, rot, .. } => (origin, rot),
            };
            *c = super::parts::mul(&m, *c);
            *r = super::parts::mat_mul(&m, r);
        }
    }

    pub fn push(&mut self, role: Role, variant: u32, prim: Primitive) {
        self.parts.push(Part {
            prim,
            role,
            variant,
        });
    }

    /// An axis-aligned box between corners `lo` and `hi` (degenerate extents are thickened to
    /// 1 mm so every box has a surface).
    pub fn cuboid(&mut self, role: Role, lo: V3, hi: V3) {
        self.cuboid_v(role, 0, lo, hi);
    }

    /// [`Builder::cuboid`] with a colour variant.
    pub fn cuboid_v(&mut self, role: Role, variant: u32, lo: V3, hi: V3) {
        let centre = [0, 1, 2].map(|i| 0.5 * (lo[i] + hi[i]));
        let half = [0, 1, 2].map(|i| (0.5 * (hi[i] - lo[i]).abs()).max(0.0005));
        self.push(
            role,
            variant,
            Primitive::Cuboid {
                centre,
                half,
                rot: IDENTITY,
            },
        );
    }

    /// A closed vertical elliptic frustum standing on `base`: radii `rx`, `ry` at the bottom,
    /// `top` times them at the top, height `h`.
    pub fn frustum(&mut self, role: Role, base: V3, rx: f64, ry: f64, top: f64, h: f64) {
        self.revolved(
            role,
            0,
            base,
            IDENTITY,
            ry / rx,
            frustum_profile(rx, rx * top, h),
        );
    }

    /// A closed vertical cylinder.
    pub fn cylinder(&mut self, role: Role, base: V3, r: f64, h: f64) {
        self.frustum(role, base, r, r, 1.0, h);
    }

    /// A closed cylinder of radius `r` from `a` to `b`.
    pub fn rod(&mut self, role: Role, a: V3, b: V3, r: f64) {
        let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-9);
        self.revolved(role, 0, a, frame_along(d), 1.0, frustum_profile(r, r, l));
    }

    /// An oriented box: `half` extents along the axes of `rot`, centred at `centre`.
    pub fn slab(&mut self, role: Role, centre: V3, half: V3, rot: M3) {
        self.slab_v(role, 0, centre, half, rot);
    }

    /// [`Builder::slab`] with a colour variant.
    pub fn slab_v(&mut self, role: Role, variant: u32, centre: V3, half: V3, rot: M3) {
        self.push(role, variant, Primitive::Cuboid { centre, half, rot });
    }

    /// Rods of radius `r` joining successive points of `pts` (a bent bar, a chain, an arc).
    pub fn polyline(&mut self, role: Role, pts: &[V3], r: f64) {
        for w in pts.windows(2) {
            self.rod(role, w[0], w[1], r);
        }
    }

    /// An ellipsoid with semi-axes `radii` (x, y, z) at `centre`.
    pub fn ellipsoid(&mut self, role: Role, centre: V3, radii: V3) {
        self.ellipsoid_rot(role, 0, centre, radii, IDENTITY);
    }

    /// An oriented ellipsoid with a colour variant.
    pub fn ellipsoid_rot(&mut self, role: Role, variant: u32, centre: V3, radii: V3, rot: M3) {
        let profile = ellipsoid_profile(radii[0], radii[2]);
        self.revolved(role, variant, centre, rot, radii[1] / radii[0], profile);
    }

    /// A surface of revolution (see [`Primitive::Revolved`]).
    pub fn revolved(
        &mut self,
        role: Role,
        variant: u32,
        origin: V3,
        rot: M3,
        ay: f64,
        profile: Vec<[f64; 2]>,
    ) {
        self.push(
            role,
            variant,
            Primitive::Revolved {
                origin,
                rot,
                ay,
                profile,
            },
        );
    }

    /// Four square legs of side `s` inset `inset` from the corners, from `z0` to `z1`.
    pub fn legs(&mut self, role: Role, s: f64, inset: f64, z0: f64, z1: f64) {
        let (hw, hd) = self.half();
        for sx in [-1.0, 1.0] {
            for sy in [-1.0, 1.0] {
                let (x, y) = (sx * (hw - inset - s / 2.0), sy * (hd - inset - s / 2.0));
                self.cuboid(
                    role,
                    [x - s / 2.0, y - s / 2.0, z0],
                    [x + s / 2.0, y + s / 2.0, z1],
                );
            }
        }
    }
}

/// A rotation whose local z axis points along `d`.
pub fn frame_along(d: V3) -> M3 {
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-12);
    let z = d.map(|v| v / l);
    let helper = if z[2].abs() < 0.9 {
        [0.0, 0.0, 1.0]
    } else {
        [1.0, 0.0, 0.0]
    };
    let x = {
        let c = [
            helper[1] * z[2] - helper[2] * z[1],
            helper[2] * z[0] - helper[0] * z[2],
            helper[0] * z[1] - helper[1] * z[0],
        ];
        let l = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
        c.map(|v| v / l)
    };
    let y = [
        z[1] * x[2] - z[2] * x[1],
        z[2] * x[0] - z[0] * x[2],
        z[0] * x[1] - z[1] * x[0],
    ];
    [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]
}
