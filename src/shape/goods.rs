//! What shelves hold: the kind of goods a category's shelves carry (`kb/shelf_goods.txt`:
//! books, loaves and bread baskets, grocery packs and cans, medicine boxes, toys, boxes and
//! bins, bottles and jars, folded clothes, baskets, balls), one builder that lays a row of them
//! along a board, and each kind's palette for the [`Role::Books`] parts, so a bakery's shelf
//! never shows book spines. Deterministic: the same board gives the same goods.
use super::builder::{frame_along, Builder};
use super::materials::{Rgb, Role::*};
use super::parts::{frustum_profile, IDENTITY};
use std::sync::OnceLock;

/// A kind of goods on shelves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Goods {
    #[default]
    Books,
    Loaves,
    Groceries,
    Medicine,
    Toys,
    Boxes,
    Bottles,
    Clothes,
    Baskets,
    Balls,
    Magazines,
    /// Fruit and vegetables: round things in the colours of produce.
    Produce,
    /// Bunches of flowers (a vase's bouquet).
    Flowers,
    /// Plates standing on their rims (a kitchen dresser's rack).
    Plates,
    /// Rings, chains and stones on velvet pads (a jeweller's case).
    Jewels,
    /// Urns, busts and tablets (a museum's case).
    Artefacts,
}

impl Goods {
    /// Every kind, in table order.
    pub const ALL: [Goods; 16] = [
        Goods::Books,
        Goods::Loaves,
        Goods::Groceries,
        Goods::Medicine,
        Goods::Toys,
        Goods::Boxes,
        Goods::Bottles,
        Goods::Clothes,
        Goods::Baskets,
        Goods::Balls,
        Goods::Magazines,
        Goods::Produce,
        Goods::Flowers,
        Goods::Plates,
        Goods::Jewels,
        Goods::Artefacts,
    ];

    /// The table's name of the kind.
    pub fn name(self) -> &'static str {
        match self {
            Goods::Books => "books",
            Goods::Loaves => "loaves",
            Goods::Groceries => "groceries",
            Goods::Medicine => "medicine",
            Goods::Toys => "toys",
            Goods::Boxes => "boxes",
            Goods::Bottles => "bottles",
            Goods::Clothes => "clothes",
            Goods::Baskets => "baskets",
            Goods::Balls => "balls",
            Goods::Magazines => "magazines",
            Goods::Produce => "produce",
            Goods::Flowers => "flowers",
            Goods::Plates => "plates",
            Goods::Jewels => "jewels",
            Goods::Artefacts => "artefacts",
        }
    }

    /// The kind a table name names.
    pub fn parse(name: &str) -> Option<Goods> {
        Goods::ALL.into_iter().find(|g| g.name() == name.trim())
    }

    /// Colours of this kind's goods, chosen by a part's variant: the first few entries (its
    /// specials) are fixed colours the builder asks for by index (a basket's wicker, a
    /// medicine box's white), the rest are the kind's product colours.
    pub fn palette(self) -> &'static [Rgb] {
        match self {
            Goods::Books => BOOKS,
            Goods::Loaves => LOAVES,
            Goods::Groceries => GROCERIES,
            Goods::Medicine => MEDICINE,
            Goods::Toys => TOYS,
            Goods::Boxes => BOXES,
            Goods::Bottles => BOTTLES,
            Goods::Clothes => CLOTHES,
            Goods::Baskets => BASKETS,
            Goods::Balls => BALLS,
            Goods::Magazines => MAGAZINES,
            Goods::Produce => PRODUCE,
            Goods::Flowers => FLOWERS,
            Goods::Plates => PLATES,
            Goods::Jewels => JEWELS,
            Goods::Artefacts => ARTEFACTS,
        }
    }

    /// How many leading palette entries are fixed colours rather than product colours.
    fn specials(self) -> usize {
        match self {
            Goods::Loaves | Goods::Medicine | Goods::Bottles => 2,
            Goods::Jewels => 3,
            Goods::Boxes | Goods::Balls | Goods::Flowers | Goods::Plates | Goods::Artefacts => 1,
            _ => 0,
        }
    }

    /// A product colour's variant for a draw `r` in [0, 1).
    pub(super) fn accent(self, r: f64) -> u32 {
        let (s, n) = (self.specials(), self.palette().len());
        (s + ((r * (n - s) as f64) as usize).min(n - s - 1)) as u32
    }
}

