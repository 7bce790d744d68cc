//! Draft colours and surface patterns of the environment, read from the scene text: a small
//! table of surface words ("oak floor", "brick walls", "sandy ground", "sunset sky") over
//! defaults per scene kind of the knowledge base. Host-only and deterministic.
use crate::plan::finish::words;
use crate::plan::kb::KnowledgeBase;
use crate::plan::spec::SceneType;

/// A surface pattern, evaluated at a point's surface coordinates in metres, so that the draft
/// floor and walls are not flat-coloured (better looks, and texture for the prior to grip).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pattern {
    /// A faint low-frequency mottle (painted walls, ceilings).
    Plain,
    /// Floorboards: 14 cm boards with staggered ends, per-plank tint, dark seams and grain.
    Boards,
    /// 50 cm tiles with grout lines and a per-tile tint.
    Tiles,
    /// Veined stone.
    Marble,
    /// Running-bond bricks (stylised 30 x 12 cm) with mortar.
    Bricks,
    /// Small stones in offset rows with dark joints (cobblestone, paving).
    Cobbles,
    /// Strong per-point speckle (carpet, gravel, sand, asphalt).
    Speckled,
    /// Strong low-frequency mottle (grass, soil, concrete, snow).
    Mottled,
    /// 60 cm paving slabs with wide joints and a per-slab tint, legible at the outdoor ground's
    /// coarser point spacing.
    Slabs,
    /// Tatami mats: 90 x 180 cm straw mats in offset rows, a fine weave across each, dark cloth
    /// borders along their long sides.
    Tatami,
    /// Rough rock (a cave's walls, ceiling and floor): dark and light masses, cracks.
    Rock,
    /// A ship's deck: 30 cm planks with wide dark caulked seams and staggered butt ends, legible
    /// at the outdoor ground's coarser point spacing.
    Planks,
    /// Glazing: tall glass panes on a thin light frame (a greenhouse's walls and roof), the
    /// glass pale, greener low down where the planting outside shows through.
    Panes,
}

/// Colours (linear RGB in [0, 1]) and patterns of the environment surfaces. `floor` is the
/// indoor floor, `ground` the outdoor ground disk; `sky` is the zenith colour of the hemisphere
/// (it fades towards a lighter horizon).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnvColours {
    pub wall: [f32; 3],
    pub floor: [f32; 3],
    pub ceiling: [f32; 3],
    pub sky: [f32; 3],
    pub ground: [f32; 3],
    pub wall_pattern: Pattern,
    /// The ceiling's pattern: plain paint, a cave's rock.
    pub ceiling_pattern: Pattern,
    pub floor_pattern: Pattern,
    pub ground_pattern: Pattern,
    /// Outdoors: the ground around the scene area (a lawn round a patio, the sea round a deck).
    pub surround: [f32; 3],
    pub surround_pattern: Pattern,
    /// Outdoors: a parapet's colour round the scene area (a rooftop), none elsewhere.
    pub parapet: Option<[f32; 3]>,
    /// Outdoors: the sea past one side of the ground (a beach's), set from the layout.
    pub shore: Option<super::grounds::Shore>,
    /// The door leaf: the scene kind's, its style words' ("modern", "rustic"), or what the text
    /// says of its doors ("a red door").
    pub door: [f32; 3],
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Target {
    /// The floor indoors and the ground outdoors.
    Floor,
    Wall,
    Ceiling,
    Sky,
    Door,
}

/// A material word: its colour, pattern, the surface it names when it stands alone, and whether
/// it may stand alone (`"parquet"` always means the floor; `"wooden"` needs a surface noun, since
/// "a wooden table" says nothing of the floor).
struct Material {
    words: &'static [&'static str],
    colour: [f32; 3],
    pattern: Pattern,
    target: Target,
    alone: bool,
}

const fn m(
    words: &'static [&'static str],
    colour: [f32; 3],
    pattern: Pattern,
    target: Target,
    alone: bool,
) -> Material {
    Material {
        words,
        colour,
        pattern,
        target,
        alone,
    }
}

use Pattern::*;
use Target::*;

