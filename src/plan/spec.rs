//! The planner's output and the layout's input: `SceneSpec` (spec.json), and the layout's output
//! `Layout` (layout.json), with the contracts of ARCHITECTURE.md. No GPU here.
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// Indoor (walls, corners) or outdoor (ground boundary, no corners).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SceneType {
    Indoor,
    Outdoor,
}

/// Region anchor of an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, PartialOrd, Ord)]
#[serde(rename_all = "UPPERCASE")]
pub enum Anchor {
    Center,
    Side,
    Corner,
    Others,
    /// At a window: before its span, near its wall ([`crate::plan::check::at_window`]).
    Window,
    /// Facing a window: see [`crate::plan::check::anchor_holds_in`].
    #[serde(rename = "FACE_WINDOW")]
    FaceWindow,
    /// Beside a door, outside its clear zone: see [`crate::plan::check::anchor_holds_in`].
    Door,
    /// Facing a door from the room, clear of its zone: see
    /// [`crate::plan::check::anchor_holds_in`].
    #[serde(rename = "FACE_DOOR")]
    FaceDoor,
}

/// Pairwise relation: "subject is RELATION of object", in the object's own frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, PartialOrd, Ord)]
#[serde(rename_all = "UPPERCASE")]
pub enum RelationKind {
    Left,
    Right,
    Front,
    Behind,
    Over,
    Under,
    Next,
    Opposite,
    /// A seat at a table, on one of its sides, facing it (functional group).
    Around,
    /// A seat at the front of a desk or counter, facing it (functional group).
    At,
    /// Flush beside the head end of the object, turned as it is (nightstands by a bed).
    Flank,
    /// Seats gathered round a fire: 0.6–1.5 m away, facing it.
    Circle,
    /// In front of the object (the subject's centre beyond the object's front face, in the
    /// object's frame) and turned to face it: the subject's facing is within 30° of the
    /// opposite of the object's (desks, seats, pews in rows facing a board, screen or altar).
    Row,
    /// A seat at the back of a desk, facing the way the desk faces (a pupil at a school desk
    /// turned to the board, a teacher behind a desk turned to the class): the subject's centre
    /// beyond the object's back face (local y < -depth/2), its footprint in the band that face
    /// sweeps, the footprint gap at most [`crate::plan::check::SEAT_GAP`], no overlap beyond the
    /// validity tolerance, and facing the object's footprint within 30°.
    #[serde(rename = "AT_BACK")]
    AtBack,
    /// Before the object and turned the way it faces, with room for a seat between (a teacher's
    /// desk before the board, facing the class; a lectern before the screen): the subject's
    /// centre beyond the object's front face (local y > depth/2), its footprint in the band
    /// that face sweeps, the footprint gap within [`crate::plan::check::BEFORE_GAP`], and its
    /// facing within 30° of the object's.
    Before,
}

impl RelationKind {
    pub const ALL: [RelationKind; 15] = [
        RelationKind::Left,
        RelationKind::Right,
        RelationKind::Front,
        RelationKind::Behind,
        RelationKind::Over,
        RelationKind::Under,
        RelationKind::Next,
        RelationKind::Opposite,
        RelationKind::Around,
        RelationKind::At,
        RelationKind::Flank,
        RelationKind::Circle,
        RelationKind::Row,
        RelationKind::AtBack,
        RelationKind::Before,
    ];

    /// Whether it puts a seat at its object (AROUND, AT, AT_BACK): the seat belongs to it.
    pub fn is_seat(self) -> bool {
        matches!(
            self,
            RelationKind::Around | RelationKind::At | RelationKind::AtBack
        )
    }

    /// The name as spec.json writes it (`OPPOSITE`).
    pub fn name(self) -> &'static str {
        use RelationKind::*;
        match self {
            Left => "LEFT",
            Right => "RIGHT",
            Front => "FRONT",
            Behind => "BEHIND",
            Over => "OVER",
            Under => "UNDER",
            Next => "NEXT",
            Opposite => "OPPOSITE",
            Around => "AROUND",
            At => "AT",
            Flank => "FLANK",
            Circle => "CIRCLE",
            Row => "ROW",
            AtBack => "AT_BACK",
            Before => "BEFORE",
        }
    }
}

impl std::fmt::Display for RelationKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::fmt::Display for Relation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {} {}", self.subject, self.relation, self.object)
    }
}

