//! Procedural shape priors: every knowledge-base category names a parametric archetype (table,
//! chair, sofa, bed, cabinet, shelf, lamp, plant, screen, rug, …) that is built from primitive
//! parts at the planned size `[width x, depth y, height z]` in the object frame (bottom-face
//! centre at the origin, front towards +y, z up), sampled as flat surface Gaussians and coloured
//! from the description's colour and material words.
//!
//! This is the offline initialisation (the paper's Point-E) and the draft object when no
//! diffusion model is installed. Host-only: it never imports `ash` or `crate::gpu`.
//!
//! Density: by default the surfel spacing is `diag / 220` (`diag` the size box's diagonal), so an
//! object framed to fill a 512² image gets a surfel every ~2 pixels and the tangent scales
//! (0.7 spacing) overlap; the count is then clamped to [`MIN_GAUSSIANS`, `MAX_GAUSSIANS`]
//! (a 2.1 m sofa gets the 60 000 cap, a rug ~45 000). [`ShapeOptions::gaussians`] overrides it;
//! the result has that many Gaussians to within a few percent (rounding of the sample grids).
mod amusements;
mod animals;
mod appliances;
mod archetypes;
mod audio;
mod backs;
mod backyard;
mod barriers;
mod beasts;
mod bellhop;
mod bins;
mod birds;
mod boards;
mod boathouse;
mod booths;
mod bowls;
mod braziers;
mod builder;
mod canopy;
mod care;
mod carts;
mod cases;
mod clearglass;
mod clocks;
mod coast;
mod coats;
mod contents;
mod contraptions;
mod counters;
mod crafts;
mod crates;
mod daily;
mod displays;
mod drapes;
mod drawers;
mod effigies;
mod engines;
mod everyday;
mod fittings;
mod fixtures;
mod florist;
mod forms;
mod fossils;
mod fowl;
mod frames;
pub mod functions;
mod furniture;
mod gadgets;
mod games;
mod garden;
mod gizmos;
mod glasshouse;
mod glazed;
mod goods;
mod grounds;
mod gym;
mod hangings;
mod heritage;
mod holders;
mod homefit;
mod household;
mod instruments;
mod jobtables;
mod kiosks;
mod kitchenyard;
mod lair;
mod laundry;
mod lockers;
mod lounge;
mod machines;
mod markers;
mod market;
pub mod materials;
mod mirrors;
mod more;
mod mount;
mod named;
mod nursery;
mod officefit;
mod orchard;
mod ornaments;
mod ovens;
mod packs;
mod parlour;
mod partitions;
pub mod parts;
mod pegs;
mod pets;
mod picnic;
mod plants;
mod play;
mod podiums;
mod poles;
mod ponds;
mod prints;
mod racks;
mod recliners;
mod redrawn;
mod riders;
mod rigs;
mod rocks;
mod rows;
mod salon;
mod scopes;
mod sculpted;
mod seats;
mod servers;
mod sets;
mod sewing;
mod skeleton;
mod sleepers;
mod smithy;
mod sport;
mod stands;
mod streetside;
mod structures;
mod sundries;
mod surgical;
mod tanks;
mod taps;
mod textiles;
mod things;
mod training;
mod transit;
mod utility;
mod vanities;
pub mod variants;
mod vehicles;
mod vendors;
mod vitrines;
mod wards;
mod wares;
mod washroom;
mod workshop;
mod worktops;
mod yard;

pub use goods::Goods;
pub use materials::{colour_words, Class, ColourWord, Role, WordKind};
pub use mount::Mount;
pub use named::shore_band;
pub use parts::{Part, Primitive};

use crate::plan::kb::KnowledgeBase;
use crate::splat::cloud::SH_C0;
use crate::splat::Gaussians;
use rand::{Rng, SeedableRng};