const WOOD: [f32; 3] = [0.58, 0.40, 0.24];
const OFF_WHITE: [f32; 3] = [0.90, 0.88, 0.83];
const CEILING_WHITE: [f32; 3] = [0.93, 0.93, 0.91];
const BLUE_SKY: [f32; 3] = [0.38, 0.58, 0.88];
const GRASS: [f32; 3] = [0.30, 0.50, 0.20];
/// Door leaves: painted, light and dark wood, bare metal.
const PAINTED: [f32; 3] = [0.91, 0.90, 0.87];
const DOOR_WOOD: [f32; 3] = [0.62, 0.46, 0.30];
const DARK_WOOD: [f32; 3] = [0.34, 0.22, 0.13];
const METAL: [f32; 3] = [0.62, 0.63, 0.65];

/// Style words of a scene and the door leaf they suggest.
#[rustfmt::skip]
const STYLES: &[(&[&str], [f32; 3])] = &[
    (&["modern", "minimalist", "scandinavian", "contemporary"], PAINTED),
    (&["rustic", "medieval", "cottage", "cabin", "farmhouse", "victorian", "antique", "old"], DARK_WOOD),
    (&["futuristic", "sci-fi", "scifi", "cyberpunk", "industrial", "high-tech"], METAL),
];

#[rustfmt::skip]
const MATERIALS: &[Material] = &[
    m(&["parquet", "floorboards", "hardwood", "laminate"], WOOD, Boards, Floor, true),
    m(&["wooden", "wood", "timber", "plank"], WOOD, Boards, Floor, false),
    m(&["oak"], [0.66, 0.50, 0.32], Boards, Floor, false),
    m(&["walnut", "mahogany", "ebony"], [0.36, 0.22, 0.13], Boards, Floor, false),
    m(&["pine", "birch", "maple"], [0.78, 0.63, 0.43], Boards, Floor, false),
    m(&["tile", "tiles", "tiled", "ceramic"], [0.85, 0.84, 0.80], Tiles, Floor, false),
    m(&["marble"], [0.90, 0.89, 0.86], Marble, Floor, false),
    m(&["carpet", "carpeted", "rugged", "wall-to-wall"], [0.62, 0.56, 0.50], Speckled, Floor, true),
    m(&["concrete", "cement", "industrial"], [0.60, 0.60, 0.58], Mottled, Floor, false),
    m(&["stone", "flagstone", "slate"], [0.55, 0.53, 0.50], Cobbles, Floor, false),
    m(&["linoleum", "vinyl"], [0.72, 0.72, 0.70], Speckled, Floor, true),
    m(&["metal", "metallic", "steel", "aluminium", "aluminum"], METAL, Plain, Door, false),
    m(&["brick", "bricks", "exposed-brick"], [0.62, 0.30, 0.22], Bricks, Wall, false),
    m(&["wallpaper", "wallpapered", "plaster", "painted"], [0.86, 0.82, 0.74], Plain, Wall, false),
    m(&["grass", "grassy", "lawn", "meadow", "turf"], GRASS, Mottled, Floor, true),
    m(&["sand", "sandy", "dune", "dunes"], [0.86, 0.76, 0.55], Speckled, Floor, true),
    m(&["snow", "snowy", "snow-covered", "winter"], [0.93, 0.95, 0.98], Mottled, Floor, true),
    m(&["gravel", "pebble", "pebbles"], [0.58, 0.56, 0.52], Speckled, Floor, true),
    m(&["cobblestone", "cobblestones", "cobbled"], [0.50, 0.48, 0.45], Cobbles, Floor, true),
    m(&["paved", "paving", "slabs", "flagstones"], [0.66, 0.63, 0.58], Slabs, Floor, true),
    m(&["decking", "decked"], [0.55, 0.40, 0.26], Boards, Floor, true),
    m(&["asphalt", "tarmac"], [0.25, 0.25, 0.26], Speckled, Floor, true),
    m(&["dirt", "soil", "mud", "muddy", "earth"], [0.42, 0.32, 0.22], Mottled, Floor, true),
    m(&["sunset", "dusk", "golden-hour"], [0.95, 0.55, 0.35], Plain, Sky, true),
    m(&["night", "starry", "moonlit"], [0.06, 0.08, 0.20], Plain, Sky, true),
    m(&["overcast", "cloudy", "foggy", "misty", "rainy"], [0.70, 0.72, 0.75], Plain, Sky, true),
];