/// Book spines.
const BOOKS: &[Rgb] = &[
    [0.62, 0.14, 0.12],
    [0.14, 0.24, 0.45],
    [0.20, 0.40, 0.24],
    [0.80, 0.68, 0.40],
    [0.30, 0.20, 0.14],
    [0.85, 0.82, 0.74],
    [0.55, 0.30, 0.45],
    [0.15, 0.15, 0.16],
    [0.80, 0.45, 0.15],
];
/// Wicker, a basket's dark inside, then crusts from pale to dark.
const LOAVES: &[Rgb] = &[
    [0.66, 0.50, 0.30],
    [0.36, 0.25, 0.14],
    [0.86, 0.64, 0.34],
    [0.76, 0.50, 0.24],
    [0.62, 0.38, 0.18],
    [0.90, 0.76, 0.50],
    [0.50, 0.32, 0.18],
];
/// Bright packaging.
const GROCERIES: &[Rgb] = &[
    [0.86, 0.16, 0.12],
    [0.98, 0.80, 0.10],
    [0.12, 0.45, 0.80],
    [0.20, 0.62, 0.25],
    [0.96, 0.55, 0.10],
    [0.95, 0.95, 0.93],
    [0.55, 0.20, 0.55],
    [0.10, 0.20, 0.45],
    [0.80, 0.10, 0.35],
];
/// A box's white, a pale blister blue, then the bands of the brands.
const MEDICINE: &[Rgb] = &[
    [0.95, 0.95, 0.94],
    [0.85, 0.90, 0.95],
    [0.15, 0.50, 0.30],
    [0.20, 0.40, 0.75],
    [0.85, 0.20, 0.20],
    [0.95, 0.60, 0.10],
    [0.50, 0.25, 0.60],
    [0.10, 0.60, 0.65],
];
/// Primary toy colours and a teddy's brown.
const TOYS: &[Rgb] = &[
    [0.90, 0.15, 0.12],
    [0.15, 0.40, 0.85],
    [0.98, 0.82, 0.10],
    [0.20, 0.70, 0.30],
    [0.95, 0.50, 0.75],
    [0.60, 0.40, 0.22],
    [0.98, 0.55, 0.10],
    [0.55, 0.30, 0.80],
];
/// Packing tape, then cardboard and plastic bins.
const BOXES: &[Rgb] = &[
    [0.50, 0.36, 0.20],
    [0.72, 0.55, 0.34],
    [0.66, 0.49, 0.30],
    [0.76, 0.60, 0.40],
    [0.25, 0.35, 0.55],
    [0.45, 0.46, 0.48],
    [0.70, 0.53, 0.32],
];
/// Cork, a label's paper, then coloured glass.
const BOTTLES: &[Rgb] = &[
    [0.55, 0.40, 0.25],
    [0.90, 0.85, 0.70],
    [0.20, 0.55, 0.30],
    [0.45, 0.15, 0.55],
    [0.15, 0.30, 0.70],
    [0.75, 0.15, 0.15],
    [0.85, 0.60, 0.15],
    [0.10, 0.55, 0.60],
];
/// Folded textiles.
const CLOTHES: &[Rgb] = &[
    [0.20, 0.25, 0.40],
    [0.85, 0.84, 0.80],
    [0.60, 0.15, 0.18],
    [0.35, 0.45, 0.30],
    [0.15, 0.15, 0.16],
    [0.70, 0.62, 0.50],
    [0.45, 0.55, 0.70],
    [0.80, 0.55, 0.60],
];
/// Woven and fabric baskets.
const BASKETS: &[Rgb] = &[
    [0.70, 0.54, 0.32],
    [0.55, 0.40, 0.24],
    [0.80, 0.72, 0.58],
    [0.45, 0.50, 0.55],
    [0.30, 0.35, 0.45],
];
/// A finger hole's black, then ball colours.
const BALLS: &[Rgb] = &[
    [0.03, 0.03, 0.03],
    [0.15, 0.20, 0.65],
    [0.70, 0.10, 0.12],
    [0.10, 0.50, 0.30],
    [0.45, 0.15, 0.55],
    [0.10, 0.10, 0.11],
    [0.85, 0.50, 0.10],
];

