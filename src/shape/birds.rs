//! The bird table (`kb/birds.txt`): one row per bird naming, at the bird's real size in metres,
//! the features the `bird` archetype draws it with (body tilt and size, legs, neck, head, beak,
//! tail, an owl's face disc and ear tufts, a hen's comb, webbed feet, colours). It only reads
//! the table; `fowl.rs` draws.
use super::materials::{Rgb, Role};
use std::sync::OnceLock;

/// A beak's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Beak {
    /// A short straight cone (hen, pigeon, penguin, songbird).
    Cone,
    /// A hooked beak curving down (parrot, owl).
    Hook,
    /// A flat, wide bill (duck, goose, swan).
    Flat,
    /// A bill bent down half-way (flamingo).
    Bent,
}

/// A tail's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tail {
    /// A tall fan of feathers held upright (hen, rooster).
    Fan,
    /// A long narrow tail (parrot, songbird).
    Long,
    /// A short flat wedge (duck, owl, pigeon).
    Short,
}

/// One row of the table; lengths in metres at the bird's real size.
#[derive(Debug, Clone, PartialEq)]
pub struct Bird {
    /// The body's rise from level, in degrees (0: a swimming duck, 90: a penguin).
    pub tilt: f64,
    /// The body's semi-axes: along its tilt, across it (up), and sideways.
    pub body: [f64; 3],
    /// Leg length, ground to belly.
    pub legs: f64,
    /// Neck rise in degrees, length and radius.
    pub neck: (f64, f64, f64),
    /// Head radius.
    pub head: f64,
    pub beak: (Beak, f64),
    /// Tail kind, length and rise in degrees over the body's line.
    pub tail: (Tail, f64, f64),
    /// Eye radius over the head radius.
    pub eye: f64,
    /// A hen's comb and wattle.
    pub comb: bool,
    /// An owl's flat face, eyes to the front.
    pub disc: bool,
    /// An owl's ear tufts.
    pub tufts: bool,
    /// Flat webbed feet (else three toes).
    pub webbed: bool,
    pub plumage: Rgb,
    pub wings: Rgb,
    pub belly: Rgb,
    pub crown: Rgb,
    pub bill: Rgb,
    pub feet: Rgb,
    pub wattle: Rgb,
    /// The ring round the pupil (an owl's yellow eye); `None`: a dark eye.
    pub iris: Option<Rgb>,
}

impl Default for Bird {
    fn default() -> Bird {
        Bird {
            tilt: 30.0,
            body: [0.05, 0.035, 0.03],
            legs: 0.02,
            neck: (60.0, 0.01, 0.015),
            head: 0.02,
            beak: (Beak::Cone, 0.012),
            tail: (Tail::Long, 0.05, 10.0),
            eye: 0.18,
            comb: false,
            disc: false,
            tufts: false,
            webbed: false,
            plumage: [0.45, 0.33, 0.22],
            wings: [0.36, 0.26, 0.17],
            belly: [0.78, 0.68, 0.52],
            crown: [0.45, 0.33, 0.22],
            bill: [0.25, 0.22, 0.20],
            feet: [0.45, 0.38, 0.30],
            wattle: [0.80, 0.10, 0.08],
            iris: None,
        }
    }
}

impl Bird {
    /// The row's colours by the roles the drawing paints them on.
    pub fn colours(&self) -> Vec<(Role, Rgb)> {
        let mut c = vec![
            (Role::Body, self.plumage),
            (Role::Frame, self.wings),
            (Role::Cushion, self.belly),
            (Role::Top, self.crown),
            (Role::Handle, self.bill),
            (Role::Metal, self.feet),
            (Role::Skin, self.wattle),
            (Role::Interior, [0.04, 0.04, 0.05]),
        ];
        if let Some(i) = self.iris {
            c.push((Role::Light, i));
        }
        c
    }
}

/// Parses one row's features; `Err` names the first it does not understand.
pub fn parse(features: &str) -> Result<Bird, String> {
    let mut a = Bird::default();
    for f in features.split(',').map(str::trim).filter(|f| !f.is_empty()) {
        let mut words = f.split_whitespace();
        let key = words.next().unwrap_or_default();
        let rest: Vec<&str> = words.collect();
        let nums: Vec<f64> = rest.iter().filter_map(|w| w.parse().ok()).collect();
        let num = |i: usize| {
            nums.get(i)
                .copied()
                .filter(|v| v.is_finite())
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
            "tilt" => a.tilt = num(0)?,
            "body" => a.body = [num(0)?, num(1)?, num(2)?],
            "legs" => a.legs = num(0)?,
            "neck" => a.neck = (num(0)?, num(1)?, num(2)?),
            "head" => a.head = num(0)?,
            "eye" => a.eye = num(0)?,
            "comb" => a.comb = true,
            "disc" => a.disc = true,
            "tufts" => a.tufts = true,
            "webbed" => a.webbed = true,
            "plumage" => a.plumage = rgb()?,
            "wings" => a.wings = rgb()?,
            "belly" => a.belly = rgb()?,
            "crown" => a.crown = rgb()?,
            "bill" => a.bill = rgb()?,
            "feet" => a.feet = rgb()?,
            "wattle" => a.wattle = rgb()?,
            "iris" => a.iris = Some(rgb()?),
            "beak" => {
                let k = match kind {
                    "cone" => Beak::Cone,
                    "hook" => Beak::Hook,
                    "flat" => Beak::Flat,
                    "bent" => Beak::Bent,
                    _ => return Err(format!("`{f}`: beak cone, hook, flat or bent")),
                };
                a.beak = (k, num(0)?);
            }
            "tail" => {
                let k = match kind {
                    "fan" => Tail::Fan,
                    "long" => Tail::Long,
                    "short" => Tail::Short,
                    _ => return Err(format!("`{f}`: tail fan, long or short")),
                };
                a.tail = (k, num(0)?, num(1)?);
            }
            _ => return Err(format!("`{f}`: unknown feature `{key}`")),
        }
    }
    let lengths = [a.body[0], a.body[1], a.body[2], a.head, a.neck.2];
    if lengths.iter().any(|v| *v <= 0.0) || a.legs < 0.0 || a.neck.1 < 0.0 {
        return Err("body, head and neck sizes must be positive".into());
    }
    Ok(a)
}

type Table = super::rows::RowTable<Bird>;

fn table() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| super::rows::read(include_str!("kb/birds.txt"), parse))
}

/// The table's rows (the `default` row among them).
pub fn rows() -> Vec<(&'static str, &'static Bird)> {
    table().listed()
}

/// The table's lines that do not parse, with why (for the tests).
pub fn bad_lines() -> Vec<String> {
    table().bad.clone()
}

/// The row `default`, drawn for a bird the table does not list.
pub fn default_bird() -> &'static Bird {
    static D: OnceLock<Bird> = OnceLock::new();
    super::rows::default_row(table(), &D)
}

/// A category's row (by its name or a synonym; "parrot" for an unknown "grey parrot"), if the
/// table lists it.
pub fn bird_of(category: &str) -> Option<&'static Bird> {
    let c = category.trim().to_lowercase();
    let kb = crate::plan::kb::KnowledgeBase::builtin();
    let name = kb.object(&c).map_or(c.clone(), |o| o.category.clone());
    let find = |n: &str| table().row(n);
    find(&name).or_else(|| {
        let head = c.rsplit(' ').next()?;
        find(
            &kb.object(head)
                .map_or(head.to_string(), |o| o.category.clone()),
        )
    })
}