/// Colour words: they set the colour of the material or surface noun that follows them.
#[rustfmt::skip]
const COLOURS: &[(&str, [f32; 3])] = &[
    ("white", [0.92, 0.92, 0.90]), ("off-white", OFF_WHITE), ("cream", [0.93, 0.88, 0.76]),
    ("beige", [0.84, 0.76, 0.62]), ("grey", [0.58, 0.58, 0.58]), ("gray", [0.58, 0.58, 0.58]),
    ("black", [0.10, 0.10, 0.10]), ("blue", [0.30, 0.45, 0.75]), ("green", [0.35, 0.55, 0.35]),
    ("red", [0.70, 0.20, 0.18]), ("yellow", [0.90, 0.80, 0.35]), ("pink", [0.90, 0.65, 0.70]),
    ("brown", [0.45, 0.30, 0.18]), ("orange", [0.90, 0.55, 0.25]), ("purple", [0.50, 0.35, 0.60]),
    ("teal", [0.20, 0.50, 0.50]), ("navy", [0.15, 0.20, 0.40]), ("golden", [0.85, 0.70, 0.35]),
];

/// Tone words: they scale the brightness of what follows.
const TONES: &[(&str, f32)] = &[
    ("dark", 0.6),
    ("light", 1.25),
    ("pale", 1.2),
    ("bright", 1.15),
];

/// Surface nouns.
const NOUNS: &[(&str, Target)] = &[
    ("floor", Floor),
    ("floors", Floor),
    ("flooring", Floor),
    ("ground", Floor),
    ("wall", Wall),
    ("walls", Wall),
    ("ceiling", Ceiling),
    ("ceilings", Ceiling),
    ("sky", Sky),
    ("door", Door),
    ("doors", Door),
];