/// Apples, oranges, lemons, limes, aubergines, tomatoes, cabbages, onions.
const PRODUCE: &[Rgb] = &[
    [0.78, 0.12, 0.10],
    [0.95, 0.55, 0.08],
    [0.96, 0.85, 0.20],
    [0.45, 0.70, 0.20],
    [0.30, 0.12, 0.32],
    [0.88, 0.22, 0.12],
    [0.55, 0.75, 0.45],
    [0.80, 0.62, 0.40],
];

/// A stem's green, then blooms.
const FLOWERS: &[Rgb] = &[
    [0.22, 0.45, 0.18],
    [0.90, 0.15, 0.20],
    [0.98, 0.85, 0.20],
    [0.95, 0.55, 0.70],
    [0.98, 0.97, 0.95],
    [0.55, 0.30, 0.75],
    [0.98, 0.50, 0.10],
];
/// A well's white glaze, then rims: blue-and-white, cream, green, a painted red.
const PLATES: &[Rgb] = &[
    [0.96, 0.96, 0.94],
    [0.20, 0.35, 0.70],
    [0.92, 0.88, 0.76],
    [0.45, 0.62, 0.50],
    [0.75, 0.25, 0.20],
    [0.85, 0.85, 0.88],
];
/// A pad's dark velvet, gold, silver, then stones.
const JEWELS: &[Rgb] = &[
    [0.10, 0.08, 0.14],
    [0.85, 0.68, 0.25],
    [0.82, 0.83, 0.86],
    [0.75, 0.05, 0.15],
    [0.10, 0.35, 0.85],
    [0.10, 0.65, 0.35],
    [0.95, 0.95, 0.98],
];
/// A plinth's marble, then terracotta, bronze, old stone, gilt and glazed blue.
const ARTEFACTS: &[Rgb] = &[
    [0.90, 0.89, 0.86],
    [0.72, 0.40, 0.24],
    [0.45, 0.32, 0.16],
    [0.62, 0.60, 0.55],
    [0.80, 0.64, 0.30],
    [0.25, 0.40, 0.60],
];

/// Glossy covers and their pictures.
const MAGAZINES: &[Rgb] = &[
    [0.85, 0.12, 0.15],
    [0.10, 0.30, 0.70],
    [0.98, 0.85, 0.15],
    [0.92, 0.92, 0.90],
    [0.10, 0.10, 0.12],
    [0.90, 0.40, 0.60],
    [0.20, 0.60, 0.55],
    [0.95, 0.55, 0.15],
    [0.45, 0.65, 0.85],
];

/// The table: category rows and archetype rows.
struct Table {
    categories: Vec<(String, Goods)>,
    archetypes: Vec<(String, Goods)>,
}

fn table() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| {
        let mut t = Table {
            categories: vec![],
            archetypes: vec![],
        };
        for line in include_str!("kb/shelf_goods.txt").lines() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let Some((name, kind)) = line.split_once('|') else {
                continue;
            };
            let Some(g) = Goods::parse(kind) else {
                continue;
            };
            match name.trim().strip_prefix("archetype ") {
                Some(a) => t.archetypes.push((a.trim().to_string(), g)),
                None => t.categories.push((name.trim().to_string(), g)),
            }
        }
        t
    })
}

/// The table's category rows.
pub fn rows() -> Vec<(&'static str, Goods)> {
    table()
        .categories
        .iter()
        .map(|(c, g)| (c.as_str(), *g))
        .collect()
}

/// The lines of the table whose kind does not parse or that lack a `|` (for the tests).
pub fn bad_lines() -> Vec<&'static str> {
    include_str!("kb/shelf_goods.txt")
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter(|l| {
            l.split_once('|')
                .and_then(|(_, k)| Goods::parse(k))
                .is_none()
        })
        .collect()
}

/// What a category's shelves hold: its row, else its archetype's row; `None` when neither is
/// listed (the archetype's parts then keep the book palette for their products).
pub fn goods_of(category: &str, archetype: &str) -> Option<Goods> {
    let t = table();
    let c = category.trim().to_lowercase();
    // A synonym ("metal shelving") holds what its category holds.
    let c = crate::plan::kb::KnowledgeBase::builtin()
        .object(&c)
        .map_or(c, |o| o.category.clone());
    t.categories
        .iter()
        .find(|(n, _)| *n == c)
        .or_else(|| t.archetypes.iter().find(|(n, _)| n == archetype))
        .map(|(_, g)| *g)
}

/// A small deterministic generator (xorshift) for the goods' sizes and colours.
pub struct Draws(u64);