/// The archetype of categories the knowledge base does not know.
pub const DEFAULT_ARCHETYPE: &str = "box";
/// Smallest default Gaussian count.
pub const MIN_GAUSSIANS: usize = 30_000;
/// Largest default Gaussian count.
pub const MAX_GAUSSIANS: usize = 60_000;
/// Default surfel spacing as a fraction of the size box's diagonal.
const SPACING_PER_DIAGONAL: f64 = 1.0 / 220.0;
/// Tangent scale (σ) of a surfel as a fraction of its sample spacing: neighbours overlap.
const TANGENT_SCALE: f64 = 0.7;
/// Thickness (σ along the normal) as a fraction of the spacing: flat surfels.
const THICKNESS: f64 = 0.15;
/// Opacity after the sigmoid.
const OPACITY: f64 = 0.93;
/// Opacity of see-through glass ([`Role::Pane`]): neighbouring surfels overlap, so a pane
/// covers about a third of what stands behind it.
const PANE_OPACITY: f64 = 0.12;
/// Per-Gaussian brightness variation (±).
const BRIGHTNESS_JITTER: f64 = 0.04;

/// Options of [`build`].
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ShapeOptions {
    /// Approximate Gaussian count; `None` chooses one from the surface area (see the module docs).
    pub gaussians: Option<usize>,
    /// Seed of the sample jitter and colour variation.
    pub seed: u64,
    /// Which variant of its archetype to draw (`kb/variants.txt`: a poster's print, a statue's
    /// pose), taken modulo the archetype's count; 0 is its usual drawing.
    pub variant: u32,
    /// How it is held up (on a wall, from the ceiling, standing); `None` takes its category's
    /// placement class (`kb/placement.txt`), as [`Mount::of_category`].
    pub mount: Option<Mount>,
}

/// Errors of [`build`].
#[derive(Debug, thiserror::Error)]
pub enum ShapeError {
    #[error("object size {0:?}: every side must be finite and positive")]
    BadSize([f64; 3]),
    #[error("Gaussian count {0}: at least 100 are needed")]
    BadCount(usize),
}

/// Names of all archetypes.
pub fn archetype_names() -> &'static [&'static str] {
    &archetypes::NAMES
}

/// The archetype of a category (its name or a synonym) through the knowledge base: the one its
/// row names, else the one its words suggest; unknown categories get [`DEFAULT_ARCHETYPE`].
pub fn archetype_of(category: &str) -> &'static str {
    let name = category.trim().to_lowercase();
    match KnowledgeBase::builtin().object(&name) {
        Some(o) => archetypes::NAMES
            .iter()
            .find(|n| **n == o.archetype)
            .copied()
            .unwrap_or_else(|| archetype_by_keyword(&o.category)),
        // an unknown object takes its WordNet kind's archetype ("a divan" is drawn as a sofa)
        None => match name.rsplit(' ').next().and_then(crate::plan::lexicon::kind) {
            Some(crate::plan::lexicon::Kind::Category(c)) if c != name => archetype_of(c),
            _ => DEFAULT_ARCHETYPE,
        },
    }
}

/// The archetype drawn for a category described by `description`: [`archetype_of`], changed
/// by a form word before the category's name ("a round mirror", "an oval table"; the table is
/// `kb/forms.txt`).
pub fn archetype_described(category: &str, description: &str) -> &'static str {
    forms::reshaped(archetype_of(category), category, description)
}

/// The rows of the form table: (archetype, form words, archetype drawn instead).
pub fn form_rows() -> Vec<(&'static str, Vec<&'static str>, &'static str)> {
    forms::rows().collect()
}

/// The archetype a category name suggests by its words, for knowledge-base rows without an
/// archetype column ("desk chair" → `chair`, "oak tree" → `tree`); [`DEFAULT_ARCHETYPE`] otherwise.
pub fn archetype_by_keyword(category: &str) -> &'static str {
    const RULES: &[(&str, &str)] = &[
        ("sofa", "sofa"),
        ("couch", "sofa"),
        ("armchair", "armchair"),
        ("chair", "chair"),
        ("stool", "stool"),
        ("bench", "bench"),
        ("bed", "bed"),
        ("desk", "desk"),
        ("round table", "round_table"),
        ("table", "table"),
        ("shelf", "shelf"),
        ("bookcase", "shelf"),
        ("wardrobe", "wardrobe"),
        ("cabinet", "cabinet"),
        ("lamp", "floor_lamp"),
        ("plant", "plant"),
        ("tree", "tree"),
        ("bush", "bush"),
        ("rug", "rug"),
        ("mat", "rug"),
        ("tv", "screen"),
        ("screen", "screen"),
        ("monitor", "screen"),
        ("counter", "counter"),
        ("car", "vehicle"),
        ("tent", "tent"),
        ("pond", "pond"),
        ("fountain", "water"),
        ("bridge", "bridge"),
        ("tower", "tower"),
        ("lantern", "lantern"),
        ("palm", "palm"),
        ("telescope", "tripod"),
        ("robot", "robot"),
        ("lounger", "lounger"),
        ("deckchair", "lounger"),
        ("horse", "quadruped"),
        ("dog", "quadruped"),
        ("bird", "bird"),
        ("owl", "bird"),
        ("parrot", "bird"),
        ("easel", "easel"),
        ("grill", "grill"),
        ("barbecue", "grill"),
    ];
    let c = category.to_lowercase();
    RULES
        .iter()
        .find(|(k, _)| c.contains(k))
        .map_or(DEFAULT_ARCHETYPE, |(_, a)| a)
}