/// A scene kind's draft look: (kind name, floor colour, floor pattern, wall colour, wall pattern,
/// door leaf colour).
type KindLook = (&'static str, [f32; 3], Pattern, [f32; 3], Pattern, [f32; 3]);

/// Draft looks per scene kind of the knowledge base. Kinds not listed take the indoor or
/// outdoor default.
#[rustfmt::skip]
const KINDS: &[KindLook] = &[
    ("living room", WOOD, Boards, OFF_WHITE, Plain, DOOR_WOOD),
    ("bedroom", [0.66, 0.50, 0.32], Boards, [0.88, 0.84, 0.76], Plain, PAINTED),
    ("kids room", [0.72, 0.66, 0.55], Speckled, [0.78, 0.85, 0.92], Plain, PAINTED),
    ("nursery", [0.72, 0.66, 0.55], Speckled, [0.92, 0.86, 0.84], Plain, PAINTED),
    ("kitchen", [0.80, 0.78, 0.74], Tiles, [0.93, 0.92, 0.88], Plain, PAINTED),
    ("bathroom", [0.90, 0.90, 0.88], Tiles, [0.86, 0.90, 0.92], Tiles, PAINTED),
    ("home office", [0.50, 0.50, 0.52], Speckled, [0.90, 0.90, 0.88], Plain, DOOR_WOOD),
    ("library", [0.40, 0.26, 0.15], Boards, [0.86, 0.80, 0.68], Plain, DARK_WOOD),
    ("classroom", [0.72, 0.72, 0.70], Speckled, [0.90, 0.88, 0.78], Plain, DOOR_WOOD),
    ("conference room", [0.42, 0.44, 0.48], Speckled, [0.90, 0.90, 0.90], Plain, PAINTED),
    ("cafe", [0.45, 0.30, 0.18], Boards, [0.86, 0.80, 0.70], Plain, DARK_WOOD),
    ("restaurant", [0.45, 0.30, 0.18], Boards, [0.85, 0.78, 0.66], Plain, DARK_WOOD),
    ("bar", [0.36, 0.22, 0.13], Boards, [0.55, 0.32, 0.24], Bricks, DARK_WOOD),
    ("gym", [0.25, 0.25, 0.27], Speckled, [0.90, 0.90, 0.90], Plain, METAL),
    ("garage", [0.60, 0.60, 0.58], Mottled, [0.80, 0.80, 0.78], Plain, METAL),
    ("church", [0.66, 0.62, 0.55], Tiles, [0.80, 0.76, 0.68], Bricks, DARK_WOOD),
    ("museum", [0.90, 0.89, 0.86], Marble, [0.94, 0.94, 0.93], Plain, PAINTED),
    ("home theater", [0.35, 0.12, 0.12], Speckled, [0.22, 0.20, 0.22], Plain, DARK_WOOD),
    ("throne room", [0.55, 0.53, 0.50], Cobbles, [0.60, 0.57, 0.52], Bricks, DARK_WOOD),
    ("spaceship bridge", [0.45, 0.47, 0.50], Tiles, [0.70, 0.72, 0.75], Tiles, METAL),
    ("server room", [0.70, 0.72, 0.74], Tiles, [0.88, 0.88, 0.88], Plain, METAL),
    ("patio", [0.62, 0.58, 0.52], Tiles, OFF_WHITE, Plain, DOOR_WOOD),
    ("beach", [0.86, 0.76, 0.55], Speckled, OFF_WHITE, Plain, DOOR_WOOD),
    ("street", [0.25, 0.25, 0.26], Speckled, OFF_WHITE, Plain, DOOR_WOOD),
    ("market", [0.50, 0.48, 0.45], Cobbles, OFF_WHITE, Plain, DOOR_WOOD),
    ("winter village", [0.93, 0.95, 0.98], Mottled, OFF_WHITE, Plain, DOOR_WOOD),
    ("campsite", [0.40, 0.38, 0.22], Mottled, OFF_WHITE, Plain, DOOR_WOOD),
    ("farm", [0.45, 0.40, 0.25], Mottled, OFF_WHITE, Plain, DOOR_WOOD),
    ("tea room", [0.74, 0.72, 0.50], Tatami, [0.90, 0.87, 0.78], Plain, DOOR_WOOD),
    ("cave", [0.40, 0.37, 0.33], Rock, ROCK, Rock, TUNNEL),
    // garden buildings: glass on a frame, timber boards
    ("greenhouse", [0.52, 0.50, 0.46], Slabs, GLASS, Panes, GLASS),
    ("potting shed", [0.48, 0.42, 0.34], Boards, SHED_BOARDS, Boards, SHED_BOARDS),
    ("boathouse", [0.45, 0.33, 0.22], Boards, SHED_BOARDS, Boards, DARK_WOOD),
    ("sauna", [0.70, 0.55, 0.36], Boards, [0.80, 0.64, 0.42], Boards, DOOR_WOOD),
    ("log cabin", [0.46, 0.32, 0.20], Boards, LOGS, Boards, DARK_WOOD),
];

/// A greenhouse's glass (its frame is drawn by the `Panes` pattern).
const GLASS: [f32; 3] = [0.80, 0.90, 0.90];
/// Honey-brown round logs of a log cabin's walls and roof boards.
const LOGS: [f32; 3] = [0.60, 0.42, 0.25];
/// Weathered timber cladding of a shed.
const SHED_BOARDS: [f32; 3] = [0.50, 0.38, 0.26];

/// Rock of a cave's walls and roof.
const ROCK: [f32; 3] = [0.36, 0.33, 0.30];
/// A cave's way out: the dark of a tunnel, not a door leaf.
const TUNNEL: [f32; 3] = [0.06, 0.05, 0.05];

/// Ceilings of scene kinds whose roof is not plain paint: (kind, colour, pattern).
const CEILINGS: &[(&str, [f32; 3], Pattern)] = &[
    ("cave", ROCK, Rock),
    ("greenhouse", GLASS, Panes),
    ("potting shed", SHED_BOARDS, Boards),
    ("boathouse", SHED_BOARDS, Boards),
    ("sauna", [0.80, 0.64, 0.42], Boards),
    ("log cabin", LOGS, Boards),
];

/// The clinical floor: pale sheet vinyl, its fine speckle; and the walls of a clinical place
/// whose kind has no look of its own.
const CLINICAL_FLOOR: [f32; 3] = [0.80, 0.83, 0.83];
const CLINICAL_WALL: [f32; 3] = [0.93, 0.95, 0.95];

/// Whether the scene kind's name or the words naming the place say it is clinical (the words
/// of `plan/kb/finishes.txt`: "an operating room", "a dental clinic", "a vet's surgery"). What
/// the place holds ("a garage with a medical cart", "a toy doctor kit") does not make it
/// clinical.
fn clinical(kind: Option<&str>, text: &str) -> bool {
    crate::plan::finish::clinical(kind, text)
}

/// The place the scene is said to be in, when its kind has a look of its own: a scene-kind
/// name or synonym right after "in the", "in a", "inside my", ... among the words naming the
/// place (before "with", "where", a comma): "a home gym in the garage" has the garage's floor
/// and walls, "a reading corner in the living room" the living room's.
fn setting_kind(text: &str) -> Option<&'static str> {
    let head = text
        .to_lowercase()
        .split([',', ';', ':', '.'])
        .next()
        .unwrap_or("")
        .to_string();
    let w = words(&head);
    let end = w
        .iter()
        .position(|x| ["with", "where", "which", "that", "and"].contains(&x.as_str()))
        .unwrap_or(w.len());
    let w = &w[..end];
    let mut best: Option<(&str, usize)> = None;
    for i in 0..w.len().saturating_sub(2) {
        if !["in", "inside"].contains(&w[i].as_str())
            || !["a", "an", "the", "my", "our", "their", "his", "her"].contains(&w[i + 1].as_str())
        {
            continue;
        }
        for s in &KnowledgeBase::builtin().scenes {
            if !KINDS.iter().any(|x| x.0 == s.name) {
                continue;
            }
            for name in std::iter::once(&s.name).chain(&s.synonyms) {
                let n = words(name);
                let at = &w[i + 2..];
                if at.len() >= n.len()
                    && at[..n.len()] == n[..]
                    && best.is_none_or(|(_, l)| n.len() > l)
                {
                    best = Some((s.name.as_str(), n.len()));
                }
            }
        }
    }
    best.map(|(n, _)| n)
}