impl Draws {
    pub fn new(seed: u64) -> Draws {
        Draws(seed | 1)
    }

    /// A draw in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % 10_000) as f64 / 10_000.0
    }
}

/// One board's free space: from `x0` to `x1`, from the back `y0` forward by `depth`, from the
/// board's top `z` up by `room`.
#[derive(Debug, Clone, Copy)]
pub struct Bay {
    pub x0: f64,
    pub x1: f64,
    pub y0: f64,
    pub depth: f64,
    pub z: f64,
    pub room: f64,
}

/// What one item of a row may use: from `x` to the bay's end `x1`, between the bay's back `y0` and
/// its front `y1`, standing on `z` with `room` of height above it.
#[derive(Clone, Copy)]
pub(super) struct Slot {
    pub x: f64,
    pub x1: f64,
    pub y0: f64,
    pub y1: f64,
    pub z: f64,
    pub room: f64,
}

/// Lays a row of `goods` along `bay`, each item's width drawn from `r`; products of one kind
/// stand in facings (a few of the same side by side) as in a shop.
pub fn fill(b: &mut Builder, goods: Goods, bay: Bay, r: &mut Draws) {
    let Bay {
        x0,
        x1,
        y0,
        depth,
        z,
        room,
    } = bay;
    if room <= 0.02 || depth <= 0.02 {
        return;
    }
    let front = y0 + depth;
    let mut x = x0;
    while x < x1 - 0.03 {
        let slot = Slot {
            x,
            x1,
            y0,
            y1: front,
            z,
            room,
        };
        let used = match goods {
            Goods::Books => {
                let bw = (0.04 * (0.6 + 0.8 * r.next())).min(x1 - x);
                if r.next() >= 0.08 {
                    let bh = room * (0.65 + 0.3 * r.next());
                    let v = (r.next() * 9.0) as u32;
                    b.cuboid_v(
                        Books,
                        v,
                        [x, y0, z],
                        [x + bw - 0.002, y0 + depth.min(0.3), z + bh],
                    );
                }
                bw
            }
            Goods::Loaves => loaves(b, r, slot),
            Goods::Groceries | Goods::Medicine => packs(b, goods, r, slot),
            Goods::Toys => toy(b, r, slot),
            Goods::Boxes => carton(b, r, slot),
            Goods::Bottles => bottles(b, r, slot),
            Goods::Clothes => folded(b, r, slot),
            Goods::Flowers => super::wares::flowers(b, r, slot),
            Goods::Plates => super::wares::plate(b, r, slot),
            Goods::Jewels => super::wares::jewels(b, r, slot),
            Goods::Artefacts => super::wares::artefact(b, r, slot),
            Goods::Baskets => basket(
                b,
                goods.accent(r.next()),
                x,
                (x + 0.34).min(x1),
                y0,
                front,
                z,
                room * 0.8,
            ),
            Goods::Magazines => {
                let (w, h) = ((0.75 * room).min(0.21), (0.9 * room).min(0.28));
                if w > x1 - x {
                    break;
                }
                let v = goods.accent(r.next());
                super::displays::magazine(b, v, [x + 0.5 * w, front - 0.05, z], w, h);
                w + 0.02
            }
            Goods::Balls | Goods::Produce => {
                let rad = (0.45 * room).min(0.11).min(0.45 * (front - y0));
                if 2.0 * rad > x1 - x {
                    break;
                }
                let c = [x + rad, 0.5 * (y0 + front), z + rad];
                b.ellipsoid_rot(Books, goods.accent(r.next()), c, [rad; 3], IDENTITY);
                if goods == Goods::Produce {
                    x += 2.0 * rad + 0.02;
                    continue;
                }
                // Three finger holes on the front, near the top.
                for (dx, dz) in [(-0.3, 0.45), (0.3, 0.45), (0.0, 0.1)] {
                    let h = [c[0] + dx * rad, c[1] + 0.8 * rad, c[2] + dz * rad];
                    b.ellipsoid_rot(Books, 0, h, [0.12 * rad, 0.2 * rad, 0.12 * rad], IDENTITY);
                }
                2.0 * rad + 0.02
            }
        };
        x += used.max(0.01);
    }
}