fn check_size(size: [f64; 3]) -> Result<(), ShapeError> {
    if size.iter().all(|v| v.is_finite() && *v > 0.0) {
        Ok(())
    } else {
        Err(ShapeError::BadSize(size))
    }
}

/// The parts of a category's archetype at `size`, in the object frame.
pub fn parts(category: &str, size: [f64; 3]) -> Result<Vec<Part>, ShapeError> {
    parts_described(category, size, "")
}

/// The parts of a category's archetype as `description` shapes it (see
/// [`archetype_described`]), in the object frame.
pub fn parts_described(
    category: &str,
    size: [f64; 3],
    description: &str,
) -> Result<Vec<Part>, ShapeError> {
    parts_mounted(category, size, description, Mount::of_category(category))
}

/// [`parts_described`] hung or stood as `mount` says (a mirror on a wall has no legs).
pub fn parts_mounted(
    category: &str,
    size: [f64; 3],
    description: &str,
    mount: Mount,
) -> Result<Vec<Part>, ShapeError> {
    check_size(size)?;
    let arch = archetypes::get(archetype_described(category, description));
    Ok(arch.parts_holding(
        size,
        goods_described(category, arch.name, description),
        animal_for(category, arch.name),
        bird_for(category, arch.name),
        0,
        mount,
    ))
}

/// The parts of variant `variant` of a category's archetype (see [`ShapeOptions::variant`]),
/// in the object frame.
pub fn parts_variant(
    category: &str,
    size: [f64; 3],
    variant: u32,
) -> Result<Vec<Part>, ShapeError> {
    check_size(size)?;
    let arch = archetypes::get(archetype_of(category));
    Ok(arch.parts_holding(
        size,
        goods::goods_of(category, arch.name),
        animal_for(category, arch.name),
        bird_for(category, arch.name),
        variant,
        Mount::of_category(category),
    ))
}

/// What a category drawn as `archetype` holds as `description` says it ("a vase with
/// flowers", "a table full of new releases"; `kb/contents.txt`), else its own goods
/// (`kb/shelf_goods.txt`); nothing for one said to be empty.
fn goods_described(category: &str, archetype: &str, description: &str) -> Option<Goods> {
    if description
        .split(|c: char| !c.is_alphanumeric())
        .any(|w| w.eq_ignore_ascii_case("empty"))
    {
        return None;
    }
    contents::said(description).or_else(|| goods::goods_of(category, archetype))
}

/// The goods a description says its thing holds (`kb/contents.txt`), if any.
pub fn said_goods(description: &str) -> Option<Goods> {
    contents::said(description)
}

/// The lines of the contents table that do not parse.
pub fn contents_bad_lines() -> Vec<&'static str> {
    contents::bad_lines()
}

/// The animal row a category is drawn as: its own, or the table's `default` for a quadruped
/// the table does not list; `None` for archetypes that draw no animal.
fn animal_for(category: &str, archetype: &str) -> Option<&'static animals::Animal> {
    (archetype == "quadruped")
        .then(|| animals::animal_of(category).unwrap_or_else(animals::default_animal))
}

/// The bird row a category is drawn as: its own, or the table's `default` for a bird the
/// table does not list; `None` for archetypes that draw no bird.
fn bird_for(category: &str, archetype: &str) -> Option<&'static birds::Bird> {
    (archetype == "bird").then(|| birds::bird_of(category).unwrap_or_else(birds::default_bird))
}

/// The rows of the bird table (`kb/birds.txt`) as (category, features known), and the lines
/// of it that do not parse, with why.
pub fn bird_rows() -> (Vec<&'static str>, Vec<String>) {
    (
        birds::rows().into_iter().map(|(n, _)| n).collect(),
        birds::bad_lines(),
    )
}