/// The kind whose look the scene takes: the place it is said to be in (`setting_kind`), else
/// the longest scene-kind name or synonym of the knowledge base in `text` (whole words).
fn scene_kind(text: &str) -> Option<&'static str> {
    if let Some(k) = setting_kind(text) {
        return Some(k);
    }
    let t = format!(" {} ", words(text).join(" "));
    let mut best: Option<(&str, usize)> = None;
    for s in &KnowledgeBase::builtin().scenes {
        for name in std::iter::once(&s.name).chain(&s.synonyms) {
            let n = format!(" {} ", words(name).join(" "));
            if t.contains(&n) && best.is_none_or(|(_, l)| n.len() > l) {
                best = Some((s.name.as_str(), n.len()));
            }
        }
    }
    best.map(|(n, _)| n)
}

/// Whether word `i` of `w` is part of an object's name of two words or more in the knowledge
/// base ("lawn" in "a garage with a lawn mower", "snow" in "snow globes"): such a word names the
/// object, not the ground.
fn in_object_name(w: &[String], i: usize) -> bool {
    let kb = KnowledgeBase::builtin();
    let same = |name: &str, said: &str, last: bool| {
        name == said
            || (last
                && (said.strip_suffix('s') == Some(name) || said.strip_suffix("es") == Some(name)))
    };
    kb.objects.iter().any(|o| {
        std::iter::once(&o.category).chain(&o.synonyms).any(|name| {
            let n = words(name);
            n.len() >= 2
                && (0..n.len()).any(|k| {
                    i >= k
                        && i - k + n.len() <= w.len()
                        && n.iter()
                            .enumerate()
                            .all(|(j, x)| same(x, &w[i - k + j], j + 1 == n.len()))
                })
        })
    })
}