#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize, PartialOrd, Ord)]
pub struct Relation {
    pub subject: String,
    pub relation: RelationKind,
    pub object: String,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ObjectSpec {
    pub number: u32,
    /// [width, depth, height] in metres.
    pub size: [f64; 3],
    pub description: String,
    /// The rows the instances stand in ("in four rows of six", "in a row"): aligned rows, all
    /// turned the same way toward the front; 0 (the default, not written) when no rows are asked.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub rows: u32,
    /// The size of each instance in index order, where instances differ ("six tables for two
    /// and two tables for six"); `size` is then the largest. Empty (the default, not written)
    /// when every instance has `size`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub sizes: Vec<[f64; 3]>,
    /// Hung on a wall with its bottom at this height (m), where the text hangs there a thing
    /// the knowledge base stands on the floor or does not know ("a guitar hanging on the wall",
    /// "a neon sign on the wall"); absent (not written) when its placement class decides.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub on_wall: Option<f64>,
}

impl ObjectSpec {
    /// The size of instance `k` (1-based): its own where the spec gives one, else `size`.
    pub fn size_of(&self, k: u32) -> [f64; 3] {
        (k as usize)
            .checked_sub(1)
            .and_then(|i| self.sizes.get(i))
            .copied()
            .unwrap_or(self.size)
    }
}

fn is_zero(v: &u32) -> bool {
    *v == 0
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Room {
    /// [W, D, H] in metres (outdoor: ground area and sky height).
    pub size: [f64; 3],
}

/// spec.json.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneSpec {
    pub scene_type: SceneType,
    pub scene_text: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub room: Option<Room>,
    pub objects: BTreeMap<String, ObjectSpec>,
    #[serde(default)]
    pub anchors: BTreeMap<String, Anchor>,
    #[serde(default)]
    pub relations: Vec<Relation>,
}

/// One object instance of a spec.
#[derive(Debug, Clone, PartialEq)]
pub struct Instance {
    /// Category + 1-based index, e.g. `sofa1`.
    pub id: String,
    pub category: String,
    pub size: [f64; 3],
    pub anchor: Anchor,
}

/// How an object got its place.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PlacedBy {
    Constraint,
    Fallback,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PlacedObject {
    pub id: String,
    pub category: String,
    pub size: [f64; 3],
    /// Centre of the bottom face, world frame (z up, metres).
    pub position: [f64; 3],
    /// Degrees, counter-clockwise about +z; at 0 the object faces +y.
    pub yaw: f64,
    pub anchor: Anchor,
    pub placed_by: PlacedBy,
}

/// layout.json.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Layout {
    pub scene_type: SceneType,
    pub room: Room,
    pub seed: u64,
    pub objects: Vec<PlacedObject>,
    pub unsatisfied: Vec<Relation>,
    /// Anchors the layout could not meet (a desk asked under the window where no window is
    /// free), beside the relations in `unsatisfied`; empty (not written) when all hold.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unsatisfied_anchors: Vec<MissedAnchor>,
    /// Doors and windows of an indoor room (empty outdoors).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub openings: Vec<Opening>,
}

/// An instance whose anchor does not hold where it stands.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct MissedAnchor {
    pub id: String,
    pub anchor: Anchor,
}

impl std::fmt::Display for MissedAnchor {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = serde_json::to_value(self.anchor).map_err(|_| std::fmt::Error)?;
        write!(f, "{} {}", self.id, a.as_str().unwrap_or("?"))
    }
}

/// Door or window.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum OpeningKind {
    Door,
    Window,
}

/// The wall an opening is in: north is +y, east +x.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Wall {
    North,
    South,
    East,
    West,
}

/// A door or window (ARCHITECTURE.md "Openings"): `position` is the bottom centre of the
/// opening on the wall's inner face (z = sill height, 0 for a door).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Opening {
    pub kind: OpeningKind,
    pub wall: Wall,
    pub position: [f64; 3],
    pub width: f64,
    pub height: f64,
}

impl Wall {
    /// The unit vector from the wall into the room.
    pub fn inward(self) -> [f64; 2] {
        match self {
            Wall::North => [0.0, -1.0],
            Wall::South => [0.0, 1.0],
            Wall::East => [-1.0, 0.0],
            Wall::West => [1.0, 0.0],
        }
    }