/// A basket from `xa` to `xb`: a woven body with its dark open top just below the rim and a
/// hand hole in its front; returns its width.
#[allow(
    clippy::too_many_arguments,
    reason = "one call draws one basket in its bay"
)]
fn basket(b: &mut Builder, v: u32, xa: f64, xb: f64, y0: f64, y1: f64, z: f64, h: f64) -> f64 {
    let t = 0.01;
    let (xa, xb) = (xa + 0.01, xb - 0.01);
    // No sliver of a basket at the end of a board: the gap stays empty.
    if xb - xa < 0.12 {
        return xb - xa + 0.02;
    }
    let (ya, yb) = (y0 + 0.01, y1 - 0.01);
    b.cuboid_v(Books, v, [xa, ya, z], [xb, yb, z + h]);
    b.cuboid(
        Interior,
        [xa + t, ya + t, z + h],
        [xb - t, yb - t, z + h + 0.002],
    );
    let xc = 0.5 * (xa + xb);
    let hw = (0.2 * (xb - xa)).min(0.05);
    b.cuboid(
        Interior,
        [xc - hw, yb, z + 0.75 * h],
        [xc + hw, yb + 0.002, z + 0.87 * h],
    );
    xb - xa + 0.03
}

/// Loaves lying along the board, two deep, and now and then a wicker basket of rolls.
fn loaves(b: &mut Builder, r: &mut Draws, slot: Slot) -> f64 {
    let Slot {
        x,
        x1,
        y0,
        y1,
        z,
        room,
    } = slot;
    let g = Goods::Loaves;
    if r.next() < 0.25 && x1 - x > 0.3 {
        let h = (0.45 * room).min(0.12);
        let w = basket(b, 0, x, x + 0.3, y0, y1, z, h);
        // Rolls heaped in it.
        for k in 0..4 {
            let c = [
                x + 0.07 + 0.055 * k as f64,
                0.5 * (y0 + y1) + 0.03 * (k % 2) as f64,
                z + h,
            ];
            b.ellipsoid_rot(Books, g.accent(r.next()), c, [0.04, 0.04, 0.03], IDENTITY);
        }
        return w;
    }
    let len = (0.22 + 0.1 * r.next()).min(x1 - x);
    let (rw, rh) = (
        0.06_f64.min(0.25 * (y1 - y0)),
        (0.05 + 0.02 * r.next()).min(0.45 * room),
    );
    let v = g.accent(r.next());
    let ry = rw / (0.5 * len);
    for y in [y0 + 0.3 * (y1 - y0), y0 + 0.72 * (y1 - y0)] {
        b.ellipsoid_rot(
            Books,
            v,
            [x + 0.5 * len, y, z + rh],
            [0.5 * len, ry * 0.5 * len, rh],
            IDENTITY,
        );
        // Scores across the top crust.
        for k in 1..4 {
            let sx = x + len * k as f64 / 4.0;
            b.cuboid_v(
                Books,
                1,
                [sx - 0.004, y - 0.5 * rw, z + 1.85 * rh],
                [sx + 0.004, y + 0.5 * rw, z + 1.95 * rh],
            );
        }
    }
    len + 0.02
}

/// A facing of packs (or, for groceries, now and then cans): three to five of one product side
/// by side, each a box with a pale band across its face; medicine packs are small white boxes
/// with a brand's band.
fn packs(b: &mut Builder, g: Goods, r: &mut Draws, slot: Slot) -> f64 {
    let Slot {
        x,
        x1,
        y0,
        y1,
        z,
        room,
    } = slot;
    let medicine = g == Goods::Medicine;
    let n = 3 + (r.next() * 3.0) as usize;
    let accent = g.accent(r.next());
    let can = !medicine && r.next() < 0.3;
    let (w, h) = if medicine {
        (
            0.05 + 0.03 * r.next(),
            (0.07 + 0.06 * r.next()).min(0.85 * room),
        )
    } else if can {
        (0.075, (0.11 + 0.03 * r.next()).min(0.85 * room))
    } else {
        (0.07 + 0.05 * r.next(), room * (0.55 + 0.3 * r.next()))
    };
    let (body, band) = if medicine {
        ((r.next() * 2.0) as u32, accent)
    } else {
        (accent, 5)
    };
    let d = (y1 - y0).min(0.35);
    let mut used = 0.0;
    for _ in 0..n {
        let xa = x + used;
        if xa + w > x1 {
            break;
        }
        if can {
            let rad = 0.5 * w - 0.003;
            for yc in [y1 - rad - 0.005, y1 - 3.0 * rad - 0.01] {
                b.revolved(
                    Books,
                    accent,
                    [xa + 0.5 * w, yc, z],
                    IDENTITY,
                    1.0,
                    frustum_profile(rad, rad, h),
                );
                b.revolved(
                    Books,
                    5,
                    [xa + 0.5 * w, yc, z + 0.3 * h],
                    IDENTITY,
                    1.0,
                    frustum_profile(rad + 0.001, rad + 0.001, 0.35 * h),
                );
            }
        } else {
            b.cuboid_v(
                Books,
                body,
                [xa, y1 - d, z],
                [xa + w - 0.004, y1 - 0.005, z + h],
            );
            b.cuboid_v(
                Books,
                band,
                [xa + 0.004, y1 - 0.005, z + 0.45 * h],
                [xa + w - 0.008, y1 - 0.003, z + 0.7 * h],
            );
        }
        used += w;
    }
    used + 0.015
}