/// The draft colours of a scene: the scene kind's defaults, then what the text says of its
/// surfaces. A surface noun takes the material, colour and tone words just before it ("dark oak
/// floor", "white brick walls"); an unambiguous material word alone sets its own surface
/// ("a beach with white sand", "parquet").
pub fn draft_colours(scene_type: SceneType, scene_text: &str) -> EnvColours {
    let mut c = EnvColours {
        wall: OFF_WHITE,
        floor: WOOD,
        ceiling: CEILING_WHITE,
        sky: BLUE_SKY,
        ground: GRASS,
        wall_pattern: Plain,
        ceiling_pattern: Plain,
        floor_pattern: Boards,
        ground_pattern: Mottled,
        surround: GRASS,
        surround_pattern: Mottled,
        parapet: None,
        shore: None,
        door: DOOR_WOOD,
    };
    let kind = scene_kind(scene_text);
    if let Some(&(_, fc, fp, wc, wp, dc)) = kind.and_then(|k| KINDS.iter().find(|x| x.0 == k)) {
        (c.floor, c.floor_pattern, c.wall, c.wall_pattern, c.door) = (fc, fp, wc, wp, dc);
    }
    if let Some(&(_, cc, cp)) = kind.and_then(|k| CEILINGS.iter().find(|x| x.0 == k)) {
        (c.ceiling, c.ceiling_pattern) = (cc, cp);
    }
    let w = words(scene_text);
    if scene_type == SceneType::Indoor && clinical(kind, scene_text) {
        (c.floor, c.floor_pattern) = (CLINICAL_FLOOR, Speckled);
        if !KINDS.iter().any(|x| Some(x.0) == kind) {
            (c.wall, c.wall_pattern, c.door) = (CLINICAL_WALL, Plain, PAINTED);
        }
    }
    let mut one_ground = true;
    if scene_type == SceneType::Outdoor {
        let g = super::grounds::outdoor_ground(kind, &w);
        (
            (c.ground, c.ground_pattern),
            (c.surround, c.surround_pattern),
        ) = (g.area, g.surround);
        (c.floor, c.floor_pattern) = g.area;
        c.parapet = g.parapet;
        one_ground = g.one_ground;
    }
    if let Some((_, dc)) = STYLES
        .iter()
        .find(|(ws, _)| w.iter().any(|x| ws.contains(&x.as_str())))
    {
        c.door = *dc;
    }
    let material = |s: &str| MATERIALS.iter().find(|m| m.words.contains(&s));
    let colour = |s: &str| COLOURS.iter().find(|c| c.0 == s).map(|c| c.1);
    let tone = |s: &str| TONES.iter().find(|c| c.0 == s).map(|c| c.1);
    // What the words before index `i` say: (material, colour, tone), up to three words back.
    let modifiers = |i: usize| {
        let (mut mat, mut col, mut ton) = (None, None, None);
        for j in (i.saturating_sub(3)..i).rev() {
            let s = w[j].as_str();
            if let Some(x) = material(s) {
                mat = mat.or(Some(x));
            } else if let Some(x) = colour(s) {
                col = col.or(Some(x));
            } else if let Some(x) = tone(s) {
                ton = ton.or(Some(x));
            } else {
                break;
            }
        }
        (mat, col, ton)
    };
    // "a rug instead of a carpet", "no tiles": a surface word said not to be there sets nothing
    let describing = |s: &str| material(s).is_some() || colour(s).is_some() || tone(s).is_some();
    let not = |i: usize| super::said_not::negated(&w, i, describing);
    let mut explicit: Vec<Target> = vec![];
    // Surface nouns first: they are explicit about which surface they mean.
    for (i, s) in w.iter().enumerate() {
        if not(i) {
            continue;
        }
        if let Some(&(_, target)) = NOUNS.iter().find(|n| n.0 == s) {
            let (mat, col, ton) = modifiers(i);
            if mat.is_some() || col.is_some() || ton.is_some() {
                apply(&mut c, target, mat, col, ton);
                explicit.push(target);
            }
        }
    }
    for (i, s) in w.iter().enumerate() {
        if let Some(mat) = material(s).filter(|m| {
            m.alone && !explicit.contains(&m.target) && !in_object_name(&w, i) && !not(i)
        }) {
            let (_, col, ton) = modifiers(i);
            apply(&mut c, mat.target, Some(mat), col, ton);
        }
    }
    // "a kids room with a rug instead of a carpet": an indoor floor the text says is not of the
    // kind's own material is plain boards
    let denied = w
        .iter()
        .enumerate()
        .filter(|&(i, _)| not(i) && !in_object_name(&w, i))
        .filter_map(|(_, s)| material(s))
        .any(|m| m.target == Floor && m.pattern == c.floor_pattern);
    if scene_type == SceneType::Indoor && denied && !explicit.contains(&Floor) {
        (c.floor, c.floor_pattern) = (WOOD, Boards);
    }
    // "a beach with white sand": the one ground all round follows the text
    if one_ground {
        (c.surround, c.surround_pattern) = (c.ground, c.ground_pattern);
    }
    c
}