    /// The unit vector along the wall (east or north).
    pub fn along(self) -> [f64; 2] {
        match self {
            Wall::North | Wall::South => [1.0, 0.0],
            Wall::East | Wall::West => [0.0, 1.0],
        }
    }
}

impl Opening {
    /// The opening's span on the floor: its two ends on the wall's inner face.
    pub fn span(&self) -> ([f64; 2], [f64; 2]) {
        let a = self.wall.along();
        let h = 0.5 * self.width;
        let [x, y, _] = self.position;
        ([x - a[0] * h, y - a[1] * h], [x + a[0] * h, y + a[1] * h])
    }
}

/// A spec or layout problem, naming what is wrong.
#[derive(Debug, thiserror::Error)]
pub enum SpecError {
    #[error("{path}: {msg}")]
    File { path: String, msg: String },
    #[error("invalid scene spec: {0}")]
    Invalid(String),
    /// Objects that do not fit the room, with the smallest room that would take them.
    #[error("{0}")]
    DoesNotFit(String),
}

/// Most instances of one category a spec may ask for.
pub const MAX_NUMBER: u32 = 120;

impl SceneSpec {
    /// The instances, in category order then index: `sofa1`, `sofa2`, ...
    pub fn instances(&self) -> Vec<Instance> {
        let mut out = vec![];
        for (cat, o) in &self.objects {
            for k in 1..=o.number {
                let id = format!("{cat}{k}");
                let anchor = self.anchors.get(&id).copied().unwrap_or(Anchor::Others);
                out.push(Instance {
                    id,
                    category: cat.clone(),
                    size: o.size_of(k),
                    anchor,
                });
            }
        }
        out
    }

    /// The size of instance `id` (`table7`): its own where the spec gives one, else its
    /// category's.
    pub fn size_of(&self, id: &str) -> Option<[f64; 3]> {
        let cat = id.trim_end_matches(|c: char| c.is_ascii_digit());
        let o = self.objects.get(cat)?;
        let k = id[cat.len()..].parse().unwrap_or(1);
        Some(o.size_of(k))
    }

    /// Whether instances `a` and `b` are an OVER / UNDER pair (either way round): such pairs may
    /// share space.
    pub fn is_stacked(&self, a: &str, b: &str) -> bool {
        self.relations.iter().any(|r| {
            matches!(r.relation, RelationKind::Over | RelationKind::Under)
                && ((r.subject == a && r.object == b) || (r.subject == b && r.object == a))
        })
    }

    /// Checks names, sizes, counts and references; the error says which entry is wrong.
    pub fn validate(&self) -> Result<(), SpecError> {
        let bad = |m: String| Err(SpecError::Invalid(m));
        if self.objects.is_empty() {
            return bad("no objects".into());
        }
        for (cat, o) in &self.objects {
            if cat.trim().is_empty() {
                return bad("an object has an empty category name".into());
            }
            if cat.ends_with(|c: char| c.is_ascii_digit()) {
                return bad(format!(
                    "category `{cat}` ends in a digit (instances are named category + index)"
                ));
            }
            if o.number == 0 || o.number > MAX_NUMBER {
                return bad(format!("`{cat}`: number {} (1 to {MAX_NUMBER})", o.number));
            }
            let fine = |s: &[f64; 3]| s.iter().all(|v| v.is_finite() && *v > 0.0 && *v <= 50.0);
            if let Some(s) = std::iter::once(&o.size).chain(&o.sizes).find(|s| !fine(s)) {
                return bad(format!("`{cat}`: size {s:?} (each side in (0, 50] metres)"));
            }
            if !o.sizes.is_empty() && o.sizes.len() != o.number as usize {
                return bad(format!(
                    "`{cat}`: {} sizes for {} instances (one each, or none)",
                    o.sizes.len(),
                    o.number
                ));
            }
        }
        let ids: std::collections::BTreeSet<String> =
            self.instances().into_iter().map(|i| i.id).collect();
        for (id, a) in &self.anchors {
            if !ids.contains(id) {
                return bad(format!("anchor for unknown instance `{id}`"));
            }
            if *a == Anchor::Corner && self.scene_type == SceneType::Outdoor {
                return bad(format!("`{id}`: CORNER anchor in an outdoor scene"));
            }
        }
        for r in &self.relations {
            for name in [&r.subject, &r.object] {
                if !ids.contains(name) {
                    return bad(format!(
                        "relation {} {} {}: unknown instance `{name}`",
                        r.subject, r.relation, r.object
                    ));
                }
            }
            if r.subject == r.object {
                return bad(format!("relation of `{}` to itself", r.subject));
            }
        }
        if let Some(room) = &self.room {
            if !room
                .size
                .iter()
                .all(|v| v.is_finite() && *v > 0.5 && *v <= 500.0)
            {
                return bad(format!("room size {:?}", room.size));
            }
        }
        Ok(())
    }