/// One toy: a ball, a stack of blocks, a teddy or a boxed toy with a window.
fn toy(b: &mut Builder, r: &mut Draws, slot: Slot) -> f64 {
    let Slot {
        x,
        x1,
        y0,
        y1,
        z,
        room,
    } = slot;
    let g = Goods::Toys;
    let yc = 0.5 * (y0 + y1);
    let v = g.accent(r.next());
    match (r.next() * 4.0) as u32 {
        0 => {
            let rad = (0.35 * room).min(0.09).min(0.5 * (x1 - x));
            b.ellipsoid_rot(Books, v, [x + rad, yc, z + rad], [rad; 3], IDENTITY);
            2.0 * rad + 0.03
        }
        1 => {
            let s = (0.2 * room).min(0.06);
            for k in 0..3 {
                let o = 0.01 * k as f64;
                b.cuboid_v(
                    Books,
                    g.accent(r.next()),
                    [x + o, yc - s / 2.0, z + k as f64 * s],
                    [x + o + s, yc + s / 2.0, z + (k + 1) as f64 * s],
                );
            }
            2.0 * s + 0.03
        }
        2 => {
            // A teddy sitting: body, head, ears and muzzle, in bear brown.
            let s = (0.28 * room).min(0.1);
            let c = [x + s, yc, z + s];
            b.ellipsoid_rot(Books, 5, c, [s, 0.8 * s, s], IDENTITY);
            let hc = [c[0], c[1] + 0.1 * s, c[2] + 1.55 * s];
            b.ellipsoid_rot(Books, 5, hc, [0.65 * s; 3], IDENTITY);
            for sx in [-1.0, 1.0] {
                b.ellipsoid_rot(
                    Books,
                    5,
                    [hc[0] + sx * 0.5 * s, hc[1], hc[2] + 0.5 * s],
                    [0.2 * s; 3],
                    IDENTITY,
                );
            }
            b.ellipsoid_rot(
                Books,
                2,
                [hc[0], hc[1] + 0.55 * s, hc[2] - 0.1 * s],
                [0.22 * s, 0.15 * s, 0.18 * s],
                IDENTITY,
            );
            2.0 * s + 0.03
        }
        _ => {
            let w = (0.15 + 0.1 * r.next()).min(x1 - x);
            let h = room * (0.6 + 0.3 * r.next());
            let d = (y1 - y0).min(0.25);
            b.cuboid_v(Books, v, [x, y1 - d, z], [x + w - 0.005, y1 - 0.005, z + h]);
            b.cuboid(
                Pane,
                [x + 0.15 * w, y1 - 0.005, z + 0.2 * h],
                [x + 0.8 * w, y1 - 0.002, z + 0.8 * h],
            );
            w + 0.02
        }
    }
}

/// A carton with a tape strip over its top and down its face, or a plastic bin with a lid rim.
fn carton(b: &mut Builder, r: &mut Draws, slot: Slot) -> f64 {
    let Slot {
        x,
        x1,
        y0,
        y1,
        z,
        room,
    } = slot;
    let g = Goods::Boxes;
    // No sliver of a carton at the end of a board: the gap stays empty.
    if x1 - x < 0.15 {
        return x1 - x;
    }
    let w = (0.3 + 0.15 * r.next()).min(x1 - x);
    let h = room * (0.6 + 0.3 * r.next());
    let v = g.accent(r.next());
    let (ya, yb) = (y0 + 0.01, y1 - 0.01);
    b.cuboid_v(Books, v, [x, ya, z], [x + w - 0.02, yb, z + h]);
    let xc = x + 0.5 * (w - 0.02);
    if g.palette()[v as usize][2] > g.palette()[v as usize][0] {
        // A bin: a lid overhanging a little.
        b.cuboid_v(
            Books,
            v,
            [x - 0.005, ya - 0.005, z + h],
            [x + w - 0.015, yb + 0.005, z + h + 0.02],
        );
    } else {
        b.cuboid_v(
            Books,
            0,
            [xc - 0.025, ya, z + h],
            [xc + 0.025, yb, z + h + 0.002],
        );
        b.cuboid_v(
            Books,
            0,
            [xc - 0.025, yb, z + 0.7 * h],
            [xc + 0.025, yb + 0.002, z + h],
        );
    }
    w
}

