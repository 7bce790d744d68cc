//! The animal table (`kb/animals.txt`): one row per four-legged animal naming the features the
//! `quadruped` archetype draws it with (leg and neck length, head shape, ears, horns, tail,
//! hump, trunk, wool, coat pattern and colours). It only reads the table; `beasts.rs` draws.
use super::materials::{Rgb, Role};
use std::sync::OnceLock;

/// A tail's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tail {
    /// A horse's long hair.
    Brush,
    /// A thin tail ending in a tuft (cow, zebra, elephant).
    Tuft,
    /// A pig's curl.
    Curl,
    /// A short stub (sheep, goat).
    Stub,
}

/// An ear's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ears {
    Point,
    Long,
    Side,
    Flap,
}

/// A horn's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Horns {
    Curved,
    Side,
    Ossicones,
}

/// A coat pattern.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pattern {
    Stripes,
    Patches,
    Spots,
}

/// One row of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct Animal {
    pub legs: f64,
    pub body: f64,
    pub girth: f64,
    pub thick: f64,
    /// Neck rise in degrees (0: no neck) and base radius over the half-width.
    pub neck: (f64, f64),
    /// Head length over the length, depth over its length.
    pub head: (f64, f64),
    pub ears: Option<(Ears, f64)>,
    pub horns: Option<Horns>,
    pub tail: Option<(Tail, f64)>,
    pub hump: f64,
    pub mane: bool,
    pub trunk: bool,
    pub tusks: bool,
    pub snout: bool,
    pub wool: bool,
    pub pads: bool,
    pub pattern: Option<Pattern>,
    pub coat: Rgb,
    pub marks: Rgb,
    pub hair: Rgb,
    pub points: Option<Rgb>,
    pub horn: Rgb,
}

impl Default for Animal {
    fn default() -> Animal {
        Animal {
            legs: 0.5,
            body: 0.3,
            girth: 0.9,
            thick: 0.16,
            neck: (55.0, 0.45),
            head: (0.24, 0.42),
            ears: None,
            horns: None,
            tail: None,
            hump: 0.0,
            mane: false,
            trunk: false,
            tusks: false,
            snout: false,
            wool: false,
            pads: false,
            pattern: None,
            coat: [0.45, 0.28, 0.15],
            marks: [0.08, 0.08, 0.09],
            hair: [0.14, 0.09, 0.06],
            points: None,
            horn: [0.85, 0.80, 0.70],
        }
    }
}

impl Animal {
    /// The role face and lower legs are drawn in: [`Role::Skin`] where the row gives them a
    /// colour of their own, else the coat's.
    pub fn points_role(&self) -> Role {
        if self.points.is_some() {
            Role::Skin
        } else {
            Role::Body
        }
    }

    /// The row's colours by the roles the drawing paints them on (the archetype's defaults
    /// for an animal of this row).
    pub fn colours(&self) -> Vec<(Role, Rgb)> {
        let mut c = vec![
            (Role::Body, self.coat),
            (Role::Top, self.marks),
            (Role::Cushion, self.hair),
            (Role::Frame, self.horn),
        ];
        if let Some(p) = self.points {
            c.push((Role::Skin, p));
        }
        c
    }
}

/// Parses one row's features; `Err` names the first it does not understand.
pub fn parse(features: &str) -> Result<Animal, String> {
    let mut a = Animal::default();
    for f in features.split(',').map(str::trim).filter(|f| !f.is_empty()) {
        let mut words = f.split_whitespace();
        let key = words.next().unwrap_or_default();
        let rest: Vec<&str> = words.collect();
        let nums: Vec<f64> = rest.iter().filter_map(|w| w.parse().ok()).collect();
        let num = |i: usize| {
            nums.get(i)
                .copied()
                .ok_or_else(|| format!("`{f}`: a number"))
        };
        let rgb = || -> Result<Rgb, String> {
            match nums.as_slice() {
                [r, g, b] => Ok([*r as f32, *g as f32, *b as f32]),
                _ => Err(format!("`{f}`: three numbers")),
            }
        };
        let kind = rest.first().copied().unwrap_or_default();
        match key {
            "legs" => a.legs = num(0)?,
            "body" => a.body = num(0)?,
            "girth" => a.girth = num(0)?,
            "thick" => a.thick = num(0)?,
            "neck" => a.neck = (num(0)?, nums.get(1).copied().unwrap_or(0.45)),
            "head" => a.head = (num(0)?, num(1)?),
            "hump" => a.hump = num(0)?,
            "mane" => a.mane = true,
            "trunk" => a.trunk = true,
            "tusks" => a.tusks = true,
            "snout" => a.snout = true,
            "wool" => a.wool = true,
            "pads" => a.pads = true,
            "coat" => a.coat = rgb()?,
            "marks" => a.marks = rgb()?,
            "hair" => a.hair = rgb()?,
            "points" => a.points = Some(rgb()?),
            "horn" => a.horn = rgb()?,
            "ears" => {
                let e = match kind {
                    "point" => Ears::Point,
                    "long" => Ears::Long,
                    "side" => Ears::Side,
                    "flap" => Ears::Flap,
                    _ => return Err(format!("`{f}`: ears point, long, side or flap")),
                };
                a.ears = Some((e, num(0)?));
            }
            "horns" => {
                a.horns = Some(match kind {
                    "curved" => Horns::Curved,
                    "side" => Horns::Side,
                    "ossicones" => Horns::Ossicones,
                    _ => return Err(format!("`{f}`: horns curved, side or ossicones")),
                })
            }
            "tail" => {
                let t = match kind {
                    "brush" => Tail::Brush,
                    "tuft" => Tail::Tuft,
                    "curl" => Tail::Curl,
                    "stub" => Tail::Stub,
                    _ => return Err(format!("`{f}`: tail brush, tuft, curl or stub")),
                };
                a.tail = Some((t, num(0)?));
            }
            "pattern" => {
                a.pattern = Some(match kind {
                    "stripes" => Pattern::Stripes,
                    "patches" => Pattern::Patches,
                    "spots" => Pattern::Spots,
                    _ => return Err(format!("`{f}`: pattern stripes, patches or spots")),
                })
            }
            _ => return Err(format!("`{f}`: unknown feature `{key}`")),
        }
    }
    if !(0.05..=0.9).contains(&a.legs) || a.legs + a.body > 1.0 + 1e-9 {
        return Err(format!(
            "legs {} and body {} must fit the height",
            a.legs, a.body
        ));
    }
    Ok(a)
}

type Table = super::rows::RowTable<Animal>;

fn table() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| super::rows::read(include_str!("kb/animals.txt"), parse))
}

/// The table's rows (the `default` row among them).
pub fn rows() -> Vec<(&'static str, &'static Animal)> {
    table().listed()
}

/// The table's lines that do not parse, with why (for the tests).
pub fn bad_lines() -> Vec<String> {
    table().bad.clone()
}

/// The row `default`, drawn for a quadruped the table does not list.
pub fn default_animal() -> &'static Animal {
    static D: OnceLock<Animal> = OnceLock::new();
    super::rows::default_row(table(), &D)
}

/// A category's row (by its name or a synonym), if the table lists it.
pub fn animal_of(category: &str) -> Option<&'static Animal> {
    let c = category.trim().to_lowercase();
    let c = crate::plan::kb::KnowledgeBase::builtin()
        .object(&c)
        .map_or(c, |o| o.category.clone());
    table().row(&c)
}