    /// Reads and validates spec.json.
    pub fn read(path: &Path) -> Result<SceneSpec, SpecError> {
        let file = |msg: String| SpecError::File {
            path: path.display().to_string(),
            msg,
        };
        let bytes = std::fs::read(path).map_err(|e| file(e.to_string()))?;
        SceneSpec::parse(&bytes).map_err(file)
    }

    /// Parses and validates the text of a spec.json; a file of another kind (a layout.json, a
    /// cameras.json, a PLY) is named as such. Errors are one line without the file name.
    pub fn parse(bytes: &[u8]) -> Result<SceneSpec, String> {
        let spec: SceneSpec = parse_json(bytes, "spec.json", "a SceneSpec")?;
        spec.validate().map_err(|e| e.to_string())?;
        Ok(spec)
    }
}

/// Parses JSON text as `T`, the contents of a file named `name`; when it does not parse, says
/// what the file looks like if it is another kind of file.
fn parse_json<T: serde::de::DeserializeOwned>(
    bytes: &[u8],
    name: &str,
    what: &str,
) -> Result<T, String> {
    let looks = crate::util::describe_bytes(bytes);
    let raw = || -> Result<T, String> {
        let text = std::str::from_utf8(bytes).map_err(|e| e.to_string())?;
        serde_json::from_str(text).map_err(|e| e.to_string())
    };
    raw().map_err(|e| {
        if looks.starts_with("looks like a") && !looks.ends_with(name) {
            format!("this file {looks}; expected a {name} ({what})")
        } else if looks.starts_with("is a JSON") || looks.starts_with("looks like") {
            format!("not a valid {name}: {e}")
        } else {
            format!("this file {looks}; expected a {name} ({what})")
        }
    })
}

impl Layout {
    /// One line for the user: objects, room, relations satisfied, fallback placements, with
    /// singular and plural right ("1 fallback placement", "no relations to satisfy").
    pub fn summary(&self, spec: &SceneSpec) -> String {
        let n = spec.relations.len();
        let relations = match n {
            0 => "no relations to satisfy".to_string(),
            1 => format!(
                "{} of 1 relation satisfied",
                1 - self.unsatisfied.len().min(1)
            ),
            _ => format!(
                "{} of {n} relations satisfied",
                n - self.unsatisfied.len().min(n)
            ),
        };
        let fallback = self
            .objects
            .iter()
            .filter(|o| o.placed_by == PlacedBy::Fallback)
            .count();
        let plural =
            |k: usize, one: &str, many: &str| format!("{k} {}", if k == 1 { one } else { many });
        let [w, d, h] = self.room.size;
        format!(
            "{} in a {w:.1} x {d:.1} x {h:.1} m room, {relations}, {}",
            plural(self.objects.len(), "object", "objects"),
            plural(fallback, "fallback placement", "fallback placements")
        )
    }

    /// Reads layout.json.
    pub fn read(path: &Path) -> Result<Layout, SpecError> {
        let file = |msg: String| SpecError::File {
            path: path.display().to_string(),
            msg,
        };
        let bytes = std::fs::read(path).map_err(|e| file(e.to_string()))?;
        Layout::parse(&bytes).map_err(file)
    }

    /// Parses the text of a layout.json: the keys of the contract and finite numbers. Errors are
    /// one line without the file name.
    pub fn parse(bytes: &[u8]) -> Result<Layout, String> {
        let l: Layout = parse_json(bytes, "layout.json", "the layout's output")?;
        let numbers = l.room.size.iter().chain(
            l.objects
                .iter()
                .flat_map(|o| o.size.iter().chain(&o.position).chain([&o.yaw])),
        );
        if let Some(v) = numbers.copied().find(|v: &f64| !v.is_finite()) {
            return Err(format!("layout.json holds a non-finite number ({v})"));
        }
        Ok(l)
    }

    /// Writes layout.json atomically.
    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        let text = serde_json::to_string_pretty(self).expect("layout serialises");
        crate::util::write_atomic(path, text.as_bytes())
    }
}