/// A cluster of bottles and jars of coloured glass with corks and paper labels.
fn bottles(b: &mut Builder, r: &mut Draws, slot: Slot) -> f64 {
    let Slot {
        x,
        x1,
        y0,
        y1,
        z,
        room,
    } = slot;
    let g = Goods::Bottles;
    let rad = (0.03 + 0.02 * r.next()).min(0.25 * (y1 - y0));
    if 2.0 * rad > x1 - x {
        return x1 - x;
    }
    let h = (room * (0.5 + 0.35 * r.next())).min(0.3);
    let c = [x + rad, 0.5 * (y0 + y1), z];
    let v = g.accent(r.next());
    let profile = match (r.next() * 3.0) as u32 {
        // A round flask with a long neck.
        0 => vec![
            [0.0, 0.0],
            [0.7 * rad, 0.0],
            [rad, 0.25 * h],
            [0.7 * rad, 0.5 * h],
            [0.3 * rad, 0.6 * h],
            [0.3 * rad, 0.9 * h],
            [0.0, 0.9 * h],
        ],
        // A tall bottle with shoulders.
        1 => vec![
            [0.0, 0.0],
            [0.8 * rad, 0.0],
            [0.8 * rad, 0.6 * h],
            [0.3 * rad, 0.75 * h],
            [0.3 * rad, 0.9 * h],
            [0.0, 0.9 * h],
        ],
        // A squat jar.
        _ => vec![
            [0.0, 0.0],
            [rad, 0.0],
            [rad, 0.55 * h],
            [0.8 * rad, 0.6 * h],
            [0.0, 0.6 * h],
        ],
    };
    let top = profile.last().map_or(0.9 * h, |p| p[1]);
    let neck = profile[profile.len() - 2][0];
    b.revolved(Books, v, c, IDENTITY, 1.0, profile);
    b.revolved(
        Books,
        0,
        [c[0], c[1], z + top],
        IDENTITY,
        1.0,
        frustum_profile(1.1 * neck, 1.2 * neck, 0.08 * h),
    );
    b.cuboid_v(
        Books,
        1,
        [c[0] - 0.5 * rad, c[1] + 0.75 * rad, z + 0.2 * h],
        [c[0] + 0.5 * rad, c[1] + 0.82 * rad, z + 0.35 * h],
    );
    2.0 * rad + 0.015
}

/// A stack of folded clothes: three to six folds of one colour family, each a flat slab with a
/// rounded fold edge to the front.
fn folded(b: &mut Builder, r: &mut Draws, slot: Slot) -> f64 {
    let Slot {
        x,
        x1,
        y0,
        y1,
        z,
        room,
    } = slot;
    let g = Goods::Clothes;
    let w = (0.28 + 0.06 * r.next()).min(x1 - x);
    let fold = 0.045;
    let n = (((room - 0.03) / fold) as usize)
        .clamp(1, 6)
        .min(3 + (r.next() * 4.0) as usize);
    let d = (y1 - y0).min(0.35);
    for k in 0..n {
        let v = g.accent(r.next());
        let z0 = z + k as f64 * fold;
        let o = 0.008 * (k % 2) as f64;
        b.cuboid_v(
            Books,
            v,
            [x + o, y1 - d, z0],
            [x + w - 0.03 + o, y1 - 0.02, z0 + fold - 0.004],
        );
        b.revolved(
            Books,
            v,
            [x + o, y1 - 0.02, z0 + 0.5 * fold - 0.002],
            frame_along([1.0, 0.0, 0.0]),
            1.0,
            frustum_profile(0.5 * fold - 0.002, 0.5 * fold - 0.002, w - 0.03),
        );
    }
    w + 0.01
}