/// The rows of the animal table (`kb/animals.txt`) as (category, features known), and the
/// lines of it that do not parse, with why.
pub fn animal_rows() -> (Vec<&'static str>, Vec<String>) {
    (
        animals::rows().into_iter().map(|(n, _)| n).collect(),
        animals::bad_lines(),
    )
}

/// What a category's shelves hold (`kb/shelf_goods.txt`): its row, else its archetype's;
/// `None` for categories whose archetype has no shelves of goods.
pub fn goods_of(category: &str) -> Option<Goods> {
    goods::goods_of(category, archetype_of(category))
}

/// The category rows of the shelf goods table, and the lines of it that do not parse.
pub fn goods_rows() -> (Vec<(&'static str, Goods)>, Vec<&'static str>) {
    (goods::rows(), goods::bad_lines())
}

/// The default Gaussian count for parts of total surface `area` in a box of `size`.
pub fn default_gaussians(area: f64, size: [f64; 3]) -> usize {
    let diag = size.iter().map(|v| v * v).sum::<f64>().sqrt();
    let s = diag * SPACING_PER_DIAGONAL;
    ((area / (s * s)) as usize).clamp(MIN_GAUSSIANS, MAX_GAUSSIANS)
}

/// Builds the shape prior of `category` at `size` ([width, depth, height] in metres), coloured
/// from `description`: surface Gaussians (SH degree 0) inside the size box, resting on z = 0,
/// facing +y. Deterministic for a seed.
pub fn build(
    category: &str,
    size: [f64; 3],
    description: &str,
    opts: &ShapeOptions,
) -> Result<Gaussians, ShapeError> {
    check_size(size)?;
    if let Some(n) = opts.gaussians.filter(|n| *n < 100) {
        return Err(ShapeError::BadCount(n));
    }
    let arch = archetypes::get(archetype_described(category, description));
    let goods = goods_described(category, arch.name, description);
    let animal = animal_for(category, arch.name);
    let bird = bird_for(category, arch.name);
    let mount = opts.mount.unwrap_or_else(|| Mount::of_category(category));
    let parts = arch.parts_holding(size, goods, animal, bird, opts.variant, mount);
    let palette = match (animal, bird) {
        (Some(a), _) => animal_palette(description, arch.main, arch.defaults, a),
        (None, Some(f)) => {
            let mut colours: Vec<(Role, materials::Rgb)> = arch.defaults.to_vec();
            for (role, rgb) in f.colours() {
                colours.retain(|c| c.0 != role);
                colours.push((role, rgb));
            }
            bird_palette(description, arch.main, &colours)
        }
        (None, None) => materials::Palette::new(description, arch.main, arch.defaults),
    }
    .holding(goods.unwrap_or_default().palette());
    let area: f64 = parts.iter().map(|p| p.prim.area()).sum();
    let n = opts
        .gaussians
        .unwrap_or_else(|| default_gaussians(area, size));
    let mut spacing = (area / n as f64).sqrt();
    let mut g = sample(&parts, &palette, size, spacing, opts.seed);
    // Parts clipped by the size box (a hull below its gunwale) lose samples: densify once.
    if (g.len() as f64) < 0.9 * n as f64 && !g.is_empty() {
        spacing *= (g.len() as f64 / n as f64).sqrt();
        g = sample(&parts, &palette, size, spacing, opts.seed);
    }
    // Rest the lowest centre on the floor (samples sit up to a jitter above their face).
    let min_z = g.means.iter().map(|m| m[2]).fold(f32::INFINITY, f32::min);
    if min_z.is_finite() {
        for m in &mut g.means {
            m[2] -= min_z;
        }
    }
    if let Mount::Post(cm) = mount {
        mount::posts(
            &mut g,
            size,
            f64::from(cm) / 100.0,
            &palette,
            spacing,
            opts.seed,
        );
    }
    Ok(g)
}

/// A bird's colours: its row's over the archetype's defaults, the description's first colour
/// word on its whole plumage and a second one on its breast ("a black and white penguin").
fn bird_palette(
    description: &str,
    main: &[Role],
    colours: &[(Role, materials::Rgb)],
) -> materials::Palette {
    let p = materials::Palette::new(description, main, colours);
    let second = materials::colour_words(description)
        .into_iter()
        .filter(|w| w.part.is_none() && w.kind == materials::WordKind::Colour)
        .nth(1);
    match second {
        Some(w) => p.with(Role::Cushion, w.rgb),
        None => p,
    }
}

/// An animal's colours: its row's over the archetype's defaults, the description's colour word
/// on its coat; where that word makes the coat the colour of the pattern ("a black and white
/// cow"), the pattern takes the row's coat colour so it still shows.
fn animal_palette(
    description: &str,
    main: &[Role],
    defaults: &[(Role, materials::Rgb)],
    a: &animals::Animal,
) -> materials::Palette {
    let mut colours: Vec<(Role, materials::Rgb)> = defaults.to_vec();
    for (role, rgb) in a.colours() {
        colours.retain(|c| c.0 != role);
        colours.push((role, rgb));
    }
    let p = materials::Palette::new(description, main, &colours);
    if let Some([coat, marks]) = coat_pair(description, a) {
        return p.with(Role::Body, coat).with(Role::Top, marks);
    }
    let (coat, marks) = (p.colour(Role::Body, 0), p.colour(Role::Top, 0));
    let apart: f32 = (0..3).map(|i| (coat[i] - marks[i]).abs()).sum();
    if apart > 0.3 {
        return p;
    }
    colours.retain(|c| c.0 != Role::Top);
    let light = coat.iter().sum::<f32>() > 1.5;
    let row = a.coat;
    let far = (0..3).map(|i| (coat[i] - row[i]).abs()).sum::<f32>() > 0.3;
    let other = match (far, light) {
        (true, _) => row,
        (false, true) => [0.08, 0.08, 0.09],
        (false, false) => [0.92, 0.91, 0.88],
    };
    colours.push((Role::Top, other));
    materials::Palette::new(description, main, &colours)
}

/// The coat and pattern colours of a patterned animal whose description names two free colours
/// ("a black and white striped zebra", "a brown and white cow"): the one nearer the row's coat
/// colour is the coat, the other the pattern, whatever order the words come in.
fn coat_pair(description: &str, a: &animals::Animal) -> Option<[materials::Rgb; 2]> {
    a.pattern?;
    let free: Vec<materials::Rgb> = materials::colour_words(description)
        .into_iter()
        .filter(|w| w.part.is_none() && w.kind == materials::WordKind::Colour)
        .map(|w| w.rgb)
        .collect();
    let (&x, &y) = (free.first()?, free.get(1)?);
    let dist = |c: materials::Rgb| (0..3).map(|i| (c[i] - a.coat[i]).abs()).sum::<f32>();
    if (0..3).map(|i| (x[i] - y[i]).abs()).sum::<f32>() < 0.3 {
        return None;
    }
    Some(if dist(y) < dist(x) { [y, x] } else { [x, y] })
}

/// Surface Gaussians of `parts` about `spacing` apart, coloured by `palette`; samples outside the
/// size box are dropped.
fn sample(
    parts: &[Part],
    palette: &materials::Palette,
    size: [f64; 3],
    spacing: f64,
    seed: u64,
) -> Gaussians {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    // Faces laid on the size box itself (a cabinet's back, an appliance's sides) come out of
    // the part arithmetic an ulp or so outside it: a small tolerance keeps them, while parts
    // meant to be clipped (a hull below its gunwale) still lose what lies beyond it.
    let tol = 1e-6 * (1.0 + size.iter().fold(0.0f64, |a, v| a.max(*v)));
    let [hw, hd, h] = [size[0] / 2.0 + tol, size[1] / 2.0 + tol, size[2] + tol];
    let inside = |p: [f64; 3]| p[0].abs() <= hw && p[1].abs() <= hd && (-tol..=h).contains(&p[2]);
    let light = norm3([0.35, 0.55, 0.75]);
    let log_t = (THICKNESS * spacing).ln() as f32;
    let logit = (OPACITY / (1.0 - OPACITY)).ln() as f32;
    let pane_logit = (PANE_OPACITY / (1.0 - PANE_OPACITY)).ln() as f32;
    let mut g = Gaussians {
        sh_degree: 0,
        ..Default::default()
    };
    let mut surfels = vec![];
    for (i, part) in parts.iter().enumerate() {
        surfels.clear();
        part.prim.sample(spacing, &mut rng, &mut surfels);
        // A fixed per-part brightness offset keeps neighbouring parts of one colour apart.
        let part_shade = 1.0 + 0.06 * (((i as u64 * 2_654_435_761) % 1000) as f64 / 1000.0 - 0.5);
        let base = palette.colour(part.role, part.variant);
        let flat = matches!(part.role, Role::Light | Role::Screen);
        let part_logit = if part.role == Role::Pane {
            pane_logit
        } else {
            logit
        };
        for s in &surfels {
            let jitter = 1.0 + rng.gen_range(-BRIGHTNESS_JITTER..=BRIGHTNESS_JITTER);
            if !inside(s.pos) {
                continue;
            }
            let nrm = s.normal();
            // A soft key light from above the front-right, and occlusion towards the floor
            // (objects stand in their own contact shade), so forms read in a lone draft too.
            let lit = if flat {
                1.0
            } else {
                let ndl = nrm[0] * light[0] + nrm[1] * light[1] + nrm[2] * light[2];
                let t = (s.pos[2] / (0.35 * h).clamp(0.05, 0.5)).clamp(0.0, 1.0);
                (0.78 + 0.24 * ndl.max(-0.4)) * (0.8 + 0.2 * t * t * (3.0 - 2.0 * t))
            };
            let k = (lit * part_shade * jitter) as f32;
            g.means.push(s.pos.map(|v| v as f32));
            g.scales.push([
                (TANGENT_SCALE * s.du).ln() as f32,
                (TANGENT_SCALE * s.dv).ln() as f32,
                log_t,
            ]);
            g.rotations
                .push(parts::quaternion(&s.frame).map(|v| v as f32));
            g.opacities.push(part_logit);
            for c in base {
                let c = (c * k).clamp(0.0, 1.0);
                g.sh.push(((c as f64 - 0.5) / SH_C0) as f32);
            }
        }
    }
    g
}

fn norm3(a: [f64; 3]) -> [f64; 3] {
    let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    a.map(|v| v / l)
}

#[cfg(test)]
mod kb_tests {
    use super::*;

    #[test]
    fn every_knowledge_base_row_names_a_known_archetype() {
        for o in &KnowledgeBase::builtin().objects {
            assert!(
                archetypes::NAMES.contains(&o.archetype.as_str()),
                "objects.txt: `{}` names unknown archetype `{}`",
                o.category,
                o.archetype
            );
        }
        assert_eq!(archetype_by_keyword("desk chair"), "chair", "by words");
    }

    /// A part laid on the size box (a cabinet's back panel, an appliance's back) keeps every
    /// sample: were one face dropped, the object would be hollow seen from that side.
    #[test]
    fn parts_on_the_size_box_keep_all_their_faces() {
        let kb = KnowledgeBase::builtin();
        let mut lost = vec![];
        for o in &kb.objects {
            let arch = archetypes::get(archetype_of(&o.category));
            let palette = materials::Palette::new("", arch.main, arch.defaults);
            let [hw, hd, h] = [o.size[0] / 2.0, o.size[1] / 2.0, o.size[2]];
            let spacing = 0.03;
            for part in arch.parts_holding(
                o.size,
                goods::goods_of(&o.category, arch.name),
                animal_for(&o.category, arch.name),
                bird_for(&o.category, arch.name),
                0,
                Mount::of_category(&o.category),
            ) {
                let mut raw = vec![];
                part.prim.sample(
                    spacing,
                    &mut rand_chacha::ChaCha8Rng::seed_from_u64(3),
                    &mut raw,
                );
                // Parts meant to be clipped reach beyond the box by more than rounding.
                let within = raw.iter().all(|s| {
                    s.pos[0].abs() <= hw + 1e-9
                        && s.pos[1].abs() <= hd + 1e-9
                        && (-1e-9..=h + 1e-9).contains(&s.pos[2])
                });
                if !within || raw.is_empty() {
                    continue;
                }
                let kept = sample(std::slice::from_ref(&part), &palette, o.size, spacing, 3);
                if kept.len() != raw.len() {
                    lost.push(format!("{}: {} of {}", o.category, kept.len(), raw.len()));
                }
            }
        }
        assert!(lost.is_empty(), "samples dropped on the box: {lost:?}");
    }
}