fn apply(
    c: &mut EnvColours,
    target: Target,
    mat: Option<&Material>,
    col: Option<[f32; 3]>,
    ton: Option<f32>,
) {
    let (slot, pattern) = match target {
        Floor => (&mut c.floor, Some(&mut c.floor_pattern)),
        Wall => (&mut c.wall, Some(&mut c.wall_pattern)),
        Ceiling => (&mut c.ceiling, None),
        Sky => (&mut c.sky, None),
        Door => (&mut c.door, None),
    };
    let base = col.or(mat.map(|m| m.colour)).unwrap_or(*slot);
    *slot = base.map(|v| (v * ton.unwrap_or(1.0)).clamp(0.0, 1.0));
    if let (Some(p), Some(m)) = (pattern, mat) {
        *p = m.pattern;
    }
    if target == Floor {
        (c.ground, c.ground_pattern) = (c.floor, c.floor_pattern);
    }
}

/// A hash of integer lattice coordinates to [0, 1).
pub(crate) fn hash(a: i64, b: i64, seed: u64) -> f32 {
    let mut h = (a as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (b as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ seed.wrapping_mul(0x1656_67B1_9E37_79F9);
    h ^= h >> 31;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 29;
    (h >> 40) as f32 / (1u64 << 24) as f32
}

/// Smooth value noise in [0, 1) at (u, v), lattice spacing 1.
fn noise(u: f32, v: f32, seed: u64) -> f32 {
    let (iu, iv) = (u.floor(), v.floor());
    let (fu, fv) = (u - iu, v - iv);
    let s = |t: f32| t * t * (3.0 - 2.0 * t);
    let (a, b) = (iu as i64, iv as i64);
    let l0 = hash(a, b, seed) + (hash(a + 1, b, seed) - hash(a, b, seed)) * s(fu);
    let l1 = hash(a, b + 1, seed) + (hash(a + 1, b + 1, seed) - hash(a, b + 1, seed)) * s(fu);
    l0 + (l1 - l0) * s(fv)
}

/// Three octaves of value noise, in about [0, 1), features of `size` metres.
pub(super) fn fbm(u: f32, v: f32, size: f32, seed: u64) -> f32 {
    let (mut sum, mut amp, mut f) = (0.0, 0.5, 1.0 / size);
    for o in 0..3 {
        sum += amp * noise(u * f, v * f, seed.wrapping_add(o));
        amp *= 0.5;
        f *= 2.0;
    }
    sum / 0.875
}

/// The colour of `base` under `pattern` at surface coordinates (u, v) metres; `speck` is this
/// point's own uniform random number in [0, 1) (per-Gaussian variation).
pub fn shade(base: [f32; 3], pattern: Pattern, u: f32, v: f32, speck: f32, seed: u64) -> [f32; 3] {
    // Painted surfaces get only a trace of per-point speckle (it read as stucco at 512²).
    let grain = if pattern == Plain { 0.012 } else { 0.06 };
    let mut k = 1.0 + grain * (speck - 0.5);
    let mut mix_to: Option<([f32; 3], f32)> = None;
    match pattern {
        Plain => k *= 1.0 + 0.035 * (fbm(u, v, 1.5, seed) - 0.5),
        Boards => {
            let (bw, bl) = (0.14, 1.3);
            let row = (v / bw).floor();
            let off = hash(row as i64, 7, seed) * bl;
            let plank = ((u + off) / bl).floor();
            let fv = v / bw - row;
            let fu = (u + off) / bl - plank;
            k *= 0.82 + 0.36 * hash(row as i64, plank as i64, seed);
            k *= 1.0 + 0.08 * (((u * 9.0 + 5.0 * hash(row as i64, 3, seed)).sin()) * 0.5);
            if fv < 0.06 || fu < 0.008 {
                k *= 0.55;
            }
        }
        Tiles | Cobbles => {
            let (size, joint, spread) = if pattern == Tiles {
                (0.5, 0.012, 0.08)
            } else {
                (0.16, 0.025, 0.35)
            };
            let row = (v / size).floor();
            let uu = if pattern == Cobbles {
                u + 0.5 * size * (row as i64 & 1) as f32
            } else {
                u
            };
            let col = (uu / size).floor();
            let (fu, fv) = (uu - col * size, v - row * size);
            k *= 1.0 + spread * (hash(row as i64, col as i64, seed) - 0.5);
            if fu.min(size - fu) < joint || fv.min(size - fv) < joint {
                mix_to = Some(if pattern == Tiles {
                    ([0.55, 0.55, 0.53], 0.8)
                } else {
                    ([0.18, 0.17, 0.16], 0.7)
                });
            }
        }
        Marble => {
            let t = (u * 1.7 + v * 0.9 + 4.0 * fbm(u, v, 0.7, seed)).sin().abs();
            k *= 1.0 + 0.05 * (fbm(u, v, 0.4, seed + 9) - 0.5);
            if t < 0.12 {
                mix_to = Some(([0.45, 0.45, 0.47], 0.6 * (1.0 - t / 0.12)));
            }
        }
        Bricks => {
            // Stylised large bricks (30 x 12 cm): real 21.5 x 6.5 cm ones alias at the draft spacing.
            let (bw, bh, mortar) = (0.30, 0.12, 0.02);
            let row = (v / bh).floor();
            let uu = u + 0.5 * bw * (row as i64 & 1) as f32;
            let col = (uu / bw).floor();
            let (fu, fv) = (uu - col * bw, v - row * bh);
            k *= 0.85 + 0.3 * hash(row as i64, col as i64, seed);
            if fu < mortar || fv < mortar {
                mix_to = Some(([0.78, 0.76, 0.72], 0.9));
            }
        }
        Slabs => {
            let (size, joint) = (0.6, 0.035);
            let row = (v / size).floor();
            let uu = u + 0.5 * size * (row as i64 & 1) as f32;
            let col = (uu / size).floor();
            let (fu, fv) = (uu - col * size, v - row * size);
            k *= 1.0 + 0.18 * (hash(row as i64, col as i64, seed) - 0.5);
            k *= 1.0 + 0.08 * (fbm(u, v, 0.8, seed) - 0.5);
            if fu.min(size - fu) < joint || fv.min(size - fv) < joint {
                mix_to = Some(([0.30, 0.30, 0.28], 0.55));
            }
        }
        Speckled => {
            k *= 1.0 + 0.22 * (speck - 0.5) + 0.12 * (fbm(u, v, 1.5, seed) - 0.5);
        }
        Mottled => {
            k *= 1.0 + 0.35 * (fbm(u, v, 1.2, seed) - 0.5) + 0.1 * (speck - 0.5);
        }
        Tatami | Rock | Planks | Panes => {
            return super::natural::shade(base, pattern, u, v, speck, seed)
        }
    }
    let mut c = base.map(|x| x * k);
    if let Some((to, t)) = mix_to {
        c = [0, 1, 2].map(|i| c[i] + (to[i] - c[i]) * t);
    }
    c.map(|x| x.clamp(0.0, 1.0))
}
